"""A sender's loss per data-frame size, measured exactly, and the size that carries most
(sender.py; sans-IO).

Each first transmission of a frame, once a status covers its bytes, was lost if any of them is
reported missing; the estimates come from the last 64 outcomes per frame size, taken at the
pessimistic end (the Wilson upper bound: a wide frame is costly when it is lost), and a wide
frame's loss is brought back to a packet's (three packets, each of which must arrive).
"""

from __future__ import annotations

from typing import Any

from .transfer import WIDE, wilson_upper

WINDOW = 64  # outcomes kept per frame size
MIN_OUTCOMES = 8  # before an estimate
HYSTERESIS = 0.02  # efficiency difference under which the current frame size stays


class FrameLoss:
    def __init__(self) -> None:
        self.loss: dict[str, float | None] = {"narrow": None, "wide": None}  # per-packet loss estimates
        self._unclassified: list[tuple[int, int, float, str]] = []  # first sends not yet known lost or not
        self._outcomes: dict[str, list[bool]] = {"narrow": [], "wide": []}  # recent first sends: lost?

    def first_send(self, start: int, end: int, left: float, mode: str) -> None:
        """Bytes [start, end) left for the first time at `left`, in a frame of size `mode`."""
        self._unclassified.append((start, end, left, mode))

    def classify(self, horizon: float, re: int, truncated: bool, missing: list[tuple[int, int]],
                 geometry: Any) -> None:
        """A status: what it says of every first send older than `horizon` (the bytes up to `re`
        are known; past it too unless the status was `truncated`), `missing` the gaps it gave."""
        keep: list[tuple[int, int, float, str]] = []
        for rec in self._unclassified:
            start, end, when, mode = rec
            known = when <= horizon and (end <= re or not truncated)
            if not known:
                keep.append(rec)
                continue
            lost = any(a < end and start < b for a, b in missing)
            window = self._outcomes[mode]
            window.append(lost)
            if len(window) > WINDOW:
                window.pop(0)
        self._unclassified = keep
        for mode in ("narrow", "wide"):
            window = self._outcomes[mode]
            if len(window) >= MIN_OUTCOMES:
                frame_loss = wilson_upper(sum(window), len(window))  # pessimistic: wide frames are costly
                self.loss[mode] = frame_loss if mode == "narrow" else geometry.packet_loss_from_wide(frame_loss)

    def best(self, current: str, geometry: Any) -> str:
        """The frame size that carries more file bytes per link byte at the loss measured (the
        current one while the two are within HYSTERESIS; narrow before anything is known)."""
        n, w = self.loss["narrow"], self.loss["wide"]
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
