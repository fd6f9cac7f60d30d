"""The onboard end's answers to ground stations behind the tablet, queued below the app's own
control frames.

Acks, parameters, mission items and STATUSTEXT for a ground station behind the tablet must not
delay the tablet's own commands and acks: they wait here, in order, and leave as a bulk source of
the DTT scheduler (the app's control frames go first at packet granularity). One equal to an
answer still waiting (the same message and payload: a ground station asking for the parameter
list again and again) is not queued twice, so a flooding station costs the link one list, not
one per request. Frames are made as they leave, so their sequence numbers run without gaps.
Bounded (`limit` answers: beyond it the oldest is dropped, counted).
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable
from typing import Any

LIMIT = 512


class AnswerQueue:
    def __init__(self, encode: Callable[[Any], bytes], limit: int = LIMIT) -> None:
        self.encode = encode
        self.limit = limit
        self.queue: deque[tuple[tuple[int, bytes], Any]] = deque()
        self._waiting: set[tuple[int, bytes]] = set()
        self.sent = 0
        self.duplicates = 0
        self.dropped = 0

    def put(self, msg: Any) -> bool:
        key = (int(msg.MSG_ID), bytes(msg.pack_payload()))
        if key in self._waiting:
            self.duplicates += 1
            return False
        if len(self.queue) >= self.limit:
            old, _ = self.queue.popleft()
            self._waiting.discard(old)
            self.dropped += 1
        self.queue.append((key, msg))
        self._waiting.add(key)
        return True

    def pull(self, now: float, space: int) -> bytes | None:
        if not self.queue:
            return None
        key, msg = self.queue.popleft()
        self._waiting.discard(key)
        self.sent += 1
        return self.encode(msg)

    def has_data(self, now: float) -> bool:
        return bool(self.queue)

    def deadline(self, now: float) -> float | None:
        return now if self.queue else None
