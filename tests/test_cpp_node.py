"""The generated C++ onboard end (ttapi::link::Node on UDP) as a real process against ttctl's
Python ends, through `ttctl link relay --profile m100` (the emulated DJI radio) at 10 % loss.

The program is tests/cpp/node/onboard_node.cpp around the GENERATED skeleton
(cpp/onboard/ttapi_plugin.hpp) as a user edits it: on_command() counts and accepts (and refuses
trajectory flights, with words), the DJI_POSE_STAMPED handler echoes the pose. It is built with
g++ -std=c++17 -Wall -Wextra -Wpedantic -Werror, and once more with -fsanitize=address,undefined
for the hostile-input tests. What is checked:

- the emulated tablet's script (commands, a file up, a file fetched, a message answered by a
  handler) through the relay, random and burst loss: every command executed exactly once, acks
  repeated for retries; a retry whose ack was lost gets the recorded ack (deterministically, on
  raw UDP);
- `ttctl send-file` and `send-file --from`: the C++ node receives and serves at least 0.97 of the
  efficiency of Python's `recv-file --serve` on the same relay (mean of two runs each, the same
  relay seeds for both);
- SIGKILL mid-transfer: the receiving end killed and restarted resumes from its partial file
  (C++ -> Python -> C++: the partial file and its record are the same format), the sender killed
  and restarted resumes, a fetch whose C++ server was killed resumes;
- garbage and strangers change nothing; a signed link works, a wrong key is refused and counted;
- under ASan/UBSan: the shared name vectors (tests/data/names.json) offered raw, an offer beyond
  the quota, floods of offers, data, commands and fetch requests, garbage between frames:
  refused or dropped, counted, never a crash, nothing written outside the inbox, tables bounded;
  then a real transfer still works.
"""

from __future__ import annotations

import hashlib
import json
import os
import random
import shutil
import signal
import socket
import subprocess
import time
import unicodedata
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Any

import pytest

import ttapi
from conftest import ROOT, TTAPI, run_ttctl
from e2e_lib import LOCAL, Start, free_port, receiver, relay, send
from ttctl.wire.packets import packetize

pytestmark = pytest.mark.skipif(shutil.which("g++") is None, reason="needs g++")

WARN = ["-std=c++17", "-Wall", "-Wextra", "-Wpedantic", "-Werror"]
PROGRAM = ROOT / "tests" / "cpp" / "node" / "onboard_node.cpp"
SCHEDULER = ROOT / "tests" / "cpp" / "node" / "scheduler_driver.cpp"
NODE_DRIVER = ROOT / "tests" / "cpp" / "node" / "node_driver.cpp"
NAMES = json.loads((ROOT / "tests" / "data" / "names.json").read_text(encoding="utf-8"))["names"]
RATE = 8000  # B/s both ways in the efficiency runs: the relay's and both ends' pace
TABLET = (255, 190)

# The user's edits of the generated skeleton.
EDITS = [
    ("public:\n    const char* name() const noexcept override",
     "public:\n    std::uint64_t executed = 0;  // how many commands ran\n\n"
     "    const char* name() const noexcept override"),
    ("""        // TODO: carry out cmd.action (a TtAction) with cmd.param and cmd.argument, from system frame.sysid
        return {TtResult::TT_RESULT_UNSUPPORTED, "not implemented on this vehicle yet"};""",
     """        ++executed;
        if (cmd.action == static_cast<std::uint8_t>(TtAction::TT_ACTION_FLY_TRAJECTORY)) {
            return {TtResult::TT_RESULT_DENIED, "refused: this test vehicle flies no trajectories"};
        }
        return TtResult::TT_RESULT_ACCEPTED;"""),
    ("        // TODO: handle DJI_POSE_STAMPED (from system frame.sysid, component frame.compid); "
     "ctx.send(...) replies",
     """        DjiPoseStamped echo = msg;
        echo.target_system = frame.sysid;
        ctx.send(echo);"""),
]


def gxx(*args: str) -> None:
    proc = subprocess.run(["g++", *args], capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-5000:]


