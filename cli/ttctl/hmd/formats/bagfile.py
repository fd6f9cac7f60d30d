"""ROS 1 recordings as a .bag (format 2.0, uncompressed), written with rosbags from its Noetic
typestore: ROS 1 type names (tf2_msgs/TFMessage, geometry_msgs/PoseStamped, ...) with the md5sums
rosbag, rosbag play and rqt_bag check. Same topics as the MCAP (see `ros`); /tf_static and
/vr/recording are latched (connection header latching=1).

Where the stream's frame and metadata go: a bag header has no room for them, so the first
message, on the latched topic /vr/recording (std_msgs/String), is JSON
{"format": "ttctl.hmd", "version": 1, "frame", "parent_frame", "meta"}, stamped with the first
sample's time (the time of closing for an empty recording).

Replay gives the samples in time order; samples of the very same instant come by device index,
poses first (rosbags does not keep the file order of messages with equal times).

A bag is only readable once its index is written at close; one cut short (crash, kill) is
refused with a hint (`rosbag reindex` can rebuild the index).
"""

from __future__ import annotations

import json
import time
from typing import Any

from ttctl.errors import Fail

from ..model import ControllerSample, PoseSample, Sample
from .base import AtomicFile, Recording, check_frames
from .codecs import ROS1, STRING, TF, float32s
from .ros import (
    DEVICES_TOPIC,
    LEAVES,
    TF_STATIC_TOPIC,
    TF_TOPIC,
    Dev,
    RosWriter,
    recording_info,
    to_ns,
    typestore,
)

MAGIC = b"#ROSBAG V2.0\n"
INFO_TOPIC = "/vr/recording"
CALLERID = "/ttctl_hmd"
_NS = 1_000_000_000


class BagWriter(RosWriter):
    """Messages encoded by `codecs.ROS1` (one Struct per device and kind), stored by rosbags'
    bag writer (chunks, connection records, index)."""

    def __init__(self, path: str, frame: str, parent_frame: str, meta: dict[str, Any]) -> None:
        super().__init__(parent_frame)
        from rosbags.rosbag1 import Writer as _Bag

        check_frames(frame, parent_frame)
        self._store = typestore(1)
        self._parent = parent_frame.encode()
        self._info = json.dumps(recording_info(frame, parent_frame, meta), default=str, separators=(",", ":"))
        self._info_written = False
        self._connections: dict[str, Any] = {}
        self._atomic = AtomicFile(path, create=False)  # rosbags creates the file itself, exclusively
        self._bag = _Bag(self._atomic.tmp)
        try:
            self._bag.open()
        except Exception as e:  # rosbags' WriterError, or an OSError
            self._atomic.discard()
            raise Fail(f"cannot create {self._atomic.tmp}: {e}") from None

    def _connection(self, topic: str, msgtype: str, latched: bool = False) -> Any:
        """Added on the topic's first message."""
        conn = self._connections[topic] = self._bag.add_connection(
            topic, msgtype, typestore=self._store, callerid=CALLERID, latching=1 if latched else 0)
        self.counts[topic] = 0
        return conn

    def _put(self, topic: str, msgtype: str, ns: int, data: bytes, latched: bool = False) -> None:
        conn = self._connections.get(topic) or self._connection(topic, msgtype, latched)
        self._bag.write(conn, ns, data)
        self.counts[topic] += 1

    def write(self, s: Sample) -> None:
        if not self._info_written and not self._done:
            self._put(INFO_TOPIC, STRING, to_ns(s.t), ROS1.string(self._info), latched=True)
            self._info_written = True
        super().write(s)

    def _devices(self, ns: int, text: str) -> None:
        self._put(DEVICES_TOPIC, STRING, ns, ROS1.string(text))

    def _tf_static(self, ns: int, transforms: list[tuple[Any, ...]]) -> None:
        self._put(TF_STATIC_TOPIC, TF, ns, ROS1.tf(transforms), latched=True)

    def _prepare(self, dev: Dev) -> None:
        plen = len(self._parent)
        dev.pose_pack = ROS1.struct(("stamped", plen, 7), ROS1.stamped_format(plen, 7)).pack
        dev.twist_pack = ROS1.struct(("stamped", plen, 6), ROS1.stamped_format(plen, 6)).pack
        child = dev.frame.encode()
        lengths = ((plen, len(child)),)
        dev.tf_pack = ROS1.struct(("tf", lengths), ROS1.tf_format(lengths)).pack
        dev.tf_args = (plen, self._parent, len(child), child)
        dev.ready = True

    def _moving(self, dev: Dev, ns: int, s: PoseSample) -> None:
        if not dev.ready:
            self._prepare(dev)
        sec, nsec = divmod(ns, _NS)
        self._put(TF_TOPIC, TF, ns, dev.tf_pack(1, 0, sec, nsec, *dev.tf_args, *s.position, *s.orientation))
        self._posed(dev, ns, s)

    def _posed(self, dev: Dev, ns: int, s: PoseSample) -> None:
        if not dev.ready:
            self._prepare(dev)
        sec, nsec = divmod(ns, _NS)
        parent = self._parent
        self._put(dev.pose_topic, LEAVES["pose"], ns,
                  dev.pose_pack(0, sec, nsec, len(parent), parent, *s.position, *s.orientation))
        self._put(dev.twist_topic, LEAVES["twist"], ns,
                  dev.twist_pack(0, sec, nsec, len(parent), parent, *s.velocity, *s.angular_velocity))

    def _joy(self, dev: Dev, ns: int, s: ControllerSample) -> None:
        data = ROS1.joy(int(s.packet) & 0xFFFFFFFF, *divmod(ns, _NS), dev.frame,
                        float32s((float(s.pad_x), float(s.pad_y), float(s.trigger))), s.joy_buttons)
        self._put(dev.joy_topic, LEAVES["joy"], ns, data)

    def close(self) -> None:
        if self._done:
            return
        try:
            if not self._info_written:
                self._put(INFO_TOPIC, STRING, time.time_ns(), ROS1.string(self._info), latched=True)
                self._info_written = True
            self._done = True
            self._bag.close()
            self._atomic.commit()
        except BaseException:
            self._done = True
            self._bag.abort()
            self._atomic.discard()
            raise

    def abort(self) -> None:
        if self._done:
            return
        self._done = True
        self._bag.abort()
        self._atomic.discard()


# ---------------------------------------------------------------------------------------------- reading


def read_bag(path: str) -> Recording:
    """See `bagreplay` (kept apart: reading is a module of its own)."""
    from .bagreplay import read_bag as read

    return read(path)


def expected_md5(msgtype: str) -> str:
    return str(typestore(1).generate_msgdef(msgtype)[1])


__all__ = ["MAGIC", "BagWriter", "expected_md5", "read_bag"]
