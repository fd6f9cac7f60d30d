"""ROS 2 recordings as one MCAP file: what Foxglove/Lichtblick open and `ros2 bag play` accepts.

Profile "ros2", schemas "ros2msg" (the text rosbags generates from its Humble store), messages
CDR, zstd-compressed chunks; log and publish times are the sample times. Every channel carries
`offered_qos_profiles` (as ros2 bag writes it): transient-local for /tf_static, so players
and Foxglove treat it as latched, volatile for the rest. Two metadata records: "rosbag2"
{"ROS_DISTRO": "humble"} (what Humble's recorder writes; it tells newer ros2 bag versions how
to read the QoS text) and "ttctl" {"format", "version", "frame", "parent_frame", "meta" (JSON)}.

A file cut short (crash, kill, full disk) has no summary or footer: it is read up to its last
complete chunk and flagged `Recording.truncated`. A file whose end is intact but whose middle
is damaged is refused.

Speed (the recording budget is 10 % of a core at ~1,900 messages/s): the file is written by
`mcapio.ChunkWriter` (the mcap library's Writer, byte for byte, minus its per-message cost), each
message packed with its record header in one Struct (`codecs`); replay walks the chunks with
`mcapio.iter_records`, skips /tf and /tf_static unread, and takes only the numbers out of poses
and twists.
"""

from __future__ import annotations

import json
from typing import Any

from ttctl import __version__

from ..model import ControllerSample, PoseSample, Sample
from .base import AtomicFile, check_frames
from .codecs import CDR, ENCAPSULATION, STRING, TF, float32s
from .mcapio import MAGIC, MESSAGE, MESSAGE_HEAD_SIZE, ChunkWriter, message_format
from .mcapreplay import read_mcap
from .ros import (
    DEVICES_TOPIC,
    INFO_TOPIC,
    LEAVES,
    TF_STATIC_TOPIC,
    TF_TOPIC,
    Dev,
    RosWriter,
    recording_info,
    to_ns,
    typestore,
)

CHUNK_SIZE = 1 << 20  # bytes of messages per chunk: what a crash can lose, and what a reader decompresses at once
_INFINITE = "    sec: 9223372036\n    nsec: 854775807\n"  # RMW_DURATION_INFINITE as ros2 bag writes it
_NS = 1_000_000_000


def qos_profiles(latched: bool) -> str:
    """The `offered_qos_profiles` YAML of one publisher, with numeric enums (rosbag2 metadata
    version 8, which Humble reads and later versions accept for files marked ROS_DISTRO humble):
    history keep_last, reliable, durability transient_local (1) or volatile (2)."""
    return (f"- history: 1\n  depth: {1 if latched else 10}\n  reliability: 1\n  durability: {1 if latched else 2}\n"
            f"  deadline:\n{_INFINITE}  lifespan:\n{_INFINITE}  liveliness: 1\n"
            f"  liveliness_lease_duration:\n{_INFINITE}  avoid_ros_namespace_conventions: false")


def _record(body: str) -> tuple[Any, int]:
    """The Struct of a whole Message record with this CDR body, and the record's length field."""
    st = CDR.struct(("record", body), message_format(body))
    return st, st.size - 9


