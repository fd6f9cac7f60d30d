"""Java bindings against pymavlink, through the generated conformance program (a real JVM
process): every message of ttapi.xml (which includes all of common.xml) and of common.xml
(generated on its own) round-trips pymavlink -> Java decode -> Java encode -> byte-identical
frame -> pymavlink; bad input lines each get one JSON error line and the process survives."""

from __future__ import annotations

import json
import shutil
import struct
import subprocess
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from conformance_lib import (
    Conformance,
    check_message,
    generate,
    java_cmd,
    load_model,
    pymavlink_frame,
    pymavlink_module,
)
from ttctl.dialect.model import Message

pytestmark = pytest.mark.skipif(shutil.which("javac") is None or shutil.which("java") is None,
                                reason="needs a JDK (javac, java)")

TTAPI_MODEL = load_model("ttapi")
COMMON_MODEL = load_model("common")


def _world(tmp: Path, dialect: str) -> dict[str, Any]:
    out = generate(dialect, tmp / "out", "java")
    cmd = java_cmd(out, tmp / "build")
    return {"proc": Conformance(cmd), "pm": pymavlink_module(dialect, tmp), "cmd": cmd}


@pytest.fixture(scope="module")
def world(tmp_path_factory: pytest.TempPathFactory) -> Iterator[dict[str, Any]]:
    w = _world(tmp_path_factory.mktemp("conf_java"), "ttapi")
    yield w
    assert w["proc"].close() == 0


@pytest.fixture(scope="module")
def common_world(tmp_path_factory: pytest.TempPathFactory) -> Iterator[dict[str, Any]]:
    w = _world(tmp_path_factory.mktemp("conf_java_common"), "common")
    yield w
    assert w["proc"].close() == 0


TTAPI_MESSAGES = sorted(TTAPI_MODEL.messages, key=lambda m: m.id)


@pytest.mark.parametrize("m", TTAPI_MESSAGES, ids=[m.name for m in TTAPI_MESSAGES])
def test_every_message_roundtrips(world: dict[str, Any], m: Message) -> None:
    check_message(world, m, 8)


def test_every_common_message_roundtrips(common_world: dict[str, Any]) -> None:
    """common.xml generated on its own (its own registry, package ttctl.common)."""
    msgs = sorted((m for m in COMMON_MODEL.messages if m.complete), key=lambda m: m.id)
    assert len(msgs) > 200
    for m in msgs:
        check_message(common_world, m, 3)


# --- bad input ----------------------------------------------------------------------------

def _frame(msgid: int, payload: bytes, crc_extra: int, seq: int = 0) -> bytes:
    from fastcrc import crc16

    body = bytes((len(payload), 0, 0, seq, 1, 1)) + msgid.to_bytes(3, "little") + payload
    crc = crc16.mcrf4xx(bytes((crc_extra,)), crc16.mcrf4xx(body))
    return b"\xfd" + body + struct.pack("<H", crc)


def _heartbeat(world: dict[str, Any]) -> bytes:
    pm = world["pm"]
    m = TTAPI_MODEL.messages_by_name["HEARTBEAT"]
    values = {"type": 2, "autopilot": 3, "base_mode": 81, "custom_mode": 65536, "system_status": 4,
              "mavlink_version": 3}
    return pymavlink_frame(pm, m, values, 7, 1, 1)


def _is_error(answer: str) -> bool:
    doc = json.loads(answer)
    return isinstance(doc, dict) and set(doc) == {"error"} and isinstance(doc["error"], str)


