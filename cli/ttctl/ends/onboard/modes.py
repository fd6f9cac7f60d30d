"""Flight modes as ground stations read them from HEARTBEAT.custom_mode.

MAVSDK decodes the flight mode of any vehicle that is not ArduPilot with PX4's packing (main
mode in bits 16-23, sub mode in bits 24-31), and QGroundControl shows PX4's names for them; the
emulated vehicle therefore reports its states in PX4's modes (px4/src/modules/commander/
px4_custom_mode.h). DO_SET_MODE with CUSTOM_MODE_ENABLED and a PX4 main/sub mode is understood
the same way.
"""

from __future__ import annotations

from .vehicle import State

# PX4 main modes
MANUAL, ALTCTL, POSCTL, AUTO, ACRO, OFFBOARD, STABILIZED = 1, 2, 3, 4, 5, 6, 7
# PX4 AUTO sub modes
READY, TAKEOFF, LOITER, MISSION, RTL, LAND = 1, 2, 3, 4, 5, 6

_BY_STATE = {
    State.LANDED: (AUTO, READY),
    State.TAKING_OFF: (AUTO, TAKEOFF),
    State.HOVERING: (AUTO, LOITER),
    State.MOVING: (OFFBOARD, 0),
    State.TRAJECTORY: (AUTO, MISSION),
    State.LANDING: (AUTO, LAND),
    State.RETURNING: (AUTO, RTL),
}

NAMES = {(AUTO, READY): "READY", (AUTO, LOITER): "HOLD", (AUTO, TAKEOFF): "TAKEOFF", (AUTO, MISSION): "MISSION",
         (AUTO, LAND): "LAND", (AUTO, RTL): "RETURN", (OFFBOARD, 0): "OFFBOARD", (POSCTL, 0): "POSCTL"}


def custom_mode(state: State) -> int:
    main, sub = _BY_STATE[state]
    return (main << 16) | (sub << 24)


def decode(custom: int) -> tuple[int, int]:
    return (custom >> 16) & 0xFF, (custom >> 24) & 0xFF


def name(custom: int) -> str:
    main, sub = decode(custom)
    return NAMES.get((main, sub), NAMES.get((main, 0), f"{main}/{sub}"))
