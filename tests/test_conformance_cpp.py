"""C++ bindings against pymavlink, through the generated conformance program (a real process
built with g++), for every message of ttapi.xml (which includes all of common.xml) and of
common.xml generated on its own; and the program built with AddressSanitizer and
UndefinedBehaviorSanitizer, fed garbage."""

from __future__ import annotations

import json
import math
import random
import struct
import subprocess
from collections.abc import Iterator
from concurrent.futures import ThreadPoolExecutor
from typing import Any

import pytest

from conformance_lib import (
    Conformance,
    check_message,
    cpp_cmd,
    generate,
    load_model,
    pymavlink_frame,
    pymavlink_module,
)
from ttctl.dialect.model import INTEGER_RANGES, Dialect, Message

TTAPI_MODEL = load_model("ttapi")
COMMON_MODEL = load_model("common")


def _complete(d: Dialect) -> list[Message]:
    return sorted((m for m in d.messages if m.complete), key=lambda m: m.id)


@pytest.fixture(scope="module")
def builds(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    """Generate both dialects, then build the three programs at once (g++ is the slow part),
    and mavgen pymavlink's module for ttapi meanwhile."""
    tmp = tmp_path_factory.mktemp("conf_cpp")
    ttapi_out = generate("ttapi", tmp / "ttapi", "cpp")
    common_out = generate("common", tmp / "common", "cpp")
    with ThreadPoolExecutor(max_workers=3) as pool:
        jobs = {
            "ttapi": pool.submit(cpp_cmd, ttapi_out, tmp / "build_ttapi"),
            "common": pool.submit(cpp_cmd, common_out, tmp / "build_common"),
            "asan": pool.submit(cpp_cmd, ttapi_out, tmp / "build_asan", True),
        }
        pm_ttapi = pymavlink_module("ttapi", tmp)
        cmds = {k: job.result() for k, job in jobs.items()}
    return {"cmds": cmds, "pm_ttapi": pm_ttapi, "pm_common": pymavlink_module("common", tmp)}


@pytest.fixture(scope="module")
def ttapi_world(builds: dict[str, Any]) -> Iterator[dict[str, Any]]:
    proc = Conformance(builds["cmds"]["ttapi"])
    yield {"proc": proc, "pm": builds["pm_ttapi"]}
    assert proc.close() == 0


@pytest.fixture(scope="module")
def common_world(builds: dict[str, Any]) -> Iterator[dict[str, Any]]:
    proc = Conformance(builds["cmds"]["common"])
    yield {"proc": proc, "pm": builds["pm_common"]}
    assert proc.close() == 0


@pytest.mark.parametrize("m", _complete(TTAPI_MODEL), ids=lambda m: m.name)
def test_every_message_roundtrips(ttapi_world: dict[str, Any], m: Message) -> None:
    check_message(ttapi_world, m, 8)


@pytest.mark.parametrize("m", _complete(COMMON_MODEL), ids=lambda m: m.name)
def test_common_generated_alone_roundtrips(common_world: dict[str, Any], m: Message) -> None:
    check_message(common_world, m, 3)


# --- the sanitized build ------------------------------------------------------------------

def random_values(rng: random.Random, m: Message) -> dict[str, Any]:
    """Random field values in pymavlink's terms (no hypothesis: one batch for one process)."""

    def one(typ: str, width: int) -> Any:
        if typ in ("float", "double"):
            fmt = "<f" if width == 4 else "<d"
            v = struct.unpack(fmt, rng.randbytes(width))[0]
            return math.nan if math.isnan(v) else v
        lo, hi = INTEGER_RANGES[typ]
        return rng.randint(lo, hi)

    values: dict[str, Any] = {}
    for f in m.fields:
        if f.type == "char":
            values[f.name] = bytes(rng.randint(1, 255) for _ in range(rng.randint(0, max(f.array_length, 1))))
        elif f.array_length:
            values[f.name] = [one(f.type, f.type_size) for _ in range(f.array_length)]
        else:
            values[f.name] = one(f.type, f.type_size)
    return values


def _crc(data: bytes, extra: int) -> bytes:
    from fastcrc import crc16

    return struct.pack("<H", crc16.mcrf4xx(bytes([extra]), crc16.mcrf4xx(data)))


def _frame(msgid: int, payload: bytes, extra: int, incompat: int = 0) -> bytes:
    body = bytes([len(payload), incompat, 0, 1, 2, 3]) + msgid.to_bytes(3, "little") + payload
    return b"\xfd" + body + _crc(body, extra)


def garbage_lines(rng: random.Random, frames: list[bytes]) -> list[bytes]:
    """Request lines that must each get a JSON error answer."""
    lines: list[bytes] = [b"", b"D", b"E", b"X fd", b"d fd00", b"D \xff\xfe", b"D 0", b"D fdz0", b"D " + b"g" * 10_000,
                          b"\x00\x00D ", b"D \x00"]
    known = {m.id for m in TTAPI_MODEL.messages}
    for _ in range(100):
        n = rng.randint(1, 200)
        lines.append(bytes(rng.choice(b"abcdefxyz {}[]\":,0123456789\\") for _ in range(n)))
        raw = bytes(b for b in rng.randbytes(rng.randint(0, 300)) if b != 0x0A)
        lines.append(raw)
        lines.append(b"D " + raw.hex().encode())  # random bytes: almost never a frame...
    lines = [x for x in lines if not x.startswith(b"D fd") or len(x) < 26]  # ...and never one by luck
    for frame in frames:
        lines.append(b"D " + frame[: rng.randint(0, len(frame) - 1)].hex().encode())  # truncated
        bad = bytearray(frame)
        bad[-rng.randint(1, 2)] ^= 1 << rng.randint(0, 7)  # flipped CRC bit
        lines.append(b"D " + bad.hex().encode())
        bad = bytearray(frame)
        bad[rng.randint(10, len(frame) - 3)] ^= 0xFF  # corrupted payload byte
        lines.append(b"D " + bad.hex().encode())
        lines.append(b"D " + (frame + b"\x00").hex().encode())  # trailing byte
        bad = bytearray(frame)
        bad[2] = 0x80  # unknown incompat flag
        lines.append(b"D " + bad.hex().encode())
    for _ in range(40):
        msgid = rng.choice([x for x in (rng.randint(0, 0xFFFFFF), 0xABCDEF, 60000, 1) if x not in known] or [0xFFFFFF])
        lines.append(b"D " + _frame(msgid, rng.randbytes(rng.randint(1, 40)), rng.randint(0, 255)).hex().encode())
    for m in rng.sample([m for m in _complete(TTAPI_MODEL) if m.payload_length < 255], 20):
        # a payload longer than the message's, with the right CRC
        lines.append(b"D " + _frame(m.id, b"\x01" * (m.payload_length + 1), m.crc_extra).hex().encode())
    lines.append(b"D " + rng.randbytes(5000).hex().encode())  # 10 KB of hex
    lines.append(b"D " + (frames[0] * 400).hex()[:10_000].encode())
    deep = b"[" * 5000 + b"]" * 5000
    bad_json = [b"", b"{", b"}", b"[]", b"\"x\"", b"null", b"1", b"{\"name\":", b"{\"name\":\"HEARTBEAT\"",
                b"{\"name\":\"HEARTBEAT\",}", b"{\"name\":\"NOPE\"}", b"{\"msgid\":-1}", b"{\"msgid\":16777216}",
                b"{\"msgid\":1e400}", b"{\"msgid\":0.5}", b"{\"msgid\":\"0\"}", b"{}", deep,
                b"{\"a\":" + deep + b"}", b"{\"name\":\"HEARTBEAT\",\"fields\":[]}",
                b"{\"name\":\"HEARTBEAT\",\"fields\":{\"nope\":1}}",
                b"{\"name\":\"HEARTBEAT\",\"fields\":{\"type\":256}}",
                b"{\"name\":\"HEARTBEAT\",\"fields\":{\"type\":-1}}",
                b"{\"name\":\"HEARTBEAT\",\"fields\":{\"type\":1.5}}",
                b"{\"name\":\"HEARTBEAT\",\"fields\":{\"type\":\"1\"}}",
                b"{\"name\":\"HEARTBEAT\",\"fields\":{\"custom_mode\":" + b"9" * 5000 + b"}}",
                b"{\"name\":\"HEARTBEAT\",\"fields\":{\"custom_mode\":-" + b"9" * 5000 + b"}}",
                b"{\"name\":\"HEARTBEAT\",\"sysid\":256}", b"{\"name\":\"HEARTBEAT\",\"compid\":-1}",
                b"{\"name\":\"HEARTBEAT\",\"seq\":\"1\"}",
                b"{\"name\":\"ATTITUDE\",\"fields\":{\"roll\":1e39}}",
                b"{\"name\":\"ATTITUDE\",\"fields\":{\"roll\":\"nan\"}}",
                b"{\"name\":\"ATTITUDE\",\"fields\":{\"roll\":[1]}}",
                b"{\"name\":\"STATUSTEXT\",\"fields\":{\"text\":\"" + b"a" * 10_000 + b"\"}}",
                b"{\"name\":\"STATUSTEXT\",\"fields\":{\"text\":\"\\u0100\"}}",
                b"{\"name\":\"STATUSTEXT\",\"fields\":{\"text\":\"\\ud800\\udc00\"}}",
                b"{\"name\":\"STATUSTEXT\",\"fields\":{\"text\":\"\\x\"}}",
                b"{\"name\":\"STATUSTEXT\",\"fields\":{\"text\":\"\\u12\"}}",
                b"{\"name\":\"STATUSTEXT\",\"fields\":{\"text\":\"\\",
                b"{\"name\":\"STATUSTEXT\",\"fields\":{\"text\":\"\xff\xfe\"}}",
                b"{\"name\":\"STATUSTEXT\",\"fields\":{\"text\":\"\xc3\"}}",
                b"{\"name\":\"STATUSTEXT\",\"fields\":{\"text\":\"\x01\"}}",
                b"{\"name\":\"STATUSTEXT\",\"fields\":{\"text\":7}}",
                b"{\"name\":\"ATT_POS_MOCAP\",\"fields\":{\"q\":[1,2,3]}}",
                b"{\"name\":\"ATT_POS_MOCAP\",\"fields\":{\"q\":[1,2,3,4,5]}}",
                b"{\"name\":\"ATT_POS_MOCAP\",\"fields\":{\"q\":{}}}",
                b"{\"name\":\"FILE_TRANSFER_PROTOCOL\",\"fields\":{\"payload\":[" + b"1," * 251 + b"1]}}",
                b"{\"name\":\"FILE_TRANSFER_PROTOCOL\",\"fields\":{\"payload\":[-1]}}",
                b"{\"name\":\"FILE_TRANSFER_PROTOCOL\",\"fields\":{\"payload\":\"abc\"}}",
                b"{\"name\":\"HEARTBEAT\"} x", b"{\"name\":\"HEARTBEAT\"", b"{\"name\" \"HEARTBEAT\"}",
                b"{\"name\":tru}", b"{\"name\":-}", b"{\"name\":01}", b"{\"name\":1.}", b"{\"name\":.5}",
                b"{\"name\":1e}", b"{\"name\":\"HEARTBEAT\",\"fields\":{\"type\":-}}"]
    lines += [b"E " + j for j in bad_json]
    return lines


def test_sanitized_build_survives_garbage(builds: dict[str, Any]) -> None:
    rng = random.Random(20240601)
    pm = builds["pm_ttapi"]
    valid: list[tuple[Message, bytes]] = []
    for m in _complete(TTAPI_MODEL):
        values = random_values(rng, m)
        valid.append((m, pymavlink_frame(pm, m, values, rng.randint(0, 255), rng.randint(1, 255),
                                         rng.randint(0, 255))))
    garbage = garbage_lines(rng, [f for _, f in rng.sample(valid, 60)])
    # valid frames first (each decoded, then re-encoded from its own answer), then garbage
    decode_lines = [b"D " + f.hex().encode() for _, f in valid]
    proc = subprocess.run(builds["cmds"]["asan"], input=b"\n".join(decode_lines) + b"\n", capture_output=True,
                          timeout=300)
    assert proc.returncode == 0 and proc.stderr == b"", proc.stderr.decode(errors="replace")[-3000:]
    docs = [json.loads(x) for x in proc.stdout.splitlines()]
    assert len(docs) == len(valid)
    for (m, _), doc in zip(valid, docs, strict=True):
        assert doc.get("name") == m.name, doc
    encode_lines = [b"E " + json.dumps(doc).encode() for doc in docs]
    proc = subprocess.run(builds["cmds"]["asan"], input=b"\n".join(encode_lines + garbage) + b"\n",
                          capture_output=True, timeout=300)
    assert proc.returncode == 0, proc.stderr.decode(errors="replace")[-3000:]
    assert proc.stderr == b"", proc.stderr.decode(errors="replace")[-3000:]
    answers = proc.stdout.split(b"\n")
    assert answers[-1] == b"" and len(answers) - 1 == len(encode_lines) + len(garbage)
    for (_, frame), answer in zip(valid, answers, strict=False):
        assert bytes.fromhex(answer.decode()) == frame
    for line, answer in zip(garbage, answers[len(valid):-1], strict=True):
        doc = json.loads(answer)
        assert isinstance(doc, dict) and list(doc) == ["error"] and isinstance(doc["error"], str), (line[:200], answer)

    # random edits of valid requests: whatever the answer, it is one well-formed line
    mutants = [mutate(rng, line) for line in rng.sample(decode_lines + encode_lines, 150) for _ in range(4)]
    proc = subprocess.run(builds["cmds"]["asan"], input=b"\n".join(mutants) + b"\n", capture_output=True, timeout=300)
    assert proc.returncode == 0 and proc.stderr == b"", proc.stderr.decode(errors="replace")[-3000:]
    answers = proc.stdout.split(b"\n")
    assert len(answers) - 1 == len(mutants)
    for line, answer in zip(mutants, answers, strict=False):
        if answer.startswith(b"{"):
            doc = json.loads(answer)
            assert isinstance(doc, dict) and ("error" in doc or "fields" in doc), (line[:200], answer)
        else:
            assert line.startswith(b"E ") and bytes.fromhex(answer.decode()).hex().encode() == answer, (line, answer)


def mutate(rng: random.Random, line: bytes) -> bytes:
    """A request with a few random edits (never a newline)."""
    b = bytearray(line)
    for _ in range(rng.randint(1, 4)):
        at = rng.randrange(2, len(b) + 1)
        op = rng.randrange(4)
        if op == 0 and at < len(b):
            del b[at]
        elif op == 1:
            b[at:at] = bytes([rng.choice(b'0fd{}[]":,-.eE9\\u \x00\xff')])
        elif op == 2 and at < len(b):
            b[at] = rng.choice(b"0123456789abcdef\"{}")
        else:
            del b[at:at + rng.randint(1, 50)]  # truncate a stretch
    return bytes(b)
