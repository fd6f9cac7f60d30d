"""The generated C++ decoder against mavgen's C library, on one mixed stream of pymavlink's
common.xml messages with random values.

Both sides run in one program built with g++ -O2 (one translation unit per library), over the
same in-memory stream, in interleaved repetitions:
  ttctl:  Parser::feed over 4 KiB chunks, each frame decoded into its struct;
  mavgen: mavlink_parse_char per byte, each message decoded with mavlink_msg_<name>_decode.
Decoded structs are kept alive with an empty asm statement, so neither decode is optimized away.
"""

from __future__ import annotations

import json
import math
import random
import struct
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

from ..dialect.model import INTEGER_RANGES, Message

STREAM_MESSAGES = 4000
CHUNK = 4096
CXXFLAGS = ["-std=c++17", "-O2", "-w"]

_KEEP = """\
#pragma once
#include <cstddef>
#include <cstdint>

// Keep a decoded value: the compiler must materialize it, and nothing more happens.
template <class T>
inline void keep(const T& value)
{
    asm volatile("" : : "r"(&value) : "memory");
}
"""


def _common_xml() -> Path:
    from ..dialect.source import pymavlink_dialects_dir

    base = pymavlink_dialects_dir()
    if base is None:
        raise RuntimeError("pymavlink's dialects not found")
    return Path(base) / "common.xml"


def random_values(m: Message, rng: random.Random) -> dict[str, Any]:
    """Field values in pymavlink's terms; about a third of the messages get a zero tail in wire
    order, so their frames are truncated as real ones often are."""

    def one(typ: str, width: int) -> Any:
        if typ in ("float", "double"):
            v = struct.unpack("<f" if width == 4 else "<d", rng.randbytes(width))[0]
            return 0.0 if math.isnan(v) or math.isinf(v) else v
        lo, hi = INTEGER_RANGES[typ]
        return rng.randint(lo, hi)

    values: dict[str, Any] = {}
    for f in m.fields:
        if f.type == "char":
            values[f.name] = bytes(rng.randint(32, 126) for _ in range(rng.randint(0, max(f.array_length, 1))))
        elif f.array_length:
            values[f.name] = [one(f.type, f.type_size) for _ in range(f.array_length)]
        else:
            values[f.name] = one(f.type, f.type_size)
    if rng.random() < 0.33:
        for f in m.wire_fields[rng.randint(0, len(m.wire_fields)):]:
            if f.type == "char":
                values[f.name] = b""
            else:
                zero: Any = 0.0 if f.is_float else 0
                values[f.name] = [zero] * f.array_length if f.array_length else zero
    return values


def make_stream(messages: list[Message], count: int, seed: int = 1) -> bytes:
    """`count` frames (every message at least once, then random ones) encoded by pymavlink."""
    from pymavlink.dialects.v20 import common as pm  # type: ignore[import-untyped]

    rng = random.Random(seed)
    usable = [m for m in messages if m.id in pm.mavlink_map]
    mav = pm.MAVLink(None, srcSystem=1, srcComponent=1)
    frames = []
    for i in range(count):
        m = usable[i] if i < len(usable) else rng.choice(usable)
        values = random_values(m, rng)
        cls = pm.mavlink_map[m.id]
        frames.append(bytes(cls(*[values[n] for n in cls.fieldnames]).pack(mav)))
    return b"".join(frames)


def _ours_source(messages: list[Message], ident: str, types: dict[str, str]) -> str:
    """`types`: the generated C++ type of each message by name (dialect.symbols.type_names)."""
    cases = "\n".join(
        f"    case {ident}::{types[m.name]}::MSG_ID:\n        keep(f.as<{ident}::{types[m.name]}>());\n        break;"
        for m in messages)
    return f"""// ttctl's generated C++: Parser + decode into the message struct.
#include "{ident}/{ident}.hpp"
#include "keep.hpp"

namespace {{

void decode(const {ident}::Frame& f)
{{
    switch (f.msgid) {{
{cases}
    default:
        break;
    }}
}}

}}  // namespace

std::size_t ours_decode(const std::uint8_t* data, std::size_t n)
{{
    {ident}::Parser parser;
    std::size_t frames = 0;
    for (std::size_t at = 0; at < n; at += {CHUNK}) {{
        const std::size_t len = n - at < {CHUNK} ? n - at : {CHUNK};
        frames += parser.feed(data + at, len, decode);
    }}
    return frames;
}}
"""


