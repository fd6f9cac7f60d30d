"""The receiving side of every incoming file transfer of an endpoint, sans-IO (see transfer.py
for the protocol).

A transfer is known by (sender sysid, sender compid, transfer id): the id is the sender's
random nonce, so senders with equal MAVLink ids (several processes on one laptop) never meet.
Transfers of the same file under the same name share one partial file (a sender and its
restarted self, or two senders of one file), so each one's bytes count for all. A status only
ever reports bytes that were saved to disk before it was built, so whatever a sender learns
survives a crash of the receiver.

A deflated offer (TT_FILE_FLAGS_DEFLATE) is received as its zlib stream, resumed like any
file, and inflated only when the stream is whole, bounded by the size offered (storage.py); an
offer with a flag this receiver does not know is refused with REFUSED_UNSUPPORTED, the flag
named in its reason.

When transfers share the link, every status carries the transfer's rate grant (sharing.py).
"""

from __future__ import annotations

import errno
from collections import OrderedDict
from collections.abc import Callable
from typing import Any

from ..wire.bindings import Bindings
from ..wire.contract import TtFileFlags
from ..wire.contract import TtFileResult as R
from .deflate import InflateError, parse_deflate_meta
from .incoming import Incoming
from .names import SHA_LEN, Refused, check_name
from .reports import map_regions
from .sharing import ACTIVE_WINDOW, CONTROL_WINDOW, REGRANT, InboundLoad, share
from .storage import DiskFull, Partial, ReceiveDir, StorageError, partial_key
from .transfer import (
    MAP_MAX,
    MAP_MORE,
    MAX_RANGES,
    NARROW,
    NARROW_FRAME,
    RANGES_MORE,
    WIDE_FRAME,
    Key,
    TransferConfig,
    meta_check,
    reason_fit,
)

MAX_PENDING_OFFERS = 64  # offers whose metadata is still arriving: a flood of them is not our memory's problem
MAX_UNKNOWN = 256  # transfer ids recently told 'unknown'
MAX_KNOWN = 1024  # transfers remembered at once (those not receiving are forgotten first, oldest first)
# A COMPLETE status is said COMPLETE_REPEATS more times, COMPLETE_REPEAT_GAP s apart: a receiver
# process that ends right after its file is complete (send-file --from drains for a moment, then
# exits) cannot answer the sender's later probe, and a lost last COMPLETE left the sender (a Java
# or Python server) recording a delivered, verified file as failed.
COMPLETE_REPEATS = 2
COMPLETE_REPEAT_GAP = 0.05

_REFUSAL = {
    "NAME": R.TT_FILE_RESULT_REFUSED_NAME,
    "EXISTS": R.TT_FILE_RESULT_REFUSED_EXISTS,
    "QUOTA": R.TT_FILE_RESULT_REFUSED_QUOTA,
    "BUSY": R.TT_FILE_RESULT_REFUSED_BUSY,
}
_EXPLAINED = {R.TT_FILE_RESULT_REFUSED_NAME, R.TT_FILE_RESULT_REFUSED_EXISTS, R.TT_FILE_RESULT_REFUSED_QUOTA,
              R.TT_FILE_RESULT_REFUSED_BUSY, R.TT_FILE_RESULT_FAILED_CHECKSUM, R.TT_FILE_RESULT_FAILED_DISK_FULL,
              R.TT_FILE_RESULT_FAILED_IO, R.TT_FILE_RESULT_REFUSED_UNSUPPORTED}
DEFLATE = int(TtFileFlags.TT_FILE_FLAGS_DEFLATE)
MAP = int(TtFileFlags.TT_FILE_FLAGS_MAP)
KNOWN_FLAGS = int(TtFileFlags.TT_FILE_FLAGS_OVERWRITE | TtFileFlags.TT_FILE_FLAGS_CANCEL) | DEFLATE | MAP
MAP_BURST = 2  # maps per report at most (one covers hundreds of frames)


