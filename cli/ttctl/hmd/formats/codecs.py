"""The five ROS message types ttctl records, encoded and decoded with precompiled `struct.Struct`s:
ROS 2 CDR (little-endian, 4-byte encapsulation header, CDR alignment) and ROS 1.

Why not rosbags' own serialisers: building a typestore message object and serialising it cost
~50 us per message (a pose sample is three messages: /tf, pose, twist), and deserialising ~25 us,
which alone broke the floors of `ttctl hmd dump` (under 10 % of a core while recording 90 Hz +
2 x 250 Hz, a 10-minute replay in under 10 s). Our messages have a fixed shape once their strings
are known (a frame_id is the same for a whole recording), so each shape becomes one Struct,
compiled once and cached: packing a PoseStamped is one `pack` call (~1 us), unpacking one
`unpack_from`. rosbags stays the source of truth: the schemas and md5sums come from its
typestores, and tests/test_hmd_codecs.py checks these codecs byte for byte against its
`serialize_cdr` / `serialize_ros1` and value for value against its deserialisers (which are also
what a big-endian CDR message, never written by ttctl, is handed to).

Decoded forms (seq is ROS 1's header.seq, 0 in ROS 2; values are Python floats):
  PoseStamped   (seq, sec, nanosec, frame_id, (px, py, pz, qx, qy, qz, qw))
  TwistStamped  (seq, sec, nanosec, frame_id, (vx, vy, vz, wx, wy, wz))
  TFMessage     [(seq, sec, nanosec, frame_id, child_frame_id, (tx, ty, tz, qx, qy, qz, qw)), ...]
  Joy           (seq, sec, nanosec, frame_id, axes (floats), buttons (ints))
  String        data
"""

from __future__ import annotations

import math
from struct import Struct, unpack_from
from struct import error as StructError
from typing import Any

TF = "tf2_msgs/msg/TFMessage"
POSE = "geometry_msgs/msg/PoseStamped"
TWIST = "geometry_msgs/msg/TwistStamped"
JOY = "sensor_msgs/msg/Joy"
STRING = "std_msgs/msg/String"

ENCAPSULATION = b"\x00\x01\x00\x00"  # CDR, little-endian, no options
MAX_SEQUENCE = 0xFFFFFFFF

_U32 = Struct("<I")
_HEAD_CDR = Struct("<iII")  # stamp.sec, stamp.nanosec, frame_id length
_HEAD_ROS1 = Struct("<IiII")  # seq, stamp.sec, stamp.nanosec, frame_id length
_F32 = Struct("<f")
_D7 = Struct("<7d")
_D6 = Struct("<6d")


class CodecError(ValueError):
    """A message that does not decode as its type (damaged, or not what ttctl writes)."""


class _Layout:
    """One message shape as a struct format: CDR aligns each primitive to its size, counted from
    the end of the encapsulation header; ROS 1 packs without gaps."""

    def __init__(self, cdr: bool) -> None:
        self.cdr = cdr
        self.parts: list[str] = []
        self.pos = 0

    def put(self, code: str, size: int, count: int = 1) -> None:
        if self.cdr and count:
            pad = -self.pos % size
            if pad:
                self.parts.append(f"{pad}x")
                self.pos += pad
        self.parts.append(code if count == 1 else f"{count}{code}")
        self.pos += size * count

    def string(self, nbytes: int) -> None:
        """Length (CDR counts the terminating NUL) and the bytes; `s` pads the NUL for us."""
        n = nbytes + 1 if self.cdr else nbytes
        self.put("I", 4)
        self.parts.append(f"{n}s")
        self.pos += n

    def header(self, nbytes: int) -> None:
        if not self.cdr:
            self.put("I", 4)  # seq
        self.put("i", 4)
        self.put("I", 4)
        self.string(nbytes)

    @property
    def format(self) -> str:
        return "".join(self.parts)


