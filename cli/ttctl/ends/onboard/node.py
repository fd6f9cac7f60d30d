"""The onboard end as an asyncio node: the vehicle, the tablet's DTT link (a proto Endpoint under
the shared Runner: file transfer, commands, telemetry) and any number of ground-station links
(plain MAVLink 2 over UDP or TCP, the vehicle as component 1), all on one event loop.

Time: `speed` > 1 runs the vehicle's clock faster than the wall clock (tests, rehearsals); the
links keep real time: ground stations get their rates, time_boot_ms and stream timeouts (sticks,
offboard set-points) on the wall clock since start.
"""

from __future__ import annotations

import asyncio
import contextlib
import time
from collections.abc import Callable, Hashable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ...link.transport import Spec, Transport, addr_text, make_transport
from ...proto.commands import Outcome
from ...proto.endpoint import CONTROL, TELEMETRY, Endpoint
from ...proto.storage import ReceiveDir
from ...wire.bindings import Bindings
from ...wire.contract import TtAction as TT
from ...wire.contract import TtResult as RES
from ...wire.v1 import Upgrader, downgrade
from ..plugins import Context, Dispatcher, Plugin
from ..runtime import Runner, unknown_note
from .autopilot import TABLET, Autopilot
from .dtt_gcs import DTT, DttGroundStations
from .gcs import GroundStations
from .gcs_user import UserTraffic, msgid_of
from .setpoints import SetpointDesk
from .trajectory import TrajectoryError, parse_trajectory
from .vehicle import Home, Refused, SimVehicle, State

ONBOARD_COMPID = 240
AUTOPILOT_COMPID = 1
STEP = 0.02  # s of wall clock between vehicle steps in the air
STEP_GROUND = 0.1  # ... and on the ground, disarmed (nothing moves)


@dataclass
class OnboardConfig:
    sysid: int = 1
    dtt: Spec | None = None  # the tablet's link
    gcs: list[Spec] = field(default_factory=list)
    inbox: Path | None = None  # received files (trajectories) go here
    serve: Path | None = None  # files the tablet may fetch
    home: Home = field(default_factory=Home)
    speed: float = 1.0
    rate_Bps: float | None = None  # pacing of the DTT downlink
    mtu: int = 100  # the link's packet size (the profile's: 100 on DJI's DTT, 128 on the Payload SDK channel)
    inbound_Bps: float | None = None  # the DTT uplink's capacity: shared out among incoming files
    telemetry_hz: float = 2.0  # TT_NAV_SAT_FIX and TT_ODOMETRY to the tablet
    orbit_hz: float = 10.0  # the orbit camera's publishing rate while head poses arrive (0: no orbit camera)
    signing: Any = None  # Signing for the DTT link (None: unsigned, signed frames unverified)
    gcs_signing: Any = None  # Signing for the ground-station links (every frame signed, only signed ones taken)
    dtt_gcs_share: float = 0.5  # of the DTT downlink, for the streams of ground stations behind the tablet
    pipe: Any = None  # a MOP pipeline beside the tablet's link (link.pipe.PipeLink), or None
    pipe_Bps: float | None = None  # its rate


