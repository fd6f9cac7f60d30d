"""Replaying an MCAP recording (see `mcapfile` for what is in one).

The budget is a 10-minute recording (~375,000 samples, 1.1 million messages) in well under 10 s,
everything else included (conversion, writing the output): a few microseconds a message. So the
chunks' records are walked right here, in one loop that also decodes and rebuilds: /tf and
/tf_static are skipped by channel id without being sliced out, and a pose or twist whose bytes
before the numbers are those of the channel's first message (checked in full by `codecs`) has
its numbers unpacked straight from the chunk. Anything else takes the general decoders, so a
damaged or foreign message is refused as before.
"""

from __future__ import annotations

import json
import os
import zlib
from collections.abc import Iterator
from struct import Struct
from typing import Any

from ttctl.errors import Fail

from ..model import PoseSample, Sample
from .base import Recording
from .codecs import CDR, STRING, CodecError
from .mcapio import MAGIC, MESSAGE, MESSAGE_HEAD_SIZE, inner_record, iter_records, walk_error
from .ros import LEAVES, Rebuilder
from .ros import VERSION as ROS_VERSION

_FOOTER_OPCODE = 0x02
_FOOTER_SIZE = 1 + 8 + 8 + 8 + 4  # opcode, length, summary_start, summary_offset_start, summary_crc
_HEAD = Struct("<BQHIQQ")  # a Message record: opcode, length, channel_id, sequence, log_time, publish_time
_RECORD = Struct("<BQ")
_FOOTER = Struct("<BQQQI")
_U32 = Struct("<I")
_D3, _D4 = Struct("<3d"), Struct("<4d")
_NS = 1_000_000_000
_POSE, _TWIST, _JOY, _DEVICES, _BAD = range(5)


def _complete(path: str, size: int) -> bool:
    """Whether the file ends as a finished MCAP does: a Footer record, then the magic."""
    if size < len(MAGIC) * 2 + _FOOTER_SIZE:
        return False
    with open(path, "rb") as f:
        f.seek(size - len(MAGIC) - _FOOTER_SIZE)
        tail = f.read()
    return tail.endswith(MAGIC) and tail[0] == _FOOTER_OPCODE


def _summary_crc_error(path: str, size: int) -> str:
    """Why a finished file's Footer refuses its summary section ("" when its CRC matches or is 0,
    as the MCAP specification says readers check: from the summary's start through the footer's
    summary_offset_start)."""
    footer_at = size - len(MAGIC) - _FOOTER_SIZE
    with open(path, "rb") as f:
        f.seek(footer_at)
        footer = f.read(_FOOTER_SIZE)
        _, _, summary_start, _, crc = _FOOTER.unpack(footer)
        if crc == 0:
            return ""
        start = summary_start or footer_at
        if not len(MAGIC) <= start <= footer_at:
            return f"its footer points the summary at byte {summary_start}, outside the file"
        f.seek(start)
        body = f.read(footer_at - start)
    if zlib.crc32(footer[:-4], zlib.crc32(body)) != crc:
        return "damaged: its summary's CRC does not match (Foxglove's and mcap's readers refuse it)"
    return ""


def read_mcap(path: str) -> Recording:
    from mcap.records import Chunk, Metadata

    size = os.path.getsize(path)
    truncated = not _complete(path, size)
    damage = "" if truncated else _summary_crc_error(path, size)
    if truncated:
        damage = "cut short (no footer: the recording was interrupted)"
    info: dict[str, str] | None = None
    for rec in iter_records(path, size, truncated, chunks="record"):
        if isinstance(rec, Metadata) and rec.name == "ttctl":
            info = dict(rec.metadata)
            break
        if isinstance(rec, (Chunk, tuple)):  # the data has begun: ttctl writes its metadata first
            break
    if info is None:
        if not truncated:  # rewritten by a tool that drops metadata records: the messages still say it
            from .rosreplay import INFO_TOPIC, read_ros_folder

            try:
                rec = read_ros_folder(path)
                rec.damage = damage
                return rec
            except Fail as e:
                if INFO_TOPIC not in str(e):
                    raise
        what = "cut short before its first data" if truncated else "not recorded by ttctl hmd"
        raise Fail(f"{path}: no 'ttctl' metadata record: {what}")
    try:
        meta = json.loads(info.get("meta", "{}"))
        frame, parent = info["frame"], info["parent_frame"]
        version = int(info.get("version", "1"))
    except (ValueError, KeyError, RecursionError) as e:
        raise Fail(f"{path}: bad 'ttctl' metadata record ({e})") from None
    if version > ROS_VERSION:
        raise Fail(f"{path}: recording version {version}; this ttctl reads up to {ROS_VERSION}")
    if frame not in ("ros", "openvr") or not isinstance(meta, dict):
        raise Fail(f"{path}: bad 'ttctl' metadata record (frame {frame!r})")
    return Recording(frame, parent, meta, _Replay(path, truncated, version).samples(size), "mcap", truncated, damage)


