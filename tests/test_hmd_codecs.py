"""ttctl's own codecs of the ROS messages it records (struct-based, for speed) against rosbags,
the source of truth: the same bytes for many random messages (string lengths that exercise CDR
padding, NaN/inf/huge numbers, empty and non-ASCII strings), the same values back, and the same
verdict (decodes or not) on damaged bytes. Also the MCAP message iterator against the mcap
library's reader."""

from __future__ import annotations

import io
import math
import random
from typing import Any

import numpy as np
import pytest

from ttctl.hmd.formats.codecs import CDR, JOY, POSE, ROS1, STRING, TF, TWIST, Codec, CodecError

pytest.importorskip("rosbags")

NAMES = ["", "a", "ab", "abc", "abcd", "hmd", "world", "vr_world", "controller_left", "base_station_LHB_1234ABCD",
         "tracker_\u00e9\u00e8", "\u4e16\u754c", "x" * 31, "y" * 64, "z\x00z"]
SPECIAL = [0.0, -0.0, 1.0, -1.5, math.nan, math.inf, -math.inf, 1e308, -1e308, 5e-324, 3.5e38, -3.5e38, 1e39,
           3.4028235e38, 2.5e-46, 1e-40]


def _store(ros: int) -> Any:
    from rosbags.typesys import Stores, get_types_from_msg, get_typestore

    if ros == 2:
        return get_typestore(Stores.ROS2_HUMBLE)
    store = get_typestore(Stores.ROS1_NOETIC)
    store.register(get_types_from_msg("geometry_msgs/TransformStamped[] transforms", TF))
    return store


STORES = {1: _store(1), 2: _store(2)}
CODECS = {1: ROS1, 2: CDR}


def _num(rng: random.Random) -> float:
    r = rng.random()
    if r < 0.25:
        return rng.choice(SPECIAL)
    if r < 0.5:
        return rng.uniform(-1, 1)
    return rng.gauss(0, 10) * 10 ** rng.randint(-30, 30)


def _nums(rng: random.Random, n: int) -> tuple[float, ...]:
    return tuple(_num(rng) for _ in range(n))


def _head(store: Any, ros: int, seq: int, sec: int, nsec: int, frame: str) -> Any:
    T = store.types
    stamp = T["builtin_interfaces/msg/Time"](sec=sec, nanosec=nsec)
    if ros == 1:
        return T["std_msgs/msg/Header"](seq=seq, stamp=stamp, frame_id=frame)
    return T["std_msgs/msg/Header"](stamp=stamp, frame_id=frame)


