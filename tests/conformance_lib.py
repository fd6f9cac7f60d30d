"""Cross-language conformance harness: generated programs (Python, C++, Java) as real
processes speaking the `D <hex>` / `E <json>` line protocol, pymavlink as the oracle, and
hypothesis strategies for field values (integer extremes, NaN and infinities, full-length and
empty strings, zero tails that exercise MAVLink 2 truncation, extension fields)."""

from __future__ import annotations

import importlib.util
import json
import math
import os
import selectors
import shutil
import struct
import subprocess
import sys
from pathlib import Path
from types import ModuleType
from typing import Any

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from conftest import TTAPI, pymavlink_dialects, run_ttctl
from machine import scaled
from ttctl.dialect.model import INTEGER_RANGES, Dialect, Field, Message
from ttctl.validate import load_and_check

DIALECT_FILES = {"ttapi": TTAPI, "common": pymavlink_dialects() / "common.xml"}
F32 = struct.Struct("<f")


def load_model(dialect: str) -> Dialect:
    d, rep, _ = load_and_check(str(DIALECT_FILES[dialect]), [])
    assert rep.errors == 0
    return d


def generate(dialect: str, out: Path, langs: str = "python,cpp,java") -> Path:
    proc = run_ttctl("gen", str(DIALECT_FILES[dialect]), "--lang", langs, "-o", str(out), timeout=600)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    return out