def test_bad_lines_get_one_error_each(world: dict[str, Any]) -> None:
    proc = world["proc"]
    hb = _heartbeat(world)
    ack = TTAPI_MODEL.messages_by_name["TT_COMMAND_ACK"]
    unknown = _frame(0xABCDE, b"\x01\x02", 0)
    too_long = _frame(ack.id, bytes(range(1, ack.payload_length + 2)), ack.crc_extra)
    signed_short = bytearray(hb)
    signed_short[2] = 0x01  # says signed, no signature follows
    bad_flags = bytearray(hb)
    bad_flags[2] = 0x02
    data = TTAPI_MODEL.messages_by_name["TT_FILE_DATA"].field("data")
    assert data is not None
    data_len = data.array_length
    lines = [
        "",
        "hello",
        "X 00",
        "D",
        "D ",
        "D zz",
        "D abc",
        "D fd",
        "D " + hb.hex()[:-2],  # truncated
        "D " + hb.hex() + "00",  # trailing byte
        "D fe" + hb.hex()[2:],  # bad magic
        "D " + hb[:-1].hex() + f"{hb[-1] ^ 0xFF:02x}",  # bad CRC
        "D " + unknown.hex(),
        "D " + too_long.hex(),
        "D " + bytes(signed_short).hex(),
        "D " + bytes(bad_flags).hex(),
        "D " + "00" * 40,
        "D ＦＤ",  # full-width hex digits are not hex
        "E",
        "E ",
        "E {",
        "E []",
        "E 42",
        'E "HEARTBEAT"',
        "E {}",
        'E {"name": "NO_SUCH_MESSAGE"}',
        'E {"msgid": 16777215}',
        'E {"msgid": -1}',
        'E {"msgid": "0"}',
        'E {"name": 0}',
        'E {"name": "HEARTBEAT", "fields": []}',
        'E {"name": "HEARTBEAT", "fields": {"nope": 1}}',
        'E {"name": "HEARTBEAT", "fields": {"type": 256}}',
        'E {"name": "HEARTBEAT", "fields": {"type": -1}}',
        'E {"name": "HEARTBEAT", "fields": {"type": 1.5}}',
        'E {"name": "HEARTBEAT", "fields": {"type": true}}',
        'E {"name": "HEARTBEAT", "fields": {"type": null}}',
        'E {"name": "HEARTBEAT", "fields": {"custom_mode": 4294967296}}',
        'E {"name": "HEARTBEAT", "sysid": 256}',
        'E {"name": "HEARTBEAT", "seq": -1}',
        'E {"name": "HEARTBEAT", "fields": {"type": 1}} trailing',
        'E {"name": "SYSTEM_TIME", "fields": {"time_unix_usec": 18446744073709551616}}',
        'E {"name": "SYSTEM_TIME", "fields": {"time_unix_usec": -1}}',
        'E {"name": "SYSTEM_TIME", "fields": {"time_unix_usec": 99999999999999999999}}',
        'E {"name": "SYSTEM_TIME", "fields": {"time_boot_ms": 99999999999999999999}}',
        'E {"name": "ATTITUDE", "fields": {"roll": 1e39}}',
        'E {"name": "ATTITUDE", "fields": {"roll": "nan"}}',
        'E {"name": "TT_LOG", "fields": {"text": "' + "x" * 81 + '"}}',
        'E {"name": "TT_LOG", "fields": {"text": "\\u0100"}}',
        'E {"name": "TT_ODOMETRY", "fields": {"position": [1, 2]}}',
        'E {"name": "TT_FILE_DATA", "fields": {"data": [' + ",".join(["1"] * (data_len + 1)) + "]}}",
        'E {"name": "TT_FILE_DATA", "fields": {"data": [256]}}',
        'E {"name": "TT_LOG", "fields": {"text": "\\ud800\\u"}}',
        "E " + "[" * 5000,
        "E " + "{\"a\":" * 3000,
        'E {"name": "HEARTBEAT", "fields": {"type": 01}}',
        'E {"name": "HEARTBEAT", "fields": {"type": 1.}}',
        'E {"name": "HEARTBEAT", "fields": {"type": -}}',
        "E {\"name\": \"HEARTBEAT\"\x01}",
    ]
    for line in lines:
        answer = proc.ask(line)
        assert _is_error(answer), (line[:80], answer)
    # still alive and correct afterwards
    assert proc.decode(hb)["name"] == "HEARTBEAT"


