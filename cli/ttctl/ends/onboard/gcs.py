"""What ground stations (QGroundControl, MAVProxy, MAVSDK) need from a vehicle, sans-IO: the
autopilot component (compid 1) with its HEARTBEAT and telemetry, commands answered with
COMMAND_ACK exactly as MAVLink defines the results (a command in the wrong state DENIED or
TEMPORARILY_REJECTED, an unknown one UNSUPPORTED, never silence), parameters, missions,
REQUEST_MESSAGE / SET_MESSAGE_INTERVAL / REQUEST_DATA_STREAM, and PING.

`on_message(now, msg, link)` takes what a ground station sent on `link`; `tick(now)` returns
(message, link) pairs to send, link None meaning every ground-station link; `wakeup()` says when
to call tick again.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Hashable
from typing import Any

from ...wire.bindings import Bindings
from . import modes, services, telemetry
from .autopilot import INFO, WARNING, Autopilot
from .missions import Missions
from .vehicle import Refused, Snapshot

TARGETED = ("target_system",)
REPEAT = 5.0  # s: a COMMAND_LONG with confirmation > 0 equal to one done this recently is its retry
HISTORY = 8  # commands remembered per peer for that (a retry of the one before the last is still one)
STREAM_MAX_HZ = 50  # REQUEST_DATA_STREAM's ceiling, as ArduPilot's SRn_ stream rates (0-50 Hz)


def _arg(x: float, default: float) -> float:
    """MAVSDK fills unused command params with NaN: NaN means 'the default'."""
    return default if x is None or not math.isfinite(x) else float(x)


class GroundStations:
    def __init__(self, bindings: Bindings, ap: Autopilot, sysid: int, compid: int = 1, boot: float = 0.0,
                 unix: Callable[[float], float] | None = None, log: Callable[[str], None] | None = None) -> None:
        self.b = b = bindings
        self.ap = ap
        self.sysid, self.compid = sysid, compid
        self.boot = boot
        self.unix = unix or (lambda now: now)
        self.log = log or (lambda text: None)
        self._text_id = 0  # the last long STATUSTEXT's id
        self.out: list[tuple[Any, Hashable]] = []
        self._peer_links: dict[tuple[int, int], Hashable] = {}
        self._told_unsupported: set[int] = set()
        self._told_stream_cap = False
        # each peer's last commands (key, when, result): a retry of any of them is answered, not done again
        self._done: dict[tuple[int, int], list[tuple[Any, float, int]]] = {}
        ap.missions = Missions(b, sysid, compid, self._to_peer, self.log)
        self.builders: dict[int, Callable[[Snapshot], Any]] = {
            b.Heartbeat.MSG_ID: lambda s: telemetry.heartbeat(b, s, self.ap.flight.custom_mode(s)),
            b.SysStatus.MSG_ID: lambda s: telemetry.sys_status(b, s),
            b.GlobalPositionInt.MSG_ID: lambda s: telemetry.global_position_int(b, s, self._boot_ms(s)),
            b.LocalPositionNed.MSG_ID: lambda s: telemetry.local_position_ned(b, s, self._boot_ms(s)),
            b.Attitude.MSG_ID: lambda s: telemetry.attitude(b, s, self._boot_ms(s)),
            b.GpsRawInt.MSG_ID: lambda s: telemetry.gps_raw_int(b, s, self._unix_us(s)),
            b.HomePosition.MSG_ID: lambda s: telemetry.home_position(b, s, self._unix_us(s)),
            b.ExtendedSysState.MSG_ID: lambda s: telemetry.extended_sys_state(b, s),
            b.BatteryStatus.MSG_ID: lambda s: telemetry.battery_status(b, s),
            b.VfrHud.MSG_ID: lambda s: telemetry.vfr_hud(b, s),
            **services.streams(b, lambda: self._boot_ms(None), lambda: self._unix_us(None)),
            b.MissionCurrent.MSG_ID: lambda s: telemetry.mission_current(b, s, len(self._mission())),
        }
        ap.attach_missions(ap.missions, emit=lambda msg: self.out.append((msg, None)), warn=self._warn)
        ap.wrap_telemetry(self.builders)
        self.rates = telemetry.Rates(b, self.builders)
        self.now = boot
        self.services = services.Services(b, lambda: self._boot_ms(None), lambda: self._unix_us(None),
                                          lambda: self.rates, warn=self._refusal)

    def _mission(self) -> list[Any]:
        return self.ap.missions.mission() if self.ap.missions is not None else []

    def _boot_ms(self, s: Snapshot | None) -> int:
        return int((self.now - self.boot) * 1000) & 0xFFFFFFFF

    def _unix_us(self, s: Snapshot | None) -> int:
        return int(self.unix(self.now) * 1e6)

    def _refusal(self, text: str) -> None:
        self.log(text)
        self.say(WARNING, text)

    # -- out ------------------------------------------------------------------------------------
    def _to_peer(self, msg: Any, peer: tuple[int, int]) -> None:
        self.out.append((msg, self._peer_links.get(peer)))

    def _warn(self, text: str) -> None:
        self.log(text)
        self.say(WARNING, text)

    def say(self, severity: int, text: str) -> None:
        """STATUSTEXT to every ground station; a text longer than its 50 bytes goes in chunks with
        one id (MAVLink 2's long STATUSTEXT, as PX4 sends it: QGroundControl and MAVSDK join them)."""
        chunks = _chunks(text, 50)[:4]
        if len(chunks) == 1:
            self.out.append((self.b.Statustext(severity=severity, text=chunks[0]), None))
            return
        self._text_id = self._text_id % 65535 + 1
        if len(chunks[-1].encode()) == 50:
            chunks.append("")  # a null ends the sequence
        for i, chunk in enumerate(chunks):
            self.out.append((self.b.Statustext(severity=severity, text=chunk, id=self._text_id, chunk_seq=i), None))

    # -- in ---------------------------------------------------------------------------------------
    def _for_us(self, msg: Any) -> bool:
        ts = getattr(msg, "target_system", 0)
        tc = getattr(msg, "target_component", 0)
        return ts in (0, self.sysid) and tc in (0, self.compid)

    def on_message(self, now: float, msg: Any, link: Hashable = None) -> None:
        self.now = now
        peer = (msg.get_srcSystem(), msg.get_srcComponent())
        if peer[0] == self.sysid:
            return  # ourselves (or our own onboard computer), echoed
        b = self.b
        self._peer_links[peer] = link
        self.ap.heard_gcs(peer[0], now, msg)
        if isinstance(msg, b.Ping):
            if msg.target_system == 0 and msg.target_component == 0:  # a request: answer it
                self._to_peer(b.Ping(time_usec=msg.time_usec, seq=msg.seq, target_system=peer[0],
                                         target_component=peer[1]), peer)
            return
        if not self._for_us(msg):
            return
        if self.services.on_message(now, msg, lambda m: self._to_peer(m, peer), peer):
            return
        if isinstance(msg, b.SetMode):  # PX4 takes SET_MODE as DO_SET_MODE and acknowledges it as one
            msg = b.CommandLong(target_system=self.sysid, target_component=self.compid,
                                command=int(b.MavCmd.MAV_CMD_DO_SET_MODE), confirmation=0,
                                param1=float(msg.base_mode), param2=float((msg.custom_mode >> 16) & 0xFF),
                                param3=float((msg.custom_mode >> 24) & 0xFF), param4=0.0, param5=0.0, param6=0.0,
                                param7=0.0)
        if isinstance(msg, (b.CommandLong, b.CommandInt)):
            key = (peer, type(msg).__name__, msg.command, *(
                "nan" if isinstance(v, float) and math.isnan(v) else v  # NaN (unused: MAVSDK, QGC) equals NaN here
                for v in (msg.param1, msg.param2, msg.param3, msg.param4, getattr(msg, "param5", getattr(msg, "x", 0)),
                          getattr(msg, "param6", getattr(msg, "y", 0)), getattr(msg, "param7", getattr(msg, "z", 0)))))
            done = self._retry_of(now, peer, key, msg)
            if done is not None and msg.command not in self._asks_for_message:
                # a retry of a command done here (its ack was lost on the way, or the tablet's bridge
                # resent it): the same answer again, not done twice (a take-off retried while climbing
                # is not "denied", nor a second take-off). A request for a message is done again: the
                # message may be what the link lost, and PX4 answers every such request
                if msg.command in self.ap.flight_commands:
                    self.log(f"{self._cmd_name(msg.command)} from {peer[0]}/{peer[1]} again: answered as before "
                             f"({self._result_name(done)}), not done twice")
                self._to_peer(b.CommandAck(command=msg.command, result=done, target_system=peer[0],
                                           target_component=peer[1]), peer)
                return
            result, extra = self._command(now, msg)
            history = self._done.setdefault(peer, [])
            history.append((key, now, int(result)))
            del history[:-HISTORY]
            if len(self._done) > 64:  # (strangers on a listening link: each a peer)
                self._done.pop(next(iter(self._done)))
            if msg.command in self.ap.flight_commands:
                self.log(f"{self._cmd_name(msg.command)} from {peer[0]}/{peer[1]}: {self._result_name(int(result))}")
            if result == b.MavResult.MAV_RESULT_ACCEPTED and msg.command in self.ap.flight_commands:
                self.ap.commanded_by(peer[0], now)
            self._to_peer(b.CommandAck(command=msg.command, result=int(result), target_system=peer[0],
                                           target_component=peer[1]), peer)
            for m in extra:
                self._to_peer(m, peer)
        elif isinstance(msg, b.ParamRequestList):
            for m in self.ap.params.all():
                self._to_peer(m, peer)
        elif isinstance(msg, b.ParamRequestRead):
            for m in self.ap.params.read(msg):
                self._to_peer(m, peer)
        elif isinstance(msg, b.ParamSet):
            answers, complaint = self.ap.params.set(msg)
            if complaint:
                self.log(complaint)
                self.say(WARNING, complaint)
            for m in answers:
                self.out.append((m, None))  # every ground station learns the new value
        elif isinstance(msg, b.ManualControl):
            if msg.target in (0, self.sysid):
                self.ap.flight.manual_control(now, msg)
        elif isinstance(msg, (b.SetPositionTargetLocalNed, b.SetPositionTargetGlobalInt)):
            self.ap.flight.set_position_target(now, msg)
        elif isinstance(msg, b.SetAttitudeTarget):
            self.ap.flight.complain(now, "attitude is not flown")  # OFFBOARD stays refused
        elif isinstance(msg, b.RequestDataStream):
            hz = min(msg.req_message_rate, STREAM_MAX_HZ) if msg.start_stop else 0
            if hz < msg.req_message_rate and msg.start_stop and not self._told_stream_cap:
                self._told_stream_cap = True
                self._refusal(f"streams held to {STREAM_MAX_HZ} Hz (asked {msg.req_message_rate} Hz)")
            self.rates.set_all(hz)
        elif isinstance(msg, b.MissionSetCurrent):
            self.ap.set_current(msg.seq)
        elif self.ap.missions is not None and type(msg).__name__.startswith("Mission"):
            self.ap.missions.on_message(now, msg)

    @property
    def _asks_for_message(self) -> tuple[int, ...]:
        C = self.b.MavCmd
        return (int(C.MAV_CMD_REQUEST_MESSAGE), int(C.MAV_CMD_GET_HOME_POSITION),
                int(C.MAV_CMD_REQUEST_AUTOPILOT_CAPABILITIES))

    def _retry_of(self, now: float, peer: tuple[int, int], key: Any, msg: Any) -> int | None:
        """The recorded result when `msg` retries a command this peer had done within REPEAT: a
        COMMAND_LONG with confirmation > 0 (a ground station's retry, or the tablet's bridge resending
        what the link may have lost), or a COMMAND_INT equal to one done (it has no confirmation: the
        bridge's resend and a station's retry look alike, and PX4 takes both as one command)."""
        if getattr(msg, "confirmation", 1) <= 0:
            return None  # a new command, whatever it equals
        A = self.b.MavResult
        for k, when, result in reversed(self._done.get(peer, [])):
            if k == key and now - when < REPEAT:
                # what was done is not done again; what was refused is tried again (the state may have changed)
                return result if result in (A.MAV_RESULT_ACCEPTED, A.MAV_RESULT_IN_PROGRESS) else None
        return None

    def _cmd_name(self, cmd: int) -> str:
        try:
            return str(self.b.MavCmd(cmd).name).removeprefix("MAV_CMD_")
        except ValueError:
            return f"command {cmd}"

    def _result_name(self, result: int) -> str:
        try:
            return str(self.b.MavResult(result).name).removeprefix("MAV_RESULT_")
        except ValueError:
            return f"result {result}"

    def _command(self, now: float, msg: Any) -> tuple[int, list[Any]]:
        C, A = self.b.MavCmd, self.b.MavResult
        cmd = msg.command
        p = [msg.param1, msg.param2, msg.param3, msg.param4]
        v = self.ap.vehicle
        served = self.services.command(msg)
        if served is not None:
            return served
        try:
            if cmd == C.MAV_CMD_COMPONENT_ARM_DISARM:
                if p[0] is None or not math.isfinite(p[0]) or round(p[0]) not in (0, 1):
                    raise Refused("arming: param1 must be 1 (arm) or 0 (disarm)")  # as PX4
                if round(p[0]) == 1:
                    was = v.armed
                    v.arm()
                    if not was:
                        self.ap.flight.armed()
                else:
                    v.disarm()
                return A.MAV_RESULT_ACCEPTED, []
            if cmd == C.MAV_CMD_NAV_TAKEOFF:
                z = msg.param7 if isinstance(msg, self.b.CommandLong) else msg.z
                amsl = float(z) if z is not None and math.isfinite(z) else None
                if amsl is not None and isinstance(msg, self.b.CommandInt) and msg.frame in (
                        int(self.b.MavFrame.MAV_FRAME_GLOBAL_RELATIVE_ALT),
                        int(self.b.MavFrame.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT)):
                    amsl += self.ap.snapshot().home.alt
                self.ap.flight.takeoff(amsl)
                return A.MAV_RESULT_ACCEPTED, []
            if cmd == C.MAV_CMD_NAV_LAND:
                v.land()
                return A.MAV_RESULT_ACCEPTED, []
            if cmd == C.MAV_CMD_NAV_RETURN_TO_LAUNCH:
                v.return_home()
                return A.MAV_RESULT_ACCEPTED, []
            if cmd == C.MAV_CMD_DO_SET_MODE:
                self.ap.flight.set_mode(now, int(_arg(p[0], 0)), int(_arg(p[1], 0)), int(_arg(p[2], 0)))
                return A.MAV_RESULT_ACCEPTED, []
            if cmd == C.MAV_CMD_DO_REPOSITION:
                return self._reposition(msg), []
            if cmd == C.MAV_CMD_MISSION_START:
                first = _arg(p[0], -1)
                self.ap.start_mission(int(first) if first >= 0 and first == int(first) else None)
                return A.MAV_RESULT_ACCEPTED, []
            if cmd == C.MAV_CMD_SET_MESSAGE_INTERVAL:
                ok = self.rates.set_interval(int(_arg(p[0], -1)), _arg(p[1], 0))
                return (A.MAV_RESULT_ACCEPTED if ok else A.MAV_RESULT_UNSUPPORTED), []
            if cmd in (C.MAV_CMD_REQUEST_MESSAGE, C.MAV_CMD_GET_HOME_POSITION,
                       C.MAV_CMD_REQUEST_AUTOPILOT_CAPABILITIES):
                msgid = {C.MAV_CMD_GET_HOME_POSITION: self.b.HomePosition.MSG_ID,
                         C.MAV_CMD_REQUEST_AUTOPILOT_CAPABILITIES: self.b.AutopilotVersion.MSG_ID
                         }.get(cmd, int(_arg(p[0], -1)))
                reply = self._requested(msgid)
                return (A.MAV_RESULT_ACCEPTED, [reply]) if reply is not None else (A.MAV_RESULT_UNSUPPORTED, [])
            position = (msg.x / 1e7, msg.y / 1e7, msg.z) if isinstance(msg, self.b.CommandInt) \
                else (msg.param5, msg.param6, msg.param7)
            mission_result = self.ap.mission_command(int(cmd), p, position)
            if mission_result is not None:
                return mission_result, []
        except Refused as e:
            self.log(f"command {cmd} refused: {e}")
            self.say(WARNING, f"refused: {e}")
            return (A.MAV_RESULT_TEMPORARILY_REJECTED if e.temporary else A.MAV_RESULT_DENIED), []
        self._unsupported(cmd)
        return A.MAV_RESULT_UNSUPPORTED, []

    def _unsupported(self, cmd: int) -> None:
        """An UNSUPPORTED says so in words too, once per command (a ground station asking again and
        again gets the ack each time, not a flood of STATUSTEXT)."""
        if cmd in self._told_unsupported or len(self._told_unsupported) > 256:
            return
        self._told_unsupported.add(cmd)
        try:
            name = self.b.MavCmd(cmd).name.removeprefix("MAV_CMD_")
        except ValueError:
            name = f"command {cmd}"
        self.say(INFO, f"{name} is not supported here")

    def _requested(self, msgid: int) -> Any | None:
        if msgid == self.b.AutopilotVersion.MSG_ID:
            return telemetry.autopilot_version(self.b, self.sysid)
        build = self.builders.get(msgid)
        return build(self.ap.snapshot()) if build is not None else None

    def _reposition(self, msg: Any) -> int:
        b, A = self.b, self.b.MavResult
        s = self.ap.snapshot()
        if isinstance(msg, b.CommandInt):
            unset = (0x7FFFFFFF, 0)  # INT32_MAX (MAVLink) or 0 (older ground stations): "where it is now"
            lat = s.lat if msg.x in unset else msg.x / 1e7
            lon = s.lon if msg.y in unset else msg.y / 1e7
            z = msg.z
            relative = msg.frame in (int(b.MavFrame.MAV_FRAME_GLOBAL_RELATIVE_ALT),
                                     int(b.MavFrame.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT))
        else:
            lat, lon, z = _arg(msg.param5, s.lat), _arg(msg.param6, s.lon), msg.param7
            relative = False
        alt = _arg(z, s.alt_rel if relative else s.alt_msl)
        if not relative:
            alt -= s.home.alt
        if not (-90 <= lat <= 90 and -180 <= lon <= 180):
            raise Refused("position out of range")
        n = math.radians(lat - s.home.lat) * 6_378_137.0
        e = math.radians(lon - s.home.lon) * 6_378_137.0 * math.cos(math.radians(s.home.lat))
        yaw = msg.param4  # radians, as PX4 reads it (QGroundControl and MAVSDK send radians)
        self.ap.vehicle.goto(n, e, alt, float(yaw) if math.isfinite(yaw) else None)
        self.ap.flight.moving = (modes.AUTO, modes.LOITER)  # PX4 flies a reposition in Hold
        return A.MAV_RESULT_ACCEPTED

    # -- time -------------------------------------------------------------------------------------
    def tick(self, now: float) -> list[tuple[Any, Hashable]]:
        self.now = now
        self.out.extend((m, self._peer_links.get(peer)) for m, peer in self.services.tick(now)
                        if isinstance(peer, tuple))  # an FTP burst's next packets
        if self.ap.missions is not None:
            self.ap.missions.tick(now)
        self.out.extend((m, None) for m in self.ap.flight.tick(now))
        due = self.rates.take_due(now)
        if due:
            s = self.ap.snapshot()
            self.out.extend((self.builders[mid](s), None) for mid in due)
        out, self.out = self.out, []
        return out

    def wakeup(self) -> float | None:
        burst = self.services.wakeup()  # an FTP burst under way: its next packets, milliseconds away
        if burst is not None and not self.out:
            return burst
        if self.out:
            return self.now
        times = [t for t in (self.rates.next_due(), self.ap.missions.deadline() if self.ap.missions else None,
                             self.ap.flight.wakeup()) if t is not None]
        return min(times) if times else None


def _chunks(text: str, size: int) -> list[str]:
    """`text` cut into pieces of at most `size` UTF-8 bytes, never inside a character."""
    out: list[str] = []
    cur: list[str] = []
    n = 0
    for ch in text:
        k = len(ch.encode())
        if n + k > size:
            out.append("".join(cur))
            cur, n = [], 0
        cur.append(ch)
        n += k
    out.append("".join(cur))
    return out


__all__ = ["INFO", "GroundStations"]
