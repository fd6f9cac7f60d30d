"""The tablet end as a telemetry radio for ground stations: `emulate tablet --gcs ENDPOINT`.

QGroundControl, MAVProxy, MAVSDK connect to the tablet's ground-station links as to a radio, and
see the vehicle behind the onboard end (its autopilot, compid 1) over the DTT link. The rules
are sans-IO in ttctl.bridge (uplink.py: the queue toward the vehicle, routes.py: who gets what
back, RADIO_STATUS); this is their wiring on the event loop: a transport per ground-station link,
the tablet's Endpoint pulling the uplink queue as a bulk source (below the app's own commands)
and handing over every frame the vehicle sends to ground stations (`divert`).
"""

from __future__ import annotations

import asyncio
from collections.abc import Callable, Hashable
from dataclasses import dataclass
from typing import Any

from ...bridge.classes import ONBOARD_COMPID, RADIO_COMPID
from ...bridge.downloads import DownloadRelay
from ...bridge.missions import MissionRelay
from ...bridge.params import ParamLists
from ...bridge.resend import Resender
from ...bridge.routes import Routes
from ...bridge.uplink import MAX_PROTOCOL, GcsUplink
from ...link.transport import Spec, Transport, make_transport
from ...proto.endpoint import Endpoint
from ...wire.bindings import Bindings
from ...wire.v1 import Upgrader, downgrade

SHARE = 0.8  # of the DTT uplink, for ground stations' frames (the app's commands go first anyway)
RADIO_PERIOD = 1.0
TICK = 0.1  # s between the bridge's own checks
TXBUF_BYTES = MAX_PROTOCOL * 60  # RADIO_STATUS.txbuf: 100 % free when nothing waits


@dataclass
class BridgeStats:
    up: int = 0  # frames from ground stations queued toward the vehicle
    down: int = 0  # frames from the vehicle passed to ground stations
    not_carried: int = 0  # frames for another system
    radio_status: int = 0
    v1_up: int = 0  # MAVLink 1 frames from stations, carried as MAVLink 2
    v1_down: int = 0  # answers sent to MAVLink 1 stations as MAVLink 1
    v1_dropped: int = 0  # frames MAVLink 1 cannot carry (msgid over 255), or MAVLink 1 ids not in the dialect
    unknown_up: int = 0  # frames of ids the tablet's dialect lacks, carried by their header (as mavlink-router does)
    unknown_dropped: int = 0  # ... and those that could not be (signed, several in a datagram, ids to remap)


