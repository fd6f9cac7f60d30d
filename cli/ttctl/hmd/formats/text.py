"""JSONL and CSV recordings: one line per sample, readable by anything, exact to the last bit.

Numbers are written with Python's shortest round-trip form (`repr`), so reading a recording back
gives the very same floats. Both can go to stdout (one line per write call, so an interrupted
pipe ends at a line boundary) or to a file (written atomically, see `base`).

JSONL (`.jsonl`, `.ndjson`): one JSON object per line, UTF-8.
The first line describes the recording:
  {"type": "recording", "format": "ttctl.hmd", "version": 1, "frame": "ros"|"openvr",
   "parent_frame": str, "meta": {...}}
Then one object per sample. A pose:
  {"t": seconds since the UNIX epoch, "type": "pose",
   "frame": "ros" (REP-103: x forward, y left, z up) | "openvr" (x right, y up, z backwards),
   "parent": the world frame, "child": the device's tf frame (hmd, controller_left, ...),
   "device": "hmd"|"controller"|"tracker"|"base_station", "index": OpenVR device index 0..63,
   "role": "none"|"left"|"right", "serial": str, "valid": bool (false: the numbers are
   meaningless), "connected": bool, "position": [x, y, z] metres, "orientation": [x, y, z, w]
   unit quaternion, "velocity": [x, y, z] m/s, "angular_velocity": [x, y, z] rad/s}
  (vectors in the parent frame; a non-finite number is written as null)
A controller's inputs (written when its state changed):
  {"t", "type": "controller", "child", "device", "index", "role", "serial",
   "packet": OpenVR packet number, "axes": [trigger 0..1, pad_x -1..1, pad_y -1..1],
   "buttons": {"trigger_click": bool, "pad_touched": bool, "pad_pressed": bool, "menu": bool,
   "grip": bool}}
Consumers should select lines by "type" and ignore keys they do not know.

CSV (`.csv`): one header row, then one row per sample, UTF-8, "\\n" line ends. Columns:
  t, type (pose|controller), frame (ros|openvr), parent, child, device, index, role, serial,
  valid, connected, px, py, pz, qx, qy, qz, qw, vx, vy, vz, wx, wy, wz,
  packet, trigger, pad_x, pad_y, trigger_click, pad_touched, pad_pressed, menu, grip
  (p: position m, q: orientation quaternion, v: velocity m/s, w: angular velocity rad/s;
  booleans as 1/0; pose columns are blank on controller rows and controller columns blank on
  pose rows; frame and parent are on every row). CSV has no place for `meta`.
"""

from __future__ import annotations

import contextlib
import json
import math
import os
import sys
from collections.abc import Iterator
from typing import IO, Any, BinaryIO

from ttctl.errors import Fail

from ..model import BUTTONS, FRAMES, KINDS, ROLES, ControllerSample, Device, PoseSample, Sample
from .base import AtomicFile, Recording, Writer

FORMAT_NAME = "ttctl.hmd"
VERSION = 1
DEFAULT_PARENT = "world"

POSE_COLUMNS = ("px", "py", "pz", "qx", "qy", "qz", "qw", "vx", "vy", "vz", "wx", "wy", "wz")
CONTROLLER_COLUMNS = ("packet", "trigger", "pad_x", "pad_y", *BUTTONS)
COLUMNS = ("t", "type", "frame", "parent", "child", "device", "index", "role", "serial", "valid", "connected",
           *POSE_COLUMNS, *CONTROLLER_COLUMNS)


