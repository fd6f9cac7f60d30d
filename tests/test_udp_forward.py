"""The forwarders that let `ttctl bench link --to` measure DJI's real link: the generated Java
runtime.UdpForward on the tablet's DjiLink and the generated C++ udp_forward.hpp onboard, in a
chain of real processes where `ttctl link relay` stands for the radio and UDP sockets for the
two SDKs (tests/java/forward/ForwardDriver.java, tests/cpp/forward/forward_driver.cpp):

    bench link --to -> [Java UdpForward -> DjiLink -> "SDK"] -> relay -> ["OSDK" -> C++ UdpForward] -> bench serve

The measurement must come out as the relay's: its rate, its loss, its latency."""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import pytest

from conformance_lib import build_java
from conftest import ROOT, run_ttctl
from e2e_lib import LOCAL, Start, free_port

pytestmark = pytest.mark.skipif(not (shutil.which("javac") and shutil.which("java") and shutil.which("g++")),
                                reason="needs a JDK (javac, java) and g++")

RATE = 4000
LOSS = 0.05


@pytest.fixture(scope="module")
def built(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path]:
    """(Java classes, C++ driver), built from freshly generated code with warnings as errors."""
    base = tmp_path_factory.mktemp("udp_forward")
    cls, out = build_java(base, [ROOT / "tests" / "java" / "forward" / "ForwardDriver.java"], "cpp,java")
    exe = base / "forward_driver"
    gxx = subprocess.run(["g++", "-std=c++17", "-O1", "-Wall", "-Wextra", "-Werror", "-I", str(out / "cpp"), "-o",
                          str(exe), str(ROOT / "tests" / "cpp" / "forward" / "forward_driver.cpp")],
                         capture_output=True, text=True, timeout=600)
    assert gxx.returncode == 0, gxx.stderr[-6000:]
    return cls, exe


def _ready(p: subprocess.Popen[str]) -> str:
    assert p.stdout is not None
    line = p.stdout.readline()
    assert line.startswith("ready"), (line, p.stderr.read() if p.stderr else "")
    return line


def _finish(p: subprocess.Popen[str]) -> str:
    out, err = p.communicate(timeout=20)  # closes stdin: the driver prints its counters and exits
    assert p.returncode == 0, err
    return out


def test_bench_link_through_both_forwarders_measures_the_relay(built: tuple[Path, Path], start: Start) -> None:
    cls, exe = built
    serve_port, radio_port, relay_port = free_port(), free_port(), free_port()
    start("serve", "bench", "serve", "--listen", f"udpin:{LOCAL}:{serve_port}").wait_for("listening on")
    start("relay", "link", "relay", "--listen", f"udpin:{LOCAL}:{relay_port}", "--to", f"udpout:{LOCAL}:{radio_port}",
          "--profile", "m100", "--rate", str(RATE), "--loss", str(LOSS), "--seed", "3", "--stats-interval",
          "0").wait_for("relay: udpin")
    onboard = subprocess.Popen([str(exe), str(radio_port), str(serve_port)], stdin=subprocess.PIPE,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    tablet = subprocess.Popen(["java", "-cp", str(cls), "ForwardDriver", str(relay_port)], stdin=subprocess.PIPE,
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        _ready(onboard)
        port = int(_ready(tablet).split()[1])
        proc = run_ttctl("bench", "link", "--to", f"udpout:{LOCAL}:{port}", "--rate", str(2 * RATE), "--sizes",
                         "50,100", "--rates", "20,80", "--count", "150", "--json", timeout=120)
        assert proc.returncode == 0, proc.stderr[-3000:]
        rep = json.loads(proc.stdout)
        ups, downs = rep["uplink"]["rows"], rep["downlink"]["rows"]
        for row in ups + [downs[1]]:  # outpaced: the relay's rate
            assert abs(row["capacity_Bps"] - RATE) <= 0.15 * RATE, row
        gentle = downs[0]  # 2000 B/s into a 4000 B/s link: only the radio's loss
        assert gentle["received"] + gentle["lost"] == 150 and gentle["loss"] <= LOSS + 0.08, gentle
        # m100's 40 ms each way plus an 18-byte echo's time at 4000 B/s each way
        assert 80 <= rep["latency"]["rtt_p50_ms"] <= 130, rep["latency"]
        # counters: the tablet forwarded everything bench link sent (300 probes and the asking),
        # onboard what the relay let through (about half of the outpaced probes); down, the
        # 300 downlink probes less losses, and the answers
        counts = {}
        for name, p in (("tablet", tablet), ("onboard", onboard)):
            words = _finish(p).split()
            counts[name] = (int(words[1]), int(words[3]))
        assert counts["tablet"][0] > 300 and 150 < counts["onboard"][0] < counts["tablet"][0], counts
        assert counts["onboard"][1] > 200 and 150 < counts["tablet"][1] <= counts["onboard"][1], counts
    finally:
        for p in (tablet, onboard):
            if p.poll() is None:
                p.kill()
                p.wait(5)
