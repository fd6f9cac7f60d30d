"""Replaying a ROS 1 bag recording (see `bagfile` for what is in one).

rosbags' Reader reads every chunk's index into memory when it opens a bag (~10 s of a 10-minute
recording's replay, twice: once for the /vr/recording message, once for the samples) and then
fetches each message through its index (~15 us a message). A recording replays front to back,
so here the bag's header, connections and chunk list are read with rosbags' own record readers
and the chunks are then walked in file order, each message record's header unpacked with one
Struct when it has the layout rosbags writes (any other goes through rosbags' Header parser).
The order is still rosbags': by time, and at equal times by connection (in the bag's connection
order), which is what the chunks give when their time ranges follow one another, as they do in
any bag written in time order; a bag whose chunks overlap in time is read with rosbags' Reader.
"""

from __future__ import annotations

import json
import os
from collections.abc import Iterator
from io import BytesIO
from itertools import pairwise
from struct import Struct
from typing import Any

from ttctl.errors import Fail

from ..model import ControllerSample, Sample
from .bagfile import INFO_TOPIC
from .base import Recording
from .codecs import ROS1, STRING
from .ros import LEAVES, TYPES, Rebuilder, typestore
from .ros import VERSION as ROS_VERSION

# a message record as rosbags writes it: header length 38, fields op=0x02, conn=<u32>, time=<u32 u32>
_MSG_HEAD = b"\x26\x00\x00\x00\x04\x00\x00\x00op=\x02\x09\x00\x00\x00conn="
_TIME_FIELD = b"\x0d\x00\x00\x00time="
_MSG_FIELDS = Struct("<I9xIII")  # conn, (the time field's length and name), sec, nsec, data length
_U32 = Struct("<I")
_NS = 1_000_000_000


def expected_md5(msgtype: str) -> str:
    return str(typestore(1).generate_msgdef(msgtype)[1])