class _LineWriter(Writer):
    """Lines to stdout (path None), straight into an existing non-regular file (/dev/null, a
    FIFO: nothing to rename there), or to an atomic file."""

    def __init__(self, path: str | None) -> None:
        super().__init__()
        special = path is not None and os.path.exists(path) and not os.path.isfile(path)
        self._atomic = AtomicFile(path) if path is not None and not special else None
        self._binary = self._atomic.file.write if self._atomic is not None and self._atomic.file is not None else None
        self._stdout: IO[str] | None = sys.stdout if path is None else None
        if special:
            assert path is not None
            try:
                self._stdout = open(path, "w", encoding="utf-8", newline="")  # noqa: SIM115 - closed by close()
            except OSError as e:
                raise Fail(f"{path}: cannot write ({e.strerror})") from None
            self._owned = True
        else:
            self._owned = False

    def write_line(self, line: str) -> None:
        if self._binary is not None:
            self._binary(line.encode("utf-8"))
        else:
            assert self._stdout is not None
            self._stdout.write(line)

    def _release(self) -> None:
        if self._owned and self._stdout is not None:
            with contextlib.suppress(OSError):
                self._stdout.close()

    def close(self) -> None:
        if self._done:
            return
        self._done = True
        if self._atomic is not None:
            try:
                self._atomic.commit()
            except BaseException:
                self._atomic.discard()
                raise
        elif self._stdout is not None:
            try:
                self._stdout.flush()
            finally:
                self._release()

    def abort(self) -> None:
        if self._done:
            return
        self._done = True
        if self._atomic is not None:
            self._atomic.discard()
        elif self._stdout is not None:
            with contextlib.suppress(OSError, ValueError):  # a closed or broken stdout
                self._stdout.flush()  # the complete lines written so far
            self._release()


def _num(x: float) -> float | None:
    return x if math.isfinite(x) else None


class JsonlWriter(_LineWriter):
    """Pose lines are formatted directly (an f-string of float reprs and a per-device prefix made
    once), the same bytes as json.dumps at about half its cost; what remains is mostly the 14
    float reprs themselves (~0.3-0.9 us each, the shortest-round-trip digits that keep replay
    exact). Anything unusual (a number that is not a float, or is NaN/inf, a flag that is not a
    bool) takes json.dumps' path, as do controller lines (a few a second)."""

    def __init__(self, path: str | None, frame: str, parent_frame: str, meta: dict[str, Any]) -> None:
        super().__init__(path)
        self.frame, self.parent = frame, parent_frame
        self._heads: dict[int, tuple[Device, str]] = {}  # device index -> (device, pose line middle)
        try:
            self.write_line(_dumps({"type": "recording", "format": FORMAT_NAME, "version": VERSION, "frame": frame,
                                    "parent_frame": parent_frame, "meta": meta}))
        except BaseException:
            self.abort()
            raise

    def write(self, s: Sample) -> None:
        if self._done:
            raise RuntimeError("write() after close() or abort()")
        if type(s) is not PoseSample:
            self._write_slowly(s)
            return
        # the hot path: what json.dumps would make, unless only json.dumps can tell
        d = s.device
        entry = self._heads.get(d.index)
        if entry is None or (entry[0] is not d and entry[0] != d):
            entry = self._heads[d.index] = (d, self._pose_head(d))
        valid, connected = s.valid, s.connected
        if (valid is not True and valid is not False) or (connected is not True and connected is not False):
            self._write_slowly(s)
            return
        try:
            t = s.t
            p0, p1, p2 = s.position
            q0, q1, q2, q3 = s.orientation
            v0, v1, v2 = s.velocity
            w0, w1, w2 = s.angular_velocity
        except (TypeError, ValueError):
            self._write_slowly(s)
            return
        F = float
        if not (type(t) is F and type(p0) is F and type(p1) is F and type(p2) is F and type(q0) is F
                and type(q1) is F and type(q2) is F and type(q3) is F and type(v0) is F and type(v1) is F
                and type(v2) is F and type(w0) is F and type(w1) is F and type(w2) is F):
            self._write_slowly(s)
            return
        total = t + p0 + p1 + p2 + q0 + q1 + q2 + q3 + v0 + v1 + v2 + w0 + w1 + w2
        if total - total != 0.0:  # a NaN or an infinity somewhere (or only an overflowing sum): null, or refusal
            self._write_slowly(s)
            return
        self.write_line(f'{{"t":{t!r}{entry[1]}"valid":{"true" if valid else "false"},'
                        f'"connected":{"true" if connected else "false"},"position":[{p0!r},{p1!r},{p2!r}],'
                        f'"orientation":[{q0!r},{q1!r},{q2!r},{q3!r}],"velocity":[{v0!r},{v1!r},{v2!r}],'
                        f'"angular_velocity":[{w0!r},{w1!r},{w2!r}]}}\n')
        counts = self.counts
        counts["pose"] = counts.get("pose", 0) + 1

    def _pose_head(self, d: Device) -> str:
        """What comes between "t" and "valid" in a pose line of this device."""
        j = _dumps_value
        return (f',"type":"pose","frame":{j(self.frame)},"parent":{j(self.parent)},"child":{j(d.frame)},'
                f'"device":{j(d.kind)},"index":{j(d.index)},"role":{j(d.role)},"serial":{j(d.serial)},')

    def _write_slowly(self, s: Sample) -> None:
        d = s.device
        obj: dict[str, Any]
        if isinstance(s, PoseSample):
            obj = {"t": s.t, "type": "pose", "frame": self.frame, "parent": self.parent, "child": d.frame,
                   "device": d.kind, "index": d.index, "role": d.role, "serial": d.serial, "valid": s.valid,
                   "connected": s.connected, "position": [_num(v) for v in s.position],
                   "orientation": [_num(v) for v in s.orientation], "velocity": [_num(v) for v in s.velocity],
                   "angular_velocity": [_num(v) for v in s.angular_velocity]}
        else:
            obj = {"t": s.t, "type": "controller", "child": d.frame, "device": d.kind, "index": d.index,
                   "role": d.role, "serial": d.serial, "packet": s.packet,
                   "axes": [_num(s.trigger), _num(s.pad_x), _num(s.pad_y)],
                   "buttons": {b: bool(s.buttons.get(b, False)) for b in BUTTONS}}
        self.write_line(_dumps(obj))
        self._count(obj["type"])


