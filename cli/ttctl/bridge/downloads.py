"""Mission downloads through the bridge, prefetched: the ground station asks for each item and
waits for it, a round trip over DTT per item. When the vehicle's MISSION_COUNT for a ground
station comes down, the bridge asks the vehicle for the items itself (as that ground station, a
window ahead of it), holds them as they come, and answers the station's requests from them at
once; a request for one not held goes up as the station sent it (or waits for the one asked
for less than a round trip ago). Every item the station gets is the vehicle's own.
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
    carried as `who` to the vehicle, ready to go up."""

    def __init__(self, request: Callable[[tuple[int, int], int, int], bytes], window: int = WINDOW) -> None:
        self.request = request
        self.window = window
        self.downloads: dict[tuple[int, int], _Download] = {}
        self.answered = 0  # station requests answered from what the bridge held

    def _ahead(self, now: float, who: tuple[int, int], d: _Download) -> list[bytes]:
        out = []
        for seq in range(max(0, d.wanted), min(d.count, d.wanted + 1 + self.window)):
            if seq not in d.cache and seq not in d.asked:
                d.asked[seq] = now
                out.append(self.request(who, seq, d.mission_type))
        return out

    def from_vehicle(self, now: float, msg: Any, who: tuple[int, int] | None) -> tuple[bool, list[bytes]]:
        """A vehicle's frame for the station carried as `who`: (pass it on?, requests to send up)."""
        if who is None:
            return True, []
        for key in [k for k, d in self.downloads.items() if now - d.last > STALE]:
            del self.downloads[key]
        name = msg.NAME
        if name == "MISSION_COUNT":
            self.downloads.pop(who, None)
            if 0 < msg.count <= 1000:
                new = self.downloads[who] = _Download(int(msg.count), int(msg.mission_type), last=now)
                return True, self._ahead(now, who, new)
            return True, []
        d = self.downloads.get(who)
        if d is None or name not in ITEMS or getattr(msg, "mission_type", 0) != d.mission_type:
            return True, []
        d.last = now
        if name == "MISSION_ITEM_INT" and 0 <= msg.seq < d.count:
            d.cache[int(msg.seq)] = msg
        if msg.seq in d.waiting:
            d.waiting.discard(msg.seq)
            return True, []
        return name != "MISSION_ITEM_INT", []  # held for the station's request

    def from_gcs(self, now: float, msg: Any, who: tuple[int, int]) -> tuple[bool, list[Any], list[bytes]]:
        """A station's frame: (send it up?, items to answer it with now, requests to send up)."""
        name = msg.NAME
        if name in ("MISSION_REQUEST_LIST", "MISSION_ACK", "MISSION_COUNT", "MISSION_CLEAR_ALL"):
            self.downloads.pop(who, None)  # a new download, or the end of this one
            return True, [], []
        d = self.downloads.get(who)
        if d is None or name not in ("MISSION_REQUEST_INT", "MISSION_REQUEST") or msg.mission_type != d.mission_type:
            return True, [], []
        seq = int(msg.seq)
        d.last = now
        d.wanted = max(d.wanted, seq)
        more = self._ahead(now, who, d)
        held = d.cache.get(seq)
        if held is not None and name == "MISSION_REQUEST_INT":
            self.answered += 1
            return False, [held], more
        d.waiting.add(seq)
        asked = d.asked.get(seq)
        if asked is not None and now - asked < ON_ITS_WAY and name == "MISSION_REQUEST_INT":
            return False, [], more  # on its way
        d.asked[seq] = now
        return True, [], more
