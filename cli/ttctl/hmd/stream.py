"""Streaming poses over the link: TT_VR_POSE and TT_VR_CONTROLLER, newest sample wins.

The headset makes ~90 poses a second and each controller 250, about 40 KB/s as TT_VR_POSE
frames; DJI's uplink carries about 1 KB/s, shared with commands and files. So samples are not
queued: a `PoseStream` keeps, per device, only the newest sample not yet sent (an older one is
*superseded*), and the link's scheduler pulls from it when a packet may leave, after commands
and telemetry (a command never waits behind a pose). What leaves is therefore as fresh as the
link allows. The exception is a controller's buttons: every change of a button (a trigger click,
a pad press) is queued and sent in order, never superseded, because a press that vanishes is a
different command; only axis-only changes (trigger travel, thumb on the pad) are newest-wins.
On a lossy link a change is resent until the onboard end confirms it (NAMED_VALUE_INT
"vrbtn<index>" = its packet_num, see ttctl.ends.onboard.vr_controller), one change in flight
per controller (so they arrive in order), resent after 2.5 round trips (measured from changes
confirmed at their first send; `rto` s until then), backing off to `RTO_MAX`; while a
change is unconfirmed the controller's axis-only messages wait, so the onboard end never sees
its buttons change but through a change it confirms.

Which device goes next is weighted-fair: on a saturated link the headset (it steers the orbit
camera) gets twice the share of a controller's pose; base stations, which do not move, go at
most every 5 s. `max_hz` caps each device on a fast link (LAN, Wi-Fi).

Sans-IO: `offer()` samples, `pull(now, space)` messages, `on_ack(index, packet_num)` the onboard
end's confirmations; counts in `stats` (taken = sent + superseded + `held()`).
"""

from __future__ import annotations

import math
from collections import deque
from dataclasses import dataclass
from typing import Any

from ..wire.bindings import Bindings
from ..wire.contract import TtVrButtons, TtVrDevice, TtVrPoseFlags, TtVrRole
from .model import BUTTONS, ControllerSample, PoseSample, Sample

KIND_CODES = {"hmd": TtVrDevice.TT_VR_DEVICE_HMD, "controller": TtVrDevice.TT_VR_DEVICE_CONTROLLER,
              "tracker": TtVrDevice.TT_VR_DEVICE_TRACKER,
              "base_station": TtVrDevice.TT_VR_DEVICE_TRACKING_REFERENCE}
ROLE_CODES = {"none": TtVrRole.TT_VR_ROLE_NONE, "left": TtVrRole.TT_VR_ROLE_LEFT,
              "right": TtVrRole.TT_VR_ROLE_RIGHT}
BUTTON_BITS = {"trigger_click": TtVrButtons.TT_VR_BUTTONS_TRIGGER,
               "pad_touched": TtVrButtons.TT_VR_BUTTONS_PAD_TOUCHED,
               "pad_pressed": TtVrButtons.TT_VR_BUTTONS_PAD_PRESSED, "menu": TtVrButtons.TT_VR_BUTTONS_MENU,
               "grip": TtVrButtons.TT_VR_BUTTONS_GRIP}
WEIGHT = {"hmd": 1.0, "controller": 2.0, "tracker": 2.0}  # relative interval: the headset most often
STATIC_INTERVAL = 5.0  # s between two sends of a base station's pose
RTO = 1.0  # s before an unconfirmed button change is first resent, until round trips are measured
RTO_MIN = 0.3  # s
RTO_MAX = 2.0  # s: the back-off's ceiling
ACK_PREFIX = "vrbtn"  # NAMED_VALUE_INT.name of a confirmation: vrbtn<controller index>


def ack_name(index: int) -> str:
    return f"{ACK_PREFIX}{index & 0xFF}"