def _random_message(rng: random.Random, ros: int, msgtype: str) -> tuple[Any, Any, bytes]:
    """(rosbags object, what our decoder should give, our encoding)."""
    store, codec = STORES[ros], CODECS[ros]
    T = store.types
    seq = rng.randrange(2**32) if ros == 1 else 0
    sec, nsec = rng.randrange(-(2**31), 2**31), rng.randrange(2**32)
    frame = rng.choice(NAMES)
    if msgtype in (POSE, TWIST):
        v = _nums(rng, 7 if msgtype == POSE else 6)
        vec, point = T["geometry_msgs/msg/Vector3"], T["geometry_msgs/msg/Point"]
        if msgtype == POSE:
            body = T["geometry_msgs/msg/Pose"](position=point(x=v[0], y=v[1], z=v[2]), orientation=T[
                "geometry_msgs/msg/Quaternion"](x=v[3], y=v[4], z=v[5], w=v[6]))
            obj = T[POSE](header=_head(store, ros, seq, sec, nsec, frame), pose=body)
            ours = codec.pose(seq, sec, nsec, frame, v)
        else:
            body = T["geometry_msgs/msg/Twist"](linear=vec(x=v[0], y=v[1], z=v[2]),
                                                angular=vec(x=v[3], y=v[4], z=v[5]))
            obj = T[TWIST](header=_head(store, ros, seq, sec, nsec, frame), twist=body)
            ours = codec.twist(seq, sec, nsec, frame, v)
        return obj, (seq, sec, nsec, frame, v), ours
    if msgtype == TF:
        items, objs = [], []
        for _ in range(rng.choice((0, 1, 1, 1, 2, 3))):
            seq, sec, nsec = (rng.randrange(2**32) if ros == 1 else 0), rng.randrange(2**31), rng.randrange(10**9)
            frame, child, v = rng.choice(NAMES), rng.choice(NAMES), _nums(rng, 7)
            items.append((seq, sec, nsec, frame, child, v))
            objs.append(T["geometry_msgs/msg/TransformStamped"](
                header=_head(store, ros, seq, sec, nsec, frame), child_frame_id=child,
                transform=T["geometry_msgs/msg/Transform"](
                    translation=T["geometry_msgs/msg/Vector3"](x=v[0], y=v[1], z=v[2]),
                    rotation=T["geometry_msgs/msg/Quaternion"](x=v[3], y=v[4], z=v[5], w=v[6]))))
        return T[TF](transforms=objs), items, codec.tf(items)
    if msgtype == JOY:
        axes = _nums(rng, rng.choice((0, 1, 3, 3, 3, 4, 7)))
        buttons = tuple(rng.choice((0, 1, 1, -(2**31), 2**31 - 1, 7)) for _ in range(rng.choice((0, 1, 5, 5, 6))))
        with np.errstate(over="ignore"):
            f32 = np.array(axes, dtype=np.float32)
        obj = T[JOY](header=_head(store, ros, seq, sec, nsec, frame), axes=f32,
                     buttons=np.array(buttons, dtype=np.int32))
        return obj, (seq, sec, nsec, frame, tuple(float(a) for a in f32), buttons), codec.joy(
            seq, sec, nsec, frame, axes, buttons)
    text = rng.choice([*NAMES, '{"index":3,"kind":"controller"}', "\u00fc" * rng.randrange(40)])
    return T[STRING](data=text), text, codec.string(text)


def _same(a: Any, b: Any) -> bool:
    """Equal, with NaN equal to NaN and -0.0 told from 0.0."""
    if isinstance(a, (tuple, list)) and isinstance(b, (tuple, list)):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b, strict=True))
    if isinstance(a, float) or isinstance(b, float):
        fa, fb = float(a), float(b)
        return (math.isnan(fa) and math.isnan(fb)) or (fa == fb and math.copysign(1, fa) == math.copysign(1, fb))
    return bool(a == b)


TYPES = [POSE, TWIST, TF, JOY, STRING]


@pytest.mark.parametrize("ros", [1, 2])
@pytest.mark.parametrize("msgtype", TYPES)
def test_encoders_match_rosbags_byte_for_byte(ros: int, msgtype: str) -> None:
    store, codec = STORES[ros], CODECS[ros]
    rng = random.Random(f"{ros}{msgtype}")
    for _ in range(400):
        obj, _, ours = _random_message(rng, ros, msgtype)
        theirs = bytes(store.serialize_cdr(obj, msgtype, little_endian=True) if ros == 2
                       else store.serialize_ros1(obj, msgtype))
        assert ours == theirs, (obj, ours.hex(), theirs.hex())
        assert isinstance(codec, Codec)


def _ours_from_rosbags(msg: Any, msgtype: str, ros: int) -> Any:
    def head(h: Any) -> tuple[Any, ...]:
        return (h.seq if ros == 1 else 0), h.stamp.sec, h.stamp.nanosec, h.frame_id

    if msgtype == POSE:
        p, q = msg.pose.position, msg.pose.orientation
        return (*head(msg.header), (p.x, p.y, p.z, q.x, q.y, q.z, q.w))
    if msgtype == TWIST:
        v, w = msg.twist.linear, msg.twist.angular
        return (*head(msg.header), (v.x, v.y, v.z, w.x, w.y, w.z))
    if msgtype == JOY:
        return (*head(msg.header), tuple(float(a) for a in msg.axes), tuple(int(b) for b in msg.buttons))
    if msgtype == TF:
        return [(*head(tr.header), tr.child_frame_id,
                 (tr.transform.translation.x, tr.transform.translation.y, tr.transform.translation.z,
                  tr.transform.rotation.x, tr.transform.rotation.y, tr.transform.rotation.z, tr.transform.rotation.w))
                for tr in msg.transforms]
    return msg.data


