"""A stand-in for the `openvr` module: the functions, constants and structures ttctl's OpenVR
source uses, with a scriptable set of tracked devices, so the source's logic (poses, flags,
device table, events, button bits, init errors, haptics) is tested without SteamVR.

It mimics openvr 2.12.1401's Python API: `init` returns the IVRSystem; errors are
`OpenVRError` subclasses with `error_value` and an empty `str(e)`; structures are filled in
place (`(TrackedDevicePose_t * n)()` makes the array); `getControllerState(i)` returns
`(ok, state)`; `getStringTrackedDeviceProperty` returns `str`.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable
from dataclasses import dataclass, field

DESCRIPTIONS = {108: "Hmd Not Found", 110: "Installation path could not be located",
                121: "Not starting vrserver for background app"}
IDENTITY34 = [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]]


class OpenVRError(Exception):
    """Like openvr.error_code.OpenVRError: the code in error_value, an empty message."""

    def __init__(self, error_value: int) -> None:
        super().__init__("")
        self.error_value = error_value


class TrackedPropertyError(OpenVRError):
    pass


class _Vector:
    def __init__(self, n: int) -> None:
        self.v = [0.0] * n

    def __getitem__(self, i: int) -> float:
        return self.v[i]


class _Matrix34:
    def __init__(self) -> None:
        self.m = [row[:] for row in IDENTITY34]

    def __getitem__(self, r: int) -> list[float]:
        return self.m[r]


class _Struct(type):
    """`Struct * n` is an array type: calling it makes n zeroed structures (as ctypes does)."""

    def __mul__(cls, n: int) -> Callable[[], list]:
        return lambda: [cls() for _ in range(n)]


class TrackedDevicePose_t(metaclass=_Struct):
    def __init__(self) -> None:
        self.mDeviceToAbsoluteTracking = _Matrix34()
        self.vVelocity = _Vector(3)
        self.vAngularVelocity = _Vector(3)
        self.eTrackingResult = 1
        self.bPoseIsValid = 0
        self.bDeviceIsConnected = 0


class VREvent_t:
    def __init__(self) -> None:
        self.eventType = 0
        self.trackedDeviceIndex = 0
        self.eventAgeSeconds = 0.0


class VRControllerAxis_t:
    def __init__(self, x: float = 0.0, y: float = 0.0) -> None:
        self.x, self.y = x, y


class VRControllerState_t:
    def __init__(self) -> None:
        self.unPacketNum = 0
        self.ulButtonPressed = 0
        self.ulButtonTouched = 0
        self.rAxis = [VRControllerAxis_t() for _ in range(5)]


@dataclass
class FakeDevice:
    """One tracked device's truth: what the fake IVRSystem reports for its index."""

    cls: int
    role: int = 0
    serial: str = ""
    matrix: list[list[float]] = field(default_factory=lambda: [row[:] for row in IDENTITY34])
    velocity: tuple[float, float, float] = (0.0, 0.0, 0.0)
    angular_velocity: tuple[float, float, float] = (0.0, 0.0, 0.0)
    valid: bool = True
    connected: bool = True
    packet: int = 1
    pressed: int = 0
    touched: int = 0
    axes: list[tuple[float, float]] = field(default_factory=lambda: [(0.0, 0.0)] * 5)


class FakeSystem:
    """IVRSystem over `devices`; `script[n]` runs at the n-th pose poll (1-based), before it."""

    def __init__(self) -> None:
        self.devices: dict[int, FakeDevice] = {}
        self.events: deque[tuple[int, int]] = deque()
        self.script: dict[int, Callable[[FakeSystem], None]] = {}
        self.polls = 0
        self.arrays: list[object] = []
        self.origins: list[int] = []
        self.pulses: list[tuple[int, int, int]] = []

    # scripting helpers ---------------------------------------------------------------------
    def activate(self, index: int, dev: FakeDevice) -> None:
        self.devices[index] = dev
        self.events.append((100, index))

    def deactivate(self, index: int) -> None:
        self.devices[index].connected = False
        self.devices[index].valid = False
        self.events.append((101, index))

    def set_role(self, index: int, role: int) -> None:
        self.devices[index].role = role
        self.events.append((108, index))

    # IVRSystem -----------------------------------------------------------------------------
    def getTrackedDeviceClass(self, i: int) -> int:
        d = self.devices.get(i)
        return d.cls if d else 0  # OpenVR keeps the class of a device seen before

    def getControllerRoleForTrackedDeviceIndex(self, i: int) -> int:
        d = self.devices.get(i)
        return d.role if d else 0

    def getStringTrackedDeviceProperty(self, i: int, prop: int) -> str:
        d = self.devices.get(i)
        if prop != FakeOpenVR.Prop_SerialNumber_String or d is None:
            raise TrackedPropertyError(2)
        return d.serial

    def isTrackedDeviceConnected(self, i: int) -> bool:
        d = self.devices.get(i)
        return bool(d and d.connected)

    def pollNextEvent(self, event: VREvent_t) -> bool:
        if not self.events:
            return False
        event.eventType, event.trackedDeviceIndex = self.events.popleft()
        return True

    def getDeviceToAbsoluteTrackingPose(self, origin: int, predicted: float, poses: list) -> list:
        self.polls += 1
        self.origins.append(origin)
        self.arrays.append(poses)
        step = self.script.get(self.polls)
        if step is not None:
            step(self)
        for i, p in enumerate(poses):
            d = self.devices.get(i)
            if d is None:
                p.bPoseIsValid = p.bDeviceIsConnected = 0
                continue
            p.mDeviceToAbsoluteTracking.m = [row[:] for row in d.matrix]
            p.vVelocity.v = list(d.velocity)
            p.vAngularVelocity.v = list(d.angular_velocity)
            p.bPoseIsValid, p.bDeviceIsConnected = int(d.valid), int(d.connected)
        return poses

    def getControllerState(self, i: int) -> tuple[int, VRControllerState_t]:
        st = VRControllerState_t()
        d = self.devices.get(i)
        if d is None or d.cls not in (2, 3):
            return 0, st
        st.unPacketNum, st.ulButtonPressed, st.ulButtonTouched = d.packet, d.pressed, d.touched
        st.rAxis = [VRControllerAxis_t(x, y) for x, y in d.axes]
        return 1, st

    def triggerHapticPulse(self, i: int, axis: int, us: int) -> None:
        self.pulses.append((i, axis, us))


class FakeOpenVR:
    """The module: pass an instance as `module=`. `init_error` makes init raise that code."""

    VRApplication_Background = 3
    TrackingUniverseStanding = 1
    k_unMaxTrackedDeviceCount = 64
    Prop_SerialNumber_String = 1002
    OpenVRError = OpenVRError
    TrackedDevicePose_t = TrackedDevicePose_t
    VREvent_t = VREvent_t

    def __init__(self, installed: int = 1, init_error: int | None = None, describe: bool = True) -> None:
        self.installed = installed
        self.init_error = init_error
        self.system = FakeSystem()
        self.inits: list[int] = []
        self.shutdowns = 0
        if describe:
            self.getVRInitErrorAsEnglishDescription = self._describe

    def isRuntimeInstalled(self) -> int:
        return self.installed

    def init(self, application_type: int) -> FakeSystem:
        self.inits.append(application_type)
        if self.init_error is not None:
            raise OpenVRError(self.init_error)
        return self.system

    def shutdown(self) -> None:
        self.shutdowns += 1

    @staticmethod
    def _describe(code: int) -> str:
        return f"{DESCRIPTIONS.get(code, 'Unknown error')} ({code})"
