"""The MAVLink mission protocol on the vehicle's side, sans-IO: upload (MISSION_COUNT, then a
MISSION_REQUEST_INT per item, re-asked when an item does not come; an item that comes before
it is asked for is kept, as a bridge over a slow link sends them ahead: ground stations send
only what is asked, so on their own links nothing changes), download
(MISSION_REQUEST_LIST, MISSION_COUNT, MISSION_ITEM_INT per request) and clear. Mission, fence
and rally plans are kept apart, by mission_type, as the protocol asks. An item the vehicle
cannot fly (or a fence or rally item it cannot honour) is refused at upload with the MAVLink
result that says why, naming the item, as PX4's mission feasibility checks do; the mission is
flown by mission_run.py, the fence and rally points used by safety.py.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from ...wire.bindings import Bindings

RETRY = 0.25  # s before an item is asked for again: PX4's MAVLINK_MISSION_RETRY_TIMEOUT_DEFAULT (mavlink_mission.h)
RETRIES = 20  # (5 s without an item: PX4's MAVLINK_MISSION_PROTOCOL_TIMEOUT_DEFAULT)
GAP_ASK = 0.15  # s: a later item came while one is missing (the link keeps order: it was lost): ask for it
# again, at most this often (a resend is then on its way)


@dataclass
class _Upload:
    peer: tuple[int, int]
    mission_type: int
    count: int
    items: list[Any] = field(default_factory=list)  # MISSION_ITEM_INT
    ahead: dict[int, Any] = field(default_factory=dict)  # items that came before an earlier one
    asked_at: float = 0.0
    tries: int = 0
    denied_to: tuple[int, int] | None = None  # the last other station told its upload was denied


class Missions:
    """`send(msg, peer)` answers the ground station that asked."""

    def __init__(self, bindings: Bindings, sysid: int, compid: int, send: Callable[[Any, tuple[int, int]], None],
                 log: Callable[[str], None] | None = None, warn: Callable[[str], None] | None = None,
                 on_plan: Callable[[int], None] | None = None) -> None:
        self.b = b = bindings
        C, F = b.MavCmd, b.MavFrame
        self.placed = {int(C.MAV_CMD_NAV_WAYPOINT), int(C.MAV_CMD_NAV_TAKEOFF), int(C.MAV_CMD_NAV_LOITER_TIME),
                       int(C.MAV_CMD_NAV_LAND), int(C.MAV_CMD_NAV_LOITER_UNLIM), int(C.MAV_CMD_DO_SET_ROI_LOCATION),
                       int(C.MAV_CMD_DO_SET_ROI)}
        self.unplaced = {int(C.MAV_CMD_DO_CHANGE_SPEED), int(C.MAV_CMD_NAV_DELAY), int(C.MAV_CMD_DO_JUMP),
                         int(C.MAV_CMD_CONDITION_YAW), int(C.MAV_CMD_DO_SET_ROI_NONE),
                         int(C.MAV_CMD_DO_LAND_START)}  # items without a position
        self.flown = self.placed | self.unplaced | {int(C.MAV_CMD_NAV_RETURN_TO_LAUNCH)}
        self.cmd_names = {int(v): k.removeprefix("MAV_CMD_") for k, v in C.__members__.items()}
        self.fence_items = {int(C.MAV_CMD_NAV_FENCE_POLYGON_VERTEX_INCLUSION),
                            int(C.MAV_CMD_NAV_FENCE_POLYGON_VERTEX_EXCLUSION),
                            int(C.MAV_CMD_NAV_FENCE_CIRCLE_INCLUSION), int(C.MAV_CMD_NAV_FENCE_CIRCLE_EXCLUSION)}
        # NAV_FENCE_RETURN_POINT is refused: a breach's return goes home or to a rally point, as on PX4
        self.rally_items = {int(C.MAV_CMD_NAV_RALLY_POINT)}
        self.frames = {int(F.MAV_FRAME_GLOBAL_RELATIVE_ALT), int(F.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT),
                       int(F.MAV_FRAME_GLOBAL), int(F.MAV_FRAME_GLOBAL_INT), int(F.MAV_FRAME_MISSION)}
        self.sysid, self.compid = sysid, compid
        self.send = send
        self.log = log or (lambda text: None)
        self.warn = warn or self.log  # a refusal's words, for the ground station (STATUSTEXT)
        self.on_plan = on_plan or (lambda mission_type: None)  # a plan was replaced
        self.altitude_problem: Callable[[Any], str | None] = lambda item: None  # why the vehicle cannot fly at it
        self.plans: dict[int, list[Any]] = {}
        self.upload: _Upload | None = None
        self.done: tuple[tuple[int, int], int, int, float] | None = None  # the last upload: peer, type, count, when

    def mission(self) -> list[Any]:
        return self.plans.get(int(self.b.MavMissionType.MAV_MISSION_TYPE_MISSION), [])

    def fence(self) -> list[Any]:
        return self.plans.get(int(self.b.MavMissionType.MAV_MISSION_TYPE_FENCE), [])

    def rally(self) -> list[Any]:
        return self.plans.get(int(self.b.MavMissionType.MAV_MISSION_TYPE_RALLY), [])

    def _ack(self, peer: tuple[int, int], result: int, mission_type: int) -> None:
        self.send(self.b.MissionAck(target_system=peer[0], target_component=peer[1], type=result,
                                   mission_type=mission_type), peer)

    def _global(self, frame: int) -> bool:
        F = self.b.MavFrame
        return frame in (int(F.MAV_FRAME_GLOBAL), int(F.MAV_FRAME_GLOBAL_RELATIVE_ALT), int(F.MAV_FRAME_GLOBAL_INT),
                         int(F.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT), int(F.MAV_FRAME_GLOBAL_TERRAIN_ALT))

    def _as_int(self, msg: Any) -> Any:
        """A legacy MISSION_ITEM (latitude and longitude in float degrees) as a MISSION_ITEM_INT;
        a position that is not a number becomes one out of range (refused as such)."""
        item = self.b.MissionItemInt(**{name: getattr(msg, name) for name in self.b.MissionItemInt.FIELDS
                                        if name not in ("x", "y")})
        scale = 1e7 if self._global(msg.frame) else 1.0
        for name in ("x", "y"):
            v = float(getattr(msg, name)) * scale
            setattr(item, name, round(v) if math.isfinite(v) and abs(v) < 2**31 - 1 else 2**31 - 1)
        item._mav_sysid, item._mav_compid = msg.get_srcSystem(), msg.get_srcComponent()
        return item

    def _check(self, item: Any, up: _Upload) -> tuple[int, str] | None:
        T, R = self.b.MavMissionType, self.b.MavMissionResult
        if up.mission_type == int(T.MAV_MISSION_TYPE_MISSION):
            return self.check_item(item, up.count)
        allowed = self.fence_items if up.mission_type == int(T.MAV_MISSION_TYPE_FENCE) else \
            self.rally_items if up.mission_type == int(T.MAV_MISSION_TYPE_RALLY) else set()
        name = self._name(item.command)
        if item.command not in allowed:
            return int(R.MAV_MISSION_UNSUPPORTED), f"{name} is not a {self._type_name(up.mission_type)} item"
        if not (-90 <= item.x / 1e7 <= 90 and -180 <= item.y / 1e7 <= 180):
            return int(R.MAV_MISSION_INVALID_PARAM5_X), f"{name}: position out of range"
        if item.command in (int(self.b.MavCmd.MAV_CMD_NAV_FENCE_CIRCLE_INCLUSION),
                            int(self.b.MavCmd.MAV_CMD_NAV_FENCE_CIRCLE_EXCLUSION)) \
                and not (math.isfinite(item.param1) and item.param1 > 0):
            return int(R.MAV_MISSION_INVALID_PARAM1), f"{name}: radius {item.param1:g} m"
        if item.command in (int(self.b.MavCmd.MAV_CMD_NAV_FENCE_POLYGON_VERTEX_INCLUSION),
                            int(self.b.MavCmd.MAV_CMD_NAV_FENCE_POLYGON_VERTEX_EXCLUSION)) \
                and not (math.isfinite(item.param1) and 3 <= item.param1 <= up.count):
            return int(R.MAV_MISSION_INVALID_PARAM1), f"{name}: {item.param1:g} vertices"
        return None

    def _type_name(self, mission_type: int) -> str:
        T = self.b.MavMissionType
        return {int(T.MAV_MISSION_TYPE_MISSION): "mission", int(T.MAV_MISSION_TYPE_FENCE): "fence",
                int(T.MAV_MISSION_TYPE_RALLY): "rally"}.get(mission_type, f"mission type {mission_type}")

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
            up = self.upload
            if up is not None and peer != up.peer:
                # another station's upload is under way: a second transaction is denied, as PX4 denies
                # it (MAV_MISSION_DENIED), and the first goes on (it would otherwise time out)
                self._ack(peer, int(R.MAV_MISSION_DENIED), msg.mission_type)
                if up.denied_to != peer:
                    up.denied_to = peer
                    self.warn(f"mission upload from {peer[0]}/{peer[1]} denied: one from {up.peer[0]}/{up.peer[1]}"
                              f" is in progress")
                return
            if self.done is not None and self.done[0] == peer:
                self.done = None  # (another station's finished upload may still need its ack again)
            if msg.count == 0:
                self.plans[msg.mission_type] = []
                self.upload = None
                self._ack(peer, int(R.MAV_MISSION_ACCEPTED), msg.mission_type)
                self.on_plan(msg.mission_type)
                return
            if msg.count > 1000:
                self._ack(peer, int(R.MAV_MISSION_NO_SPACE), msg.mission_type)
                return
            self.upload = _Upload(peer, msg.mission_type, msg.count)
            self._ask(now)
        elif isinstance(msg, (b.MissionItemInt, b.MissionItem)):
            if isinstance(msg, b.MissionItem):
                msg = self._as_int(msg)
            up = self.upload
            if (up is None or peer != up.peer) and self.done is not None:
                # the last item again: our ack was lost (also while another station's upload has begun)
                who, kind, count, when = self.done
                if (who, kind, count - 1) == (peer, msg.mission_type, msg.seq) and now - when < 10:
                    self._ack(peer, int(R.MAV_MISSION_ACCEPTED), kind)
                    return
            if up is None or peer != up.peer:
                return
            if msg.seq != len(up.items):
                if msg.seq < len(up.items) or msg.seq >= up.count:
                    return  # a repeat of one we have, or none of this plan
                up.ahead[msg.seq] = msg  # ahead of one still missing: kept, and the missing one asked again
                if now - up.asked_at >= GAP_ASK:
                    self._ask(now)
                return
            while msg is not None:
                problem = self._check(msg, up)
                if problem is not None:
                    code, why = problem
                    self.upload = None
                    self._ack(peer, code, up.mission_type)
                    self.warn(f"item {msg.seq} refused: {why}")  # the words follow the refusal
                    return
                up.items.append(msg)
                msg = up.ahead.pop(len(up.items), None)
            up.tries = 0
            if len(up.items) == up.count:
                self.plans[up.mission_type] = up.items
                self.upload = None
                self.done = (peer, up.mission_type, up.count, now)
                self.log(f"{self._type_name(up.mission_type)} of {up.count} items received")
                self._ack(peer, int(R.MAV_MISSION_ACCEPTED), up.mission_type)
                self.on_plan(up.mission_type)
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
            legacy = isinstance(msg, b.MissionRequest)  # answered in kind, as PX4 does
            out = (b.MissionItem if legacy else b.MissionItemInt)(
                **{name: getattr(item, name) for name in b.MissionItemInt.FIELDS})
            if legacy and self._global(item.frame):
                out.x, out.y = item.x / 1e7, item.y / 1e7
            out.target_system, out.target_component = peer
            self.send(out, peer)
        elif isinstance(msg, b.MissionClearAll):
            types = list(self.plans) if msg.mission_type == int(b.MavMissionType.MAV_MISSION_TYPE_ALL) \
                else [msg.mission_type]
            for t in types:
                self.plans[t] = []
            self._ack(peer, int(R.MAV_MISSION_ACCEPTED), msg.mission_type)
            for t in types:
                self.on_plan(t)
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

    def _name(self, command: int) -> str:
        return self.cmd_names.get(command, f"command {command}")

    def check_item(self, item: Any, count: int = 0) -> tuple[int, str] | None:
        """Why a mission item cannot be flown here, with its MAV_MISSION_RESULT; None if it can.
        `count`: the mission's length (DO_JUMP's target must be in it)."""
        C, R = self.b.MavCmd, self.b.MavMissionResult
        name, cmd = self._name(item.command), item.command
        if cmd not in self.flown:
            return int(R.MAV_MISSION_UNSUPPORTED), f"{name} is not supported"
        params = (item.param1, item.param2, item.param3, item.param4)
        if cmd == int(C.MAV_CMD_DO_JUMP):
            if not (math.isfinite(item.param1) and 0 <= item.param1 < count and int(item.param1) != item.seq):
                return int(R.MAV_MISSION_INVALID_PARAM1), f"{name} to item {item.param1:g}: no such item"
            if not (math.isfinite(item.param2) and 0 <= item.param2 <= 10_000):
                return int(R.MAV_MISSION_INVALID_PARAM2), f"{name} repeat {item.param2:g}: 0..10000 only"
            return None
        if cmd == int(C.MAV_CMD_NAV_DELAY):
            if not math.isfinite(item.param1):
                return int(R.MAV_MISSION_INVALID_PARAM1), f"{name} delay is not a number"
            if item.param1 < 0:
                return int(R.MAV_MISSION_UNSUPPORTED), f"{name} until a time of day is not supported"
            return None
        if cmd == int(C.MAV_CMD_CONDITION_YAW):
            if not all(math.isfinite(x) for x in params):
                return int(R.MAV_MISSION_INVALID_PARAM1), f"{name} needs an angle"
            return None
        if cmd == int(C.MAV_CMD_DO_SET_ROI) and int(_finite(item.param1)) not in (0, 3):
            return int(R.MAV_MISSION_UNSUPPORTED), f"{name} mode {item.param1:g}: only none and location"
        if cmd in self.unplaced:
            return None
        if item.frame not in self.frames:
            return int(R.MAV_MISSION_UNSUPPORTED_FRAME), f"{name}: frame {item.frame} is not supported"
        if cmd == int(C.MAV_CMD_NAV_LOITER_TIME) and not (math.isfinite(item.param1) and item.param1 >= 0):
            return int(R.MAV_MISSION_INVALID_PARAM1), f"{name}: loiter time {item.param1:g} s"
        if cmd in self.placed:
            lat, lon = item.x / 1e7, item.y / 1e7
            if not (-90 <= lat <= 90 and -180 <= lon <= 180):
                return int(R.MAV_MISSION_INVALID_PARAM5_X), f"{name}: position out of range"
            if cmd not in (int(C.MAV_CMD_DO_SET_ROI_LOCATION), int(C.MAV_CMD_DO_SET_ROI), int(C.MAV_CMD_NAV_LAND)):
                if not math.isfinite(item.z):
                    return int(R.MAV_MISSION_INVALID_PARAM7), f"{name}: altitude is not a number"
                why = self.altitude_problem(item)
                if why is not None:
                    return int(R.MAV_MISSION_INVALID_PARAM7), f"{name}: {why}"
        return None


def _finite(x: float, default: float = -1.0) -> float:
    return float(x) if math.isfinite(x) else default
