"""One end of the link, sans-IO: packets and the time in; packets to send, and when to wake up,
out. It owns the packet receivers, the packet scheduler, file transfers (both directions,
several at once), downloads on request, and commands.

Drive it with `receive(now, packet, source)`, `poll(now)` (the next packet to send, if the
pacer lets one go) and `wakeup()`; the virtual-time simulator and the asyncio runner both do.
`source` names where a packet came from (a UDP address, a TCP connection): each source has a
packet receiver of its own, so that two peers' packets never mix in one frame.
"""

from __future__ import annotations

import dataclasses
import random
from collections import OrderedDict
from collections.abc import Callable, Hashable
from pathlib import Path
from typing import Any

from ..wire.bindings import Bindings
from ..wire.contract import TtFileResult as R
from ..wire.packets import PacketReceiver
from .commands import FINAL_OK, Action, Command, CommandClient, CommandServer, log_chunks
from .deflate import DeflatedSource
from .fetches import Request, Serving
from .names import Refused, check_name
from .pipeline import Pipe
from .receiver import FileReceiver
from .scheduler import BULK, CONTROL, TELEMETRY, Scheduler
from .sender import FileSender
from .storage import FileSource, ReceiveDir
from .transfer import (
    FIT_MAX,
    FIT_OVERHEAD,
    MAX_RANGES,
    NARROW,
    RESULT_TEXT,
    SIGNATURE,
    WIDE,
    Geometry,
    TransferConfig,
    map_bytes,
    ranges_per_status,
    reason_text,
)

TARGETED = "target_system"
STATUS_BYTES = 60  # typical TT_FILE_STATUS frame
MAX_SOURCES = 64  # packet receivers kept for distinct sources (the least recently heard goes first)
# a command's copy goes at the earliest this many full packets' time after it (commands.py): a frame
# that arrives behind the two full packets the radio's buffer holds is through in about that
COPY_PACKETS = 2.5
COPY_BELOW_BPS = 10_000.0  # ... on links paced at most this fast (DJI's DTT and low-speed channels)


