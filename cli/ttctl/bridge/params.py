"""Parameter lists through the bridge, completed: what the link lost of a list is read again by
the bridge, not after the ground station's own timer.

A PARAM_REQUEST_LIST is answered by a stream of PARAM_VALUEs, each with its index and the count.
Over DTT at 10 % loss a list of 21 values loses one or two, and QGroundControl asks for the
missing ones only after 3 s of silence (its ParameterManager); MAVProxy, after its own. The bridge
sees every PARAM_VALUE come down, so once the stream has been quiet for QUIET seconds it reads
each missing index itself (PARAM_REQUEST_READ by index, carried as the station that asked for
the list), a few at a time, as the station would, and again READ_AGAIN seconds after a read that
brought no answer; the vehicle's answers go down to every station
as any PARAM_VALUE does. Bounded: BOUND seconds after the list request, TRIES reads of an index,
at most BATCH at once, MAX_LISTS lists followed. Sans-IO: `request` when a station's
PARAM_REQUEST_LIST goes up, `value` for each PARAM_VALUE the vehicle sends, `tick` for the
indices to read now.
"""

from __future__ import annotations

from collections import OrderedDict
from dataclasses import dataclass, field

QUIET = 0.5  # s without a PARAM_VALUE: the list's stream has ended (what is missing was lost)
READ_AGAIN = 0.35  # s after reads without their answers: lost (a round trip is 0.12-0.3 s on the m100)
BOUND = 10.0  # s after the station's request: no more reads (its own retries go on)
TRIES = 5  # reads of one index, at most: all before QGroundControl's own, 3 s after the last value (at 3
# reads 0.7 s apart, one index of about 150 lists lost all three and the station read it itself)
BATCH = 8  # reads sent at once
MAX_LISTS = 8
MAX_COUNT = 4096  # a count above this is not followed (a stranger's; PX4 has about 1,000)


@dataclass
class _List:
    first: float
    last: float  # the latest PARAM_VALUE (or the request)
    count: int | None = None
    have: set[int] = field(default_factory=set)
    tries: dict[int, int] = field(default_factory=dict)


class ParamLists:
    def __init__(self, quiet: float = QUIET, bound: float = BOUND) -> None:
        self.quiet = quiet
        self.bound = bound
        self.lists: OrderedDict[tuple[int, int], _List] = OrderedDict()
        self.read = 0  # indices the bridge read again
        self.completed = 0  # lists that were whole only after those reads

    def request(self, now: float, who: tuple[int, int]) -> None:
        """A station (carried as `who`) asked for the whole list: followed afresh."""
        self.lists.pop(who, None)
        self.lists[who] = _List(now, now)
        while len(self.lists) > MAX_LISTS:
            self.lists.popitem(last=False)

    def value(self, now: float, index: int, count: int) -> None:
        """A PARAM_VALUE came down (every station gets it)."""
        if not 0 < count <= MAX_COUNT or not 0 <= index < count:
            return
        for lst in self.lists.values():
            lst.count = count
            lst.have.add(index)
            lst.last = now

    def tick(self, now: float) -> list[tuple[tuple[int, int], int]]:
        """(station as carried, index) to read now."""
        out: list[tuple[tuple[int, int], int]] = []
        for who in list(self.lists):
            lst = self.lists[who]
            if lst.count is not None and len(lst.have) >= lst.count:
                if lst.tries:
                    self.completed += 1
                del self.lists[who]
                continue
            if now - lst.first >= self.bound:
                del self.lists[who]
                continue
            if lst.count is None or now - lst.last < (READ_AGAIN if lst.tries else self.quiet):
                continue  # the stream goes on (or has not begun: the request's own resend covers that)
            missing = [i for i in range(lst.count) if i not in lst.have and lst.tries.get(i, 0) < TRIES][:BATCH]
            if not missing:
                del self.lists[who]
                continue
            for i in missing:
                lst.tries[i] = lst.tries.get(i, 0) + 1
                out.append((who, i))
            self.read += len(missing)
            lst.last = now  # (their answers come within a round trip; quiet again after them)
        return out
