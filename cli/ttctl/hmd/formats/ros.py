"""The ROS messages of a pose stream, decided once for both ROS 1 (.bag) and ROS 2 (.mcap), and
the way back from those messages to samples (replay).

`RosWriter` decides, per sample, which messages to send; each format (mcapfile, bagfile) encodes
and stores them in its hooks, with the struct-based codecs of `codecs` (rosbags' message
objects were too slow for the recording budget; rosbags still supplies the schemas and md5sums).
Topics (F = the device's tf frame: hmd, controller_left, tracker_<serial>, ...):

  /tf                tf2_msgs/TFMessage          one transform per valid pose of a moving device,
                                                  parent_frame -> F
  /tf_static         tf2_msgs/TFMessage          latched: every base station's transform, sent
                                                  again when one appears or moves (> 0.1 mm or
                                                  ~0.01 deg), as tf2's static broadcaster does
  /vr/F/pose         geometry_msgs/PoseStamped   every valid pose, frame_id parent_frame
  /vr/F/twist        geometry_msgs/TwistStamped  its velocities (linear m/s, angular rad/s), same
  /vr/F/joy          sensor_msgs/Joy             a controller's inputs in vive_ros's layout:
                                                  axes [pad_x, pad_y, trigger], buttons [menu,
                                                  trigger_click, pad_pressed, grip, pad_touched]
                                                  (recording version 1: axes [trigger, pad_x,
                                                  pad_y], buttons [trigger_click, pad_touched,
                                                  pad_pressed, menu, grip]); frame_id F; OpenVR's
                                                  packet number rides in ROS 1's header.seq and
                                                  in the MCAP message's sequence field; where a
                                                  tool dropped them (0), replay numbers each
                                                  controller's messages in order
  /vr/recording      std_msgs/String             JSON, latched, once: {"format", "version",
                                                  "frame", "parent_frame", "meta"}
  /vr/devices        std_msgs/String             JSON, when a device appears or its role, serial,
                                                  validity or connection changes:
                                                  {"index", "kind", "role", "serial", "frame",
                                                   "valid", "connected"} (valid/connected null
                                                  when a controller's input names a device no
                                                  pose has described yet)
Invalid poses never reach /tf or the pose topics (garbage must not enter a robot's tf tree);
the change to invalid is on /vr/devices, so replay gives one invalid sample (zero numbers) where
an invalid stretch starts (or its connection/role changes). Stamps = log times = sample time.
Joy axes are float32 in ROS: replay returns them to float32 precision.
"""

from __future__ import annotations

import json
import math
from functools import cache
from typing import Any

from ttctl.errors import Fail

from ..model import BUTTONS, JOY_BUTTONS, KINDS, ROLES, ControllerSample, Device, PoseSample, Sample
from .base import Writer
from .codecs import JOY, POSE, STRING, TF, TWIST

TYPES = (TF, POSE, TWIST, JOY, STRING)
DEVICES_TOPIC = "/vr/devices"
INFO_TOPIC = "/vr/recording"  # the recording's header, in a message (what tools that rewrite files keep)
TF_TOPIC, TF_STATIC_TOPIC = "/tf", "/tf_static"
STATIC_TOLERANCE = 1e-4  # metres, and quaternion components (~0.01 deg)
LEAVES = {"pose": POSE, "twist": TWIST, "joy": JOY}  # /vr/F/<leaf>: the type each carries

# Noetic's store lacks tf2_msgs (rosbags ships what ROS 1 core had); its definition is one line
_TF_MSG = "geometry_msgs/TransformStamped[] transforms"
_NS = 1_000_000_000
VERSION = 2  # of ROS recordings: 2 has vive_ros's Joy layout, 1 had ours


def to_ns(t: float) -> int:
    """Seconds to integer nanoseconds, rounded exactly (t * 1e9 in floats is off by up to 128 ns
    at today's epoch times; the whole and fractional seconds are converted apart instead)."""
    if not (0 <= t < math.inf):  # NaN fails this too
        raise Fail(f"sample time {t!r} cannot be stored in a ROS recording (seconds since 1970 expected)")
    whole = math.floor(t)
    return whole * _NS + round((t - whole) * 1e9)