def _theirs(store: Any, ros: int, data: bytes, msgtype: str) -> Any:
    return store.deserialize_cdr(data, msgtype) if ros == 2 else store.deserialize_ros1(data, msgtype)


@pytest.mark.parametrize("ros", [1, 2])
@pytest.mark.parametrize("msgtype", TYPES)
def test_decoders_match_rosbags(ros: int, msgtype: str) -> None:
    store, codec = STORES[ros], CODECS[ros]
    rng = random.Random(f"decode{ros}{msgtype}")
    for _ in range(300):
        _, want, data = _random_message(rng, ros, msgtype)
        got = codec.decode(msgtype, data)
        assert _same(got, want), (got, want)
        assert _same(got, _ours_from_rosbags(_theirs(store, ros, data, msgtype), msgtype, ros))
        assert _same(codec.decode(msgtype, memoryview(data)), want)
        if msgtype in (POSE, TWIST):  # replay's shortcut: the numbers only
            assert _same((codec.pose_values if msgtype == POSE else codec.twist_values)(data), want[4])
        if ros == 2:  # trailing CDR padding (up to 3 bytes) is accepted, as rosbags does
            assert _same(codec.decode(msgtype, data + b"\x00" * 3), want)


@pytest.mark.parametrize("ros", [1, 2])
@pytest.mark.parametrize("msgtype", TYPES)
def test_damaged_messages_decode_or_fail_as_rosbags_does(ros: int, msgtype: str) -> None:
    store, codec = STORES[ros], CODECS[ros]
    rng = random.Random(f"damage{ros}{msgtype}")
    for _ in range(400):
        _, _, data = _random_message(rng, ros, msgtype)
        bad = bytearray(data)
        how = rng.randrange(4)
        if how == 0 and bad:
            del bad[rng.randrange(len(bad)):]
        elif how == 1:
            bad += bytes(rng.randrange(256) for _ in range(rng.randint(1, 9)))
        else:
            for _ in range(rng.randint(1, 3)):
                if bad:
                    bad[rng.randrange(min(len(bad), 24 if how == 2 else len(bad)))] = rng.randrange(256)
        try:
            theirs: Any = _ours_from_rosbags(_theirs(store, ros, bytes(bad), msgtype), msgtype, ros)
        except Exception:  # rosbags' SerdeError (and numpy's errors on huge counts)
            theirs = CodecError
        try:
            ours: Any = codec.decode(msgtype, bytes(bad))
        except CodecError:
            ours = CodecError
        assert (ours is CodecError) == (theirs is CodecError), (bytes(bad).hex(), ours, theirs)
        if ours is not CodecError:
            assert _same(ours, theirs)
        if msgtype in (POSE, TWIST):
            try:
                values: Any = (codec.pose_values if msgtype == POSE else codec.twist_values)(bytes(bad))
            except CodecError:
                values = CodecError
            assert values is CodecError if ours is CodecError else _same(values, ours[4])


def test_big_endian_cdr_is_decoded_by_rosbags() -> None:
    store = STORES[2]
    T = store.types
    obj = T[STRING](data="big end")
    data = bytes(store.serialize_cdr(obj, STRING, little_endian=False))
    assert data[:2] == b"\x00\x00" and CDR.decode_string(data) == "big end"
    with pytest.raises(CodecError):
        CDR.decode_string(b"\x01\x01\x00\x00\x01\x00\x00\x00\x00")


def test_struct_formats_can_carry_a_record_header() -> None:
    """The MCAP writer packs its record header and the message in one struct."""
    from struct import Struct

    fmt = CDR.stamped_format(len(b"vr_world"), 7)
    st = Struct("<BQ" + fmt)
    v = (1.0, 2.0, 3.0, 0.0, 0.0, 0.0, 1.0)
    packed = st.pack(5, 99, b"\x00\x01\x00\x00", 12, 34, 9, b"vr_world", *v)
    assert packed[9:] == CDR.pose(0, 12, 34, "vr_world", v)


