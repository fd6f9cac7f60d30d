"""The bridge's queue toward the vehicle: ground stations' frames fitted to a share of the uplink.

Protocol frames (commands, parameters, missions, FTP...) wait in order; one equal to a frame
still waiting (same source, message and payload: a ground station's retry) is not queued twice.
Newest-wins frames (heartbeats, sticks, set-points: classes.NEWEST) wait one per source and
message, a newer one replacing the older. Protocol frames leave first, then the slots, the
longest-waiting first. The queue is a bulk source of the tablet's scheduler, so the app's own
commands, acks and file control go ahead of it at packet granularity, and it never takes more
than `budget_Bps` on average. Bounded: `max_protocol` frames and `max_slots` slots; beyond that
the oldest protocol frame (or slot) is dropped and counted, whatever a ground station floods.
Other messages (the user's own dialect's) wait in a queue of their own, `max_user` long, and
leave after the protocol frames and the slots: a station flooding its own messages loses its
oldest ones, never a command or a heartbeat.
"""

from __future__ import annotations

from collections import OrderedDict, deque
from dataclasses import dataclass

from .classes import NEWEST, ground_station_protocol

MAX_PROTOCOL = 64
MAX_SLOTS = 64
MAX_USER = 16
HEADER = 10  # a MAVLink 2 frame's header; the payload runs to the 2-byte CRC (frames here are unsigned)


@dataclass
class UplinkStats:
    queued: int = 0
    sent: int = 0
    duplicates: int = 0  # a retry of a frame still waiting
    replaced: int = 0  # a newest-wins frame overtaken while waiting
    overflow: int = 0  # dropped: the queue was full
    user_overflow: int = 0  # the user's own messages dropped: their queue was full
    sent_bytes: int = 0


def _key(frame: bytes) -> tuple[int, int, int, bytes]:
    """(sysid, compid, msgid, payload) of an unsigned MAVLink 2 frame: what a retry repeats."""
    msgid = frame[7] | frame[8] << 8 | frame[9] << 16
    return frame[5], frame[6], msgid, bytes(frame[HEADER:-2])


class GcsUplink:
    def __init__(self, budget_Bps: float | None, max_protocol: int = MAX_PROTOCOL, max_slots: int = MAX_SLOTS,
                 burst: int = 100, max_user: int = MAX_USER) -> None:
        self.budget = budget_Bps
        self.max_protocol = max_protocol
        self.max_slots = max_slots
        self.burst = burst
        self.protocol: deque[tuple[tuple[int, int, int, bytes], bytes]] = deque()
        self._waiting: dict[tuple[int, int, int, bytes], int] = {}  # key -> how many copies wait (0 or 1)
        self.slots: OrderedDict[tuple[int, int, int], tuple[bytes, float]] = OrderedDict()
        self.max_user = max_user
        self.user: deque[tuple[tuple[int, int, int, bytes], bytes]] = deque()
        self.tokens = float(burst)
        self._at: float | None = None
        self.stats = UplinkStats()

    # -- in ------------------------------------------------------------------------------------
    def put(self, now: float, name: str, frame: bytes, first: bool = False) -> str:
        """Queue an unsigned MAVLink 2 frame of message `name`: "queued", "duplicate", "replaced"
        (a newer frame took a waiting one's slot); "overflow" is counted when the oldest went.
        `first`: a protocol frame the vehicle or a station is waiting for (a lost one, sent again)
        goes ahead of the protocol frames already waiting; if an equal one waits, that one does."""
        key = _key(frame)
        if name in NEWEST:
            slot = key[:3]
            verdict = "queued"
            if slot in self.slots:
                self.stats.replaced += 1
                verdict = "replaced"
                del self.slots[slot]
            elif len(self.slots) >= self.max_slots:
                self.slots.popitem(last=False)
                self.stats.overflow += 1
            self.slots[slot] = (frame, now)
            self.stats.queued += 1
            return verdict
        if self._waiting.get(key):
            self.stats.duplicates += 1
            if first:  # the copy waiting goes ahead instead
                for i, (k, f) in enumerate(self.protocol):
                    if k == key:
                        del self.protocol[i]
                        self.protocol.appendleft((k, f))
                        break
            return "duplicate"
        if not ground_station_protocol(name):
            if len(self.user) >= self.max_user:
                old, _ = self.user.popleft()
                self._forget(old)
                self.stats.user_overflow += 1
            self.user.append((key, frame))
            self._waiting[key] = 1
            self.stats.queued += 1
            return "queued"
        if len(self.protocol) >= self.max_protocol:
            old, _ = self.protocol.popleft()
            self._forget(old)
            self.stats.overflow += 1
        if first:
            self.protocol.appendleft((key, frame))
        else:
            self.protocol.append((key, frame))
        self._waiting[key] = 1
        self.stats.queued += 1
        return "queued"

    def put_ahead(self, now: float, name: str, frames: list[bytes]) -> None:
        """Protocol `frames` ahead of what waits, in their order (`put` with `first`, last one first)."""
        for frame in reversed(frames):
            self.put(now, name, frame, first=True)

    def waiting(self, frame: bytes) -> bool:
        """This protocol (or user) frame still waits here: it has not gone to the link yet."""
        return bool(self._waiting.get(_key(frame)))

    def _forget(self, key: tuple[int, int, int, bytes]) -> None:
        self._waiting.pop(key, None)

    # -- out -----------------------------------------------------------------------------------
    def _refill(self, now: float) -> None:
        if self._at is not None and self.budget:
            self.tokens = min(float(self.burst), self.tokens + (now - self._at) * self.budget)
        self._at = now

    def pull(self, now: float, space: int) -> bytes | None:
        if not self.has_data(now):
            return None
        if self.protocol:
            key, frame = self.protocol.popleft()
            self._forget(key)
        elif self.slots:
            _, (frame, _) = self.slots.popitem(last=False)  # the longest waiting
        else:
            key, frame = self.user.popleft()
            self._forget(key)
        self.tokens -= len(frame)
        self.stats.sent += 1
        self.stats.sent_bytes += len(frame)
        return frame

    def has_data(self, now: float) -> bool:
        """Something waits and the budget lets it go now."""
        self._refill(now)
        return bool(self.protocol or self.slots or self.user) and (not self.budget or self.tokens > 0)

    def deadline(self, now: float) -> float | None:
        if not (self.protocol or self.slots or self.user):
            return None
        self._refill(now)
        if not self.budget or self.tokens > 0:
            return now
        return now + (1.0 - self.tokens) / self.budget

    @property
    def waiting_bytes(self) -> int:
        return (sum(len(f) for _, f in self.protocol) + sum(len(f) for f, _ in self.slots.values())
                + sum(len(f) for _, f in self.user))

    def __len__(self) -> int:
        return len(self.protocol) + len(self.slots) + len(self.user)
