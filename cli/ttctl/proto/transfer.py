"""Reliable file transfer over the DTT link, sans-IO: what both sides share (the protocol's
numbers, its configuration, results). The sides are in sender.py and receiver.py; the same
code runs under the virtual clock and under asyncio on UDP.

Protocol (messages of dialects/ttapi.xml):

1. The sender picks a random 32-bit transfer id (a nonce, new for every transfer, restart and
   resume) and offers the file (TT_FILE_OFFER, repeated until answered): size, SHA-256 and
   name, the latter two in parts. The receiver answers TT_FILE_STATUS: refused (with a
   TT_FILE_REASON in words), busy (offer again later), COMPLETE at once if an identical file
   is already there, or IN_PROGRESS with what it already has (a resumed transfer sends only
   the rest). Every status carries the transfer id and a check of the offer's metadata; a
   sender ignores a status whose check is not its own. No file data moves before the answer.
2. Data flows paced to the link: narrow frames (one frame per packet) while loss is high,
   TT_FILE_DATA_WIDE (247 bytes, frames spanning packets) while the transfer observes little
   loss; the choice follows the loss the sender measures from the receiver's reports. The
   narrow frame is sized to the link's packet (`Geometry`): TT_FILE_DATA (80 bytes in exactly
   100) on DJI's DTT, TT_FILE_DATA_FIT (a frame stating its count) where that fills the packet
   better: 107 bytes in the Payload SDK channel's 128, 66 in a signed 100-byte packet.
3. The receiver reports, every second and sooner when it sees new gaps or the end of the file,
   what it has: everything below an offset, and up to 7 missing ranges above it. The sender
   repeats confirmed-missing ranges before new data; a retransmission is never repeated within
   an RTT.
4. When every byte is there the receiver checks the SHA-256 (of the inflated file, when the
   offer was TT_FILE_FLAGS_DEFLATE: see deflate.py) and renames the file into place,
   then reports COMPLETE, twice more 50 ms apart (and again to any late offer or data of that
   transfer). A
   SHA-256 mismatch discards the data; the sender starts again under a new id (twice at most).
"""

from __future__ import annotations

import hashlib
import math
from dataclasses import dataclass, field

from ..wire.contract import TtFileResult as R
from .names import MAX_NAME_BYTES, SHA_LEN

NARROW = 80  # file bytes in a TT_FILE_DATA frame (100 bytes: one DTT packet)
WIDE = 247  # file bytes in a TT_FILE_DATA_WIDE frame (267 bytes)
NARROW_FRAME = 100
WIDE_FRAME = 267
FIT_MAX = 246  # file bytes a TT_FILE_DATA_FIT frame can carry (21 + count bytes unsigned)
FIT_OVERHEAD = 21  # MAVLink 2 header and CRC (12), transfer id and offset (8), count (1)
SIGNATURE = 13  # a MAVLink 2 signature's bytes
META_PART = 71  # metadata bytes per TT_FILE_OFFER
REQUEST_PART = 80  # name bytes per TT_FILE_REQUEST
MAX_RANGES = 7  # missing ranges per TT_FILE_STATUS
# range_count's top bit: more gaps follow past received_end (the status is one of several), so the bytes
# there are unknown, not missing. A status that fits one packet holds fewer than MAX_RANGES gaps; a sender
# that knows only "MAX_RANGES gaps: more follow" reads min(range_count, MAX_RANGES) = MAX_RANGES and the
# zero pairs after the real ones as empty gaps, so it takes the status the same way.
RANGES_MORE = 0x80
STATUS_FIXED = 12 + 2 + 32  # TT_FILE_STATUS's header, checksum and payload before its ranges (8 bytes a gap)