class FileReceiver:
    """Every incoming transfer of an endpoint; files land in `store`. `unsolicited=False` takes
    only files this end asked for (`expect()`), as a download does."""

    def __init__(self, bindings: Bindings, store: ReceiveDir, sysid: int, compid: int,
                 config: TransferConfig | None = None, max_transfers: int = 8,
                 on_event: Callable[[str, Incoming], None] | None = None, unsolicited: bool = True,
                 inflate: bool = True, inbound_Bps: float | None = None) -> None:
        self.b = bindings
        self.store = store
        self.sysid = sysid
        self.compid = compid
        self.cfg = config or TransferConfig()
        self.max_transfers = max_transfers
        self.unsolicited = unsolicited
        self.known_flags = KNOWN_FLAGS if inflate else KNOWN_FLAGS & ~DEFLATE
        self.transfers: dict[Key, Incoming] = {}
        self.groups: dict[str, tuple[Partial, set[Key]]] = {}  # partial key -> the partial, who shares it
        self.on_event = on_event
        self.now = 0.0
        self.expected: dict[tuple[int, int, int], str] = {}  # (peer sysid, compid, request id) -> name asked for
        self._unknown: OrderedDict[Key, float] = OrderedDict()  # told 'unknown transfer', when
        self._unknown_due: list[Key] = []
        self.evicted = 0  # offers forgotten before their metadata was whole, to make room in a flood
        self.inbound_Bps = inbound_Bps  # what this end can take from its link: shared out by grants
        self.grant = 0  # each sharing transfer's rate grant, B/s (0: none)
        self.packet = 100  # the link's packet size, bytes (set by the endpoint): one packet's time at a grant
        self.sharing: frozenset[Key] = frozenset()  # the transfers the link is shared among
        self.load = InboundLoad()  # what else comes in (the endpoint counts packets, on_data the data)
        self.control_at: float | None = None  # when a control frame (a command, a setpoint) last came in
        self.control_apart = False  # file data takes another path than control (a pipeline): no control grant
        self.ranges_per_status = MAX_RANGES  # gaps per status: as many as fit one packet (set by the endpoint)
        self.map_bytes = 0  # a TT_FILE_MAP's map bytes that fit one packet (set by the endpoint; 0: no maps)
        self._grant_field = "rate_grant" in getattr(bindings.TtFileStatus, "FIELDS", ("rate_grant",))

    def expect(self, peer: tuple[int, int], request_id: int, name: str) -> None:
        self.expected[(peer[0], peer[1], request_id)] = name

    def _live_groups(self, now: float) -> set[str]:
        return {t.group for t in self.transfers.values()
                if t.group is not None and t.partial is not None and now - t.last_activity < self.cfg.live_window}

    # -- offers ---------------------------------------------------------------------------------
    def on_offer(self, now: float, msg: Any) -> None:
        if msg.transfer_id == 0 or msg.meta_length == 0:
            return
        key = (msg.get_srcSystem(), msg.get_srcComponent(), msg.transfer_id)
        t = self.transfers.get(key)
        if t is None:
            undecided = [x for x in self.transfers.values() if not x.decided]
            if len(undecided) >= MAX_PENDING_OFFERS:
                # a flood of offers whose metadata never completes: the stalest goes, so that it
                # cannot lock real senders out until it is forgotten (a real sender's offer is
                # whole in one or two messages, and repeated until answered)
                self._close(min(undecided, key=lambda x: x.last_activity))
                self.evicted += 1
            if len(self.transfers) >= MAX_KNOWN and not self._forget_one():
                return
            t = self.transfers[key] = Incoming(key, now)
            t.size, t.meta_length, t.flags, t.request_id = msg.size, msg.meta_length, msg.flags, msg.request_id
            t.meta = bytearray(msg.meta_length)
        elif (t.size, t.meta_length, t.flags, t.request_id) != (msg.size, msg.meta_length, msg.flags, msg.request_id):
            # another file offered under this id (a 1 in 2^32 draw, or a confused peer): our
            # answer's meta_check tells that sender to draw a new id
            if t.decided:
                self._status_now(t, now)
            return
        t.last_activity = now
        self._unknown.pop(key, None)
        off = msg.meta_offset
        part = bytes(msg.meta[: max(0, min(len(msg.meta), t.meta_length - off))])
        if t.decided:
            if part and bytes(t.meta[off:off + len(part)]) != part:
                self._status_now(t, now)  # as above: not the metadata we decided on
                return
            if t.result == R.TT_FILE_RESULT_REFUSED_BUSY:
                self._decide(t, now)  # room now?
            else:
                self._status_now(t, now)  # a repeated offer, or a poll: answer with where we are
            return
        if off < t.meta_length and part:
            t.meta[off:off + len(part)] = part
            t.meta_have.add(off, off + len(part))
        if t.meta_have.covers(0, t.meta_length):
            self._decide(t, now)

    def _held_as_it_is(self, t: Incoming) -> int:
        """Bytes held of the file a deflated offer carries, received as it is."""
        assert t.original is not None
        group = self.groups.get(partial_key(t.name, t.original, t.sha256))
        if group is not None:
            return group[0].ranges.total()
        try:
            return self.store.partial(t.name, t.original, t.sha256).ranges.total()
        except (OSError, StorageError):
            return 0

    def _supersede(self, t: Incoming, now: float) -> None:
        """A request served anew (its server restarted, and was asked again, fetches.py): the
        quiet transfer that served it before makes way. This one resumes its bytes if it offers
        the same file (one partial key); another file (another SHA-256: the server's file changed)
        starts a partial of its own, and the old one's bytes, of a file no longer served, go."""
        for other in list(self.transfers.values()):
            if other is not t and other.key[:2] == t.key[:2] and other.request_id == t.request_id \
                    and other.partial is not None and now - other.last_activity >= self.cfg.status_interval:
                partial, members = self.groups.get(other.group or "", (None, set()))
                self._close(other)
                if partial is not None and members == set() and other.sha256 != t.sha256:
                    partial.discard()

    def _forget_one(self) -> bool:
        """Room for one more: forget the transfer heard from least recently among those not
        receiving (finished, refused, waiting); False if every one is receiving."""
        idle = [t for t in self.transfers.values() if t.partial is None]
        if not idle:
            return False
        self._close(min(idle, key=lambda t: t.last_activity))
        return True

    def _refuse(self, t: Incoming, now: float, code: R, reason: str) -> None:
        t.result, t.reason = code, reason
        if code == R.TT_FILE_RESULT_REFUSED_BUSY:
            if not t.said_busy:
                t.said_busy = True
                self._event("busy", t)
        else:
            self._event("refused", t)
        self._status_now(t, now)

    def _decide(self, t: Incoming, now: float) -> None:
        t.decided = True
        meta = bytes(t.meta)
        t.check = meta_check(meta)
        t.sha256 = meta[:SHA_LEN]
        raw_name = meta[SHA_LEN:]
        unknown = t.flags & ~self.known_flags
        if unknown:
            what = ": this receiver does not decompress" if unknown == DEFLATE else ""
            return self._refuse(t, now, R.TT_FILE_RESULT_REFUSED_UNSUPPORTED,
                                f"offer flags 0x{unknown:02x} not understood here{what}")
        if t.flags & DEFLATE:
            parsed = parse_deflate_meta(meta)
            if parsed is None:
                return self._refuse(t, now, R.TT_FILE_RESULT_REFUSED_NAME, "the deflate offer carries no name")
            t.sha256, t.original, raw_name = parsed
        try:
            t.name = raw_name.decode("utf-8")
            check_name(t.name)
        except UnicodeDecodeError:
            t.name = raw_name.decode("utf-8", "replace")
            return self._refuse(t, now, R.TT_FILE_RESULT_REFUSED_NAME, "the name is not valid UTF-8")
        except Refused as e:
            return self._refuse(t, now, _REFUSAL[e.code], e.reason)
        peer = (t.key[0], t.key[1])
        if t.request_id:
            asked = self.expected.get((peer[0], peer[1], t.request_id))
            if asked != t.name:
                return self._refuse(t, now, R.TT_FILE_RESULT_REFUSED_NAME,
                                    f"this end did not ask {t.who} for {t.name}")
            self._supersede(t, now)
        elif not self.unsolicited:
            return self._refuse(t, now, R.TT_FILE_RESULT_REFUSED_NAME, "this end takes only the files it asks for")
        if t.original is not None and (held := self._held_as_it_is(t)):
            # what arrived of the file sent as it is (an older sender, --no-compress) would be
            # orphaned by its stream: the sender falls back to the file and resumes it
            return self._refuse(t, now, R.TT_FILE_RESULT_REFUSED_UNSUPPORTED,
                                f"{held} bytes of it as it is are here: send it uncompressed to resume")
        group = partial_key(t.name, t.size, t.sha256, t.original)
        if group not in self.groups:
            for other in list(self.transfers.values()):
                if other.partial is None or other.name != t.name or other is t:
                    continue
                if now - other.last_activity < self.cfg.live_window:
                    return self._refuse(t, now, R.TT_FILE_RESULT_REFUSED_BUSY,
                                        f"{t.name} is being received from {other.who} right now")
                self._close(other)  # its sender went quiet: this one takes over the name (its data stays)
            if len(self._live_groups(now)) >= self.max_transfers:
                return self._refuse(t, now, R.TT_FILE_RESULT_REFUSED_BUSY,
                                    f"{self.max_transfers} transfers are running here")
            try:
                already = self.store.admit(t.name, t.file_size, t.overwrite, t.sha256,
                                           stream=t.size if t.original is not None else 0)
            except Refused as e:
                return self._refuse(t, now, _REFUSAL[e.code], e.reason)
            except (StorageError, OSError) as e:
                return self._refuse(t, now, R.TT_FILE_RESULT_FAILED_IO, str(e))
            if already:
                t.result, t.nothing_sent, t.identical, t.finished_at = R.TT_FILE_RESULT_COMPLETE, True, True, now
                t.finals_left = COMPLETE_REPEATS
                t.final_path = str(self.store.final_path(t.name))
                self._event("complete", t)
                self._status_now(t, now)
                return None
            self.groups[group] = (self.store.partial(t.name, t.size, t.sha256, t.original), set())
        partial, members = self.groups[group]
        members.add(t.key)
        t.group, t.partial = group, partial
        t.result, t.reason = R.TT_FILE_RESULT_IN_PROGRESS, ""
        self._event("accepted", t)
        if partial.complete:
            t.nothing_sent = True
            self._complete(group, now)
        self._status_now(t, now)
        return None

    # -- data -----------------------------------------------------------------------------------
    def on_data(self, now: float, msg: Any, cap: int, frame_len: int | None = None) -> None:
        """A data frame carrying min(cap, size - offset) file bytes; `frame_len`: its length
        unsigned (TT_FILE_DATA's 100, TT_FILE_DATA_WIDE's 267 if not given)."""
        key = (msg.get_srcSystem(), msg.get_srcComponent(), msg.transfer_id)
        t = self.transfers.get(key)
        if t is None:
            if self.unsolicited:
                self._tell_unknown(key, now)  # e.g. we restarted: the sender must offer again (and resume)
            return
        t.last_activity = now
        t.frames += 1
        self.load.data(now, frame_len if frame_len is not None else NARROW_FRAME if cap == NARROW else WIDE_FRAME)
        if t.partial is None or t.group is None:  # not accepted (yet), finished or refused
            if t.decided and now >= t.last_status + self.cfg.status_min_interval:
                self._status_now(t, now)
            return
        offset = msg.offset
        length = min(cap, t.size - offset) if offset < t.size else 0
        if length <= 0:
            return
        ranges = t.partial.ranges
        gaps_before = len(ranges)
        if not self._write(t, now, offset, bytes(msg.data[:length])):
            return
        if t.partial.complete:
            self._complete(t.group, now)
            return
        if t.last_data is not None:
            t.gap_dt = 0.8 * t.gap_dt + 0.2 * min(1.0, now - t.last_data)
        t.last_data = now
        t.last_offset = offset
        if offset + length < t.size or not t.chunk:  # (the file's last frame, often a shorter kind, keeps the grid)
            t.chunk = cap
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

    def _tell_unknown(self, key: Key, now: float) -> None:
        last = self._unknown.get(key)
        if last is not None and now - last < self.cfg.offer_interval:
            return
        self._unknown[key] = now
        self._unknown.move_to_end(key)
        while len(self._unknown) > MAX_UNKNOWN:
            self._unknown.popitem(last=False)
        if key not in self._unknown_due:
            self._unknown_due.append(key)

    def _flow_window(self, t: Incoming) -> float:
        """Data counts as still flowing this long after the last frame: a status interval, or
        under a grant three frames' time at it (a sender granted a frame every 1.5 s is not
        quiet; with no status it would poll, and its polls land on the others' frames)."""
        if self.grant and t.key in self.sharing:
            return max(self.cfg.status_interval, 3.0 * self.packet / self.grant)
        return self.cfg.status_interval

    def _min_interval(self, t: Incoming) -> float:
        return self.cfg.status_tail_interval if t.seen_end else self.cfg.status_min_interval

    def _write(self, t: Incoming, now: float, offset: int, data: bytes) -> bool:
        """Store a chunk; on a full disk or a storage error end every transfer of that file
        (what was written stays, for a resume) and return False."""
        assert t.partial is not None and t.group is not None
        try:
            t.partial.write(offset, data)
            return True
        except DiskFull:
            code, reason = R.TT_FILE_RESULT_FAILED_DISK_FULL, "the disk is full (what arrived is kept for a resume)"
        except StorageError as e:
            code, reason = R.TT_FILE_RESULT_FAILED_IO, str(e)
        self._end_group(t.group, now, code, reason, keep=True)
        return False

    def _end_group(self, group: str, now: float, code: R, reason: str, keep: bool, final: str | None = None) -> None:
        partial, members = self.groups.pop(group)
        if keep:
            partial.save()
        partial.close()
        for key in members:
            t = self.transfers.get(key)
            if t is None:
                continue
            t.partial, t.group = None, None
            t.result, t.reason = code, reason
            if code == R.TT_FILE_RESULT_COMPLETE:
                t.final_path, t.finished_at = final, now
                t.finals_left = COMPLETE_REPEATS
                self._event("complete", t)
            else:
                self._event("failed", t)
            self._status_now(t, now)

    def _complete(self, group: str, now: float) -> None:
        partial, members = self.groups[group]
        try:
            verified = partial.verify()
        except InflateError as e:
            partial.discard()  # a whole stream that is not the file: no resume can use it
            self._end_group(group, now, R.TT_FILE_RESULT_FAILED_CHECKSUM, str(e), keep=False)
            return
        except OSError as e:
            full = e.errno in (errno.ENOSPC, errno.EDQUOT)
            self._end_group(group, now, R.TT_FILE_RESULT_FAILED_DISK_FULL if full else R.TT_FILE_RESULT_FAILED_IO,
                            f"{partial.name}: inflating: {e.strerror or e} (the stream is kept for a resume)",
                            keep=True)
            return
        if not verified:
            partial.discard()
            self._end_group(group, now, R.TT_FILE_RESULT_FAILED_CHECKSUM,
                            "the SHA-256 of the bytes received differs from the offer's; they were discarded",
                            keep=False)
            return
        overwrite = self.store.quota.overwrite and all(
            self.transfers[k].overwrite for k in members if k in self.transfers)
        try:
            final = str(partial.finish(overwrite))
        except Refused as e:
            self._end_group(group, now, _REFUSAL[e.code], e.reason, keep=True)
            return
        except OSError as e:
            self._end_group(group, now, R.TT_FILE_RESULT_FAILED_IO, f"{partial.name}: {e.strerror or e}", keep=True)
            return
        self._end_group(group, now, R.TT_FILE_RESULT_COMPLETE, "", keep=False, final=final)

    def _close(self, t: Incoming) -> None:
        """Forget a transfer; its partial file stays (for a resume) unless others share it."""
        self.transfers.pop(t.key, None)
        if t.group is not None and t.group in self.groups:
            partial, members = self.groups[t.group]
            members.discard(t.key)
            if not members:
                partial.save()
                partial.close()
                del self.groups[t.group]
        t.partial, t.group = None, None

    def _event(self, what: str, t: Incoming) -> None:
        if self.on_event:
            self.on_event(what, t)

    def _status_now(self, t: Incoming, now: float) -> None:
        t.status_due = now

    # -- statuses -------------------------------------------------------------------------------
    def statuses(self, t: Incoming) -> list[Any]:
        """One status, or a burst describing successive regions when there are more gaps than
        one status holds."""
        if t.partial is None:
            done = t.size if t.result == R.TT_FILE_RESULT_COMPLETE else 0
            return [self._status(t, done, done, done, [])]
        ranges = t.partial.ranges
        rc = ranges.prefix()
        last = max((b for _, b in ranges), default=0)
        gaps = ranges.gaps(rc, last)
        if len(gaps) > self.ranges_per_status and t.flags & MAP and self.map_bytes and t.chunk:
            return self._maps(t, rc, last, gaps)
        out = []
        start = rc
        per = self.ranges_per_status
        for k in range(max(1, self.cfg.status_batches)):
            batch = gaps[k * per:(k + 1) * per]
            more = len(gaps) > (k + 1) * per
            end = batch[-1][1] if more else last
            out.append(self._status(t, rc, start, end, batch, more))
            start = end
            if not more:
                break
        return out

    def _maps(self, t: Incoming, rc: int, last: int, gaps: list[tuple[int, int]]) -> list[Any]:
        """More gaps than a status lists: maps, a bit a frame, each one packet (reports.py)."""
        return [self._map(t, rc, a, b, t.chunk, bits, more)
                for a, b, bits, more in map_regions(rc, last, t.last_offset, t.chunk, gaps, self.map_bytes, MAP_BURST)]

    def _map(self, t: Incoming, rc: int, region: int, re: int, chunk: int, bits: bytes, more: bool) -> Any:
        return self.b.TtFileMap(
            target_system=t.key[0], target_component=t.key[1], transfer_id=t.key[2], meta_check=t.check,
            received_contiguous=rc, region_start=region, received_end=re, last_offset=t.last_offset,
            hold_ms=min(65535, int(1000 * (self.now - t.last_data))) if t.last_data is not None else 65535,
            chunk=chunk, rate_grant=self.grant if t.key in self.sharing else 0, flags=MAP_MORE if more else 0,
            map=list(bits) + [0] * (MAP_MAX - len(bits)))

    def _share(self, now: float) -> None:
        """Who shares the link now (receiving, heard from lately); on a change, the new grant
        is told to every one of them at once."""
        window = max(ACTIVE_WINDOW, 4.0 * self.packet / self.grant) if self.grant else ACTIVE_WINDOW
        sharing = frozenset(k for k, t in self.transfers.items()
                            if t.partial is not None and now - t.last_activity < window)
        control = self.control_at is not None and now - self.control_at < CONTROL_WINDOW and not self.control_apart
        grant = share(self.inbound_Bps, len(sharing), self.load.other_Bps(now), control)
        if sharing == self.sharing and (grant == 0) == (self.grant == 0) \
                and abs(grant - self.grant) <= REGRANT * self.grant:
            return
        self.sharing = sharing
        if grant == self.grant:
            return
        self.grant = grant
        step = float(self.packet) / (grant * len(sharing)) if grant else 0.0
        for i, k in enumerate(sorted(sharing)):
            t = self.transfers[k]
            soon = max(now + i * step, t.last_status + self._min_interval(t))
            t.status_due = soon

    def _status(self, t: Incoming, rc: int, region: int, re: int,
                gaps: list[tuple[int, int]], more: bool = False) -> Any:
        flat = [x for gap in gaps for x in gap]
        extra = {}
        if self._grant_field:  # (a dialect with an older copy of ttapi.xml has no grants)
            sharing = t.key in self.sharing and t.result == R.TT_FILE_RESULT_IN_PROGRESS and t.partial is not None
            extra["rate_grant"] = self.grant if sharing else 0
        return self.b.TtFileStatus(
            target_system=t.key[0], target_component=t.key[1], transfer_id=t.key[2], result=int(t.result),
            received_contiguous=rc, region_start=region, received_end=re, last_offset=t.last_offset,
            hold_ms=min(65535, int(1000 * (self.now - t.last_data))) if t.last_data is not None else 65535,
            range_count=len(gaps) | (RANGES_MORE if more else 0), meta_check=t.check,
            ranges=flat + [0] * (2 * MAX_RANGES - len(flat)), **extra)

    def reason_message(self, t: Incoming) -> Any:
        return self.b.TtFileReason(target_system=t.key[0], target_component=t.key[1], transfer_id=t.key[2],
                                  result=int(t.result), text=reason_fit(t.reason))

    def control(self, now: float) -> list[tuple[Any, object]]:
        """Statuses due now (each after the reason for a refusal or failure), each with a key
        under which a newer one replaces it while it waits to be sent; forget silent transfers.
        Partial state is saved before the statuses that report it leave."""
        self.now = now
        out: list[tuple[Any, object]] = []
        for t in list(self.transfers.values()):
            if now >= t.last_activity + self.cfg.idle_timeout:  # as deadline() adds it: no float gap
                self._close(t)
        self._share(now)
        for t in list(self.transfers.values()):
            quiet = t.quiet_due is not None and now >= max(t.quiet_due, t.last_status + self._min_interval(t))
            if not (quiet or (t.status_due is not None and now >= t.status_due)):
                continue
            if t.partial is not None:
                t.partial.save()
            if t.result in _EXPLAINED and t.reason:
                out.append((self.reason_message(t), ("reason", t.key)))
            out.extend((m, ("status", t.key, i)) for i, m in enumerate(self.statuses(t)))
            t.last_status = now
            t.quiet_due = None
            flowing = (t.result == R.TT_FILE_RESULT_IN_PROGRESS and t.partial is not None
                       and t.last_data is not None and now - t.last_data < self._flow_window(t))
            t.status_due = now + self.cfg.status_interval if flowing else None
            if t.result == R.TT_FILE_RESULT_COMPLETE and t.finals_left > 0:  # said again, shortly
                t.finals_left -= 1
                t.status_due = now + COMPLETE_REPEAT_GAP
        for key in self._unknown_due:
            out.append((self.b.TtFileStatus(target_system=key[0], target_component=key[1], transfer_id=key[2],
                                           result=int(R.TT_FILE_RESULT_UNKNOWN_TRANSFER)), ("unknown", key)))
        self._unknown_due.clear()
        return out

    def deadline(self) -> float | None:
        if self._unknown_due:
            return self.now
        times = [t.status_due for t in self.transfers.values() if t.status_due is not None]
        times += [max(t.quiet_due, t.last_status + self._min_interval(t))
                  for t in self.transfers.values() if t.quiet_due is not None]
        times += [t.last_activity + self.cfg.idle_timeout for t in self.transfers.values()]
        return min(times) if times else None

    def close(self) -> None:
        for t in list(self.transfers.values()):
            self._close(t)


__all__ = ["FileReceiver", "Incoming"]