# ------------------------------------------------------------------------------------------------ MCAP


def _mcap_messages_theirs(path: str) -> list[tuple[str, int, int, int, bytes]]:
    from mcap.reader import make_reader

    with open(path, "rb") as f:
        return [(c.topic, m.sequence, m.log_time, m.publish_time, m.data)
                for _, c, m in make_reader(f).iter_messages(log_time_order=False)]


def _mcap_messages_ours(path: str) -> list[tuple[str, int, int, int, bytes]]:
    import os

    from mcap.records import Channel

    from ttctl.hmd.formats.mcapio import iter_records

    topics: dict[int, str] = {}
    out = []
    for rec in iter_records(path, os.path.getsize(path), False):
        if isinstance(rec, Channel):
            topics[rec.id] = rec.topic
        elif isinstance(rec, tuple):
            ch, seq, log_time, publish_time, data = rec
            out.append((topics[ch], seq, log_time, publish_time, bytes(data)))
    return out


def _library_file(path: str, compression: str, chunk_size: int, seed: int) -> None:
    from mcap.writer import CompressionType, Writer

    rng = random.Random(seed)
    kinds = {"": CompressionType.NONE, "zstd": CompressionType.ZSTD, "lz4": CompressionType.LZ4}
    with open(path, "wb") as f:
        w = Writer(f, chunk_size=chunk_size, compression=kinds[compression])
        w.start(profile="ros2", library="test")
        w.add_metadata("m", {"k": "v"})
        schema = w.register_schema(POSE, "ros2msg", b"...")
        channels = [w.register_channel(f"/t{k}", "cdr", schema, {"a": str(k)}) for k in range(3)]
        other = w.register_channel("/raw", "", 0)
        t = 1_700_000_000_000_000_000
        for k in range(3000):
            t += rng.randrange(0, 3_000_000)
            ch = rng.choice([*channels, other])
            w.add_message(ch, log_time=t, data=bytes(rng.randrange(256) for _ in range(rng.randrange(0, 90))),
                          publish_time=t - rng.randrange(1000), sequence=k)
            if k == 1500:
                channels.append(w.register_channel("/late", "cdr", schema, {}))
        w.finish()


@pytest.mark.parametrize("compression", ["", "zstd", "lz4"])
@pytest.mark.parametrize("chunk_size", [512, 16 * 1024, 1 << 20])
def test_mcap_iterator_yields_what_the_mcap_library_yields(tmp_path: Any, compression: str, chunk_size: int) -> None:
    path = str(tmp_path / "lib.mcap")
    _library_file(path, compression, chunk_size, seed=chunk_size)
    theirs = _mcap_messages_theirs(path)
    assert len(theirs) == 3000
    assert _mcap_messages_ours(path) == theirs


def test_mcap_iterator_on_ttctl_recordings(tmp_path: Any) -> None:
    from hmd_recordings import make_samples
    from ttctl.hmd.formats import mcapfile, open_writer

    for chunk_size in (4096, 1 << 20):
        mcapfile.CHUNK_SIZE, saved = chunk_size, mcapfile.CHUNK_SIZE
        try:
            path = str(tmp_path / f"rec{chunk_size}.mcap")
            with open_writer(path, "mcap", "ros", "vr_world", {}) as w:
                for s in make_samples(1.0):
                    w.write(s)
        finally:
            mcapfile.CHUNK_SIZE = saved
        theirs = _mcap_messages_theirs(path)
        assert _mcap_messages_ours(path) == theirs and len(theirs) > 500


