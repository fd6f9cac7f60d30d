"""One incoming file transfer's state, as the receiver (receiver.py) keeps it: its offer's
metadata as it arrives, the decision taken on it, its partial file, and when it is next due a
status."""

from __future__ import annotations

from ..wire.contract import TtFileFlags
from ..wire.contract import TtFileResult as R
from .ranges import RangeSet
from .storage import Partial
from .transfer import Key


class Incoming:
    """The receiving side of one transfer."""

    def __init__(self, key: Key, now: float) -> None:
        self.key = key
        self.meta = bytearray()
        self.meta_have = RangeSet()
        self.meta_length = 0
        self.size = 0  # bytes on the link: the file's, or its zlib stream's
        self.original: int | None = None  # the file's size, when a zlib stream of it is offered
        self.flags = 0
        self.request_id = 0
        self.name = ""
        self.sha256 = b""
        self.check = 0  # meta_check, once the metadata is whole
        self.decided = False  # accepted, refused, busy, finished
        self.group: str | None = None  # the partial file it receives into
        self.partial: Partial | None = None
        self.result = R.TT_FILE_RESULT_IN_PROGRESS
        self.reason = ""
        self.frames = 0
        self.last_activity = now
        self.status_due: float | None = None
        self.last_status = -1e9
        self.final_path: str | None = None
        self.finished_at: float | None = None
        self.finals_left = 0  # repeats of the COMPLETE status still to send (see COMPLETE_REPEATS)
        self.nothing_sent = False  # complete without data: an identical file, or a whole partial, was here
        self.identical = False  # complete because an identical file was there under the name
        self.started = now
        self.last_data: float | None = None
        self.last_offset = 0
        self.chunk = 0  # the latest data frame's capacity: what a bit of a TT_FILE_MAP stands for
        self.seen_end = False  # the last chunk has arrived once: the tail, where every round trip counts
        self.gap_dt = 0.05  # EWMA of the time between data frames
        self.quiet_due: float | None = None  # report when data stops coming
        self.said_busy = False

    @property
    def who(self) -> str:
        return f"{self.key[0]}/{self.key[1]}"

    @property
    def offered_again(self) -> bool:
        """Refused for what the offer carried (REFUSED_UNSUPPORTED: deflate, where the file as it
        is was wanted): its sender offers the file again without it, under a new transfer id; a
        download waits for that offer rather than failing."""
        return self.result == R.TT_FILE_RESULT_REFUSED_UNSUPPORTED

    @property
    def file_size(self) -> int:
        return self.size if self.original is None else self.original

    @property
    def overwrite(self) -> bool:
        return bool(self.flags & TtFileFlags.TT_FILE_FLAGS_OVERWRITE)


__all__ = ["Incoming"]
