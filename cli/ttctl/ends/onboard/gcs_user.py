"""The user's own messages from ground stations, sans-IO: which reach the plugins, and what is
counted and said once instead of delivered.

A ground station may send any message of the end's dialect; those that plugins handle are
delivered to them (node.py), each station at most RATE a second on average (BURST at once):
beyond that they are shed, so a station flooding its own messages costs the vehicle's protocol
(HEARTBEAT, commands, parameters) nothing but the parsing. A message id the dialect lacks (its
CRC cannot be checked, so it is never delivered) and a handler that raises are counted and named
once each, never a crash.
"""

from __future__ import annotations

from collections import OrderedDict
from collections.abc import Callable, Hashable
from dataclasses import dataclass

RATE = 100.0  # user messages a second per station, delivered to plugins
BURST = 50
MAX_TOLD = 32  # distinct things said once (message ids, handlers): then only counted
MAX_PEERS = 64


@dataclass
class UserStats:
    delivered: int = 0  # handed to plugins
    shed: int = 0  # over a station's RATE: not delivered
    unknown: int = 0  # frames of message ids the dialect lacks
    failed: int = 0  # handler calls that raised
    replies: int = 0  # plugins' answers sent to one station


class UserTraffic:
    def __init__(self, log: Callable[[str], None], rate: float = RATE, burst: int = BURST) -> None:
        self.log = log
        self.rate = rate
        self.burst = float(burst)
        self.stats = UserStats()
        self._buckets: OrderedDict[Hashable, tuple[float, float]] = OrderedDict()  # peer -> (tokens, at)
        self._told: set[Hashable] = set()

    def _once(self, key: Hashable) -> bool:
        if key in self._told or len(self._told) >= MAX_TOLD:
            return False
        self._told.add(key)
        return True

    def admit(self, now: float, peer: Hashable, name: str) -> bool:
        """May this station's user message `name` go to the plugins now? (counted either way)"""
        tokens, at = self._buckets.pop(peer, (self.burst, now))
        tokens = min(self.burst, tokens + (now - at) * self.rate)
        ok = tokens >= 1.0
        self._buckets[peer] = (tokens - 1.0 if ok else tokens, now)
        while len(self._buckets) > MAX_PEERS:
            self._buckets.popitem(last=False)
        if ok:
            self.stats.delivered += 1
            return True
        self.stats.shed += 1
        if self._once(("shed", peer)):
            self.log(f"ground station {_who(peer)} sends its own messages ({name}...) faster than "
                     f"{self.rate:g} a second: the rest are not delivered to plugins (counted, said once; "
                     "the vehicle's HEARTBEAT and commands go on)")
        return False

    def unknown_id(self, where: str, msgid: int | None, dialect: str, frames: int) -> None:
        self.stats.unknown += frames
        if self._once(("unknown", msgid)):
            what = f"message id {msgid}" if msgid is not None else "a message id"
            self.log(f"{where}: {what} is not in the dialect this end speaks ({dialect}): not delivered "
                     f"(its CRC cannot be checked; start the end with --dialect naming the dialect that "
                     f"defines it; counted, said once)")

    def failed(self, where: str, name: str, e: BaseException) -> None:
        self.stats.failed += 1
        if self._once(("failed", where, type(e).__name__)):
            self.log(f"plugin {where} failed on {name}: {type(e).__name__}: {e} (the node keeps running; "
                     f"said once, counted)")

    def summary(self) -> str:
        s = self.stats
        return (f"ground stations' own messages: {s.delivered} delivered to plugins, {s.replies} answers, "
                f"{s.shed} shed (over {self.rate:g}/s), {s.unknown} not in the dialect, {s.failed} handler failures")


def _who(peer: Hashable) -> str:
    if isinstance(peer, tuple) and len(peer) == 2 and all(isinstance(x, int) for x in peer):
        return f"{peer[0]}/{peer[1]}"
    return str(peer)


def msgid_of(data: bytes) -> int | None:
    """The message id of a MAVLink 2 frame at the start of `data` (one datagram), or None."""
    if len(data) >= 10 and data[0] == 0xFD:
        return data[7] | data[8] << 8 | data[9] << 16
    return None