def from_ns(ns: int) -> float:
    return ns / _NS  # int / int: correctly rounded


def device_json(d: Device, valid: bool | None, connected: bool | None) -> str:
    """The /vr/devices message of a device."""
    return json.dumps({"index": d.index, "kind": d.kind, "role": d.role, "serial": d.serial, "frame": d.frame,
                       "valid": valid, "connected": connected}, separators=(",", ":"))


@cache
def typestore(ros_version: int) -> Any:
    """rosbags' Humble store (ROS 2, CDR) or Noetic's with tf2_msgs/TFMessage added (ROS 1)."""
    from rosbags.typesys import Stores, get_types_from_msg, get_typestore

    if ros_version == 2:
        return get_typestore(Stores.ROS2_HUMBLE)
    store = get_typestore(Stores.ROS1_NOETIC)
    if TF not in store.types:
        store.register(get_types_from_msg(_TF_MSG, TF))
    return store


def recording_info(frame: str, parent_frame: str, meta: dict[str, Any]) -> dict[str, Any]:
    return {"format": "ttctl.hmd", "version": VERSION, "frame": frame, "parent_frame": parent_frame, "meta": meta}


class Dev:
    """What a writer keeps per device: its frame and topics; each format adds its channels and
    encoders as attributes of its own (lazily, when the device's first message of a kind is
    written; channels are per topic, which devices of one frame share)."""

    def __init__(self, device: Device) -> None:
        self.device = device
        self.frame = device.frame
        self.static = device.kind == "base_station"
        self.pose_topic = f"/vr/{self.frame}/pose"
        self.twist_topic = f"/vr/{self.frame}/twist"
        self.joy_topic = f"/vr/{self.frame}/joy"
        self.ready = False  # pose/tf encoders made
        self.joy_ready = False


class RosWriter(Writer):
    """Samples to ROS messages, for both ROS formats: remembers what /vr/devices and /tf_static
    last said, and calls the format's hooks (`_devices`, `_moving`, `_posed`, `_tf_static`,
    `_joy`) with the stamp in nanoseconds. The hot path (a valid pose of a device already seen)
    is a few dict lookups and one hook call."""

    def __init__(self, parent_frame: str) -> None:
        super().__init__()
        self.parent = parent_frame
        self._by_index: dict[int, Dev] = {}  # the last Dev seen at each OpenVR index
        self._devs: dict[Device, Dev] = {}
        self._announced: dict[int, tuple[Device, bool | None, bool | None]] = {}
        self._static: dict[str, tuple[tuple[float, ...], tuple[Any, ...]]] = {}  # frame -> (pose, transform)

    def write(self, s: Sample) -> None:
        if self._done:
            raise RuntimeError("write() after close() or abort()")
        d = s.device
        index = d.index
        dev = self._by_index.get(index)
        if dev is None or (dev.device is not d and dev.device != d):
            dev = self._dev(d)
        ns = to_ns(s.t)
        last = self._announced.get(index)
        if isinstance(s, PoseSample):
            valid, connected = bool(s.valid), bool(s.connected)
            if last is None or last[0] is not d or last[1] is not valid or last[2] is not connected:
                state = (d, valid, connected)
                if state != last:  # not just another Device object equal to the last
                    self._announce(state, ns)
            if not valid:
                return
            if dev.static:
                self._base_station(dev, ns, s)
            else:
                self._moving(dev, ns, s)
            return
        if last is None or (last[0] is not d and last[0] != d):  # validity unknown until a pose says
            self._announce((d, None, None), ns)
        self._joy(dev, ns, s)

    def _dev(self, d: Device) -> Dev:
        dev = self._devs.get(d)
        if dev is None:
            dev = self._devs[d] = Dev(d)
        self._by_index[d.index] = dev
        return dev

    def _announce(self, state: tuple[Device, bool | None, bool | None], ns: int) -> None:
        d, valid, connected = state
        self._announced[d.index] = state
        self._devices(ns, device_json(d, valid, connected))

    def _base_station(self, dev: Dev, ns: int, s: PoseSample) -> None:
        pose = (*s.position, *s.orientation)
        seen = self._static.get(dev.frame)
        if seen is None or any(not abs(a - b) <= STATIC_TOLERANCE for a, b in zip(seen[0], pose, strict=True)):
            sec, nsec = divmod(ns, _NS)
            self._static[dev.frame] = (pose, (0, sec, nsec, self.parent, dev.frame, pose))
            self._tf_static(ns, [x[1] for x in self._static.values()])
        self._posed(dev, ns, s)

    # the format's hooks ---------------------------------------------------------------------

    def _devices(self, ns: int, text: str) -> None:
        """A /vr/devices message."""
        raise NotImplementedError

    def _moving(self, dev: Dev, ns: int, s: PoseSample) -> None:
        """/tf, then /vr/F/pose and /vr/F/twist, of a valid pose."""
        raise NotImplementedError

    def _posed(self, dev: Dev, ns: int, s: PoseSample) -> None:
        """/vr/F/pose and /vr/F/twist only (base stations: their tf is on /tf_static)."""
        raise NotImplementedError

    def _tf_static(self, ns: int, transforms: list[tuple[Any, ...]]) -> None:
        """/tf_static with these (seq, sec, nanosec, frame_id, child_frame_id, 7 numbers)."""
        raise NotImplementedError

    def _joy(self, dev: Dev, ns: int, s: ControllerSample) -> None:
        """/vr/F/joy (OpenVR's packet number in the sequence / header.seq)."""
        raise NotImplementedError


