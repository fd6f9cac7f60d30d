"""A model of one direction of the DTT link, in terms of packets and seconds.

The model is a single-server queue: the SDK's send buffer (a few packets; a packet arriving
to a full buffer is dropped silently), drained by the radio at the profile's rate with DJI's
pacing, then loss (random or Gilbert-Elliott bursts), corruption, duplication, reordering and
outages, then a fixed latency. Everything is computed from the packet's submission time, so
the same object serves the virtual clock (tests, benchmarks) and the real-time relay.

Bursts live in time, not in packets: the Gilbert-Elliott chain steps once per *slot*, the time
the radio needs for one full packet (service_time(mtu)), and between two packets it advances by
the slots that elapsed, so a burst lasts burst_mean slots whether the flow is saturated or one
ack a second. On a saturated link a slot is a packet, so burst_mean is still "the mean run of
lost packets" there. (The two-state burst-noise channel of E. N. Gilbert, "Capacity of a
burst-noise channel", Bell System Technical Journal 39(5), 1960, here with every packet lost in
the bad state and none in the good.)
"""

from __future__ import annotations

import itertools
import math
import random
import tomllib
from dataclasses import dataclass, field
from importlib import resources
from typing import Any

DIRECTIONS = ("up", "down")
LOSS_MODELS = ("random", "burst")


class ProfileError(ValueError):
    pass


def _interp(points: list[list[float]], x: float) -> float:
    pts = sorted((float(a), float(b)) for a, b in points)
    if x <= pts[0][0]:
        return pts[0][1]
    for (x0, y0), (x1, y1) in itertools.pairwise(pts):
        if x <= x1:
            return y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    return pts[-1][1]


def _number(v: Any) -> bool:
    return isinstance(v, int | float) and not isinstance(v, bool) and math.isfinite(v)


@dataclass(frozen=True)
class DirectionProfile:
    rate_Bps: list[list[float]]
    loss: list[list[float]]
    latency_s: float = 0.04
    queue_packets: int = 2
    queue_bytes: int = 0  # also a limit in bytes on what waits (the Payload SDK's 512-byte buffer); 0: none
    pacing_bytes: int = 0
    pacing_interval_s: float = 0.0
    advertised_Bps: float | None = None
    feedback: bool = False
    loss_model: str = "random"  # random | burst (Gilbert-Elliott)
    burst_mean: float = 3.0  # with burst: the mean run of lost packets on a saturated link, in slots (full packets)

    def check(self, where: str) -> None:
        """Refuse values the model cannot run with, naming the field (`where` says which
        profile and direction)."""
        for key, points in (("rate_Bps", self.rate_Bps), ("loss", self.loss)):
            if not isinstance(points, list) or not points or not all(
                    isinstance(p, list) and len(p) == 2 and all(_number(v) for v in p) for p in points):
                raise ProfileError(f"{where}.{key} must be a non-empty list of [metres, value] pairs")
            if any(p[0] < 0 for p in points):
                raise ProfileError(f"{where}.{key}: distances must not be negative")
        if any(p[1] <= 0 for p in self.rate_Bps):
            raise ProfileError(f"{where}.rate_Bps: rates must be positive")
        if any(not 0.0 <= p[1] <= 1.0 for p in self.loss):
            raise ProfileError(f"{where}.loss: loss must be in 0..1")
        if not (_number(self.latency_s) and self.latency_s >= 0):
            raise ProfileError(f"{where}.latency_s must be a number of seconds >= 0")
        if isinstance(self.queue_packets, bool) or not isinstance(self.queue_packets, int) or self.queue_packets < 1:
            raise ProfileError(f"{where}.queue_packets must be a whole number >= 1")
        if isinstance(self.queue_bytes, bool) or not isinstance(self.queue_bytes, int) or self.queue_bytes < 0:
            raise ProfileError(f"{where}.queue_bytes must be a whole number >= 0 (0: no byte limit)")
        if isinstance(self.pacing_bytes, bool) or not isinstance(self.pacing_bytes, int) or self.pacing_bytes < 0:
            raise ProfileError(f"{where}.pacing_bytes must be a whole number >= 0")
        if not (_number(self.pacing_interval_s) and self.pacing_interval_s >= 0):
            raise ProfileError(f"{where}.pacing_interval_s must be a number of seconds >= 0")
        if self.loss_model not in LOSS_MODELS:
            raise ProfileError(f"{where}.loss_model must be one of {', '.join(LOSS_MODELS)}, not {self.loss_model!r}")
        if not (_number(self.burst_mean) and self.burst_mean >= 1.0):
            raise ProfileError(f"{where}.burst_mean must be at least 1 packet")

    def rate_at(self, distance_m: float) -> float:
        return _interp(self.rate_Bps, distance_m)

    def loss_at(self, distance_m: float) -> float:
        return min(1.0, max(0.0, _interp(self.loss, distance_m)))

    def service_time(self, size: int, distance_m: float) -> float:
        t = size / self.rate_at(distance_m)
        if self.pacing_bytes and self.pacing_interval_s:
            t = max(t, math.ceil(size / self.pacing_bytes) * self.pacing_interval_s)
        return t