class _Bag:
    """A bag opened as rosbags' Reader.open() does, minus reading every chunk's index."""

    def __init__(self, path: str) -> None:
        from rosbags.rosbag1 import Reader

        self.path = path
        self.reader = Reader(path)
        self.connections: list[Any] = []
        self.chunk_infos: list[Any] = []

    def open(self) -> _Bag:
        try:
            self._open()
        except Exception as e:  # ReaderError, and struct errors or asserts on garbage
            self.close()
            text = str(e) or type(e).__name__
            if "not indexed" in text:
                raise Fail(f"{self.path}: the bag has no index (recording cut short); `rosbag reindex` can "
                           "rebuild it") from None
            raise Fail(f"{self.path}: not a readable ROS 1 bag ({text})") from None
        return self

    def _open(self) -> None:
        import re

        from rosbags.rosbag1.reader import Header, ReaderError, RecordType

        r = self.reader
        r.bio = bio = open(self.path, "rb")  # noqa: SIM115 - closed by close()
        magic = bio.readline().decode()
        if not magic:
            raise ReaderError(f"File {self.path!r} seems to be empty.")
        found = re.match(r"#ROSBAG V(\d+).(\d+)\n", magic)
        if not found:
            raise ReaderError("File magic is invalid.")
        if int(found.group(1)) * 100 + int(found.group(2)) != 200:
            raise ReaderError(f"Bag version {found.group(1)}.{found.group(2)} is not supported.")
        header = Header.read(bio, RecordType.BAGHEADER)
        index_pos = header.get_uint64("index_pos")
        conn_count, chunk_count = header.get_uint32("conn_count"), header.get_uint32("chunk_count")
        if "encryptor" in header and header.get_string("encryptor"):
            raise ReaderError(f"Bag encryption {header.get_string('encryptor')!r} is not supported.")
        if index_pos == 0:
            raise ReaderError("Bag is not indexed, reindex before reading.")
        size = os.fstat(bio.fileno()).st_size
        if index_pos >= size:
            raise ReaderError(f"cut short: its index should start at byte {index_pos} but the file has {size} "
                              "bytes; `rosbag reindex` can rebuild the index")
        if chunk_count == 0:
            return
        bio.seek(index_pos)
        try:
            self.connections = [r.read_connection() for _ in range(conn_count)]
            self.chunk_infos = [r.read_chunk_info() for _ in range(chunk_count)]
        except ReaderError as e:
            raise ReaderError(f"its index is damaged ({'; '.join(str(a) for a in e.args)})") from None

    def close(self) -> None:
        bio, self.reader.bio = self.reader.bio, None
        if bio is not None:
            bio.close()

    def in_order(self) -> bool:
        """Whether the chunks, in file order, follow one another in time (rosbags' end_time is
        one past the last message)."""
        infos = sorted(self.chunk_infos, key=lambda c: c.pos)
        return all(a.end_time - 1 <= b.start_time for a, b in pairwise(infos))

    def chunk_messages(self, info: Any, wanted: dict[int, Any]) -> list[tuple[int, Any, bytes]]:
        """(time, wanted[conn], data) of the chunk's messages on the wanted connections, in file
        order, checked against the chunk's index records (as rosbags checks each message it
        fetches against its index entry: a bag has no checksums)."""
        from rosbags.rosbag1.reader import Header, read_bytes

        r = self.reader
        r.bio.seek(info.pos)
        chunk = r.read_chunk()  # the chunk's header (it leaves the file after the chunk's data)
        r.bio.seek(chunk.datapos)
        data = chunk.decompressor(read_bytes(r.bio, chunk.datasize))
        out: list[tuple[int, Any, bytes]] = []
        seen: dict[int, list[int]] = {conn: [] for conn in wanted}  # conn -> time, offset, time, offset, ...
        pos, n = 0, len(data)
        fields = _MSG_FIELDS.unpack_from
        while pos < n:
            if data.startswith(_MSG_HEAD, pos) and data.startswith(_TIME_FIELD, pos + 25):
                conn, sec, nsec, size = fields(data, pos + 21)
                start = pos + 46
                ns = sec * _NS + nsec
            else:
                (hlen,) = _U32.unpack_from(data, pos)
                start = pos + 8 + hlen
                (size,) = _U32.unpack_from(data, start - 4)
                if _op(data, pos + 4, start - 4) != 2:  # a connection record: nothing to replay
                    pos = start + size
                    continue
                src = BytesIO(data)
                src.seek(pos)
                header = Header.read(src)
                conn, ns = header.get_uint32("conn"), header.get_time("time")
            end = start + size
            if end > n:
                raise ValueError(f"a record of {size} bytes at {start} of a {n}-byte chunk")
            route = wanted.get(conn)
            if route is not None:
                out.append((ns, route, data[start:end]))
                entries = seen[conn]
                entries.append(ns)
                entries.append(pos)
            pos = end
        self._check_index(info, seen)
        return out

    def _check_index(self, info: Any, seen: dict[int, list[int]]) -> None:
        """The index records after the chunk list, per connection, (time, offset) of its
        messages: those of the wanted connections must be what the chunk holds."""
        from rosbags.rosbag1.reader import Header, RecordType, read_bytes, read_uint32

        bio = self.reader.bio
        indexed: dict[int, list[int]] = {}
        for _ in range(len(info.connection_counts)):
            header = Header.read(bio, RecordType.IDXDATA)
            if header.get_uint32("ver") != 1:
                raise ValueError("unknown index record version")
            conn, count = header.get_uint32("conn"), header.get_uint32("count")
            raw = read_bytes(bio, read_uint32(bio))
            if conn not in seen:
                continue
            if len(raw) != 12 * count:
                raise ValueError(f"index record of connection {conn}: {len(raw)} bytes for {count} entries")
            entries = indexed[conn] = []
            for sec, nsec, offset in _INDEX_ENTRY.iter_unpack(raw):
                entries.append(sec * _NS + nsec)
                entries.append(offset)
        for conn, entries in seen.items():
            if entries != indexed.get(conn, []):
                raise ValueError(f"the chunk at {info.pos} does not hold what its index says (connection {conn})")


