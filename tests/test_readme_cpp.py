"""The README's C++ onboard code, as it stands in README.md: the skeleton's methods it fills in,
the program for the drone (DJI Onboard SDK 3.9 or 4.1) and the one for a laptop (UDP). They are
taken out of the README, built with g++ -Werror (the methods put into a freshly generated
skeleton) against DJI's real Onboard SDK headers (tests/vendor/dji/, as system headers) with
tests/cpp/osdk_standin/ for the SDK's functions, which carries the packets over UDP on a thread of
its own, as the SDK calls back on its thread, and run against ttctl's emulated tablet through the
m100 relay, and against send-file."""

from __future__ import annotations

import hashlib
import json
import os
import random
import re
import shutil
import signal
import subprocess
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

from conftest import ROOT, TTAPI, manual, run_ttctl
from e2e_lib import LOCAL, Start, free_port, relay, send

pytestmark = pytest.mark.skipif(shutil.which("g++") is None, reason="needs g++")

WARN = ["-std=c++17", "-Wall", "-Wextra", "-Wpedantic", "-Werror"]
OSDK_STANDIN = ROOT / "tests" / "cpp" / "osdk_standin" / "fake_osdk.cpp"
OSDK = {"39": ROOT / "tests" / "vendor" / "dji" / "osdk-3.9.0", "41": ROOT / "tests" / "vendor" / "dji" / "osdk-4.1.0"}


def system_includes(root: Path) -> list[str]:
    """-isystem for every folder of vendored headers (as DJI's build puts them on the path)."""
    dirs = sorted({p.parent for p in root.rglob("*.h*")})
    return [arg for d in dirs for arg in ("-isystem", str(d))]


def blocks() -> dict[str, str]:
    """The cpp blocks of the README's C++ onboard section, by the file their first line names."""
    text = manual()
    section = text.split("### C++ onboard: the node", 1)[1].split("\n## ", 1)[0]
    out = {}
    for code in re.findall(r"```cpp\n(.+?)```", section, re.S):
        first = code.split("\n", 1)[0]
        m = re.match(r"// ([\w./]+)", first)
        assert m, first
        out[m.group(1)] = code
    return out


def fill_skeleton(skeleton: str, methods: str) -> str:
    """The README's methods in place of the skeleton's, its other members added to the class."""
    body = methods.split("\n", 1)[1]
    chunks = [c for c in re.split(r"\n\n(?=    \S)", body.rstrip("\n") + "\n") if c.strip()]
    extra = []
    for chunk in chunks:
        head = chunk.split("(", 1)[0] + "("
        if "(" in chunk.split("\n", 1)[0] and head in skeleton:
            start = skeleton.index(head)
            end = skeleton.index("\n    }\n", start) + len("\n    }\n")
            skeleton = skeleton[:start] + chunk.rstrip("\n") + "\n" + skeleton[end:]
        else:
            extra.append(chunk.rstrip("\n"))
    close = skeleton.rindex("\n};\n")
    return skeleton[:close] + "\n\n" + "\n".join(extra) + skeleton[close:]


def gxx(*args: str) -> None:
    proc = subprocess.run(["g++", *args], capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-5000:]