@dataclass(frozen=True)
class PipeProfile:
    """A pipeline beside the packet channel (DJI's MOP): a reliable byte stream at `rate_Bps`
    each way, delivering `latency_s` after its bytes leave."""

    rate_Bps: float
    latency_s: float = 0.02

    def check(self, where: str) -> None:
        for key, v in (("rate_Bps", self.rate_Bps), ("latency_s", self.latency_s)):
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v) or v < 0:
                raise ProfileError(f"{where}.{key} must be a finite number >= 0")
        if not 1000 <= self.rate_Bps <= 1e9:
            raise ProfileError(f"{where}.rate_Bps must be in 1000..1e9 bytes per second")


@dataclass(frozen=True)
class Profile:
    name: str
    description: str
    mtu: int
    up: DirectionProfile
    down: DirectionProfile
    pipe: PipeProfile | None = None  # a MOP pipeline beside the packets ([NAME.pipe])

    def direction(self, d: str) -> DirectionProfile:
        if d not in DIRECTIONS:
            raise ProfileError(f"direction must be 'up' or 'down', not {d!r}")
        return self.up if d == "up" else self.down

    def extrapolated(self, distance_m: float) -> str | None:
        """Words for a distance outside what the profile's rates and losses were measured at (the
        model holds the nearest measured value there), or None. A table with one point at 0 m
        is distance-independent (lan)."""
        out = []
        for d in DIRECTIONS:
            dp = self.direction(d)
            for key, points in (("rate", dp.rate_Bps), ("loss", dp.loss)):
                metres = sorted({float(m) for m, _ in points})
                if metres == [0.0] or metres[0] <= distance_m <= metres[-1]:
                    continue
                out.append(f"{d} {key} at {metres[0]:g} m" if len(metres) == 1
                           else f"{d} {key} {metres[0]:g}..{metres[-1]:g} m")
        if not out:
            return None
        return (f"profile {self.name!r} is extrapolated at {distance_m:g} m (measured: {', '.join(out)}; the "
                f"nearest measured value is held)")

    def capacity_Bps(self, direction: str, distance_m: float) -> float:
        """What the model delivers with back-to-back full packets, before loss."""
        return self.mtu / self.direction(direction).service_time(self.mtu, distance_m)


def _load_table() -> dict[str, Any]:
    text = resources.files("ttctl.link").joinpath("profiles.toml").read_text(encoding="utf-8")
    return tomllib.loads(text)


def profile_names() -> list[str]:
    return sorted(_load_table())


