"""The peers of `ttctl bench transfer`: the thesis file transfer and MAVLink FTP, run as sans-IO
ends by the same Simulation, over the same channels and seeds as ttctl's own transfer.

Both baselines time the same thing as `run_ttctl`: seconds from the moment the sender starts
until the receiver holds every byte of the file, correct; (limit, False) if that never happens.

Between each protocol and DJI's SDK sits what a straightforward bridge would do: every MAVLink
frame is cut into packets of its own (at most 100 bytes; frames never share a packet), queued,
and handed to the SDK paced at the link's capacity (the tablet only when the radio is free, as
its completion callback allows). Frames are reassembled by ttctl's packet-aware receiver, so
what is measured is each protocol, not a dispatch bug.

thesis (dialect data/dji_icg.xml; the thesis's file transfer, chapter 3), as designed and without the
implementation's bugs: the sender repeats DJI_FTP_REQUEST every 3 s until DJI_FTP_REQUEST_ACK
(ACCEPTED), then sends parts 0..n-1 of 250 bytes in DJI_FTP frames (266 bytes: packets of 100,
100 and 66 bytes). The receiver restarts a 3 s timer on every part; when it expires it asks for
the first missing range only (DJI_FTP_REQUEST_RESEND start..end) and restarts the timer; the
sender sends that range. Completion is a DJI_FTP_REQUEST_RESEND of 0xFFFF..0xFFFF, repeated
every 3 s (3 repeats) and in answer to any late part or request. Fixed: resent parts keep their
numbers, the last part is not over-read, out-of-range parts are ignored, a repeated request does
not reset the transfer. Not fixed, being the design: nothing checks the whole file, so a frame
that the receiver reassembles across a lost packet and that passes the 16-bit CRC by chance
(1 in 65536) corrupts the file; the run then reports ok=False.

mavftp: the client is pymavlink's own MAVFTP class (pymavlink/mavftp.py, default settings),
driven in virtual time: a private copy of the module whose `time` is the simulation clock, with
its blocking `recv_match(timeout=0.1)` loop run in a thread that hands control back and forth
with the simulation, so exactly one of them runs at any moment and runs are deterministic. As
its command line does, it resets the sessions, then `cmd_put` (CreateFile, then WriteFile of
`write_size` = 80-byte blocks, i.e. 107-byte frames, two packets each, `write_qsize` = 5 in
flight, round-robin repeats with the same seq) and `process_ftp_reply("put")` (no overall timeout
here; the benchmark's limit applies), ending with TerminateSession. If the put fails (pymavlink
aborts a put when a write is refused, e.g. after its CreateFile was lost), the command is run
again, as a user would. The server is a model of ArduPilot's (AP_MAVLinkFTP ftp_worker): one
open file, sessions, a repeated request answered with the stored reply, ACK/NAK per request.
The simulator polls the tablet only when its radio is free, so on the uplink pymavlink's 0.1 s
idle ticks (which only drive its retry heuristics) can run up to one packet time late; replies
reach it on time.
"""

from __future__ import annotations

import importlib.util
import io
import logging
import math
import struct
import threading
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import lru_cache
from importlib import resources
from types import ModuleType
from typing import TYPE_CHECKING, Any, ClassVar

import ttapi
from ttapi.mavlink import REGISTRY, Message, MessageInfo

from ..link.model import Channel, Profile
from ..link.sim import Simulation
from ..proto.scheduler import Pacer
from ..wire.packets import PacketReceiver, packetize
from .transfer import ONBOARD, TABLET, Case, channels, pace

Ids = tuple[int, int]

# -- thesis protocol constants (thesis source: TIMEOUT_MILISECS = 3000, payload u8[250]) ----------
THESIS_PART = 250
THESIS_TIMEOUT = 3.0
THESIS_REQUEST_INTERVAL = 3.0  # the sender's repeat of an unanswered DJI_FTP_REQUEST
THESIS_REQUEST_TRIES = 40
THESIS_DONE_REPEATS = 3
THESIS_GIVE_UP = 120.0  # sender: nothing heard for this long after sending everything
DONE = 0xFFFF
ACCEPTED, FAILED, IN_PROGRESS = 0, 1, 2  # DJI_FTP_REQUEST_RESULT

# -- the thesis dialect --------------------------------------------------------------------------

_STRUCT = {"uint8_t": "B", "int8_t": "b", "uint16_t": "H", "int16_t": "h", "uint32_t": "I", "int32_t": "i",
           "uint64_t": "Q", "int64_t": "q", "float": "f", "double": "d", "char": "s"}


