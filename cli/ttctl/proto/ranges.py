"""Sets of byte ranges [start, end), kept sorted and merged."""

from __future__ import annotations

import bisect
from collections.abc import Iterable, Iterator


class RangeSet:
    __slots__ = ("_ends", "_starts")

    def __init__(self, ranges: Iterable[tuple[int, int]] = ()) -> None:
        self._starts: list[int] = []
        self._ends: list[int] = []
        for a, b in ranges:
            self.add(a, b)

    def add(self, start: int, end: int) -> None:
        if end <= start:
            return
        starts, ends = self._starts, self._ends
        i = bisect.bisect_left(ends, start)  # first range that ends at or after start
        j = bisect.bisect_right(starts, end)  # ranges from i to j-1 touch [start, end)
        if i < j:
            start = min(start, starts[i])
            end = max(end, ends[j - 1])
        starts[i:j] = [start]
        ends[i:j] = [end]

    def remove(self, start: int, end: int) -> None:
        if end <= start:
            return
        out: list[tuple[int, int]] = []
        for a, b in self:
            if b <= start or a >= end:
                out.append((a, b))
            else:
                if a < start:
                    out.append((a, start))
                if b > end:
                    out.append((end, b))
        self._starts = [a for a, _ in out]
        self._ends = [b for _, b in out]

    def __iter__(self) -> Iterator[tuple[int, int]]:
        return zip(self._starts, self._ends, strict=True)

    def __len__(self) -> int:
        return len(self._starts)

    def __bool__(self) -> bool:
        return bool(self._starts)

    def __contains__(self, x: object) -> bool:
        if not isinstance(x, int):
            return False
        i = bisect.bisect_right(self._starts, x) - 1
        return i >= 0 and x < self._ends[i]

    def covers(self, start: int, end: int) -> bool:
        i = bisect.bisect_right(self._starts, start) - 1
        return i >= 0 and self._ends[i] >= end

    def total(self) -> int:
        return sum(b - a for a, b in self)

    def prefix(self) -> int:
        """Length of the range starting at 0 (0 if none)."""
        return self._ends[0] if self._starts and self._starts[0] == 0 else 0

    def gaps(self, start: int, end: int) -> list[tuple[int, int]]:
        """The parts of [start, end) not in the set."""
        out: list[tuple[int, int]] = []
        pos = start
        for a, b in self:
            if b <= pos:
                continue
            if a >= end:
                break
            if a > pos:
                out.append((pos, min(a, end)))
            pos = max(pos, b)
            if pos >= end:
                break
        if pos < end:
            out.append((pos, end))
        return out

    def first(self) -> tuple[int, int] | None:
        return (self._starts[0], self._ends[0]) if self._starts else None

    def to_list(self) -> list[list[int]]:
        return [[a, b] for a, b in self]

    def __repr__(self) -> str:
        return f"RangeSet({list(self)})"