class OnboardNode:
    """`bindings`: the dialect on every link (the tablet's and the ground stations'): plugins'
    handlers get its classes, and what it lacks is counted and told once, never a crash.
    Plugins whose messages the dialect lacks are refused here (PluginError)."""

    def __init__(self, bindings: Bindings, cfg: OnboardConfig, plugins: list[Plugin] | None = None,
                 log: Callable[[str], None] | None = None) -> None:
        self.b = bindings
        self.cfg = cfg
        self.log = log or (lambda text: None)
        self.vehicle = SimVehicle(home=cfg.home)
        self.ap = Autopilot(bindings, self.vehicle, cfg.sysid, say=self._say)
        self.ap.clock = time.monotonic  # link-loss timeouts on the wall clock, as the links run
        self.started = 0.0
        self.setpoints = SetpointDesk()
        self.gcs = GroundStations(bindings, self.ap, cfg.sysid, AUTOPILOT_COMPID, unix=self._unix, log=self.log)
        self.gcs_encoder = bindings.encoder(cfg.sysid, AUTOPILOT_COMPID, cfg.gcs_signing)
        self.gcs_links: list[Transport] = []
        self._gcs_v1: dict[tuple[Hashable, Hashable], Upgrader] = {}  # each station's MAVLink 1 upgrader
        self._v1_told: set[Hashable] = set()
        self.dtt_gcs = DttGroundStations(bindings, self.gcs, cfg.sysid, AUTOPILOT_COMPID, cfg.dtt_gcs_share,
                                         cfg.rate_Bps)
        self._gcs_parsers: dict[Hashable, Any] = {}
        self.dispatcher = Dispatcher(on_error=self._plugin_error, dialect=bindings)
        from .orbit_camera import OrbitCameraPlugin

        # --orbit-hz of the wall clock, and CAMERA_FOV_STATUS in the ground stations' time, at any --speed
        orbit = OrbitCameraPlugin(cfg.orbit_hz / (cfg.speed or 1.0), boot_ms=lambda: int(self._wall() * 1000))
        builtin: list[Plugin] = [orbit] if cfg.orbit_hz > 0 else []
        from .vr_controller import VrControllerPlugin

        builtin.append(VrControllerPlugin())  # the controllers' button changes, confirmed to the tablet
        self.plugins = builtin + (plugins or [])
        for p in self.plugins:
            self.dispatcher.add(p)
        # the user's plugins also hear ground stations (the built-in ones serve the tablet's VR)
        self.gcs_dispatcher = Dispatcher(on_error=self._gcs_plugin_error, dialect=bindings)
        for p in plugins or []:
            self.gcs_dispatcher.add(p)
        self.user = UserTraffic(self.log)
        self._stations: dict[tuple[int, int], tuple[Hashable, Hashable]] = {}  # ids -> (link, address)
        self.endpoint: Endpoint | None = None
        self.runner: Runner | None = None
        self.probes: Any = None  # ttctl.link.probes.LinkProbes
        self._wake = asyncio.Event()
        self.vehicle_time = 0.0
        self._tele_due = 0.0
        self._hb_due = 0.0
        self._closed = False
        self._timers: list[list[Any]] = []  # [due, period, fn]
        self._ctx = Context(send=self._send_dtt, log=self.log, sysid=cfg.sysid, compid=ONBOARD_COMPID,
                            vehicle=self.vehicle, every=self._every,
                            send_gcs=lambda msg: self._send_gcs([(msg, None)]), dialect=bindings)
        self._ctx._send_to = self._send_to_station

    # -- wiring ---------------------------------------------------------------------------------
    def _unix(self, now: float) -> float:
        return time.time()

    def _wall(self) -> float:
        """Seconds of the wall clock since start: the ground stations' time, whatever --speed is."""
        return asyncio.get_running_loop().time() - self.started

    def _say(self, severity: int, text: str, urgent: bool = False, tablet: bool = True) -> None:
        """Tell ground stations (STATUSTEXT) and the tablet (TT_LOG; `urgent`: ahead of
        telemetry). A refusal's words reach the tablet with the refusing ack instead
        (`tablet=False`: the endpoint's command server sends them, and again for a retry)."""
        self.log(text)
        self.gcs.say(severity, text)
        if tablet and self.endpoint is not None:
            self.endpoint.say(text, severity, urgent)

    def _plugin_error(self, msg: Any, e: BaseException, where: str) -> None:
        self.log(f"plugin {where} failed on {msg.NAME}: {type(e).__name__}: {e} (the node keeps running)")

    def _gcs_plugin_error(self, msg: Any, e: BaseException, where: str) -> None:
        self.user.failed(where, msg.NAME, e)

    def context(self) -> Context:
        return self._ctx

    def _every(self, seconds: float, fn: Callable[[], None]) -> None:
        self._timers.append([self.vehicle_time + seconds, seconds, fn])

    def _run_timers(self) -> None:
        for timer in self._timers:
            due, period, fn = timer
            if self.vehicle_time >= due:
                timer[0] = max(due + period, self.vehicle_time)
                try:
                    fn()
                except Exception as e:
                    self.log(f"plugin timer {getattr(fn, '__qualname__', fn)} failed: {type(e).__name__}: {e}")

    def _send_dtt(self, msg: Any, urgent: bool = False) -> None:
        if self.endpoint is not None:
            self.endpoint.send_message(msg, CONTROL if urgent else TELEMETRY)

    # -- the tablet's commands ------------------------------------------------------------------
    def tablet_action(self, msg: Any) -> Outcome:
        v = self.vehicle
        p0 = float(msg.param[0]) if msg.param else 0.0
        try:
            if msg.action == TT.TT_ACTION_TAKE_OFF:
                if p0 < 0:  # checked before arming: a refused take-off leaves the vehicle as it was
                    raise Refused(f"take-off altitude {p0:g} m is below 0 (0: the vehicle's default)")
                v.arm()
                v.takeoff(p0 if p0 > 0 else None)
            elif msg.action == TT.TT_ACTION_LAND:
                v.land()
            elif msg.action == TT.TT_ACTION_HOVER:
                v.hover()
            elif msg.action == TT.TT_ACTION_RETURN_HOME:
                v.return_home(p0 if p0 > 0 else None)
            elif msg.action == TT.TT_ACTION_SYNC_TIME:
                pass
            elif msg.action == TT.TT_ACTION_FLY_TRAJECTORY:
                self._fly_file(msg.argument.rstrip("\x00"), p0)
            else:
                return int(RES.TT_RESULT_UNSUPPORTED), f"action {int(msg.action)} is not one this vehicle knows"
        except Refused as e:
            words = f"refused: {e}"
            self._say(4, words, tablet=False)
            return int(RES.TT_RESULT_BUSY if e.temporary else RES.TT_RESULT_DENIED), words
        except TrajectoryError as e:
            words = f"trajectory refused: {e}"
            self._say(4, words, tablet=False)
            return int(RES.TT_RESULT_FAILED), words
        if msg.action != TT.TT_ACTION_SYNC_TIME:
            self.ap.commanded_by(TABLET, self.vehicle_time)  # the tablet's link is the one watched now
        return int(RES.TT_RESULT_ACCEPTED)

    def _fly_file(self, name: str, speed: float) -> None:
        if self.cfg.inbox is None:
            raise TrajectoryError("this vehicle has no inbox for trajectory files")
        from ...proto.names import Refused as NameRefused
        from ...proto.names import check_name

        try:
            check_name(name)
        except NameRefused as e:
            raise TrajectoryError(f"{name!r}: {e.reason}") from None
        path = self.cfg.inbox / name
        try:
            text = path.read_text(encoding="utf-8")
        except OSError as e:
            raise TrajectoryError(f"{name}: {e.strerror or e} (send it first)") from None
        except UnicodeDecodeError:
            raise TrajectoryError(f"{name}: not UTF-8 text") from None
        try:
            route = parse_trajectory(text, self.vehicle.limits.max_alt)
        except TrajectoryError as e:
            raise TrajectoryError(f"{name}: {e}") from None
        if speed > 0:
            for w in route:
                w.speed = speed
        self.ap.fly_trajectory(route, name)

    def _on_tablet_message(self, now: float, msg: Any) -> None:
        self.ap.heard_tablet(self.vehicle_time)
        if isinstance(msg, self.b.DjiPoseStamped) and msg.topic_name == self.b.DjiTopicName.DJI_TOPIC_NAME_SETPOINT:
            self._setpoint(msg)
        self.dispatcher.dispatch(msg, self._ctx)

    def _setpoint(self, msg: Any) -> None:
        """Fly the tablet's set-point and answer it (setpoints.py): echoed if flown, the reason said if not."""
        x, y, z = (float(v) for v in msg.position)

        def fly() -> None:
            self.vehicle.goto(x, y, z)
            self.ap.commanded_by(TABLET, self.vehicle_time)

        src = (msg.get_srcSystem(), msg.get_srcComponent())
        answer, repeat = self.setpoints.handle(src, (int(msg.sec), int(msg.nsec)), fly)
        if not answer.flown:
            if not repeat:
                self._say(4, answer.words, urgent=True)  # the log, ground stations and the tablet
            elif self.endpoint is not None:
                self.endpoint.say(answer.words, 4, urgent=True)  # the tablet asked again: its words were lost
            return
        if self.endpoint is not None:
            echo = self.b.DjiPoseStamped(target_system=src[0], sec=msg.sec, nsec=msg.nsec, topic_name=msg.topic_name,
                                         position=list(msg.position), orientation=list(msg.orientation))
            self.endpoint.send_message(echo, CONTROL)

    # -- telemetry to the tablet ----------------------------------------------------------------
    def _tablet_telemetry(self) -> None:
        if self.endpoint is None:
            return
        s = self.vehicle.snapshot()
        unix_us = int(time.time() * 1e6)
        b = self.b
        fix = b.TtNavSatFix(time_usec=unix_us, latitude=round(s.lat * 1e7), longitude=round(s.lon * 1e7),
                            altitude=s.alt_msl, position_covariance=[0.64, 0, 0, 0, 0.64, 0, 0, 0, 1.44],
                            status=int(b.TtFixType.TT_FIX_TYPE_FIX),
                            service=int(b.TtGnssService.TT_GNSS_SERVICE_GPS),
                            covariance_type=int(b.TtCovarianceType.TT_COVARIANCE_TYPE_DIAGONAL_KNOWN),
                            satellites=14)
        import math

        cy, sy = math.cos(s.yaw / 2), math.sin(s.yaw / 2)
        cp, sp = math.cos(s.pitch / 2), math.sin(s.pitch / 2)
        cr, sr = math.cos(s.roll / 2), math.sin(s.roll / 2)
        q = [sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy, cr * cp * sy - sr * sp * cy,
             cr * cp * cy + sr * sp * sy]  # x, y, z, w of the NED (FRD) attitude
        odo = b.TtOdometry(time_usec=unix_us, frame_id=int(b.TtFrame.TT_FRAME_WORLD_NED),
                           child_frame_id=int(b.TtFrame.TT_FRAME_WORLD_NED), position=[s.n, s.e, s.d],
                           orientation=q, linear=[s.vn, s.ve, s.vd], angular=[0.0, 0.0, s.yaw_rate],
                           pose_variance=[0.25, 0.25, 0.5, 0.01, 0.01, 0.02])
        self.endpoint.send_message(fix, TELEMETRY)
        self.endpoint.send_message(odo, TELEMETRY)

    # -- running ---------------------------------------------------------------------------------
    async def start(self) -> None:
        loop = asyncio.get_running_loop()
        self.started = loop.time()
        self.gcs.boot = self.gcs.now = 0.0
        for spec in self.cfg.gcs:  # UDP or TCP (tcpin: ground stations connect; tcp: we connect to one)
            t = make_transport(spec, log=self._logger(str(spec)), mtu=65535)
            t.on_receive = self._receiver(t)
            t.on_close = self._closer(t)
            await t.open()
            self.gcs_links.append(t)
        store = ReceiveDir(self.cfg.inbox) if self.cfg.inbox is not None else None
        self.gcs.services.ftp.serve, self.gcs.services.ftp.inbox = self.cfg.serve, store  # MAVLink FTP's tree
        if self.cfg.dtt is not None:
            transport: Transport = make_transport(self.cfg.dtt, log=lambda text: self.log(f"dtt: {text}"),
                                                  mtu=self.cfg.mtu if self.cfg.dtt.udp else None)
            self.endpoint = Endpoint(self.b, self.cfg.sysid, ONBOARD_COMPID, mtu=transport.mtu,
                                     rate_Bps=self.cfg.rate_Bps, receive_dir=store, inbound_Bps=self.cfg.inbound_Bps,
                                     serve_dir=str(self.cfg.serve) if self.cfg.serve else None,
                                     action=self.tablet_action, on_message=self._on_tablet_message,
                                     on_event=self._file_event, signing=self.cfg.signing,
                                     clock_ms=lambda now: int(self.vehicle_time * 1000), divert=self._from_dtt_gcs)
            self.dtt_gcs.attach(self.endpoint)
            self.runner = Runner(self.endpoint, transport, probes=self._probes(transport), pipe=self.cfg.pipe,
                                 pipe_rate_Bps=self.cfg.pipe_Bps)
            await self.runner.start()
        if store is not None:
            store.prepare()
        ctx = self.context()
        for p in self.plugins:
            try:
                p.start(ctx)
            except Exception as e:
                self.log(f"plugin {type(p).__name__} failed to start: {type(e).__name__}: {e}")

    def _probes(self, transport: Transport) -> Any:
        """`ttctl bench link --to` answered on the DTT link (datagram links only, and not where
        --key asks for signed frames only: a peer without the key gets no answer at all)."""
        signing = self.cfg.signing
        if transport.stream or not hasattr(transport, "send_to") or (
                signing is not None and not getattr(signing, "allow_unsigned", False)):
            return None
        from ...link.probes import LinkProbes

        assert self.endpoint is not None
        self.probes = LinkProbes(transport.send_to, self.endpoint.mid_frame, lambda text: self.log(f"dtt: {text}"))
        return self.probes

    def _logger(self, where: str) -> Callable[[str], None]:
        return lambda text: self.log(f"{where}: {text}")

    def _receiver(self, link: Transport) -> Callable[[bytes, Hashable], None]:
        def receive(data: bytes, source: Hashable) -> None:
            # each peer's parser checks signatures with --gcs-key (frames that fail are dropped, said once)
            parser = self._gcs_parsers.get((link, source))
            if parser is None:
                parser = self._gcs_parsers[(link, source)] = self.b.parser(self.cfg.gcs_signing)
            refused = parser.stats.bad_signature
            self._from_gcs(link, data, source)
            if refused == 0 and parser.stats.bad_signature:
                who = addr_text(source) if isinstance(source, tuple) else getattr(source, "name", "a connection")
                self.log(f"{link.spec}: ignoring {who}: unsigned frames or signatures that do not verify "
                         "(the same --gcs-key at both ends?)")

        return receive

    def _closer(self, link: Transport) -> Callable[[Hashable], None]:
        """A TCP connection ended: its parser (and any half frame in it) goes with it."""
        def closed(source: Hashable) -> None:
            self._gcs_parsers.pop((link, source), None)
            self._gcs_v1.pop((link, source), None)

        return closed

    def _file_event(self, what: str, t: Any) -> None:
        if what == "link-refused":
            self.log(f"dtt: ignoring {addr_text(t[0])}: {t[1]} (the same --key at both ends?)")
        elif what == "unknown-message":
            self.log(f"dtt: {unknown_note(self.b, t)}")
        elif what == "file-complete":
            how = f", deflated to {t.size} B on the link" if t.original is not None else ""
            self._say(6, f"received {t.name} ({t.file_size} bytes){how}")  # the file's size, not its stream's
        elif what in ("file-accepted", "file-busy", "file-refused", "file-failed"):
            self.log(f"dtt: {incoming_text(what, t)}")  # as `recv-file` says them


    def _from_gcs(self, link: Transport, data: bytes, source: Hashable) -> None:
        parser = self._gcs_parsers.get((link, source))
        if parser is None:
            parser = self._gcs_parsers[(link, source)] = self.b.parser()
        v1 = self._gcs_v1.get((link, source))
        if v1 is None:
            if len(self._gcs_v1) >= 64:
                self._gcs_v1.pop(next(iter(self._gcs_v1)))
            v1 = self._gcs_v1[(link, source)] = Upgrader(self.b.registry)
        data = v1.feed(data, not link.stream)  # MAVLink 1 re-framed as MAVLink 2, the rest as it came
        if v1.saw_v1 and not v1.saw_v2 and link.spec.kind != "udpout" and link not in self._v1_told:
            self._v1_told.add(link)
            self.log(f"{link.spec}: a ground station there speaks MAVLink 1: its frames are taken, but answers "
                     f"on a listening link go as MAVLink 2 (give it --gcs udpout:HOST:PORT, where it listens, "
                     f"or set it to MAVLink 2)")
        now = self._wall()
        unknown = parser.stats.unknown
        for msg in parser.feed(data):
            src = (msg.get_srcSystem(), msg.get_srcComponent())
            link.confirm(source, {src})  # a udpin link learns its peers
            self.gcs.on_message(now, msg, link)
            if src[0] != self.cfg.sysid:
                self._remember_station(src, link, source)
                self._deliver_gcs(now, msg, link, source)
        if parser.stats.unknown > unknown:
            who = addr_text(source) if isinstance(source, tuple) else getattr(source, "name", "a connection")
            self.user.unknown_id(f"{link.spec}: ground station at {who}", msgid_of(data), self.b.name,
                                 parser.stats.unknown - unknown)
        self._wake.set()

    # -- the user's messages from ground stations ---------------------------------------------------
    def _remember_station(self, src: tuple[int, int], link: Hashable, address: Hashable) -> None:
        if src not in self._stations and len(self._stations) >= 64:
            self._stations.pop(next(iter(self._stations)))
        self._stations[src] = (link, address)

    def _deliver_gcs(self, now: float, msg: Any, link: Hashable, address: Hashable) -> None:
        """A ground station's message that user plugins handle: to them (at most gcs_user.RATE a
        second per station), their `ctx.reply` back to that station on the link it came in on."""
        if not self.gcs_dispatcher.handlers_for(msg.MSG_ID):
            return
        if getattr(msg, "target_system", 0) not in (0, self.cfg.sysid):
            return  # another vehicle's (a ground station's link may be shared by a fleet)
        src = (msg.get_srcSystem(), msg.get_srcComponent())
        if not self.user.admit(now, src, msg.NAME):
            return
        self.gcs_dispatcher.dispatch(msg, self._ctx, reply=lambda m, urgent: self._to_station(m, link, address),
                                     source="gcs")

    def _to_station(self, msg: Any, link: Hashable, address: Hashable) -> None:
        self.user.stats.replies += 1
        if link is DTT:
            self.dtt_gcs.send_user(msg)
            if self.runner is not None:
                self.runner.kick()
            return
        if not isinstance(link, Transport):
            return
        out = self._in_kind(link, self.gcs_encoder.encode(msg))
        if out is None:
            return
        send_to = getattr(link, "send_to", None)
        if send_to is not None and isinstance(address, tuple):
            send_to(out, address)
        else:
            link.send(out)

    def _send_to_station(self, msg: Any, peer: tuple[int, int]) -> None:
        """`ctx.send_gcs(msg, to=...)`: to the station heard with those ids (compid 0: any)."""
        hit = self._stations.get(peer)
        if hit is None and peer[1] == 0:
            hit = next((v for k, v in reversed(self._stations.items()) if k[0] == peer[0]), None)
        if hit is None:
            raise ValueError(f"no ground station {peer[0]}/{peer[1]} was heard here")
        self._to_station(msg, *hit)

    def _from_dtt_gcs(self, now: float, msg: Any) -> bool:
        """A ground station's frame over DTT (dtt_gcs.py): the vehicle takes it as on its own links."""
        if not self.dtt_gcs.takes(msg):
            return False
        self.dtt_gcs.heard(now)
        self.gcs.on_message(self._wall(), msg, DTT)
        src = (msg.get_srcSystem(), msg.get_srcComponent())
        self._remember_station(src, DTT, None)
        self._deliver_gcs(self._wall(), msg, DTT, None)
        self._wake.set()
        return True

    def _send_gcs(self, pairs: list[tuple[Any, Hashable]]) -> None:
        now = asyncio.get_running_loop().time()
        behind_tablet = self.dtt_gcs.present(now)
        heartbeat = self.b.Heartbeat
        for msg, link in pairs:
            # the autopilot's HEARTBEAT goes down DTT whether or not a ground station is there yet:
            # one connecting to the tablet's bridge learns the vehicle (and its autopilot type, by
            # which MAVProxy decodes parameters) before it asks for anything; 21 bytes a second
            if link is DTT or (link is None and (behind_tablet or isinstance(msg, heartbeat))):
                self.dtt_gcs.send(now, msg, link is None)
                if link is DTT:
                    continue
            if not self.gcs_links:
                continue
            frame = self.gcs_encoder.encode(msg)
            for t in self.gcs_links:
                if link is None or link is t:
                    out = self._in_kind(t, frame)
                    if out is not None:
                        t.send(out)
        if behind_tablet and self.runner is not None:
            self.runner.kick()

    def _in_kind(self, link: Transport, frame: bytes) -> bytes | None:
        """A frame for a udpout ground-station link as its one station reads it: MAVLink 1 if it
        speaks only that; None for what MAVLink 1 cannot carry (ids over 255: said once)."""
        if link.spec.kind != "udpout" or self.cfg.gcs_signing is not None:  # (MAVLink 1 has no signatures)
            return frame
        for (t, _), v1 in self._gcs_v1.items():
            if t is link and v1.saw_v1 and not v1.saw_v2:
                old = downgrade(frame, self.b.registry)
                if old is not None:
                    return old
                msgid = frame[7] | frame[8] << 8 | frame[9] << 16
                if (link, msgid) not in self._v1_told and len(self._v1_told) < 32:
                    self._v1_told.add((link, msgid))
                    info = self.b.registry.get(msgid)
                    self.log(f"{link.spec}: not sending {info.cls.NAME if info else msgid} to a MAVLink 1 ground "
                             f"station: MAVLink 1 carries message ids up to 255 (set it to MAVLink 2 to get it)")
                return None
        return frame

    async def run(self, stop: asyncio.Event) -> None:
        loop = asyncio.get_running_loop()
        last = loop.time()
        while not stop.is_set() and not self._closed:
            now = loop.time()
            dt = (now - last) * self.cfg.speed
            last = now
            self.vehicle_time += dt
            self.ap.step(self.vehicle_time, dt)
            self._run_timers()
            wall = now - self.started
            self._send_gcs(self.gcs.tick(wall))
            if self.endpoint is not None:
                # on the wall clock, as the link runs, whatever --speed is (on the vehicle's clock, at
                # --speed 4 they took four times their share of the downlink from the tablet's downloads)
                if wall >= self._hb_due:
                    self.endpoint.send_message(telemetry_heartbeat(self.b, self.vehicle.snapshot()))
                    self._hb_due = wall + 1.0
                if self.cfg.telemetry_hz > 0 and wall >= self._tele_due:
                    self._tablet_telemetry()
                    self._tele_due = wall + 1.0 / self.cfg.telemetry_hz
                if self.runner is not None:
                    self.runner.kick()
            self._wake.clear()
            idle = self.vehicle.state is State.LANDED and not self.vehicle.armed
            step = STEP_GROUND if idle else STEP
            gcs_due = self.gcs.wakeup()
            if gcs_due is not None:
                step = min(step, max(0.001, gcs_due - wall))
            timer_due = min((t[0] for t in self._timers), default=None)
            if timer_due is not None:
                step = min(step, max(0.001, (timer_due - self.vehicle_time) / self.cfg.speed))
            with contextlib.suppress(TimeoutError):
                await asyncio.wait_for(self._wake.wait(), step)

    async def close(self) -> None:
        self._closed = True
        if self.user.stats != type(self.user.stats)():
            self.log(self.user.summary())
        for p in self.plugins:
            with contextlib.suppress(Exception):
                p.stop()
        if self.endpoint is not None:
            self.endpoint.close()
        if self.probes is not None:
            self.probes.close()
        self.gcs.services.ftp.close()  # a write not finished is discarded
        if self.runner is not None:
            await self.runner.close()
        for t in self.gcs_links:
            t.close()


def telemetry_heartbeat(b: Bindings, s: Any) -> Any:
    from .telemetry import heartbeat

    hb = heartbeat(b, s)
    hb.type = int(b.MavType.MAV_TYPE_ONBOARD_CONTROLLER)
    hb.autopilot = int(b.MavAutopilot.MAV_AUTOPILOT_INVALID)
    return hb


def incoming_text(what: str, t: Any) -> str:
    """An incoming transfer's accept, wait, refusal or failure in words, the receiver's own
    reason included (the lines `recv-file` prints)."""
    name, peer = t.name or "?", f"{t.key[0]}/{t.key[1]}"
    if what == "file-accepted":
        have = t.partial.ranges.total() if t.partial is not None else 0
        how = f", deflated to {t.size} B on the link" if t.original is not None else ""
        return f"accepted {name} ({t.file_size} bytes) from {peer}{how}" + (
            f", resuming with {have} bytes already here" if have else "")
    if what == "file-busy":
        return f"{name} from {peer} waits: {t.reason}"
    if what == "file-refused":
        return f"refused {name} from {peer}: {t.reason}"
    return f"failed {name} from {peer}: {t.reason}"


__all__ = ["OnboardConfig", "OnboardNode", "State"]
