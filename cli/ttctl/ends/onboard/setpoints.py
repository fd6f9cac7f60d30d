"""The tablet's set-points (DJI_POSE_STAMPED, topic SETPOINT) answered, sans-IO.

A set-point is one message with no ack of its own in the thesis dialect, so the onboard end
answers each one: flown, it echoes the set-point back to its sender (the same stamp, sec and
nsec, and topic SETPOINT: "this one is being flown"); refused, it says why in a TT_LOG warning
("set-point refused: ..."). The tablet sends a set-point again, with the same stamp, until one
of the two answers arrives; a repeat of the last stamp from a sender is answered as the first
was and not flown again (a late copy cannot undo what came after it). A stamp of 0.0 is never
taken for a repeat.
"""

from __future__ import annotations

from collections.abc import Callable, Hashable
from dataclasses import dataclass

from .vehicle import Refused


@dataclass(frozen=True)
class Answer:
    flown: bool
    words: str  # for a refusal: the vehicle's own, as said to the tablet


class SetpointDesk:
    def __init__(self) -> None:
        self._last: dict[Hashable, tuple[tuple[int, int], Answer]] = {}

    def handle(self, sender: Hashable, stamp: tuple[int, int], fly: Callable[[], None]) -> tuple[Answer, bool]:
        """Fly the set-point (`fly` raises Refused), unless it repeats the sender's last one:
        (the answer, whether it is a repeat)."""
        last = self._last.get(sender)
        if last is not None and stamp != (0, 0) and last[0] == stamp:
            return last[1], True
        try:
            fly()
            answer = Answer(True, "")
        except Refused as e:
            answer = Answer(False, f"set-point refused: {e}")
        self._last[sender] = (stamp, answer)
        return answer, False


__all__ = ["Answer", "SetpointDesk"]