def pose_message(b: Bindings, s: PoseSample) -> Any:
    flags = (TtVrPoseFlags.TT_VR_POSE_FLAGS_VALID if s.valid else 0) | \
        (TtVrPoseFlags.TT_VR_POSE_FLAGS_CONNECTED if s.connected else 0)
    return b.TtVrPose(time_usec=int(s.t * 1e6), device=int(KIND_CODES[s.device.kind]),
                      role=int(ROLE_CODES.get(s.device.role, 0)), index=s.device.index & 0xFF, flags=int(flags),
                      position=list(s.position), orientation=list(s.orientation), velocity=list(s.velocity),
                      angular_velocity=list(s.angular_velocity))


def button_bits(s: ControllerSample) -> int:
    return sum(int(BUTTON_BITS[b]) for b in BUTTONS if s.buttons.get(b))


def controller_message(b: Bindings, s: ControllerSample) -> Any:
    return b.TtVrController(time_usec=int(s.t * 1e6), packet_num=s.packet & 0xFFFFFFFF,
                            index=s.device.index & 0xFF, role=int(ROLE_CODES.get(s.device.role, 0)),
                            trigger=s.trigger, pad_x=s.pad_x, pad_y=s.pad_y, buttons=button_bits(s))


@dataclass
class StreamStats:
    taken: int = 0  # samples offered
    sent: int = 0  # samples that left (pulled into a packet; a resent button change counts once)
    superseded: int = 0  # samples replaced by a newer one before they could leave
    buttons: int = 0  # button changes offered (none is ever superseded)
    confirmed: int = 0  # button changes the onboard end confirmed
    resent: int = 0  # extra sends of unconfirmed button changes

    def as_dict(self) -> dict[str, int]:
        return {"taken": self.taken, "sent": self.sent, "superseded": self.superseded, "button_changes": self.buttons,
                "confirmed": self.confirmed, "resent": self.resent}


class _Changes:
    """One controller's button changes: the first in flight until confirmed, the rest waiting."""

    __slots__ = ("due", "first", "queue", "rto", "sends")

    def __init__(self) -> None:
        self.queue: deque[ControllerSample] = deque()
        self.due = -math.inf  # when the head may (again) leave
        self.sends = 0  # of the head
        self.first = 0.0  # when the head first left
        self.rto = RTO


class _Slot:
    __slots__ = ("interval", "last_sent", "pending", "virtual", "weight")

    def __init__(self, interval: float, weight: float, virtual: float) -> None:
        self.pending: Sample | None = None
        self.last_sent = -math.inf
        self.interval = interval  # at most one send per interval (max_hz; a base station's 5 s)
        self.weight = weight  # its share of a saturated link is proportional to 1 / weight
        self.virtual = virtual  # weighted-fair-queuing clock: + weight per send, least goes first


