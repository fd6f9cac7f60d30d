"""Flight modes as ground stations read them from HEARTBEAT.custom_mode: PX4's (main mode in
bits 16-23, sub mode in bits 24-31, px4/src/modules/commander/px4_custom_mode.h), which MAVSDK,
MAVProxy and QGroundControl name for a PX4 autopilot. `NAMES` are the modes the vehicle flies
(flight.py enters each on DO_SET_MODE); `custom_mode(state)` is the state as the tablet's link
reports it (its own encoding: READY is "landed").
"""

from __future__ import annotations

from typing import Any

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
    State.MANUAL: (POSCTL, 0),
    State.OFFBOARD: (OFFBOARD, 0),
}

# the modes this vehicle flies, by PX4's names (as MAVProxy and pymavlink spell them)
NAMES = {(MANUAL, 0): "MANUAL", (ALTCTL, 0): "ALTCTL", (POSCTL, 0): "POSCTL", (AUTO, LOITER): "LOITER",
         (AUTO, TAKEOFF): "TAKEOFF", (AUTO, MISSION): "MISSION", (AUTO, RTL): "RTL", (AUTO, LAND): "LAND",
         (OFFBOARD, 0): "OFFBOARD"}
_OTHERS = {(AUTO, READY): "READY", (ACRO, 0): "ACRO", (STABILIZED, 0): "STABILIZED", (8, 0): "RATTITUDE",
           (AUTO, 7): "RTGS", (AUTO, 8): "FOLLOWME", (AUTO, 9): "PRECLAND", (AUTO, 10): "VTOL_TAKEOFF"}


def custom_mode(state: State) -> int:
    main, sub = _BY_STATE[state]
    return (main << 16) | (sub << 24)


def decode(custom: int) -> tuple[int, int]:
    return (custom >> 16) & 0xFF, (custom >> 24) & 0xFF


def name(custom: int) -> str:
    main, sub = decode(custom)
    if main != AUTO:
        sub = 0
    return NAMES.get((main, sub)) or _OTHERS.get((main, sub), f"{main}/{sub}")


def base_flags(b: Any, custom: int) -> int:
    """HEARTBEAT.base_mode for a PX4 custom mode, as PX4's get_mavlink_navigation_mode sets it
    for a multicopter (SAFETY_ARMED is the caller's)."""
    F = b.MavModeFlag
    main, _ = decode(custom)
    flags = int(F.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED)
    if main in (MANUAL, ALTCTL, POSCTL, STABILIZED):
        flags |= int(F.MAV_MODE_FLAG_MANUAL_INPUT_ENABLED | F.MAV_MODE_FLAG_STABILIZE_ENABLED)
        if main == POSCTL:
            flags |= int(F.MAV_MODE_FLAG_GUIDED_ENABLED)
    elif main in (AUTO, OFFBOARD):
        flags |= int(F.MAV_MODE_FLAG_AUTO_ENABLED | F.MAV_MODE_FLAG_STABILIZE_ENABLED
                     | F.MAV_MODE_FLAG_GUIDED_ENABLED)
    return flags