@pytest.fixture(scope="module")
def bins(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    """ttapi generated, the skeleton edited as a user would, the program built plain and with
    the sanitizers (in parallel)."""
    tmp = tmp_path_factory.mktemp("cpp_node")
    out = tmp / "out"
    proc = run_ttctl("gen", str(TTAPI), "--lang", "cpp", "-o", str(out), timeout=300)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    skeleton = out / "cpp" / "onboard" / "ttapi_plugin.hpp"
    text = skeleton.read_text()
    for old, new in EDITS:
        assert old in text, old
        text = text.replace(old, new)
    skeleton.write_text(text)
    inc = ["-I", str(out / "cpp"), "-I", str(skeleton.parent)]
    exes = {"plain": tmp / "onboard_node", "asan": tmp / "onboard_node_asan", "scheduler": tmp / "scheduler_driver",
            "driver": tmp / "node_driver"}
    with ThreadPoolExecutor(max_workers=2) as pool:
        jobs = [pool.submit(gxx, *WARN, "-O2", *inc, str(PROGRAM), "-o", str(exes["plain"])),
                pool.submit(gxx, *WARN, "-O1", "-g", "-fsanitize=address,undefined", "-fno-sanitize-recover=all",
                            "-fno-omit-frame-pointer", *inc, str(PROGRAM), "-o", str(exes["asan"])),
                pool.submit(gxx, *WARN, "-O1", *inc, str(SCHEDULER), "-o", str(exes["scheduler"])),
                pool.submit(gxx, *WARN, "-O1", *inc, str(NODE_DRIVER), "-o", str(exes["driver"]))]
        for job in jobs:
            job.result()
    return exes


class Node:
    """onboard_node as a process: JSON events on stdout (a file), stopped with SIGTERM."""

    def __init__(self, exe: Path, folder: Path, name: str, *args: str) -> None:
        self.name = name
        self.out_path = folder / f"{name}.out"
        self.err_path = folder / f"{name}.err"
        self._out = open(self.out_path, "w")  # noqa: SIM115 - closed in stop()
        self._err = open(self.err_path, "w")  # noqa: SIM115
        env = {**os.environ, "ASAN_OPTIONS": "detect_leaks=1:abort_on_error=0", "UBSAN_OPTIONS": "print_stacktrace=1"}
        self.p = subprocess.Popen([str(exe), *args], stdout=self._out, stderr=self._err, cwd=folder, env=env)
        self.port = int(self.wait_event("ready", 20)["port"])

    def events(self, kind: str | None = None) -> list[dict[str, Any]]:
        out = []
        for line in self.out_path.read_text().splitlines():
            try:
                e = json.loads(line)
            except ValueError:
                continue
            if kind is None or e.get("event") == kind:
                out.append(e)
        return out

    def wait_event(self, kind: str, timeout: float = 30.0, **match: Any) -> dict[str, Any]:
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            for e in self.events(kind):
                if all(e.get(k) == v for k, v in match.items()):
                    return e
            if self.p.poll() is not None:
                break
            time.sleep(0.02)
        raise AssertionError(f"{self.name}: no {kind} {match} (exit {self.p.poll()}):\n{self.out_path.read_text()}\n"
                             f"{self.err_path.read_text()[-4000:]}")

    def stop(self) -> dict[str, Any]:
        """SIGTERM; the stats line. The process must exit cleanly with nothing on stderr (the
        sanitizers report there)."""
        if self.p.poll() is None:
            self.p.send_signal(signal.SIGTERM)
        try:
            code = self.p.wait(20)
        finally:
            self._out.close()
            self._err.close()
        err = self.err_path.read_text()
        assert code == 0 and err == "", f"{self.name}: exit {code}\n{err[-6000:]}"
        stats = self.events("stats")
        assert stats, self.out_path.read_text()[-3000:]
        return stats[-1]

    def kill(self) -> None:
        if self.p.poll() is None:
            self.p.kill()
            self.p.wait(10)
        self._out.close()
        self._err.close()


@pytest.fixture
def nodes() -> Any:
    started: list[Node] = []

    def start(*args: Any, **kw: Any) -> Node:
        n = Node(*args, **kw)
        started.append(n)
        return n

    yield start
    for n in started:
        if n.p.poll() is None:
            n.kill()


def sha(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def write(path: Path, size: int, seed: int) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(random.Random(seed).randbytes(size))
    return path


class Raw:
    """A UDP socket that speaks MAVLink to the node directly: frames in packets, and what comes
    back decoded."""

    def __init__(self, port: int, sysid: int = 255, compid: int = 190) -> None:
        self.s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.s.bind((LOCAL, 0))
        self.s.settimeout(0.05)
        self.to = (LOCAL, port)
        self.enc = ttapi.Encoder(sysid=sysid, compid=compid)
        self.parser = ttapi.Parser()

    def frames(self, *msgs: Any) -> None:
        """The messages' frames in DTT packets, by the packing rule."""
        for p in packetize([self.enc.encode(m) for m in msgs]):
            self.s.sendto(p, self.to)

    def raw(self, data: bytes) -> None:
        self.s.sendto(data, self.to)

    def collect(self, seconds: float, until: Any = None) -> list[Any]:
        out: list[Any] = []
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            try:
                data, _ = self.s.recvfrom(2048)
            except TimeoutError:
                continue
            out.extend(ttapi.Parser().feed(data))
            if until is not None and until(out):
                break
        return out

    def close(self) -> None:
        self.s.close()


def offer_frames(name: bytes, payload: bytes, nonce: int, size: int | None = None) -> list[Any]:
    meta = hashlib.sha256(payload).digest() + name
    return [ttapi.TtFileOffer(target_system=1, target_component=240, transfer_id=nonce,
                              size=len(payload) if size is None else size, meta_length=len(meta), meta_offset=off,
                              meta=meta[off:off + 71]) for off in range(0, len(meta), 71)]


# -- the name rules -----------------------------------------------------------------------------

def test_name_rules_refuse_the_characters_python_refuses(bins: dict[str, Path]) -> None:
    """The C++ table of control and format characters is Python's unicodedata (Cc, Cf): checked
    for every code point when Python's Unicode is the table's (14.0.0)."""
    run = subprocess.run([str(bins["plain"]), "--print-name-rules"], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    got = [tuple(int(x, 16) for x in line.split()) for line in run.stdout.splitlines()]
    if unicodedata.unidata_version != "14.0.0":
        pytest.skip(f"Python's Unicode is {unicodedata.unidata_version}, the C++ table's 14.0.0")
    want: list[list[int]] = []
    for cp in range(1, 0x110000):
        if 0xD800 <= cp <= 0xDFFF or unicodedata.category(chr(cp)) not in ("Cc", "Cf"):
            continue
        if want and want[-1][1] == cp - 1:
            want[-1][1] = cp
        else:
            want.append([cp, cp])
    assert got == [tuple(w) for w in want]


# -- the scheduler: Python's decisions -----------------------------------------------------------

def scheduler_script(rng: random.Random) -> list[str]:
    """Random work for a scheduler: control frames (some keyed, as statuses are), telemetry,
    bulk sources of narrow (100-byte) and wide (267-byte) data frames coming and going, and
    packets asked for at rising times."""
    enc = ttapi.Encoder(sysid=1, compid=240)
    ops: list[str] = []
    live: list[int] = []
    now = 0.0
    queued = 0
    for _ in range(600):
        r = rng.random()
        if r < 0.15 and queued < 40:
            msg = rng.choice([ttapi.TtCommandAck(command_id=rng.randrange(65536), result=0, progress=100),
                              ttapi.TtFileStatus(transfer_id=rng.randrange(1, 4), result=0,
                                                 received_contiguous=rng.randrange(10**6), range_count=1,
                                                 ranges=[rng.randrange(100), 200] + [0] * 12),
                              ttapi.TtLog(id=0, severity=6, text="x" * rng.randint(1, 79))])
            key = rng.choice([0, 0, 1, 2, 3])
            ops.append(f"C {enc.encode(msg).hex()} {key}")
            queued += 1
        elif r < 0.25:
            msg = rng.choice([ttapi.Heartbeat(type=18, custom_mode=rng.randrange(2**32)),
                              ttapi.TtOdometry(time_usec=rng.randrange(2**40), position=[rng.random(), 0, 1])])
            ops.append(f"T {enc.encode(msg).hex()} 0")  # (Python's telemetry has no keys: the C++ one's are extra)
        elif r < 0.3 and len(live) < 3:
            sid = rng.randrange(1000)
            if sid not in live:
                live.append(sid)
                ops.append(f"S {sid}")
        elif r < 0.32 and live:
            ops.append(f"R {live.pop(rng.randrange(len(live)))}")
        elif r < 0.5 and live:
            sid = rng.choice(live)
            data = ttapi.TtFileDataWide(transfer_id=sid, offset=rng.randrange(10**6), data=rng.randbytes(247)) \
                if rng.random() < 0.4 else ttapi.TtFileData(transfer_id=sid, offset=rng.randrange(10**6),
                                                            data=rng.randbytes(80))
            ops.append(f"B {sid} {enc.encode(data).hex()}")
        else:
            now += rng.choice([0.0, 0.001, 0.005, 0.015, 0.05])
            ops.append(f"P {now!r}")
            queued = max(0, queued - 3)
    return ops


def python_packets(ops: list[str], mtu: int, rate: float) -> list[str]:
    from collections import deque

    from ttctl.proto.scheduler import CONTROL, TELEMETRY, Scheduler

    sched = Scheduler(mtu, rate)
    sources: dict[int, tuple[deque[bytes], Any]] = {}
    out = []
    for op in ops:
        parts = op.split()
        if parts[0] in ("C", "T"):
            key = int(parts[2])
            sched.send(bytes.fromhex(parts[1]), CONTROL if parts[0] == "C" else TELEMETRY, key=key or None)
        elif parts[0] == "S":
            q: deque[bytes] = deque()

            def pull(now: float, space: int, q: deque[bytes] = q) -> bytes | None:
                if not q or (len(q[0]) == 100 and space < 100):
                    return None
                return q.popleft()

            sources[int(parts[1])] = (q, pull)
            sched.add_source(pull)
        elif parts[0] == "R":
            sched.remove_source(sources[int(parts[1])][1])
        elif parts[0] == "B":
            sources[int(parts[1])][0].append(bytes.fromhex(parts[2]))
        else:
            pkt = sched.next_packet(float(parts[1]))
            out.append(pkt.hex() if pkt else "-")
    return out


@pytest.mark.parametrize("mtu,rate", [(100, 6700.0), (100, 0.0), (64, 500.0)])
def test_the_scheduler_builds_the_packets_pythons_builds(bins: dict[str, Path], mtu: int, rate: float) -> None:
    """On seeded random work (control frames keyed and not, telemetry, bulk sources coming and
    going, narrow and wide data frames, packets asked for at paced times), the C++ scheduler
    builds byte for byte the packets ttctl's Python one builds, at the same moments."""
    for seed in range(4):
        ops = scheduler_script(random.Random(seed))
        run = subprocess.run([str(bins["scheduler"]), str(mtu), str(rate)], input="\n".join(ops) + "\n",
                             capture_output=True, text=True, timeout=60)
        assert run.returncode == 0, run.stderr
        got = run.stdout.splitlines()
        want = python_packets(ops, mtu, rate)
        assert len(got) == len(want)
        for i, (g, w) in enumerate(zip(got, want, strict=True)):
            assert g == w, (seed, i, g, w)
        assert sum(p != "-" for p in want) > 30  # packets were built, not just refused


# -- the node: the Python endpoint's decisions ----------------------------------------------------

def receiving_script(tmp: Path, seed: int, loss: float, size: int) -> tuple[list[str], list[str]]:
    """A Python tablet (Endpoint 255/190, seeded) uploads a file and sends commands to a Python
    onboard Endpoint (1/240, paced at 6700 B/s) over a channel that loses `loss` of the packets
    either way, in virtual time (5 ms steps). Returns the onboard end's input as a node_driver
    script, and what it sent at each poll."""
    from ttctl.proto.endpoint import Endpoint
    from ttctl.proto.storage import BytesSource, ReceiveDir

    b = shipped_bindings()
    rng = random.Random(seed)
    tx = Endpoint(b, *TABLET, rate_Bps=500.0, rng=random.Random(seed))
    # an action that accepts every command, as node_driver's (without one, both ends answer UNSUPPORTED)
    rx = Endpoint(b, 1, 240, rate_Bps=6700.0, receive_dir=ReceiveDir(tmp / "python"),
                  action=lambda msg: int(ttapi.TtResult.TT_RESULT_ACCEPTED))
    data = random.Random(seed + 1).randbytes(size)
    sender = tx.send_file("f.bin", (1, 240), source=BytesSource(data, "f.bin"))
    script: list[str] = []
    sent: list[str] = []
    now = 0.0
    commands = 0
    while not sender.done and now < 300:
        if commands < 6 and rng.random() < 0.01:
            tx.command(b.TtActionCommand(action=commands % 5), (1, 240))
            commands += 1
        while (pkt := tx.poll(now)) is not None:
            if rng.random() >= loss:
                script.append(f"R {now!r} {pkt.hex()}")
                rx.receive(now, pkt)
        out = []
        while (pkt := rx.poll(now)) is not None:
            out.append(pkt)
        script.append(f"P {now!r}")
        sent.append(" ".join(p.hex() for p in out) or "-")
        for pkt in out:
            if rng.random() >= loss:
                tx.receive(now, pkt)
        now = round(now + 0.005, 6)
    assert sender.result is not None and sender.result.ok, sender.result
    assert (tmp / "python" / "f.bin").read_bytes() == data
    return script, sent


def shipped_bindings() -> Any:
    from conftest import shipped

    return shipped()


@pytest.mark.parametrize("seed,loss", [(1, 0.1), (2, 0.25)])
def test_the_node_answers_what_pythons_endpoint_answers(bins: dict[str, Path], tmp_path: Path, seed: int,
                                                        loss: float) -> None:
    """The C++ node and ttctl's Python Endpoint, as the onboard end of an upload with commands
    over a lossy channel in virtual time, given the same packets at the same moments, send the
    same packets byte for byte at the same moments: the same statuses (when, how many, which
    gaps, hold times), the same acks, the same pacing; and store the same file."""
    script, want = receiving_script(tmp_path, seed, loss, 20_000)
    run = subprocess.run([str(bins["driver"]), str(tmp_path / "cpp"), "-", "6700"], input="\n".join(script) + "\n",
                         capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    got = run.stdout.splitlines()
    assert len(got) == len(want)
    polls = [line for line in script if line.startswith("P")]
    for i, (g, w) in enumerate(zip(got, want, strict=True)):
        assert g == w, (i, polls[i], g, w)
    assert (tmp_path / "cpp" / "f.bin").read_bytes() == (tmp_path / "python" / "f.bin").read_bytes()
    assert sum(w != "-" for w in want) > 20


@pytest.mark.parametrize("seed,loss", [(3, 0.02), (4, 0.1), (5, 0.25)])
def test_the_node_serves_what_pythons_endpoint_serves(bins: dict[str, Path], tmp_path: Path, seed: int,
                                                      loss: float) -> None:
    """Two worlds in virtual time, alike but for the onboard end: a Python tablet fetches a file
    (TT_FILE_REQUEST) over a channel that loses `loss` of the packets either way, from ttctl's
    Python Endpoint in one world and from the C++ node (drawing the same transfer ids) in the
    other. At every 5 ms step both onboard ends send the same packets byte for byte: the same
    offers, the same narrow and wide data frames chosen from the same loss estimates, the same
    repeats, at the same pace; and both fetches complete."""
    from ttctl.proto.endpoint import Endpoint
    from ttctl.proto.storage import ReceiveDir

    b = shipped_bindings()
    serve = write(tmp_path / "serve" / "s.bin", 30_000, seed).parent
    onboard_seed = seed + 100
    draws = random.Random(onboard_seed)
    draws.randint(1, 65535)  # the endpoint's first command id: its first draw
    ids = [draws.getrandbits(32) for _ in range(8)]
    drv = subprocess.Popen([str(bins["driver"]), str(tmp_path / "cpp_in"), str(serve), "6700"], stdin=subprocess.PIPE,
                           stdout=subprocess.PIPE, text=True)
    assert drv.stdin is not None and drv.stdout is not None
    for i in ids:
        drv.stdin.write(f"I {i}\n")
    onboard = Endpoint(b, 1, 240, rate_Bps=6700.0, receive_dir=ReceiveDir(tmp_path / "py_in"), serve_dir=str(serve),
                       rng=random.Random(onboard_seed))
    worlds = []
    for name in ("python", "cpp"):
        done: list[bool] = []
        tab = Endpoint(b, *TABLET, rate_Bps=500.0, receive_dir=ReceiveDir(tmp_path / f"tablet_{name}"),
                       unsolicited=False, accept_commands=False, rng=random.Random(seed),
                       on_event=lambda what, obj, done=done: done.append(True) if what == "file-complete" else None)
        tab.request_file("s.bin", (1, 240))
        worlds.append((name, tab, random.Random(seed), done))
    now = 0.0
    steps = sent = wide = 0
    try:
        while not all(w[3] for w in worlds) and now < 120:
            outs = {}
            for name, tab, lose, _ in worlds:
                while (pkt := tab.poll(now)) is not None:
                    if lose.random() >= loss:
                        if name == "python":
                            onboard.receive(now, pkt)
                        else:
                            drv.stdin.write(f"R {now!r} {pkt.hex()}\n")
                if name == "python":
                    out = []
                    while (pkt := onboard.poll(now)) is not None:
                        out.append(pkt)
                else:
                    drv.stdin.write(f"P {now!r}\n")
                    drv.stdin.flush()
                    line = drv.stdout.readline().strip()
                    out = [] if line == "-" else [bytes.fromhex(h) for h in line.split()]
                outs[name] = out
                for pkt in out:
                    if lose.random() >= loss:
                        tab.receive(now, pkt)
            assert outs["cpp"] == outs["python"], (now, [p.hex() for p in outs["cpp"]],
                                                   [p.hex() for p in outs["python"]])
            sent += len(outs["python"])
            wide += sum(p.count(bytes.fromhex("59c300")) for p in outs["python"])  # TT_FILE_DATA_WIDE's msgid
            steps += 1
            now = round(now + 0.005, 6)
    finally:
        drv.stdin.close()
        drv.wait(20)
    assert all(w[3] for w in worlds), "a fetch did not complete"
    for name in ("python", "cpp"):
        assert (tmp_path / f"tablet_{name}" / "s.bin").read_bytes() == (serve / "s.bin").read_bytes()
    assert sent > 300 and steps > 300
    assert (wide > 20) == (loss < 0.05), wide  # little loss: wide frames (the choice is the same too)


# -- against the emulated tablet ----------------------------------------------------------------

SCRIPT = """\
- takeoff: 5
- hover
- send: up.bin
- fetch: served.bin
- msg: {send: DJI_POSE_STAMPED sec=7 topic_name=SETPOINT, until: DJI_POSE_STAMPED.sec == 7, timeout: 20}
- land
- return
- status
"""


def tablet(tmp: Path, port: int, script: str) -> tuple[subprocess.CompletedProcess[str], list[dict[str, Any]]]:
    (tmp / "script.yaml").write_text(script)
    proc = run_ttctl("emulate", "tablet", "--to", f"udpout:{LOCAL}:{port}", "--profile", "m100", "--script",
                     "script.yaml", "--dir", str(tmp / "tablet"), "--json", cwd=tmp, timeout=150)
    steps = [json.loads(line) for line in proc.stdout.splitlines() if line.startswith("{")]
    return proc, [s for s in steps if s.get("event") == "step"]


@pytest.mark.parametrize("model,seed", [("random", 5), ("burst", 6)])
def test_against_the_emulated_tablet(bins: dict[str, Path], tmp_path: Path, start: Start, nodes: Any, model: str,
                                     seed: int) -> None:
    """`ttctl emulate tablet --script` through the m100 relay at 10 % loss: it sees the vehicle
    (HEARTBEAT), its commands are acknowledged and each runs once (retries answered from the
    record), a file goes up, another comes down, a message is answered by the skeleton's
    handler; a trajectory flight is refused in the handler's words."""
    inbox, serve = tmp_path / "inbox", tmp_path / "serve"
    served = write(serve / "served.bin", 8000, 1)
    up = write(tmp_path / "up.bin", 1000, 2)
    b = free_port()
    node = nodes(bins["plain"], tmp_path, "node", "--listen", f"udpin:{LOCAL}:{b}", "--inbox", str(inbox), "--serve",
                 str(serve))
    a = free_port()
    relay(start, a, b, "--profile", "m100", "--loss", "0.1", "--loss-model", model, "--seed", str(seed),
          "--stats-interval", "0")
    proc, steps = tablet(tmp_path, a, SCRIPT)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "tablet: connected to 1/240" in proc.stderr
    assert [s["ok"] for s in steps] == [True] * 8, proc.stdout
    assert sha(inbox / "up.bin") == sha(up)
    assert sha(tmp_path / "tablet" / "served.bin") == sha(served)
    proc, steps = tablet(tmp_path, a, "- fly: route.yaml\n")
    assert proc.returncode == 1 and len(steps) == 1 and not steps[0]["ok"], proc.stdout + proc.stderr
    assert "refused: this test vehicle flies no trajectories" in steps[0]["reason"], steps  # the handler's words
    commands = node.events("command")
    ran = [c for c in commands if not c["repeated"]]
    # take-off, hover, land, return and the refused flight: each run once, whatever was retried
    assert sorted(c["action"] for c in ran) == [0, 1, 2, 3, 5], commands
    assert len({c["command_id"] for c in ran}) == len(ran)
    assert [c["result"] for c in ran if c["action"] != 2] == [0, 0, 0, 0]  # ACCEPTED
    assert [c["result"] for c in ran if c["action"] == 2] == [4]  # DENIED
    stats = node.stop()
    assert stats["plugin_executed"] == stats["executed"] == 5, stats
    assert stats["duplicates"] == sum(c["repeated"] for c in commands)
    print("MEASURED", json.dumps({"model": model, "commands": len(ran), "repeated_acks": stats["duplicates"]}))


def test_a_retry_whose_ack_was_lost_gets_the_recorded_ack(bins: dict[str, Path], tmp_path: Path, nodes: Any) -> None:
    """The tablet's ack is lost (this test ignores it) and it sends the command again: the node
    answers with the same ack and does not run the action again; the same command id with a new
    issue time is a new command and runs. The refusal's words leave ahead of the refusing ack."""
    node = nodes(bins["plain"], tmp_path, "node", "--listen", f"udpin:{LOCAL}:0", "--heartbeat", "0")
    raw = Raw(node.port)
    try:
        cmd = ttapi.TtActionCommand(target_system=1, target_component=240, command_id=77, action=1, time_usec=1000)
        acks: list[Any] = []
        for _ in range(3):  # the first ack "lost", two retries
            raw.frames(cmd)
            got = raw.collect(2.0, until=lambda m: any(isinstance(x, ttapi.TtCommandAck) for x in m))
            acks += [m for m in got if isinstance(m, ttapi.TtCommandAck)]
        assert len(acks) == 3 and {(a.command_id, a.result, a.progress) for a in acks} == {(77, 0, 100)}
        raw.frames(ttapi.TtActionCommand(target_system=1, target_component=240, command_id=77, action=1,
                                         time_usec=2000))
        got = raw.collect(2.0, until=lambda m: any(isinstance(x, ttapi.TtCommandAck) for x in m))
        assert [m.command_id for m in got if isinstance(m, ttapi.TtCommandAck)] == [77]
        raw.frames(ttapi.TtActionCommand(target_system=1, target_component=240, command_id=78, action=2,
                                         time_usec=3000))
        got = raw.collect(2.0, until=lambda m: any(isinstance(x, ttapi.TtCommandAck) for x in m))
        kinds = [type(m).__name__ for m in got if isinstance(m, (ttapi.TtLog, ttapi.TtCommandAck))]
        assert kinds == ["TtLog", "TtCommandAck"], kinds  # the words first
        log = next(m for m in got if isinstance(m, ttapi.TtLog))
        assert log.text == "refused: this test vehicle flies no trajectories" and log.severity == 4
    finally:
        raw.close()
    stats = node.stop()
    assert (stats["executed"], stats["duplicates"], stats["plugin_executed"]) == (3, 2, 3), stats


# -- efficiency against Python's receiver -------------------------------------------------------

def one_run(start: Start, tmp: Path, exe: Path | None, nodes: Any, seed: int, up: Path, name: str) -> dict[str, float]:
    """The C++ node (exe) or recv-file --serve, paced at RATE: `up` sent to it, then the served
    file fetched from it, each through a fresh relay (m100 at RATE, 10 % random loss, `seed`), so
    that both implementations meet the same losses; both efficiencies (send-file's)."""
    inbox = tmp / f"inbox_{name}"
    b = free_port()
    if exe is not None:
        node = nodes(exe, tmp, name, "--listen", f"udpin:{LOCAL}:{b}", "--inbox", str(inbox), "--serve",
                     str(tmp / "serve"), "--rate", str(RATE))
    else:
        py = receiver(start, tmp, f"udpin:{LOCAL}:{b}", "--rate", str(RATE), "--serve", str(tmp / "serve"), "--dir",
                      str(inbox), name=name)

    def air() -> tuple[Any, int]:
        a = free_port()
        return relay(start, a, b, "--profile", "m100", "--rate", str(RATE), "--loss", "0.1", "--seed", str(seed),
                     "--stats-interval", "0"), a

    radio, a = air()
    proc, r = send(str(up), "--to", f"udpout:{LOCAL}:{a}", "--rate", str(RATE), "--timeout", "30", timeout=120)
    assert proc.returncode == 0 and r["ok"], proc.stderr
    assert sha(inbox / up.name) == sha(up)
    radio.kill()
    radio, a = air()
    got = tmp / f"got_{name}"
    got.mkdir()
    proc, f = send("served.bin", "--from", f"udpout:{LOCAL}:{a}", "--dir", str(got), "--rate", str(RATE), "--timeout",
                   "30", timeout=120)
    assert proc.returncode == 0 and f["ok"], proc.stderr
    assert sha(got / "served.bin") == sha(tmp / "serve" / "served.bin")
    radio.kill()
    if exe is not None:
        node.stop()
    else:
        py.kill()
    return {"receive": r["efficiency"], "serve": f["efficiency"]}


def test_receive_and_serve_efficiency_vs_python(bins: dict[str, Path], tmp_path: Path, start: Start,
                                                nodes: Any) -> None:
    """32 KiB each way through the m100 relay at 8 KB/s and 10 % loss, against the C++ node and
    against `ttctl recv-file --serve`, each transfer through a fresh relay with the same seed for
    both; two runs each, alternating.
    The C++ node's efficiency (file bytes / (seconds x link rate), as send-file measures it)
    is at least 0.97 of Python's, receiving and serving."""
    write(tmp_path / "serve" / "served.bin", 32 * 1024, 3)
    cpp, py = [], []
    for run, seed in enumerate((11, 12)):
        up = write(tmp_path / f"up{run}.bin", 32 * 1024, 10 + run)
        cpp.append(one_run(start, tmp_path, bins["plain"], nodes, seed, up, f"cpp{run}"))
        py.append(one_run(start, tmp_path, None, nodes, seed, up, f"py{run}"))
    mean = {k: {side: sum(r[side] for r in runs) / len(runs) for side in ("receive", "serve")}
            for k, runs in (("cpp", cpp), ("python", py))}
    report = {"cpp": cpp, "python": py, "receive_ratio": round(mean["cpp"]["receive"] / mean["python"]["receive"], 3),
              "serve_ratio": round(mean["cpp"]["serve"] / mean["python"]["serve"], 3)}
    print("MEASURED", json.dumps(report))
    assert report["receive_ratio"] >= 0.97 and report["serve_ratio"] >= 0.97, report


# -- SIGKILL and resume --------------------------------------------------------------------------

def partial_bytes(inbox: Path) -> int:
    """What the partial files' records say was received."""
    total = 0
    for rec in (inbox / ".ttctl-partial").glob("*.json"):
        try:
            state = json.loads(rec.read_text())
        except ValueError:
            continue
        total += sum(b - a for a, b in state["ranges"])
    return total


def wait_partial(inbox: Path, at_least: int, timeout: float = 30.0) -> int:
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        n = partial_bytes(inbox)
        if n >= at_least:
            return n
        time.sleep(0.05)
    raise AssertionError(f"the partial file never held {at_least} bytes ({partial_bytes(inbox)})")


def test_the_receiver_killed_mid_transfer_resumes_cpp_python_cpp(bins: dict[str, Path], tmp_path: Path,
                                                                 start: Start, nodes: Any) -> None:
    """One upload (`send-file`, paced at 8 KB/s) while its receiver is SIGKILLed twice: the C++
    node, then ttctl's Python recv-file in its place on the same folder, then the C++ node again.
    Each resumes the partial file the other left (one format), the sender carries on, and the
    file arrives whole; what a receiver had is not sent again."""
    inbox = tmp_path / "inbox"
    src = write(tmp_path / "big.bin", 40_000, 4)
    port = free_port()
    spec = f"udpin:{LOCAL}:{port}"
    first = nodes(bins["plain"], tmp_path, "node1", "--listen", spec, "--inbox", str(inbox))
    sender = start("send", "send-file", str(src), "--to", f"udpout:{LOCAL}:{port}", "--rate", "8000", "--json",
                   "--timeout", "60")
    had1 = wait_partial(inbox, 10_000)
    first.kill()
    py = receiver(start, tmp_path, spec, "--dir", str(inbox), "--json", name="py")
    py.wait_for('"event": "accepted"', 30, where="stdout")
    accepted = next(json.loads(line) for line in py.stdout.splitlines() if "\"accepted\"" in line)
    assert accepted["resumed_bytes"] >= had1, accepted  # Python resumed the C++ partial
    had2 = wait_partial(inbox, accepted["resumed_bytes"] + 10_000)
    py.kill()
    last = nodes(bins["plain"], tmp_path, "node2", "--listen", spec, "--inbox", str(inbox))
    acc = last.wait_event("accepted", 30)
    assert acc["resumed_bytes"] >= had2 - 2000, (acc, had2)  # the C++ node resumed Python's partial
    last.wait_event("complete", 60)
    assert sender.wait(60) == 0, sender.stderr
    r = json.loads(sender.stdout)
    assert r["ok"] and sha(inbox / "big.bin") == sha(src)
    assert not list((inbox / ".ttctl-partial").glob("*"))  # done: no partial state left
    # each restart cost at most the frames in flight and the unsaved tail, not the file again
    print("MEASURED", json.dumps({"size": 40_000, "bytes_sent": r["bytes_sent"], "resumed_cpp_to_py":
                                  accepted["resumed_bytes"], "resumed_py_to_cpp": acc["resumed_bytes"]}))
    assert r["bytes_sent"] < 40_000 * 1.3, r
    last.stop()


def test_the_sender_killed_mid_upload_resumes(bins: dict[str, Path], tmp_path: Path, start: Start,
                                              nodes: Any) -> None:
    """`ttctl send-file` SIGKILLed half way and started again: the C++ node offers what it has,
    and only the rest is sent."""
    inbox = tmp_path / "inbox"
    src = write(tmp_path / "half.bin", 32_000, 5)
    node = nodes(bins["plain"], tmp_path, "node", "--listen", f"udpin:{LOCAL}:0", "--inbox", str(inbox))
    to = f"udpout:{LOCAL}:{node.port}"
    s1 = start("send1", "send-file", str(src), "--to", to, "--rate", "8000", "--json")
    had = wait_partial(inbox, 12_000)
    s1.kill()
    time.sleep(0.3)
    proc, r = send(str(src), "--to", to, "--rate", "8000", timeout=60)
    assert proc.returncode == 0 and r["ok"], proc.stderr
    assert sha(inbox / "half.bin") == sha(src)
    accepted = node.events("accepted")
    assert len(accepted) == 2 and accepted[1]["resumed_bytes"] >= had, accepted
    assert r["resumed_bytes"] >= had and r["bytes_sent"] <= 32_000 - had + 4000, r
    node.stop()


def test_a_fetch_whose_server_was_killed_resumes(bins: dict[str, Path], tmp_path: Path, start: Start,
                                                 nodes: Any) -> None:
    """The C++ node serving a fetch is SIGKILLed half way; started again, the same fetch
    resumes from the fetcher's partial file and completes."""
    serve = tmp_path / "serve"
    src = write(serve / "log.bin", 32_000, 6)
    port = free_port()
    spec = f"udpin:{LOCAL}:{port}"
    got = tmp_path / "got"
    got.mkdir()
    n1 = nodes(bins["plain"], tmp_path, "node1", "--listen", spec, "--serve", str(serve), "--rate", "8000")
    fetch = start("fetch1", "send-file", "log.bin", "--from", f"udpout:{LOCAL}:{port}", "--dir", str(got), "--rate",
                  "8000", "--json")
    had = wait_partial(got, 12_000)
    n1.kill()
    fetch.signal(signal.SIGINT)
    assert fetch.wait(20) in (1, 130, 0)
    n2 = nodes(bins["plain"], tmp_path, "node2", "--listen", spec, "--serve", str(serve), "--rate", "8000")
    proc, r = send("log.bin", "--from", f"udpout:{LOCAL}:{port}", "--dir", str(got), "--rate", "8000", timeout=60)
    assert proc.returncode == 0 and r["ok"], proc.stderr
    assert sha(got / "log.bin") == sha(src)
    # frames of 80 bytes: the resumed fetch needed about the rest only
    assert r["frames_received"] * 80 < 32_000 - had + 8000, (r, had)
    assert n2.events("served")
    n2.stop()


# -- garbage, strangers, signing -----------------------------------------------------------------

def rss_kb(pid: int) -> int:
    for line in Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1])
    return 0


def junk(rng: random.Random) -> bytes:
    kind = rng.randrange(4)
    if kind == 0:
        return rng.randbytes(rng.randint(1, 100))
    if kind == 1:
        return b"\xfd" + rng.randbytes(rng.randint(0, 99))  # a magic and nothing that follows
    if kind == 2:  # a valid frame cut short, then more junk
        frame = ttapi.encode(ttapi.TtFileOffer(target_system=1, transfer_id=rng.randrange(1, 2**32), meta_length=40),
                             0, 255, 190)
        return frame[:rng.randint(1, len(frame) - 1)] + rng.randbytes(rng.randint(0, 10))
    return rng.randbytes(rng.randint(101, 300))  # longer than a DTT packet


def flood(raw: Raw, rng: random.Random, count: int, first_id: int) -> None:
    """Offers whose metadata never completes, data for transfers nobody offered, commands for
    another vehicle, fetch requests whose name never completes, garbage: from a stranger."""
    for i in range(count):
        tid = first_id + i
        k = i % 5
        if k == 0:
            raw.frames(offer_frames(b"x" * 100, b"", tid, size=10)[0])  # 2 parts of 3: never whole
        elif k == 1:
            raw.frames(ttapi.TtFileData(transfer_id=tid, offset=rng.randrange(2**32), data=rng.randbytes(80)))
        elif k == 2:
            raw.frames(ttapi.TtActionCommand(target_system=9, target_component=240, command_id=tid & 0xFFFF, action=0))
        elif k == 3:
            raw.frames(ttapi.TtFileRequest(target_system=1, target_component=240, request_id=tid, name_length=200,
                                           name_offset=0, name=b"n" * 80))
        else:
            raw.raw(junk(rng))
        if i % 50 == 49:
            time.sleep(0.005)  # a socket buffer's worth at a time


def test_garbage_and_strangers_change_nothing_and_memory_stays_bounded(bins: dict[str, Path], tmp_path: Path,
                                                                         start: Start, nodes: Any) -> None:
    """During an upload: garbage datagrams from another port, and a stranger (77/1) sending data
    under the upload's own transfer id, an offer of the same name, commands for another
    vehicle, floods of offers, data and requests. The file arrives intact, nothing else is
    stored or run, the stranger's offer is told BUSY; the node's memory stays where two floods
    of thousands of frames put it (its tables are fixed)."""
    inbox = tmp_path / "inbox"
    src = write(tmp_path / "a.bin", 30_000, 7)
    node = nodes(bins["plain"], tmp_path, "node", "--listen", f"udpin:{LOCAL}:0", "--inbox", str(inbox))
    stranger = Raw(node.port, sysid=77, compid=1)
    rng = random.Random(9)
    try:
        flood(stranger, rng, 3000, 10_000)
        rss1 = rss_kb(node.p.pid)
        sender = start("send", "send-file", str(src), "--to", f"udpout:{LOCAL}:{node.port}", "--rate", "8000",
                       "--json")
        acc = node.wait_event("accepted", 20, name="a.bin")
        assert acc["peer"] == "255/190"
        # the stranger: an offer of the same file name, and zeros under the upload's own id
        stranger.frames(*offer_frames(b"a.bin", b"other", 4242, size=5))
        for off in range(0, 30_000, 80):
            stranger.frames(ttapi.TtFileData(transfer_id=acc["transfer_id"], offset=off, data=b"\0" * 80))
        flood(stranger, rng, 3000, 50_000)
        rss2 = rss_kb(node.p.pid)
        assert sender.wait(60) == 0, sender.stderr
    finally:
        stranger.close()
    r = json.loads(sender.stdout)
    assert r["ok"] and r["restarts"] == 0 and sha(inbox / "a.bin") == sha(src)
    busy = node.wait_event("busy", 5)
    assert busy["peer"] == "77/1" and "being received from 255/190 right now" in busy["reason"], busy
    assert sorted(p.name for p in inbox.iterdir()) == [".ttctl-partial", "a.bin"]
    stats = node.stop()
    assert stats["executed"] == 0 and stats["files_received"] == 1, stats
    assert stats["requests_forgotten"] > 500 and stats["oversize"] > 0 and stats["ignored"] >= 1200, stats
    print("MEASURED", json.dumps({"rss_after_first_flood_kb": rss1, "rss_after_second_kb": rss2}))
    assert rss2 - rss1 < 2048, (rss1, rss2)  # bounded: the second flood found the tables at their size


def test_a_signed_link_works_and_a_wrong_key_is_refused(bins: dict[str, Path], tmp_path: Path, nodes: Any) -> None:
    """The node with --key and `send-file --key` with the same passphrase: an upload and a fetch
    work, every frame signed both ways. Another key, or none: nothing is accepted, the node
    counts the refused frames and says once that it refuses that peer."""
    (tmp_path / "key").write_text("our secret\n")
    (tmp_path / "other").write_text("not our secret\n")
    inbox = tmp_path / "inbox"
    src = write(tmp_path / "s.bin", 12_000, 8)
    served = write(tmp_path / "serve" / "d.bin", 12_000, 9)
    node = nodes(bins["plain"], tmp_path, "node", "--listen", f"udpin:{LOCAL}:0", "--inbox", str(inbox), "--serve",
                 str(served.parent), "--key", str(tmp_path / "key"), "--rate", "8000")
    to = f"udpout:{LOCAL}:{node.port}"
    proc, r = send(str(src), "--to", to, "--rate", "8000", "--key", str(tmp_path / "key"), timeout=60)
    assert proc.returncode == 0 and r["ok"], proc.stderr
    assert sha(inbox / "s.bin") == sha(src)
    # served signed: 113-byte data frames span two packets, signed as they are placed, nothing between
    (tmp_path / "got").mkdir()
    proc, f = send("d.bin", "--from", to, "--dir", str(tmp_path / "got"), "--rate", "8000", "--key",
                   str(tmp_path / "key"), timeout=60)
    assert proc.returncode == 0 and f["ok"], proc.stderr
    assert sha(tmp_path / "got" / "d.bin") == sha(served)
    for key in (["--key", str(tmp_path / "other")], []):
        proc, r = send(str(src), "--to", to, "--name", "t.bin", "--rate", "8000", "--timeout", "2", *key, timeout=60)
        assert proc.returncode == 1 and r["code"] == "TIMEOUT", proc.stderr
    assert not (inbox / "t.bin").exists()
    refused = node.events("link-refused")
    stats = node.stop()
    assert stats["refused_signature"] >= 4 and len(refused) >= 1, (stats, refused)


# -- hostile input under the sanitizers ----------------------------------------------------------

def reason_fit(text: str) -> str:
    raw = text.encode()
    return text if len(raw) <= 80 else raw[:77].decode("utf-8", "ignore") + "..."


def test_hostile_input_under_asan(bins: dict[str, Path], tmp_path: Path, start: Start, nodes: Any) -> None:
    """The ASan/UBSan build, listening. Every name of tests/data/names.json is offered raw: the
    refused ones get TT_FILE_REASON in the receiver's words (as Python's) and REFUSED_NAME, the
    others are stored inside the inbox. An offer beyond --max-file is refused for its quota;
    offers claiming impossible metadata are dropped; floods of offers, data, commands, requests
    and garbage are absorbed; then a real upload still works. No sanitizer report, no file
    outside the inbox."""
    jail = tmp_path / "jail"
    inbox = jail / "inbox"
    (jail / "outside").mkdir(parents=True)
    node = nodes(bins["asan"], tmp_path, "asan", "--listen", f"udpin:{LOCAL}:0", "--inbox", str(inbox), "--max-file",
                 "100000", "--heartbeat", "0")
    raw = Raw(node.port)
    rng = random.Random(11)
    try:
        def answer(tid: int) -> list[Any]:
            return raw.collect(3.0, until=lambda ms: any(isinstance(m, ttapi.TtFileStatus) and m.transfer_id == tid
                                                         for m in ms))

        stored = []
        for i, case in enumerate(NAMES):
            name = bytes.fromhex(case["hex"])
            if len(name) + 32 > 255:
                continue  # cannot even be offered: the metadata length is one byte
            tid = 5000 + i
            raw.frames(*offer_frames(name, b"data", tid))
            got = answer(tid)
            status = [m for m in got if isinstance(m, ttapi.TtFileStatus) and m.transfer_id == tid]
            reasons = [m for m in got if isinstance(m, ttapi.TtFileReason) and m.transfer_id == tid]
            assert status, (case, got)
            if case["refused"] is None:
                assert status[0].result == ttapi.TtFileResult.TT_FILE_RESULT_IN_PROGRESS, case
                raw.frames(ttapi.TtFileData(transfer_id=tid, offset=0, data=b"data"))
                done = raw.collect(3.0, until=lambda ms, t=tid: any(
                    isinstance(m, ttapi.TtFileStatus) and m.transfer_id == t and m.result == 1 for m in ms))
                assert any(isinstance(m, ttapi.TtFileStatus) and m.result == 1 for m in done), case
                stored.append(name.decode())
            else:
                assert status[0].result == ttapi.TtFileResult.TT_FILE_RESULT_REFUSED_NAME, case
                assert reasons and reasons[0].text == reason_fit(case["refused"]), (case, reasons)
        for name in stored:
            assert (inbox / name).read_bytes() == b"data", name
        # links someone left in the inbox: through a directory link, and a dangling file link
        (inbox / "esc").symlink_to(jail / "outside", target_is_directory=True)
        (inbox / "dangling.bin").symlink_to(jail / "outside" / "planted.bin")
        for tid, name, code in ((9101, b"esc/x.bin", ttapi.TtFileResult.TT_FILE_RESULT_REFUSED_NAME),
                                (9102, b"dangling.bin", ttapi.TtFileResult.TT_FILE_RESULT_REFUSED_EXISTS)):
            raw.frames(*offer_frames(name, b"data", tid))
            got = answer(tid)
            assert [m.result for m in got if isinstance(m, ttapi.TtFileStatus) and m.transfer_id == tid][:1] == [code]
        assert [m.text for m in got if isinstance(m, ttapi.TtFileReason)][:1] == [
            "dangling.bin exists here and is a symbolic link"]
        # beyond the quota
        raw.frames(*offer_frames(b"big.bin", b"", 9001, size=100_001))
        got = answer(9001)
        assert [m.result for m in got if isinstance(m, ttapi.TtFileStatus)][:1] == [
            ttapi.TtFileResult.TT_FILE_RESULT_REFUSED_QUOTA]
        assert [m.text for m in got if isinstance(m, ttapi.TtFileReason)][:1] == [
            "100001 bytes exceed the per-file quota of 100000 bytes"]
        # metadata that cannot be: offsets past the end, lengths that disagree, a zero id
        raw.frames(ttapi.TtFileOffer(target_system=1, transfer_id=9002, size=5, meta_length=255, meta_offset=250,
                                     meta=b"\xff" * 71),
                   ttapi.TtFileOffer(target_system=1, transfer_id=9002, size=6, meta_length=40, meta_offset=0),
                   ttapi.TtFileOffer(target_system=1, transfer_id=0, size=5, meta_length=33, meta_offset=0,
                                     meta=b"a" * 33))
        flood(raw, rng, 4000, 100_000)
        for _ in range(300):  # garbage between frames, in one packet
            frame = ttapi.encode(ttapi.Heartbeat(), 0, 255, 190)
            raw.raw((rng.randbytes(rng.randint(0, 20)) + frame + rng.randbytes(rng.randint(0, 20)))[:100])
        cmds = [ttapi.TtActionCommand(target_system=1, target_component=240, command_id=i, action=3, time_usec=i)
                for i in range(700)]
        for i in range(0, 700, 4):
            raw.frames(*cmds[i:i + 4])
            time.sleep(0.002)
    finally:
        raw.close()
    src = write(tmp_path / "after.bin", 8000, 12)
    proc, r = send(str(src), "--to", f"udpout:{LOCAL}:{node.port}", "--rate", "8000", timeout=90)
    assert proc.returncode == 0 and r["ok"], proc.stderr
    assert sha(inbox / "after.bin") == sha(src)
    stats = node.stop()  # exit 0 and nothing on stderr: no sanitizer report
    assert stats["commands_forgotten"] > 0 and stats["executed"] <= 700, stats
    assert stats["requests_forgotten"] > 0 and stats["bad_frames"] + stats["oversize"] > 0, stats
    assert list((jail / "outside").iterdir()) == []
    escaped = [p for p in tmp_path.rglob("*") if p.is_file() and inbox not in p.parents
               and p.suffix not in (".out", ".err", ".bin")]
    assert escaped == [], escaped


def test_several_transfers_at_once(bins: dict[str, Path], tmp_path: Path, start: Start, nodes: Any) -> None:
    """Three uploads from three send-file processes (the same MAVLink ids, other transfer ids)
    and a fetch, all at once: each arrives whole; the data of one never lands in another."""
    inbox = tmp_path / "inbox"
    served = write(tmp_path / "serve" / "d.bin", 16_000, 20)
    node = nodes(bins["plain"], tmp_path, "node", "--listen", f"udpin:{LOCAL}:0", "--inbox", str(inbox), "--serve",
                 str(served.parent), "--rate", "20000")
    to = f"udpout:{LOCAL}:{node.port}"
    srcs = [write(tmp_path / f"u{i}.bin", 16_000, 21 + i) for i in range(3)]
    ups = [start(f"send{i}", "send-file", str(s), "--to", to, "--rate", "6000", "--json") for i, s in enumerate(srcs)]
    (tmp_path / "got").mkdir()
    fetch = start("fetch", "send-file", "d.bin", "--from", to, "--dir", str(tmp_path / "got"), "--rate", "6000",
                  "--json")
    for proc in [*ups, fetch]:
        assert proc.wait(60) == 0, proc.stderr
        assert json.loads(proc.stdout)["ok"]
    for s in srcs:
        assert sha(inbox / s.name) == sha(s)
    assert sha(tmp_path / "got" / "d.bin") == sha(served)
    accepted = node.events("accepted")
    assert len({e["transfer_id"] for e in accepted}) == 3
    node.stop()


def test_the_node_uploads_to_recv_file(bins: dict[str, Path], tmp_path: Path, start: Start, nodes: Any) -> None:
    """Node::send_file, an upload from the onboard end (system 2 here) to `ttctl recv-file`
    (1/240) through the m100 relay at 10 % loss: it arrives whole, verified."""
    src = write(tmp_path / "up.bin", 20_000, 30)
    b = free_port()
    rx = receiver(start, tmp_path, f"udpin:{LOCAL}:{b}", "--rate", str(RATE), "--json")
    a = free_port()
    relay(start, a, b, "--profile", "m100", "--rate", str(RATE), "--loss", "0.1", "--seed", "8", "--stats-interval",
          "0")
    node = nodes(bins["plain"], tmp_path, "node", "--to", f"udpout:{LOCAL}:{a}", "--sysid", "2", "--rate", str(RATE),
                 "--send", str(src), "--send-to", "1/240")
    sent = node.wait_event("sent", 60)
    assert sent["ok"] and sent["code"] == "COMPLETE", sent
    rx.wait_for('"event": "complete"', 10, where="stdout")
    assert sha(tmp_path / "inbox" / "up.bin") == sha(src)
    node.stop()


# -- a user's dialect ------------------------------------------------------------------------------

ROBOLAB_MAIN = r"""#include <atomic>
#include <csignal>
#include <cstdio>

#include "onboard/robolab_plugin.hpp"
#include "robolab/udp_link.hpp"

static std::atomic<bool> stop{false};

int main(int argc, char** argv)
{
    robolab::link::NodeConfig cfg;
    cfg.inbox = "inbox";
    robolab::link::Node node(cfg);
    robolab::onboard::RobolabPlugin plugin;
    node.add(plugin);
    robolab::link::Words why;
    robolab::link::UdpLink udp(node);
    if (argc != 2 || !node.start(why) || !udp.open(argv[1], why)) {
        std::fprintf(stderr, "%s\n", why.c_str());
        return 1;
    }
    std::printf("%u\n", static_cast<unsigned>(udp.local_port()));
    std::fflush(stdout);
    std::signal(SIGTERM, [](int) { stop = true; });
    udp.run(stop);
    return 0;
}
"""
ROBOLAB_REPLY = ("        // TODO: handle KR_MOTOR_CONTROL (from system frame.sysid, component frame.compid); "
                 "ctx.send(...) replies",
                 """        KrMotorStatus st;
        st.target_system = frame.sysid;
        st.seq = msg.seq;
        st.dir = msg.dir;
        st.speed = msg.speed;
        st.rpm = 12.5f * static_cast<float>(msg.speed);
        ctx.send(st);""")


def test_a_users_dialect_that_includes_ttapi_gets_the_node(tmp_path: Path) -> None:
    """dialects/examples/robolab.xml (ttapi.xml included, messages of its own): the node is
    generated in its namespace, the skeleton's KR_MOTOR_CONTROL handler answers with
    KR_MOTOR_STATUS, and the emulated tablet with --dialect gets the answer and sends a file."""
    xml = ROOT / "dialects" / "examples" / "robolab.xml"
    out = tmp_path / "out"
    proc = run_ttctl("gen", str(xml), "--lang", "cpp", "-o", str(out), timeout=300)
    assert proc.returncode == 0, proc.stderr
    cpp = out / "cpp"
    assert (cpp / "robolab" / "node.hpp").is_file()
    skeleton = cpp / "onboard" / "robolab_plugin.hpp"
    text = skeleton.read_text()
    assert ROBOLAB_REPLY[0] in text
    skeleton.write_text(text.replace(*ROBOLAB_REPLY))
    (tmp_path / "main.cpp").write_text(ROBOLAB_MAIN)
    gxx(*WARN, "-O1", "-I", str(cpp), str(tmp_path / "main.cpp"), "-o", str(tmp_path / "robolab_node"))
    prog = subprocess.Popen([str(tmp_path / "robolab_node"), f"udpin:{LOCAL}:0"], cwd=tmp_path, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    try:
        assert prog.stdout is not None
        port = int(prog.stdout.readline())
        (tmp_path / "up.bin").write_bytes(random.Random(1).randbytes(3000))
        (tmp_path / "drive.yaml").write_text(
            "- msg: {send: KR_MOTOR_CONTROL seq=1 dir=FORWARD speed=40, until: KR_MOTOR_STATUS.seq == 1, timeout: 20}\n"
            "- wait: {until: KR_MOTOR_STATUS.rpm >= 500, timeout: 5}\n"
            "- send: up.bin\n")
        run = run_ttctl("emulate", "tablet", "--dialect", str(xml), "--to", f"udpout:{LOCAL}:{port}", "--rate", "8000",
                        "--script", "drive.yaml", cwd=tmp_path, timeout=90)
        assert run.returncode == 0, run.stdout + run.stderr
        assert "answered after" in run.stdout and "up.bin: 3000 bytes delivered and verified" in run.stdout
        assert (tmp_path / "inbox" / "up.bin").read_bytes() == (tmp_path / "up.bin").read_bytes()
    finally:
        prog.send_signal(signal.SIGTERM)
        assert prog.wait(20) == 0
