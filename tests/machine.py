"""How busy the machine running the tests is, for the tests whose bounds are wall-clock times.

A protocol bound ("a command's round trip stays within its idle p95 + 200 ms while a flood runs")
holds on an idle machine by the protocol's design; on a machine where other work (the other
xdist workers, a build, a browser) takes the cores, every process also waits for a core, and
the tail of a handful of samples grows with that wait, not with anything the protocol does.
Such bounds are scaled by `busy()`: the load average per core, at least 1 (1 on an idle
machine, so there the bound is exactly the one the README states). Medians and counts are not
scaled: they are what the tests judge the protocol by.
"""

from __future__ import annotations

import os


def busy() -> float:
    """The machine's 1-minute load average per core, at least 1 (at most 4: beyond that a run
    says nothing of the protocol and should fail loudly)."""
    try:
        load = os.getloadavg()[0]
    except OSError:  # not available: assume idle
        return 1.0
    return min(4.0, max(1.0, load / (os.cpu_count() or 1)))


def scaled(seconds: float) -> float:
    """A wall-clock allowance (a wait, a tail bound) stretched by how busy the machine is."""
    return seconds * busy()
