"""Mission uploads through the bridge, pipelined: the items cross the slow link back to back,
not one round trip each.

The mission protocol asks for each item and waits for it: over DTT that is a round trip of
about 0.2 s per item, and a lost item costs the vehicle's retry time. The bridge instead asks the
ground station for the items itself (MISSION_REQUEST_INT as the vehicle would, in order), as fast
as the uplink takes them (AHEAD items waiting in its queue, not a count ahead of the vehicle's
requests, which come a round trip late and are lost too), sends each up as it comes, and answers
the vehicle's requests from what it holds: a first request for an item already sent is swallowed
(the item is on its way), a repeated one (the item was lost) sends it again. The onboard end keeps
items that come ahead of one it asked for (onboard/missions.py).

The station's clock: a station gives up when it is asked for nothing for a while (QGroundControl
1.5 s; MAVSDK counts 0.5 s timeouts to 4, and a request for its next item starts it afresh), and
once it has given its last item only the verdict stops that clock. So the bridge asks no further
than WINDOW items ahead of the vehicle's requests (more than the link holds in a round trip) and
the last item only when the vehicle is LAST_AHEAD items from the end: the items it has not asked
for are a reserve, one of which it asks for whenever KEEP_ALIVE seconds passed without a request,
while the vehicle waits for a lost one. (Asking the station again for an item it gave does not
serve: MAVSDK counts that as one of its retries, and the answer could reach the vehicle after its
verdict and bring a second one, which MAVSDK takes as the end of its next upload: PROTOCOL_ERROR.)
A vehicle's request for an item the bridge never asked the station for, or one that comes just
after the verdict, is a late one of an earlier upload: swallowed. The upload's
result is the vehicle's own MISSION_ACK, passed on as it comes: the bridge never acknowledges
anything itself.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

AHEAD = 2  # items waiting in the uplink queue: the station is asked for the next when fewer wait
WINDOW = 10  # items asked for ahead of the vehicle's requests, at most (but see KEEP_ALIVE)
KEEP_ALIVE = 1.0  # s without a request to the station: it is asked for its next item anyway
LAST_AHEAD = 3  # the last item is asked for once the vehicle is this many items from it
LOST_AFTER = 0.6  # s after an item was queued: a first request for it means it was lost (it takes 0.3 s at most)
RESEND_GAP = 0.3  # s: an item sent again is not sent again for a request that comes sooner (one in flight)
COUNT_AGAIN = 0.6  # s without a request from the vehicle after the count: it was lost, send it again
COUNT_TRIES = 5
ACK_WAIT = 0.6  # s after the vehicle asked for the last item without a MISSION_ACK: it is sent again
ACK_TRIES = 4
ECHO_WINDOW = 3.0  # s after an upload's verdict in which the vehicle's answers to the bridge's resends come
STALE = 15.0  # s without a word of an upload: it is over (the ground station gave up)
UPLOAD = ("MISSION_ITEM_INT", "MISSION_ITEM")
REQUESTS = ("MISSION_REQUEST_INT", "MISSION_REQUEST")


@dataclass
class _Upload:
    count: int
    mission_type: int
    cache: dict[int, bytes] = field(default_factory=dict)  # seq -> the item's frame as carried
    next_ask: int = 0  # the next item to ask the ground station for
    waiting: bool = False  # asked for next_ask - 1, not had yet
    wanted: int = -1  # the highest item the vehicle has asked for
    asks: dict[int, int] = field(default_factory=dict)  # how often the vehicle asked for each
    unsent: set[int] = field(default_factory=set)  # held but to be sent again (the count was repeated)
    last: float = 0.0
    count_frame: bytes = b""
    count_sent: float = 0.0
    count_tries: int = 1
    last_again: int = 0  # times the last item went again (the vehicle may answer each with its verdict)
    resent_at: dict[int, float] = field(default_factory=dict)  # seq -> when it last went again
    sent_at: dict[int, float] = field(default_factory=dict)  # seq -> when the station's item was queued
    station_asked: float = 0.0  # when the bridge last asked the station for an item (or it sent its count)


class MissionRelay:
    """`request(carried_ids, seq, mission_type)` makes the MISSION_REQUEST_INT for a ground station
    (as from the vehicle's autopilot); the caller sends it to the station that uses those ids."""

    def __init__(self, request: Callable[[tuple[int, int], int, int], Any], ahead: int = AHEAD,
                 waiting: Callable[[bytes], bool] = lambda frame: False, window: int = WINDOW) -> None:
        self.request = request
        self.ahead = ahead
        self.window = window
        self.waiting = waiting  # whether a frame still waits in the uplink queue (it has not gone yet)
        self.uploads: dict[tuple[int, int], _Upload] = {}
        self.echoes: dict[tuple[int, int], tuple[int, int, float]] = {}  # who -> (type, acks to swallow, since)
        self.verdicts: dict[tuple[int, int], tuple[int, float]] = {}  # who -> (type, when) of the latest verdict
        self.resent = 0
        self.swallowed = 0

    def _expire(self, now: float) -> None:
        for key in [k for k, u in self.uploads.items() if now - u.last > STALE]:
            del self.uploads[key]
        for key in [k for k, (_, when) in self.verdicts.items() if now - when > ECHO_WINDOW]:
            del self.verdicts[key]

    def _prefetch(self, now: float, who: tuple[int, int], up: _Upload) -> list[Any]:
        while up.next_ask in up.cache:  # (a station that sent one unasked)
            up.next_ask += 1
        k = up.next_ask
        if up.waiting or k >= up.count:
            return []
        if sum(1 for f in up.cache.values() if self.waiting(f)) >= self.ahead:
            return []  # the uplink has enough to do: asked for when it has taken some
        if (k > up.wanted + self.window or (k == up.count - 1 and up.wanted < up.count - 1 - LAST_AHEAD)) \
                and now - up.station_asked < KEEP_ALIVE:
            return []  # the vehicle is behind: held back, the station's clock not yet near its end
        up.waiting = True
        up.station_asked = now
        up.next_ask += 1
        return [self.request(who, k, up.mission_type)]

    def ahead_requests(self, now: float) -> list[tuple[tuple[int, int], Any]]:
        """Requests for the ground stations now (who, request): the next items, as the uplink
        takes them."""
        return [(who, req) for who, up in self.uploads.items() for req in self._prefetch(now, who, up)]

    # -- from a ground station ----------------------------------------------------------------------
    def from_gcs(self, now: float, msg: Any, who: tuple[int, int], frame: bytes) -> list[Any]:
        """A ground station's frame (carried as `who`, going up as `frame`): returns requests to
        send it back."""
        self._expire(now)
        name = msg.NAME
        if name == "MISSION_COUNT":
            up = self.uploads.get(who)
            if up is not None and (up.count, up.mission_type) == (msg.count, msg.mission_type) and not up.cache:
                # the count again before any item: a retry (it goes up as it is); once items were sent
                # an equal count is a new upload (the ground station started over), never the old items
                self._count_again(now, up)
                return []
            if msg.count == 0:
                self.uploads.pop(who, None)
                return []
            up = self.uploads[who] = _Upload(msg.count, msg.mission_type, last=now, count_frame=frame,
                                             count_sent=now, station_asked=now)
            self.verdicts.pop(who, None)
            return self._prefetch(now, who, up)
        if name in UPLOAD:
            up = self.uploads.get(who)
            if up is None or msg.mission_type != up.mission_type or not 0 <= msg.seq < up.count:
                return []
            up.cache[msg.seq] = frame
            up.sent_at[msg.seq] = now  # (queued for the link now)
            up.last = now
            if msg.seq == up.next_ask - 1:
                up.waiting = False
            return self._prefetch(now, who, up)
        if name == "MISSION_CLEAR_ALL":
            self.uploads.pop(who, None)
        return []

    def _count_again(self, now: float, up: _Upload) -> None:
        """The count goes again: the vehicle may have missed it, and with it what followed."""
        up.unsent = set(up.cache)
        up.asks.clear()
        up.count_sent = now
        up.count_tries += 1
        up.last = now

    def tick(self, now: float) -> list[bytes]:
        """Frames to send up again now, in order, ahead of what waits: a count the vehicle did not
        answer (it was lost, or its answer was: either way the vehicle starts the upload afresh
        when it comes, and every item sent before it is to go again, right behind it, as the first
        time), or the last item when no MISSION_ACK came for it."""
        out = []
        for up in self.uploads.values():
            # the vehicle has asked for the last item, or every item has gone up (pipelined, the
            # vehicle need ask for none of them): its verdict is due
            verdict_due = (up.wanted == up.count - 1 or len(up.cache) == up.count) and up.count - 1 in up.cache
            if up.wanted < 0 and not up.asks and self.waiting(up.count_frame):
                up.count_sent = now  # the count has not gone yet: its wait for an answer starts when it goes
            elif up.wanted < 0 and not up.asks and now - up.count_sent >= COUNT_AGAIN and up.count_tries < COUNT_TRIES:
                self._count_again(now, up)
                out.append(up.count_frame)
                for seq in sorted(up.unsent):
                    if not self.waiting(up.cache[seq]):  # (one still waiting stays where it is: behind it)
                        out.append(up.cache[seq])
                        up.sent_at[seq] = now
                up.unsent.clear()
            elif verdict_due and any(self.waiting(f) for f in up.cache.values()):
                up.last = now  # items still queued for the link: the wait for the verdict starts when they left
            elif verdict_due and now - up.last >= ACK_WAIT and up.last_again < ACK_TRIES:
                # and nothing came since: an item or the MISSION_ACK was lost (the station, its items
                # all given, waits and sends nothing: MAVSDK then says TIMEOUT of an upload the
                # vehicle stored). The last item again, which the vehicle answers with its verdict
                # again, or with a request for one it lacks
                up.last_again += 1
                up.last = now
                out.append(up.cache[up.count - 1])
        return out

    # -- from the vehicle -----------------------------------------------------------------------------
    def from_vehicle(self, now: float, msg: Any, who: tuple[int, int] | None) -> tuple[bool, list[bytes], list[Any]]:
        """A vehicle's frame for the ground station carried as `who` (None: not for one):
        (pass it on?, frames to send up again, requests for the ground station)."""
        if who is None:
            return True, [], []
        echo = self.echoes.get(who)
        if echo is not None and msg.NAME == "MISSION_ACK":
            kind, left, since = echo
            fresh = self.uploads.get(who)
            if msg.mission_type == kind and now - since < ECHO_WINDOW and left > 0 and (
                    fresh is None or (fresh.wanted < 0 and not fresh.asks)):  # (not a verdict on a newer upload)
                # the vehicle's verdict again, for a last item the bridge sent again (the station sent it
                # once): the station has its verdict, and to it this one would end its next upload
                # (MAVSDK: PROTOCOL_ERROR). Swallowed.
                self.echoes[who] = (kind, left - 1, since)
                self.swallowed += 1
                return False, [], []
        up = self.uploads.get(who)
        name = msg.NAME
        if up is None:
            verdict = self.verdicts.get(who)
            if (name in REQUESTS and verdict is not None and msg.mission_type == verdict[0]
                    and now - verdict[1] < ECHO_WINDOW):
                self.swallowed += 1  # the vehicle's request sent before its verdict, come after it
                return False, [], []
            return True, [], []
        if name in REQUESTS and msg.mission_type == up.mission_type:
            seq = int(msg.seq)
            if seq > up.next_ask:  # never asked of the station, so never sent: an earlier upload's
                self.swallowed += 1
                return False, [], []
            up.last = now
            up.wanted = max(up.wanted, seq)
            n = up.asks[seq] = up.asks.get(seq, 0) + 1
            again: list[bytes] = []
            frame = up.cache.get(seq)
            # lost on the way: asked for again, or first asked for long after it went up (the link
            # keeps order: what went after it has come, or will before a resend would)
            overdue = frame is not None and not self.waiting(frame) and now - up.sent_at.get(seq, now) >= LOST_AFTER
            if frame is not None and (n > 1 or overdue or seq in up.unsent) and (
                    seq in up.unsent or now - up.resent_at.get(seq, -1e9) >= RESEND_GAP):  # once more
                again.append(up.cache[seq])
                up.unsent.discard(seq)
                up.resent_at[seq] = now
                self.resent += 1
                if seq == up.count - 1:
                    up.last_again += 1  # (the vehicle may answer each send of the last item with its verdict)
            self.swallowed += 1
            return False, again, self._prefetch(now, who, up)
        if name == "MISSION_ACK" and msg.mission_type == up.mission_type:
            del self.uploads[who]  # the vehicle's verdict, passed on as it is
            self.verdicts[who] = (up.mission_type, now)
            if up.last_again:  # the last item went again: the vehicle may answer each send of it
                self.echoes[who] = (up.mission_type, up.last_again, now)
        return True, [], []
