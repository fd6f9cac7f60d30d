"""The thesis's file transfer as a `ttctl bench transfer` baseline (see ttctl.bench.baselines.common).

The thesis protocol (dialect data/dji_icg.xml; the thesis's file transfer, chapter 3), as designed and without the
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
"""

from __future__ import annotations

import math
import struct
from collections import deque
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources
from typing import TYPE_CHECKING, Any, ClassVar

from ttapi.mavlink import Message, MessageInfo  # the generated framing runtime, under the thesis's messages

from ...link.model import Profile
from ..shipped import bindings
from ..transfer import Case
from .common import BaselineRun, End, Ids, realised_loss, simulate, targets

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
    from ...dialect import load_dialect

    d = load_dialect(thesis_xml()).dialect
    by_name = {m.name: m for m in d.messages}
    names = ("DJI_FTP_REQUEST", "DJI_FTP_REQUEST_ACK", "DJI_FTP", "DJI_FTP_REQUEST_RESEND")
    classes = [_message_class(by_name[n]) for n in names]
    registry = dict(bindings().registry)  # common.xml comes from ttapi; 50000+ are the thesis's here
    registry.update({c.MSG_ID: MessageInfo(c) for c in classes})
    return ThesisDialect(request=classes[0], ack=classes[1], part=classes[2], resend=classes[3], registry=registry)


# -- the thesis file transfer --------------------------------------------------------------------

class ThesisSender(End):
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
        if not targets(msg, self.ids) or getattr(msg, "file_id", None) != self.file_id:
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


class ThesisReceiver(End):
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
        if not targets(msg, self.ids):
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


def thesis_transfer(profile: Profile, distance: float, case: Case, data: bytes, seed: int, limit: float = 7200.0,
                    until_sender_done: bool = False) -> BaselineRun:
    def make(s_ids: Ids, r_ids: Ids, s_rate: float, r_rate: float, mtu: int) -> tuple[End, End]:
        return ThesisSender(s_ids, r_ids, data, s_rate, mtu), ThesisReceiver(r_ids, r_rate, mtu)

    def done(s: Any, r: Any) -> bool:
        if until_sender_done:
            return s.state in ("done", "failed")
        return r.complete_at is not None or s.state == "failed"

    sim, s, r, up, down = simulate(make, profile, distance, case, seed, limit, done)
    assert isinstance(s, ThesisSender) and isinstance(r, ThesisReceiver)
    ok = r.complete_at is not None and r.content == data
    stats = {"requests": s.requests, "parts_sent": s.parts_sent, "resends": s.resends, "sender_state": s.state,
             "resend_requests": r.resend_requests, "resend_log": r.resend_log, "parts_received": r.parts_received,
             "duplicates": r.duplicates,
             "frames_sent": s.frames_sent, "packets_sent": s.packets_sent, "ended_at": sim.now}
    return BaselineRun(r.complete_at if ok and r.complete_at is not None else limit, ok, stats,
                       up.stats.as_dict(), down.stats.as_dict())


def run_thesis(profile: Profile, distance: float, case: Case, data: bytes, seed: int,
               limit: float = 7200.0) -> tuple[float, bool, float]:
    """The thesis file transfer (see the module documentation): (seconds, ok, the loss the
    data's direction realised)."""
    r = thesis_transfer(profile, distance, case, data, seed, limit)
    return r.seconds, r.ok, realised_loss(r, case)