class Endpoint:
    """`bindings`: the dialect on the link (its parser decodes what arrives; its classes are
    what the runtime makes). `signing`: MAVLink 2 signing (a Signing of any package: frames are
    signed against this dialect's registry). `inbound_Bps`: what this end can take from its link,
    shared out among concurrent incoming transfers by rate grants (sharing.py; None: no grants)."""

    def __init__(self, bindings: Bindings, sysid: int, compid: int, *, mtu: int = 100, rate_Bps: float | None = None,
                 receive_dir: ReceiveDir | None = None, serve_dir: str | None = None,
                 config: TransferConfig | None = None, signing: Any = None,
                 action: Action | None = None, clock_ms: Callable[[float], int] | None = None,
                 on_message: Callable[[float, Any], None] | None = None,
                 on_event: Callable[[str, Any], None] | None = None, accept_commands: bool = True,
                 unsolicited: bool = True, rng: random.Random | None = None, compress: bool = True,
                 inflate: bool = True, inbound_Bps: float | None = None,
                 divert: Callable[[float, Any], bool] | None = None) -> None:
        self.b = bindings
        self.sysid = sysid
        self.compid = compid
        self.cfg = config or TransferConfig()
        self.signing = signing
        self.encoder = bindings.encoder(sysid, compid)  # unsigned: the scheduler signs frames as they leave
        self._rxs: OrderedDict[Hashable, PacketReceiver] = OrderedDict()
        self._streams: OrderedDict[Hashable, Any] = OrderedDict()  # byte-stream links (TCP): parsers
        self._last_rx: dict[Hashable, float] = {}
        self.geometry = Geometry(mtu, signing is not None)  # ValueError for a packet too small for file data
        self.scheduler = Scheduler(mtu, rate_Bps, sign=bindings.sign(signing) if signing is not None else None)
        # a command's copy (commands.py), on a link slow enough for it to matter
        self._copy_after = COPY_PACKETS * mtu / rate_Bps if rate_Bps and rate_Bps <= COPY_BELOW_BPS else None
        self.receiver = (FileReceiver(bindings, receive_dir, sysid, compid, self.cfg, on_event=self._file_event,
                                      unsolicited=unsolicited, inflate=inflate, inbound_Bps=inbound_Bps)
                         if receive_dir is not None else None)
        if self.receiver is not None:
            self.receiver.packet = mtu
            self.receiver.ranges_per_status = per = ranges_per_status(mtu, signing is not None)
            self.receiver.map_bytes = map_bytes(mtu, signing is not None)
            # as many gaps in a report as MAX_RANGES-gap statuses would hold, in more, one-packet statuses
            paced: dict[str, Any] = {"status_batches": -(-self.cfg.status_batches * MAX_RANGES // per)}
            if rate_Bps:
                # statuses go back over our own link: on a slow one, fewer of them (a status with a few
                # gaps is about 60 bytes on the wire, its ranges truncated; a signature 13 more)
                status = STATUS_BYTES + (SIGNATURE if signing is not None else 0)
                paced["status_min_interval"] = max(self.cfg.status_min_interval, 1.5 * status / rate_Bps)
                paced["status_tail_interval"] = max(self.cfg.status_tail_interval, 0.8 * status / rate_Bps)
            self.receiver.cfg = dataclasses.replace(self.receiver.cfg, **paced)
        # the tablet's control traffic, which rate grants leave room for (not the other end's telemetry,
        # nor a sender's hello HEARTBEAT); ground stations' frames the onboard end takes over DTT count too
        self._control = tuple(getattr(bindings, n) for n in ("TtActionCommand", "DjiPoseStamped", "TtVrPose",
                                                              "TtVrController") if hasattr(bindings, n))
        self.serving = Serving(self, serve_dir)  # the files it serves, on request (fetches.py)
        self.compress = compress  # offer files deflated when that saves (sends and served fetches)
        self.senders: dict[int, FileSender] = {}
        self.requests: dict[int, Request] = {}
        # transfer, request and first command ids are random (seeded in simulations): never reused by accident
        self._rng = rng or random.SystemRandom()
        self.commands = CommandClient(sysid, compid, first_id=self._rng.randint(1, 65535))
        self.scheduler.control_due = self.commands.next_send  # bulk leaves the radio free for a command's retry
        self.server = CommandServer(bindings, sysid, compid, action) if accept_commands else None
        self.clock_ms = clock_ms or (lambda now: int(now * 1000))  # TT_LOG.time_boot_ms
        self._log_id = 0
        self.on_message = on_message
        self.divert = divert  # sees each frame first (but file data); True: it took the frame (ground stations')
        self.on_event = on_event
        self.now = 0.0
        self.ignored = 0
        self.peers: dict[tuple[int, int], float] = {}  # who we heard from, when
        self.heard: dict[tuple[int, int], int] = {}  # frames from each of them
        self._streams_out: list[Any] = []  # newest-wins sources (add_stream)
        self._refused_sources: set[Hashable] = set()  # reported once each (signing)
        self.unknown = 0  # frames of messages this dialect lacks (the peer speaks another one)
        self._unknown_told: set[int] = set()  # msgids reported (once each)
        self.pipe = Pipe(self)  # a pipeline beside the packets, when one opens (pipeline.py)

    # -- node interface -----------------------------------------------------------------------
    def receive(self, now: float, packet: bytes, source: Hashable = None) -> set[tuple[int, int]]:
        """A packet from `source`; returns the (sysid, compid) of every valid frame in it, so
        that a transport learns who is behind an address only from what proves it."""
        self.now = now
        rx = self._rxs.get(source)
        if rx is None:
            rx = self._rxs[source] = PacketReceiver(self.b, signing=self.signing,
                                                    on_bad=self._refused_by_signing(source),
                                                    on_unknown=self._unknown_from(source))
            if len(self._rxs) > MAX_SOURCES:
                old, _ = self._rxs.popitem(last=False)
                self._last_rx.pop(old, None)
        else:
            self._rxs.move_to_end(source)
        self._last_rx[source] = now
        msgs = rx.feed(packet)
        if self.receiver is not None and (msgs or rx.pending):  # (garbage from a stranger uses no link here)
            self.receiver.load.packet(now, len(packet))
        return self._handle_all(now, msgs)

    def receive_stream(self, now: float, data: bytes, source: Hashable = None) -> set[tuple[int, int]]:
        """Bytes from a stream link (TCP), where chunk boundaries mean nothing."""
        self.now = now
        parser = self._streams.get(source)
        if parser is None:
            parser = self._streams[source] = self.b.parser(self.signing)
            if len(self._streams) > MAX_SOURCES:
                self._streams.popitem(last=False)
        self._last_rx[source] = now
        msgs = parser.feed(data)
        if self.receiver is not None and (msgs or parser.pending):
            self.receiver.load.packet(now, len(data))
        return self._handle_all(now, msgs)

    def mid_frame(self, source: Hashable) -> bool:
        """Whether a frame from `source` is half received (its next packet is a continuation)."""
        rx = self._rxs.get(source)
        return rx is not None and rx.pending > 0

    def forget_source(self, source: Hashable) -> None:
        """A connection closed: its half-received frame goes with it."""
        self._rxs.pop(source, None)
        self._streams.pop(source, None)
        self._last_rx.pop(source, None)

    def pending_since(self) -> float | None:
        """When the quietest source holding half a frame last sent something (None: none does)."""
        times = [self._last_rx.get(s, 0.0) for s, rx in self._rxs.items() if rx.pending]
        times += [self._last_rx.get(s, 0.0) for s, p in self._streams.items() if p.pending]
        return min(times) if times else None

    def flush(self, now: float, quiet: float = 0.0) -> None:
        """Sources quiet for `quiet` seconds: give up on their half-received long frames."""
        for source, rx in list(self._rxs.items()):
            if rx.pending and now - self._last_rx.get(source, 0.0) >= quiet:
                self._handle_all(now, rx.flush())
        for source, parser in list(self._streams.items()):
            if parser.pending and now - self._last_rx.get(source, 0.0) >= quiet:
                self._handle_all(now, parser.flush())

    def poll(self, now: float) -> bytes | None:
        self.now = now
        self._tick(now)
        return self.scheduler.next_packet(now)

    def wakeup(self) -> float | None:
        times = [t for t in (self.commands.deadline(),
                             self.receiver.deadline() if self.receiver else None) if t is not None]
        times += [t for s in self.senders.values() if (t := s.deadline(self.now)) is not None]
        if self.receiver is not None:
            times += [t for r in self.requests.values() if (t := r.deadline(self.receiver)) is not None]
        file_data = not self.pipe.is_open and any(s.has_data(self.now) for s in self.senders.values())
        if self.scheduler.busy or file_data \
                or any(s.has_data(self.now) for s in self._streams_out):
            times.append(self.scheduler.ready_at())
        times += [t for s in self._streams_out if (t := s.deadline(self.now)) is not None]
        if (t := self.pipe.ready_at()) is not None:
            times.append(t)
        return min(times) if times else None

    # -- what the user asks for ------------------------------------------------------------------
    def send_message(self, msg: Any, priority: int = TELEMETRY) -> None:
        self.scheduler.send(self.encoder.encode(msg), priority)

    def send_file(self, path: str | Path, target: tuple[int, int], name: str | None = None,
                  overwrite: bool = False, request_id: int = 0,
                  on_progress: Callable[[FileSender], None] | None = None, source: Any = None,
                  compress: bool | DeflatedSource | None = None) -> FileSender:
        """Start sending a file (ValueError for a name no receiver would take, StorageError for
        a file that cannot be sent)."""
        src = source if source is not None else FileSource(path)
        sender = FileSender(self.b, self._new_id, src, name or Path(path).name, target, self.cfg, request_id, overwrite,
                            self.now, on_progress, self.compress if compress is None else compress)
        sender.owns_source = source is None
        self.pipe.adopt(sender)  # its frames cut for the path file data takes now
        self.senders[sender.id] = sender
        self.scheduler.add_source(self._puller(sender))
        return sender

    def request_file(self, name: str, target: tuple[int, int]) -> Request:
        """Ask the peer for a file (ValueError for a name no peer would serve)."""
        try:
            check_name(name)
        except Refused as e:
            raise ValueError(e.reason) from None
        if self.receiver is None:
            raise ValueError("this end has no receive directory")
        rid = self._new_id()
        req = Request(self.b, rid, name, target, self.now, self.cfg)
        self.requests[rid] = req
        self.receiver.expect(target, rid, name)
        return req

    def command(self, msg: Any, target: tuple[int, int], retries: int = 3,
                timeout: float = 1.5, on_success: Callable[[Command], None] | None = None,
                on_failure: Callable[[Command], None] | None = None) -> Command:
        return self.commands.submit(Command(msg, target, retries, timeout, on_success, on_failure,
                                            copy_after=self._copy_after), self.now)

    def close(self) -> None:
        if self.receiver is not None:
            self.receiver.close()
        for s in list(self.senders.values()):
            self._retire(s)

    # -- internals ------------------------------------------------------------------------------
    def _new_id(self) -> int:
        """A transfer or request id: 32 random bits, never 0, not in use here."""
        while True:
            n = self._rng.getrandbits(32)
            if n and n not in self.senders and n not in self.requests:
                return n

    def _retire(self, s: FileSender) -> None:
        if self.senders.get(s.id) is s:
            del self.senders[s.id]
        self.scheduler.remove_source(getattr(s, "_pull", None))  # type: ignore[arg-type]
        s.close()
        if s.owns_source:
            s.raw_source.close()
            s.owns_source = False

    def add_stream(self, stream: Any) -> None:
        """A newest-wins message source (hmd.stream.PoseStream: `pull(now, space)` -> message, a
        frame already encoded, or None; `has_data(now)`, `deadline(now)`), pulled like file data
        when a packet may leave."""
        def pull(now: float, space: int) -> bytes | None:
            msg = stream.pull(now, space)
            return msg if msg is None or isinstance(msg, bytes) else self.encoder.encode(msg)

        self._streams_out.append(stream)
        self.scheduler.add_source(pull)

    def _puller(self, sender: FileSender) -> Callable[[float, int], bytes | None]:
        def pull(now: float, space: int) -> bytes | None:
            msg = sender.next_data(now, space)
            return None if msg is None else self.encoder.encode(msg)

        sender._pull = pull  # type: ignore[attr-defined]
        return pull

    def _tick(self, now: float) -> None:
        send = self.scheduler.send
        enc = self.encoder.encode
        for msg in self.commands.control(now):
            send(enc(msg), CONTROL)
        if self.receiver is not None:
            for msg, key in self.receiver.control(now):
                send(enc(msg), CONTROL, key=key)
        for s in list(self.senders.values()):
            for msg in s.control(now):
                send(enc(msg), CONTROL)
            if s.done and now - (s.stats.finished or now) > 30:
                self._retire(s)
        for req in self.requests.values():
            if req.code is not None:
                continue
            if req._refusal is not None and now >= req._refusal[1] + req.reason_wait:
                self._fail_request(req, req._refusal[0])
                continue
            if not req.answered and now >= req.give_up:
                req.answered, req.code = True, "TIMEOUT"
                req.error = f"no answer to the request for {req.name}"
                self._event("request-failed", req)
                continue
            if self.receiver is not None:  # (asked again, too, while its transfer is quiet)
                for msg in req.control(now, self.receiver):
                    send(enc(msg), CONTROL)

    def _refused_by_signing(self, source: Hashable) -> Callable[[bytes, str], None] | None:
        """With signing on: the first frame from `source` refused for its signature (or for
        having none) is reported once, as a "link-refused" event with (source, reason), so a
        peer with another key is not mistaken for no peer at all."""
        if self.signing is None:
            return None

        def bad(frame: bytes, reason: str) -> None:
            # a replayed timestamp is a duplicated packet or a replay, not another key
            if reason in ("unsigned frame refused", "bad signature") and source not in self._refused_sources:
                self._refused_sources.add(source)
                self._event("link-refused", (source, "unsigned frames" if reason.startswith("unsigned")
                                             else "frames whose signatures do not verify"))
        return bad

    def _unknown_from(self, source: Hashable) -> Callable[[int, int, int], None]:
        """A frame of a message this dialect lacks: counted, and reported once per msgid as an
        "unknown-message" event with (source, msgid, (sysid, compid)); never an error."""
        def unknown(msgid: int, sysid: int, compid: int) -> None:
            self.unknown += 1
            if msgid not in self._unknown_told and len(self._unknown_told) < 256:
                self._unknown_told.add(msgid)
                self._event("unknown-message", (source, msgid, (sysid, compid)))
        return unknown

    def _event(self, what: str, obj: Any) -> None:
        if self.on_event is not None:
            self.on_event(what, obj)

    def _file_event(self, what: str, incoming: Any) -> None:
        self._event(f"file-{what}", incoming)

    def _for_us(self, msg: Any) -> bool:
        if hasattr(msg, TARGETED):
            ts = msg.target_system
            if ts not in (0, self.sysid):
                return False
            tc = getattr(msg, "target_component", 0)
            if tc not in (0, self.compid):
                return False
        return True

    def _handle_all(self, now: float, msgs: list[Any]) -> set[tuple[int, int]]:
        seen: set[tuple[int, int]] = set()
        for msg in msgs:
            src = (msg.get_srcSystem(), msg.get_srcComponent())
            if src == (self.sysid, self.compid):
                continue  # our own frames, echoed
            seen.add(src)
            self._handle(now, msg)
        return seen

    def _handle(self, now: float, msg: Any) -> None:
        src = (msg.get_srcSystem(), msg.get_srcComponent())
        self.peers[src] = now
        self.heard[src] = self.heard.get(src, 0) + 1
        b = self.b
        if isinstance(msg, (b.TtFileData, b.TtFileDataWide, b.TtFileDataFit)):
            if self.receiver is None:
                return
            if isinstance(msg, b.TtFileDataFit):
                if 1 <= msg.count <= FIT_MAX:  # else malformed: ignored
                    self.receiver.on_data(now, msg, msg.count, FIT_OVERHEAD + msg.count)
            else:
                self.receiver.on_data(now, msg, WIDE if isinstance(msg, b.TtFileDataWide) else NARROW)
            return
        if self.receiver is not None and isinstance(msg, self._control):
            self.receiver.control_at = now  # another process's commands share the link: grants leave them room
        if self.divert is not None and self.divert(now, msg):
            if self.receiver is not None and self.server is not None:  # a ground station's request, not telemetry
                self.receiver.control_at = now
            return
        if not self._for_us(msg):
            self.ignored += 1
            return
        if isinstance(msg, b.TtFileOffer):
            self._on_offer(now, msg)
        elif isinstance(msg, b.TtFileStatus):
            self._on_status(now, msg)
        elif isinstance(msg, b.TtFileMap):
            sender = self.senders.get(msg.transfer_id)
            if sender is not None and sender.target == (msg.get_srcSystem(), msg.get_srcComponent()):
                sender.on_map(now, msg)
        elif isinstance(msg, b.TtFileReason):
            self._on_reason(now, msg)
        elif isinstance(msg, b.TtFileRequest):
            self.serving.on_request(now, msg)
        elif isinstance(msg, b.TtCommandAck):
            self.commands.on_ack(now, msg)
        elif isinstance(msg, b.TtActionCommand) and self.server is not None:
            ack, words = self.server.answer(msg)
            if ack is not None:
                if words:  # so that a refusal's words leave before the refusing ack
                    self.say(words, 6 if ack.result in FINAL_OK else 4, urgent=True)
                self.scheduler.send(self.encoder.encode(ack), CONTROL)
        if self.on_message is not None:
            self.on_message(now, msg)

    def say(self, text: str, severity: int = 6, urgent: bool = False) -> None:
        """A TT_LOG line to whoever listens (`urgent`: at control priority, ahead of telemetry)."""
        self._log_id = self._log_id % 65535 + 1
        for msg in log_chunks(self.b, text, severity, self.clock_ms(self.now), self._log_id):
            self.send_message(msg, CONTROL if urgent else TELEMETRY)

    def _on_offer(self, now: float, msg: Any) -> None:
        if self.receiver is None:
            self.ignored += 1
            return
        src = (msg.get_srcSystem(), msg.get_srcComponent())
        if msg.request_id:
            req = self.requests.get(msg.request_id)
            if req is not None and req.target == src and req.code is None:
                req.answer(now, (src[0], src[1], msg.transfer_id))  # the first offer, or the request served anew
        self.receiver.on_offer(now, msg)

    def _on_status(self, now: float, msg: Any) -> None:
        src = (msg.get_srcSystem(), msg.get_srcComponent())
        if msg.result in (R.TT_FILE_RESULT_NOT_FOUND, R.TT_FILE_RESULT_REQUEST_REFUSED):
            req = self.requests.get(msg.transfer_id)
            if req is not None and req.target == src and req.code is None:  # (asked again, too: fetches.py)
                code = "NOT_FOUND" if msg.result == R.TT_FILE_RESULT_NOT_FOUND else "REQUEST_REFUSED"
                if req.reason is not None:
                    self._fail_request(req, code)
                elif req._refusal is None:
                    req._refusal = (code, now)  # wait a moment for the words, and ask once more
                    req.due = now
            return
        sender = self.senders.get(msg.transfer_id)
        if sender is not None and sender.target == src:
            sender.on_status(now, msg)
            if sender.id != msg.transfer_id:  # it started again under a new id
                self.senders.pop(msg.transfer_id, None)
                self.senders[sender.id] = sender

    def _on_reason(self, now: float, msg: Any) -> None:
        src = (msg.get_srcSystem(), msg.get_srcComponent())
        req = self.requests.get(msg.transfer_id)
        if req is not None and req.target == src and req.code is None:
            req.reason = reason_text(msg.text)
            if req._refusal is not None:
                self._fail_request(req, req._refusal[0])
            return
        sender = self.senders.get(msg.transfer_id)
        if sender is not None and sender.target == src:
            sender.on_reason(now, msg)

    def _fail_request(self, req: Request, code: str) -> None:
        req.answered, req.code = True, code
        req.error = req.reason or RESULT_TEXT.get(code, "refused")
        self._event("request-failed", req)


__all__ = ["BULK", "CONTROL", "TELEMETRY", "Endpoint", "Request"]