class Codec:
    """Encoders and decoders of one ROS version (2: CDR, 1: ROS 1). The `*_format` methods give
    the struct format of a message shape (without byte order), for callers that pack a message
    together with their own record header (the MCAP writer); the argument order is the one of the
    encoder below: CDR starts with ENCAPSULATION, ROS 1 with seq, each string is (length, bytes)
    with CDR's length counting the NUL."""

    def __init__(self, ros_version: int) -> None:
        if ros_version not in (1, 2):
            raise ValueError(f"ROS version 1 or 2, not {ros_version!r}")
        self.ros = ros_version
        self.cdr = ros_version == 2
        self._structs: dict[tuple[Any, ...], Struct] = {}

    # ------------------------------------------------------------------------------ formats

    def _layout(self) -> _Layout:
        return _Layout(self.cdr)

    def _prefix(self) -> str:
        return "4s" if self.cdr else ""

    def stamped_format(self, frame_len: int, doubles: int) -> str:
        """PoseStamped (7 doubles) or TwistStamped (6): a header, then the numbers."""
        lay = self._layout()
        lay.header(frame_len)
        lay.put("d", 8, doubles)
        return self._prefix() + lay.format

    def tf_format(self, lengths: tuple[tuple[int, int], ...]) -> str:
        """TFMessage with one transform per (frame_id, child_frame_id) length pair."""
        lay = self._layout()
        lay.put("I", 4)
        for frame_len, child_len in lengths:
            lay.header(frame_len)
            lay.string(child_len)
            lay.put("d", 8, 7)
        return self._prefix() + lay.format

    def joy_format(self, frame_len: int, axes: int, buttons: int) -> str:
        lay = self._layout()
        lay.header(frame_len)
        lay.put("I", 4)
        lay.put("f", 4, axes)
        lay.put("I", 4)
        lay.put("i", 4, buttons)
        return self._prefix() + lay.format

    def string_format(self, nbytes: int) -> str:
        lay = self._layout()
        lay.string(nbytes)
        return self._prefix() + lay.format

    def struct(self, key: tuple[Any, ...], fmt: str) -> Struct:
        s = self._structs.get(key)
        if s is None:
            s = self._structs[key] = Struct("<" + fmt)
        return s

    def _str(self, b: bytes) -> tuple[int, bytes]:
        return (len(b) + 1 if self.cdr else len(b)), b

    def _head(self, seq: int, sec: int, nsec: int, frame: bytes) -> tuple[Any, ...]:
        """A header's pack arguments (ROS 2 has no seq)."""
        n, b = self._str(frame)
        return (sec, nsec, n, b) if self.cdr else (seq, sec, nsec, n, b)

    def _enc(self) -> tuple[bytes, ...]:
        return (ENCAPSULATION,) if self.cdr else ()

    # ------------------------------------------------------------------------------ encoders

    def pose(self, seq: int, sec: int, nsec: int, frame_id: str, values: Any) -> bytes:
        """PoseStamped: values = position x, y, z, orientation x, y, z, w."""
        return self._stamped(seq, sec, nsec, frame_id, values, 7)

    def twist(self, seq: int, sec: int, nsec: int, frame_id: str, values: Any) -> bytes:
        """TwistStamped: values = linear x, y, z, angular x, y, z."""
        return self._stamped(seq, sec, nsec, frame_id, values, 6)

    def _stamped(self, seq: int, sec: int, nsec: int, frame_id: str, values: Any, doubles: int) -> bytes:
        frame = frame_id.encode()
        if len(values) != doubles:
            raise ValueError(f"{doubles} numbers expected, got {len(values)}")
        st = self.struct(("stamped", len(frame), doubles), self.stamped_format(len(frame), doubles))
        return st.pack(*self._enc(), *self._head(seq, sec, nsec, frame), *values)

    def tf(self, transforms: Any) -> bytes:
        """TFMessage from (seq, sec, nanosec, frame_id, child_frame_id, 7 numbers) tuples."""
        enc = [(f.encode(), c.encode(), seq, sec, nsec, v) for seq, sec, nsec, f, c, v in transforms]
        lengths = tuple((len(f), len(c)) for f, c, *_ in enc)
        st = self.struct(("tf", lengths), self.tf_format(lengths))
        args: list[Any] = [*self._enc(), len(enc)]
        for f, c, seq, sec, nsec, v in enc:
            if len(v) != 7:
                raise ValueError(f"7 numbers expected, got {len(v)}")
            args.extend(self._head(seq, sec, nsec, f))
            args.extend(self._str(c))
            args.extend(v)
        return st.pack(*args)

    def joy(self, seq: int, sec: int, nsec: int, frame_id: str, axes: Any, buttons: Any) -> bytes:
        frame = frame_id.encode()
        st = self.struct(("joy", len(frame), len(axes), len(buttons)),
                         self.joy_format(len(frame), len(axes), len(buttons)))
        return st.pack(*self._enc(), *self._head(seq, sec, nsec, frame), len(axes), *float32s(axes), len(buttons),
                       *buttons)

    def string(self, data: str) -> bytes:
        b = data.encode()
        st = self.struct(("string", len(b)), self.string_format(len(b)))
        return st.pack(*self._enc(), *self._str(b))

    # ------------------------------------------------------------------------------ decoders

    def _start(self, data: Any) -> tuple[bytes, int]:
        """The bytes, and where the message proper starts; a CDR message that is not
        little-endian goes to rosbags (`_Fallback`)."""
        if not isinstance(data, bytes):
            data = bytes(data)
        if not self.cdr:
            return data, 0
        if len(data) < 4 or data[0] != 0 or data[1] > 1:
            raise CodecError("invalid or unsupported CDR encapsulation")
        if data[1] == 0:
            raise _Fallback
        return data, 4

    def _header(self, data: bytes, pos: int) -> tuple[int, int, int, str, int]:
        """seq, sec, nanosec, frame_id and the position after it."""
        if self.cdr:
            sec, nsec, n = _HEAD_CDR.unpack_from(data, pos)
            seq, pos = 0, pos + 12
        else:
            seq, sec, nsec, n = _HEAD_ROS1.unpack_from(data, pos)
            pos += 16
        frame, pos = self._string_at(data, pos, n)
        return seq, sec, nsec, frame, pos

    def _string_at(self, data: bytes, pos: int, n: int) -> tuple[str, int]:
        end = pos + n
        if end > len(data) or (self.cdr and (n < 1 or data[end - 1] != 0)):
            raise CodecError(f"invalid string of length {n} at offset {pos}")
        return data[pos:end - 1 if self.cdr else end].decode(), end

    def _align(self, pos: int, k: int) -> int:
        """Pad `pos` (an offset into the data, CDR counting from byte 4) to a multiple of k."""
        return pos + (-(pos - 4) % k) if self.cdr else pos

    def _done(self, data: bytes, pos: int, msgtype: str) -> None:
        # rosbags' rule: CDR may carry up to 3 bytes of trailing padding, ROS 1 none
        if (pos + 3 < len(data)) if self.cdr else (pos != len(data)):
            raise CodecError(f"message size mismatch for {msgtype}")

    def decode_pose(self, data: Any) -> tuple[int, int, int, str, tuple[float, ...]]:
        return self._decode_stamped(data, POSE, _D7)

    def decode_twist(self, data: Any) -> tuple[int, int, int, str, tuple[float, ...]]:
        return self._decode_stamped(data, TWIST, _D6)

    def _decode_stamped(self, data: Any, msgtype: str, doubles: Struct) -> Any:
        try:
            data, pos = self._start(data)
            seq, sec, nsec, frame, pos = self._header(data, pos)
            pos = self._align(pos, 8)
            values = doubles.unpack_from(data, pos)
        except _Fallback:
            return _from_rosbags(data, msgtype)
        except (StructError, UnicodeDecodeError) as e:
            raise CodecError(f"could not decode {msgtype}: {e}") from None
        self._done(data, pos + doubles.size, msgtype)
        return seq, sec, nsec, frame, values

    def pose_values(self, data: bytes) -> tuple[float, ...]:
        """Only the 7 numbers of a PoseStamped (what replay needs), checked as `decode_pose` does."""
        return self._values(data, _D7, POSE)

    def twist_values(self, data: bytes) -> tuple[float, ...]:
        """Only the 6 numbers of a TwistStamped."""
        return self._values(data, _D6, TWIST)

    def _values(self, data: bytes, doubles: Struct, msgtype: str) -> tuple[float, ...]:
        # the hot path of replay: ~1 us. Both versions put frame_id's length at byte 12 (after
        # CDR's encapsulation or ROS 1's seq, then the stamp) and its bytes at 16.
        try:
            if self.cdr and (data[0] != 0 or data[1] != 1):
                return self._decode_stamped(data, msgtype, doubles)[4]  # type: ignore[no-any-return]
            (n,) = _U32.unpack_from(data, 12)
            end = 16 + n
            if self.cdr:
                if n < 1 or end > len(data) or data[end - 1] != 0:
                    raise CodecError(f"could not decode {msgtype}: invalid string length {n}")
                str(data[16:end - 1], "utf-8")
                pos = end + (-(end - 4) & 7)
                if pos + doubles.size + 3 < len(data):
                    raise CodecError(f"message size mismatch for {msgtype}")
            else:
                if end > len(data):
                    raise CodecError(f"could not decode {msgtype}: invalid string length {n}")
                str(data[16:end], "utf-8")
                pos = end
                if pos + doubles.size != len(data):
                    raise CodecError(f"message size mismatch for {msgtype}")
            return doubles.unpack_from(data, pos)
        except (StructError, UnicodeDecodeError, IndexError) as e:
            raise CodecError(f"could not decode {msgtype}: {e}") from None

    def decode_tf(self, data: Any) -> list[tuple[int, int, int, str, str, tuple[float, ...]]]:
        out = []
        try:
            data, pos = self._start(data)
            (count,) = _U32.unpack_from(data, pos)
            pos += 4
            if count > MAX_SEQUENCE or pos + count * 4 > len(data):  # 4: the least a transform can take
                raise CodecError(f"invalid sequence length {count}")
            for _ in range(count):
                pos = self._align(pos, 4)
                seq, sec, nsec, frame, pos = self._header(data, pos)
                pos = self._align(pos, 4)
                (n,) = _U32.unpack_from(data, pos)
                child, pos = self._string_at(data, pos + 4, n)
                pos = self._align(pos, 8)
                out.append((seq, sec, nsec, frame, child, _D7.unpack_from(data, pos)))
                pos += 56
        except _Fallback:
            return _from_rosbags(data, TF)  # type: ignore[no-any-return]
        except (StructError, UnicodeDecodeError) as e:
            raise CodecError(f"could not decode {TF}: {e}") from None
        self._done(data, pos, TF)
        return out

    def decode_joy(self, data: Any) -> tuple[int, int, int, str, tuple[float, ...], tuple[int, ...]]:
        try:
            data, pos = self._start(data)
            seq, sec, nsec, frame, pos = self._header(data, pos)
            axes, pos = self._array(data, pos, "f")
            buttons, pos = self._array(data, pos, "i")
        except _Fallback:
            return _from_rosbags(data, JOY)  # type: ignore[no-any-return]
        except (StructError, UnicodeDecodeError) as e:
            raise CodecError(f"could not decode {JOY}: {e}") from None
        self._done(data, pos, JOY)
        return seq, sec, nsec, frame, axes, buttons

    def _array(self, data: bytes, pos: int, code: str) -> tuple[tuple[Any, ...], int]:
        pos = self._align(pos, 4)
        (count,) = _U32.unpack_from(data, pos)
        pos += 4
        if count > MAX_SEQUENCE or pos + count * 4 > len(data):
            raise CodecError(f"invalid sequence length {count} at offset {pos - 4}")
        # struct's own (bounded) cache, not ours: a foreign file could hold any number of lengths
        return unpack_from(f"<{count}{code}", data, pos), pos + 4 * count

    def decode_string(self, data: Any) -> str:
        try:
            data, pos = self._start(data)
            (n,) = _U32.unpack_from(data, pos)
            text, pos = self._string_at(data, pos + 4, n)
        except _Fallback:
            return _from_rosbags(data, STRING)  # type: ignore[no-any-return]
        except (StructError, UnicodeDecodeError) as e:
            raise CodecError(f"could not decode {STRING}: {e}") from None
        self._done(data, pos, STRING)
        return text

    def decode(self, msgtype: str, data: Any) -> Any:
        """Any of the five types by name (ROS 2 spelling)."""
        fn = {POSE: self.decode_pose, TWIST: self.decode_twist, TF: self.decode_tf, JOY: self.decode_joy,
              STRING: self.decode_string}.get(msgtype)
        if fn is None:
            raise CodecError(f"no codec for {msgtype}")
        return fn(data)