class _DialectMessage(Message):
    """A message class built at run time from ttctl's dialect model (wire order, lengths and
    CRC_EXTRA all come from the model); byte arrays are `bytes`, other arrays lists."""

    _S: ClassVar[struct.Struct]
    _PLAN: ClassVar[tuple[tuple[str, int, bool], ...]] = ()  # (field, count, as bytes), wire order

    if TYPE_CHECKING:
        def __getattr__(self, name: str) -> Any: ...  # fields are set from the dialect at run time

    def __init__(self, **values: Any) -> None:
        for name, count, as_bytes in self._PLAN:
            setattr(self, name, b"" if as_bytes else (0 if count == 1 else [0] * count))
        for k, v in values.items():
            if k not in self.FIELDS:
                raise TypeError(f"{self.NAME} has no field {k!r}")
            setattr(self, k, v)

    def pack_payload(self) -> bytes:
        args: list[Any] = []
        for name, count, as_bytes in self._PLAN:
            v = getattr(self, name)
            if count > 1 and not as_bytes:
                args.extend(v)
            else:
                args.append(v)
        p = self._S.pack(*args)
        return p.rstrip(b"\x00") or b"\x00"

    @classmethod
    def _unpack(cls, b: Any, off: int) -> _DialectMessage:
        vals = cls._S.unpack_from(b, off)
        self = object.__new__(cls)
        i = 0
        for name, count, as_bytes in cls._PLAN:
            if count > 1 and not as_bytes:
                setattr(self, name, list(vals[i:i + count]))
                i += count
            else:
                setattr(self, name, vals[i])
                i += 1
        return self


def _message_class(m: Any) -> type[_DialectMessage]:
    fmt = "<"
    plan = []
    for f in m.wire_fields:
        code = _STRUCT[f.type]
        if f.type in ("uint8_t", "char") and f.array_length:
            fmt += f"{f.array_length}s"
            plan.append((f.name, f.array_length, True))
        elif f.type == "char":
            fmt += "1s"
            plan.append((f.name, 1, True))
        else:
            n = max(1, f.array_length)
            fmt += f"{n}{code}" if f.array_length else code
            plan.append((f.name, n, False))
    s = struct.Struct(fmt)
    assert s.size == m.payload_length, m.name
    attrs = {"MSG_ID": m.id, "NAME": m.name, "CRC_EXTRA": m.crc_extra, "PAYLOAD_LENGTH": m.payload_length,
             "MIN_LENGTH": m.min_length, "FIELDS": tuple(f.name for f in m.fields), "ENUMS": {},
             "_IDB": m.id.to_bytes(3, "little"), "_XB": bytes((m.crc_extra,)), "_S": s, "_PLAN": tuple(plan)}
    return type("".join(w.capitalize() for w in m.name.split("_")), (_DialectMessage,), attrs)


@dataclass(frozen=True)
class ThesisDialect:
    request: type[_DialectMessage]
    ack: type[_DialectMessage]
    part: type[_DialectMessage]
    resend: type[_DialectMessage]
    registry: dict[int, MessageInfo]


def thesis_xml() -> str:
    return str(resources.files("ttctl.bench").joinpath("data", "dji_icg.xml"))


@lru_cache(maxsize=1)
def thesis_dialect() -> ThesisDialect:
    """The four file-transfer messages of the thesis dialect, from data/dji_icg.xml through
    ttctl's loader (no generated code to write, import or keep in step)."""
    from ..dialect import load_dialect

    d = load_dialect(thesis_xml()).dialect
    by_name = {m.name: m for m in d.messages}
    names = ("DJI_FTP_REQUEST", "DJI_FTP_REQUEST_ACK", "DJI_FTP", "DJI_FTP_REQUEST_RESEND")
    classes = [_message_class(by_name[n]) for n in names]
    registry = dict(REGISTRY)  # common.xml comes from ttapi; 50000+ are the thesis's here
    registry.update({c.MSG_ID: MessageInfo(c) for c in classes})
    return ThesisDialect(request=classes[0], ack=classes[1], part=classes[2], resend=classes[3], registry=registry)


# -- one end: frames in their own packets, paced -------------------------------------------------

