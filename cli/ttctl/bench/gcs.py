"""`ttctl bench gcs`: a ground station through the tablet end, the bridge against a naive
forwarder, side by side in one run, on real processes on loopback.

For each distance and each way across (bridge, naive) it starts afresh:
    ttctl emulate onboard --no-gcs --listen udpin:...          (the vehicle, behind DTT)
    ttctl link relay --profile m100 --distance D --loss L      (the radio link)
    bridge: ttctl emulate tablet --to <relay> --gcs udpout:127.0.0.1:G
    naive:  ttctl emulate tablet --to <forwarder>  +  python -m ttctl.bench.gcs_naive (see there)
and a QGroundControl-like pymavlink peer listening on G (see gcs_peer). The app's command is the
tablet prompt's `hover`: on the ground the vehicle answers DENIED, a whole round trip through the
tablet's command queue (retries included), timed from the line written to its answer read.
Idle: before the ground station starts; connected: during its connect, mission upload and
download (the commands go on until its sequence ends). With `--ftp KB` the onboard end serves a
file of that size and the ground station then fetches it by MAVLink FTP (gcs_peer.py): its longest
HEARTBEAT gap and position rate during the download against the same idle just before.
"""

from __future__ import annotations

import contextlib
import json
import os
import queue
import socket
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import IO, Any

from .procs import console_script

LOCAL = "127.0.0.1"
MODES = ("bridge", "naive")


@dataclass
class Options:
    distances: list[float]
    loss: float = 0.1
    loss_model: str = "random"
    items: int = 20
    commands: int = 50
    interval: float = 0.5
    step_timeout: float = 60.0
    seed: int = 1
    gcs_id: tuple[int, int] = (255, 190)  # QGroundControl's default, which is also the tablet's
    sticks_hz: float = 0.0  # MANUAL_CONTROL from the ground station once it hears the vehicle
    profile: str = "m100"
    json_out: bool = False
    quick: bool = False
    modes: tuple[str, ...] = MODES
    keep: str | None = None  # keep every process's stderr in this folder
    ftp_kb: int = 0  # the ground station fetches a file of this size by MAVLink FTP after the mission (0: no)
    repeat: int = 1  # runs of each, on seeds seed, seed + 1, ...: the report gives their medians


@dataclass
class Run:
    mode: str
    distance_m: float
    started: bool = True
    why_not: str | None = None  # the set-up failed: the words of the process that refused
    connect_s: float | None = None
    heartbeat_s: float | None = None
    version_s: float | None = None
    mission_list_s: float | None = None
    params_s: float | None = None
    param_count: int = 0
    param_reads: int = 0
    upload_s: float | None = None
    upload_restarts: int = 0
    ack_wait_s: float | None = None
    download_s: float | None = None
    items_checked: bool = False
    ftp_s: float | None = None
    hb_gap_idle_s: float | None = None
    hb_gap_ftp_s: float | None = None
    gpi_idle_hz: float | None = None
    gpi_ftp_hz: float | None = None
    age_p50_ms: float | None = None
    age_p95_ms: float | None = None
    ages: int = 0
    age_method: str = ""
    idle_p50_ms: float | None = None
    idle_p95_ms: float | None = None
    idle_failed: int = 0
    gcs_p50_ms: float | None = None
    gcs_p95_ms: float | None = None
    gcs_failed: int = 0
    gcs_commands: int = 0
    idle_ms: list[float] = field(default_factory=list)  # every answered command, in order
    gcs_ms: list[float] = field(default_factory=list)
    sticks: int = 0  # MANUAL_CONTROL sent
    failed: dict[str, str] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)


def percentile(xs: list[float], q: float) -> float | None:
    if not xs:
        return None
    xs = sorted(xs)
    k = (len(xs) - 1) * q
    lo = int(k)
    hi = min(lo + 1, len(xs) - 1)
    return round(xs[lo] + (xs[hi] - xs[lo]) * (k - lo), 1)


def free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind((LOCAL, 0))
        return int(s.getsockname()[1])