def test_valid_edge_lines(world: dict[str, Any]) -> None:
    """Lines that are odd but valid: uppercase hex, surrounding spaces, defaults, short payloads."""
    proc = world["proc"]
    hb = _heartbeat(world)
    assert proc.decode(hb) == json.loads(proc.ask("D " + hb.hex().upper()))
    assert "error" not in json.loads(proc.ask("D  " + hb.hex() + "  "))
    # absent fields keep the defaults, absent header fields are seq 0, sysid 1, compid 1
    frame = proc.encode({"name": "SYSTEM_TIME"})
    assert isinstance(frame, bytes)
    doc = proc.decode(frame)
    assert (doc["seq"], doc["sysid"], doc["compid"]) == (0, 1, 1)
    assert doc["fields"] == {"time_unix_usec": 0, "time_boot_ms": 0}
    assert len(frame) == 10 + 1 + 2  # all-zero payload truncated to one byte
    # by msgid, uint64 extremes, float specials, Latin-1 text
    extremes = {"time_unix_usec": 18446744073709551615, "time_boot_ms": 4294967295}
    frame = proc.encode({"msgid": 2, "fields": extremes})
    assert isinstance(frame, bytes)
    assert proc.decode(frame)["fields"] == extremes
    frame = proc.encode({"name": "TT_LOG", "fields": {"text": "caf\u00e9 \u00ff\u0001", "severity": 6}})
    assert isinstance(frame, bytes)
    assert proc.decode(frame)["fields"]["text"] == "caf\u00e9 \u00ff\u0001"
    frame = proc.encode({"name": "ATTITUDE", "fields": {"roll": "NaN", "pitch": "-Infinity", "yaw": -0.0,
                                                         "rollspeed": 1.401298464324817e-45}})
    assert isinstance(frame, bytes)
    f = proc.decode(frame)["fields"]
    assert (f["roll"], f["pitch"], str(f["yaw"])) == ("NaN", "-Infinity", "-0.0")
    assert struct.pack("<f", f["rollspeed"]) == struct.pack("<f", 1.401298464324817e-45)  # the smallest subnormal


def _mutations(hb: bytes) -> st.SearchStrategy[bytes]:
    flip = st.tuples(st.integers(0, len(hb) - 1), st.integers(1, 255)).map(
        lambda t: hb[:t[0]] + bytes((hb[t[0]] ^ t[1],)) + hb[t[0] + 1:])
    cut = st.integers(0, len(hb) - 1).map(lambda n: hb[:n])
    extra = st.binary(min_size=1, max_size=20).map(lambda b: hb + b)
    return st.one_of(flip, cut, extra)


def test_mutated_frames_are_refused(world: dict[str, Any]) -> None:
    proc = world["proc"]
    hb = _heartbeat(world)

    @settings(max_examples=150, deadline=None, suppress_health_check=list(HealthCheck), database=None)
    @given(frame=_mutations(hb))
    def check(frame: bytes) -> None:
        assert _is_error(proc.ask("D " + frame.hex())), frame.hex()

    check()


def test_random_lines_never_kill_it(world: dict[str, Any]) -> None:
    proc = world["proc"]
    text = st.text(st.characters(codec="utf-8", exclude_characters="\n"), max_size=200)

    @settings(max_examples=150, deadline=None, suppress_health_check=list(HealthCheck), database=None)
    @given(line=st.one_of(text, text.map(lambda t: "E " + t), text.map(lambda t: "D " + t),
                          st.binary(max_size=120).map(lambda b: "D " + b.hex())))
    def check(line: str) -> None:
        doc = json.loads(proc.ask(line))
        assert isinstance(doc, dict) and ("error" in doc or "msgid" in doc), (line[:80], doc)

    check()


def test_raw_garbage_then_eof_exits_zero(world: dict[str, Any]) -> None:
    """Invalid UTF-8, NUL bytes, CR LF endings and a last line without newline: one answer per
    line, and exit status 0 at EOF."""
    hb = _heartbeat(world)
    lines = [b"\xff\xfe\x00garbage", b"D " + hb.hex().encode() + b"\r", b"E {\"name\": \"\xc3\x28\"}", b"\x00" * 50,
             b"E " + json.dumps({"name": "HEARTBEAT"}).encode(), b"D fd"]
    data = b"\n".join(lines)  # no newline after the last line
    proc = subprocess.run(world["cmd"], input=data, capture_output=True, timeout=60)
    assert proc.returncode == 0, proc.stderr[-2000:]
    answers = proc.stdout.decode().splitlines()
    assert len(answers) == len(lines), answers
    assert json.loads(answers[1])["name"] == "HEARTBEAT"
    assert all(c in "0123456789abcdef" for c in answers[4])
    for i in (0, 2, 3, 5):
        assert _is_error(answers[i]), answers[i]
