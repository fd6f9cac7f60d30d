"""The onboard end's streams to ground stations over DTT, fitted to a share of the downlink.

Each stream message type has one slot: the newest frame waits there (an older one still waiting
is worth nothing once a newer exists). The types leave at the rates ground stations asked for
while those fit `budget_Bps`; when they need more, every type but HEARTBEAT (always at its own
1 Hz: link-loss detection depends on it) is slowed by the same factor, and `interval_us` says the
interval actually kept, for the MESSAGE_INTERVAL answers. Pulled as a bulk source of the DTT
scheduler (the tablet's commands, acks and file control go first), never more than the budget
over any second.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

HEARTBEAT_ID = 0
EARLY = 0.9  # a type may leave after this fraction of its interval (generation jitter is not a reason to skip one)
GUESS = 40  # bytes of a frame not yet sent once


class StreamFit:
    """`asked(msgid)`: the interval in seconds ground stations asked for (None: off). `encode`
    makes a message a frame as it leaves (so that the frames on the link have consecutive
    sequence numbers, and a gap the ground station sees is a loss, not a replaced frame)."""

    def __init__(self, budget_Bps: float | None, asked: Callable[[int], float | None],
                 encode: Callable[[Any], bytes]) -> None:
        self.budget = budget_Bps
        self.asked = asked
        self.encode = encode
        self.slots: dict[int, tuple[Any, float]] = {}  # msgid -> (message, when put)
        self.sizes: dict[int, int] = {}  # msgid -> its last frame's length
        self.last_sent: dict[int, float] = {}
        self.tokens = 0.0
        self._at = 0.0
        self.sent = 0
        self.replaced = 0  # frames a newer one overtook while waiting

    # -- in ------------------------------------------------------------------------------------
    def put(self, now: float, msgid: int, msg: Any) -> None:
        if msgid in self.slots:
            self.replaced += 1
        self.slots[msgid] = (msg, now)
        self.sizes.setdefault(msgid, GUESS)

    # -- the fit -------------------------------------------------------------------------------
    def factor(self) -> float:
        """1, or what the asked-for rates are slowed by so that they fit the budget."""
        if not self.budget:
            return 1.0
        need, fixed = 0.0, 0.0
        for msgid, size in self.sizes.items():
            interval = self.asked(msgid)
            if interval is None or interval <= 0:
                continue
            if msgid == HEARTBEAT_ID:
                fixed += size / interval
            else:
                need += size / interval
        room = max(self.budget - fixed, 0.0)
        return 1.0 if need <= room else room / need

    def interval(self, msgid: int, factor: float | None = None) -> float | None:
        """Seconds between frames of `msgid` actually sent (None: off); `factor`: factor(), if known."""
        asked = self.asked(msgid)
        if asked is None or asked <= 0 or msgid == HEARTBEAT_ID:
            return asked
        f = self.factor() if factor is None else factor
        return asked / f if f > 0 else None

    def interval_us(self, msgid: int, asked_us: float) -> float:
        """For MESSAGE_INTERVAL: the interval kept on this link, in µs (-1 off, as asked if unknown)."""
        if asked_us <= 0 or msgid not in self.sizes:
            return asked_us
        kept = self.interval(msgid)
        return -1 if kept is None else max(asked_us, kept * 1e6)

    # -- out -----------------------------------------------------------------------------------
    def _refill(self, now: float) -> None:
        if self.budget:
            burst = max(100.0, self.budget * 0.25)
            self.tokens = min(burst, self.tokens + (now - self._at) * self.budget)
        self._at = now

    def _due(self, now: float) -> dict[int, float]:
        """When each waiting type may leave (the fit computed once, not once per type)."""
        f = self.factor()
        due = {}
        for msgid in self.slots:
            kept = self.interval(msgid, f)
            if kept is not None:
                last = self.last_sent.get(msgid)
                due[msgid] = now if last is None else last + EARLY * kept
        return due

    def _eligible(self, now: float) -> list[int]:
        return [msgid for msgid, t in self._due(now).items() if t <= now]

    def pull(self, now: float, space: int) -> bytes | None:
        self._refill(now)
        ready = sorted(self._eligible(now), key=lambda m: self.slots[m][1])  # longest waiting first
        for msgid in ready:
            msg, _ = self.slots[msgid]
            if self.budget and self.tokens < min(self.sizes[msgid], 100):
                return None  # (a frame that does not fit `space` waits in the scheduler for the next packet)
            del self.slots[msgid]
            frame = self.encode(msg)
            self.sizes[msgid] = len(frame)
            self.last_sent[msgid] = now
            self.tokens -= len(frame)
            self.sent += 1
            return frame
        return None

    def has_data(self, now: float) -> bool:
        return bool(self._eligible(now))

    def deadline(self, now: float) -> float | None:
        """When the next waiting frame may leave (its interval, or the budget's tokens)."""
        times = list(self._due(now).values())
        if not times:
            return None
        t = min(times)
        if self.budget and self.tokens < 100:
            t = max(t, now + (100 - self.tokens) / self.budget)
        return t
