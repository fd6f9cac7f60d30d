"""The peers of `ttctl bench transfer`: the thesis file transfer and MAVLink FTP, run as sans-IO
ends by the same Simulation, over the same channels and seeds as ttctl's own transfer.

Both baselines time the same thing as `run_ttctl`: seconds from the moment the sender starts
until the receiver holds every byte of the file, correct; (limit, False) if that never happens.

Between each protocol and DJI's SDK sits what a straightforward bridge would do: every MAVLink
frame is cut into packets of its own (at most 100 bytes; frames never share a packet), queued,
and handed to the SDK paced at the link's capacity (the tablet only when the radio is free, as
its completion callback allows). Frames are reassembled by ttctl's packet-aware receiver, so
what is measured is each protocol, not a dispatch bug.

This module holds what both share: the end's plumbing and the simulation run; thesis.py and
mavftp.py hold the two protocols.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from ...link.model import Channel, Profile
from ...link.sim import Simulation
from ...proto.scheduler import Pacer
from ...wire.packets import PacketReceiver, packetize
from ..shipped import bindings
from ..transfer import ONBOARD, TABLET, Case, channels, pace

Message = Any  # a message of the generated bindings
MessageInfo = Any

Ids = tuple[int, int]


# -- one end: frames in their own packets, paced -------------------------------------------------

class End:
    """Node plumbing shared by the baselines (see the module documentation)."""

    def __init__(self, ids: Ids, rate_Bps: float | None, mtu: int, registry: dict[int, MessageInfo]) -> None:
        self.ids = ids
        self.encoder = bindings().encoder(*ids)
        self.rx = PacketReceiver(bindings(), registry=registry)
        self.pacer = Pacer(rate_Bps)
        self.mtu = mtu
        self.fifo: deque[bytes] = deque()
        self.frames_sent = 0
        self.packets_sent = 0

    def send(self, msg: Message) -> tuple[int, int]:
        """Queue one frame in packets of its own: (frame bytes, packets)."""
        frame = self.encoder.encode(msg)
        packets = packetize([frame], self.mtu)
        self.fifo.extend(packets)
        self.frames_sent += 1
        return len(frame), len(packets)

    # hooks
    def on_message(self, now: float, msg: Message) -> None:
        pass

    def on_time(self, now: float) -> None:
        pass

    def next_timer(self) -> float | None:
        return None

    def has_frames(self) -> bool:
        """More frames would be made on demand (refill)."""
        return False

    def refill(self, now: float) -> None:
        pass

    # the Node interface of ttctl.link.sim
    def receive(self, now: float, packet: bytes) -> None:
        for msg in self.rx.feed(packet):
            self.on_message(now, msg)
        self.on_time(now)

    def poll(self, now: float) -> bytes | None:
        self.on_time(now)
        if not self.fifo:
            self.refill(now)
        if self.fifo and self.pacer.ready(now):
            pkt = self.fifo.popleft()
            self.pacer.sent(now, len(pkt))
            self.packets_sent += 1
            return pkt
        return None

    def wakeup(self) -> float | None:
        t = self.next_timer()
        if self.fifo or self.has_frames():
            r = self.pacer.ready_at()
            t = r if t is None else min(t, r)
        return t


def targets(msg: Any, ids: Ids) -> bool:
    return getattr(msg, "target_system", None) == ids[0]


# -- runners -------------------------------------------------------------------------------------

@dataclass
class BaselineRun:
    """One simulated transfer: the benchmark's figures plus what the tests look at."""

    seconds: float
    ok: bool
    stats: dict[str, Any] = field(default_factory=dict)
    up: dict[str, int] = field(default_factory=dict)
    down: dict[str, int] = field(default_factory=dict)


def sender_receiver_ids(case: Case) -> tuple[Ids, Ids]:
    """(sender, receiver) ids."""
    return (TABLET, ONBOARD) if case.direction == "up" else (ONBOARD, TABLET)


def simulate(make: Callable[[Ids, Ids, float, float, int], tuple[End, End]], profile: Profile, distance: float,
              case: Case, seed: int, limit: float, done: Callable[[End, End], bool]
              ) -> tuple[Simulation, End, End, Channel, Channel]:
    up, down = channels(profile, distance, case, seed)
    s_ids, r_ids = sender_receiver_ids(case)
    s_rate, r_rate = (pace(up), pace(down)) if case.direction == "up" else (pace(down), pace(up))
    sender, receiver = make(s_ids, r_ids, s_rate, r_rate, profile.mtu)
    tablet, onboard = (sender, receiver) if case.direction == "up" else (receiver, sender)
    sim = Simulation(tablet, onboard, up, down)
    sim.run(limit, stop=lambda: done(sender, receiver))
    return sim, sender, receiver, up, down


def realised_loss(r: BaselineRun, case: Case) -> float:
    ch = r.up if case.direction == "up" else r.down
    return ch.get("lost", 0) / max(1, ch.get("submitted", 0))