def ranges_per_status(mtu: int, signed: bool) -> int:
    """The gaps a TT_FILE_STATUS may list and still fit one packet of `mtu` bytes (at least 1, at most
    MAX_RANGES): a status over two packets is lost when either is, and the sender then hears nothing."""
    room = mtu - STATUS_FIXED - (SIGNATURE if signed else 0)
    return max(1, min(MAX_RANGES, room // 8))
REASON_BYTES = 80
MAP_FIXED = 12 + 33  # TT_FILE_MAP's header, checksum and payload before its map
MAP_MAX = 52  # its map field's bytes
MAP_MORE = 1  # its flags: more gaps follow past received_end (the bytes there are unknown, not missing)


def map_bytes(mtu: int, signed: bool) -> int:
    """The map bytes of a TT_FILE_MAP that fits one packet of `mtu` bytes (0: none fits)."""
    return max(0, min(MAP_MAX, mtu - MAP_FIXED - (SIGNATURE if signed else 0)))

__all__ = [
    "DTT",
    "FIT_MAX",
    "FIT_OVERHEAD",
    "MAP_MORE",
    "MAX_NAME_BYTES",
    "MAX_RANGES",
    "META_PART",
    "NARROW",
    "NARROW_FRAME",
    "RANGES_MORE",
    "REASON_BYTES",
    "REQUEST_PART",
    "SHA_LEN",
    "SIGNATURE",
    "STATUS_FIXED",
    "WIDE",
    "WIDE_FRAME",
    "Geometry",
    "TransferConfig",
    "TransferResult",
    "TransferStats",
    "frame_survival_wide",
    "map_bytes",
    "meta_check",
    "packet_loss_from_wide",
    "quiet_after",
    "ranges_per_status",
    "reason_fit",
    "reason_text",
    "result_name",
    "wilson_upper",
]

Key = tuple[int, int, int]  # (sender sysid, sender compid, transfer id)


@dataclass
class TransferConfig:
    offer_interval: float = 0.5  # first retry of an unanswered offer; grows 1.5x
    first_offer_copies: int = 2  # the first offer goes out this often (each copy is answered)
    offer_interval_max: float = 8.0
    give_up_after: float = 60.0  # sender: no progress for this long: fail (what arrived is kept for resume)
    status_interval: float = 1.0  # receiver: regular status period while data flows
    status_min_interval: float = 0.2  # receiver: earliest repeat of an event-driven status
    status_tail_interval: float = 0.1  # receiver: earliest repeat once the end of the file was seen
    status_batches: int = 3  # receiver: statuses per report when there are more gaps than one holds
    early_status_frames: int = 12  # receiver: report after this many data frames (a first loss figure)
    idle_timeout: float = 120.0  # receiver: forget a silent transfer (its partial file stays)
    live_window: float = 15.0  # receiver: a transfer heard from within this is running (counts as busy)
    frame_mode: str = "auto"  # auto | narrow | wide
    probe_frames: int = 24  # narrow frames sent before the first choice of frame size
    checksum_restarts: int = 2  # sender: start again from scratch after a SHA-256 mismatch, this often
    reason_wait: float = 1.0  # sender: wait this long for the words of a refusal before giving the code's


def quiet_after(cfg: TransferConfig, rtt: float, grant: float = 0.0, packet: int = 0) -> float:
    """How long a running transfer may go without word from the far end before this end asks it
    where it is, since it may have restarted: three status intervals, an RTT more, and under a
    rate grant three packets' time at it more (the far end reports on, or sends, frames at that
    pace). A sender then offers again (the restarted receiver resumes from its partial file); a
    fetch asks again (the restarted server offers the file anew, and this end resumes)."""
    wait = max(3 * cfg.status_interval, 2 * rtt + cfg.status_interval)
    return wait + (3 * packet / grant if grant else 0.0)


@dataclass
class TransferStats:
    bytes_sent: int = 0  # file bytes put in data frames, repeats included
    bytes_retransmitted: int = 0
    frames_sent: int = 0
    narrow_frames: int = 0
    wide_frames: int = 0
    offers_sent: int = 0
    statuses: int = 0
    started: float = 0.0
    data_started: float | None = None
    finished: float | None = None
    resumed_bytes: int = 0  # the receiver already had these when we started
    restarts: int = 0  # starts from scratch after a SHA-256 mismatch
    min_grant: int | None = None  # the lowest rate grant the receiver gave (B/s): it shared the link


@dataclass
class TransferResult:
    ok: bool
    code: str  # COMPLETE or a TT_FILE_RESULT name / LOCAL reason
    message: str
    name: str
    size: int
    seconds: float
    stats: TransferStats = field(default_factory=TransferStats)
    nothing_sent: bool = False  # the receiver had every byte already (an identical file, or a whole partial)
    deflated: int | None = None  # the zlib stream's size, when the file went deflated
    fallback: str | None = None  # why a deflated offer went back to the file as it is


def result_name(value: int) -> str:
    try:
        return R(value).name.removeprefix("TT_FILE_RESULT_")
    except ValueError:
        return f"RESULT_{value}"


def meta_check(meta: bytes) -> int:
    """TT_FILE_STATUS.meta_check for an offer's metadata blob (the file's SHA-256 then its
    name): the first 4 bytes of its SHA-256, little-endian. Never 0 (0 means 'not known')."""
    return int.from_bytes(hashlib.sha256(meta).digest()[:4], "little") or 1


def reason_fit(text: str) -> str:
    """A reason cut (at a character boundary) to what TT_FILE_REASON.text holds."""
    raw = text.encode("utf-8", "replace")
    if len(raw) <= REASON_BYTES:
        return text
    return raw[:REASON_BYTES - 3].decode("utf-8", "ignore") + "..."


def reason_text(text: str) -> str:
    """A received TT_FILE_REASON.text for printing (undecodable bytes shown as U+FFFD)."""
    return text.encode("utf-8", "surrogateescape").decode("utf-8", "replace")


@dataclass(frozen=True)
class Geometry:
    """The data frames a link's packet size and signing call for (the same rule in the C++ and
    Java runtimes, decision for decision).

    narrow (one frame per packet): TT_FILE_DATA (80 file bytes, a 100-byte frame, 113 signed)
    when it fits the packet and carries at least what a TT_FILE_DATA_FIT sized to the packet
    would; else TT_FILE_DATA_FIT with count = min(246, mtu - 21 - signature): exactly one packet.
    wide: TT_FILE_DATA_WIDE (247 file bytes in 267, 280 signed), spanning packets."""

    mtu: int = 100
    signed: bool = False

    def __post_init__(self) -> None:
        if self.mtu < FIT_OVERHEAD + 1 + self.sig:
            raise ValueError(f"a {self.mtu}-byte packet cannot carry a file-data frame "
                             f"(at least {FIT_OVERHEAD + 1 + self.sig} bytes{' signed' if self.signed else ''})")

    @property
    def sig(self) -> int:
        return SIGNATURE if self.signed else 0

    @property
    def fit_cap(self) -> int:
        return min(FIT_MAX, self.mtu - FIT_OVERHEAD - self.sig)

    @property
    def narrow_fit(self) -> bool:
        """True: the narrow frame is a TT_FILE_DATA_FIT; False: a TT_FILE_DATA."""
        return not (NARROW_FRAME + self.sig <= self.mtu and self.fit_cap <= NARROW)

    @property
    def narrow_cap(self) -> int:
        return self.fit_cap if self.narrow_fit else NARROW

    @property
    def narrow_frame(self) -> int:
        return self.fit_cap + FIT_OVERHEAD + self.sig if self.narrow_fit else NARROW_FRAME + self.sig

    @property
    def wide_frame(self) -> int:
        return WIDE_FRAME + self.sig

    def survival_wide(self, p: float) -> float:
        """Probability that a wide frame, streamed back to back, survives packet loss p: with
        L its length and M the packet's, it overlaps c = ceil(L/M) packets with probability
        (c M - L + 1)/M and c + 1 otherwise (0.34 q^3 + 0.66 q^4 for 267 bytes in 100)."""
        q = 1.0 - p
        length, m = self.wide_frame, self.mtu
        c = -(-length // m)
        pc = min(1.0, (c * m - length + 1) / m)
        return pc * q**c + (1.0 - pc) * q ** (c + 1)

    def packet_loss_from_wide(self, frame_loss: float) -> float:
        lo, hi = 0.0, 1.0
        for _ in range(40):
            mid = (lo + hi) / 2
            if 1.0 - self.survival_wide(mid) < frame_loss:
                lo = mid
            else:
                hi = mid
        return lo


DTT = Geometry()


def frame_survival_wide(p: float) -> float:
    """Probability that a 267-byte frame, streamed back to back in 100-byte packets, survives
    packet loss p: it overlaps 3 packets a third of the time and 4 otherwise."""
    return DTT.survival_wide(p)


def wilson_upper(lost: int, n: int, z: float = 1.0) -> float:
    """Upper end of the Wilson interval (about 84% one-sided) for a loss rate from n trials."""
    if n == 0:
        return 1.0
    p = lost / n
    denom = 1 + z * z / n
    centre = p + z * z / (2 * n)
    spread = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n))
    return min(1.0, (centre + spread) / denom)


def packet_loss_from_wide(frame_loss: float) -> float:
    return DTT.packet_loss_from_wide(frame_loss)


RESULT_TEXT = {
    "REFUSED_NAME": "the receiver refused the name",
    "REFUSED_EXISTS": "a file of that name exists there",
    "REFUSED_QUOTA": "the file exceeds the receiver's quota",
    "REFUSED_BUSY": "the receiver is busy; try again later",
    "FAILED_CHECKSUM": "the received bytes did not match the SHA-256",
    "FAILED_DISK_FULL": "the receiver's disk is full (what arrived is kept: send again to resume)",
    "FAILED_IO": "the receiver could not store the file",
    "NOT_FOUND": "no such file there",
    "REQUEST_REFUSED": "the peer does not serve that file",
    "CANCELLED": "cancelled",
    "REFUSED_UNSUPPORTED": "the receiver does not understand the offer's flags",
}

