"""The link model's Gilbert-Elliott bursts live in time: the chain steps once per slot (a full
packet's time on the radio) and between two packets advances by the slots that elapsed, so a
burst lasts as long on a saturated flow as on one ack every second, and the long-run loss is
the loss whatever the flow's density. (The model once stepped per packet: on a sparse flow a
"3-packet" burst lasted seconds.)"""

from __future__ import annotations

import itertools
import math

import pytest

from ttctl.link.model import Channel, Impairments, load_profile

LOSS = 0.1
MEAN = 3.0  # packets on a saturated link = slots


def channel(seed: int) -> Channel:
    return Channel(load_profile("m100"), "up", 10.0, Impairments(loss=LOSS, loss_model="burst", burst_mean=MEAN),
                   seed=seed)


def flow(size: int, gap: float | None, packets: int, seed: int) -> tuple[list[bool], float, float]:
    """`packets` packets of `size` bytes, each `gap` s after the one before (None: back to back,
    as the radio frees): which were lost, the mean gap between their starts in slots, the slot."""
    ch = channel(seed)
    lost, t = [], 0.0
    for _ in range(packets):
        lost.append(not ch.submit(t, bytes(size)))
        t = ch.free_at() if gap is None else t + gap
    slot = ch.slot()
    return lost, t / packets / slot, slot


def burst_seconds(lost: list[bool], step_slots: float, slot: float) -> tuple[float, float]:
    """The mean burst (the chain's mean time in the bad state on a saturated link, burst_mean x
    slot) that explains the losses seen on a flow sampled every `step_slots` slots: a lost
    packet's successor is lost with q = p + (1 - p) lam^n, lam = 1 - b / (1 - p); the mean burst
    is 1 / b slots. Also the realised loss."""
    p = sum(lost) / len(lost)
    pairs = [b for a, b in itertools.pairwise(lost) if a]
    q = sum(pairs) / len(pairs)
    lam = max(1e-9, (q - p) / (1 - p)) ** (1 / step_slots)
    return slot / ((1 - p) * (1 - lam)), p


# a full packet back to back (one per slot), 20-byte acks back to back (5 a slot), one every 200 ms
# (a slot), one a second (5 slots)
FLOWS = {"saturated": (100, None), "dense acks": (20, None), "acks every 200 ms": (20, 0.2),
         "acks every second": (20, 1.0)}


@pytest.mark.parametrize("name", list(FLOWS))
def test_a_burst_lasts_the_same_time_whatever_the_flow(name: str) -> None:
    size, gap = FLOWS[name]
    lost, step, slot = flow(size, gap, 60_000, seed=5)
    assert slot == pytest.approx(0.2)  # m100 uplink at 10 m: 100 B at 500 B/s
    seconds, p = burst_seconds(lost, step, slot)
    # 60,000 packets hold about 2,000 bursts: the mean burst is known within a few per cent
    assert seconds == pytest.approx(MEAN * slot, rel=0.12), (name, seconds, p)
    assert p == pytest.approx(LOSS, abs=0.012), (name, p)


def test_saturated_runs_are_burst_mean_packets_and_sparse_acks_see_short_runs() -> None:
    """On a saturated link a burst is burst_mean packets (as the model always said); acks a
    second apart, 5 slots, mostly see a burst as one lost ack (the old model: 3 in a row, 3 s)."""
    def mean_run(lost: list[bool]) -> float:
        runs, k = [], 0
        for x in [*lost, False]:
            if x:
                k += 1
            elif k:
                runs.append(k)
                k = 0
        return sum(runs) / len(runs)

    dense, _, _ = flow(100, None, 60_000, seed=9)
    sparse, _, _ = flow(20, 1.0, 60_000, seed=9)
    assert mean_run(dense) == pytest.approx(MEAN, rel=0.08)
    # the chain after 5 slots from bad: p + (1 - p) lam^5, lam = 1 - (1/3) / 0.9
    q = LOSS + (1 - LOSS) * (1 - 1 / MEAN / (1 - LOSS)) ** 5
    assert mean_run(sparse) == pytest.approx(1 / (1 - q), rel=0.08)
    assert mean_run(sparse) < 1.3


def test_same_instant_and_memoryless_chains() -> None:
    """Elapsed time 0 keeps the state; bursts no longer than random loss's (lam <= 0) still give
    the loss in the long run and a probability in 0..1 at every fraction of a slot."""
    ch = Channel(load_profile("m100"), "up", 10.0, Impairments(loss=0.3, loss_model="burst", burst_mean=1.0),
                 seed=3)
    ch._state_at, ch._bad = 0.0, True
    assert ch.bad_probability(0.0) == 1.0
    for k in range(0, 41):
        for bad in (True, False):
            ch._bad = bad
            assert 0.0 <= ch.bad_probability(k * 0.0125) <= 1.0
    ch._bad = False
    assert ch.bad_probability(10.0) == pytest.approx(0.3, abs=1e-9)
    lost = [not ch.submit(i * 0.05, bytes(20)) for i in range(40_000)]
    assert sum(lost) / len(lost) == pytest.approx(0.3, abs=0.015)
    assert not math.isnan(ch.bad_probability(0.07))
