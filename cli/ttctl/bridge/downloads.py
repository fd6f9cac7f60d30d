"""Mission downloads through the bridge, prefetched: the ground station asks for each item and
waits for it, a round trip over DTT per item. When the vehicle's MISSION_COUNT for a ground
station comes down, the bridge asks the vehicle for the items itself (as that ground station, a
window ahead of it), holds them as they come, and answers the station's requests from them at
once. Every item the station gets is the vehicle's own.

The item a station waits for goes first: a request for one not held goes up ahead of the
prefetch (or, if the bridge's request for it still waits in the uplink, that one is moved ahead:
behind 16 prefetch requests it waited 0.6 s of a 480 B/s uplink, and QGroundControl gives an item
1.5 s); one asked for less than ON_ITS_WAY ago that has left is on its way. The link keeps order,
so an item that comes while one asked for before it has not means that request or its answer was
lost: it is asked again at once, ahead of what waits (a lost packet of prefetch requests cost the
station one round trip per item it held, and a download failed when the station's retries were
lost behind them).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

WINDOW = 16  # items asked of the vehicle ahead of the ground station's requests
ON_ITS_WAY = 0.2  # s: an item asked for this recently is coming (longer: lost, ask again; QGroundControl
# gives an item 0.25 s and five tries, so each of its tries after the first goes up: at 0.3 s every
# other one was swallowed, and three lost in a row failed a download through the Java bridge)
STALE = 15.0
ITEMS = ("MISSION_ITEM_INT", "MISSION_ITEM")


@dataclass
class _Download:
    count: int
    mission_type: int
    cache: dict[int, Any] = field(default_factory=dict)  # seq -> the vehicle's MISSION_ITEM_INT
    asked: dict[int, float] = field(default_factory=dict)  # seq -> when the bridge (or the station) asked
    waiting: set[int] = field(default_factory=set)  # items the station asked for, not given yet
    wanted: int = -1  # the highest item the station asked for
    last: float = 0.0


class DownloadRelay:
    """`request(who, seq, mission_type)`: a MISSION_REQUEST_INT frame from the ground station
    carried as `who` to the vehicle, ready to go up; `waiting(frame)`: whether an equal frame
    still waits in the uplink (has not gone to the link)."""

    def __init__(self, request: Callable[[tuple[int, int], int, int], bytes], window: int = WINDOW,
                 waiting: Callable[[bytes], bool] = lambda frame: False) -> None:
        self.request = request
        self.window = window
        self.waiting = waiting
        self.downloads: dict[tuple[int, int], _Download] = {}
        self.answered = 0  # station requests answered from what the bridge held

    def _ahead(self, now: float, who: tuple[int, int], d: _Download) -> list[bytes]:
        out = []
        for seq in range(max(0, d.wanted), min(d.count, d.wanted + 1 + self.window)):
            if seq not in d.cache and seq not in d.asked:
                d.asked[seq] = now
                out.append(self.request(who, seq, d.mission_type))
        return out

    def _lost(self, now: float, who: tuple[int, int], d: _Download, seq: int) -> list[bytes]:
        """Item `seq` came: those asked for no later and neither had nor waiting to go were lost
        (their requests or their answers), asked again, in order."""
        at = d.asked.get(seq)
        if at is None:
            return []
        out = []
        for j in sorted(k for k, t in d.asked.items() if k < seq and t <= at and k not in d.cache):
            frame = self.request(who, j, d.mission_type)
            if not self.waiting(frame):
                d.asked[j] = now
                out.append(frame)
        return out

    def from_vehicle(self, now: float, msg: Any, who: tuple[int, int] | None) -> tuple[bool, list[bytes], list[bytes]]:
        """A vehicle's frame for the station carried as `who`: (pass it on?, requests to send up
        ahead of what waits, in order; requests to send up behind it)."""
        if who is None:
            return True, [], []
        for key in [k for k, d in self.downloads.items() if now - d.last > STALE]:
            del self.downloads[key]
        name = msg.NAME
        if name == "MISSION_COUNT":
            self.downloads.pop(who, None)
            if 0 < msg.count <= 1000:
                new = self.downloads[who] = _Download(int(msg.count), int(msg.mission_type), last=now)
                return True, [], self._ahead(now, who, new)
            return True, [], []
        d = self.downloads.get(who)
        if d is None or name not in ITEMS or getattr(msg, "mission_type", 0) != d.mission_type:
            return True, [], []
        d.last = now
        seq = int(msg.seq)
        again = self._lost(now, who, d, seq)
        if name == "MISSION_ITEM_INT" and 0 <= seq < d.count:
            d.cache[seq] = msg
        if seq in d.waiting:
            d.waiting.discard(seq)
            return True, again, []
        return name != "MISSION_ITEM_INT", again, []  # held for the station's request

    def from_gcs(self, now: float, msg: Any, who: tuple[int, int]) -> tuple[bool, list[Any], list[bytes], list[bytes]]:
        """A station's frame: (send it up?, items to answer it with now, requests to send up ahead
        of what waits, requests to send up behind it)."""
        name = msg.NAME
        if name in ("MISSION_REQUEST_LIST", "MISSION_ACK", "MISSION_COUNT", "MISSION_CLEAR_ALL"):
            self.downloads.pop(who, None)  # a new download, or the end of this one
            return True, [], [], []
        d = self.downloads.get(who)
        if d is None or name not in ("MISSION_REQUEST_INT", "MISSION_REQUEST") or msg.mission_type != d.mission_type:
            return True, [], [], []
        seq = int(msg.seq)
        d.last = now
        d.wanted = max(d.wanted, seq)
        more = self._ahead(now, who, d)
        held = d.cache.get(seq)
        if held is not None and name == "MISSION_REQUEST_INT":
            self.answered += 1
            return False, [held], [], more
        d.waiting.add(seq)
        if name != "MISSION_REQUEST_INT":
            d.asked[seq] = now
            return True, [], [], more  # (legacy: answered in kind, as the station asked)
        frame = self.request(who, seq, d.mission_type)
        asked = d.asked.get(seq)
        if self.waiting(frame):
            return False, [], [frame], more  # the bridge's request for it, still waiting: moved ahead
        if asked is not None and now - asked < ON_ITS_WAY:
            return False, [], [], more  # on its way
        d.asked[seq] = now
        return False, [], [frame], more