def _dumps_value(v: Any) -> str:
    return json.dumps(v, ensure_ascii=False, allow_nan=False)


def _dumps(obj: dict[str, Any]) -> str:
    return json.dumps(obj, separators=(",", ":"), ensure_ascii=False, allow_nan=False) + "\n"


# ---------------------------------------------------------------------------------------------- reading


MAX_LINE = 1 << 20  # bytes: a sample's line is ~400; a longer one is no recording's (and is not read whole)


def bounded(f: BinaryIO, path: str) -> Iterator[bytes]:
    """The file's lines, each read at most MAX_LINE bytes at a time: a longer line is a Fail
    (a file of zeros, a binary file named .jsonl), not a read that fills the memory."""
    readline = f.readline
    n = 0
    while raw := readline(MAX_LINE):
        n += 1
        if len(raw) == MAX_LINE and not raw.endswith(b"\n") and f.read(1):
            raise Fail(f"{path} line {n}: longer than {MAX_LINE // 1024} KiB: not a line of a recording")
        yield raw


def _lines(f: BinaryIO, path: str, state: dict[str, bool]) -> Iterator[tuple[int, str, bool]]:
    """(line number, text, ends with a newline), decoding each line on its own so a bad byte is
    reported with its line number."""
    for n, raw in enumerate(bounded(f, path), 1):
        try:
            text = raw.decode("utf-8-sig" if n == 1 else "utf-8")  # a spreadsheet's byte-order mark
        except UnicodeDecodeError:
            if n == 1:
                raise Fail(f"{path}: not a text file (line 1 is not UTF-8)") from None
            raise Fail(f"{path} line {n}: not UTF-8 text") from None
        complete = raw.endswith(b"\n")
        state["partial"] = not complete
        yield n, text, complete


def _last_line(path: str) -> bytes | None:
    """The file's final line when it does not end with a newline (a cut-off write), else None."""
    with open(path, "rb") as f:
        size = f.seek(0, os.SEEK_END)
        if size == 0:
            return None
        back = min(size, 1 << 20)
        f.seek(size - back)
        tail = f.read(back)
    if tail.endswith(b"\n"):
        return None
    return tail.rsplit(b"\n", 1)[-1]


def read_jsonl(path: str) -> Recording:
    header: dict[str, Any] | None = None
    first_pose: dict[str, Any] | None = None
    with open(path, "rb") as f:
        for n, text, _ in _lines(f, path, {}):
            if not text.strip():
                continue
            obj = _json_object(text, path, n)
            if obj.get("type") == "recording":
                header = obj
                break
            if obj.get("type") == "pose":
                first_pose = obj
                break
    if header is not None:
        if header.get("format") != FORMAT_NAME:
            raise Fail(f"{path} line 1: format {header.get('format')!r}, expected {FORMAT_NAME!r}")
        if not isinstance(header.get("version"), int) or header["version"] > VERSION:
            raise Fail(f"{path}: recording version {header.get('version')!r}; this ttctl reads up to {VERSION}")
        frame, parent = header.get("frame"), header.get("parent_frame")
        meta = header.get("meta", {})
        if not isinstance(meta, dict):
            raise Fail(f"{path} line 1: 'meta' is not an object")
    elif first_pose is not None:  # a hand-made file without the header line: the first pose tells
        frame, parent, meta = first_pose.get("frame"), first_pose.get("parent"), {}
    else:
        frame, parent, meta = "ros", DEFAULT_PARENT, {}
    if frame not in FRAMES:
        raise Fail(f"{path}: frame {frame!r}, expected one of {', '.join(FRAMES)}")
    if not isinstance(parent, str):
        raise Fail(f"{path}: parent frame {parent!r} is not a string")
    truncated = False
    last = _last_line(path)
    if last is not None:
        try:
            truncated = not isinstance(json.loads(last), dict)
        except (ValueError, UnicodeDecodeError, RecursionError):
            truncated = True
    return Recording(frame, parent, meta, _jsonl_samples(path, frame, parent, truncated), "jsonl", truncated)