class McapWriter(RosWriter):
    """Each message is one Struct.pack of record header and CDR body (formats made per device,
    when its first message is written), handed to the chunk writer with its index entry."""

    def __init__(self, path: str, frame: str, parent_frame: str, meta: dict[str, Any]) -> None:
        super().__init__(parent_frame)
        check_frames(frame, parent_frame)
        self._schemas: dict[str, int] = {}
        self._topics: dict[str, tuple[int, list[int]]] = {}  # topic -> channel id, its message index
        self._parent = parent_frame.encode()
        self._tf: tuple[int, list[int]] | None = None
        self._static_channel: tuple[int, list[int]] | None = None
        self._devices_channel: tuple[int, list[int]] | None = None
        self._atomic = AtomicFile(path)
        try:
            assert self._atomic.file is not None
            self._mcap = ChunkWriter(self._atomic.file, chunk_size=CHUNK_SIZE, compression="zstd")
            self._mcap.start(profile="ros2", library=f"ttctl {__version__}")
            self._mcap.add_metadata("rosbag2", {"ROS_DISTRO": "humble"})
            info = recording_info(frame, parent_frame, meta)
            self._info = json.dumps(info, default=str, separators=(",", ":"))
            self._mcap.add_metadata("ttctl", {k: json.dumps(v, default=str) if k == "meta" else str(v)
                                              for k, v in info.items()})
        except BaseException:
            self._atomic.discard()
            raise

    def _channel(self, topic: str, msgtype: str, latched: bool = False) -> tuple[int, list[int]]:
        """Registered on the topic's first message, so channel ids follow first appearance (and
        once: two devices can share a frame, as a swapped controller takes over controller_left)."""
        known = self._topics.get(topic)
        if known is not None:
            return known
        schema = self._schemas.get(msgtype)
        if schema is None:
            text = typestore(2).generate_msgdef(msgtype, ros_version=2)[0]
            schema = self._schemas[msgtype] = self._mcap.register_schema(msgtype, "ros2msg", text.encode())
        channel = self._mcap.register_channel(topic, "cdr", schema, {"offered_qos_profiles": qos_profiles(latched)})
        self.counts[topic] = 0
        known = self._topics[topic] = (channel, self._mcap.index(channel))
        return known

    def _put(self, topic: str, channel: tuple[int, list[int]], ns: int, data: bytes, sequence: int = 0) -> None:
        """A message of the rarer kinds, encoded by the codec (not per device)."""
        record = _RECORD_HEAD.pack(MESSAGE, MESSAGE_HEAD_SIZE - 9 + len(data), channel[0], sequence, ns, ns) + data
        self._mcap.add_record(channel[0], channel[1], ns, record)
        self.counts[topic] += 1

    def write(self, s: Sample) -> None:
        if INFO_TOPIC not in self._topics and not self._done:  # latched, once, before the first sample
            self._put(INFO_TOPIC, self._channel(INFO_TOPIC, STRING, latched=True), to_ns(s.t), CDR.string(self._info))
        super().write(s)

    def _devices(self, ns: int, text: str) -> None:
        if self._devices_channel is None:
            self._devices_channel = self._channel(DEVICES_TOPIC, STRING)
        self._put(DEVICES_TOPIC, self._devices_channel, ns, CDR.string(text))

    def _tf_static(self, ns: int, transforms: list[tuple[Any, ...]]) -> None:
        if self._static_channel is None:
            self._static_channel = self._channel(TF_STATIC_TOPIC, TF, latched=True)
        self._put(TF_STATIC_TOPIC, self._static_channel, ns, CDR.tf(transforms))

    def _first(self, dev: Dev, ns: int, s: PoseSample) -> None:
        """A device's first valid pose: each channel registered just before its first message
        (as the mcap library's users do, so channel ids follow first appearance), and the
        device's record Structs made for `_moving` / `_posed`: per kind (Struct, record header
        arguments, strings' arguments, channel id, message index, topic)."""
        parent = (len(self._parent) + 1, self._parent)
        sec_nsec = divmod(ns, _NS)
        if not dev.static:
            if self._tf is None:
                self._tf = self._channel(TF_TOPIC, TF)
            ch, index = self._tf
            child = dev.frame.encode()
            st, length = _record(CDR.tf_format(((len(self._parent), len(child)),)))
            dev.tf = (st, (MESSAGE, length, ch, 0), (*parent, len(child) + 1, child), ch, index, TF_TOPIC)
            self._mcap.add_record(ch, index, ns, st.pack(MESSAGE, length, ch, 0, ns, ns, ENCAPSULATION, 1, *sec_nsec,
                                                         *dev.tf[2], *s.position, *s.orientation))
            self.counts[TF_TOPIC] += 1
        for leaf, doubles, values in (("pose", 7, (*s.position, *s.orientation)),
                                      ("twist", 6, (*s.velocity, *s.angular_velocity))):
            topic = f"/vr/{dev.frame}/{leaf}"
            ch, index = self._channel(topic, LEAVES[leaf])
            st, length = _record(CDR.stamped_format(len(self._parent), doubles))
            setattr(dev, leaf, (st, (MESSAGE, length, ch, 0), parent, ch, index, topic))
            self._mcap.add_record(ch, index, ns, st.pack(MESSAGE, length, ch, 0, ns, ns, ENCAPSULATION, *sec_nsec,
                                                         *parent, *values))
            self.counts[topic] += 1
        if not dev.static:  # /tf, pose and twist of a sample in one Struct, for ChunkWriter.add_three
            kinds = (dev.tf, dev.pose, dev.twist)
            formats = [k[0].format[1:] for k in kinds]  # without the byte order
            dev.triple = CDR.struct(("triple", *formats), "".join(formats)).pack
            dev.group = tuple(x for k in kinds for x in (k[3], k[4], k[0].size))
            dev.args = (dev.tf[1], dev.tf[2], dev.pose[1], dev.twist[1], parent)
        dev.ready = True

    def _moving(self, dev: Dev, ns: int, s: PoseSample) -> None:
        """The hot path of recording: three records in one pack, handed over in one call."""
        if not dev.ready:
            self._first(dev, ns, s)
            return
        sec, nsec = divmod(ns, _NS)
        p, q = s.position, s.orientation
        tf_head, tf_tail, pose_head, twist_head, parent = dev.args
        self._mcap.add_three(dev.group, ns, dev.triple(
            *tf_head, ns, ns, ENCAPSULATION, 1, sec, nsec, *tf_tail, *p, *q,
            *pose_head, ns, ns, ENCAPSULATION, sec, nsec, *parent, *p, *q,
            *twist_head, ns, ns, ENCAPSULATION, sec, nsec, *parent, *s.velocity, *s.angular_velocity))
        counts = self.counts
        counts[TF_TOPIC] += 1
        counts[dev.pose_topic] += 1
        counts[dev.twist_topic] += 1

    def _posed(self, dev: Dev, ns: int, s: PoseSample) -> None:
        if not dev.ready:
            self._first(dev, ns, s)
            return
        sec, nsec = divmod(ns, _NS)
        add, counts = self._mcap.add_record, self.counts
        st, head, tail, ch, index, topic = dev.pose
        add(ch, index, ns, st.pack(*head, ns, ns, ENCAPSULATION, sec, nsec, *tail, *s.position, *s.orientation))
        counts[topic] += 1
        st, head, tail, ch, index, topic = dev.twist
        add(ch, index, ns, st.pack(*head, ns, ns, ENCAPSULATION, sec, nsec, *tail, *s.velocity, *s.angular_velocity))
        counts[topic] += 1

    def _joy(self, dev: Dev, ns: int, s: ControllerSample) -> None:
        if not dev.joy_ready:
            dev.joy_channel = self._channel(dev.joy_topic, LEAVES["joy"])
            dev.joy_ready = True
        data = CDR.joy(0, *divmod(ns, _NS), dev.frame, float32s((float(s.pad_x), float(s.pad_y), float(s.trigger))),
                       s.joy_buttons)
        self._put(dev.joy_topic, dev.joy_channel, ns, data, int(s.packet) & 0xFFFFFFFF)

    def close(self) -> None:
        if self._done:
            return
        self._done = True
        try:
            self._mcap.finish()
            self._atomic.commit()
        except BaseException:
            self._atomic.discard()
            raise

    def abort(self) -> None:
        if self._done:
            return
        self._done = True
        self._atomic.discard()


_RECORD_HEAD = CDR.struct(("record head",), message_format(""))


__all__ = ["MAGIC", "McapWriter", "qos_profiles", "read_mcap"]