def pymavlink_module(dialect: str, tmp: Path) -> ModuleType:
    """pymavlink's own Python for the dialect (mavgen on a staged copy beside its includes)."""
    if dialect == "common":
        from pymavlink.dialects.v20 import common

        return common
    stage = tmp / "pm_stage"
    stage.mkdir(exist_ok=True)
    for xml in pymavlink_dialects().glob("*.xml"):
        shutil.copy(xml, stage)
    shutil.copy(DIALECT_FILES[dialect], stage)
    out = tmp / f"pm_{dialect}.py"
    proc = subprocess.run([sys.executable, "-m", "pymavlink.tools.mavgen", "--lang", "Python3", "--wire-protocol",
                           "2.0", "-o", str(out), str(stage / DIALECT_FILES[dialect].name)],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    spec = importlib.util.spec_from_file_location(f"pm_{dialect}", out)
    assert spec and spec.loader
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


# --- the programs -------------------------------------------------------------------------

def python_cmd(out: Path) -> list[str]:
    return [sys.executable, str(out / "python" / "conformance.py")]


def cpp_cmd(out: Path, build: Path, sanitize: bool = False) -> list[str]:
    exe = build / ("conformance_asan" if sanitize else "conformance")
    flags = ["-std=c++17", "-Wall", "-Wextra", "-Wpedantic", "-Werror"]
    flags += ["-O1", "-g", "-fsanitize=address,undefined", "-fno-sanitize-recover=all",
              "-fno-omit-frame-pointer"] if sanitize else ["-O2"]
    build.mkdir(parents=True, exist_ok=True)
    proc = subprocess.run(["g++", *flags, "-I", str(out / "cpp"), str(out / "cpp" / "conformance.cpp"), "-o",
                           str(exe)], capture_output=True, text=True, timeout=900)
    assert proc.returncode == 0, proc.stderr[-4000:]
    return [str(exe)]


def java_cmd(out: Path, build: Path) -> list[str]:
    classes = build / "classes"
    classes.mkdir(parents=True, exist_ok=True)
    sources = sorted(str(p) for p in (out / "java").rglob("*.java"))
    proc = subprocess.run(["javac", "--release", "11", "-Xlint:all", "-Werror", "-d", str(classes), *sources],
                          capture_output=True, text=True, timeout=900)
    assert proc.returncode == 0, proc.stderr[-4000:]
    return ["java", "-Xss8m", "-cp", str(classes), "Conformance"]


class Conformance:
    """One long-lived conformance process; one request line, one answer line."""

    def __init__(self, cmd: list[str], env: dict[str, str] | None = None) -> None:
        self.cmd = cmd
        self.proc = subprocess.Popen(cmd, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                     env={**os.environ, **(env or {})}, bufsize=0)
        self.sel = selectors.DefaultSelector()
        assert self.proc.stdout is not None
        self.sel.register(self.proc.stdout, selectors.EVENT_READ)
        self._buf = b""

    def ask(self, line: str, timeout: float = 30.0) -> str:
        timeout = scaled(timeout)  # longer on a busy machine
        assert self.proc.stdin is not None and self.proc.stdout is not None
        if "\n" in line:
            raise ValueError("one line at a time")
        try:
            self.proc.stdin.write(line.encode() + b"\n")
            self.proc.stdin.flush()
        except BrokenPipeError:
            raise AssertionError(f"{self.cmd[0]} died: {self.stderr()}") from None
        while b"\n" not in self._buf:
            if not self.sel.select(timeout):
                raise AssertionError(f"{self.cmd[0]}: no answer within {timeout} s to {line[:80]}")
            chunk = os.read(self.proc.stdout.fileno(), 65536)
            if not chunk:
                raise AssertionError(f"{self.cmd[0]} exited ({self.proc.poll()}): {self.stderr()}")
            self._buf += chunk
        answer, self._buf = self._buf.split(b"\n", 1)
        return answer.decode()

    def decode(self, frame: bytes) -> dict[str, Any]:
        result: dict[str, Any] = json.loads(self.ask("D " + frame.hex()))
        return result

    def encode(self, obj: dict[str, Any]) -> bytes | dict[str, Any]:
        answer = self.ask("E " + json.dumps(obj))
        if answer.startswith("{"):
            err: dict[str, Any] = json.loads(answer)
            return err
        return bytes.fromhex(answer)

    def stderr(self) -> str:
        if self.proc.poll() is None:
            return ""
        assert self.proc.stderr is not None
        return self.proc.stderr.read().decode(errors="replace")[-3000:]

    def close(self) -> int:
        assert self.proc.stdin is not None
        self.proc.stdin.close()
        try:
            return self.proc.wait(timeout=30)
        finally:
            self.sel.close()


# --- values -------------------------------------------------------------------------------

def _float_strategy(width: int) -> st.SearchStrategy[float]:
    specials = [math.nan, math.inf, -math.inf, 0.0, -0.0, 1.0, -1.0]
    if width == 4:
        specials += [1.401298464324817e-45, 3.4028234663852886e38, -3.4028234663852886e38, 1.1754943508222875e-38]
        finite = st.floats(width=32, allow_nan=False, allow_infinity=False)
    else:
        specials += [5e-324, 1.7976931348623157e308, 2.2250738585072014e-308]
        finite = st.floats(allow_nan=False, allow_infinity=False)
    return st.one_of(st.sampled_from(specials), finite)


def _int_strategy(typ: str) -> st.SearchStrategy[int]:
    lo, hi = INTEGER_RANGES[typ]
    return st.one_of(st.sampled_from(sorted({lo, hi, 0, 1, min(hi, 255)} | ({-1} if lo < 0 else set()))),
                     st.integers(lo, hi))


def field_strategy(f: Field) -> st.SearchStrategy[Any]:
    n = f.array_length
    if f.type == "char":
        size = max(n, 1)
        return st.one_of(st.binary(max_size=size), st.binary(min_size=size, max_size=size)).map(
            lambda b: b.replace(b"\x00", b"\x01"))
    elem: st.SearchStrategy[Any] = (_float_strategy(f.type_size) if f.is_float else _int_strategy(f.type))
    if f.mavlink_version:
        return st.integers(0, 255)
    return st.lists(elem, min_size=n, max_size=n) if n else elem


def zero_of(f: Field) -> Any:
    if f.type == "char":
        return b""
    z: Any = 0.0 if f.is_float else 0
    return [z] * f.array_length if f.array_length else z


@st.composite
def message_values(draw: st.DrawFn, m: Message) -> dict[str, Any]:
    """Values in pymavlink's terms (char arrays as bytes, arrays as lists); with some
    probability a zero tail in wire order, so frames get truncated."""
    values = {f.name: draw(field_strategy(f)) for f in m.fields}
    if draw(st.booleans()):
        keep = draw(st.integers(0, len(m.wire_fields)))
        for f in m.wire_fields[keep:]:
            values[f.name] = zero_of(f)
    return values


def pymavlink_frame(mod: ModuleType, m: Message, values: dict[str, Any], seq: int, sysid: int,
                    compid: int) -> bytes:
    cls = mod.mavlink_map[m.id]
    mav = mod.MAVLink(None, srcSystem=sysid, srcComponent=compid)
    mav.seq = seq
    args = [values[name] for name in cls.fieldnames]
    return bytes(cls(*args).pack(mav))


def json_fields(m: Message, values: dict[str, Any]) -> dict[str, Any]:
    """How the conformance programs must present these values."""
    out: dict[str, Any] = {}
    for f in m.fields:
        v = values[f.name]
        if f.type == "char":
            out[f.name] = bytes(v).split(b"\x00", 1)[0].decode("latin-1")
        elif f.is_float:
            out[f.name] = [_json_float(x) for x in v] if f.array_length else _json_float(v)
        else:
            out[f.name] = list(v) if f.array_length else v
    return out


def _json_float(v: float) -> Any:
    if math.isnan(v):
        return "NaN"
    if math.isinf(v):
        return "Infinity" if v > 0 else "-Infinity"
    return v


def _same_float(a: Any, b: Any, width: int) -> bool:
    if isinstance(a, str) or isinstance(b, str):
        return a == b
    if width == 4:
        return F32.pack(a) == F32.pack(b)
    return struct.pack("<d", a) == struct.pack("<d", b)


def assert_fields_match(m: Message, got: dict[str, Any], want: dict[str, Any]) -> None:
    assert set(got) == {f.name for f in m.fields}, (m.name, sorted(got))
    for f in m.fields:
        g, w = got[f.name], want[f.name]
        if f.is_float:
            gs, ws = (g, w) if f.array_length else ([g], [w])
            assert len(gs) == len(ws), (m.name, f.name, g, w)
            for a, b in zip(gs, ws, strict=True):
                assert _same_float(a, b, f.type_size), (m.name, f.name, g, w)
        else:
            assert g == w, (m.name, f.name, g, w)


def roundtrip(world: dict[str, Any], m: Message, values: dict[str, Any], seq: int, sysid: int, compid: int) -> None:
    """pymavlink encodes; the program (world["proc"]) decodes and re-encodes byte-identically;
    pymavlink parses its frame."""
    proc, pm = world["proc"], world["pm"]
    frame = pymavlink_frame(pm, m, values, seq, sysid, compid)
    doc = proc.decode(frame)
    assert "error" not in doc, (m.name, doc, frame.hex())
    assert (doc["msgid"], doc["name"], doc["sysid"], doc["compid"], doc["seq"]) == (m.id, m.name, sysid, compid, seq)
    assert_fields_match(m, doc["fields"], json_fields(m, values))
    again = proc.encode(doc)
    assert again == frame, (m.name, frame.hex(), again)
    parsed = pm.MAVLink(None).parse_buffer(again)
    assert parsed and parsed[0].get_msgId() == m.id


def check_message(world: dict[str, Any], m: Message, examples: int) -> None:
    """`roundtrip` on `examples` hypothesis-generated values of m."""
    @settings(max_examples=examples, deadline=None, suppress_health_check=list(HealthCheck), database=None)
    @given(values=message_values(m), seq=st.integers(0, 255), sysid=st.integers(1, 255), compid=st.integers(0, 255))
    def check(values: dict[str, Any], seq: int, sysid: int, compid: int) -> None:
        roundtrip(world, m, values, seq, sysid, compid)

    check()


def build_java(base: Path, drivers: list[Path], langs: str = "java") -> tuple[Path, Path]:
    """`ttctl gen` of ttapi.xml (`langs`, java among them) into base/gen, then the Java sources
    and the `drivers` (.java files) compiled with javac --release 11 -Xlint:all -Werror into
    base/classes: (classes, generated tree)."""
    out = base / "gen"
    proc = run_ttctl("gen", str(TTAPI), "--lang", langs, "-o", str(out), timeout=600)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    sources = sorted(str(p) for p in (out / "java").rglob("*.java")) + sorted(map(str, drivers))
    cls = base / "classes"
    cls.mkdir()
    javac = subprocess.run(["javac", "--release", "11", "-Xlint:all", "-Werror", "-encoding", "UTF-8", "-d", str(cls),
                            *sources], capture_output=True, text=True, timeout=600)
    assert javac.returncode == 0 and "warning" not in javac.stderr, javac.stderr[-6000:]
    return cls, out
