"""A real headset's poses and controller inputs through OpenVR (the `openvr` package, ttctl[vr]).

ttctl runs as an OpenVR *background* application (VRApplication_Background): it reads poses
without rendering, and it never starts SteamVR itself: when SteamVR is not running, init fails
with VRInitError 121 instead of launching a compositor on somebody's desk. Every init failure
becomes one line naming the VRInitError code and what to do about it.

The poll loop (IVRSystem, openvr.h): GetDeviceToAbsoluteTrackingPose(TrackingUniverseStanding,
0, poses) into one preallocated TrackedDevicePose_t[k_unMaxTrackedDeviceCount] array, at the
faster of the two rates, sleeping to each tick. Per device bPoseIsValid / bDeviceIsConnected
become `valid` / `connected`; an invalid pose is still yielded, flagged, so a recording shows
where tracking was lost. The device table (class, role, serial per index) is read at start and
again whenever OpenVR reports TrackedDeviceActivated, TrackedDeviceDeactivated or
TrackedDeviceRoleChanged, so controllers switched on late, switched off, or swapped between
hands are followed. Controller inputs come from the legacy GetControllerState and are emitted
only when its unPacketNum changes. (That API reads zeros once a process uses IVRInput, and
nothing while another app has input focus: ValveSoftware/openvr issues #907, #128.)

Angular velocities are passed on as OpenVR reports them; its documentation says tracking
space, but observations differ (ValveSoftware/openvr issue #1768).
"""

from __future__ import annotations

import contextlib
import math
import os
import sys
import time
from collections.abc import Iterator
from typing import Any

from ...errors import Fail
from ..frames import continuous, quat_from_matrix
from ..model import BUTTONS, ControllerSample, Device, PoseSample, Quat, Sample

# ETrackedDeviceClass -> model kind; ETrackedControllerRole -> model role (openvr.h)
KINDS = {1: "hmd", 2: "controller", 3: "tracker", 4: "base_station"}
ROLES = {1: "left", 2: "right"}
# EVRButtonId bits of ulButtonPressed / ulButtonTouched
BUTTON_MENU, BUTTON_GRIP, BUTTON_TOUCHPAD, BUTTON_TRIGGER = 1, 2, 32, 33
# EVREventType
EVENT_ACTIVATED, EVENT_DEACTIVATED, EVENT_ROLE_CHANGED = 100, 101, 108
MAX_PULSE_US = 3999  # TriggerHapticPulse takes at most 3999 us per call
BASE_PERIOD = 1.0  # s between poses of base stations, which do not move (as the synthetic source)

_NAMES = {100: "installation not found", 108: "HMD not found", 110: "path registry not found",
          121: "no server for background app"}
_INSTALL = " (is SteamVR installed?)"
_HINTS = {**dict.fromkeys((100, 101, 102, 103, 110, 111, 112, 113), _INSTALL),
          108: " (no headset found: is it connected, powered on and seen by SteamVR?)",
          126: " (no headset found: is it connected, powered on and seen by SteamVR?)",
          121: " (SteamVR is not running: start it first; a background app never starts it)"}
_SYNTHETIC = "; try --source synthetic"


def load(module: Any = None) -> Any:
    """The openvr module (or the stand-in given), with a one-line error when it is missing."""
    if module is not None:
        return module
    try:
        import openvr
    except ImportError:
        raise Fail("the openvr source needs the VR extra: pip install 'ttctl[vr]'") from None
    except OSError as e:  # the wheel bundles libopenvr_api only for Linux x86_64 and Windows
        raise Fail(f"the openvr module could not load its native library ({e}){_SYNTHETIC}") from None
    return openvr


def init_error_line(vr: Any, code: Any, installed: bool = True) -> str:
    """One line for a VRInitError: its code, OpenVR's own description of it, and a hint."""
    desc = ""
    describe = getattr(vr, "getVRInitErrorAsEnglishDescription", None)
    if describe is not None and isinstance(code, int):
        try:
            desc = describe(code)
        except Exception:  # a description is a nicety; the code is what matters
            desc = ""
    if isinstance(desc, bytes):
        desc = desc.decode("utf-8", "replace")
    desc = " ".join(str(desc).split())
    if desc.endswith(f"({code})"):  # "Installation path could not be located (110)"
        desc = desc[: -len(f"({code})")].rstrip()
    if not desc and isinstance(code, int):
        desc = _NAMES.get(code, "VRInitError")
    hint = _HINTS.get(code, _INSTALL if not installed else " (is SteamVR running with the headset connected?)")
    return f"OpenVR could not start: {' '.join(str(p) for p in (code, desc) if p)}{hint}{_SYNTHETIC}"


@contextlib.contextmanager
def _native_stderr_silenced() -> Iterator[None]:
    """libopenvr_api writes its own complaints ("Unable to read VR Path Registry from ...", several
    times) straight to file descriptor 2; the one-line Fail says the same, so they are dropped
    while OpenVR starts. A no-op where fd 2 cannot be redirected."""
    saved = None
    with contextlib.suppress(OSError, ValueError, AttributeError):
        sys.stderr.flush()
        saved = os.dup(2)
    if saved is None:
        yield
        return
    try:
        null = os.open(os.devnull, os.O_WRONLY)
        try:
            os.dup2(null, 2)
        finally:
            os.close(null)
        yield
    finally:
        os.dup2(saved, 2)
        os.close(saved)


