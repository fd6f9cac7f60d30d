"""The vehicle's parameters and the MAVLink parameter protocol, sans-IO.

PARAM_REQUEST_LIST is answered with every PARAM_VALUE (count and index right, paced by the
caller's scheduler), PARAM_REQUEST_READ by name or index, PARAM_SET with the new value echoed
(or the old one, if refused) and the change applied at once. Values travel in the float field;
INT32 parameters are packed bytewise (PARAM_ENCODE_BYTEWISE, what MAVSDK expects of a
non-ArduPilot vehicle), so integers above 2^24 survive.
"""

from __future__ import annotations

import math
import struct
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from ...wire.bindings import Bindings

INT32 = 6  # MAV_PARAM_TYPE_INT32 (common.xml; tests check it against the dialect)
REAL32 = 9  # MAV_PARAM_TYPE_REAL32


@dataclass
class Param:
    name: str
    value: float
    kind: int  # INT32 or REAL32
    low: float
    high: float
    doc: str

    def encoded(self) -> float:
        if self.kind == INT32:
            return float(struct.unpack("<f", struct.pack("<i", int(self.value)))[0])
        return float(self.value)

    def decode(self, raw: float) -> float:
        if self.kind == INT32:
            return float(struct.unpack("<i", struct.pack("<f", raw))[0])
        return raw


def default_params() -> list[Param]:
    """The parameter set: names after PX4's where PX4 has one (ground stations know them)."""
    return [
        Param("COM_DL_LOSS_T", 10.0, REAL32, 1.0, 300.0,
              "seconds without the tablet's link before the link-loss action"),
        Param("NAV_DLL_ACT", 2, INT32, 0, 3, "link-loss action: 0 none, 1 hover, 2 return, 3 land"),
        Param("COM_RTL_AFTER_T", 15.0, REAL32, 0.0, 600.0, "seconds of hovering after link loss before the return"),
        Param("MIS_TAKEOFF_ALT", 2.0, REAL32, 0.5, 120.0, "take-off altitude above home, m"),
        Param("RTL_RETURN_ALT", 10.0, REAL32, 2.0, 120.0, "return altitude above home, m"),
        Param("TT_MAX_DIST", 1000.0, REAL32, 10.0, 100000.0,
              "farthest from home (horizontally, m) a set-point, trajectory or mission waypoint may lead"),
        Param("MPC_XY_VEL_MAX", 1.5, REAL32, 0.1, 20.0, "horizontal speed limit, m/s"),
        Param("MPC_Z_VEL_MAX_UP", 1.0, REAL32, 0.1, 10.0, "vertical speed limit, m/s"),
        Param("COM_OF_LOSS_T", 1.0, REAL32, 0.2, 60.0,
              "seconds without OFFBOARD set-points before COM_OBL_RC_ACT (ground-station time)"),
        Param("COM_OBL_RC_ACT", 0, INT32, 0, 5, "offboard loss: 0 position, 1 altitude, 2 manual (with "
              "MANUAL_CONTROL, else hold), 3 return, 4 land, 5 hold"),
        Param("COM_RC_LOSS_T", 0.5, REAL32, 0.1, 35.0,
              "seconds without MANUAL_CONTROL in MANUAL/ALTCTL/POSCTL before NAV_RCL_ACT"),
        Param("NAV_RCL_ACT", 2, INT32, 1, 3, "manual control loss: 1 hold, 2 return, 3 land"),
        Param("MAV_SYS_ID", 1, INT32, 1, 254, "this vehicle's MAVLink system id (read only here)"),
        Param("SYS_AUTOSTART", 4001, INT32, 4001, 4001,
              "PX4 airframe: 4001, the generic quadcopter (QGroundControl's PX4 plugin reads it; read only)"),
    ]


class Parameters:
    def __init__(self, bindings: Bindings, params: list[Param], on_change: Callable[[Param], None] | None = None,
                 read_only: tuple[str, ...] = ("MAV_SYS_ID", "SYS_AUTOSTART")) -> None:
        self.b = bindings
        self.params = params
        self.index = {p.name: i for i, p in enumerate(params)}
        self.on_change = on_change
        self.read_only = read_only

    def __getitem__(self, name: str) -> float:
        return self.params[self.index[name]].value

    def value_msg(self, i: int) -> Any:
        p = self.params[i]
        return self.b.ParamValue(param_id=p.name, param_value=p.encoded(), param_type=p.kind,
                                 param_count=len(self.params), param_index=i)

    def all(self) -> list[Any]:
        return [self.value_msg(i) for i in range(len(self.params))]

    def read(self, msg: Any) -> list[Any]:
        if msg.param_index >= 0:
            return [self.value_msg(msg.param_index)] if msg.param_index < len(self.params) else []
        i = self.index.get(msg.param_id.rstrip("\x00"))
        return [] if i is None else [self.value_msg(i)]

    def set(self, msg: Any) -> tuple[list[Any], str | None]:
        """The PARAM_VALUE to answer with, and a complaint to log if the value was refused."""
        name = msg.param_id.rstrip("\x00")
        i = self.index.get(name)
        if i is None:
            return [], f"PARAM_SET of unknown parameter {name!r}"
        p = self.params[i]
        value = p.decode(msg.param_value)
        if name in self.read_only:
            return [self.value_msg(i)], f"{name} cannot be changed here"
        if not math.isfinite(value) or not p.low <= value <= p.high:
            return [self.value_msg(i)], f"{name} = {value:g} refused: outside {p.low:g}..{p.high:g}"
        p.value = float(int(value)) if p.kind == INT32 else value
        if self.on_change is not None:
            self.on_change(p)
        return [self.value_msg(i)], None