def _mavgen_source(messages: list[Message]) -> str:
    cases = "\n".join(
        f"        case MAVLINK_MSG_ID_{m.name}: {{\n"
        f"            mavlink_{m.name.lower()}_t x;\n"
        f"            mavlink_msg_{m.name.lower()}_decode(&msg, &x);\n"
        f"            keep(x);\n"
        f"            break;\n"
        f"        }}"
        for m in messages)
    return f"""// mavgen's C library: mavlink_parse_char per byte + mavlink_msg_<name>_decode.
#include "common/mavlink.h"
#include "keep.hpp"

std::size_t mavgen_decode(const std::uint8_t* data, std::size_t n)
{{
    mavlink_message_t msg;
    mavlink_status_t status;
    std::size_t frames = 0;
    for (std::size_t i = 0; i < n; ++i) {{
        if (!mavlink_parse_char(MAVLINK_COMM_0, data[i], &msg, &status)) {{
            continue;
        }}
        ++frames;
        switch (msg.msgid) {{
{cases}
        default:
            break;
        }}
    }}
    return frames;
}}
"""


_MAIN = """// Interleaved repetitions of both decoders over the same in-memory stream.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "keep.hpp"

std::size_t ours_decode(const std::uint8_t* data, std::size_t n);
std::size_t mavgen_decode(const std::uint8_t* data, std::size_t n);

namespace {

using Clock = std::chrono::steady_clock;

double seconds_of(std::size_t (*fn)(const std::uint8_t*, std::size_t), const std::vector<std::uint8_t>& s,
                  int passes, std::size_t& frames)
{
    const auto t0 = Clock::now();
    for (int i = 0; i < passes; ++i) {
        frames = fn(s.data(), s.size());
    }
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc != 4) {
        std::fprintf(stderr, "usage: %s STREAM MESSAGES SECONDS\\n", argv[0]);
        return 2;
    }
    std::FILE* fh = std::fopen(argv[1], "rb");
    if (fh == nullptr) {
        std::perror(argv[1]);
        return 2;
    }
    std::vector<std::uint8_t> stream;
    std::uint8_t buf[65536];
    for (std::size_t got; (got = std::fread(buf, 1, sizeof buf, fh)) > 0;) {
        stream.insert(stream.end(), buf, buf + got);
    }
    std::fclose(fh);
    const std::size_t messages = std::strtoull(argv[2], nullptr, 10);
    const double budget = std::atof(argv[3]);

    std::size_t ours = 0;
    std::size_t theirs = 0;
    // warm up, check both see every frame, and size a repetition to about 20 ms
    const double t_ours = seconds_of(ours_decode, stream, 1, ours);
    const double t_theirs = seconds_of(mavgen_decode, stream, 1, theirs);
    if (ours != messages || theirs != messages) {
        std::fprintf(stderr, "frames decoded: ttctl %zu, mavgen %zu, expected %zu\\n", ours, theirs, messages);
        return 1;
    }
    const int passes = std::max(1, static_cast<int>(0.02 / std::max(1e-9, std::max(t_ours, t_theirs))));
    std::vector<double> rate_ours;
    std::vector<double> rate_theirs;
    const auto start = Clock::now();
    while (rate_ours.size() < 5
           || std::chrono::duration<double>(Clock::now() - start).count() < budget) {
        const bool ours_first = rate_ours.size() % 2 == 0;  // alternate which side runs first
        for (int k = 0; k < 2; ++k) {
            if ((k == 0) == ours_first) {
                rate_ours.push_back(passes * static_cast<double>(messages)
                                    / seconds_of(ours_decode, stream, passes, ours));
            } else {
                rate_theirs.push_back(passes * static_cast<double>(messages)
                                      / seconds_of(mavgen_decode, stream, passes, theirs));
            }
        }
    }
    std::printf("{\\"ours_msgs_per_s\\": %.1f, \\"mavgen_c_msgs_per_s\\": %.1f, \\"repetitions\\": %zu, "
                "\\"passes\\": %d}\\n", median(rate_ours), median(rate_theirs), rate_ours.size(), passes);
    return 0;
}
"""