def _op(data: bytes, pos: int, end: int) -> int:
    """The op field of a record header that is not laid out as rosbags lays out a message's."""
    while pos < end:
        (size,) = _U32.unpack_from(data, pos)
        if data.startswith(b"op=", pos + 4) and size == 4:
            return data[pos + 7]
        pos += 4 + size
    raise ValueError("a record header without its op field")


_INDEX_ENTRY = Struct("<III")  # sec, nsec, offset of the message record in the chunk


def read_bag(path: str) -> Recording:
    bag = _Bag(path).open()
    try:
        for conn in bag.connections:
            if conn.msgtype in TYPES and conn.digest != expected_md5(conn.msgtype):
                raise Fail(f"{path}: topic {conn.topic!r} has {conn.msgtype} with md5sum {conn.digest!r}, "
                           f"expected {expected_md5(conn.msgtype)}")
        info_ids = {c.id: c for c in bag.connections if c.topic == INFO_TOPIC and c.msgtype == STRING}
        raw = None
        if info_ids:
            try:
                raw = _first_message(bag, info_ids)
            except Exception as e:  # damage shows as many kinds of error
                raise Fail(f"{path}: damaged bag ({str(e) or type(e).__name__})") from None
        if raw is None:
            raise Fail(f"{path}: no {INFO_TOPIC} message: not recorded by ttctl hmd")
        try:
            info = json.loads(ROS1.decode_string(raw))
            frame, parent, meta = info["frame"], info["parent_frame"], info.get("meta", {})
            version = int(info.get("version", 1))
        except (ValueError, KeyError, TypeError, RecursionError) as e:  # CodecError is a ValueError
            raise Fail(f"{path}: bad {INFO_TOPIC} message ({e})") from None
        if version > ROS_VERSION:
            raise Fail(f"{path}: recording version {version}; this ttctl reads up to {ROS_VERSION}")
        if frame not in ("ros", "openvr") or not isinstance(parent, str) or not isinstance(meta, dict):
            raise Fail(f"{path}: bad {INFO_TOPIC} message (frame {frame!r})")
    finally:
        bag.close()
    return Recording(frame, parent, meta, _samples(path, version), "bag")


def _first_message(bag: _Bag, conns: dict[int, Any]) -> bytes | None:
    """The earliest message on these connections (ties: the first connection, then file order)."""
    if not bag.in_order():
        reader = _rosbags_open(bag.path)
        try:
            first = next(iter(reader.messages(connections=list(conns.values()))), None)
        finally:
            reader.close()
        return None if first is None else bytes(first[2])
    rank = {c.id: k for k, c in enumerate(bag.connections)}
    for info in sorted(bag.chunk_infos, key=lambda c: c.pos):
        found = bag.chunk_messages(info, {cid: rank[cid] for cid in conns})
        if found:
            return min(found, key=lambda m: (m[0], m[1]))[2]
    return None


def _rosbags_open(path: str) -> Any:
    from rosbags.rosbag1 import Reader

    reader = Reader(path)
    try:
        reader.open()
    except Exception as e:  # as in _Bag.open
        raise Fail(f"{path}: not a readable ROS 1 bag ({str(e) or type(e).__name__})") from None
    return reader


def _routes(path: str, connections: list[Any]) -> dict[int, tuple[int, str, str]]:
    """(rank in the bag's connection order, leaf, frame) of each connection replay reads."""
    routes: dict[int, tuple[int, str, str]] = {}
    for rank, conn in enumerate(connections):
        route = Rebuilder.route(conn.topic)
        if route is None:
            continue
        if conn.msgtype not in TYPES:
            raise Fail(f"{path}: topic {conn.topic!r} has type {conn.msgtype!r}, not what ttctl records")
        if conn.msgtype != (STRING if route[0] == "devices" else LEAVES[route[0]]):
            raise Fail(f"{path}: topic {conn.topic!r} has type {conn.msgtype!r}, not what ttctl records there")
        routes[conn.id] = (rank, route[0], route[1])
    return routes