class GcsBridge:
    def __init__(self, b: Bindings, specs: list[Spec], vehicle_sysid: int, uplink_Bps: float | None,
                 share: float = SHARE, log: Callable[[str], None] | None = None) -> None:
        self.b = b
        self.specs = specs
        self.vehicle = vehicle_sysid
        self.log = log or (lambda text: None)
        self.routes = Routes(vehicle_sysid)
        self.uplink = GcsUplink(share * uplink_Bps if uplink_Bps else None)
        self.links: list[Transport] = []
        self._parsers: dict[tuple[Hashable, Hashable], Any] = {}
        self._v1: dict[tuple[Hashable, Hashable], Upgrader] = {}  # each station's MAVLink 1 upgrader
        self._v1_told: set[int] = set()  # msgids said once
        self.radio = b.encoder(vehicle_sysid, RADIO_COMPID)
        self.autopilot = b.encoder(vehicle_sysid, 1)  # the mission relay's requests, as the vehicle's
        self.missions = MissionRelay(self._request, waiting=self.uplink.waiting)
        self.downloads = DownloadRelay(self._request_up, waiting=self.uplink.waiting)
        # one-shot requests (commands, parameter reads, mission lists) sent again until answered
        self.resend = Resender(lambda msg, seq, who: bytes(msg.pack(seq, *who)), self.uplink.waiting)
        self.params = ParamLists()  # parameter lists: what the link lost of one, read again at once
        self._up_seq = 0
        self.stats = BridgeStats()
        self.ep: Endpoint | None = None
        self.kick: Callable[[], None] = lambda: None
        self._task: asyncio.Task[None] | None = None
        self._told_other: set[Hashable] = set()
        self.running = False  # every ground-station link open

    async def start(self, ep: Endpoint, kick: Callable[[], None]) -> None:
        self.ep, self.kick = ep, kick
        ep.add_stream(self.uplink)
        for spec in self.specs:
            t = make_transport(spec, log=self._logger(spec), mtu=65535)
            t.on_receive = self._receiver(t)
            t.on_close = self._closer(t)
            await t.open()
            self.links.append(t)
            if spec.kind in ("udpout", "tcp"):
                self.routes.fixed.append(t)
        self._task = asyncio.get_running_loop().create_task(self._radio_status())
        self.running = True

    def _logger(self, spec: Spec) -> Callable[[str], None]:
        return lambda text: self.log(f"gcs {spec}: {text}")

    def _closer(self, link: Transport) -> Callable[[Hashable], None]:
        """A TCP ground station left: its parser (and any half frame in it) goes with it."""
        def closed(source: Hashable) -> None:
            self._parsers.pop((link, source), None)
            self._v1.pop((link, source), None)

        return closed

    def close(self) -> None:
        if self._task is not None:
            self._task.cancel()
        for t in self.links:
            t.close()

    def describe(self) -> str:
        return ", ".join(t.describe() for t in self.links)

    # -- ground stations -> vehicle ---------------------------------------------------------------
    def _receiver(self, link: Transport) -> Callable[[bytes, Hashable], None]:
        def receive(data: bytes, source: Hashable) -> None:
            parser = self._parsers.get((link, source))
            if parser is None:
                parser = self._parsers[(link, source)] = self.b.parser()
            v1 = self._v1.get((link, source))
            if v1 is None:
                if len(self._v1) >= 64:  # bounded: the oldest station's goes (it starts afresh if it comes back)
                    self._v1.pop(next(iter(self._v1)))
                v1 = self._v1[(link, source)] = Upgrader(self.b.registry, self._unknown_v1)
            before = v1.v1_frames
            data = v1.feed(data, not getattr(link, "stream", False))  # MAVLink 1 re-framed as 2; the rest as it came
            self.stats.v1_up += v1.v1_frames - before
            now = asyncio.get_running_loop().time()
            queued = False
            unknown = parser.stats.unknown
            for msg in parser.feed(data):
                src = (msg.get_srcSystem(), msg.get_srcComponent())
                target = getattr(msg, "target_system", 0)
                if target not in (0, self.vehicle):  # (and its sender is no station of ours for it)
                    self.stats.not_carried += 1
                    if target not in self._told_other and len(self._told_other) < 16:
                        self._told_other.add(target)
                        self.log(f"not carrying {msg.NAME} for system {target}: the vehicle here is {self.vehicle}")
                    continue
                carried = self.routes.heard(now, link, source, src)
                link.confirm(source, {src})  # a listening link answers only who sent frames it carries
                if msg.NAME.startswith("MISSION_"):
                    forward, answers, wanted, ahead = self.downloads.from_gcs(now, msg, carried)
                    for answer in answers:
                        self._to_gcs(now, answer, carried)
                    self.uplink.put_ahead(now, "MISSION_REQUEST_INT", wanted)  # (ahead of the prefetch)
                    for frame in ahead:
                        self.uplink.put(now, "MISSION_REQUEST_INT", frame)
                    queued = queued or bool(ahead) or bool(wanted)
                    if not forward:
                        continue
                if msg.NAME == "PARAM_REQUEST_LIST":
                    self.params.request(now, carried)
                frame = msg.pack(msg.get_seq(), *carried)
                self.uplink.put(now, msg.NAME, frame)
                self.resend.request(now, msg.NAME, msg, carried, bytes(frame))
                self.stats.up += 1
                queued = True
                for req in self.missions.from_gcs(now, msg, carried, frame):
                    self._to_gcs(now, req, carried)
            if parser.stats.unknown > unknown and not getattr(link, "stream", False):
                queued = self._unknown_up(now, link, source, data) or queued
            if queued:
                self.kick()

        return receive

    def _unknown_up(self, now: float, link: Transport, source: Hashable, data: bytes) -> bool:
        """A datagram holding one frame of an id the tablet's dialect lacks: carried toward the
        vehicle by its header, as mavlink-router forwards what it cannot decode (its CRC cannot
        be checked here; the vehicle checks it, or counts it as unknown). Not when the station
        must be carried under other ids (the CRC covers them) or the frame is signed."""
        plen = data[1] if len(data) >= 12 else -1
        msgid = data[7] | data[8] << 8 | data[9] << 16 if len(data) >= 10 else -1
        src = (data[5], data[6]) if len(data) >= 7 else (0, 0)
        why = None
        if data[:1] != b"\xfd" or len(data) != 12 + plen:
            why = "it is signed, or not one MAVLink 2 frame a datagram"
        elif self.routes.heard(now, link, source, src) != src:
            why = f"the station uses the tablet's own ids {src[0]}/{src[1]}, which the frame's CRC covers"
        if why is not None:
            self.stats.unknown_dropped += 1
            if ("unknown", msgid) not in self._told_other and len(self._told_other) < 32:
                self._told_other.add(("unknown", msgid))
                self.log(f"not carrying message id {msgid} from a ground station: the tablet's dialect "
                         f"({self.b.name}) lacks it and {why} (give the tablet --dialect)")
            return False
        self.uplink.put(now, f"#{msgid}", data)  # (not a protocol frame: the user's queue)
        self.stats.unknown_up += 1
        if ("carried", msgid) not in self._told_other and len(self._told_other) < 32:
            self._told_other.add(("carried", msgid))
            self.log(f"carrying message id {msgid} from a ground station by its header: the tablet's dialect "
                     f"({self.b.name}) lacks it, so answers in it cannot come back (give the tablet --dialect)")
        return True

    # -- vehicle -> ground stations ----------------------------------------------------------------
    def divert(self, now: float, msg: Any) -> bool:
        """The tablet's Endpoint hands every frame over first: the vehicle's frames for ground
        stations (its sysid, any component but the onboard end's) are taken here."""
        sysid, compid = msg.get_srcSystem(), msg.get_srcComponent()
        if sysid != self.vehicle or compid == ONBOARD_COMPID:
            return False
        loop_now = asyncio.get_running_loop().time()
        self.routes.vehicle_frame(loop_now, compid, msg.get_seq())
        target = None
        if hasattr(msg, "target_system"):
            target = (int(msg.target_system), int(getattr(msg, "target_component", 0) or 0))
        who = target if target is not None and target[0] else None
        self.resend.answer(loop_now, msg, who)  # (the answer to a request: no more resends of it)
        if msg.NAME == "PARAM_VALUE":
            self.params.value(loop_now, int(msg.param_index), int(msg.param_count))
        if msg.NAME.startswith("MISSION_"):
            forward, again, requests = self.missions.from_vehicle(loop_now, msg, who)
            passed, lost, ahead = self.downloads.from_vehicle(loop_now, msg, who)
            forward = forward and passed
            for frame in ahead:
                self.uplink.put(loop_now, "MISSION_REQUEST_INT", frame)
            self.uplink.put_ahead(loop_now, "MISSION_REQUEST_INT", lost)  # (items whose requests or answers
            # the link lost) and an item the vehicle lacks, asked for again: ahead of the next ones
            self.uplink.put_ahead(loop_now, "MISSION_ITEM_INT", again)
            for req in requests:
                self._to_gcs(loop_now, req, target)  # type: ignore[arg-type]
            if again or ahead or lost:
                self.kick()
            if not forward:
                return True
        dests, own = self.routes.destinations(loop_now, target)
        if own is not None:
            msg.target_system = own[0]
            if getattr(msg, "target_component", 0):
                msg.target_component = own[1]
        frame = msg.pack(msg.get_seq(), sysid, compid)
        for link, address in dests:
            self._send(link, address, frame)
        self.stats.down += 1
        return True

    def _request(self, who: tuple[int, int], seq: int, mission_type: int) -> Any:
        return self.b.MissionRequestInt(target_system=who[0], target_component=who[1], seq=seq,
                                        mission_type=mission_type)

    def _as_station(self, who: tuple[int, int], msg: Any) -> bytes:
        """`msg` to the vehicle's autopilot as the station carried as `who` sends it (the bridge's
        own requests on a station's behalf), with the bridge's sequence numbers."""
        self._up_seq = (self._up_seq + 1) & 0xFF
        return bytes(msg.pack(self._up_seq, *who))

    def _request_up(self, who: tuple[int, int], seq: int, mission_type: int) -> bytes:
        return self._as_station(who, self.b.MissionRequestInt(target_system=self.vehicle, target_component=1,
                                                              seq=seq, mission_type=mission_type))

    def _param_read_up(self, who: tuple[int, int], index: int) -> bytes:
        return self._as_station(who, self.b.ParamRequestRead(target_system=self.vehicle, target_component=1,
                                                             param_id=b"", param_index=index))

    def _to_gcs(self, now: float, msg: Any, carried: tuple[int, int]) -> None:
        """A frame of the bridge's own, as the vehicle's autopilot, to the station carried as `carried`."""
        dests, own = self.routes.destinations(now, carried)
        if own is not None:
            msg.target_system, msg.target_component = own
        frame = self.autopilot.encode(msg)
        for link, address in dests:
            self._send(link, address, frame)

    def _unknown_v1(self, msgid: int) -> None:
        self.stats.v1_dropped += 1
        if msgid not in self._v1_told and len(self._v1_told) < 16:
            self._v1_told.add(msgid)
            self.log(f"not carrying MAVLink 1 message id {msgid} from a ground station: the dialect on the link "
                     f"has no such message (its CRC cannot be checked)")

    def _send(self, link: Any, address: Hashable, frame: bytes) -> None:
        v1 = self._v1.get((link, address))
        if v1 is not None and v1.saw_v1 and not v1.saw_v2:  # a station that speaks MAVLink 1: answered in kind
            old = downgrade(frame, self.b.registry)
            if old is None:
                self.stats.v1_dropped += 1
                msgid = frame[7] | frame[8] << 8 | frame[9] << 16
                if msgid not in self._v1_told and len(self._v1_told) < 16:
                    self._v1_told.add(msgid)
                    name = getattr(self.b.registry.get(msgid), "cls", None)
                    self.log(f"not sending {getattr(name, 'NAME', msgid)} to a MAVLink 1 ground station: MAVLink 1 "
                             f"carries message ids up to 255 (set the station to MAVLink 2 to get it)")
                return
            self.stats.v1_down += 1
            frame = old
        if address is not None and hasattr(link, "send_to"):
            link.send_to(frame, address)
        else:
            link.send(frame)

    async def _radio_status(self) -> None:
        """RADIO_STATUS to every ground station once a second, as SiK radios and mLRS send it:
        the link's quality from the vehicle's frames that arrived, the uplink queue's room."""
        loop = asyncio.get_running_loop()
        b = self.b
        due = 0.0
        while True:
            now = loop.time()
            again = self.missions.tick(now)  # (and a mission upload's lost count or last item, sent again)
            self.uplink.put_ahead(now, "MISSION_ITEM_INT", again)  # (protocol frames: the name tells only
            # newest-wins from the rest)
            for who, req in self.missions.ahead_requests(now):  # (the next items as the uplink takes them:
                self._to_gcs(now, req, who)  # those just sent again count as waiting in it)
            resent = self.resend.tick(now)  # one-shot requests whose answer has not come in a round trip
            for name, frame in resent:
                self.uplink.put(now, name, frame)
            reads = self.params.tick(now)  # what the link lost of a parameter list, read again
            for who, index in reads:
                self.uplink.put(now, "PARAM_REQUEST_READ", self._param_read_up(who, index))
            if again or resent or reads:
                self.kick()
            if now < due:
                await asyncio.sleep(TICK)
                continue
            due = now + RADIO_PERIOD
            q = self.routes.quality(now)
            free = max(0, min(100, round(100 * (1 - self.uplink.waiting_bytes / TXBUF_BYTES))))
            msg = b.RadioStatus(rssi=q, remrssi=q, txbuf=free, noise=0, remnoise=0,
                                rxerrors=self.routes.lost & 0xFFFF, fixed=self.uplink.stats.overflow & 0xFFFF)
            frame = self.radio.encode(msg)
            dests, _ = self.routes.destinations(now, None)
            for link, address in dests:
                self._send(link, address, frame)
            self.stats.radio_status += 1
            await asyncio.sleep(TICK)

    def summary(self) -> str:
        u = self.uplink.stats
        return (f"ground stations: {self.stats.up} frames up ({u.sent} sent, {u.duplicates} retries dropped as "
                f"duplicates, {u.replaced} overtaken by newer, {u.overflow} dropped for room, "
                + (f"{u.user_overflow} of their own messages dropped for room, " if u.user_overflow else "")
                + f"{self.stats.not_carried} for other systems not carried), {self.stats.down} down; "
                + f"{self.resend.resent} one-shot requests resent ({self.resend.rescued} answered only then, "
                + f"{self.resend.given_up} never)"
                + (f"; {self.params.read} parameters of lists read again" if self.params.read else "")
                + (f"; ids the dialect lacks: {self.stats.unknown_up} carried by header, "
                   f"{self.stats.unknown_dropped} not" if self.stats.unknown_up or self.stats.unknown_dropped else "")
                + (f"; MAVLink 1: {self.stats.v1_up} up, {self.stats.v1_down} down, {self.stats.v1_dropped} not "
                   f"carried" if self.stats.v1_up or self.stats.v1_dropped else ""))