class Procs:
    """The processes of one run; each one's stderr in a file, every one stopped at the end."""

    def __init__(self, folder: Path) -> None:
        self.folder = folder
        self.procs: list[tuple[str, subprocess.Popen[bytes]]] = []

    def start(self, name: str, args: list[str], stdin: bool = False) -> subprocess.Popen[bytes]:
        err = open(self.folder / f"{name}.err", "wb")  # noqa: SIM115 (closed with the process)
        env = {**os.environ, "PYTHONUNBUFFERED": "1"}
        p = subprocess.Popen(args, stdin=subprocess.PIPE if stdin else subprocess.DEVNULL,
                             stdout=subprocess.PIPE if stdin else subprocess.DEVNULL, stderr=err, env=env)
        err.close()
        self.procs.append((name, p))
        return p

    def stderr(self, name: str) -> str:
        path = self.folder / f"{name}.err"
        return path.read_text(errors="replace") if path.exists() else ""

    def wait_for(self, name: str, p: subprocess.Popen[bytes], text: str, timeout: float = 20.0) -> str | None:
        """None once `text` is on its stderr, else why not (it ended, or took too long)."""
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            if text in self.stderr(name):
                return None
            if p.poll() is not None:
                return f"{name} ended ({p.returncode}): {_last(self.stderr(name))}"
            time.sleep(0.05)
        return f"{name} not ready in {timeout:g} s: {_last(self.stderr(name))}"

    def stop(self) -> None:
        for _, p in reversed(self.procs):
            if p.poll() is None:
                p.terminate()
        for _, p in reversed(self.procs):
            try:
                p.wait(5)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait()
            for s in (p.stdin, p.stdout):
                if s is not None:
                    with contextlib.suppress(OSError):
                        s.close()


def _last(text: str) -> str:
    lines = [ln for ln in text.strip().splitlines() if ln.strip()]
    return lines[-1].strip() if lines else "(nothing said)"


class Prompt:
    """The tablet's prompt on pipes (--json): one command at a time, timed to its answer."""

    def __init__(self, p: subprocess.Popen[bytes]) -> None:
        assert p.stdin is not None and p.stdout is not None
        self.p = p
        self.stdin: IO[bytes] = p.stdin
        self.lines: queue.Queue[tuple[float, dict[str, Any]] | None] = queue.Queue()
        threading.Thread(target=self._read, args=(p.stdout,), daemon=True).start()

    def _read(self, out: IO[bytes]) -> None:
        for raw in out:
            try:
                event = json.loads(raw)
            except ValueError:
                continue
            self.lines.put((time.monotonic(), event))
        self.lines.put(None)

    def wait_event(self, kind: str, timeout: float) -> dict[str, Any] | None:
        end = time.monotonic() + timeout
        while True:
            try:
                got = self.lines.get(timeout=max(0.01, end - time.monotonic()))
            except queue.Empty:
                return None
            if got is None:
                return None
            if got[1].get("event") == kind:
                return got[1]

    def command(self, line: str, timeout: float = 60.0) -> tuple[float | None, str]:
        """(seconds to the vehicle's answer, None if it did not answer), and the answer's words."""
        t0 = time.monotonic()
        try:
            self.stdin.write(line.encode() + b"\n")
            self.stdin.flush()
        except OSError as e:
            return None, f"the tablet's prompt is closed ({e})"
        end = t0 + timeout
        while True:
            try:
                got = self.lines.get(timeout=max(0.01, end - time.monotonic()))
            except queue.Empty:
                return None, f"no answer in {timeout:g} s"
            if got is None:
                return None, "the tablet ended"
            at, ev = got
            if ev.get("event") != "step":
                continue
            words = str(ev.get("result") if ev.get("ok") else ev.get("reason"))
            answered = bool(ev.get("ok")) or "DENIED" in words or "ACCEPTED" in words
            return (at - t0 if answered else None), words


def _commands(prompt: Prompt, count: int, interval: float, more: Any = None) -> tuple[list[float], int, str | None]:
    """`hover` every `interval` s, `count` times (and on while `more()`); latencies, failures and
    the first failure's words."""
    lat: list[float] = []
    failed = 0
    first: str | None = None
    i = 0
    while i < count or (more is not None and more()):
        t0 = time.monotonic()
        took, words = prompt.command("hover")
        i += 1
        if took is None:
            failed += 1
            first = first or words
            if "ended" in words or "closed" in words or "no answer in" in words:
                break
        else:
            lat.append(took * 1000)
        time.sleep(max(0.0, interval - (time.monotonic() - t0)))
    return lat, failed, first


