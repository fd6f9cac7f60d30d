"""Replaying what ROS tools wrote from a ttctl recording: ROS 2 bag folders (`metadata.yaml` with
SQLite or MCAP storage, from `ros2 bag record` of our topics or `rosbags-convert`), and single
MCAP files a tool rewrote without ttctl's "ttctl" metadata record.

What such a file keeps is what is in the messages: the recording's header on /vr/recording
(std_msgs/String JSON), /vr/devices, and the pose, twist and joy topics. Sequence numbers do not
survive (ROS 2's Header has no seq; converters write 0), so the Rebuilder numbers each
controller's Joy messages in order. Slower than the MCAP and bag readers (rosbags' AnyReader
deserializes every message), which is fine for files that took a detour.
"""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from ttctl.errors import Fail

from ..model import ControllerSample, Sample
from .bagfile import INFO_TOPIC
from .base import Recording
from .ros import VERSION, Rebuilder


def _open(path: str) -> Any:
    from rosbags.highlevel import AnyReader

    try:
        reader = AnyReader([Path(path)])
        reader.open()
    except Exception as e:  # rosbags raises many kinds on what it cannot read
        text = "; ".join(str(a) for a in e.args) or type(e).__name__
        raise Fail(f"{path}: not a readable ROS bag ({text})") from None
    return reader


def read_ros_folder(path: str) -> Recording:
    """A ROS 2 bag folder, or a ROS file whose header is only in /vr/recording."""
    reader = _open(path)
    try:
        info_conns = [c for c in reader.connections if c.topic == INFO_TOPIC]
        raw = None
        for conn, _, data in reader.messages(connections=info_conns):
            raw = reader.deserialize(data, conn.msgtype).data
            break
    except Fail:
        raise
    except Exception as e:
        raise Fail(f"{path}: damaged ROS bag ({str(e) or type(e).__name__})") from None
    finally:
        reader.close()
    if raw is None:
        raise Fail(f"{path}: no {INFO_TOPIC} message: not recorded by ttctl hmd (or recorded without that topic)")
    try:
        info = json.loads(raw)
        frame, parent, meta = info["frame"], info["parent_frame"], info.get("meta", {})
        version = int(info.get("version", 1))
    except (ValueError, KeyError, TypeError, RecursionError) as e:
        raise Fail(f"{path}: bad {INFO_TOPIC} message ({e})") from None
    if version > VERSION:
        raise Fail(f"{path}: recording version {version}; this ttctl reads up to {VERSION}")
    if frame not in ("ros", "openvr") or not isinstance(parent, str) or not isinstance(meta, dict):
        raise Fail(f"{path}: bad {INFO_TOPIC} message (frame {frame!r})")
    return Recording(frame, parent, meta, _samples(path, version), "ros2" if Path(path).is_dir() else "mcap")


def _samples(path: str, version: int) -> Iterator[Sample]:
    rebuild = Rebuilder(path, version)
    reader = _open(path)
    try:
        routes = {}
        for conn in reader.connections:
            route = Rebuilder.route(conn.topic)
            if route is not None:
                routes[conn.id] = route
        conns = [c for c in reader.connections if c.id in routes]
        group: list[tuple[tuple[str, str], Any]] = []
        group_ns = -1
        messages = iter(reader.messages(connections=conns)) if conns else iter(())
        while True:
            try:
                conn, ns, data = next(messages)
                msg = reader.deserialize(data, conn.msgtype)
            except StopIteration:
                break
            except Exception as e:
                raise Fail(f"{path}: damaged ROS bag ({str(e) or type(e).__name__})") from None
            if ns != group_ns:
                yield from _instant(rebuild, group, group_ns)
                group, group_ns = [], ns
            group.append((routes[conn.id], msg))
        yield from _instant(rebuild, group, group_ns)
        rebuild.finish()
        yield from rebuild.out
    finally:
        reader.close()


def _instant(rebuild: Rebuilder, group: list[tuple[tuple[str, str], Any]], ns: int) -> list[Sample]:
    """The samples of one instant: /vr/devices first, by device index, poses before inputs."""
    group.sort(key=lambda m: m[0][0] != "devices")
    out = rebuild.out
    out.clear()
    for (leaf, frame), msg in group:
        if leaf == "pose":
            p, q = msg.pose.position, msg.pose.orientation
            rebuild.pose(frame, ns, (p.x, p.y, p.z, q.x, q.y, q.z, q.w))
        elif leaf == "twist":
            v, w = msg.twist.linear, msg.twist.angular
            rebuild.twist(frame, ns, (v.x, v.y, v.z, w.x, w.y, w.z))
        elif leaf == "joy":
            rebuild.joy(frame, ns, int(getattr(msg.header, "seq", 0)), list(msg.axes), list(msg.buttons))
        else:
            rebuild.devices(ns, msg.data)
    done = sorted(out, key=lambda s: (s.device.index, isinstance(s, ControllerSample)))
    out.clear()
    return done


__all__ = ["INFO_TOPIC", "read_ros_folder"]
