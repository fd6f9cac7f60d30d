"""Reliable file transfer over the DTT link, sans-IO: messages and the time in, messages and
deadlines out. The same code runs under the virtual clock and under asyncio on UDP.

Protocol (messages of dialects/ttapi.xml):

1. The sender offers (TT_FILE_OFFER, repeated until answered): size, SHA-256 and name, the
   latter two in parts. The receiver answers TT_FILE_STATUS: refused with a reason, or
   IN_PROGRESS with what it already has (a resumed transfer sends only the rest).
2. Data flows paced to the link: TT_FILE_DATA (83 bytes, one frame per packet) while loss is
   high, TT_FILE_DATA_WIDE (250 bytes, frames spanning packets) while the transfer observes
   little loss; the choice follows the loss the sender measures from the receiver's counts.
3. The receiver reports, every second and sooner when it sees new gaps or the end of the file,
   what it has: everything below an offset, and up to 8 missing ranges above it. The sender
   repeats confirmed-missing ranges before new data; a retransmission is never repeated within
   an RTT.
4. When every byte is there the receiver checks the SHA-256 and renames the file into place,
   then reports COMPLETE (and repeats that to any late offer or data).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import ttapi
from ttapi import TtFileResult as R

from .ranges import RangeSet
from .storage import DiskFull, Partial, ReceiveDir, Refused, StorageError

NARROW = 83  # file bytes in a TT_FILE_DATA frame (100 bytes: one packet)
WIDE = 250  # file bytes in a TT_FILE_DATA_WIDE frame (267 bytes)
NARROW_FRAME = 100
WIDE_FRAME = 267
META_PART = 77
MAX_RANGES = 8
SHA_LEN = 32
MAX_NAME_BYTES = 255 - SHA_LEN

Key = tuple[int, int, int]  # (sender sysid, sender compid, transfer id)


@dataclass
class TransferConfig:
    offer_interval: float = 1.0  # first retry of an unanswered offer; grows 1.5x
    offer_interval_max: float = 8.0
    give_up_after: float = 60.0  # no word from the receiver for this long: fail (state kept for resume)
    status_interval: float = 1.0  # receiver: regular status period while data flows
    status_min_interval: float = 0.2  # receiver: earliest repeat of an event-driven status
    status_tail_interval: float = 0.1  # receiver: earliest repeat once the end of the file was seen
    status_batches: int = 3  # receiver: statuses per report when there are more gaps than one holds
    early_status_frames: int = 12  # receiver: report after this many data frames (a first loss figure)
    idle_timeout: float = 120.0  # receiver: forget a silent transfer (its partial file stays)
    frame_mode: str = "auto"  # auto | narrow | wide
    probe_frames: int = 24  # narrow frames sent before the first choice of frame size
    zero_rtt: bool = True  # stream data right behind the first offer instead of waiting an RTT
    early_limit: int = 256 * 1024  # receiver: data buffered for a transfer whose offer is not admitted yet
    unknown_after: float = 3.0  # receiver: data without an offer this long: tell the sender


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


@dataclass
class TransferResult:
    ok: bool
    code: str  # COMPLETE or a TT_FILE_RESULT name / LOCAL reason
    message: str
    name: str
    size: int
    seconds: float
    stats: TransferStats = field(default_factory=TransferStats)


def result_name(value: int) -> str:
    try:
        return R(value).name.removeprefix("TT_FILE_RESULT_")
    except ValueError:
        return f"RESULT_{value}"


def frame_survival_wide(p: float) -> float:
    """Probability that a 267-byte frame, streamed back to back, survives packet loss p: it
    overlaps 3 packets a third of the time and 4 otherwise."""
    q = 1.0 - p
    return 0.34 * q**3 + 0.66 * q**4


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
    lo, hi = 0.0, 1.0
    for _ in range(40):
        mid = (lo + hi) / 2
        if 1.0 - frame_survival_wide(mid) < frame_loss:
            lo = mid
        else:
            hi = mid
    return lo


class FileSender:
    """One outgoing transfer. The endpoint calls `control(now)` for offers, `next_data(now,
    space)` when the scheduler has room, `on_status(now, msg)` on answers."""

    def __init__(self, transfer_id: int, source: Any, name: str, target: tuple[int, int],
                 config: TransferConfig | None = None, request_id: int = 0, overwrite: bool = False,
                 now: float = 0.0, on_progress: Callable[[FileSender], None] | None = None) -> None:
        raw = name.encode("utf-8", "surrogateescape")
        if not raw or len(raw) > MAX_NAME_BYTES:
            raise ValueError(f"file names must be 1..{MAX_NAME_BYTES} bytes of UTF-8, not {len(raw)}")
        self.id = transfer_id
        self.source = source
        self.name = name
        self.size = source.size
        self.target = target
        self.cfg = config or TransferConfig()
        self.request_id = request_id
        self.flags = int(ttapi.TtFileFlags.TT_FILE_FLAGS_OVERWRITE) if overwrite else 0
        self.meta = source.sha256 + raw
        self.state = "offering"
        self.result: TransferResult | None = None
        self.stats = TransferStats(started=now)
        self.on_progress = on_progress
        self.acked = RangeSet()
        self.retx = RangeSet()
        self.next_new = 0
        self._sent: list[tuple[int, int, float]] = []  # (offset, end, last send time), by offset
        self._offer_due = now
        self._offer_interval = self.cfg.offer_interval
        self._last_offer: float | None = None
        self._offers_since_answer = 0
        self.last_heard = now
        self.rtt = 0.5
        self._rtt_sampled = False
        self.mode = "narrow" if self.cfg.frame_mode in ("auto", "narrow") else "wide"
        self.loss: dict[str, float | None] = {"narrow": None, "wide": None}  # per-packet loss estimates
        self._unclassified: list[tuple[int, int, float, str]] = []  # first sends not yet known lost or not
        self._outcomes: dict[str, list[bool]] = {"narrow": [], "wide": []}  # recent first sends: lost?
        self._probe_due: float | None = None
        self.byte_time = 0.0  # seconds per byte on the link, if known (set by the endpoint)
        self._sends: dict[int, tuple[float, int]] = {}  # offset -> (last send time, sends)
        self._since: dict[int, int] = {}  # offset -> sends since it was last known to be missing

    # -- progress -----------------------------------------------------------------------------
    @property
    def done(self) -> bool:
        return self.state in ("complete", "failed")

    @property
    def acked_bytes(self) -> int:
        return self.acked.total()

    def _finish(self, now: float, ok: bool, code: str, message: str) -> None:
        if self.done:
            return
        self.state = "complete" if ok else "failed"
        self.stats.finished = now
        self.result = TransferResult(ok, code, message, self.name, self.size, now - self.stats.started, self.stats)
        if self.on_progress:
            self.on_progress(self)

    def cancel(self, now: float) -> None:
        self._finish(now, False, "CANCELLED", "cancelled")

    # -- offers -------------------------------------------------------------------------------
    def offer_messages(self) -> list[ttapi.Message]:
        parts: list[ttapi.Message] = []
        for off in range(0, len(self.meta), META_PART):
            parts.append(ttapi.TtFileOffer(
                target_system=self.target[0], target_component=self.target[1], transfer_id=self.id,
                request_id=self.request_id, size=self.size, flags=self.flags, meta_length=len(self.meta),
                meta_offset=off, meta=self.meta[off:off + META_PART]))
        return parts

    def control(self, now: float) -> list[ttapi.Message]:
        """Offers due now (the first, retries, or a poll when the receiver has gone quiet)."""
        if self.done:
            return []
        if now - self.last_heard >= self.cfg.give_up_after:
            self._finish(now, False, "TIMEOUT",
                         f"no answer from {self.target[0]}/{self.target[1]} for {self.cfg.give_up_after:.0f} s "
                         "(what arrived is kept there: send again to resume)")
            return []
        due = self._offer_due if self.state == "offering" else self._probe_due
        if due is None or now < due:
            return []
        self.stats.offers_sent += 1
        self._offers_since_answer += 1
        self._last_offer = now
        if self.state == "offering":
            self._offer_due = now + self._offer_interval
            self._offer_interval = min(self._offer_interval * 1.5, self.cfg.offer_interval_max)
        else:
            self._probe_due = now + max(2 * self.rtt, self.cfg.offer_interval)
        return self.offer_messages()

    # -- data ---------------------------------------------------------------------------------
    def _streaming(self) -> bool:
        if self.state == "sending":
            return True
        return self.state == "offering" and self.cfg.zero_rtt and self.stats.offers_sent > 0

    def has_data(self, now: float) -> bool:
        if not self._streaming():
            return False
        if self.retx or self.next_new < self.size:
            return True
        due = self._tail_due()
        return due is not None and now >= due

    def _tail_wait(self) -> float:
        return 0.0

    def _tail_due(self) -> float | None:
        """When the oldest unacknowledged bytes become worth sending again on an otherwise idle
        link (a tail-loss probe: the link would idle until the next status anyway)."""
        oldest = min((ts for s, e, ts in self._sent if not self.acked.covers(s, e)), default=None)
        return None if oldest is None else oldest + self._tail_wait()

    def _choose_mode(self) -> str:
        if self.cfg.frame_mode != "auto":
            return self.cfg.frame_mode
        n, w = self.loss["narrow"], self.loss["wide"]
        p = w if self.mode == "wide" and w is not None else (n if n is not None else w)
        if p is None:
            return "narrow"
        eff_narrow = NARROW / NARROW_FRAME * (1 - p)
        eff_wide = WIDE / WIDE_FRAME * frame_survival_wide(p)
        better = "wide" if eff_wide > eff_narrow else "narrow"
        if better != self.mode and abs(eff_wide - eff_narrow) < 0.02:
            return self.mode  # hysteresis
        return better

    def next_data(self, now: float, space: int) -> ttapi.Message | None:
        if not self._streaming():
            return None
        mode = self.mode
        frame_len = WIDE_FRAME if mode == "wide" else NARROW_FRAME
        if mode == "narrow" and space < frame_len:
            return None  # a narrow frame takes a packet of its own: wait for the next one
        cap = WIDE if mode == "wide" else NARROW
        retx = self.retx.first()
        if retx is not None:
            # a data frame always carries min(cap, size - offset) bytes (the receiver counts on
            # it), so a short gap is resent with the bytes after it
            offset = retx[0]
            length = min(cap, self.size - offset)
            self.retx.remove(offset, offset + length)
            self.stats.bytes_retransmitted += length
        elif self.next_new < self.size:
            offset = self.next_new
            length = min(cap, self.size - offset)
            self.next_new += length
        else:
            tail = self._tail_candidate(now)
            if tail is None:
                return None
            offset = tail
            length = min(cap, self.size - offset)
            self.stats.bytes_retransmitted += length
        data = self.source.read(offset, length)
        self._sends[offset] = (now, self._sends.get(offset, (0.0, 0))[1] + 1)
        self._since[offset] = self._since.get(offset, 0) + 1
        # when its last byte can have left: frames longer than a packet take several packets
        left = now + (frame_len + NARROW_FRAME) * self.byte_time
        self._record(left, offset, offset + length)
        if retx is None:
            self._unclassified.append((offset, offset + length, left, mode))
        self.stats.bytes_sent += length
        self.stats.frames_sent += 1
        if self.stats.data_started is None:
            self.stats.data_started = now
        if mode == "wide":
            self.stats.wide_frames += 1
            msg: ttapi.Message = ttapi.TtFileDataWide(transfer_id=self.id, offset=offset, data=data)
        else:
            self.stats.narrow_frames += 1
            msg = ttapi.TtFileData(transfer_id=self.id, offset=offset, data=data)
        if self.cfg.frame_mode == "auto" and self.stats.narrow_frames >= self.cfg.probe_frames:
            self.mode = self._choose_mode()
        if not self.has_data(now) and self._probe_due is None:
            self._probe_due = now + max(2 * self.rtt, 0.5)
        return msg

    def _tail_candidate(self, now: float) -> int | None:
        """The unacknowledged chunk most likely still missing: the fewest sends since it was
        last known to be missing (each send leaves it missing with probability p), the one
        sent longest ago among those. No part of the tail starves when statuses are lost."""
        wait = self._tail_wait()
        best: tuple[int, float, int] | None = None
        for s, e, ts in self._sent:
            if ts + wait > now:
                continue
            gaps = self.acked.gaps(s, e)
            if not gaps:
                continue
            key = (self._since.get(s, 1), ts, gaps[0][0])
            if best is None or key < best:
                best = key
        return None if best is None else best[2]

    def _record(self, when: float, start: int, end: int) -> None:
        """Remember when bytes [start, end) last left; a resend supersedes older records, so a
        status written before the resend arrived does not trigger another one."""
        sent = [(s, e, t) for s, e, t in self._sent if e <= start or s >= end]
        for s, e, t in self._sent:
            if s < start < e:
                sent.append((s, start, t))
            if s < end < e:
                sent.append((end, e, t))
        sent.append((start, end, when))
        sent.sort()
        self._sent = sent

    # -- answers ------------------------------------------------------------------------------
    def on_status(self, now: float, msg: ttapi.TtFileStatus) -> None:
        if self.done:
            return
        self.last_heard = now
        self.stats.statuses += 1
        if (self.state == "offering" and self._offers_since_answer == 1 and self._last_offer is not None
                and not self._rtt_sampled):
            # Karn: only an offer answered without a repeat gives a clean sample
            self.rtt = min(5.0, max(0.02, now - self._last_offer))
            self._rtt_sampled = True
        elif self.state == "offering" and self._last_offer is not None and not self._rtt_sampled:
            # answered after repeats: since the last offer is a lower bound; better than a guess
            self.rtt = min(5.0, max(0.05, now - self._last_offer))
        self._offers_since_answer = 0
        code = msg.result
        if code == R.TT_FILE_RESULT_COMPLETE:
            self.acked.add(0, self.size)
            self._finish(now, True, "COMPLETE", f"{self.name}: {self.size} bytes delivered and verified")
            return
        if code == R.TT_FILE_RESULT_UNKNOWN_TRANSFER:
            self.state = "offering"  # the receiver restarted: offer again, it resumes from disk
            self._offer_due = now
            return
        if code != R.TT_FILE_RESULT_IN_PROGRESS:
            self._finish(now, False, result_name(code), _RESULT_TEXT.get(result_name(code), "refused"))
            return
        if self.state == "offering":
            self.state = "sending"
            self._probe_due = None
        self._rtt_from_echo(now, msg)
        self._apply_status(now, msg)
        if self.on_progress:
            self.on_progress(self)

    def _rtt_from_echo(self, now: float, msg: ttapi.TtFileStatus) -> None:
        """A round-trip sample from the status's echo of the latest frame it saw (Karn: only
        frames sent once)."""
        sent = self._sends.get(msg.last_offset)
        if sent is None or sent[1] != 1 or msg.hold_ms == 65535:
            return
        sample = now - msg.hold_ms / 1000.0 - sent[0]
        if not 0.0 < sample < 10.0:
            return
        if not self._rtt_sampled:
            self.rtt, self._rtt_sampled = sample, True
        else:
            self.rtt = 0.8 * self.rtt + 0.2 * sample

    def _apply_status(self, now: float, msg: ttapi.TtFileStatus) -> None:
        rc = min(msg.received_contiguous, self.size)
        region = max(rc, min(msg.region_start, self.size))
        re = max(region, min(msg.received_end, self.size))
        n = min(msg.range_count, MAX_RANGES)
        pairs = list(msg.ranges)
        missing = [(max(pairs[2 * i], region), min(pairs[2 * i + 1], re)) for i in range(n)]
        missing = [(a, b) for a, b in missing if a < b]
        before = self.acked.total()
        self.acked.add(0, rc)
        pos = region
        for a, b in missing:
            if a > pos:
                self.acked.add(pos, a)
            pos = max(pos, b)
        if re > pos:
            self.acked.add(pos, re)
        if self.stats.statuses == 1 and before == 0:
            # what the receiver had before we started: its first answer, less what we had sent
            # by then (0-RTT data may already be in it)
            self.stats.resumed_bytes = max(0, self.acked.total() - self.next_new)
        # a resumed transfer: skip what the receiver already has
        while self.next_new < self.size and self.acked.covers(self.next_new, min(self.size, self.next_new + 1)):
            end = next((b for a, b in self.acked if a <= self.next_new < b), self.next_new + 1)
            self.next_new = min(end, self.size)
        # confirmed losses: bytes reported missing, or beyond everything the receiver has seen,
        # whose last send is older than what this status can tell about: the frame it echoes
        # left at `echo`; anything sent before it arrived before it or was lost (a few packet
        # times of slack for reordering). Without an echo, an RTT before now.
        horizon = now - self.rtt - 0.05
        echo = self._sends.get(msg.last_offset)
        if echo is not None and msg.hold_ms != 65535:
            horizon = min(horizon, echo[0] - 2 * NARROW_FRAME * self.byte_time)
        truncated = n >= MAX_RANGES  # bytes past received_end are unknown, not missing
        if re < self.next_new and not truncated:
            missing = [*missing, (re, self.next_new)]
        for a, b in missing:
            for s, e, ts in self._sent:
                if e <= a or s >= b or ts > horizon:
                    continue
                self.retx.add(max(a, s), min(b, e))
                self._since[s] = 0
        for a, b in self.acked:
            self.retx.remove(a, b)
        self._sent = [(s, e, ts) for s, e, ts in self._sent if not self.acked.covers(s, e)]
        self._classify(horizon, re, truncated, missing)
        self._probe_due = None if self.has_data(now) else now + max(2 * self.rtt, 0.5)

    def _classify(self, horizon: float, re: int, truncated: bool, missing: list[tuple[int, int]]) -> None:
        """Loss, measured exactly: each first transmission, once a status covers its bytes, was
        lost if any of them is reported missing. Estimates come from the last 64 per frame size."""
        keep: list[tuple[int, int, float, str]] = []
        for rec in self._unclassified:
            start, end, when, mode = rec
            known = when <= horizon and (end <= re or not truncated)
            if not known:
                keep.append(rec)
                continue
            lost = any(a < end and start < b for a, b in missing)
            window = self._outcomes[mode]
            window.append(lost)
            if len(window) > 64:
                window.pop(0)
        self._unclassified = keep
        for mode in ("narrow", "wide"):
            window = self._outcomes[mode]
            if len(window) >= 8:
                frame_loss = wilson_upper(sum(window), len(window))  # pessimistic: wide frames are costly
                self.loss[mode] = frame_loss if mode == "narrow" else packet_loss_from_wide(frame_loss)
        if self.cfg.frame_mode == "auto" and self.stats.narrow_frames >= self.cfg.probe_frames:
            self.mode = self._choose_mode()

    def deadline(self, now: float) -> float | None:
        """The next time this transfer needs attention (data waiting for the pacer is the
        scheduler's business, not a deadline)."""
        if self.done:
            return None
        times = [self.last_heard + self.cfg.give_up_after]
        if self._streaming() and not self.retx and self.next_new >= self.size:
            due = self._tail_due()
            if due is not None and due > now:
                times.append(due)
        if self.state == "offering":
            times.append(self._offer_due)
        elif self._probe_due is not None:
            times.append(self._probe_due)
        return min(times)


_RESULT_TEXT = {
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
}


class _Incoming:
    """The receiving side of one transfer."""

    def __init__(self, key: Key, now: float) -> None:
        self.key = key
        self.meta = bytearray()
        self.meta_have = RangeSet()
        self.meta_length = 0
        self.size = 0
        self.flags = 0
        self.request_id = 0
        self.name = ""
        self.sha256 = b""
        self.partial: Partial | None = None
        self.result = R.TT_FILE_RESULT_IN_PROGRESS
        self.reason = ""
        self.frames = 0
        self.last_activity = now
        self.status_due: float | None = now
        self.last_status = -1e9
        self.gaps_seen = 0
        self.final_path: str | None = None
        self.finished_at: float | None = None
        self.started = now
        self.last_data: float | None = None
        self.last_offset = 0
        self.early: list[tuple[int, int, bytes]] = []  # (offset, cap, data) before the offer is admitted
        self.early_bytes = 0
        self.first_early: float | None = None
        self.seen_end = False  # the last chunk has arrived once: the tail, where every round trip counts
        self.gap_dt = 0.05  # EWMA of the time between data frames
        self.quiet_due: float | None = None  # report when data stops coming

    @property
    def offered(self) -> bool:
        """An offer (at least its first part) has arrived."""
        return self.meta_length > 0

    @property
    def accepted(self) -> bool:
        """The offer was decided: accepted (receiving), refused, finished or failed. A transfer
        that so far only has data (its offer lost or late) is not."""
        return self.partial is not None or self.result not in (R.TT_FILE_RESULT_IN_PROGRESS,
                                                               R.TT_FILE_RESULT_UNKNOWN_TRANSFER)


class FileReceiver:
    """Every incoming transfer of an endpoint; files land in `store`."""

    def __init__(self, store: ReceiveDir, sysid: int, compid: int, config: TransferConfig | None = None,
                 max_transfers: int = 8, on_event: Callable[[str, _Incoming], None] | None = None) -> None:
        self.store = store
        self.sysid = sysid
        self.compid = compid
        self.cfg = config or TransferConfig()
        self.max_transfers = max_transfers
        self.transfers: dict[Key, _Incoming] = {}
        self.on_event = on_event
        self.now = 0.0
        self.expected_requests: dict[tuple[int, int, int], str] = {}  # (peer sys, comp, request id) -> name

    def active(self) -> list[_Incoming]:
        return [t for t in self.transfers.values() if t.result == R.TT_FILE_RESULT_IN_PROGRESS]

    def on_offer(self, now: float, msg: ttapi.TtFileOffer) -> None:
        key = (msg.get_srcSystem(), msg.get_srcComponent(), msg.transfer_id)
        t = self.transfers.get(key)
        if t is not None and t.accepted and (t.size != msg.size or t.meta_length != msg.meta_length):
            self._close(t)  # the sender reused the id for another file
            t = None
        if t is None or not t.offered:
            if t is None and len(self.active()) >= self.max_transfers:
                t = _Incoming(key, now)
                t.result, t.reason = R.TT_FILE_RESULT_REFUSED_BUSY, "too many transfers"
                self._send_status_now(t, now)
                self.transfers[key] = t
                return
            if t is None:
                t = self.transfers[key] = _Incoming(key, now)
            t.result = R.TT_FILE_RESULT_IN_PROGRESS  # it may have been UNKNOWN while only data came
            t.size, t.meta_length, t.flags, t.request_id = msg.size, msg.meta_length, msg.flags, msg.request_id
            t.meta = bytearray(msg.meta_length)
        t.last_activity = now
        if t.accepted:
            self._send_status_now(t, now)  # a repeated offer, or a poll: answer with where we are
            return
        off = msg.meta_offset
        part = bytes(msg.meta[: max(0, min(len(msg.meta), t.meta_length - off))])
        if off < t.meta_length and part:
            t.meta[off:off + len(part)] = part
            t.meta_have.add(off, off + len(part))
        if not t.meta_have.covers(0, t.meta_length):
            return
        self._admit(t, now)

    def _admit(self, t: _Incoming, now: float) -> None:
        if t.meta_length < SHA_LEN + 1:
            t.result, t.reason = R.TT_FILE_RESULT_REFUSED_NAME, "no name"
            self._send_status_now(t, now)
            return
        t.sha256 = bytes(t.meta[:SHA_LEN])
        try:
            name = bytes(t.meta[SHA_LEN:]).decode("utf-8")
        except UnicodeDecodeError:
            t.result, t.reason = R.TT_FILE_RESULT_REFUSED_NAME, "name is not UTF-8"
            self._send_status_now(t, now)
            return
        t.name = name
        wants_overwrite = bool(t.flags & ttapi.TtFileFlags.TT_FILE_FLAGS_OVERWRITE)
        try:
            self.store.admit(name, t.size, wants_overwrite)
            t.partial = self.store.partial(name, t.size, t.sha256)
        except Refused as e:
            t.result, t.reason = _REFUSAL[e.code], e.reason
        except StorageError as e:
            t.result, t.reason = R.TT_FILE_RESULT_FAILED_IO, str(e)
        self._event("accepted" if t.partial is not None else "refused", t)
        early, t.early, t.early_bytes = t.early, [], 0
        if t.partial is not None:
            for offset, cap, data in early:
                length = min(cap, t.size - offset)
                if length > 0 and not self._write(t, now, offset, data[:length]):
                    return
        if t.partial is not None and t.partial.complete:
            self._complete(t, now)
        self._send_status_now(t, now)

    def on_data(self, now: float, msg: ttapi.TtFileData | ttapi.TtFileDataWide, cap: int) -> None:
        key = (msg.get_srcSystem(), msg.get_srcComponent(), msg.transfer_id)
        t = self.transfers.get(key)
        if t is None or not t.accepted:
            # data ahead of (or without) its offer: keep it, within bounds, until the offer is in
            if t is None:
                if len(self.active()) >= self.max_transfers:
                    return
                t = self.transfers[key] = _Incoming(key, now)
            t.last_activity = now
            t.frames += 1
            if t.first_early is None:
                t.first_early = now
            if t.early_bytes + cap <= self.cfg.early_limit:
                t.early.append((msg.offset, cap, bytes(msg.data)))
                t.early_bytes += cap
            if t.meta_length == 0 and now - t.first_early >= self.cfg.unknown_after:
                t.result = R.TT_FILE_RESULT_UNKNOWN_TRANSFER  # no offer came: the sender must offer again
                if now - t.last_status >= self.cfg.status_min_interval:
                    self._send_status_now(t, now)
            return
        t.last_activity = now
        t.frames += 1
        if t.partial is None:  # finished or refused: remind the sender
            if now - t.last_status >= self.cfg.status_min_interval:
                self._send_status_now(t, now)
            return
        offset = msg.offset
        length = min(cap, t.size - offset) if offset < t.size else 0
        if length <= 0:
            return
        gaps_before = len(t.partial.ranges)
        if not self._write(t, now, offset, bytes(msg.data[:length])):
            return
        if t.partial.complete:
            self._complete(t, now)
            self._send_status_now(t, now)
            return
        if t.last_data is not None:
            t.gap_dt = 0.8 * t.gap_dt + 0.2 * min(1.0, now - t.last_data)
        t.last_data = now
        t.last_offset = offset
        ranges = t.partial.ranges
        new_gap = len(ranges) > gaps_before
        at_end = offset + length >= t.size
        # the last second of data (at the rate it is coming): report at tail frequency already,
        # so that little is in doubt when the sender runs out of new data
        rate = cap / max(t.gap_dt, 1e-3)
        t.seen_end = t.seen_end or at_end or t.size - (offset + length) < rate * 1.0
        repaired = len(ranges) < gaps_before
        early = t.frames == self.cfg.early_status_frames
        if early or new_gap or at_end or repaired:
            soon = max(now, t.last_status + self._min_interval(t))
            t.status_due = soon if t.status_due is None else min(t.status_due, soon)
        elif t.status_due is None:
            t.status_due = now + self.cfg.status_interval
        if len(ranges) > 1 or at_end or repaired:
            t.quiet_due = now + max(3 * t.gap_dt, 0.03)  # if data stops with gaps left, report then

    def _min_interval(self, t: _Incoming) -> float:
        return self.cfg.status_tail_interval if t.seen_end else self.cfg.status_min_interval

    def _write(self, t: _Incoming, now: float, offset: int, data: bytes) -> bool:
        """Store a chunk; on a full disk or a storage error end the transfer (what was written
        stays, for a resume) and return False."""
        assert t.partial is not None
        try:
            t.partial.write(offset, data)
            return True
        except DiskFull:
            t.result, t.reason = R.TT_FILE_RESULT_FAILED_DISK_FULL, "disk full"
        except StorageError as e:
            t.result, t.reason = R.TT_FILE_RESULT_FAILED_IO, str(e)
        t.partial.close()
        t.partial = None
        self._event("failed", t)
        self._send_status_now(t, now)
        return False

    def _complete(self, t: _Incoming, now: float) -> None:
        assert t.partial is not None
        p = t.partial
        t.partial = None
        if not p.verify():
            p.discard()
            t.result, t.reason = R.TT_FILE_RESULT_FAILED_CHECKSUM, "SHA-256 mismatch"
            self._event("failed", t)
            return
        try:
            wants_overwrite = bool(t.flags & ttapi.TtFileFlags.TT_FILE_FLAGS_OVERWRITE)
            t.final_path = str(p.finish(self.store.quota.overwrite and wants_overwrite))
            t.result = R.TT_FILE_RESULT_COMPLETE
            t.finished_at = now
            self._event("complete", t)
        except Refused as e:
            t.result, t.reason = _REFUSAL[e.code], e.reason
            self._event("failed", t)
        except OSError as e:
            t.result, t.reason = R.TT_FILE_RESULT_FAILED_IO, str(e)
            self._event("failed", t)

    def _close(self, t: _Incoming) -> None:
        if t.partial is not None:
            t.partial.save()
            t.partial.close()
            t.partial = None
        self.transfers.pop(t.key, None)

    def _event(self, what: str, t: _Incoming) -> None:
        if self.on_event:
            self.on_event(what, t)

    def _send_status_now(self, t: _Incoming, now: float) -> None:
        t.status_due = now

    def statuses(self, t: _Incoming) -> list[ttapi.TtFileStatus]:
        """One status, or a burst describing successive regions when there are more gaps than
        one status holds."""
        if t.partial is None:
            done = t.size if t.result == R.TT_FILE_RESULT_COMPLETE else 0
            return [self._status(t, done, done, done, [])]
        ranges = t.partial.ranges
        rc = ranges.prefix()
        last = max((b for _, b in ranges), default=0)
        gaps = ranges.gaps(rc, last)
        out = []
        start = rc
        for k in range(max(1, self.cfg.status_batches)):
            batch = gaps[k * MAX_RANGES:(k + 1) * MAX_RANGES]
            more = len(gaps) > (k + 1) * MAX_RANGES
            end = batch[-1][1] if more else last
            out.append(self._status(t, rc, start, end, batch))
            start = end
            if not more:
                break
        return out

    def _status(self, t: _Incoming, rc: int, region: int, re: int,
                gaps: list[tuple[int, int]]) -> ttapi.TtFileStatus:
        flat = [x for gap in gaps for x in gap]
        return ttapi.TtFileStatus(
            target_system=t.key[0], target_component=t.key[1], transfer_id=t.key[2], result=int(t.result),
            received_contiguous=rc, region_start=region, received_end=re, last_offset=t.last_offset,
            hold_ms=min(65535, int(1000 * (self.now - t.last_data))) if t.last_data is not None else 65535,
            range_count=len(gaps), ranges=flat + [0] * (2 * MAX_RANGES - len(flat)))

    def status(self, t: _Incoming) -> ttapi.TtFileStatus:
        return self.statuses(t)[0]

    def control(self, now: float) -> list[tuple[ttapi.Message, object]]:
        """Statuses due now, each with a key under which a newer one replaces it while it
        waits to be sent; forget silent transfers."""
        self.now = now
        out: list[tuple[ttapi.Message, object]] = []
        for t in list(self.transfers.values()):
            if now - t.last_activity >= self.cfg.idle_timeout:
                self._close(t)
                continue
            quiet = t.quiet_due is not None and now >= max(t.quiet_due, t.last_status + self._min_interval(t))
            if quiet or (t.status_due is not None and now >= t.status_due):
                out.extend((m, ("status", t.key, i)) for i, m in enumerate(self.statuses(t)))
                t.last_status = now
                t.quiet_due = None
                flowing = (t.result == R.TT_FILE_RESULT_IN_PROGRESS and t.partial is not None
                           and t.last_data is not None and now - t.last_data < self.cfg.status_interval)
                t.status_due = now + self.cfg.status_interval if flowing else None
                if t.partial is not None:
                    t.partial.save()
        return out

    def deadline(self) -> float | None:
        times = [t.status_due for t in self.transfers.values() if t.status_due is not None]
        times += [max(t.quiet_due, t.last_status + self._min_interval(t))
                  for t in self.transfers.values() if t.quiet_due is not None]
        times += [t.last_activity + self.cfg.idle_timeout for t in self.transfers.values()]
        return min(times) if times else None

    def close(self) -> None:
        for t in list(self.transfers.values()):
            self._close(t)


_REFUSAL = {
    "NAME": R.TT_FILE_RESULT_REFUSED_NAME,
    "EXISTS": R.TT_FILE_RESULT_REFUSED_EXISTS,
    "QUOTA": R.TT_FILE_RESULT_REFUSED_QUOTA,
}


def ceil_div(a: int, b: int) -> int:
    return -(-a // b)


def ideal_seconds(size: int, capacity: float, loss: float, frame_efficiency: float) -> float:
    return size / (capacity * (1 - loss) * frame_efficiency) if capacity > 0 else math.inf