def run_one(o: Options, mode: str, distance: float, folder: Path, progress: Any) -> Run:
    from .gcs_peer import QgcLikePeer, run_sequence

    r = Run(mode, distance)
    procs = Procs(folder)
    ttctl = console_script("ttctl", "ttctl")
    ob, rl, g = free_port(), free_port(), free_port()
    link = ["--profile", o.profile, "--distance", f"{distance:g}"]
    ftp: tuple[str, bytes] | None = None
    serve: list[str] = []
    if o.ftp_kb:
        import random

        (folder / "serve").mkdir()
        data = random.Random(o.seed).randbytes(o.ftp_kb * 1024)
        (folder / "serve" / "bench.bin").write_bytes(data)
        ftp, serve = ("/serve/bench.bin", data), ["--serve", str(folder / "serve")]
    try:
        onboard = procs.start("onboard", [*ttctl, "emulate", "onboard", "--no-gcs", "--listen", f"udpin:{LOCAL}:{ob}",
                                          *link, *serve])
        relay = procs.start("relay", [*ttctl, "link", "relay", "--listen", f"udp:{LOCAL}:{rl}", "--to",
                                      f"udp:{LOCAL}:{ob}", *link, "--loss", f"{o.loss:g}", "--loss-model",
                                      o.loss_model, "--seed", str(o.seed), "--stats-interval", "0"])
        for name, p, text in (("onboard", onboard, "onboard"), ("relay", relay, "relay:")):
            why = procs.wait_for(name, p, text)
            if why:
                r.started, r.why_not = False, why
                return r
        if mode == "bridge":
            tablet = procs.start("tablet", [*ttctl, "emulate", "tablet", "--to", f"udpout:{LOCAL}:{rl}", "--gcs",
                                            f"udpout:{LOCAL}:{g}", "--json", *link], stdin=True)
        else:
            from ..link.model import load_profile

            a = free_port()
            rate = load_profile(o.profile).capacity_Bps("up", distance)
            naive = procs.start("naive", [sys.executable, "-m", "ttctl.bench.gcs_naive", "--app", str(a), "--gcs",
                                          str(g), "--to", str(rl), "--rate", f"{rate:g}"])
            why = procs.wait_for("naive", naive, "naive: ready")
            if why:
                r.started, r.why_not = False, why
                return r
            tablet = procs.start("tablet", [*ttctl, "emulate", "tablet", "--to", f"udpout:{LOCAL}:{a}", "--json",
                                            *link], stdin=True)
        prompt = Prompt(tablet)
        if prompt.wait_event("state", 30.0) is None:
            tablet.poll()
            r.started = False
            r.why_not = f"the tablet end did not reach the vehicle: {_last(procs.stderr('tablet'))}"
            return r
        progress(f"{mode} {distance:g} m: app commands, idle")
        lat, r.idle_failed, why = _commands(prompt, o.commands, o.interval)
        r.idle_ms = [round(x, 1) for x in lat]
        r.idle_p50_ms, r.idle_p95_ms = percentile(lat, 0.5), percentile(lat, 0.95)
        if why:
            r.notes.append(f"idle command: {why}")
        progress(f"{mode} {distance:g} m: the ground station connects, uploads and downloads {o.items} items"
                 + (f", then fetches {o.ftp_kb} KB by MAVLink FTP" if o.ftp_kb else ""))
        peer = QgcLikePeer(g, sysid=o.gcs_id[0], compid=o.gcs_id[1], deadline_s=o.step_timeout,
                           sticks_hz=o.sticks_hz)
        done = threading.Event()
        box: dict[str, Any] = {}

        def gcs() -> None:
            try:
                box["f"] = run_sequence(peer, o.items, linger=lambda: box.get("commands_done", False), ftp=ftp)
            except Exception as e:  # reported as the run's failure, not a traceback
                box["error"] = f"{type(e).__name__}: {e}"
            finally:
                done.set()

        worker = threading.Thread(target=gcs, daemon=True)
        worker.start()
        seq_done = lambda: peer.f.download_s is not None or bool(peer.f.failed)  # noqa: E731
        lat, r.gcs_failed, why = _commands(prompt, o.commands, o.interval, more=lambda: not seq_done())
        box["commands_done"] = True
        r.gcs_ms = [round(x, 1) for x in lat]
        r.gcs_commands = len(lat) + r.gcs_failed
        r.gcs_p50_ms, r.gcs_p95_ms = percentile(lat, 0.5), percentile(lat, 0.95)
        if why:
            r.notes.append(f"command with a ground station: {why}")
        waited = 4 * o.step_timeout + 30
        if not done.wait(waited):  # a step still running has no figure: say so, never a bare "-"
            r.failed["ground station"] = f"its sequence had not ended after {waited:g} s more"
        peer.close()
        if tablet.poll() is not None:
            r.notes.append(f"the tablet end exited {tablet.returncode}: {_last(procs.stderr('tablet'))}")
        if "error" in box:
            r.failed["ground station"] = box["error"]
            return r
        f = box.get("f") or peer.f
        r.connect_s, r.params_s, r.param_count, r.param_reads = f.connect_s, f.params_s, f.param_count, f.param_reads
        r.heartbeat_s, r.version_s, r.mission_list_s = f.heartbeat_s, f.version_s, f.mission_list_s
        r.sticks = peer.sticks
        r.ack_wait_s = f.ack_wait_s
        r.upload_s, r.upload_restarts, r.download_s, r.items_checked = (f.upload_s, f.upload_restarts, f.download_s,
                                                                        f.items_checked)
        r.ftp_s, r.hb_gap_idle_s, r.hb_gap_ftp_s = f.ftp_s, f.hb_gap_idle_s, f.hb_gap_ftp_s
        r.gpi_idle_hz, r.gpi_ftp_hz = f.gpi_idle_hz, f.gpi_ftp_hz
        r.age_p50_ms, r.age_p95_ms, r.ages, r.age_method = (percentile(f.ages_ms, 0.5), percentile(f.ages_ms, 0.95),
                                                            len(f.ages_ms), f.age_method)
        r.failed.update(f.failed)
        if r.download_s is not None and not r.items_checked:
            r.failed["download"] = "the items downloaded differ from the ones uploaded"
        if mode == "naive":
            procs.stop()
            line = [ln for ln in procs.stderr("naive").splitlines() if "packets up" in ln]
            if line:
                r.notes.append(line[-1])
        return r
    finally:
        procs.stop()