def start(vr: Any) -> Any:
    """openvr.init as a background application -> IVRSystem, or Fail with one line.

    When isRuntimeInstalled() says no, init is still called (as a background app it starts
    nothing) because its error code says *why* more precisely than the yes/no does."""
    installed = True
    try:
        with _native_stderr_silenced():
            try:
                installed = bool(vr.isRuntimeInstalled())
            except Exception:
                installed = True
            system = vr.init(vr.VRApplication_Background)
    except vr.OpenVRError as e:
        code = getattr(e, "error_value", None)
        if code is None:
            code = str(e) or type(e).__name__
        raise Fail(init_error_line(vr, code, installed)) from None
    if not installed:
        _shutdown(vr)
        raise Fail(f"OpenVR could not start: isRuntimeInstalled() is 0{_INSTALL}{_SYNTHETIC}")
    return system


def _shutdown(vr: Any) -> None:
    with contextlib.suppress(Exception):  # shutting down is best effort: the process ends anyway
        vr.shutdown()


def _serial(vr: Any, system: Any, index: int) -> str:
    try:
        s = system.getStringTrackedDeviceProperty(index, vr.Prop_SerialNumber_String)
    except vr.OpenVRError:  # TrackedPropertyError: no serial for this device
        return ""
    return s.decode("utf-8", "replace") if isinstance(s, bytes) else str(s)


def scan(vr: Any, system: Any) -> dict[int, Device]:
    """The tracked devices by index: class, role (controllers) and serial, as OpenVR says now.
    A device that disconnected keeps its class (OpenVR remembers it), so it stays here and its
    poses say connected False."""
    devices = {}
    for i in range(vr.k_unMaxTrackedDeviceCount):
        kind = KINDS.get(int(system.getTrackedDeviceClass(i)))
        if kind is None:
            continue
        role = "none"
        if kind == "controller":
            role = ROLES.get(int(system.getControllerRoleForTrackedDeviceIndex(i)), "none")
        devices[i] = Device(i, kind, role, _serial(vr, system, i))
    return devices


def _bit(mask: int, button: int) -> bool:
    return bool((int(mask) >> button) & 1)


