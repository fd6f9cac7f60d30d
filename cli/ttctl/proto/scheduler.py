"""Which bytes go into the next DTT packet, and when: priorities at packet granularity.

A packet is built only when the pacer allows one to leave, from what is waiting at that
moment: control frames (commands, acks, file-transfer control) first, then telemetry, then
bulk data pulled from the active transfers (round-robin). A frame longer than a packet
continues in the next packets; if control frames are waiting meanwhile, they go first in a
packet of their own (the receiver keeps the long frame's pieces apart from it). Nothing sits
in a FIFO behind a file, so a command sent during a bulk transfer waits at most for the
packet on the air.

A command sent again (its copy or retry, when no ack came) is due at a known time
(`control_due`): bulk data then goes in packets that leave the radio by that time, so the retry
does not wait behind one. A packet is at most (due - now) x rate bytes of bulk; when not even a
frame (or a piece of a long one, MIN_PIECE bytes) fits, the link waits for the retry. A first
try cannot be foreseen, and waits for the packet on the air as before.

With MAVLink signing, frames are signed as they are placed in a packet (`sign`), so their
timestamps increase in the order they go on the wire whatever the priorities reorder, and no
frame is slipped between the pieces of a long one (it would arrive, with a later timestamp,
before the long frame completes, which the receiver would then refuse as a replay).

A second path, a pipeline (DJI's MOP: a reliable byte stream beside the packet channel), may be
open (`open_pipe`): while it is, bulk data is pulled for it (`next_pipe_frame`, paced at the
pipeline's own rate, whole frames, no packet size) and the packets carry only control and
telemetry, so a command never waits behind a file. When it closes (`close_pipe`) bulk data goes
back into the packets. Signed frames from both paths take their timestamps from one signer, in the
order they are placed.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable

SIGNATURE_OVERHEAD = 13
MIN_PIECE = 20  # bytes: a long frame's piece shorter than this does not go just to fill the time before a retry
PIPE_SLACK = 0.02  # s of a late wake-up the pipeline's pacer makes up (a stream has no radio buffer to overflow)

CONTROL, TELEMETRY, BULK = 0, 1, 2
PRIORITY_NAMES = {CONTROL: "control", TELEMETRY: "telemetry", BULK: "bulk"}

BulkPull = Callable[[float, int], bytes | None]
"""A bulk source: given (now, bytes free in the packet being built, possibly 0) returns the next
frame, or None if it has nothing to send now."""


class Pacer:
    """Lets packets leave at `rate` bytes per second on average: a packet of n bytes
    occupies n / rate seconds of the link. rate None means unpaced."""

    def __init__(self, rate_Bps: float | None, slack: float = 0.0) -> None:
        self.rate = rate_Bps
        self.next_free = 0.0
        # seconds of lateness it makes up (a timer that wakes late sends a little burst rather
        # than losing the time; 0: none, for a radio whose buffer a burst would overflow)
        self.slack = slack

    def ready_at(self) -> float:
        return self.next_free if self.rate else 0.0

    def ready(self, now: float) -> bool:
        return self.rate is None or now >= self.next_free - 1e-9

    def sent(self, now: float, nbytes: int) -> None:
        if self.rate:
            self.next_free = max(now - self.slack, self.next_free) + nbytes / self.rate


class Scheduler:
    def __init__(self, mtu: int = 100, rate_Bps: float | None = None, telemetry_limit: int = 32,
                 sign: Callable[[bytes], bytes] | None = None,
                 control_due: Callable[[], float | None] | None = None) -> None:
        self.mtu = mtu
        # when a control frame is next known to be queued (a command's copy or retry), or None
        self.control_due = control_due
        self._held_until: float | None = None  # bulk data waits for a due control frame until then
        self.sign = sign  # signs an unsigned frame as it is placed (MAVLink signing), or None
        self.pacer = Pacer(rate_Bps)
        self.control: deque[bytes] = deque()
        self._control_keys: deque[object] = deque()  # each queued control frame's coalescing key (None: none)
        self.telemetry: deque[bytes] = deque()
        self.telemetry_limit = telemetry_limit
        self.sources: list[BulkPull] = []
        self._rr = 0
        self._spill = b""  # the rest of a frame longer than a packet
        self._held: bytes | None = None  # a bulk frame pulled but not yet placed
        self.packets = 0
        self.bytes = 0
        self.dropped_telemetry = 0
        self.pipe: Pacer | None = None  # the pipeline's pace while one is open
        self._pipe_sign: Callable[[bytes], bytes] | None = None
        self.pipe_frames = 0
        self.pipe_bytes = 0

    # -- what to send ------------------------------------------------------------------------
    def send(self, frame: bytes, priority: int = CONTROL, key: object = None) -> None:
        """Queue a frame. A control frame with a `key` replaces a queued, unsent frame with
        the same key (a newer status makes an older one worthless)."""
        if priority == CONTROL:
            if key is not None:
                # (by key, not by the queued frame's id(): CPython reuses the id of a frame that
                # was sent and freed, and a keyed frame then replaced an unrelated one, an ack say)
                for i, queued_key in enumerate(self._control_keys):
                    if queued_key == key:
                        self.control[i] = frame
                        return
            self.control.append(frame)
            self._control_keys.append(key)
        elif priority == TELEMETRY:
            if len(self.telemetry) >= self.telemetry_limit:
                self.telemetry.popleft()  # stale telemetry goes first; control is never dropped
                self.dropped_telemetry += 1
            self.telemetry.append(frame)
        else:
            raise ValueError("bulk data is pulled from a source, not sent")

    def add_source(self, pull: BulkPull) -> None:
        self.sources.append(pull)

    def remove_source(self, pull: BulkPull) -> None:
        if pull in self.sources:
            self.sources.remove(pull)

    # -- the pipeline ------------------------------------------------------------------------
    def open_pipe(self, rate_Bps: float | None, now: float = 0.0,
                  sign: Callable[[bytes], bytes] | None = None) -> None:
        """Bulk data goes on a pipeline at `rate_Bps` (None: as fast as it is pulled) from now,
        signed by `sign` when the link is signed (the pipeline's own link id: see pipeline.py)."""
        self.pipe = Pacer(rate_Bps, slack=PIPE_SLACK)
        self.pipe.next_free = now
        self._pipe_sign = sign

    def close_pipe(self) -> None:
        self.pipe = None

    def pipe_ready_at(self) -> float | None:
        """When the pipeline may take the next bulk frame (None: no pipeline)."""
        return None if self.pipe is None else self.pipe.ready_at()

    def next_pipe_frame(self, now: float, space: int) -> bytes | None:
        """The next bulk frame for the pipeline, if one may leave now (`space`: the largest frame
        the stream takes in one piece, any MAVLink frame)."""
        pipe = self.pipe
        if pipe is None or not pipe.ready(now):
            return None
        pulled = self._pull(now, space)
        if pulled is None:
            return None
        sign = self._pipe_sign or self.sign
        frame = sign(pulled) if sign is not None else pulled
        pipe.sent(now, len(frame))
        self.pipe_frames += 1
        self.pipe_bytes += len(frame)
        return frame

    def _pull(self, now: float, space: int) -> bytes | None:
        """The next bulk frame from the sources, round-robin."""
        n = len(self.sources)
        for k in range(n):
            i = (self._rr + k) % n
            pulled = self.sources[i](now, space)
            if pulled is not None:
                self._rr = (i + 1) % n
                return pulled
        return None

    @property
    def busy(self) -> bool:
        """Anything queued (sources may still have data on demand)."""
        return bool(self.control or self.telemetry or self._spill or self._held)

    # -- building packets --------------------------------------------------------------------
    def ready_at(self) -> float:
        t = self.pacer.ready_at()
        if self._held_until is not None and not (self.control or self.telemetry):
            due = self._due()
            if due is not None and due <= self._held_until:  # only bulk waits, and for that retry still
                t = max(t, due)
        return t

    def _due(self) -> float | None:
        return self.control_due() if self.control_due is not None else None

    def _bulk_limit(self, now: float) -> int:
        """How long a packet bulk data may fill now: the whole packet, or what leaves the radio
        before a control frame falls due (the pacer's rate; unpaced: no limit)."""
        due = self._due()
        if due is None or not self.pacer.rate or due <= now:
            return self.mtu
        return min(self.mtu, int((due - now) * self.pacer.rate))

    def next_packet(self, now: float) -> bytes | None:
        if not self.pacer.ready(now):
            return None
        pkt = self._build(now)
        if pkt:
            self.pacer.sent(now, len(pkt))
            self.packets += 1
            self.bytes += len(pkt)
            return pkt
        return None

    def _build(self, now: float) -> bytes:
        mtu = self.mtu
        pkt = bytearray()
        over = SIGNATURE_OVERHEAD if self.sign is not None else 0
        self._held_until = None
        limit = self._bulk_limit(now)
        if self._spill and self.control and len(self.control[0]) + over <= mtu and self.sign is None:
            while self.control and len(self.control[0]) <= mtu - len(pkt):  # urgent, in a packet of its own
                pkt += self.control.popleft()
                self._control_keys.popleft()
            return bytes(pkt)
        if self._spill:
            # signed, nothing goes between a long frame's pieces: a shorter piece would not help
            n = mtu if self.sign is not None or limit >= mtu else self._piece(limit, len(self._spill))
            if n == 0:
                self._held_until = self._due()
                return b""
            pkt += self._spill[:n]
            self._spill = self._spill[n:]
            if self._spill or len(pkt) == mtu:
                return bytes(pkt)
        while len(pkt) < mtu:
            space = mtu - len(pkt)
            # (signed, a frame is `over` longer than its source thinks)
            got = self._next_frame(now, space, limit - len(pkt))
            if got is None:
                break
            frame, kind, key = got
            size = len(frame) + over
            if kind == BULK and limit < mtu:  # a control frame is due: only what leaves before it
                space = limit - len(pkt)
                if size > space and (size <= mtu or self.sign is not None or self._piece(space, size) == 0):
                    self._held = frame
                    break
            if (size <= space or size > mtu) and self.sign is not None:
                frame = self.sign(frame)  # placed now: signed now
            if size <= space:
                pkt += frame
            elif size > mtu:
                pkt += frame[:space]
                self._spill = frame[space:]
                break
            else:  # does not fit what is left: back to the head of its queue, for the next packet
                if kind == CONTROL:
                    self.control.appendleft(frame)
                    self._control_keys.appendleft(key)
                elif kind == TELEMETRY:
                    self.telemetry.appendleft(frame)
                else:
                    self._held = frame
                break
        if not pkt and limit < mtu:  # (what bulk there is waits: a source's frame may not fit either)
            self._held_until = self._due()
        return bytes(pkt)

    @staticmethod
    def _piece(room: int, left: int) -> int:
        """How much of a long frame's `left` bytes go in `room` before a due control frame: all
        that fits, if that is the rest or at least MIN_PIECE bytes, else none."""
        if room >= left:
            return left
        return room if room >= MIN_PIECE else 0

    def _next_frame(self, now: float, space: int, bulk_space: int) -> tuple[bytes, int, object] | None:
        if self.control:
            return self.control.popleft(), CONTROL, self._control_keys.popleft()
        if self.telemetry:
            return self.telemetry.popleft(), TELEMETRY, None
        if self._held is not None:
            frame, self._held = self._held, None
            return frame, BULK, None
        if self.pipe is not None or bulk_space <= 0:
            return None  # bulk data takes the pipeline, or waits for a due control frame
        pulled = self._pull(now, min(space, bulk_space))
        return None if pulled is None else (pulled, BULK, None)

    def wants_to_send(self, now: float) -> bool:
        """Something is queued or a source may produce (callers use ready_at for timing)."""
        return self.busy or bool(self.sources)