def load_profile(name: str | None, path: str | None = None) -> Profile:
    """A profile by name, from ttctl's profiles.toml or from `path` (a TOML file of the same
    shape, such as `ttctl link fit` writes). With a path, the name may be None when the file
    holds one profile."""
    where = "ttctl's profiles.toml"
    if path is not None:
        where = path
        from ..errors import Fail
        from ..safeio import MiB, read_capped

        try:
            table = tomllib.loads(read_capped(path, f"--profile-file {path}", MiB).decode("utf-8"))
        except Fail as e:
            raise ProfileError(str(e)) from None
        except UnicodeDecodeError as e:
            raise ProfileError(f"--profile-file {path}: not UTF-8 text (byte {e.start})") from None
        except tomllib.TOMLDecodeError as e:
            raise ProfileError(f"--profile-file {path}: not TOML: {e}") from None
        profiles = sorted(k for k, v in table.items() if isinstance(v, dict))
        if not profiles:
            raise ProfileError(f"--profile-file {path}: holds no profile (a [NAME] table with [NAME.up] and "
                               f"[NAME.down])")
        if name is None:
            if len(profiles) > 1:
                raise ProfileError(f"--profile-file {path} holds {len(profiles)} profiles: pick one with --profile "
                                   f"({', '.join(profiles)})")
            name = profiles[0]
    else:
        table = _load_table()
        if name is None:
            name = "m100"
    if name not in table or not isinstance(table[name], dict):
        known = ", ".join(sorted(k for k, v in table.items() if isinstance(v, dict)))
        raise ProfileError(f"unknown link profile {name!r} in {where} (known: {known})")
    raw = table[name]
    try:
        dirs = {}
        for d in DIRECTIONS:
            if not isinstance(raw.get(d), dict):
                raise ProfileError(f"profile {name!r} in {where} has no [{name}.{d}] table")
            dirs[d] = DirectionProfile(**raw[d])
            dirs[d].check(f"{where}: {name}.{d}")
        mtu = raw.get("mtu", 100)
        if isinstance(mtu, bool) or not isinstance(mtu, int) or not 22 <= mtu <= 255:
            raise ProfileError(f"{where}: {name}.mtu must be a whole number of bytes in 22..255 (100 on DJI's DTT, "
                               f"128 on the Payload SDK channel; 22 is the least a file-data frame needs)")
        pipe = None
        if "pipe" in raw:
            if not isinstance(raw["pipe"], dict):
                raise ProfileError(f"{where}: {name}.pipe must be a table ([{name}.pipe] with rate_Bps)")
            pipe = PipeProfile(**raw["pipe"])
            pipe.check(f"{where}: {name}.pipe")
        return Profile(name, str(raw.get("description", "")), mtu, dirs["up"], dirs["down"], pipe)
    except TypeError as e:
        field_name = str(e).rsplit(" ", 1)[-1].strip("'")
        raise ProfileError(f"{where}: profile {name!r} is malformed: unknown or missing field {field_name!r}") from None


@dataclass
class Impairments:
    """What to do to packets besides the profile's own loss. `loss` overrides the profile's
    distance-dependent loss when given."""

    loss: float | None = None
    loss_model: str | None = None  # random | burst (Gilbert-Elliott); None: the profile's
    burst_mean: float | None = None  # mean loss burst, in slots (full packets' times); None: the profile's
    corrupt: float = 0.0  # probability that a delivered packet has bytes flipped
    duplicate: float = 0.0  # probability that a delivered packet arrives twice
    reorder: float = 0.0  # probability that a packet is held back behind later ones
    outages: list[tuple[float, float]] = field(default_factory=list)  # (start, duration) in seconds

    def check(self) -> None:
        for name in ("corrupt", "duplicate", "reorder"):
            v = getattr(self, name)
            if not 0.0 <= v <= 1.0:
                raise ProfileError(f"{name} must be a probability in 0..1, not {v}")
        if self.loss is not None and not 0.0 <= self.loss < 1.0:
            raise ProfileError(f"loss must be in 0..1 (exclusive of 1), not {self.loss}")
        if self.loss_model is not None and self.loss_model not in LOSS_MODELS:
            raise ProfileError(f"loss model must be one of {', '.join(LOSS_MODELS)}, not {self.loss_model!r}")
        if self.burst_mean is not None and not self.burst_mean >= 1.0:
            raise ProfileError("mean burst length must be at least 1 packet")
        for start, length in self.outages:
            if not (start >= 0.0 and length > 0.0 and math.isfinite(start + length)):
                raise ProfileError(f"an outage needs a start >= 0 and a positive duration, not {start:g}:{length:g}")


class ChannelStats:
    __slots__ = ("bytes_delivered", "corrupted", "delivered", "duplicated", "lost", "overflow", "refused",
                 "reordered", "submitted")

    def __init__(self) -> None:
        self.submitted = 0  # packets handed to the radio
        self.refused = 0  # larger than the MTU
        self.overflow = 0  # the SDK buffer was full: dropped silently
        self.lost = 0
        self.reordered = 0
        self.corrupted = 0
        self.duplicated = 0
        self.delivered = 0  # copies delivered (duplicates count twice)
        self.bytes_delivered = 0

    def as_dict(self) -> dict[str, int]:
        return {k: getattr(self, k) for k in self.__slots__}