def _json_object(text: str, path: str, n: int) -> dict[str, Any]:
    try:
        obj = json.loads(text)
    except json.JSONDecodeError as e:
        raise Fail(f"{path} line {n}: not JSON ({e.msg} at column {e.colno})") from None
    except ValueError as e:  # e.g. a number too long to convert
        raise Fail(f"{path} line {n}: not JSON ({e})") from None
    except RecursionError:  # the decoder recurses once per level
        raise Fail(f"{path} line {n}: nested too deeply to be a sample") from None
    if not isinstance(obj, dict):
        raise Fail(f"{path} line {n}: a {type(obj).__name__}, not an object")
    return obj


def _jsonl_samples(path: str, frame: str, parent: str, truncated: bool) -> Iterator[Sample]:
    """The samples; a pose line of the usual shape (what JsonlWriter writes) skips the general
    field checks (`_fast_pose`), anything else goes through them, so errors read as before."""
    devices: dict[tuple[Any, ...], Device] = {}
    scan = json.decoder.JSONDecoder().scan_once  # json.loads minus two Python-level wrappers (~1 us a line)
    fast_pose = _fast_pose
    with open(path, "rb") as f:
        for n, raw in enumerate(bounded(f, path), 1):
            try:
                text = raw.decode("utf-8-sig" if n == 1 else "utf-8")  # a spreadsheet's byte-order mark
            except UnicodeDecodeError:
                if n == 1:
                    raise Fail(f"{path}: not a text file (line 1 is not UTF-8)") from None
                raise Fail(f"{path} line {n}: not UTF-8 text") from None
            if truncated and not raw.endswith(b"\n"):
                return
            try:
                obj, end = scan(text, 0)
                if end != len(text) - 1 or text[end] != "\n":  # not one value and a newline: json.loads decides
                    obj = json.loads(text)
            except (StopIteration, ValueError, RecursionError):  # the scanner's "no value here", or json.loads' errors
                if not text.strip():
                    continue
                obj = _json_object(text, path, n)  # the value, or a Fail saying what is wrong
            if type(obj) is dict and obj.get("type") == "pose":
                s = fast_pose(obj, frame, parent, devices)
                if s is not None:
                    yield s
                    continue
            elif not isinstance(obj, dict):
                obj = _json_object(text, path, n)  # raises
            kind = obj.get("type")
            if kind == "recording":
                continue
            if kind not in ("pose", "controller"):
                raise Fail(f"{path} line {n}: unknown type {kind!r} (expected pose, controller or recording)")
            try:
                yield _json_sample(obj, frame, parent, devices)
            except _Bad as e:
                raise Fail(f"{path} line {n}: {e}") from None


