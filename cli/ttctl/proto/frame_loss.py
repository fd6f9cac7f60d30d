"""A sender's loss per data-frame size, measured exactly, and the size that carries most
(sender.py; sans-IO).

Each first transmission of a frame (never a repeat from the tail, which often arrives twice) was
lost if a status reports any of its bytes missing (known at once), or arrived if a status covers
them without a gap (known later when the gaps are many and each status lists a few: a status of a
burst says nothing of the regions before its own). The estimates come from the 64 latest outcomes
per frame size by the time they were sent (in the order they became known, the window would be all
arrivals at once), taken at the
pessimistic end (the Wilson upper bound: a wide frame is costly when it is lost), and a wide
frame's loss is brought back to a packet's (three packets, each of which must arrive).
"""

from __future__ import annotations

import bisect
from typing import Any

from .transfer import WIDE, wilson_upper

WINDOW = 64  # the latest outcomes per frame size the estimate comes from
LONG_WINDOW = 256  # and those the narrow frames' estimate must also allow, before going wide
MIN_OUTCOMES = 8  # before an estimate
HYSTERESIS = 0.02  # efficiency difference under which the current frame size stays


class FrameLoss:
    def __init__(self) -> None:
        self.loss: dict[str, float | None] = {"narrow": None, "wide": None}  # per-packet loss estimates
        self.long_loss: float | None = None  # narrow frames' over the longer window
        self._unclassified: list[tuple[int, int, float, str]] = []  # first sends not yet known lost or not
        # the latest first sends by the time they left: (time, lost?). A loss is known as soon as a status
        # reports the gap, an arrival only once a status covers it (later, when gaps are many and each
        # status holds a few): kept in the order they were sent, the window is not all arrivals at once
        self._outcomes: dict[str, list[tuple[float, bool]]] = {"narrow": [], "wide": []}

    def first_send(self, start: int, end: int, left: float, mode: str) -> None:
        """Bytes [start, end) left for the first time at `left`, in a frame of size `mode`."""
        self._unclassified.append((start, end, left, mode))

    def lost(self, start: int, end: int, horizon: float) -> None:
        """Bytes [start, end) are confirmed lost (a status reported them missing, and they left
        before what it can tell about): the first sends that carried them, older than `horizon`,
        were lost, whatever a later status says once they are repaired."""
        keep: list[tuple[int, int, float, str]] = []
        for rec in self._unclassified:
            s, e, when, mode = rec
            if when <= horizon and s < end and start < e:
                self._outcome(mode, when, True)
            else:
                keep.append(rec)
        self._unclassified = keep

    def _outcome(self, mode: str, when: float, lost: bool) -> None:
        window = self._outcomes[mode]
        bisect.insort(window, (when, lost))
        if len(window) > LONG_WINDOW:
            window.pop(0)

    def classify(self, horizon: float, re: int, truncated: bool, missing: list[tuple[int, int]],
                 geometry: Any, rc: int = 0, region: int = 0) -> None:
        """A status: what it says of every first send older than `horizon` (the bytes up to `rc`
        and from `region` up to `re` are known; past `re` too unless the status was `truncated`),
        `missing` the gaps it gave. A status that is one batch of several says nothing of
        [rc, region): an earlier batch gave those gaps."""
        keep: list[tuple[int, int, float, str]] = []
        for rec in self._unclassified:
            start, end, when, mode = rec
            known = when <= horizon and (end <= re or not truncated) and (end <= rc or start >= region)
            if not known:
                keep.append(rec)
                continue
            self._outcome(mode, when, any(a < end and start < b for a, b in missing))
        self._unclassified = keep
        for mode in ("narrow", "wide"):
            window = self._outcomes[mode][-WINDOW:]
            if len(window) >= MIN_OUTCOMES:
                # pessimistic: wide frames are costly
                frame_loss = wilson_upper(sum(lost for _, lost in window), len(window))
                self.loss[mode] = frame_loss if mode == "narrow" else geometry.packet_loss_from_wide(frame_loss)
        longer = self._outcomes["narrow"]
        if len(longer) > WINDOW:
            self.long_loss = wilson_upper(sum(lost for _, lost in longer), len(longer))

    def best(self, current: str, geometry: Any) -> str:
        """The frame size that carries more file bytes per link byte at the loss measured (the
        current one while the two are within HYSTERESIS; narrow before anything is known)."""
        n, w = self.loss["narrow"], self.loss["wide"]
        if current == "narrow" and n is not None and self.long_loss is not None:
            # slow to go wide, quick to come back: under bursts of loss a second without one is
            # common, and wide frames sent into the next burst are lost three packets at a time
            n = max(n, self.long_loss)
        p = w if current == "wide" and w is not None else (n if n is not None else w)
        if p is None:
            return "narrow"
        g = geometry
        eff_narrow = g.narrow_cap / g.narrow_frame * (1 - p)
        eff_wide = WIDE / g.wide_frame * g.survival_wide(p)
        better = "wide" if eff_wide > eff_narrow else "narrow"
        if better != current and abs(eff_wide - eff_narrow) < HYSTERESIS:
            return current
        return better


__all__ = ["FrameLoss"]