@pytest.fixture(scope="module")
def built(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    tmp = tmp_path_factory.mktemp("readme_cpp")
    code = blocks()
    assert set(code) == {"onboard/ttapi_plugin.hpp", "main.cpp", "laptop.cpp"}, sorted(code)
    out = tmp / "out"
    proc = run_ttctl("gen", str(TTAPI), "--lang", "cpp", "-o", str(out), timeout=300)
    assert proc.returncode == 0, proc.stderr
    skeleton = out / "cpp" / "onboard" / "ttapi_plugin.hpp"
    skeleton.write_text(fill_skeleton(skeleton.read_text(), code["onboard/ttapi_plugin.hpp"]))
    (tmp / "main.cpp").write_text(code["main.cpp"])
    (tmp / "laptop.cpp").write_text(code["laptop.cpp"])
    inc = ["-I", str(out / "cpp")]
    exes = {"main": tmp / "main", "main39": tmp / "main39", "laptop": tmp / "laptop"}
    with ThreadPoolExecutor(max_workers=2) as pool:
        jobs = [pool.submit(gxx, *WARN, "-O1", *inc, *system_includes(OSDK[v]), f"-DFAKE_OSDK_VERSION={v}",
                            str(tmp / "main.cpp"), str(OSDK_STANDIN), "-pthread", "-o",
                            str(exes["main" if v == "41" else "main39"]), "-lz") for v in OSDK]
        jobs.append(pool.submit(gxx, *WARN, "-O1", *inc, str(tmp / "laptop.cpp"), "-o", str(exes["laptop"]), "-lz"))
        for job in jobs:
            job.result()
    return exes


def sha(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


@pytest.mark.parametrize("exe", ["main", "main39"])
def test_the_osdk_program_against_the_emulated_tablet(built: dict[str, Path], tmp_path: Path, start: Start,
                                                      exe: str) -> None:
    (tmp_path / "outbox").mkdir()
    served = tmp_path / "outbox" / "log.bin"
    served.write_bytes(random.Random(1).randbytes(5000))
    up = tmp_path / "up.bin"
    up.write_bytes(random.Random(2).randbytes(1200))
    b = free_port()
    env = {**os.environ, "FAKE_OSDK_LISTEN": f"{LOCAL}:{b}"}
    with open(tmp_path / "main.out", "w") as out, open(tmp_path / "main.err", "w") as err:
        prog = subprocess.Popen([str(built[exe])], cwd=tmp_path, env=env, stdout=out, stderr=err)
    try:
        a = free_port()
        relay(start, a, b, "--profile", "m100", "--loss", "0.1", "--seed", "4", "--stats-interval", "0")
        script = tmp_path / "script.yaml"
        script.write_text("- takeoff: 3\n- goto: [3, 4, 5]\n- send: up.bin\n- fetch: log.bin\n"
                          "- msg: {send: DJI_POSE_STAMPED sec=9, until: DJI_POSE_STAMPED.sec == 9, timeout: 20}\n"
                          "- land\n")
        tablet = ["emulate", "tablet", "--to", f"udpout:{LOCAL}:{a}", "--profile", "m100", "--dir",
                  str(tmp_path / "tablet"), "--json", "--script", str(script)]
        proc = run_ttctl(*tablet, cwd=tmp_path, timeout=120)
        assert proc.returncode == 0, proc.stdout + proc.stderr
        steps = [json.loads(line) for line in proc.stdout.splitlines() if line.startswith("{")]
        assert [s["ok"] for s in steps if s.get("event") == "step"] == [True] * 6, proc.stdout
        assert sha(tmp_path / "inbox" / "up.bin") == sha(up)
        assert sha(tmp_path / "tablet" / "log.bin") == sha(served)
        script.write_text("- hover\n")
        proc = run_ttctl(*tablet, cwd=tmp_path, timeout=120)
        assert proc.returncode == 1 and "refused: this vehicle only takes off and lands" in proc.stderr, proc.stderr
        assert prog.poll() is None
    finally:
        prog.send_signal(signal.SIGINT)
        code = prog.wait(20)
    assert code == 0 and (tmp_path / "main.err").read_text() == ""


def test_the_laptop_program_takes_a_file(built: dict[str, Path], tmp_path: Path) -> None:
    port = 14560  # as the README has it
    src = tmp_path / "a.bin"
    src.write_bytes(random.Random(3).randbytes(9000))
    prog = subprocess.Popen([str(built["laptop"])], cwd=tmp_path, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    try:
        time.sleep(0.3)
        if prog.poll() is not None:
            pytest.skip(f"port {port} is taken here: {prog.stderr.read().decode() if prog.stderr else ''}")
        proc, r = send(str(src), "--to", f"udpout:{LOCAL}:{port}", "--rate", "8000", timeout=60)
        assert proc.returncode == 0 and r["ok"], proc.stderr
        assert sha(tmp_path / "inbox" / "a.bin") == sha(src)
    finally:
        prog.kill()
        prog.wait(10)