class _End:
    """Node plumbing shared by the baselines (see the module documentation)."""

    def __init__(self, ids: Ids, rate_Bps: float | None, mtu: int, registry: dict[int, MessageInfo]) -> None:
        self.ids = ids
        self.encoder = ttapi.Encoder(*ids)
        self.rx = PacketReceiver(registry)
        self.pacer = Pacer(rate_Bps)
        self.mtu = mtu
        self.fifo: deque[bytes] = deque()
        self.frames_sent = 0
        self.packets_sent = 0

    def send(self, msg: Message) -> tuple[int, int]:
        """Queue one frame in packets of its own: (frame bytes, packets)."""
        frame = self.encoder.encode(msg)
        packets = packetize([frame], self.mtu)
        self.fifo.extend(packets)
        self.frames_sent += 1
        return len(frame), len(packets)

    # hooks
    def on_message(self, now: float, msg: Message) -> None:
        pass

    def on_time(self, now: float) -> None:
        pass

    def next_timer(self) -> float | None:
        return None

    def has_frames(self) -> bool:
        """More frames would be made on demand (refill)."""
        return False

    def refill(self, now: float) -> None:
        pass

    # the Node interface of ttctl.link.sim
    def receive(self, now: float, packet: bytes) -> None:
        for msg in self.rx.feed(packet):
            self.on_message(now, msg)
        self.on_time(now)

    def poll(self, now: float) -> bytes | None:
        self.on_time(now)
        if not self.fifo:
            self.refill(now)
        if self.fifo and self.pacer.ready(now):
            pkt = self.fifo.popleft()
            self.pacer.sent(now, len(pkt))
            self.packets_sent += 1
            return pkt
        return None

    def wakeup(self) -> float | None:
        t = self.next_timer()
        if self.fifo or self.has_frames():
            r = self.pacer.ready_at()
            t = r if t is None else min(t, r)
        return t


def _targets(msg: Any, ids: Ids) -> bool:
    return getattr(msg, "target_system", None) == ids[0]


# -- the thesis file transfer --------------------------------------------------------------------

class ThesisSender(_End):
    def __init__(self, ids: Ids, peer: Ids, data: bytes, rate_Bps: float | None, mtu: int = 100,
                 file_id: int = 1, name: str = "bench.bin") -> None:
        self.d = thesis_dialect()
        super().__init__(ids, rate_Bps, mtu, self.d.registry)
        self.peer = peer
        self.data = data
        self.parts = math.ceil(len(data) / THESIS_PART)
        if self.parts >= DONE:
            raise ValueError(f"the thesis protocol numbers parts with u16: at most {(DONE - 1) * THESIS_PART} bytes")
        self.file_id = file_id
        self.name = name.encode()[:64]
        self.state = "request"  # request | sending | done | failed
        self.next_request = 0.0
        self.requests = 0
        self.queue: deque[int] = deque()
        self.queued: set[int] = set()
        self.last_heard = 0.0
        self.parts_sent = 0
        self.resends = 0

    def on_time(self, now: float) -> None:
        if self.state == "request" and now >= self.next_request:
            if self.requests >= THESIS_REQUEST_TRIES:
                self.state = "failed"
                return
            self.send(self.d.request(target_system=self.peer[0], file_size=len(self.data), file_id=self.file_id,
                                     file_name=self.name))
            self.requests += 1
            self.next_request = now + THESIS_REQUEST_INTERVAL
        elif (self.state == "sending" and not self.queue and not self.fifo
              and now >= self.last_heard + THESIS_GIVE_UP):
            self.state = "failed"

    def next_timer(self) -> float | None:
        if self.state == "request":
            return self.next_request
        if self.state == "sending" and not self.queue:
            return self.last_heard + THESIS_GIVE_UP
        return None

    def has_frames(self) -> bool:
        return self.state == "sending" and bool(self.queue)

    def refill(self, now: float) -> None:
        if self.state != "sending" or not self.queue:
            return
        seq = self.queue.popleft()
        self.queued.discard(seq)
        chunk = self.data[seq * THESIS_PART:(seq + 1) * THESIS_PART]
        self.send(self.d.part(target_system=self.peer[0], file_id=self.file_id, sequence=seq, payload=chunk))
        self.parts_sent += 1
        if not self.queue:
            self.last_heard = max(self.last_heard, now)

    def _enqueue(self, start: int, end: int) -> None:
        for seq in range(start, end + 1):
            if seq not in self.queued:
                self.queue.append(seq)
                self.queued.add(seq)

    def on_message(self, now: float, msg: Message) -> None:
        if not _targets(msg, self.ids) or getattr(msg, "file_id", None) != self.file_id:
            return
        if isinstance(msg, self.d.ack):
            self.last_heard = now
            if self.state == "request":
                if msg.result == ACCEPTED:
                    self.state = "sending"
                    self._enqueue(0, self.parts - 1)
                else:
                    self.state = "failed"
        elif isinstance(msg, self.d.resend) and self.state in ("sending", "request"):
            self.last_heard = now
            start, end = msg.sequence_start, msg.sequence_end
            if start == DONE and end == DONE:
                self.state = "done"
                self.queue.clear()
                self.queued.clear()
            elif start <= end < self.parts:
                self.state = "sending"
                self.resends += 1
                self._enqueue(start, end)


