"""`ttctl bench codec`: the generated Python bindings against pymavlink (both with fastcrc)
on one mixed stream of every common.xml message with random values, decode and encode,
measured in interleaved rounds; optionally the generated C++ decoder against mavgen's C."""

from __future__ import annotations

import json
import random
import statistics
import tempfile
import time
from pathlib import Path
from typing import Any

from ..dialect.model import INTEGER_RANGES, Message

FLOORS = {"python_decode": 2.0, "python_encode": 1.5, "cpp_decode": 1.0}
STREAM_MESSAGES = 20_000


def random_values(m: Message, rng: random.Random) -> dict[str, Any]:
    """Field values in pymavlink's terms (char arrays bytes, arrays lists)."""
    out: dict[str, Any] = {}
    for f in m.fields:
        n = f.array_length
        if f.type == "char":
            size = max(n, 1)
            out[f.name] = bytes(rng.randint(32, 126) for _ in range(rng.randint(0, size)))
            continue

        def one(f: Any = f) -> Any:
            if f.is_float:
                return rng.uniform(-1000.0, 1000.0)
            lo, hi = INTEGER_RANGES[f.type]
            return rng.randint(lo, hi)

        out[f.name] = [one() for _ in range(n)] if n else one()
    return out


def build(seed: int = 1) -> dict[str, Any]:
    """The mixed stream and the message objects of both libraries, from the same values."""
    from pymavlink.dialects.v20 import common as pm

    import ttapi

    from ..dialect.source import pymavlink_dialects_dir
    from ..validate import load_and_check

    base = pymavlink_dialects_dir()
    assert base is not None
    dialect, _, _ = load_and_check(str(Path(base) / "common.xml"), [])
    rng = random.Random(seed)
    models = sorted((m for m in dialect.messages if m.complete), key=lambda m: m.id)
    mav = pm.MAVLink(None, srcSystem=1, srcComponent=1)
    pm_msgs, our_msgs, frames = [], [], []
    for i in range(STREAM_MESSAGES):
        m = models[i % len(models)] if i < len(models) else rng.choice(models)
        values = random_values(m, rng)
        pcls = pm.mavlink_map[m.id]
        pmsg = pcls(*[values[n] for n in pcls.fieldnames])
        frames.append(bytes(pmsg.pack(mav)))
        pm_msgs.append(pmsg)
        ours_values = {f.name: bytes(values[f.name]) if f.type == "uint8_t" and f.array_length else values[f.name]
                       for f in m.fields}
        our_msgs.append(ttapi.BY_NAME[m.name](**ours_values))
    stream = b"".join(frames)
    chunks = [stream[i:i + 4096] for i in range(0, len(stream), 4096)]
    return {"pm": pm, "ttapi": ttapi, "mav": mav, "pm_msgs": pm_msgs, "our_msgs": our_msgs, "chunks": chunks,
            "messages": len(frames), "kinds": len(models), "bytes": len(stream)}


def _rate(fn: Any, count: int, budget: float) -> float:
    reps, elapsed = 0, 0.0
    while elapsed < budget or reps == 0:
        t0 = time.perf_counter()
        fn()
        elapsed += time.perf_counter() - t0
        reps += 1
    return count * reps / elapsed


def measure(world: dict[str, Any], seconds: float, rounds: int) -> dict[str, Any]:
    pm, ttapi, mav = world["pm"], world["ttapi"], world["mav"]
    chunks, n = world["chunks"], world["messages"]

    def decode_ours() -> None:
        p = ttapi.Parser()
        got = sum(len(p.feed(c)) for c in chunks)
        assert got == n, got

    def decode_pm() -> None:
        m = pm.MAVLink(None)
        got = sum(len(m.parse_buffer(c) or ()) for c in chunks)
        assert got == n, got

    def encode_ours() -> None:
        for i, msg in enumerate(world["our_msgs"]):
            msg.pack(i & 0xFF, 1, 1)

    def encode_pm() -> None:
        for msg in world["pm_msgs"]:
            msg.pack(mav)

    cases = {"decode ttctl": decode_ours, "decode pymavlink": decode_pm,
             "encode ttctl": encode_ours, "encode pymavlink": encode_pm}
    rates: dict[str, list[float]] = {k: [] for k in cases}
    for _ in range(rounds):
        for k, fn in cases.items():
            rates[k].append(_rate(fn, n, seconds))
    return {k: statistics.median(v) for k, v in rates.items()}


def run(seconds: float, rounds: int, cpp: bool, as_json: bool) -> None:
    from ..errors import Fail

    try:
        import fastcrc  # noqa: F401 - both libraries use it when present; make sure they do
    except ImportError:
        raise Fail("fastcrc is not installed; both sides must use it for a fair comparison") from None
    world = build()
    med = measure(world, seconds, rounds)
    result: dict[str, Any] = {
        "stream": {"messages": world["messages"], "message_kinds": world["kinds"], "bytes": world["bytes"]},
        "msgs_per_s": {k: round(v) for k, v in med.items()},
        "ratios": {
            "python_decode": round(med["decode ttctl"] / med["decode pymavlink"], 2),
            "python_encode": round(med["encode ttctl"] / med["encode pymavlink"], 2),
        },
        "floors": FLOORS,
    }
    if cpp:
        from . import codec_cpp

        with tempfile.TemporaryDirectory(prefix="ttctl-bench-cpp-") as tmp:
            try:
                c = codec_cpp.run(Path(tmp), seconds_budget=max(2.0, seconds * rounds * 2))
            except (OSError, RuntimeError) as e:
                raise Fail(f"C++ benchmark failed: {e}") from None
        result["cpp"] = c
        result["ratios"]["cpp_decode"] = round(c["ratio"], 2)
    if as_json:
        print(json.dumps(result, indent=2))
        return
    from rich.console import Console
    from rich.table import Table

    console = Console()
    table = Table(title=f"{world['messages']} frames of {world['kinds']} common.xml messages, medians of {rounds}")
    table.add_column("measurement")
    table.add_column("messages/s", justify="right")
    for k, v in med.items():
        table.add_row(k, f"{v:,.0f}")
    if cpp:
        table.add_row("C++ decode ttctl", f"{result['cpp']['ours_msgs_per_s']:,.0f}")
        table.add_row("C++ decode mavgen C", f"{result['cpp']['mavgen_c_msgs_per_s']:,.0f}")
    console.print(table)
    for key, ratio in result["ratios"].items():
        floor = FLOORS[key]
        verdict = "[green]meets[/]" if ratio >= floor else "[red]misses[/]"
        console.print(f"{key.replace('_', ' ')}: [bold]{ratio:.2f}x[/] the peer ({verdict} the {floor}x floor)")