def run(o: Options) -> int:
    import signal
    from dataclasses import replace

    from .gcs_report import checks, combine, print_report

    progress = (lambda s: None) if o.json_out else (lambda s: print(s, file=sys.stderr, flush=True))
    runs: list[Run] = []

    def interrupted(signum: int, frame: Any) -> None:
        raise KeyboardInterrupt  # the processes of the run are stopped on the way out

    old = signal.signal(signal.SIGTERM, interrupted)
    try:
        with tempfile.TemporaryDirectory(prefix="ttctl-bench-gcs-") as d:
            for i in range(o.repeat):
                one = replace(o, seed=o.seed + i)
                for distance in o.distances:
                    for mode in o.modes:
                        folder = Path(o.keep or d) / (f"{mode}-{distance:g}" + (f"-seed{one.seed}" if o.repeat > 1
                                                                                  else ""))
                        folder.mkdir(parents=True)
                        if o.repeat > 1:
                            progress(f"run {i + 1} of {o.repeat} (seed {one.seed})")
                        runs.append(run_one(one, mode, distance, folder, progress))
    except KeyboardInterrupt:
        print("ttctl: bench gcs interrupted (its processes are stopped)", file=sys.stderr)
        return 130
    finally:
        signal.signal(signal.SIGTERM, old)
    rep: dict[str, Any] = {"profile": o.profile, "loss": o.loss, "loss_model": o.loss_model, "items": o.items,
                           "commands": o.commands, "interval_s": o.interval, "seed": o.seed,
                           "gcs_id": f"{o.gcs_id[0]}/{o.gcs_id[1]}", "sticks_hz": o.sticks_hz,
                           "ftp_kb": o.ftp_kb}
    samples = [asdict(r) for r in runs]
    if o.repeat > 1:
        seeds = [o.seed + i for i in range(o.repeat)]
        rep["seeds"] = seeds
        rep["runs"] = combine(samples, seeds)
        rep["samples"] = samples
    else:
        rep["runs"] = samples
    rep["checks"] = checks(rep)
    if o.json_out:
        print(json.dumps(rep, indent=2))
    else:
        print_report(rep)
    counted = [c for c in rep["checks"] if c["counts"]]
    return 0 if all(c["ok"] for c in counted) else 1