class Channel:
    """One direction of the link. submit() takes a packet at time t and returns when (and
    what) arrives at the far end: a list of (arrival time, packet), empty if it was lost."""

    def __init__(self, profile: Profile, direction: str, distance_m: float = 10.0,
                 impairments: Impairments | None = None, seed: int = 0) -> None:
        self.profile = profile
        self.direction = direction
        self.dir = profile.direction(direction)
        self.distance_m = distance_m
        self.imp = impairments or Impairments()
        self.imp.check()
        self.rng = random.Random(seed)
        self.stats = ChannelStats()
        self._busy_until = 0.0
        self._starts: list[float] = []  # service start times of packets waiting in the buffer
        self._sizes: list[int] = []  # and their sizes (for a buffer limited in bytes)
        self._bad = False  # Gilbert-Elliott state
        self._state_at: float | None = None  # when it was last drawn (None: never; the chain is stationary)
        self.loss_p = self.imp.loss if self.imp.loss is not None else self.dir.loss_at(distance_m)
        self.loss_model = self.imp.loss_model or self.dir.loss_model
        self.burst_mean = self.imp.burst_mean or self.dir.burst_mean

    @property
    def mtu(self) -> int:
        return self.profile.mtu

    def capacity_Bps(self) -> float:
        return self.profile.capacity_Bps(self.direction, self.distance_m)

    def service_time(self, size: int) -> float:
        return self.dir.service_time(size, self.distance_m)

    def free_at(self) -> float:
        """When the radio finishes what it has been given (what a per-packet completion
        callback would report)."""
        return self._busy_until

    def slot(self) -> float:
        """The Gilbert-Elliott chain's time step: one full packet's time on the radio."""
        return self.service_time(self.profile.mtu)

    def bad_probability(self, elapsed: float) -> float:
        """P(bad) `elapsed` seconds after the state was last drawn, given that state: the
        chain's n-step transition with n = elapsed / slot (n need not be whole; never drawn:
        the stationary share, the loss)."""
        p = self.loss_p
        if self._state_at is None:
            return p
        to_good = 1.0 / self.burst_mean  # b = P(bad -> good) per slot
        to_bad = min(1.0, p * to_good / (1.0 - p))  # a = P(good -> bad), so that a / (a + b) = p
        lam = 1.0 - to_good - to_bad  # the chain's second eigenvalue: memory left after one slot
        n = max(0.0, elapsed / self.slot())
        if lam > 0.0:
            decay = lam ** n
        else:  # memory gone within a slot (bursts no longer than random loss gives): lam^k at whole k,
            k = math.floor(n)  # straight between them
            f = n - k
            decay = (lam ** k) * (1.0 - f + f * lam)
        return p + (1.0 - p) * decay if self._bad else p - p * decay

    def _lost(self, t: float) -> bool:
        """Whether the packet on the air from time t is lost."""
        p = self.loss_p
        if p <= 0.0:
            return False
        if self.loss_model == "burst":
            if p >= 1.0:
                return True
            chance = self.bad_probability(t - self._state_at if self._state_at is not None else 0.0)
            self._bad = self.rng.random() < chance
            self._state_at = t
            return self._bad
        return self.rng.random() < p

    def _in_outage(self, t: float) -> bool:
        return any(start <= t < start + length for start, length in self.imp.outages)

    def submit(self, t: float, packet: bytes) -> list[tuple[float, bytes]]:
        st = self.stats
        st.submitted += 1
        if not packet:
            return []  # 0-byte packets are ignored
        if len(packet) > self.profile.mtu:
            st.refused += 1
            return []
        keep = [i for i, s in enumerate(self._starts) if s > t]
        self._starts = [self._starts[i] for i in keep]
        self._sizes = [self._sizes[i] for i in keep]
        start = max(t, self._busy_until)
        if start > t and (len(self._starts) >= self.dir.queue_packets or (
                self.dir.queue_bytes and sum(self._sizes) + len(packet) > self.dir.queue_bytes)):
            st.overflow += 1  # the SDK buffer is full: silently dropped
            return []
        if start > t:
            self._starts.append(start)
            self._sizes.append(len(packet))
        end = start + self.service_time(len(packet))
        self._busy_until = end
        if self._lost(start) or self._in_outage(end):
            st.lost += 1
            return []
        arrive = end + self.dir.latency_s
        if self.imp.reorder and self.rng.random() < self.imp.reorder:
            st.reordered += 1
            arrive += self.rng.uniform(1.0, 3.0) * self.service_time(self.profile.mtu)
        data = packet
        if self.imp.corrupt and self.rng.random() < self.imp.corrupt:
            st.corrupted += 1
            buf = bytearray(packet)
            for _ in range(self.rng.randint(1, 3)):
                buf[self.rng.randrange(len(buf))] ^= self.rng.randint(1, 255)
            data = bytes(buf)
        out = [(arrive, data)]
        if self.imp.duplicate and self.rng.random() < self.imp.duplicate:
            st.duplicated += 1
            out.append((arrive + 0.001, data))
        st.delivered += len(out)
        st.bytes_delivered += len(data) * len(out)
        return out