class _Fallback(Exception):
    """Big-endian CDR: valid, but never written by ttctl; rosbags decodes it."""


def float32s(values: Any) -> tuple[float, ...] | Any:
    """The values as struct's `f` packs them, except that numbers beyond float32's range become
    +-inf (as numpy, and so rosbags, converts them) rather than an OverflowError."""
    try:
        for v in values:
            _F32.pack(v)
    except OverflowError:
        return tuple(_clamp32(v) for v in values)
    return values


def _clamp32(v: Any) -> float:
    try:
        _F32.pack(v)
    except OverflowError:
        return math.copysign(math.inf, v)
    return float(v)


def _from_rosbags(data: bytes, msgtype: str) -> Any:
    """A big-endian CDR message, decoded by rosbags into our tuples."""
    from .ros import typestore

    try:
        msg: Any = typestore(2).deserialize_cdr(data, msgtype)
    except Exception as e:  # rosbags' SerdeError and whatever a damaged message raises
        raise CodecError(f"could not decode {msgtype}: {e}") from None
    if msgtype == STRING:
        return msg.data

    def head(h: Any) -> tuple[int, int, str]:
        return h.stamp.sec, h.stamp.nanosec, h.frame_id

    if msgtype == POSE:
        p, q = msg.pose.position, msg.pose.orientation
        return 0, *head(msg.header), (p.x, p.y, p.z, q.x, q.y, q.z, q.w)
    if msgtype == TWIST:
        v, w = msg.twist.linear, msg.twist.angular
        return 0, *head(msg.header), (v.x, v.y, v.z, w.x, w.y, w.z)
    if msgtype == JOY:
        return 0, *head(msg.header), tuple(float(a) for a in msg.axes), tuple(int(b) for b in msg.buttons)
    out = []
    for tr in msg.transforms:
        t, r = tr.transform.translation, tr.transform.rotation
        out.append((0, *head(tr.header), tr.child_frame_id, (t.x, t.y, t.z, r.x, r.y, r.z, r.w)))
    return out


CDR = Codec(2)
ROS1 = Codec(1)

__all__ = ["CDR", "ENCAPSULATION", "JOY", "POSE", "ROS1", "STRING", "TF", "TWIST", "Codec", "CodecError", "float32s"]