class PoseStream:
    """Newest-wins pose streaming, pulled by the link's scheduler (see the module's docstring)."""

    def __init__(self, bindings: Bindings, max_hz: float = 30.0, rto: float = RTO) -> None:
        if not max_hz > 0:
            raise ValueError("max_hz must be positive")
        self.b = bindings
        self.min_interval = 1.0 / max_hz
        self.rto = rto
        self.srtt: float | None = None  # smoothed round trip of a button change and its confirmation
        self.now = 0.0
        self.stats = StreamStats()
        self._slots: dict[tuple[str, int], _Slot] = {}
        self._changes: dict[int, _Changes] = {}
        self._last_bits: dict[int, int] = {}

    def unconfirmed(self) -> int:
        """Button changes offered and not (yet) confirmed by the onboard end."""
        return sum(len(c.queue) for c in self._changes.values())

    def held(self) -> int:
        """Samples taken that never left: waiting in a slot, or button changes never sent."""
        return sum(s.pending is not None for s in self._slots.values()) + \
            sum(len(c.queue) - (1 if c.sends else 0) for c in self._changes.values())

    def on_ack(self, index: int, packet_num: int) -> bool:
        """The onboard end confirmed controller `index`'s change `packet_num`: the next may leave."""
        c = self._changes.get(index & 0xFF)
        if c is None or not c.queue or c.sends == 0 or (c.queue[0].packet & 0xFFFFFFFF) != packet_num & 0xFFFFFFFF:
            return False
        c.queue.popleft()
        if c.sends == 1:  # Karn: only a change sent once times the round trip unambiguously
            rtt = max(self.now - c.first, 0.0)
            self.srtt = rtt if self.srtt is None else 0.8 * self.srtt + 0.2 * rtt
            self.rto = min(max(2.5 * self.srtt, RTO_MIN), RTO_MAX)
        c.due, c.sends, c.rto = -math.inf, 0, self.rto
        self.stats.confirmed += 1
        return True

    def offer(self, s: Sample) -> None:
        self.stats.taken += 1
        if isinstance(s, ControllerSample):
            bits = button_bits(s)
            if bits != self._last_bits.get(s.device.index, 0):
                self._last_bits[s.device.index] = bits
                axes = self._slots.get(("axes", s.device.index))
                if axes is not None and axes.pending is not None:  # the queued change carries newer axes
                    axes.pending = None
                    self.stats.superseded += 1
                self._changes.setdefault(s.device.index & 0xFF, _Changes()).queue.append(s)
                self.stats.buttons += 1
                return
            key: tuple[str, int] = ("axes", s.device.index)
            interval, weight = self.min_interval, 2.0
        else:
            key = ("pose", s.device.index)
            static = s.device.kind == "base_station"
            interval = STATIC_INTERVAL if static else self.min_interval
            weight = WEIGHT.get(s.device.kind, 2.0)
        slot = self._slots.get(key)
        if slot is None:  # a newcomer starts level with the least served, not ahead of everyone
            start = min((x.virtual for x in self._slots.values()), default=0.0)
            slot = self._slots[key] = _Slot(interval, weight, start)
        if slot.pending is not None:
            self.stats.superseded += 1
        slot.pending = s

    def _ready(self, key: tuple[str, int], slot: _Slot, now: float) -> bool:
        if slot.pending is None or now < slot.last_sent + slot.interval:
            return False
        c = self._changes.get(key[1] & 0xFF) if key[0] == "axes" else None
        return c is None or not c.queue  # a controller's axes wait while a button change is unconfirmed

    def _due_change(self, now: float) -> _Changes | None:
        due = [c for c in self._changes.values() if c.queue and now >= c.due]
        return min(due, key=lambda c: c.due) if due else None

    def has_data(self, now: float) -> bool:
        """Something may leave now."""
        return self._due_change(now) is not None or any(self._ready(k, s, now) for k, s in self._slots.items())

    def deadline(self, now: float) -> float | None:
        """When a held sample becomes due, if later than now (has_data says what is due now)."""
        times = [t for k, s in self._slots.items()
                 if s.pending is not None and (t := s.last_sent + s.interval) > now and self._ready(k, s, t)]
        times += [c.due for c in self._changes.values() if c.queue and c.due > now]
        return min(times) if times else None

    def pull(self, now: float, space: int) -> Any:
        """The next message to send, or None: button changes first (new or due again), then the
        most overdue slot."""
        self.now = now
        c = self._due_change(now)
        if c is not None:
            s = c.queue[0]
            if c.sends == 0:
                self.stats.sent += 1
                c.first = now
                c.rto = self.rto
            else:
                self.stats.resent += 1
                c.rto = min(c.rto * 1.5, RTO_MAX)
            c.sends += 1
            c.due = now + c.rto
            return controller_message(self.b, s)
        best: _Slot | None = None
        for key, slot in self._slots.items():
            if self._ready(key, slot, now) and (best is None or slot.virtual < best.virtual):
                best = slot
        if best is None or best.pending is None:
            return None
        held: Sample = best.pending
        best.pending = None
        best.last_sent = now
        best.virtual += best.weight
        self.stats.sent += 1
        return pose_message(self.b, held) if isinstance(held, PoseSample) else controller_message(self.b, held)