class ThesisReceiver(_End):
    def __init__(self, ids: Ids, rate_Bps: float | None, mtu: int = 100) -> None:
        self.d = thesis_dialect()
        super().__init__(ids, rate_Bps, mtu, self.d.registry)
        self.peer: Ids | None = None
        self.file_id: int | None = None
        self.size = 0
        self.parts = 0
        self.have: bytearray = bytearray()
        self.missing = 0
        self.buf = bytearray()
        self.timer: float | None = None
        self.complete_at: float | None = None
        self.done_at: float | None = None
        self.done_left = 0
        self.resend_requests = 0
        self.resend_log: list[tuple[float, int, int]] = []  # (time, first part, last part) asked for
        self.parts_received = 0
        self.duplicates = 0

    @property
    def content(self) -> bytes:
        return bytes(self.buf)

    def _accept(self, msg: Any) -> None:
        self.file_id = msg.file_id
        self.size = msg.file_size
        self.parts = math.ceil(self.size / THESIS_PART)
        self.have = bytearray(self.parts)
        self.missing = self.parts
        self.buf = bytearray(self.size)
        self.timer = None  # the thesis starts the timer on the first part
        self.complete_at = None

    def _send_done(self, now: float) -> None:
        assert self.peer is not None and self.file_id is not None
        self.send(self.d.resend(target_system=self.peer[0], file_id=self.file_id, sequence_start=DONE,
                                sequence_end=DONE))

    def _complete(self, now: float) -> None:
        self.complete_at = now
        self.timer = None
        self._send_done(now)
        self.done_left = THESIS_DONE_REPEATS
        self.done_at = now + THESIS_TIMEOUT

    def on_message(self, now: float, msg: Message) -> None:
        if not _targets(msg, self.ids):
            return
        if isinstance(msg, self.d.request):
            self.peer = (msg.get_srcSystem(), msg.get_srcComponent())
            same = self.file_id == msg.file_id and self.size == msg.file_size
            if not same:
                if self.file_id is not None and self.complete_at is None:
                    self.send(self.d.ack(target_system=self.peer[0], file_id=msg.file_id, result=IN_PROGRESS,
                                         progress=self._progress()))
                    return
                self._accept(msg)
            if self.complete_at is not None:
                self._send_done(now)
                return
            self.send(self.d.ack(target_system=self.peer[0], file_id=msg.file_id, result=ACCEPTED,
                                 progress=self._progress()))
            if self.parts == 0:
                self._complete(now)
        elif isinstance(msg, self.d.part) and msg.file_id == self.file_id:
            seq = msg.sequence
            if seq >= self.parts:
                return  # the thesis crashed here
            if self.complete_at is not None:
                self.duplicates += 1
                self._send_done(now)
                return
            self.parts_received += 1
            if self.have[seq]:
                self.duplicates += 1
            else:
                self.have[seq] = 1
                self.missing -= 1
                n = min(THESIS_PART, self.size - seq * THESIS_PART)  # the thesis copied 250 bytes always
                self.buf[seq * THESIS_PART:seq * THESIS_PART + n] = msg.payload[:n].ljust(n, b"\x00")
            if self.missing == 0:
                self._complete(now)
            else:
                self.timer = now + THESIS_TIMEOUT

    def _progress(self) -> int:
        return 100 * (self.parts - self.missing) // self.parts if self.parts else 100

    def first_missing_range(self) -> tuple[int, int] | None:
        start = self.have.find(0)
        if start < 0:
            return None
        end = self.have.find(1, start)
        return start, (end - 1 if end >= 0 else self.parts - 1)

    def on_time(self, now: float) -> None:
        if self.timer is not None and now >= self.timer:
            rng = self.first_missing_range()
            if rng is not None and self.peer is not None and self.file_id is not None:
                self.send(self.d.resend(target_system=self.peer[0], file_id=self.file_id, sequence_start=rng[0],
                                        sequence_end=rng[1]))
                self.resend_requests += 1
                self.resend_log.append((now, *rng))
            self.timer = now + THESIS_TIMEOUT
        if self.done_at is not None and now >= self.done_at:
            self._send_done(now)
            self.done_left -= 1
            self.done_at = now + THESIS_TIMEOUT if self.done_left > 0 else None

    def next_timer(self) -> float | None:
        ts = [t for t in (self.timer, self.done_at) if t is not None]
        return min(ts) if ts else None


