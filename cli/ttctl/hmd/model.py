"""The samples every part of `ttctl.hmd` exchanges: a device's pose, and a controller's state.

Times are seconds since the UNIX epoch (float). Positions in metres, quaternions (x, y, z, w)
in ROS order, unit length, sign-continuous per device. Which axes the numbers are in (the
stream's *frame*: "ros" for REP-103, "openvr" raw) is a property of the stream, not of each
sample: sources make OpenVR samples, `frames.to_ros` converts them.
"""

from __future__ import annotations

from dataclasses import dataclass, field

Vec3 = tuple[float, float, float]
Quat = tuple[float, float, float, float]  # x, y, z, w

KINDS = ("hmd", "controller", "tracker", "base_station")
ROLES = ("none", "left", "right")
FRAMES = ("ros", "openvr")
# Joy buttons, in the order ROS Vive nodes publish them (sensor_msgs/Joy.buttons)
BUTTONS = ("trigger_click", "pad_touched", "pad_pressed", "menu", "grip")
# sensor_msgs/Joy as vive_ros (github.com/robosavvy/vive_ros, vive_node.cpp) publishes a Vive
# controller: buttons [menu, trigger, pad pressed, grip], axes [pad x, pad y, trigger]; what
# vive_ros lacks (the pad touched) comes after its four
JOY_BUTTONS = ("menu", "trigger_click", "pad_pressed", "grip", "pad_touched")


@dataclass(frozen=True, slots=True)
class Device:
    """One tracked device as OpenVR names it: its index (0..63), class, role and serial."""

    index: int
    kind: str  # one of KINDS
    role: str = "none"  # one of ROLES: controllers only
    serial: str = ""

    @property
    def frame(self) -> str:
        """Its tf frame: hmd, controller_left/right, tracker_<serial>, base_station_<serial>
        (a controller without a hand is controller_<serial>)."""
        if self.kind == "hmd":
            return "hmd"
        if self.kind == "controller":
            hand = self.role if self.role in ("left", "right") else _safe(self.serial, self.index)
            return f"controller_{hand}"
        return f"{self.kind}_{_safe(self.serial, self.index)}"


def _safe(serial: str, index: int) -> str:
    """A serial as a tf frame / topic name part: [A-Za-z0-9_] only (`LHB-1234` -> `LHB_1234`)."""
    s = "".join(c if c.isalnum() else "_" for c in serial)
    return s if s else str(index)


@dataclass(slots=True)
class PoseSample:
    """Where a device is: its pose in the parent (world) frame and its velocities there."""

    t: float
    device: Device
    valid: bool = True  # OpenVR's bPoseIsValid: the numbers are meaningless when False
    connected: bool = True  # bDeviceIsConnected
    position: Vec3 = (0.0, 0.0, 0.0)
    orientation: Quat = (0.0, 0.0, 0.0, 1.0)
    velocity: Vec3 = (0.0, 0.0, 0.0)
    angular_velocity: Vec3 = (0.0, 0.0, 0.0)


@dataclass(slots=True)
class ControllerSample:
    """A controller's inputs when its state changed (OpenVR's unPacketNum moved on)."""

    t: float
    device: Device
    packet: int = 0
    trigger: float = 0.0  # 0..1
    pad_x: float = 0.0  # -1..1
    pad_y: float = 0.0
    buttons: dict[str, bool] = field(default_factory=lambda: dict.fromkeys(BUTTONS, False))

    @property
    def axes(self) -> list[float]:
        """sensor_msgs/Joy axes: [trigger, pad_x, pad_y]."""
        return [self.trigger, self.pad_x, self.pad_y]

    @property
    def button_list(self) -> list[int]:
        """[trigger_click, pad_touched, pad_pressed, menu, grip] (JSONL, CSV order)."""
        return [int(bool(self.buttons.get(b, False))) for b in BUTTONS]

    @property
    def joy_axes(self) -> list[float]:
        """sensor_msgs/Joy axes as vive_ros publishes them: [pad_x, pad_y, trigger]."""
        return [self.pad_x, self.pad_y, self.trigger]

    @property
    def joy_buttons(self) -> list[int]:
        """sensor_msgs/Joy buttons as vive_ros publishes them, then ours: [menu, trigger_click,
        pad_pressed, grip, pad_touched]."""
        return [int(bool(self.buttons.get(b, False))) for b in JOY_BUTTONS]


Sample = PoseSample | ControllerSample
