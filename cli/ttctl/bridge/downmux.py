"""The onboard end's downlink to ground stations behind the tablet, fair between stations and
between kinds of traffic (issue 29).

One bulk source of the DTT scheduler (below the tablet's own commands, acks and telemetry), which
picks each frame in this order:

1. the vehicle's HEARTBEAT (newest wins), and again REPEAT s after it left, REPEATS times, while
   no newer one came (three a second, about 70 B/s of the 6.7 KB/s): a station sees one at least
   every second with two packets in a row lost (a gap of 2 s takes five), and never waits behind
   a file transfer (it used to queue with the answers, 14 s behind an FTP burst);
2. the streams (GLOBAL_POSITION_INT, ATTITUDE, ...: downfit.StreamFit, newest-wins, at most their
   share of the downlink: so what is left for the answers is never less than the rest);
3. short answers (acks, MISSION_COUNT, STATUSTEXT, MESSAGE_INTERVAL, ...) in order: a command's
   ack does not wait for a list;
4. bulk answers (FTP data, parameter and mission lists both ways, log data), one lane per station they are
   addressed to (and one for those addressed to every station), fair by bytes between the lanes
   that have something waiting: two stations downloading share the rest of the link, and a
   station's one parameter does not wait behind another's 64 KB file.

Frames are made as they leave (consecutive sequence numbers); an answer equal to one still waiting
in its lane is not queued twice (answers.py). Bounded: LANES bulk lanes (answers to further
stations share the broadcast lane), each answers.LIMIT frames.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from .answers import LIMIT, AnswerQueue
from .downfit import StreamFit

REPEAT = 1 / 3  # s after a HEARTBEAT left, it leaves again if no newer one came ...
REPEATS = 2  # ... this many times
LANES = 16
BULK = frozenset({"FILE_TRANSFER_PROTOCOL", "PARAM_VALUE", "PARAM_EXT_VALUE", "MISSION_ITEM_INT", "MISSION_ITEM",
                  "MISSION_REQUEST_INT", "MISSION_REQUEST", "LOG_ENTRY", "LOG_DATA", "ENCAPSULATED_DATA",
                  "DATA_TRANSMISSION_HANDSHAKE"})
SHORT_LIMIT = 128

Lane = tuple[int, int] | None  # the station a bulk answer is addressed to (None: every station)


class FairDownlink:
    def __init__(self, fit: StreamFit, encode: Callable[[Any], bytes], limit: int = LIMIT) -> None:
        self.fit = fit
        self.encode = encode
        self.limit = limit
        self.short = AnswerQueue(encode, limit=SHORT_LIMIT)
        self.lanes: dict[Lane, AnswerQueue] = {}
        self.served: dict[Lane, float] = {}  # bytes each lane sent while others waited (fair queueing)
        self.heartbeat: Any = None
        self._hb_due: float | None = None
        self._hb_repeats = 0
        self.heartbeats = 0

    # -- in ------------------------------------------------------------------------------------
    def put_heartbeat(self, now: float, msg: Any) -> None:
        self.heartbeat = msg
        self._hb_due = now
        self._hb_repeats = REPEATS

    def put(self, msg: Any) -> bool:
        """An answer (False: equal to one still waiting, not queued twice)."""
        if msg.NAME not in BULK:
            return self.short.put(msg)
        lane = self._lane(msg)
        q = self.lanes.get(lane)
        if q is None:
            q = self.lanes[lane] = AnswerQueue(self.encode, limit=self.limit)
        if not q.queue:  # joining the waiting lanes: no credit for the time it had nothing to send
            active = [self.served[k] for k, v in self.lanes.items() if v.queue]
            self.served[lane] = max(self.served.get(lane, 0.0), min(active, default=0.0))
        return q.put(msg)

    def _lane(self, msg: Any) -> Lane:
        target = getattr(msg, "target_system", 0)
        if not target:
            return None
        lane = (int(target), int(getattr(msg, "target_component", 0)))
        if lane not in self.lanes and len(self.lanes) >= LANES:
            return None
        return lane

    @property
    def waiting(self) -> int:
        return len(self.short.queue) + sum(len(q.queue) for q in self.lanes.values())

    @property
    def dropped(self) -> int:
        return self.short.dropped + sum(q.dropped for q in self.lanes.values())

    # -- out -----------------------------------------------------------------------------------
    def pull(self, now: float, space: int) -> bytes | None:
        if self._hb_due is not None and self._hb_due <= now:
            self.heartbeats += 1
            if self._hb_repeats > 0:
                self._hb_repeats -= 1
                self._hb_due = now + REPEAT
            else:
                self._hb_due = None
            return bytes(self.encode(self.heartbeat))
        frame = self.fit.pull(now, space)
        if frame is not None:
            return frame
        if self.short.queue:
            return self.short.pull(now, space)
        waiting = [k for k, q in self.lanes.items() if q.queue]
        if not waiting:
            return None
        lane = min(waiting, key=lambda k: self.served[k])
        frame = self.lanes[lane].pull(now, space)
        if frame is not None:
            self.served[lane] += len(frame)
        return frame

    def has_data(self, now: float) -> bool:
        return ((self._hb_due is not None and self._hb_due <= now) or self.fit.has_data(now)
                or self.waiting > 0)

    def deadline(self, now: float) -> float | None:
        if self.waiting:
            return now
        times = [t for t in (self._hb_due, self.fit.deadline(now)) if t is not None]
        return min(times) if times else None
