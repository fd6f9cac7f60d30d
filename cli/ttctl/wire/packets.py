"""MAVLink frames in DTT packets (at most `mtu` bytes, 100 on DJI's link) and back.

Packets carry raw MAVLink 2 bytes, no header of their own, so any MAVLink tool can read the
stream. The packing rule (the generated C++ and Java packetizers follow it too):

- a frame that fits in the space left in the current packet is appended;
- else a frame of at most `mtu` bytes starts a new packet: it never straddles two packets;
- else (a frame longer than a packet) it fills the current packet and continues in the next
  ones, back to back.

The receiver is packet-aware: every frame inside one packet is delivered as soon as that
packet arrives, whatever happened to other packets; a frame spanning packets is assembled
from the packets that continue it. A packet that starts with a whole valid frame is never taken
as a continuation, so a sender may slip a packet of urgent frames between the pieces of a long
frame; and a long frame must end at its last packet's end or be followed there by the next
frame's header, so a false assembly across a lost packet whose CRC matches by chance is rarely
believed. A lost, corrupted, duplicated or reordered packet therefore costs only the frames
that overlapped it.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any

from .bindings import Bindings

MAGIC = 0xFD
INCOMPAT_SIGNED = 0x01
SIGNATURE_LENGTH = 13

DTT_MTU = 100


class Packetizer:
    """Cuts frames into packets by the rule above. `emit` receives each finished packet."""

    def __init__(self, emit: Callable[[bytes], None], mtu: int = DTT_MTU) -> None:
        if mtu < 13:
            raise ValueError("an MTU below 13 bytes cannot carry a MAVLink 2 header")
        self.mtu = mtu
        self.emit = emit
        self._cur = bytearray()

    @property
    def pending(self) -> int:
        return len(self._cur)

    def add(self, frame: bytes) -> None:
        mtu, cur = self.mtu, self._cur
        n = len(frame)
        if n <= mtu - len(cur):
            cur += frame
        elif n <= mtu:
            if cur:
                self._ship()
            self._cur += frame
        else:
            view = memoryview(frame)
            space = mtu - len(cur)
            self._cur += view[:space]
            view = view[space:]
            while True:
                self._ship()
                self._cur += view[:mtu]
                view = view[mtu:]
                if not view:
                    break
        if len(self._cur) == mtu:
            self._ship()

    def flush(self) -> None:
        if self._cur:
            self._ship()

    def _ship(self) -> None:
        self.emit(bytes(self._cur))
        self._cur = bytearray()


def packetize(frames: Iterable[bytes], mtu: int = DTT_MTU) -> list[bytes]:
    out: list[bytes] = []
    p = Packetizer(out.append, mtu)
    for f in frames:
        p.add(f)
    p.flush()
    return out


class ReceiverStats:
    __slots__ = ("bad_frames", "carries_dropped", "frames", "packets", "rescans", "unknown")

    def __init__(self) -> None:
        self.packets = 0
        self.unknown = 0  # whole frames of a message this dialect does not have (see PacketReceiver)
        self.frames = 0
        self.bad_frames = 0  # complete frames that failed CRC, signature or decoding
        self.carries_dropped = 0  # spanning frames whose continuation never came
        self.rescans = 0  # packets taken for a continuation that were scanned on their own after all

    def as_dict(self) -> dict[str, int]:
        return {k: getattr(self, k) for k in self.__slots__}


class PacketReceiver:
    """Frames out of DTT packets; see the module documentation."""

    def __init__(self, bindings: Bindings, signing: Any = None,
                 on_bad: Callable[[bytes, str], None] | None = None,
                 on_unknown: Callable[[int, int, int], None] | None = None,
                 registry: dict[int, Any] | None = None) -> None:
        """`registry`: decode these messages instead of the dialect's (msgid -> MessageInfo of
        the generated framing code: the benchmarks' other protocols)."""
        self.registry = bindings.registry if registry is None else registry
        self._decode_frame = bindings.mavlink.decode
        self._decode_error = bindings.mavlink.DecodeError
        self.signing = signing
        self.on_bad = on_bad
        # (msgid, sysid, compid) of a frame whose message the dialect does not know: its header
        # is where the packing rule puts a frame (at the packet's start or right after a frame)
        # and its length ends it at the packet's end or at the next magic byte. The scan goes on
        # as before (the runtimes decide identically): this only counts and tells.
        self.on_unknown = on_unknown
        self.stats = ReceiverStats()
        self._carry = b""  # a frame begun in an earlier packet, with its continuation so far
        self._origin = b""  # the part of the carry that came from its first packet
        self._taken: list[bytes] = []  # packets appended to the carry, rescanned if it proves false

    @property
    def pending(self) -> int:
        return len(self._carry)

    def feed(self, packet: bytes) -> list[Any]:
        """Messages completed by this packet."""
        self.stats.packets += 1
        out: list[Any] = []
        if packet:  # DJI ignores 0-byte packets; so do we
            self._feed(packet, out)
        self.stats.frames += len(out)
        return out

    def flush(self) -> list[Any]:
        """The link went quiet: give up on a frame still waiting for its continuation and
        return what the packets taken for it hold on their own."""
        out: list[Any] = []
        self._give_up(out)
        self.stats.frames += len(out)
        return out

    def _feed(self, packet: bytes, out: list[Any]) -> None:
        pos = 0
        if self._carry:
            buf = self._carry + packet
            total = self._total(buf, 0)
            complete = total is not None and len(buf) >= total
            own = self._starts_with_frame(packet)
            fits = not own and complete and total is not None and self._rest_plausible(buf, total)
            msg = self._try(buf[:total]) if fits and total is not None else None
            if own:  # 1. a packet of its own (maybe urgent frames slipped between the pieces)
                pass
            elif msg is not None and total is not None:  # 2. the long frame's continuation
                out.append(msg)
                pos = len(packet) - (len(buf) - total)
                self._carry, self._taken, self._origin = b"", [], b""
            elif not complete and (total is not None or len(buf) < 10):  # 3. continues further
                self._carry = buf
                self._taken.append(packet)
                return
            else:  # 4. the long frame was not one
                self.stats.bad_frames += 1
                self._drop_carry(out, packet)
                return
        self._scan(packet, pos, out)

    def _rest_plausible(self, buf: bytes, end: int) -> bool:
        """By the packing rule, what follows a long frame's end in its last packet is nothing or
        the next frame's header: a false continuation whose CRC happens to match (1 in 65536)
        is caught here nearly always, instead of taking the packet's own frames with it."""
        if end == len(buf):
            return True
        return buf[end] == MAGIC and (len(buf) - end < 10 or self._total(buf, end) is not None)

    def _starts_with_frame(self, packet: bytes) -> bool:
        total = self._total(packet, 0)
        return total is not None and total <= len(packet) and self._try(packet[:total], peek=True) is not None

    def _try(self, frame: bytes, peek: bool = False) -> Any:
        """The frame's message, or None. A `peek` leaves the signing's replay state alone: the
        frame is decoded for real when its packet is scanned."""
        try:
            return self._decode_frame(frame, self.registry, self.signing, peek)
        except self._decode_error:
            return None

    def _give_up(self, out: list[Any]) -> None:
        """Drop the frame being assembled for good: replaying the packets it took may begin
        another, which is given up too, so that every frame in those packets comes out."""
        while self._carry:
            self._drop_carry(out)

    def _drop_carry(self, out: list[Any], then: bytes | None = None) -> None:
        """The frame being assembled was not one. Give the next candidate head inside its first
        packet a chance, and replay the packets it had taken (and `then`) so that frames in
        them, and a long frame starting in them, live."""
        self.stats.carries_dropped += 1
        origin = self._origin
        replay = self._taken + ([then] if then is not None else [])
        self._carry, self._taken, self._origin = b"", [], b""
        k = self._next_head(origin, 1)
        if k >= 0:
            self._carry = self._origin = origin[k:]
        for p in replay:
            self.stats.rescans += 1
            self._feed(p, out)

    def _next_head(self, buf: bytes, start: int) -> int:
        """Offset of the first plausible header at or after `start` whose frame runs past the
        end of `buf`, or -1."""
        n = len(buf)
        j = buf.find(b"\xfd", start)
        while j >= 0:
            if n - j < 10:
                return j
            total = self._total(buf, j)
            if total is not None and j + total > n:
                return j
            j = buf.find(b"\xfd", j + 1)
        return -1

    def _total(self, buf: bytes, i: int) -> int | None:
        """Length of the frame whose plausible header starts at buf[i], else None."""
        if len(buf) - i < 10 or buf[i] != MAGIC:
            return None
        incompat = buf[i + 2]
        if incompat & ~INCOMPAT_SIGNED:
            return None
        info = self.registry.get(buf[i + 7] | buf[i + 8] << 8 | buf[i + 9] << 16)
        plen = buf[i + 1]
        if info is None or plen > info.length:
            return None
        return 12 + plen + (SIGNATURE_LENGTH if incompat else 0)

    def _decode(self, frame: bytes) -> Any:
        try:
            return self._decode_frame(frame, self.registry, self.signing)
        except self._decode_error as e:
            self.stats.bad_frames += 1
            if self.on_bad is not None:
                self.on_bad(frame, str(e))
            return None

    def _scan(self, pkt: bytes, pos: int, out: list[Any]) -> None:
        head = -1  # a frame that runs past the end of this packet
        i = pos
        n = len(pkt)
        boundary = pos  # where the packing rule would begin the next frame
        while True:
            j = pkt.find(b"\xfd", i)
            if j < 0:
                break
            if n - j < 10:
                if head < 0:
                    head = j
                break
            total = self._total(pkt, j)
            if total is None:
                if j == boundary:
                    boundary = self._unknown(pkt, j)
                i = j + 1
                continue
            if j + total <= n:
                msg = self._decode(pkt[j:j + total])
                if msg is not None:
                    out.append(msg)
                    head = -1  # a complete frame after it: that head was false
                    i = boundary = j + total
                else:
                    i = j + 1
                continue
            if head < 0:
                head = j
            i = j + 1
        if head >= 0:
            self._give_up(out)  # a newer long frame began: the old one is gone
            self._carry = self._origin = pkt[head:]
            self._taken = []

    def _unknown(self, pkt: bytes, j: int) -> int:
        """Count a frame at a frame boundary whose msgid this dialect lacks (see on_unknown);
        the next boundary: where such a frame ends (-1 if it was not one)."""
        if pkt[j + 2] & ~INCOMPAT_SIGNED:
            return -1
        msgid = pkt[j + 7] | pkt[j + 8] << 8 | pkt[j + 9] << 16
        if msgid in self.registry:
            return -1  # known, but longer than its definition allows: not a frame
        end = j + 12 + pkt[j + 1] + (SIGNATURE_LENGTH if pkt[j + 2] else 0)
        if end == len(pkt) or (end < len(pkt) and pkt[end] == MAGIC) or (j == 0 and end > len(pkt)):
            self.stats.unknown += 1
            if self.on_unknown is not None:
                self.on_unknown(msgid, pkt[j + 5], pkt[j + 6])
            return end
        return -1


def describe(msg: Any) -> str:
    return f"{msg.NAME} from {msg.get_srcSystem()}/{msg.get_srcComponent()}"