def _fast_pose(obj: dict[str, Any], frame: str, parent: str, devices: dict[tuple[Any, ...], Device]) \
        -> PoseSample | None:
    """The pose of a line whose fields all have their usual types (floats, bools, a device seen
    before), or None to let `_json_sample` decide (and word any error)."""
    t = obj.get("t")
    valid, connected = obj.get("valid"), obj.get("connected")
    if (type(t) is not float or (valid is not True and valid is not False)
            or (connected is not True and connected is not False)):
        return None
    if obj.get("frame", frame) != frame or obj.get("parent", parent) != parent:
        return None
    index = obj.get("index")
    if type(index) is not int:
        return None
    try:
        device = devices.get((obj.get("device", "hmd"), obj.get("role", "none"), index, obj.get("serial", "")))
        if device is None:
            return None
        p0, p1, p2 = obj["position"]
        q0, q1, q2, q3 = obj["orientation"]
        v0, v1, v2 = obj["velocity"]
        w0, w1, w2 = obj["angular_velocity"]
    except (KeyError, TypeError, ValueError):  # missing, unhashable, not a list of the right length
        return None
    F = float
    if not (type(p0) is F and type(p1) is F and type(p2) is F and type(q0) is F and type(q1) is F
            and type(q2) is F and type(q3) is F and type(v0) is F and type(v1) is F and type(v2) is F
            and type(w0) is F and type(w1) is F and type(w2) is F):
        return None
    return PoseSample(t, device, valid, connected, (p0, p1, p2), (q0, q1, q2, q3), (v0, v1, v2), (w0, w1, w2))


class _Bad(Exception):
    """A field that is missing or of the wrong kind (the caller adds file and line)."""


def _get(obj: dict[str, Any], key: str, types: type | tuple[type, ...], default: Any = ...) -> Any:
    if key not in obj:
        if default is not ...:
            return default
        raise _Bad(f"missing {key!r}")
    v = obj[key]
    if not isinstance(v, types) or (isinstance(v, bool) and bool not in (types if isinstance(types, tuple)
                                                                            else (types,))):
        raise _Bad(f"bad {key!r}: {v!r}")
    return v


def _jnum(v: Any, key: str) -> float:
    if v is None:
        return math.nan
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise _Bad(f"bad {key!r}: {v!r} is not a number")
    return float(v)


def _jvec(obj: dict[str, Any], key: str, size: int) -> Any:
    v = _get(obj, key, list)
    if len(v) != size:
        raise _Bad(f"bad {key!r}: {size} numbers expected, got {len(v)}")
    return tuple(_jnum(x, key) for x in v)


def _json_device(obj: dict[str, Any], default_kind: str, cache: dict[tuple[Any, ...], Device] | None = None) \
        -> Device:
    """The line's device, checked; with `cache`, remembered (one Device per device, not per line)."""
    kind = _get(obj, "device", str, default_kind)
    role = _get(obj, "role", str, "none")
    if kind not in KINDS:
        raise _Bad(f"bad 'device': {kind!r} (expected one of {', '.join(KINDS)})")
    if role not in ROLES:
        raise _Bad(f"bad 'role': {role!r} (expected one of {', '.join(ROLES)})")
    index = _get(obj, "index", int)
    if not 0 <= index < 64:
        raise _Bad(f"bad 'index': {index} (OpenVR devices are 0..63)")
    serial = _get(obj, "serial", str, "")
    if cache is None:
        return Device(index, kind, role, serial)
    key = (kind, role, index, serial)
    device = cache.get(key)
    if device is None:
        device = cache[key] = Device(index, kind, role, serial)
    return device


def _json_sample(obj: dict[str, Any], frame: str, parent: str,
                 devices: dict[tuple[Any, ...], Device] | None = None) -> Sample:
    t = _jnum(_get(obj, "t", (int, float)), "t")
    if obj["type"] == "pose":
        if _get(obj, "frame", str, frame) != frame:
            raise _Bad(f"frame {obj['frame']!r} but the recording is in {frame!r}")
        if _get(obj, "parent", str, parent) != parent:
            raise _Bad(f"parent {obj['parent']!r} but the recording's parent frame is {parent!r}")
        return PoseSample(t, _json_device(obj, "hmd", devices), _get(obj, "valid", bool), _get(obj, "connected", bool),
                          _jvec(obj, "position", 3), _jvec(obj, "orientation", 4), _jvec(obj, "velocity", 3),
                          _jvec(obj, "angular_velocity", 3))
    axes = _jvec(obj, "axes", 3)
    buttons = _get(obj, "buttons", dict)
    for b, v in buttons.items():
        if b not in BUTTONS or not isinstance(v, bool):
            raise _Bad(f"bad button {b!r}: {v!r} (buttons are {', '.join(BUTTONS)}: true/false)")
    packet = _get(obj, "packet", int, 0)
    return ControllerSample(t, _json_device(obj, "controller", devices), packet, axes[0], axes[1], axes[2],
                            {b: bool(buttons.get(b, False)) for b in BUTTONS})


__all__ = ["COLUMNS", "JsonlWriter", "read_jsonl"]