def _samples(path: str, version: int) -> Iterator[Sample]:
    bag = _Bag(path).open()
    try:
        routes = _routes(path, bag.connections)
        if not bag.in_order():
            bag.close()
            yield from _samples_rosbags(path, routes, version)
            return
        rebuild = Rebuilder(path, version)
        group: list[tuple[tuple[int, str, str], Any]] = []  # the messages of one instant
        group_ns = -1
        for info in sorted(bag.chunk_infos, key=lambda c: c.pos) if routes else ():
            try:
                messages = bag.chunk_messages(info, routes)
                if any(a[0] > b[0] for a, b in pairwise(messages)):
                    messages.sort(key=lambda m: (m[0], m[1][0]))  # as rosbags' merge of the connections
                for ns, route, raw in messages:
                    msg = _decode(route[1], raw)
                    if ns != group_ns:
                        yield from _instant(rebuild, group, group_ns)
                        group, group_ns = [], ns
                    group.append((route, msg))
            except Fail:
                raise
            except Exception as e:  # the reader raises many kinds on damage; CodecError
                raise Fail(f"{path}: damaged bag ({str(e) or type(e).__name__})") from None
        yield from _instant(rebuild, group, group_ns)
        rebuild.finish()
        yield from rebuild.out
    finally:
        bag.close()


def _decode(leaf: str, raw: bytes) -> Any:
    if leaf == "pose":
        return ROS1.pose_values(raw)
    if leaf == "twist":
        return ROS1.twist_values(raw)
    if leaf == "joy":
        return ROS1.decode_joy(raw)
    return ROS1.decode_string(raw)


def _samples_rosbags(path: str, routes: dict[int, tuple[int, str, str]],
                     version: int = ROS_VERSION) -> Iterator[Sample]:
    """rosbags' Reader, for bags whose chunks overlap in time."""
    rebuild = Rebuilder(path, version)
    reader = _rosbags_open(path)
    try:
        conns = [c for c in reader.connections if c.id in routes]
        messages = iter(reader.messages(connections=conns)) if conns else iter(())
        group: list[tuple[tuple[int, str, str], Any]] = []
        group_ns = -1
        while True:
            try:
                conn, ns, raw = next(messages)
                route = routes[conn.id]
                msg = _decode(route[1], raw)
            except StopIteration:
                break
            except Exception as e:  # the reader asserts and raises many kinds on damage; CodecError
                raise Fail(f"{path}: damaged bag ({str(e) or type(e).__name__})") from None
            if ns != group_ns:
                yield from _instant(rebuild, group, group_ns)
                group, group_ns = [], ns
            group.append((route, msg))
        yield from _instant(rebuild, group, group_ns)
        rebuild.finish()
        yield from rebuild.out
    finally:
        reader.close()


def _instant(rebuild: Rebuilder, group: list[tuple[tuple[int, str, str], Any]], ns: int) -> list[Sample]:
    """The samples of one instant. rosbags orders messages of equal time by connection, not by
    their place in the file, so within an instant /vr/devices goes first, then the connections
    in the bag's order, and the samples come out by device index, poses before controller inputs."""
    if len(group) > 1:
        group.sort(key=lambda m: (m[0][1] != "devices", m[0][0]))
    out = rebuild.out
    out.clear()
    for (_, leaf, frame), msg in group:
        if leaf == "pose":
            rebuild.pose(frame, ns, msg)
        elif leaf == "twist":
            rebuild.twist(frame, ns, msg)
        elif leaf == "joy":
            rebuild.joy(frame, ns, msg[0], msg[4], msg[5])
        else:
            rebuild.devices(ns, msg)
    done = out[:] if len(out) == 1 else sorted(out, key=lambda s: (s.device.index, isinstance(s, ControllerSample)))
    out.clear()
    return done


__all__ = ["expected_md5", "read_bag"]
