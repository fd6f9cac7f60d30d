"""The bridge's ground-station side: who is connected where, under which ids their frames are
carried, where the vehicle's answers go, and the RADIO_STATUS each gets.

A ground station is a (link, address) the bridge heard valid frames from, with the (sysid,
compid) it sends as; one on a link that sends to a fixed address (udpout) is reached there before
it says anything (QGroundControl and MAVProxy listen and answer the source). A ground station
using the tablet's own ids (255/190, QGroundControl's default) is carried under the highest free
system id below 255, so that the onboard end tells it from the tablet; the vehicle's answers to
that id get the ground station's own back.
"""

from __future__ import annotations

from collections import OrderedDict, deque
from collections.abc import Hashable
from dataclasses import dataclass, field

from .classes import TABLET

FORGET = 30.0  # s: a ground station silent this long is no longer one (its address may be reused)
QUALITY_WINDOW = 5.0  # s of the vehicle's frames behind RADIO_STATUS's quality
SILENT = 3.5  # s without a frame from the vehicle: quality 0 (QGroundControl's link-loss figure)
MAX_STATIONS = 32


@dataclass
class Station:
    link: Hashable
    address: Hashable
    ids: set[tuple[int, int]] = field(default_factory=set)
    last: float = 0.0
    frames: int = 0


class Routes:
    def __init__(self, vehicle_sysid: int, tablet: tuple[int, int] = TABLET) -> None:
        self.vehicle = vehicle_sysid
        self.tablet = tablet
        self.stations: OrderedDict[tuple[Hashable, Hashable], Station] = OrderedDict()
        # (station, its ids) -> the ids it is carried under on the DTT link, and back
        self.carried_as: dict[tuple[tuple[Hashable, Hashable], tuple[int, int]], tuple[int, int]] = {}
        self._own: dict[tuple[int, int], tuple[tuple[Hashable, Hashable], tuple[int, int]]] = {}
        self.fixed: list[Hashable] = []  # links that send to a fixed address (udpout): always reached
        # the vehicle's frames over DTT, for RADIO_STATUS: (time, received, lost) per arrival
        self._seq: dict[int, int] = {}
        self._window: deque[tuple[float, int]] = deque()  # (time, frames lost just before this one)
        self.lost = 0
        self.received = 0
        self.heard_vehicle: float | None = None

    # -- ground stations -------------------------------------------------------------------------
    def heard(self, now: float, link: Hashable, address: Hashable, src: tuple[int, int]) -> tuple[int, int]:
        """A valid frame from `src` at (link, address), to be carried; returns the ids to carry it
        under (a station is recorded only once it sends something the bridge carries)."""
        key = (link, address)
        st = self.stations.get(key)
        if st is None:
            st = self.stations[key] = Station(link, address)
            while len(self.stations) > MAX_STATIONS:
                gone, _ = self.stations.popitem(last=False)
                for carried in [c for c, (k, _) in self._own.items() if k == gone]:
                    del self._own[carried]
                    self.carried_as.pop((gone, self.tablet), None)
        else:
            self.stations.move_to_end(key)
        st.ids.add(src)
        st.last = now
        st.frames += 1
        return self._carry(key, src)

    def _carry(self, key: tuple[Hashable, Hashable], src: tuple[int, int]) -> tuple[int, int]:
        """Each station using the tablet's own ids gets a system id of its own (two QGroundControls
        at once do not get each other's answers)."""
        if src != self.tablet:
            return src
        got = self.carried_as.get((key, src))
        if got is None:
            used = {s for st in self.stations.values() for s, _ in st.ids} | {s for s, _ in self._own}
            sysid = next((n for n in range(254, 0, -1) if n not in used and n != self.vehicle), 254)
            got = self.carried_as[(key, src)] = (sysid, src[1])
            self._own[got] = (key, src)
        return got

    def live(self, now: float) -> list[Station]:
        return [st for st in self.stations.values() if now - st.last < FORGET]

    def destinations(self, now: float, target: tuple[int, int] | None) -> tuple[list[tuple[Hashable, Hashable]],
                                                                                tuple[int, int] | None]:
        """Where a frame from the vehicle goes: [(link, address or None = the link's fixed peer)],
        and the target ids to write back into it (a remapped station's own), or None."""
        live = self.live(now)
        if target is None or target[0] == 0:
            out = [(st.link, st.address) for st in live]
            out += [(link, None) for link in self.fixed if not any(st.link is link for st in live)]
            return out, None
        mapped = self._own.get(target) or (self._own.get((target[0], self.tablet[1])) if target[1] == 0 else None)
        if mapped is not None:
            key, own = mapped
            st = self.stations.get(key)
            return ([(st.link, st.address)] if st is not None and now - st.last < FORGET else []), own
        if target == self.tablet or (target[1] == 0 and target[0] == self.tablet[0] and not any(
                s == target[0] and c != self.tablet[1] for st in live for s, c in st.ids)):
            return [], None  # the tablet's own (its stations with those ids are carried as others)
        hits = [(st.link, st.address) for st in live
                if any(s == target[0] and (target[1] == 0 or c == target[1]) for s, c in st.ids)]
        return hits, None

    # -- the vehicle's side, for RADIO_STATUS ------------------------------------------------------
    def vehicle_frame(self, now: float, compid: int, seq: int) -> None:
        last = self._seq.get(compid)
        gap = 0 if last is None else (seq - last - 1) & 0xFF
        if gap > 128:  # behind the newest: one counted lost came late after all (or a restart)
            if self.lost > 0 and gap != 255:
                self.lost -= 1
                for i in range(len(self._window) - 1, -1, -1):
                    t, g = self._window[i]
                    if g > 0:
                        self._window[i] = (t, g - 1)
                        break
            gap = 0
        else:
            self._seq[compid] = seq
        self.lost += gap
        self.received += 1
        self.heard_vehicle = now
        self._window.append((now, gap))
        while self._window and now - self._window[0][0] > QUALITY_WINDOW:
            self._window.popleft()

    def quality(self, now: float) -> int:
        """0..254: the share of the vehicle's frames that arrived over the last seconds."""
        if self.heard_vehicle is None or now - self.heard_vehicle > SILENT:
            return 0
        got = [g for t, g in self._window if now - t <= QUALITY_WINDOW]
        if not got:
            return 0
        return round(254 * len(got) / (len(got) + sum(got)))