# -- MAVLink FTP: pymavlink's client in virtual time, an ArduPilot-like server --------------------

class _Abort(BaseException):
    """Ends the client thread from inside pymavlink's loop (not an Exception: nothing catches it)."""


class _Clock:
    """What the private copy of pymavlink.mavftp sees as the `time` module."""

    def __init__(self) -> None:
        self.now = 0.0

    def time(self) -> float:
        return self.now

    def monotonic(self) -> float:
        return self.now

    def sleep(self, seconds: float) -> None:
        self.now += seconds


def _load_mavftp(clock: _Clock) -> ModuleType:
    """A private copy of pymavlink.mavftp whose clock is `clock` and whose log is quiet; the
    real module is left untouched."""
    from pymavlink import mavftp  # type: ignore[import-untyped]

    spec = importlib.util.spec_from_file_location("_ttctl_bench_mavftp", mavftp.__file__)
    assert spec is not None and spec.loader is not None
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    quiet = logging.getLogger("ttctl.bench.mavftp")
    quiet.propagate = False
    if not quiet.handlers:
        quiet.addHandler(logging.NullHandler())
    mod.time = clock  # type: ignore[attr-defined]
    mod.logging = quiet  # type: ignore[attr-defined]
    return mod


def mavftp_defaults() -> dict[str, Any]:
    """pymavlink's MAVFTP settings as its command line defines them (the same values as the
    class's built-in defaults)."""
    from pymavlink.mavftp import create_argument_parser  # type: ignore[import-untyped]

    p = create_argument_parser()
    names = ("debug", "pkt_loss_tx", "pkt_loss_rx", "max_backlog", "burst_read_size", "write_size", "write_qsize",
             "idle_detection_time", "read_retry_time", "retry_time")
    return {n: p.get_default(n) for n in names}