class _Route:
    """What to do with one channel's messages. For poses and twists, `fast` is (record length,
    where the numbers start, the bytes from frame_id's length to the numbers) of the channel's
    first message, once it decoded."""

    __slots__ = ("fast", "frame", "kind", "topic", "why")

    def __init__(self, kind: int, frame: str, topic: str, why: str = "") -> None:
        self.kind, self.frame, self.topic, self.why = kind, frame, topic, why
        self.fast: tuple[int, int, bytes] | None = None


class _Replay:
    def __init__(self, path: str, truncated: bool, version: int) -> None:
        self.path, self.truncated = path, truncated
        self.rebuild = Rebuilder(path, version)
        self.schemas: dict[int, str] = {}
        self.routes: dict[int, _Route] = {}
        self.skip: set[int] = set()  # channels replay does not need (/tf, /tf_static, ...)

    def samples(self, size: int) -> Iterator[Sample]:
        from mcap.records import Channel, Schema

        out = self.rebuild.out
        for item in iter_records(self.path, size, self.truncated, self.skip, chunks="bytes"):
            if type(item) is bytes:
                try:
                    yield from self._walk(item)
                except (ValueError, IndexError, EOFError, UnicodeDecodeError) as e:  # struct.error is a ValueError
                    fail = walk_error(self.path, self.truncated, e)
                    if fail is not None:
                        raise fail from None
                    break  # the cut of a truncated file: what came before it still counts
            elif type(item) is tuple:  # a message outside chunks (not what ttctl writes, but valid)
                channel, sequence, ns, _, data = item
                self._message(channel, sequence, ns, data, 0, len(data), 0)
                yield from out
                out.clear()
            elif isinstance(item, Schema):
                self.schemas[item.id] = item.name
            elif isinstance(item, Channel):
                self._channel(item)
        self.rebuild.finish()
        yield from out

    def _channel(self, rec: Any) -> None:
        route = Rebuilder.route(rec.topic)
        if route is None:
            self.skip.add(rec.id)
            return
        msgtype = self.schemas.get(rec.schema_id, "")
        if msgtype != (STRING if route[0] == "devices" else LEAVES[route[0]]) or rec.message_encoding != "cdr":
            why = (f"{self.path}: topic {rec.topic!r} has type {msgtype or 'unknown'!r} ({rec.message_encoding!r}), "
                   "not what ttctl records")
            self.routes[rec.id] = _Route(_BAD, route[1], rec.topic, why)  # refused when a message comes
        else:
            kind = {"pose": _POSE, "twist": _TWIST, "joy": _JOY, "devices": _DEVICES}[route[0]]
            self.routes[rec.id] = _Route(kind, route[1], rec.topic)

    def _walk(self, data: bytes) -> Iterator[Sample]:
        """One chunk's records: the hot loop of replay. A pose whose twist follows at once (as
        ttctl writes them) becomes a sample right here; anything else goes through the Rebuilder,
        a pose held back being handed to it first, so the order of events is kept."""
        from mcap.records import Channel, Schema

        routes, skip, out = self.routes, self.skip, self.rebuild.out
        rebuild = self.rebuild
        devices, pending = rebuild.devices_by_frame, rebuild.pending
        head = _HEAD.unpack_from
        d3, d4 = _D3.unpack_from, _D4.unpack_from
        held: tuple[str, int, tuple[float, ...], tuple[float, ...]] | None = None  # a pose waiting for its twist
        pos, n = 0, len(data)
        try:
            while pos < n:
                if data[pos] == MESSAGE and pos + MESSAGE_HEAD_SIZE <= n:
                    _, length, channel, sequence, ns, _ = head(data, pos)
                    end = pos + 9 + length
                    if length < 22 or end > n:
                        raise ValueError(f"message record of {length} bytes at {pos} of a {n}-byte chunk")
                    route = routes.get(channel)
                    if route is None:
                        if channel not in skip:
                            raise Fail(f"{self.path}: damaged MCAP file (a message on unknown channel {channel})")
                        pos = end
                        continue
                    fast = route.fast
                    p = pos + MESSAGE_HEAD_SIZE
                    if (fast is not None and length == fast[0] and data[p] == 0 and data[p + 1] == 1
                            and data[p + 12:p + fast[1]] == fast[2]):
                        at = p + fast[1]
                        if route.kind == _POSE:
                            if held is not None:
                                rebuild.pose(held[0], held[1], held[2] + held[3])
                                held = None
                            if route.frame in pending:
                                rebuild.pose(route.frame, ns, d3(data, at) + d4(data, at + 24))
                            else:
                                held = (route.frame, ns, d3(data, at), d4(data, at + 24))
                        elif held is not None and held[0] == route.frame and held[1] == ns:
                            state = devices.get(route.frame)
                            if state is not None:
                                yield PoseSample(ns / _NS, state[0], True, state[2] is not False, held[2], held[3],
                                                 d3(data, at), d3(data, at + 24))
                            else:  # the Rebuilder words the error
                                rebuild.pose(held[0], held[1], held[2] + held[3])
                            held = None
                        else:
                            if held is not None:
                                rebuild.pose(held[0], held[1], held[2] + held[3])
                                held = None
                            rebuild.twist(route.frame, ns, d3(data, at) + d3(data, at + 24))
                    else:
                        if held is not None:
                            rebuild.pose(held[0], held[1], held[2] + held[3])
                            held = None
                        self._message(channel, sequence, ns, data, p, end, length)
                    if out:
                        yield from out
                        out.clear()
                    pos = end
                    continue
                if held is not None:
                    rebuild.pose(held[0], held[1], held[2] + held[3])
                    held = None
                opcode, length = _RECORD.unpack_from(data, pos)
                end = pos + 9 + length
                if end > n:
                    raise ValueError(f"record of {length} bytes at {pos} of a {n}-byte chunk")
                rec = inner_record(opcode, data[pos + 9:end])
                if isinstance(rec, Schema):
                    self.schemas[rec.id] = rec.name
                elif isinstance(rec, Channel):
                    self._channel(rec)
                pos = end
        except Exception:
            if held is not None and held[0] in devices:  # as if the Rebuilder had had it all along
                rebuild.pose(held[0], held[1], held[2] + held[3])
            raise
        if held is not None:
            rebuild.pose(held[0], held[1], held[2] + held[3])
        if out:
            yield from out
            out.clear()

    def _message(self, channel: int, sequence: int, ns: int, data: bytes, start: int, end: int, length: int) -> None:
        """Any message, through the general decoders (the first of each pose and twist channel
        sets up the fast path)."""
        route = self.routes.get(channel)
        if route is None:
            if channel in self.skip:
                return
            raise Fail(f"{self.path}: damaged MCAP file (a message on unknown channel {channel})")
        body = data[start:end]
        rebuild = self.rebuild
        try:
            if route.kind == _POSE or route.kind == _TWIST:
                values = (CDR.pose_values if route.kind == _POSE else CDR.twist_values)(body)
                if route.fast is None and length:
                    end = 16 + _U32.unpack_from(body, 12)[0]  # frame_id's length at 12, its bytes from 16
                    where = end + (-(end - 4) & 7)  # the numbers, aligned to 8 from the encapsulation's end
                    route.fast = (length, where, body[12:where])
                (rebuild.pose if route.kind == _POSE else rebuild.twist)(route.frame, ns, values)
            elif route.kind == _JOY:
                _, _, _, _, axes, buttons = CDR.decode_joy(body)
                rebuild.joy(route.frame, ns, sequence, axes, buttons)
            elif route.kind == _DEVICES:
                rebuild.devices(ns, CDR.decode_string(body))
            else:
                raise Fail(route.why)
        except CodecError as e:
            raise Fail(f"{self.path}: undecodable message on {route.topic!r} ({e})") from None


__all__ = ["read_mcap"]