# ---------------------------------------------------------------------------------------------- replay


class Rebuilder:
    """Samples again from a ROS recording's messages, fed in log-time order: devices from
    /vr/devices, a pose sample from /vr/F/pose plus /vr/F/twist of the same stamp, a controller
    sample from /vr/F/joy, an invalid sample where /vr/devices says a device became invalid.
    Each feed method appends the samples it completes to `out`, which the caller empties."""

    def __init__(self, where: str, version: int = VERSION) -> None:
        self.where = where  # the file, for messages
        self.version = version  # of the recording: the Joy layout
        self._packets: dict[str, int] = {}  # by frame: the last packet number given
        self.out: list[Sample] = []
        # by frame: (device, valid, connected) as /vr/devices last said; (ns, pose or None, twist
        # or None) of a pose or twist waiting for its other half (public for mcapreplay's fast path)
        self.devices_by_frame: dict[str, tuple[Device, bool | None, bool | None]] = {}
        self.pending: dict[str, tuple[int, Any, Any]] = {}
        self._devices, self._pending = self.devices_by_frame, self.pending

    @staticmethod
    def route(topic: str) -> tuple[str, str] | None:
        """(leaf, frame) of a /vr/F/{pose,twist,joy} topic, ("devices", "") for /vr/devices, None
        for the rest (/tf, /tf_static and anything else: all that replay needs is above)."""
        if topic == DEVICES_TOPIC:
            return "devices", ""
        parts = topic.split("/")
        if len(parts) != 4 or parts[0] or parts[1] != "vr" or parts[3] not in LEAVES:
            return None
        return parts[3], parts[2]

    def _device(self, frame: str, topic: str) -> tuple[Device, bool | None, bool | None]:
        state = self._devices.get(frame)
        if state is None:
            raise Fail(f"{self.where}: {topic!r} comes before /vr/devices names the device {frame!r}: "
                       "not a ttctl recording, or a damaged one")
        return state

    def joy(self, frame: str, ns: int, sequence: int, axes: Any, buttons: Any) -> None:
        device = self._device(frame, f"/vr/{frame}/joy")[0]
        if len(axes) < 3 or len(buttons) < len(BUTTONS):
            raise Fail(f"{self.where}: '/vr/{frame}/joy' at {from_ns(ns):.6f}: {len(axes)} axes and {len(buttons)} "
                       f"buttons, expected 3 and {len(BUTTONS)}")
        if not sequence:  # dropped by a tool (rosbags-convert, ROS 2's Header has no seq): in order instead
            sequence = self._packets.get(frame, 0) + 1
        self._packets[frame] = sequence
        if self.version >= 2:
            self.out.append(ControllerSample(from_ns(ns), device, sequence, float(axes[2]), float(axes[0]),
                                             float(axes[1]), {b: bool(v) for b, v in
                                                              zip(JOY_BUTTONS, buttons, strict=False)}))
            return
        self.out.append(ControllerSample(from_ns(ns), device, sequence, float(axes[0]), float(axes[1]),
                                         float(axes[2]), {b: bool(v) for b, v in zip(BUTTONS, buttons, strict=False)}))

    def pose(self, frame: str, ns: int, values: tuple[float, ...]) -> None:
        """The 7 numbers of a PoseStamped (position, orientation)."""
        state = self._devices.get(frame) or self._device(frame, f"/vr/{frame}/pose")
        pending = self._pending.get(frame)
        if pending is not None and pending[0] != ns:
            self._flush(frame)
            pending = None
        if pending is not None and pending[2] is not None:
            del self._pending[frame]
            self._sample(state, ns, values, pending[2])
        else:
            self._pending[frame] = (ns, values, None)

    def twist(self, frame: str, ns: int, values: tuple[float, ...]) -> None:
        """The 6 numbers of a TwistStamped (linear, angular)."""
        state = self._devices.get(frame) or self._device(frame, f"/vr/{frame}/twist")
        pending = self._pending.get(frame)
        if pending is not None and pending[0] != ns:
            self._flush(frame)
            pending = None
        if pending is not None and pending[1] is not None:
            del self._pending[frame]
            self._sample(state, ns, pending[1], values)
        else:
            self._pending[frame] = (ns, None, values)

    def _sample(self, state: tuple[Device, bool | None, bool | None], ns: int, pose: tuple[float, ...],
                twist: tuple[float, ...] | None) -> None:
        self.out.append(PoseSample(from_ns(ns), state[0], True, state[2] is not False, pose[0:3], pose[3:7],
                                   twist[0:3] if twist is not None else (0.0, 0.0, 0.0),
                                   twist[3:6] if twist is not None else (0.0, 0.0, 0.0)))

    def _flush(self, frame: str) -> None:
        pending = self._pending.pop(frame, None)
        if pending is not None and pending[1] is not None:  # a pose without its twist (a twist alone is dropped)
            self._sample(self._device(frame, f"/vr/{frame}/pose"), pending[0], pending[1], pending[2])

    def finish(self) -> None:
        for frame in list(self._pending):
            self._flush(frame)

    def devices(self, ns: int, text: str) -> None:
        try:
            obj = json.loads(text)
            kind, role, index = obj["kind"], obj["role"], obj["index"]
            device = Device(int(index), str(kind), str(role), str(obj["serial"]))
            valid, connected = obj["valid"], obj["connected"]
            flags_ok = all(v is None or isinstance(v, bool) for v in (valid, connected))
            if kind not in KINDS or role not in ROLES or not isinstance(index, int) or not flags_ok:
                raise ValueError(f"bad value in {text!r}")
        except (ValueError, KeyError, TypeError, RecursionError) as e:
            raise Fail(f"{self.where}: bad /vr/devices message at {from_ns(ns):.6f}: {e}") from None
        self._devices[device.frame] = (device, valid, connected)
        if valid is False:
            self.out.append(PoseSample(from_ns(ns), device, False, connected is not False))


__all__ = ["DEVICES_TOPIC", "LEAVES", "TYPES", "Dev", "Rebuilder", "RosWriter", "device_json", "from_ns",
           "recording_info", "to_ns", "typestore"]
