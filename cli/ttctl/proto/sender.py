"""The sending side of one file transfer, sans-IO (see transfer.py for the protocol).

The endpoint calls `control(now)` for offers, `next_data(now, space)` when the scheduler has
room, `on_status(now, msg)` and `on_reason(now, msg)` on answers. A transfer ends exactly once:
COMPLETE only on a status that carries its own transfer id and metadata check, anything else
with a code and the receiver's reason when it gave one.

With `compress`, a file that deflates well is offered as its zlib stream (deflate.py); a
receiver that refuses that (REFUSED_UNSUPPORTED: it does not inflate; or, as receivers from
before deflate do, the name the longer metadata makes; or a stream it could not inflate to the
file) gets the file again, uncompressed, under a new transfer id: `fallback` says why.

Data frames leave no faster than the receiver's latest rate grant allows (sharing.py), when
it gives one.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from ..wire.bindings import Bindings
from ..wire.contract import TtFileFlags
from ..wire.contract import TtFileResult as R
from .deflate import DeflatedSource, deflate_meta, deflated
from .frame_loss import FrameLoss
from .names import Refused, check_name, encoded
from .ranges import RangeSet
from .reports import Report, read_map, read_status, refused_flags
from .sharing import GrantPacer
from .transfer import (
    DTT,
    META_PART,
    RESULT_TEXT,
    WIDE,
    TransferConfig,
    TransferResult,
    TransferStats,
    meta_check,
    quiet_after,
    reason_text,
    result_name,
)

MAP = int(TtFileFlags.TT_FILE_FLAGS_MAP)



class FileSender:
    """One outgoing transfer. `new_id()` draws a fresh transfer id (the endpoint's, so that it
    is unique among its transfers); the transfer takes a new one when it starts again."""

    def __init__(self, bindings: Bindings, new_id: Callable[[], int], source: Any, name: str, target: tuple[int, int],
                 config: TransferConfig | None = None, request_id: int = 0, overwrite: bool = False,
                 now: float = 0.0, on_progress: Callable[[FileSender], None] | None = None,
                 compress: bool | DeflatedSource = True) -> None:
        try:
            check_name(name)
        except Refused as e:
            raise ValueError(e.reason) from None
        self.b = bindings
        self.new_id = new_id
        self.id = new_id()
        self.raw_source = source  # the file
        self.owns_source = False  # the endpoint opened it, and closes it when the transfer is retired
        self.name = name
        self.file_size = source.size
        self.target = target
        self.cfg = config or TransferConfig()
        self.request_id = request_id
        # TT_FILE_FLAGS_MAP: this sender reads TT_FILE_MAP (a receiver that never sends one ignores it)
        self._flags = (int(TtFileFlags.TT_FILE_FLAGS_OVERWRITE) if overwrite else 0) | MAP
        self.fallback: str | None = None  # why a deflated offer went back to the file as it is
        # compress: True decides here; a DeflatedSource of this file was decided before (the
        # command line deflates before its link starts, so that a big file blocks nothing)
        self._use(compress if isinstance(compress, DeflatedSource)
                  else deflated(source, encoded(name)) if compress else None)
        self.result: TransferResult | None = None
        self.stats = TransferStats(started=now)
        self.on_progress = on_progress
        self.busy: str | None = None  # the receiver's words while it has no room for us
        self.last_heard = now
        self.last_progress = now
        self.heard_any = False
        self.rtt = 0.5
        self._rtt_sampled = False
        self.byte_time = 0.0  # seconds per byte on the link, if known (set by the endpoint)
        self.geometry = DTT  # the link's packet size and signing: the data frames' sizes (set by the endpoint)
        self.on_stream = False  # file data goes on a pipeline (a byte stream) now: see use_path
        self.pacer = GrantPacer()  # the receiver's rate grant for our data frames
        self._begin(now)

    def _begin(self, now: float) -> None:
        """The per-attempt state: a first offer due now, nothing known of the receiver."""
        self.state = "offering"
        self.reason: str | None = None  # the receiver's words for a refusal or failure
        self._refusal: tuple[str, float] | None = None  # (code, when) of a refusal awaiting its words
        self._unzip_refusal: tuple[int, float] | None = None  # (code, when): a deflated offer refused, words awaited
        self.acked = RangeSet()
        self.retx = RangeSet()
        self.next_new = 0
        self._sent: list[tuple[int, int, float]] = []  # (offset, end, last send time), by offset
        self._offer_due = now
        self._offer_interval = self.cfg.offer_interval
        self._last_offer: float | None = None
        self._offers_since_answer = 0
        self.mode = self._first_mode()
        self.frame_loss = FrameLoss()  # loss per frame size, and the size that carries most
        self._probe_due: float | None = None
        self._sends: dict[int, tuple[float, int]] = {}  # offset -> (last send time, sends)
        self._since: dict[int, int] = {}  # offset -> sends since it was last known to be missing
        self.sent = RangeSet()  # the bytes this attempt put in data frames
        self.stats.resumed_bytes = 0  # acknowledged bytes this attempt never sent: the receiver had them

    def _first_mode(self) -> str:
        if self.cfg.frame_mode == "auto":
            return "wide" if self.on_stream else "narrow"
        return "narrow" if self.cfg.frame_mode == "narrow" else "wide"

    def use_path(self, geometry: Any, byte_time: float, stream: bool) -> None:
        """File data takes another path from now on (a pipeline opened or closed, pipeline.py):
        frames are cut for it from the next offset. What was sent and not acknowledged stays
        owed: the receiver's status reports what the old path lost, and that is resent. Loss
        learnt on the old path says nothing of the new one."""
        if stream == self.on_stream and geometry == self.geometry and byte_time == self.byte_time:
            return
        self.geometry = geometry
        self.byte_time = byte_time
        self.on_stream = stream
        self.mode = self._first_mode()
        self.frame_loss = FrameLoss()

    def _use(self, z: DeflatedSource | None) -> None:
        """Offer the zlib stream `z`, or the file as it is (None)."""
        self.deflated = z
        self.source: Any = z if z is not None else self.raw_source
        self.size = self.source.size  # bytes on the link: the file's, or its stream's
        if z is not None:
            self.flags = self._flags | int(TtFileFlags.TT_FILE_FLAGS_DEFLATE)
            self.meta = deflate_meta(self.raw_source.sha256, self.file_size, encoded(self.name))
        else:
            self.flags = self._flags
            self.meta = self.raw_source.sha256 + encoded(self.name)
        self.check = meta_check(self.meta)

    def _fall_back(self, now: float, why: str, count: bool = False) -> None:
        """The receiver did not take the zlib stream: the file as it is, under a new id."""
        self.fallback = why
        if self.deflated is not None:
            self.deflated.close()
        self._use(None)
        self._restart(now, count)
        self.last_progress = now

    def close(self) -> None:
        """Release what the transfer made for itself (a large stream's temporary file)."""
        if self.deflated is not None:
            self.deflated.close()

    # -- progress -----------------------------------------------------------------------------
    @property
    def done(self) -> bool:
        return self.result is not None

    @property
    def acked_bytes(self) -> int:
        return self.acked.total()

    def _finish(self, now: float, ok: bool, code: str, message: str, nothing_sent: bool = False) -> None:
        if self.done:
            return
        self.state = "complete" if ok else "failed"
        self.stats.finished = now
        self.result = TransferResult(ok, code, message, self.name, self.file_size, now - self.stats.started,
                                     self.stats, nothing_sent, self.size if self.deflated is not None else None,
                                     self.fallback)
        if self.on_progress:
            self.on_progress(self)

    def cancel(self, now: float) -> None:
        self._finish(now, False, "CANCELLED", "cancelled")

    def _restart(self, now: float, count: bool = True) -> None:
        """Start again from scratch under a new transfer id."""
        self.stats.restarts += count
        self.id = self.new_id()
        self._begin(now)

    # -- offers -------------------------------------------------------------------------------
    def offer_messages(self) -> list[Any]:
        parts: list[Any] = []
        for off in range(0, len(self.meta), META_PART):
            parts.append(self.b.TtFileOffer(
                target_system=self.target[0], target_component=self.target[1], transfer_id=self.id,
                request_id=self.request_id, size=self.size, flags=self.flags, meta_length=len(self.meta),
                meta_offset=off, meta=self.meta[off:off + META_PART]))
        return parts

    def control(self, now: float) -> list[Any]:
        """Offers due now (the first, retries, or a poll when the receiver has gone quiet)."""
        if self.done:
            return []
        if self._refusal is not None and now >= self._refusal[1] + max(self.cfg.reason_wait, 3 * self.rtt):
            self._refuse(now, self._refusal[0])
            return []
        if self._unzip_refusal is not None and now >= self._unzip_refusal[1] + max(self.cfg.reason_wait, 3 * self.rtt):
            code = self._unzip_refusal[0]  # no words came: the code's
            self._fall_back(now, RESULT_TEXT.get(result_name(code), "refused"),
                            count=code == R.TT_FILE_RESULT_FAILED_CHECKSUM)
        # each time compared as deadline() computes it: `now - a >= b` can be false at now == a + b
        if now >= self.last_progress + self.cfg.give_up_after:
            self._time_out(now)
            return []
        if self.state == "sending" and self._probe_due is None \
                and now >= self.last_heard + self._quiet_after():
            # statuses stopped while data flows: the receiver may have restarted; ask where it is
            self._probe_due = now
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
        if self.stats.offers_sent == 1 and self.cfg.first_offer_copies > 1:
            # nothing moves before the answer: at 30 % loss a single offer and its answer both
            # arrive half the time, two copies (each answered) 83 % of the time
            return self.offer_messages() * self.cfg.first_offer_copies
        return self.offer_messages()

    def _quiet_after(self) -> float:
        """How long without a status, while data flows, before asking where the receiver is:
        three status intervals, an RTT more, and under a grant three frames' time at it more
        (the receiver reports on the frames it gets)."""
        return quiet_after(self.cfg, self.rtt, self.pacer.grant, self.geometry.mtu)

    def _time_out(self, now: float) -> None:
        who = f"{self.target[0]}/{self.target[1]}"
        secs = f"{self.cfg.give_up_after:g} s"
        if not self.heard_any:
            text = f"no answer from {who} for {secs}"
        elif self.busy is not None:
            text = f"{who} stayed busy for {secs} ({self.busy})"
        else:
            text = f"no progress for {secs}"
            if now >= self.last_heard + self.cfg.give_up_after:
                text += f", nothing heard from {who}"
        if self.acked_bytes:
            text += " (what arrived is kept there: send again to resume)"
        self._finish(now, False, "TIMEOUT", text)

    def _refuse(self, now: float, code: str) -> None:
        text = self.reason or RESULT_TEXT.get(code, "refused")
        if code == "FAILED_CHECKSUM" and self.source.changed():
            text = f"{self.source.path} changed while it was being sent"
        self._finish(now, False, code, text)

    # -- data ---------------------------------------------------------------------------------
    def has_data(self, now: float) -> bool:
        """A data frame may leave now (the scheduler's pacer permitting)."""
        return self._wants_data(now) and self.pacer.ready(now)

    def _wants_data(self, now: float) -> bool:
        if self.state != "sending":
            return False
        if self.retx or self.next_new < self.size:
            return True
        due = self._tail_due()
        return due is not None and now >= due

    def _tail_due(self) -> float | None:
        """When the oldest unacknowledged bytes become worth sending again on an otherwise idle
        link (a tail-loss probe: the link would idle until the next status anyway). On a pipeline
        nothing is lost while it stays open (a close moves the data, and this wait, back to the
        packets), so there a probe waits for the status that should have come."""
        oldest = min((ts for s, e, ts in self._sent if not self.acked.covers(s, e)), default=None)
        return oldest + self._probe_wait() if oldest is not None else None

    def _probe_wait(self) -> float:
        return max(3 * self.rtt, 1.5) if self.on_stream else 0.0  # (statuses come every second or so)

    def _choose_mode(self) -> str:
        if self.cfg.frame_mode != "auto":
            return self.cfg.frame_mode
        if self.on_stream:
            return "wide"  # a stream loses nothing but what is in flight when it closes
        if self.pacer.grant:
            # sharing the link: a wide frame's three packets back to back fill the radio's
            # buffer for the others, and the buffer's overflow takes the whole frame
            return "narrow"
        return self.frame_loss.best(self.mode, self.geometry)

    def next_data(self, now: float, space: int) -> Any:
        if self.state != "sending" or not self.pacer.ready(now):
            return None
        mode, g = self.mode, self.geometry
        frame_len = g.wide_frame if mode == "wide" else g.narrow_frame
        if mode == "narrow" and space < frame_len:
            return None  # a narrow frame takes a packet of its own: wait for the next one
        cap = WIDE if mode == "wide" else g.narrow_cap
        retx = self.retx.first()
        new = False  # bytes never sent before: their fate measures the loss of this frame size
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
            new = True
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
        left = now + (frame_len + g.mtu) * self.byte_time
        self._record(left, offset, offset + length)
        if new:  # (not a resend from the tail: a repeat of bytes that may well have arrived)
            self.frame_loss.first_send(offset, offset + length, left, mode)
        self.pacer.sent(now, frame_len)
        self.sent.add(offset, offset + length)
        self.stats.bytes_sent += length
        self.stats.frames_sent += 1
        if self.stats.data_started is None:
            self.stats.data_started = now
        if mode == "wide":
            self.stats.wide_frames += 1
            msg: Any = self.b.TtFileDataWide(transfer_id=self.id, offset=offset, data=data)
        else:
            self.stats.narrow_frames += 1
            if g.narrow_fit:
                msg = self.b.TtFileDataFit(transfer_id=self.id, offset=offset, count=length, data=data)
            else:
                msg = self.b.TtFileData(transfer_id=self.id, offset=offset, data=data)
        if self.cfg.frame_mode == "auto" and self.stats.narrow_frames >= self.cfg.probe_frames:
            self.mode = self._choose_mode()
        if not self._wants_data(now) and self._probe_due is None:
            self._probe_due = now + max(2 * self.rtt, 0.5)
        return msg

    def _tail_candidate(self, now: float) -> int | None:
        """The unacknowledged chunk most likely still missing: the fewest sends since it was
        last known to be missing (each send leaves it missing with probability p), the one
        sent longest ago among those. No part of the tail starves when statuses are lost."""
        best: tuple[int, float, int] | None = None
        wait = self._probe_wait()
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
    def on_reason(self, now: float, msg: Any) -> None:
        """The receiver's words for a refusal or failure (they come just before its status)."""
        if self.done or msg.transfer_id != self.id:
            return
        text = reason_text(msg.text)
        if msg.result == R.TT_FILE_RESULT_REFUSED_BUSY:
            self.busy = text
            return
        self.reason = text
        if self._refusal is not None:
            self._refuse(now, self._refusal[0])
        elif self._unzip_refusal is not None:
            self._fall_back(now, text, count=self._unzip_refusal[0] == R.TT_FILE_RESULT_FAILED_CHECKSUM)

    def on_status(self, now: float, msg: Any) -> None:
        if self.done or msg.transfer_id != self.id:
            return
        code = msg.result
        if msg.meta_check != self.check:
            if code == R.TT_FILE_RESULT_UNKNOWN_TRANSFER or (code == R.TT_FILE_RESULT_REFUSED_BUSY
                                                             and msg.meta_check == 0):
                pass  # said before the receiver had our metadata: nothing to mistake
            elif msg.meta_check != 0:
                # the receiver holds another transfer under our id (a 1 in 2^32 draw): take a new one
                self._restart(now, count=False)
                return
            else:
                return
        self.last_heard = now
        self.heard_any = True
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
        if code == R.TT_FILE_RESULT_COMPLETE:
            nothing = self.stats.bytes_sent == 0 and self.size > 0
            if nothing:
                self.acked.add(0, self.size)  # an identical file was there (or all of it): no resume
            else:
                self._ack(0, self.size)
            how = "verified there (it had them already)" if nothing else "delivered and verified"
            self._finish(now, True, "COMPLETE", f"{self.name}: {self.file_size} bytes {how}", nothing)
            return
        if code == R.TT_FILE_RESULT_UNKNOWN_TRANSFER:
            self.state = "offering"  # the receiver restarted: offer again, it resumes from disk
            self._offer_due = now
            return
        if code == R.TT_FILE_RESULT_REFUSED_BUSY:
            self.busy = self.busy or RESULT_TEXT["REFUSED_BUSY"]
            self.state = "offering"  # keep offering (with backoff) until there is room or time is up
            return
        if code == R.TT_FILE_RESULT_REFUSED_UNSUPPORTED and self._flags & MAP and refused_flags(self.reason) & MAP:
            # a receiver from before TT_FILE_MAP refuses the flag it does not know, in words naming it:
            # offer again without it (and if it refuses a zlib stream too, that comes next), under a new id
            self._flags &= ~MAP
            self._use(self.deflated)
            self._restart(now, count=False)
            self.last_progress = now
            return
        if self.deflated is not None and code in (R.TT_FILE_RESULT_REFUSED_UNSUPPORTED, R.TT_FILE_RESULT_REFUSED_NAME,
                                                  R.TT_FILE_RESULT_FAILED_CHECKSUM):
            # it does not inflate, or (a receiver from before deflate) took the original size
            # for part of the name, or the stream did not inflate to the file there
            if self.reason is not None:
                self._fall_back(now, self.reason, count=code == R.TT_FILE_RESULT_FAILED_CHECKSUM)
            elif self._unzip_refusal is None:  # the words may come after the status: wait a moment, ask again
                self._unzip_refusal = (code, now)
                self._offer_due = now
                self.state = "offering"
            return
        if code == R.TT_FILE_RESULT_FAILED_CHECKSUM and self.stats.restarts < self.cfg.checksum_restarts \
                and not self.source.changed():
            self._restart(now)  # the receiver discarded what it had: again, from scratch
            self.last_progress = now
            return
        if code != R.TT_FILE_RESULT_IN_PROGRESS:
            name = result_name(code)
            if self.reason is not None:
                self._refuse(now, name)
            elif self._refusal is None:
                self._refusal = (name, now)  # wait a moment for the words, and ask once more
                self._offer_due = now
                self.state = "offering"
            return
        if self.state == "offering":
            self.state = "sending"
            self._probe_due = None
            self.busy = None
            self.last_progress = now
        grant = getattr(msg, "rate_grant", 0)
        self.pacer.update(grant, now)
        if grant and (self.stats.min_grant is None or grant < self.stats.min_grant):
            self.stats.min_grant = grant
        self._rtt_from_echo(now, msg)
        self._apply(now, read_status(msg, self.size), msg)
        if self.on_progress:
            self.on_progress(self)

    def on_map(self, now: float, msg: Any) -> None:
        """A TT_FILE_MAP: a status in progress whose gaps come as a bit a chunk."""
        if self.done or msg.transfer_id != self.id or msg.meta_check != self.check or self.state == "offering":
            return  # (a map is sent only once data flows: after the status that accepted the offer)
        self.last_heard = now
        self.stats.statuses += 1
        grant = msg.rate_grant
        self.pacer.update(grant, now)
        if grant and (self.stats.min_grant is None or grant < self.stats.min_grant):
            self.stats.min_grant = grant
        self._rtt_from_echo(now, msg)
        self._apply(now, read_map(msg, self.size), msg)
        if self.on_progress:
            self.on_progress(self)

    def _ack(self, start: int, end: int) -> None:
        """Bytes [start, end) are at the receiver; those newly known that this attempt never sent
        were there before it (resumed), whatever the order of the statuses that say so."""
        for a, b in self.acked.gaps(start, end):
            self.stats.resumed_bytes += sum(y - x for x, y in self.sent.gaps(a, b))
        self.acked.add(start, end)

    def _rtt_from_echo(self, now: float, msg: Any) -> None:
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

    def _apply_status(self, now: float, msg: Any) -> None:
        self._apply(now, read_status(msg, self.size), msg)

    def _apply(self, now: float, report: Report, msg: Any) -> None:
        """What a status or a map says (reports.py), `msg` for its echo of the latest frame."""
        rc, region, re, missing, truncated = report.rc, report.region, report.end, report.missing, report.truncated
        before = self.acked.total()
        self._ack(0, rc)
        pos = region
        for a, b in missing:
            if a > pos:
                self._ack(pos, a)
            pos = max(pos, b)
        if re > pos:
            self._ack(pos, re)
        if self.acked.total() > before:
            self.last_progress = now
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
            horizon = min(horizon, echo[0] - 2 * self.geometry.mtu * self.byte_time)
        if re < self.next_new and not truncated:
            missing = [*missing, (re, self.next_new)]
        for a, b in missing:
            for s, e, ts in self._sent:
                if e <= a or s >= b or ts > horizon:
                    continue
                self.retx.add(max(a, s), min(b, e))
                self._since[s] = 0
            self.frame_loss.lost(a, b, horizon)
        for a, b in self.acked:
            self.retx.remove(a, b)
        self._sent = [(s, e, ts) for s, e, ts in self._sent if not self.acked.covers(s, e)]
        self.frame_loss.classify(horizon, re, truncated, missing, self.geometry, rc, region)
        if self.cfg.frame_mode == "auto" and self.stats.narrow_frames >= self.cfg.probe_frames:
            self.mode = self._choose_mode()
        self._probe_due = None if self._wants_data(now) else now + max(2 * self.rtt, 0.5)

    def deadline(self, now: float) -> float | None:
        """The next time this transfer needs attention (data waiting for the pacer is the
        scheduler's business, not a deadline)."""
        if self.done:
            return None
        times = [self.last_progress + self.cfg.give_up_after]
        granted = self.pacer.ready_at()
        if granted is not None and granted > now and self._wants_data(now):
            times.append(granted)  # data waits for its grant
        if self.state == "sending" and not self.retx and self.next_new >= self.size:
            due = self._tail_due()
            if due is not None and due > now:
                times.append(due)
        for waiting in (self._refusal, self._unzip_refusal):
            if waiting is not None:
                times.append(waiting[1] + max(self.cfg.reason_wait, 3 * self.rtt))
        if self.state == "offering":
            times.append(self._offer_due)
        elif self._probe_due is not None:
            times.append(self._probe_due)
        else:
            times.append(self.last_heard + self._quiet_after())
        return min(times)