class OpenVRSource:
    """Poses of every tracked device and the controllers' inputs, in real time (`paced`).

    The hmd's pose at rate_hmd, the other devices' at rate_controllers (base stations, which
    do not move, once a second and when their flags change), polled at the faster rate. A
    device that disconnects is reported once with connected False, then not until it is back."""

    frame = "openvr"
    paced = True

    def __init__(self, rate_hmd: float = 90, rate_controllers: float = 250, duration: float | None = None,
                 module: Any = None) -> None:
        for name, rate in (("rate_hmd", rate_hmd), ("rate_controllers", rate_controllers)):
            if not (math.isfinite(rate) and rate > 0):
                raise Fail(f"{name} must be a positive number of samples per second, not {rate}")
        if duration is not None and not (duration >= 0):
            raise Fail(f"duration must be >= 0 seconds, not {duration}")
        self.rate_hmd = float(rate_hmd)
        self.rate_controllers = float(rate_controllers)
        self.duration = duration
        self.counts: dict[str, int] = {}
        self._vr = load(module)
        self._system = start(self._vr)
        self._closed = False
        self._poses = (self._vr.TrackedDevicePose_t * self._vr.k_unMaxTrackedDeviceCount)()
        self._event = self._vr.VREvent_t()
        self.devices: dict[int, Device] = scan(self._vr, self._system)
        self._packets: dict[int, int] = {}  # index -> last unPacketNum emitted
        self._flags: dict[int, tuple[bool, bool]] = {}  # index -> last (valid, connected) emitted
        self._last_q: dict[int, Quat] = {}

    def _events(self) -> None:
        """Drain OpenVR's event queue; rescan the device table if devices came, went or swapped."""
        changed = False
        while self._system.pollNextEvent(self._event):
            if int(self._event.eventType) in (EVENT_ACTIVATED, EVENT_DEACTIVATED, EVENT_ROLE_CHANGED):
                changed = True
        if changed:
            self.devices = scan(self._vr, self._system)

    def _pose(self, t: float, dev: Device) -> PoseSample:
        p = self._poses[dev.index]
        m = p.mDeviceToAbsoluteTracking
        rows = [[float(m[r][c]) for c in range(4)] for r in range(3)]
        valid, connected = bool(p.bPoseIsValid), bool(p.bDeviceIsConnected)
        q = quat_from_matrix(rows)
        if valid:
            q = continuous(q, self._last_q.get(dev.index))
            self._last_q[dev.index] = q
        v, w = p.vVelocity, p.vAngularVelocity
        return PoseSample(t, dev, valid, connected, (rows[0][3], rows[1][3], rows[2][3]), q,
                          (float(v[0]), float(v[1]), float(v[2])), (float(w[0]), float(w[1]), float(w[2])))

    def _state(self, t: float, dev: Device) -> ControllerSample | None:
        """The controller's inputs if its packet number moved on since the last one emitted."""
        ok, st = self._system.getControllerState(dev.index)
        if not ok or self._packets.get(dev.index) == int(st.unPacketNum):
            return None
        self._packets[dev.index] = int(st.unPacketNum)
        trigger = float(st.rAxis[1].x)
        pressed, touched = int(st.ulButtonPressed), int(st.ulButtonTouched)
        buttons = dict.fromkeys(BUTTONS, False)
        buttons.update(trigger_click=_bit(pressed, BUTTON_TRIGGER) or trigger >= 1.0,
                       pad_touched=_bit(touched, BUTTON_TOUCHPAD), pad_pressed=_bit(pressed, BUTTON_TOUCHPAD),
                       menu=_bit(pressed, BUTTON_MENU), grip=_bit(pressed, BUTTON_GRIP))
        return ControllerSample(t, dev, int(st.unPacketNum), trigger, float(st.rAxis[0].x), float(st.rAxis[0].y),
                                buttons)

    def _poll(self, t: float, hmd_due: bool, other_due: bool, base_due: bool) -> Iterator[Sample]:
        for i in sorted(self.devices):
            dev = self.devices[i]
            due = hmd_due if dev.kind == "hmd" else base_due if dev.kind == "base_station" else other_due
            s = self._pose(t, dev)
            flags = (s.valid, s.connected)
            previous = self._flags.get(i)
            changed = previous != flags
            if s.connected and previous is not None and not previous[1]:
                self._packets.pop(i, None)  # back from off, perhaps with its old packet number: report afresh
            if (due or changed) and (s.connected or changed):
                self._flags[i] = flags
                yield s
            if dev.kind == "controller" and other_due and s.connected:
                c = self._state(t, dev)
                if c is not None:
                    yield c

    def samples(self) -> Iterator[Sample]:
        """Poll until the duration is over (or forever), sleeping to each tick; ticks missed
        because the consumer was slow are skipped, not caught up in a burst."""
        vr = self._vr
        tick = 1.0 / max(self.rate_hmd, self.rate_controllers)
        start_mono = time.monotonic()
        k = 0
        n_hmd = n_other = n_base = 0
        eps = 1e-9
        while not self._closed:
            elapsed = k * tick
            if self.duration is not None and elapsed >= self.duration:
                return
            wait = start_mono + elapsed - time.monotonic()
            if wait > 0:
                time.sleep(wait)
            self._events()
            self._system.getDeviceToAbsoluteTrackingPose(vr.TrackingUniverseStanding, 0, self._poses)
            t = time.time()
            hmd_due = elapsed + eps >= n_hmd / self.rate_hmd
            other_due = elapsed + eps >= n_other / self.rate_controllers
            base_due = elapsed + eps >= n_base * BASE_PERIOD
            if hmd_due:
                n_hmd = math.floor(elapsed * self.rate_hmd + eps) + 1
            if other_due:
                n_other = math.floor(elapsed * self.rate_controllers + eps) + 1
            if base_due:
                n_base = math.floor(elapsed / BASE_PERIOD + eps) + 1
            for s in self._poll(t, hmd_due, other_due, base_due):
                self.counts[s.device.frame] = self.counts.get(s.device.frame, 0) + 1
                yield s
            k += 1
            late = time.monotonic() - (start_mono + k * tick)
            if late > tick:
                k += int(late / tick)

    def close(self) -> None:
        """openvr.shutdown(), once."""
        if not self._closed:
            self._closed = True
            _shutdown(self._vr)

    def __enter__(self) -> OpenVRSource:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def pulse(device: str, us: int, module: Any = None) -> tuple[int, str | None]:
    """A haptic pulse of `us` microseconds on the left or right controller.

    Returns the length used (clamped to OpenVR's 0..3999 us) and a warning when it was clamped."""
    if device not in ROLES.values():
        raise Fail(f"haptic pulse: device {device!r} must be left or right")
    used = min(max(int(us), 0), MAX_PULSE_US)
    warning = None if used == us else f"a pulse of {us} us was clamped to {used} us (OpenVR takes 0..{MAX_PULSE_US})"
    try:
        vr = load(module)
        system = start(vr)
    except Fail as e:  # a synthetic source has no controller to pulse: no advice to use one
        raise Fail(str(e).replace(_SYNTHETIC, ""), e.code) from None
    try:
        found = [d.index for d in scan(vr, system).values()
                 if d.kind == "controller" and d.role == device and system.isTrackedDeviceConnected(d.index)]
        if not found:
            raise Fail(f"no {device} controller is connected: switch it on (and check SteamVR sees it in that hand)")
        system.triggerHapticPulse(found[0], 0, used)
    finally:
        _shutdown(vr)
    return used, warning


__all__ = ["KINDS", "ROLES", "OpenVRSource", "init_error_line", "load", "pulse", "scan", "start"]
