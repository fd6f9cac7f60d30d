"""The MAVLink mission protocol on the vehicle's side, sans-IO: upload (MISSION_COUNT, then a
MISSION_REQUEST_INT per item, re-asked when an item does not come), download
(MISSION_REQUEST_LIST, MISSION_COUNT, MISSION_ITEM_INT per request), clear, and the conversion
of a mission into the vehicle's waypoints. Mission, fence and rally plans are kept apart, by
mission_type, as the protocol asks; only the mission is flown.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from ...wire.bindings import Bindings
from .vehicle import EARTH_RADIUS, Home, Waypoint

RETRY = 1.0  # s before an item is asked for again
RETRIES = 5


@dataclass
class _Upload:
    peer: tuple[int, int]
    mission_type: int
    count: int
    items: list[Any] = field(default_factory=list)  # MISSION_ITEM_INT
    asked_at: float = 0.0
    tries: int = 0


class Missions:
    """`send(msg, peer)` answers the ground station that asked."""

    def __init__(self, bindings: Bindings, sysid: int, compid: int, send: Callable[[Any, tuple[int, int]], None],
                 log: Callable[[str], None] | None = None) -> None:
        self.b = b = bindings
        C, F = b.MavCmd, b.MavFrame
        self.flown = {int(C.MAV_CMD_NAV_WAYPOINT), int(C.MAV_CMD_NAV_TAKEOFF), int(C.MAV_CMD_NAV_LOITER_TIME),
                      int(C.MAV_CMD_NAV_LAND), int(C.MAV_CMD_NAV_RETURN_TO_LAUNCH), int(C.MAV_CMD_NAV_LOITER_UNLIM),
                      int(C.MAV_CMD_DO_CHANGE_SPEED)}
        self.unplaced = {int(C.MAV_CMD_DO_CHANGE_SPEED)}  # items without a position
        self.frames = {int(F.MAV_FRAME_GLOBAL_RELATIVE_ALT), int(F.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT),
                       int(F.MAV_FRAME_GLOBAL), int(F.MAV_FRAME_GLOBAL_INT), int(F.MAV_FRAME_MISSION)}
        self.sysid, self.compid = sysid, compid
        self.send = send
        self.log = log or (lambda text: None)
        self.plans: dict[int, list[Any]] = {}
        self.upload: _Upload | None = None

    def mission(self) -> list[Any]:
        return self.plans.get(int(self.b.MavMissionType.MAV_MISSION_TYPE_MISSION), [])

    def _ack(self, peer: tuple[int, int], result: int, mission_type: int) -> None:
        self.send(self.b.MissionAck(target_system=peer[0], target_component=peer[1], type=result,
                                   mission_type=mission_type), peer)

    def _ask(self, now: float) -> None:
        up = self.upload
        assert up is not None
        up.asked_at = now
        up.tries += 1
        self.send(self.b.MissionRequestInt(target_system=up.peer[0], target_component=up.peer[1],
                                          seq=len(up.items), mission_type=up.mission_type), up.peer)

    def on_message(self, now: float, msg: Any) -> None:
        b, R = self.b, self.b.MavMissionResult
        peer = (msg.get_srcSystem(), msg.get_srcComponent())
        if isinstance(msg, b.MissionCount):
            if msg.count == 0:
                self.plans[msg.mission_type] = []
                self.upload = None
                self._ack(peer, int(R.MAV_MISSION_ACCEPTED), msg.mission_type)
                return
            if msg.count > 1000:
                self._ack(peer, int(R.MAV_MISSION_NO_SPACE), msg.mission_type)
                return
            self.upload = _Upload(peer, msg.mission_type, msg.count)
            self._ask(now)
        elif isinstance(msg, b.MissionItemInt):
            up = self.upload
            if up is None or peer != up.peer:
                return
            if msg.seq != len(up.items):
                if msg.seq < len(up.items):
                    return  # a repeat of one we have
                self._ask(now)  # out of order: ask for the next one we need
                return
            problem = self.check_item(msg) if up.mission_type == int(b.MavMissionType.MAV_MISSION_TYPE_MISSION) \
                else None
            if problem is not None:
                code, why = problem
                self.log(f"mission item {msg.seq} refused: {why}")
                self.upload = None
                self._ack(peer, code, up.mission_type)
                return
            up.items.append(msg)
            up.tries = 0
            if len(up.items) == up.count:
                self.plans[up.mission_type] = up.items
                self.upload = None
                self.log(f"mission of {up.count} items received")
                self._ack(peer, int(R.MAV_MISSION_ACCEPTED), up.mission_type)
            else:
                self._ask(now)
        elif isinstance(msg, b.MissionRequestList):
            plan = self.plans.get(msg.mission_type, [])
            self.send(b.MissionCount(target_system=peer[0], target_component=peer[1], count=len(plan),
                                         mission_type=msg.mission_type), peer)
        elif isinstance(msg, (b.MissionRequestInt, b.MissionRequest)):
            plan = self.plans.get(msg.mission_type, [])
            if msg.seq >= len(plan):
                self._ack(peer, int(R.MAV_MISSION_INVALID_SEQUENCE), msg.mission_type)
                return
            item = plan[msg.seq]
            out = b.MissionItemInt(**{name: getattr(item, name) for name in b.MissionItemInt.FIELDS})
            out.target_system, out.target_component = peer
            self.send(out, peer)
        elif isinstance(msg, b.MissionClearAll):
            types = list(self.plans) if msg.mission_type == int(b.MavMissionType.MAV_MISSION_TYPE_ALL) \
                else [msg.mission_type]
            for t in types:
                self.plans[t] = []
            self._ack(peer, int(R.MAV_MISSION_ACCEPTED), msg.mission_type)
        elif isinstance(msg, b.MissionAck):
            pass  # the end of a download

    def tick(self, now: float) -> None:
        up = self.upload
        if up is not None and now - up.asked_at >= RETRY:
            if up.tries >= RETRIES:
                self.log(f"mission upload from {up.peer[0]}/{up.peer[1]} abandoned: item {len(up.items)} never came")
                self.upload = None
                self._ack(up.peer, int(self.b.MavMissionResult.MAV_MISSION_OPERATION_CANCELLED), up.mission_type)
            else:
                self._ask(now)

    def deadline(self) -> float | None:
        return self.upload.asked_at + RETRY if self.upload is not None else None

    def check_item(self, item: Any) -> tuple[int, str] | None:
        """Why a mission item cannot be flown here, with its MAV_MISSION_RESULT; None if it can."""
        C, R = self.b.MavCmd, self.b.MavMissionResult
        if item.command not in self.flown:
            return int(R.MAV_MISSION_UNSUPPORTED), f"command {item.command} is not supported"
        if item.command in self.unplaced:
            return None
        if item.frame not in self.frames:
            return int(R.MAV_MISSION_UNSUPPORTED_FRAME), f"frame {item.frame} is not supported"
        if item.command in (int(C.MAV_CMD_NAV_WAYPOINT), int(C.MAV_CMD_NAV_TAKEOFF), int(C.MAV_CMD_NAV_LOITER_TIME)):
            lat, lon = self._latlon(item)
            if not (-90 <= lat <= 90 and -180 <= lon <= 180) or not math.isfinite(item.z):
                return int(R.MAV_MISSION_INVALID_PARAM5_X), "position out of range"
        return None

    @staticmethod
    def _latlon(item: Any) -> tuple[float, float]:
        return item.x / 1e7, item.y / 1e7

    def waypoints(self, items: list[Any], home: Home, here: tuple[float, float, float]) -> list[Waypoint]:
        """The mission as the vehicle flies it: positions in metres from home; take-off climbs where
        it is, a land or return ends the list (the caller lands or returns)."""
        C, F = self.b.MavCmd, self.b.MavFrame
        out: list[Waypoint] = []
        n, e, alt = here
        speed: float | None = None
        for item in items:
            if item.command in (int(C.MAV_CMD_NAV_LAND), int(C.MAV_CMD_NAV_RETURN_TO_LAUNCH)):
                break
            if item.command == int(C.MAV_CMD_DO_CHANGE_SPEED):
                speed = float(item.param2) if math.isfinite(item.param2) and item.param2 > 0 else None
                continue
            if item.command == int(C.MAV_CMD_NAV_LOITER_UNLIM):
                continue
            if item.x != 0 or item.y != 0:
                lat, lon = self._latlon(item)
                n = math.radians(lat - home.lat) * EARTH_RADIUS
                e = math.radians(lon - home.lon) * EARTH_RADIUS * math.cos(math.radians(home.lat))
            z = float(item.z)
            if item.frame in (int(F.MAV_FRAME_GLOBAL), int(F.MAV_FRAME_GLOBAL_INT)):
                z -= home.alt  # above mean sea level to above home
            alt = max(0.5, z)
            hold = max(0.0, float(item.param1)) if item.command in (int(C.MAV_CMD_NAV_WAYPOINT),
                                                                    int(C.MAV_CMD_NAV_LOITER_TIME)) else 0.0
            yaw = None if not math.isfinite(item.param4) or item.command == int(C.MAV_CMD_NAV_TAKEOFF) \
                else math.radians(item.param4)
            out.append(Waypoint(n, e, alt, yaw=yaw, speed=speed, hold=hold))
        return out

    def ends_with(self, items: list[Any]) -> str | None:
        """'land' or 'return' if the mission says what to do at its end."""
        C = self.b.MavCmd
        for item in items:
            if item.command == int(C.MAV_CMD_NAV_LAND):
                return "land"
            if item.command == int(C.MAV_CMD_NAV_RETURN_TO_LAUNCH):
                return "return"
        return None