class MavftpClient(_End):
    """pymavlink's MAVFTP put, run in a thread that only runs while the simulation waits."""

    def __init__(self, ids: Ids, peer: Ids, data: bytes, rate_Bps: float | None, mtu: int = 100,
                 name: str = "bench.bin", settings: dict[str, Any] | None = None, max_attempts: int = 50) -> None:
        super().__init__(ids, rate_Bps, mtu, REGISTRY)
        self.peer = peer
        self.data = data
        self.name = name
        self.clock = _Clock()
        self.mod = _load_mavftp(self.clock)
        self.overrides = dict(settings or {})
        self.settings: dict[str, Any] = {}  # what the client ran with, read back from pymavlink
        self.max_attempts = max_attempts
        self.attempts = 0
        self.result: int | None = None  # pymavlink's FtpError of the last put
        self.error: BaseException | None = None
        self.finished = False
        self.writes_sent = 0
        self.write_frames: dict[tuple[int, int, int], int] = {}  # (data bytes, frame bytes, packets) -> count
        self.ops_sent: dict[int, int] = {}
        self._inbox: deque[Any] = deque()
        self._deadline: float | None = None
        self._abort = False
        self._go = threading.Semaphore(0)
        self._back = threading.Semaphore(0)
        self._thread: threading.Thread | None = None

    # -- what pymavlink sees as `master` ---------------------------------------------------------
    @property
    def source_system(self) -> int:
        return self.ids[0]

    @property
    def source_component(self) -> int:
        return self.ids[1]

    @property
    def mav(self) -> MavftpClient:
        return self

    def file_transfer_protocol_send(self, target_network: int, target_system: int, target_component: int,
                                    payload: Any) -> None:
        p = bytes(payload)
        op = p[3]
        self.ops_sent[op] = self.ops_sent.get(op, 0) + 1
        sent = self.send(ttapi.FileTransferProtocol(target_network=target_network, target_system=target_system,
                                                    target_component=target_component, payload=p))
        if op == self.mod.OP_WriteFile:
            self.writes_sent += 1
            key = (p[4], *sent)  # (data bytes, frame bytes, packets)
            self.write_frames[key] = self.write_frames.get(key, 0) + 1

    def recv_match(self, type: Any = None, timeout: float | None = None, blocking: bool = False,
                   condition: Any = None) -> Any:
        if self._inbox:
            return self._inbox.popleft()
        self._deadline = self.clock.now + max(timeout or 0.0, 1e-3)
        self._back.release()
        self._go.acquire()
        self._deadline = None
        if self._abort:
            raise _Abort
        return self._inbox.popleft() if self._inbox else None

    # -- the client thread -----------------------------------------------------------------------
    def _main(self) -> None:
        mod = self.mod
        try:
            while self.attempts < self.max_attempts:
                self.attempts += 1
                ftp = mod.MAVFTP(self, self.peer[0], self.peer[1])  # pymavlink's own defaults
                for k, v in self.overrides.items():  # the put reads these (write_size, write_qsize...) later
                    setattr(ftp.ftp_settings, k, v)
                self.settings = {k: getattr(ftp.ftp_settings, k) for k in ftp.ftp_settings._vars}
                ret = ftp.cmd_put([self.name], fh=io.BytesIO(self.data))
                if ret.error_code == mod.FtpError.Success:
                    ret = ftp.process_ftp_reply("put", timeout=0)
                self.result = int(ret.error_code)
                if ret.error_code == mod.FtpError.Success:
                    break
        except _Abort:
            pass
        except Exception as e:  # a pymavlink we do not know how to drive: report, do not hang
            self.error = e
        finally:
            self.finished = True
            self._deadline = None
            self._back.release()

    def _resume(self, now: float) -> None:
        self.clock.now = max(self.clock.now, now)
        self._go.release()
        self._back.acquire()

    def start(self) -> None:
        self._thread = threading.Thread(target=self._main, name="ttctl-bench-mavftp", daemon=True)
        self._thread.start()
        self._back.acquire()  # until it first waits for a reply (or ends)

    def close(self) -> None:
        if self._thread is None:
            return
        if not self.finished:
            self._abort = True
            self._go.release()
            self._back.acquire()
        self._thread.join(timeout=5)
        self._thread = None

    # -- node hooks ------------------------------------------------------------------------------
    def on_message(self, now: float, msg: Message) -> None:
        if isinstance(msg, ttapi.FileTransferProtocol) and msg.target_system == self.ids[0]:
            self._inbox.append(msg)

    def on_time(self, now: float) -> None:
        if self.finished or self._deadline is None:
            return
        if self._inbox or now >= self._deadline - 1e-9:
            self._resume(now)

    def next_timer(self) -> float | None:
        return None if self.finished else self._deadline


FTP_HEADER = struct.Struct("<HBBBBBBI")  # seq, session, opcode, size, req_opcode, burst_complete, pad, offset
FTP_DATA_MAX = 239
FTP_SESSION_TIMEOUT = 3.0  # AP_MAVLinkFTP


@dataclass
class _Reply:
    seq: int
    session: int
    opcode: int
    size: int
    req_opcode: int
    offset: int = 0
    data: bytes = b""
    sysid: int = 0
    compid: int = 0