@pytest.mark.parametrize("compression", ["", "zstd", "lz4"])
def test_mcap_chunk_writer_writes_what_the_mcap_library_writes(compression: str) -> None:
    """Byte for byte: the same chunks, message indexes, summary and footer as mcap's Writer."""
    from mcap.writer import CompressionType, Writer

    from ttctl.hmd.formats.mcapio import ChunkWriter

    kinds = {"": CompressionType.NONE, "zstd": CompressionType.ZSTD, "lz4": CompressionType.LZ4}
    rng = random.Random(compression)
    plan: list[tuple[Any, ...]] = []
    t = 1_700_000_000_000_000_000
    for k in range(4000):
        t += rng.randrange(-1000, 2_000_000)  # not quite in order: chunk and file times are min / max
        plan.append(("msg", rng.randrange(1, 4), t, bytes(rng.randrange(256) for _ in range(rng.randrange(90))),
                     t + 5, k % 7))
        if k == 2000:
            plan.append(("channel", "/late"))
    for chunk_size in (300, 8192, 1 << 20):
        outs = []
        for ours in (False, True):
            buf = io.BytesIO()
            w: Any = (ChunkWriter(buf, chunk_size=chunk_size, compression=compression) if ours
                      else Writer(buf, chunk_size=chunk_size, compression=kinds[compression]))
            w.start(profile="ros2", library="x")
            w.add_metadata("rosbag2", {"ROS_DISTRO": "humble"})
            w.add_metadata("ttctl", {"a": "b", "c": "\u00e9"})
            s1 = w.register_schema(POSE, "ros2msg", b"schema one")
            s2 = w.register_schema(STRING, "ros2msg", b"schema two")
            for topic, schema in (("/a", s1), ("/b", s2), ("/c", s1)):
                w.register_channel(topic, "cdr", schema, {"offered_qos_profiles": topic * 3})
            for step in plan:
                if step[0] == "channel":
                    w.register_channel(step[1], "cdr", s2, {})
                else:
                    _, ch, log_time, data, publish_time, seq = step
                    w.add_message(ch, log_time=log_time, data=data, publish_time=publish_time, sequence=seq)
            w.finish()
            outs.append(buf.getvalue())
        assert outs[0] == outs[1], chunk_size


def test_mcap_chunk_writer_empty_file_matches_the_library() -> None:
    from mcap.writer import Writer

    from ttctl.hmd.formats.mcapio import ChunkWriter

    outs = []
    for cls in (Writer, ChunkWriter):
        buf = io.BytesIO()
        w: Any = cls(buf)
        w.start(profile="ros2", library="x")
        w.add_metadata("ttctl", {})
        w.register_channel("/a", "cdr", w.register_schema(POSE, "ros2msg", b"s"), {})
        w.finish()
        outs.append(buf.getvalue())
    assert outs[0] == outs[1]