def _run(cmd: list[str], what: str, timeout: float = 600) -> None:
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    if proc.returncode != 0:
        raise RuntimeError(f"{what} failed ({proc.returncode}): {(proc.stderr or proc.stdout)[-2000:]}")


def run(tmp: Path, seconds_budget: float = 20) -> dict[str, Any]:
    """Generate, build and run the comparison in `tmp`; returns messages/s of both decoders,
    their ratio (ours / mavgen's) and the stream size. Raises RuntimeError if a step fails."""
    from ..codegen.engine import dialect_ident, language, render, write_tree
    from ..dialect.symbols import type_names
    from ..validate import load_and_check

    t0 = time.monotonic()
    tmp.mkdir(parents=True, exist_ok=True)
    xml = _common_xml()
    dialect, rep, _ = load_and_check(str(xml), [])
    if rep.errors:
        raise RuntimeError(f"{xml}: {rep.errors} validation error(s)")
    ident = dialect_ident(dialect)
    ours_out = tmp / "ttctl"
    write_tree(ours_out, render(dialect, ["cpp"]), language("cpp").owned_dirs(dialect), False, False)
    mavgen_out = tmp / "mavgen"
    _run([sys.executable, "-m", "pymavlink.tools.mavgen", "--lang", "C", "--wire-protocol", "2.0", "-o",
          str(mavgen_out), str(xml)], "mavgen --lang C")

    messages = sorted((m for m in dialect.messages if m.complete), key=lambda m: m.id)
    stream = make_stream(messages, STREAM_MESSAGES)
    (tmp / "stream.bin").write_bytes(stream)
    src = tmp / "src"
    src.mkdir(exist_ok=True)
    (src / "keep.hpp").write_text(_KEEP)
    (src / "ours.cpp").write_text(_ours_source(messages, ident, type_names(dialect).messages))
    (src / "mavgen.cpp").write_text(_mavgen_source(messages))
    (src / "main.cpp").write_text(_MAIN)

    units = {
        "ours": ["-I", str(ours_out / "cpp"), "-I", str(src), str(src / "ours.cpp")],
        "mavgen": ["-I", str(mavgen_out), "-I", str(src), str(src / "mavgen.cpp")],
        "main": ["-I", str(src), str(src / "main.cpp")],
    }
    procs = {k: subprocess.Popen(["g++", *CXXFLAGS, "-c", *args, "-o", str(tmp / f"{k}.o")],
                                 stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
             for k, args in units.items()}
    for k, p in procs.items():
        _, err = p.communicate(timeout=600)
        if p.returncode != 0:
            raise RuntimeError(f"compiling the {k} part of the benchmark failed: {err[-2000:]}")
    exe = tmp / "codec_bench"
    _run(["g++", "-O2", *(str(tmp / f"{k}.o") for k in units), "-o", str(exe)], "linking the benchmark")

    measure = max(0.3, seconds_budget - (time.monotonic() - t0))
    proc = subprocess.run([str(exe), str(tmp / "stream.bin"), str(STREAM_MESSAGES), f"{measure:.3f}"],
                          capture_output=True, text=True, timeout=measure * 4 + 120)
    if proc.returncode != 0:
        raise RuntimeError(f"benchmark failed ({proc.returncode}): {proc.stderr[-2000:]}")
    result = json.loads(proc.stdout)
    ours, theirs = float(result["ours_msgs_per_s"]), float(result["mavgen_c_msgs_per_s"])
    return {
        "ours_msgs_per_s": ours,
        "mavgen_c_msgs_per_s": theirs,
        "ratio": ours / theirs,
        "messages": STREAM_MESSAGES,
        "message_kinds": len(messages),
        "bytes": len(stream),
        "repetitions": int(result["repetitions"]),
    }


def main() -> None:  # pragma: no cover - manual runs: python -m ttctl.bench.codec_cpp [seconds]
    import tempfile

    with tempfile.TemporaryDirectory(prefix="ttctl-bench-cpp-") as tmp:
        print(json.dumps(run(Path(tmp), float(sys.argv[1]) if len(sys.argv) > 1 else 20), indent=2))


if __name__ == "__main__":  # pragma: no cover
    main()