class FtpServer(_End):
    """MAVLink FTP server, after ArduPilot's ftp_worker (CreateFile/OpenFileWO, WriteFile,
    TerminateSession, ResetSessions; one open file). `expect` is the benchmark's oracle: the
    moment the file holds exactly those bytes is recorded in complete_at."""

    def __init__(self, ids: Ids, rate_Bps: float | None, expect: bytes, mtu: int = 100) -> None:
        super().__init__(ids, rate_Bps, mtu, REGISTRY)
        from pymavlink import mavftp_op as op  # type: ignore[import-untyped]

        self.op = op
        self.expect = expect
        self.disk = bytearray()  # the one file this model serves, as stored
        self.open = False
        self.session = -1
        self.last: _Reply | None = None
        self.last_send = -math.inf
        self.complete_at: float | None = None
        self._mask = bytearray(len(expect))
        self._covered = 0
        self.requests = 0
        self.repeats_answered = 0

    @property
    def content(self) -> bytes:
        return bytes(self.disk)

    def _nak(self, r: _Reply, error: int) -> None:
        r.opcode, r.size, r.data = self.op.OP_Nack, 1, bytes((error,))

    def _push(self, now: float, r: _Reply) -> None:
        payload = FTP_HEADER.pack(r.seq & 0xFFFF, r.session & 0xFF, r.opcode, r.size, r.req_opcode, 0, 0,
                                  r.offset) + r.data
        self.send(ttapi.FileTransferProtocol(target_network=0, target_system=r.sysid, target_component=r.compid,
                                             payload=payload.ljust(251, b"\x00")))
        self.last_send = now

    def on_message(self, now: float, msg: Message) -> None:
        if not isinstance(msg, ttapi.FileTransferProtocol) or msg.target_system != self.ids[0]:
            return
        p = bytes(msg.payload)
        seq, session, opcode, size, _req, _burst, _pad, offset = FTP_HEADER.unpack_from(p)
        data = p[12:12 + min(size, FTP_DATA_MAX)]
        sysid, compid = msg.get_srcSystem(), msg.get_srcComponent()
        self.requests += 1
        last = self.last
        if (last is not None and last.sysid == sysid and last.compid == compid and last.session == session
                and (seq + 1) & 0xFFFF == last.seq):
            self.repeats_answered += 1  # a re-request: send the stored reply again
            self._push(now, last)
            return
        op = self.op
        r = _Reply(seq=(seq + 1) & 0xFFFF, session=session, opcode=op.OP_Ack, size=0, req_opcode=opcode,
                   sysid=sysid, compid=compid)
        open_ = self.open
        if size > FTP_DATA_MAX:
            self._nak(r, 3)  # InvalidDataSize
        elif session != self.session and opcode in (op.OP_TerminateSession, op.OP_ResetSessions):
            pass  # terminating another session: just ack
        elif open_ and session != self.session and now - self.last_send < FTP_SESSION_TIMEOUT:
            self._nak(r, 4)  # InvalidSession
        else:
            if open_ and session != self.session:
                self.open, self.session = False, -1  # the old session went quiet: close it
            if opcode in (op.OP_TerminateSession, op.OP_ResetSessions):
                self.open, self.session = False, -1
            elif opcode in (op.OP_CreateFile, op.OP_OpenFileWO):
                name = data.split(b"\x00", 1)[0]
                if self.open:
                    self._nak(r, 1)  # Fail: one open file
                elif not name or len(name) != size:
                    self._nak(r, 3)
                else:
                    self._open(now, truncate=opcode == op.OP_CreateFile)
                    self.session = session
            elif opcode == op.OP_WriteFile:
                if not self.open:
                    self._nak(r, 10)  # FileNotFound
                else:
                    self._write(now, offset, data)
                    r.offset = offset
            elif opcode in (op.OP_Ack, op.OP_Nack):
                return
            elif opcode != op.OP_None:
                self._nak(r, 7)  # UnknownCommand (what this model does not serve)
        self.last = r
        self._push(now, r)

    def _open(self, now: float, truncate: bool) -> None:
        self.open = True
        if truncate:
            self.disk = bytearray()
            self._mask = bytearray(len(self.expect))
            self._covered = 0
            if not self.expect and self.complete_at is None:
                self.complete_at = now

    def _write(self, now: float, offset: int, data: bytes) -> None:
        f = self.disk
        end = offset + len(data)
        if len(f) < end:
            f.extend(bytes(end - len(f)))
        f[offset:end] = data
        lo, hi = min(offset, len(self._mask)), min(end, len(self._mask))
        if hi > lo:
            self._covered += self._mask[lo:hi].count(0)
            self._mask[lo:hi] = b"\x01" * (hi - lo)
        if (self.complete_at is None and self._covered == len(self.expect) and len(f) == len(self.expect)
                and f == self.expect):
            self.complete_at = now


# -- runners -------------------------------------------------------------------------------------

@dataclass
class BaselineRun:
    """One simulated transfer: the benchmark's figures plus what the tests look at."""

    seconds: float
    ok: bool
    stats: dict[str, Any] = field(default_factory=dict)
    up: dict[str, int] = field(default_factory=dict)
    down: dict[str, int] = field(default_factory=dict)


def _ends(case: Case) -> tuple[Ids, Ids]:
    """(sender, receiver) ids."""
    return (TABLET, ONBOARD) if case.direction == "up" else (ONBOARD, TABLET)


def _simulate(make: Callable[[Ids, Ids, float, float, int], tuple[_End, _End]], profile: Profile, distance: float,
              case: Case, seed: int, limit: float, done: Callable[[_End, _End], bool]
              ) -> tuple[Simulation, _End, _End, Channel, Channel]:
    up, down = channels(profile, distance, case, seed)
    s_ids, r_ids = _ends(case)
    s_rate, r_rate = (pace(up), pace(down)) if case.direction == "up" else (pace(down), pace(up))
    sender, receiver = make(s_ids, r_ids, s_rate, r_rate, profile.mtu)
    tablet, onboard = (sender, receiver) if case.direction == "up" else (receiver, sender)
    sim = Simulation(tablet, onboard, up, down)
    sim.run(limit, stop=lambda: done(sender, receiver))
    return sim, sender, receiver, up, down


