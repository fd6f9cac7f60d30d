"""Where `ttctl hmd dump` gets its samples: a headset through OpenVR, or a synthetic user.

Both make the same stream: `model` samples in OpenVR's axes (`frame = "openvr"`), in time
order, which the driver converts to the recording's frame. A source either keeps real time
itself (`paced`: a headset can only be read as fast as it moves) or leaves pacing to the
driver, which sleeps to each sample's `t` (so a synthetic run can also go faster than life).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Protocol

from ..model import Sample


class Source(Protocol):
    """What the `hmd dump` driver needs of a source."""

    frame: str  # the axes the samples are in: "openvr"
    paced: bool  # True: samples() blocks to real time itself; False: the driver sleeps to sample.t
    counts: dict[str, int]  # samples yielded so far, per device frame (Device.frame)

    def samples(self) -> Iterator[Sample]:
        """The samples in time order (t in UNIX seconds); ends after the source's duration (None: never)."""
        ...

    def close(self) -> None:
        """Release the device (idempotent)."""
        ...


__all__ = ["Source"]