def _odd_mcap(path: str, seed: int, chunk_size: int) -> None:
    """A ttctl-like MCAP written by the mcap library, with what ttctl itself never writes: twists
    before poses, poses without twists and twists without poses, two poses of one instant,
    trailing CDR padding, big-endian messages, unknown topics, pose and twist split across
    chunks."""
    import json

    from mcap.writer import Writer

    from ttctl.hmd.formats.ros import typestore

    rng = random.Random(seed)
    store = STORES[2]
    T = store.types
    with open(path, "wb") as f:
        w = Writer(f, chunk_size=chunk_size)
        w.start(profile="ros2", library="test")
        w.add_metadata("ttctl", {"format": "ttctl.hmd", "version": "1", "frame": "ros", "parent_frame": "world",
                                 "meta": "{}"})
        schemas = {t: w.register_schema(t, "ros2msg", typestore(2).generate_msgdef(t, ros_version=2)[0].encode())
                   for t in (POSE, TWIST, STRING, TF, JOY)}
        channels: dict[str, int] = {}

        def put(topic: str, msgtype: str, ns: int, data: bytes, seq: int = 0) -> None:
            if topic not in channels:
                channels[topic] = w.register_channel(topic, "cdr", schemas[msgtype])
            w.add_message(channels[topic], log_time=ns, data=data, publish_time=ns, sequence=seq)

        frames = ["hmd", "controller_left", "tracker_X1"]
        for i, frame in enumerate(frames):
            kind = frame.split("_")[0]
            put("/vr/devices", STRING, 10**18, CDR.string(json.dumps(
                {"index": i, "kind": kind, "role": "left" if "left" in frame else "none",
                 "serial": "X1" if kind == "tracker" else "", "frame": frame, "valid": True, "connected": True})))
        ns = 10**18
        for _ in range(2500):
            ns += rng.choice((0, 1000, 4_000_000))
            frame = rng.choice(frames)
            v7, v6 = _nums(rng, 7), _nums(rng, 6)
            pose = CDR.pose(0, ns // 10**9, ns % 10**9, rng.choice(("world", "world", "w")), v7)
            twist = CDR.twist(0, ns // 10**9, ns % 10**9, "world", v6)
            r = rng.random()
            if r < 0.03:
                twist += b"\x00\x00\x00"
            elif r < 0.06:
                obj = T[TWIST](header=_head(store, 2, 0, ns // 10**9, ns % 10**9, "world"), twist=T[
                    "geometry_msgs/msg/Twist"](linear=T["geometry_msgs/msg/Vector3"](x=v6[0], y=v6[1], z=v6[2]),
                                               angular=T["geometry_msgs/msg/Vector3"](x=v6[3], y=v6[4], z=v6[5])))
                twist = bytes(store.serialize_cdr(obj, TWIST, little_endian=False))
            order = rng.random()
            if order < 0.7:
                put(f"/vr/{frame}/pose", POSE, ns, pose)
                put(f"/vr/{frame}/twist", TWIST, ns, twist)
            elif order < 0.8:
                put(f"/vr/{frame}/twist", TWIST, ns, twist)
                put(f"/vr/{frame}/pose", POSE, ns, pose)
            elif order < 0.88:
                put(f"/vr/{frame}/pose", POSE, ns, pose)
            elif order < 0.94:
                put(f"/vr/{frame}/twist", TWIST, ns, twist)
            else:
                put("/tf", TF, ns, CDR.tf([(0, 1, 2, "world", frame, v7)]))
                put("/other", STRING, ns, CDR.string("x"))
            if rng.random() < 0.01:
                put("/vr/devices", STRING, ns, CDR.string(json.dumps(
                    {"index": 0, "kind": "hmd", "role": "none", "serial": "", "frame": "hmd", "valid": False,
                     "connected": rng.random() < 0.5})))
        w.finish()


def _generic_replay(path: str) -> list[Any]:
    """The reference: every message decoded by rosbags and fed to the Rebuilder one by one."""
    from mcap.reader import make_reader

    from ttctl.hmd.formats.ros import Rebuilder

    rebuild = Rebuilder(path)
    got: list[Any] = []
    with open(path, "rb") as f:
        for schema, channel, message in make_reader(f).iter_messages(log_time_order=False):
            route = Rebuilder.route(channel.topic)
            if route is None:
                continue
            msg = _ours_from_rosbags(STORES[2].deserialize_cdr(message.data, schema.name), schema.name, 2)
            if route[0] == "pose":
                rebuild.pose(route[1], message.log_time, msg[4])
            elif route[0] == "twist":
                rebuild.twist(route[1], message.log_time, msg[4])
            elif route[0] == "devices":
                rebuild.devices(message.log_time, msg)
            got.extend(rebuild.out)
            rebuild.out.clear()
    rebuild.finish()
    return got + rebuild.out


@pytest.mark.parametrize(("seed", "chunk_size"), [(1, 1 << 20), (2, 2048), (3, 300)])
def test_mcap_replay_fast_path_matches_the_rebuilder(tmp_path: Any, seed: int, chunk_size: int) -> None:
    from ttctl.hmd.formats import read_recording

    path = str(tmp_path / "odd.mcap")
    _odd_mcap(path, seed, chunk_size)
    want = _generic_replay(path)
    got = list(read_recording(path).samples)
    assert len(got) == len(want) > 1000
    for g, w in zip(got, want, strict=True):
        assert type(g) is type(w) and g.device == w.device and g.t == w.t, (g, w)
        assert (g.valid, g.connected) == (w.valid, w.connected)
        assert _same((*g.position, *g.orientation, *g.velocity, *g.angular_velocity),
                     (*w.position, *w.orientation, *w.velocity, *w.angular_velocity)), (g, w)