def thesis_transfer(profile: Profile, distance: float, case: Case, data: bytes, seed: int, limit: float = 7200.0,
                    until_sender_done: bool = False) -> BaselineRun:
    def make(s_ids: Ids, r_ids: Ids, s_rate: float, r_rate: float, mtu: int) -> tuple[_End, _End]:
        return ThesisSender(s_ids, r_ids, data, s_rate, mtu), ThesisReceiver(r_ids, r_rate, mtu)

    def done(s: Any, r: Any) -> bool:
        if until_sender_done:
            return s.state in ("done", "failed")
        return r.complete_at is not None or s.state == "failed"

    sim, s, r, up, down = _simulate(make, profile, distance, case, seed, limit, done)
    assert isinstance(s, ThesisSender) and isinstance(r, ThesisReceiver)
    ok = r.complete_at is not None and r.content == data
    stats = {"requests": s.requests, "parts_sent": s.parts_sent, "resends": s.resends, "sender_state": s.state,
             "resend_requests": r.resend_requests, "resend_log": r.resend_log, "parts_received": r.parts_received,
             "duplicates": r.duplicates,
             "frames_sent": s.frames_sent, "packets_sent": s.packets_sent, "ended_at": sim.now}
    return BaselineRun(r.complete_at if ok and r.complete_at is not None else limit, ok, stats,
                       up.stats.as_dict(), down.stats.as_dict())


def mavftp_transfer(profile: Profile, distance: float, case: Case, data: bytes, seed: int, limit: float = 7200.0,
                    settings: dict[str, Any] | None = None, until_client_done: bool = False) -> BaselineRun:
    clients: list[MavftpClient] = []

    def make(s_ids: Ids, r_ids: Ids, s_rate: float, r_rate: float, mtu: int) -> tuple[_End, _End]:
        c = MavftpClient(s_ids, r_ids, data, s_rate, mtu, settings=settings)
        clients.append(c)
        srv = FtpServer(r_ids, r_rate, data, mtu)
        c.start()
        return c, srv

    def done(c: Any, srv: Any) -> bool:
        if until_client_done:
            return bool(c.finished)
        return srv.complete_at is not None or c.finished

    try:
        sim, c, srv, up, down = _simulate(make, profile, distance, case, seed, limit, done)
    finally:
        for cl in clients:
            cl.close()
    assert isinstance(c, MavftpClient) and isinstance(srv, FtpServer)
    if c.error is not None:
        raise RuntimeError(f"pymavlink's MAVFTP could not be driven: {type(c.error).__name__}: {c.error}") \
            from c.error
    ok = srv.complete_at is not None and srv.content == data
    stats = {"attempts": c.attempts, "result": c.result, "writes_sent": c.writes_sent, "ops_sent": dict(c.ops_sent),
             "write_frames": dict(c.write_frames),
             "frames_sent": c.frames_sent, "packets_sent": c.packets_sent, "server_requests": srv.requests,
             "repeats_answered": srv.repeats_answered, "settings": c.settings, "ended_at": sim.now}
    return BaselineRun(srv.complete_at if ok and srv.complete_at is not None else limit, ok, stats,
                       up.stats.as_dict(), down.stats.as_dict())


def _realised(r: BaselineRun, case: Case) -> float:
    ch = r.up if case.direction == "up" else r.down
    return ch.get("lost", 0) / max(1, ch.get("submitted", 0))


def run_thesis(profile: Profile, distance: float, case: Case, data: bytes, seed: int,
               limit: float = 7200.0) -> tuple[float, bool, float]:
    """The thesis file transfer (see the module documentation): (seconds, ok, the loss the
    data's direction realised)."""
    r = thesis_transfer(profile, distance, case, data, seed, limit)
    return r.seconds, r.ok, _realised(r, case)


def run_mavftp(profile: Profile, distance: float, case: Case, data: bytes, seed: int,
               limit: float = 7200.0) -> tuple[float, bool, float]:
    """MAVLink FTP upload by pymavlink's MAVFTP with its defaults (see the module
    documentation): (seconds, ok, realised loss)."""
    r = mavftp_transfer(profile, distance, case, data, seed, limit)
    return r.seconds, r.ok, _realised(r, case)
