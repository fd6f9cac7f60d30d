"""The promise of `send-file`, tested on real processes: exit 0 means the receiver holds that
name with that SHA-256, whatever else happens meanwhile.

Each round starts a few `ttctl send-file` processes at once, all with the default MAVLink ids,
against one `ttctl recv-file` (directly, or through `ttctl link relay` with loss): names shared
between senders, contents the same or different at the same size, random bytes or text (a CSV
log, which goes deflated: the compressed rounds), `--overwrite` or not (senders at once share the
link by the receiver's rate grants: "granted" counts those paced to one); at
random a sender is killed with SIGKILL and started again, the receiver is killed and started
again, strangers send garbage datagrams. Checked, all the time:
- every file visible under its final name is a whole file that some sender offered under that
  name (never a partial one);
- a sender that exits 0 reported the SHA-256 of its file, and the receiver holds that name with
  that SHA-256 when it exits (unless the receiver completed a later transfer of that name);
- after each round, each name holds the content of the last transfer of it the receiver
  reported complete;
- no process prints a traceback; senders exit 0 or 1 (or are killed); strangers get no reply.

`run()` is what both `tests/test_integrity_e2e.py` (a few rounds, seeded) and `ttctl bench
integrity` (a soak, as many rounds as asked) use.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import random
import signal
import socket
import subprocess
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .procs import console_script
from .textfiles import flight_log_csv

LOCAL = "127.0.0.1"
NAMES = ["m.yaml", "data/run.bin", "r.csv", "big.bin"]
SIZES = [0, 1, 79, 80, 81, 246, 247, 248, 1000, 4502, 4502, 20_000, 60_000]
RATE = "100000"  # bytes per second for every end: transfers last long enough to be interrupted
TIMEOUT = "20"


@dataclass
class Report:
    rounds: int = 0
    concurrent_rounds: int = 0  # rounds with several senders at once
    sends: int = 0
    delivered: int = 0  # exit 0
    deflated: int = 0  # exit 0, the file went as its zlib stream
    granted: int = 0  # exit 0, paced to a share of the link the receiver granted (others sent at once)
    nothing_sent: int = 0  # exit 0, the receiver had it already
    refused: int = 0  # exit 1 with a REFUSED_* code
    failed: int = 0  # exit 1 otherwise
    senders_killed: int = 0
    receivers_killed: int = 0
    stranger_datagrams: int = 0
    checks: int = 0  # looks at the receive directory
    violations: list[str] = field(default_factory=list)
    seconds: float = 0.0


@dataclass
class _Send:
    name: str
    path: Path
    sha: str
    overwrite: bool
    proc: subprocess.Popen[bytes]
    out: Path
    err: Path
    killed: bool = False
    code: int | None = None


class _NotStarted(RuntimeError):
    def __init__(self, text: str, exited: bool) -> None:
        super().__init__(text)
        self.exited = exited


def _free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind((LOCAL, 0))
        return int(s.getsockname()[1])


def _sha_of(path: Path) -> str | None:
    try:
        with open(path, "rb") as fh:
            return hashlib.sha256(fh.read()).hexdigest()
    except OSError:
        return None


class Harness:
    def __init__(self, work: Path, seed: int, relay: bool, strangers: bool,
                 log: Callable[[str], None] | None = None) -> None:
        self.work = work
        self.rng = random.Random(seed)
        self.seed = seed
        self.use_relay = relay
        self.use_strangers = strangers
        self.log = log or (lambda text: None)
        self.cmd = console_script("ttctl", "ttctl")
        self.inbox = work / "inbox"
        self.src = work / "src"
        self.src.mkdir(parents=True, exist_ok=True)
        self.port = _free_port()
        self.air = _free_port()
        self.report = Report()
        self.offered: dict[str, set[str]] = {}  # name -> every SHA-256 ever offered under it
        self.contents: dict[str, list[tuple[Path, str]]] = {}  # name -> files made for it
        self.receiver: subprocess.Popen[bytes] | None = None
        self.relay: subprocess.Popen[bytes] | None = None
        self.recv_log = work / "recv.jsonl"
        self.recv_errs: list[Path] = []
        self.relay_err: Path | None = None
        self.last_receiver_kill = 0.0
        self._stop = threading.Event()
        self._lock = threading.Lock()
        self._n = 0

    # -- processes ------------------------------------------------------------------------------
    def _spawn(self, args: list[str], tag: str, out_mode: str = "wb") -> tuple[subprocess.Popen[bytes], Path, Path]:
        self._n += 1
        out, err = self.work / f"{self._n:04d}-{tag}.out", self.work / f"{self._n:04d}-{tag}.err"
        with open(out, out_mode) as o, open(err, "wb") as e:
            p = subprocess.Popen(self.cmd + args, stdout=o, stderr=e, cwd=self.work)
        return p, out, err

    def start_receiver(self) -> None:
        args = ["recv-file", "--listen", f"udpin:{LOCAL}:{self.port}", "--dir", str(self.inbox), "--overwrite",
                "--json", "--rate", RATE]
        with open(self.recv_log, "ab") as o:
            self._n += 1
            err = self.work / f"{self._n:04d}-recv.err"
            with open(err, "wb") as e:
                self.receiver = subprocess.Popen(self.cmd + args, stdout=o, stderr=e, cwd=self.work)
        self.recv_errs.append(err)
        self._wait_for(err, "receiving into", self.receiver)

    def start_relay(self) -> None:
        model = self.rng.choice(["random", "burst"])
        p, _, err = self._spawn(["link", "relay", "--listen", f"udp:{LOCAL}:{self.air}", "--to",
                                 f"udp:{LOCAL}:{self.port}", "--profile", "lan", "--rate", "400000", "--loss", "0.05",
                                 "--loss-model", model, "--seed", str(self.seed), "--stats-interval", "0"], "relay")
        self.relay = p
        self._wait_for(err, "relay: udpin", p)
        self.relay_err = err

    def _start_ends(self, tries: int = 3) -> None:
        """The receiver (and the relay) on ports picked free a moment ago: another process's
        ephemeral port can take one in between, and the process then exits at once ('address
        in use'); pick again, a few times."""
        for attempt in range(tries):
            try:
                self.start_receiver()
                if self.use_relay:
                    self.start_relay()
                return
            except _NotStarted as e:
                for p in (self.receiver, self.relay):
                    if p is not None and p.poll() is None:
                        p.kill()
                        p.wait(5)
                self.receiver = self.relay = None
                if not e.exited or attempt == tries - 1:
                    raise RuntimeError(str(e)) from None
                self.port, self.air = _free_port(), _free_port()

    def _wait_for(self, path: Path, text: str, p: subprocess.Popen[bytes], timeout: float = 20.0) -> None:
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            if text in path.read_text(errors="replace"):
                return
            if p.poll() is not None:
                break
            time.sleep(0.02)
        raise _NotStarted(f"{path.name}: no {text!r}: {path.read_text(errors='replace').strip()}", p.poll() is not None)

    def _content(self, name: str) -> tuple[Path, str]:
        made = self.contents.setdefault(name, [])
        if made and self.rng.random() < 0.35:
            return self.rng.choice(made)  # the same bytes again (a resend, or a second sender of it)
        same_size = made and self.rng.random() < 0.5  # the same size, other bytes: what tripped the old ids
        size = made[-1][0].stat().st_size if same_size else self.rng.choice(SIZES)
        path = self.src / f"{len(list(self.src.iterdir())):05d}.bin"
        if self.rng.random() < 0.5:  # text, which deflates: a CSV log cut to the size
            body = flight_log_csv(seconds=size / 80 + 1, seed=self.rng.randrange(1 << 30))[:size]
        else:
            body = self.rng.randbytes(size)
        path.write_bytes(body)
        sha = hashlib.sha256(body).hexdigest()
        made.append((path, sha))
        self.offered.setdefault(name, set()).add(sha)
        return path, sha

    def start_sender(self, name: str, path: Path, sha: str, overwrite: bool) -> _Send:
        to = self.air if self.use_relay else self.port
        args = ["send-file", str(path), "--to", f"udpout:{LOCAL}:{to}", "--name", name, "--json", "--rate", RATE,
                "--timeout", TIMEOUT] + (["--overwrite"] if overwrite else [])
        p, out, err = self._spawn(args, "send")
        self.report.sends += 1
        return _Send(name, path, sha, overwrite, p, out, err)

    # -- watching ---------------------------------------------------------------------------------
    def _complete_events(self) -> list[dict[str, Any]]:
        out = []
        with contextlib.suppress(OSError):
            for line in self.recv_log.read_text(errors="replace").splitlines():
                with contextlib.suppress(ValueError):
                    e = json.loads(line)
                    if e.get("event") == "complete":
                        out.append(e)
        return out

    def violation(self, text: str) -> None:
        with self._lock:
            self.report.violations.append(text)
        self.log(f"VIOLATION: {text}")

    def _look(self) -> None:
        """Every file under its final name is whole: one that was offered under that name."""
        if not self.inbox.is_dir():
            return
        for dirpath, dirs, files in os.walk(self.inbox):
            dirs[:] = [d for d in dirs if d != ".ttctl-partial"]
            for f in files:
                path = Path(dirpath) / f
                name = path.relative_to(self.inbox).as_posix()
                sha = _sha_of(path)
                if sha is not None and sha not in self.offered.get(name, set()):
                    self.violation(f"{name} is visible with content nobody offered under that name "
                                   f"(a partial file?): {sha[:12]}")
        with self._lock:
            self.report.checks += 1

    def _watch(self) -> None:
        while not self._stop.is_set():
            self._look()
            time.sleep(0.02)

    def _strangers(self) -> None:
        """Garbage datagrams from two ports of their own, at the receiver (or the relay): they
        must never be answered."""
        socks = [socket.socket(socket.AF_INET, socket.SOCK_DGRAM) for _ in range(2)]
        rng = random.Random(self.seed + 7)
        try:
            for s in socks:
                s.bind((LOCAL, 0))
                s.setblocking(False)
            while not self._stop.is_set():
                s = rng.choice(socks)
                target = self.air if self.use_relay else self.port
                junk = rng.randbytes(rng.randint(1, 100))
                if rng.random() < 0.3:
                    junk = b"\xfd" + junk  # looks like the start of a MAVLink 2 frame
                with contextlib.suppress(OSError):
                    s.sendto(junk, (LOCAL, target))
                    with self._lock:
                        self.report.stranger_datagrams += 1
                for s2 in socks:
                    with contextlib.suppress(BlockingIOError, OSError):
                        data = s2.recv(2048)
                        self.violation(f"a stranger got an answer: {data[:16].hex()}")
                time.sleep(0.01)
        finally:
            for s in socks:
                s.close()

    # -- a round ----------------------------------------------------------------------------------
    def round(self) -> None:
        rng = self.rng
        n = rng.randint(1, 4)
        self.report.concurrent_rounds += n > 1
        plan = []
        for _ in range(n):
            name = rng.choice(NAMES)
            path, sha = self._content(name)
            plan.append((name, path, sha, rng.random() < 0.5))
        sends: list[_Send] = []
        pending = list(plan)
        kill_sender_at = time.monotonic() + rng.uniform(0.05, 0.8) if rng.random() < 0.35 else None
        kill_receiver_at = time.monotonic() + rng.uniform(0.05, 0.8) if rng.random() < 0.2 else None
        restart_receiver_at: float | None = None
        begin = time.monotonic()
        while pending or any(s.code is None for s in sends) or restart_receiver_at is not None:
            now = time.monotonic()
            if pending and (not sends or rng.random() < 0.3):
                sends.append(self.start_sender(*pending.pop(0)))
            if kill_sender_at is not None and now >= kill_sender_at:
                kill_sender_at = None
                running = [s for s in sends if s.proc.poll() is None]
                if running:
                    victim = rng.choice(running)
                    victim.proc.kill()
                    victim.proc.wait()
                    victim.killed = True
                    self.report.senders_killed += 1
                    if rng.random() < 0.7:  # started again: it must resume, not corrupt
                        sends.append(self.start_sender(victim.name, victim.path, victim.sha, victim.overwrite))
            if kill_receiver_at is not None and now >= kill_receiver_at and self.receiver is not None:
                kill_receiver_at = None
                self.receiver.kill()
                self.receiver.wait()
                self.last_receiver_kill = time.time()
                self.report.receivers_killed += 1
                restart_receiver_at = now + rng.uniform(0.1, 1.0)
            if restart_receiver_at is not None and now >= restart_receiver_at:
                restart_receiver_at = None
                self.start_receiver()
            for s in sends:
                if s.code is None and s.proc.poll() is not None:
                    s.code = s.proc.returncode
                    if not s.killed:
                        self._judge(s)
            if now - begin > 120:
                for s in sends:
                    if s.proc.poll() is None:
                        s.proc.kill()
                self.violation("a round took more than 120 s")
                break
            time.sleep(0.01)
        self._end_of_round()
        self.report.rounds += 1

    def _judge(self, s: _Send) -> None:
        err = s.err.read_text(errors="replace")
        out = s.out.read_text(errors="replace")
        if "Traceback" in err or "Traceback" in out:
            self.violation(f"send-file {s.name} printed a traceback: {err[-300:]}")
        if s.code not in (0, 1):
            self.violation(f"send-file {s.name} exited {s.code}: {err.strip()[-200:]}")
            return
        try:
            report = json.loads(out)
        except ValueError:
            self.violation(f"send-file {s.name} exited {s.code} without a JSON report: {err.strip()[-200:]}")
            return
        if s.code != 0:
            if report.get("ok"):
                self.violation(f"send-file {s.name} exited {s.code} with ok true")
            if str(report.get("code", "")).startswith("REFUSED"):
                self.report.refused += 1
            else:
                self.report.failed += 1
            return
        self.report.delivered += 1
        self.report.nothing_sent += bool(report.get("nothing_sent"))
        self.report.deflated += bool(report.get("deflated_bytes"))
        self.report.granted += bool(report.get("rate_grant_Bps"))
        if not report.get("ok") or report.get("sha256") != s.sha:
            self.violation(f"send-file {s.name} exited 0 but reported {report.get('ok')} / "
                           f"{str(report.get('sha256'))[:12]} for {s.sha[:12]}")
        held = _sha_of(self.inbox / s.name)
        if held == s.sha:
            return
        # the name may have been replaced since, by a later transfer of it (with --overwrite)
        later = [e for e in self._complete_events() if e.get("name") == s.name]
        mine = [i for i, e in enumerate(later) if e.get("sha256") == s.sha]
        if not mine:
            self.violation(f"send-file {s.name} exited 0 ({s.sha[:12]}) but the receiver never reported it "
                           f"complete; it holds {str(held)[:12]}")
        elif not any(e.get("sha256") == held for e in later[mine[-1] + 1:]):
            self.violation(f"send-file {s.name} exited 0 ({s.sha[:12]}) but the receiver holds {str(held)[:12]}")

    def _end_of_round(self) -> None:
        self._look()
        events = self._complete_events()
        last: dict[str, dict[str, Any]] = {}
        for e in events:
            last[str(e.get("name"))] = e
        for name, e in last.items():
            held = _sha_of(self.inbox / name)
            if held != e.get("sha256") and float(e.get("time", 0)) > self.last_receiver_kill:
                # a receiver killed after it stored a file but before it said so may leave a newer file
                self.violation(f"{name}: the last transfer reported complete was {str(e.get('sha256'))[:12]}, "
                               f"the directory holds {str(held)[:12]}")

    # -- all of it --------------------------------------------------------------------------------
    def run(self, rounds: int) -> Report:
        t0 = time.monotonic()
        threads = [threading.Thread(target=self._watch, daemon=True)]
        if self.use_strangers:
            threads.append(threading.Thread(target=self._strangers, daemon=True))
        try:
            self._start_ends()
            for t in threads:
                t.start()
            for i in range(rounds):
                self.round()
                self.log(f"round {i + 1}/{rounds}: {self.report.delivered} delivered, {self.report.refused} refused, "
                         f"{self.report.failed} failed, {len(self.report.violations)} violations")
        finally:
            self._stop.set()
            for t in threads:
                if t.ident is not None:  # started: a receiver or relay that never came up started none
                    t.join(5)
            for p in (self.receiver, self.relay):
                if p is not None and p.poll() is None:
                    p.send_signal(signal.SIGINT)
                    try:
                        p.wait(10)
                    except subprocess.TimeoutExpired:
                        p.kill()
                        self.violation("a process did not stop on SIGINT")
            for err in [*self.recv_errs, *([self.relay_err] if self.relay_err else [])]:
                if "Traceback" in err.read_text(errors="replace"):
                    self.violation(f"{err.name}: a traceback")
        self.report.seconds = round(time.monotonic() - t0, 1)
        return self.report


def run(work: Path, rounds: int, seed: int, relay: bool, strangers: bool = True,
        log: Callable[[str], None] | None = None) -> Report:
    return Harness(work, seed, relay, strangers, log).run(rounds)


def main(rounds: int, seed: int, relay: str, strangers: bool, keep: Path | None, as_json: bool) -> int:
    """`ttctl bench integrity`: the checks above as a soak; exit 1 if any was broken."""
    import sys
    import tempfile
    from dataclasses import asdict

    from ..errors import Fail

    if relay not in ("direct", "relay", "both"):
        raise Fail("--topology must be direct, relay or both")
    if keep is not None:
        if keep.exists() and not keep.is_dir():
            raise Fail(f"--keep {keep} is not a folder (it keeps every process's output)")
        if keep.exists() and any(keep.iterdir()):
            raise Fail(f"--keep {keep} exists and is not empty")
        if not keep.parent.is_dir():
            raise Fail(f"--keep {keep}: no folder {keep.parent}")
        keep = keep.absolute()  # the processes run in their own working folders
    topologies = ["direct", "relay"] if relay == "both" else [relay]
    reports = {}
    for topo in topologies:
        def say(text: str, topo: str = topo) -> None:
            if not as_json:
                print(f"{topo}: {text}", file=sys.stderr, flush=True)

        if keep is not None:
            work = keep / topo
            work.mkdir(parents=True, exist_ok=True)
            reports[topo] = run(work, rounds, seed, topo == "relay", strangers, say)
        else:
            with tempfile.TemporaryDirectory(prefix="ttctl-integrity-") as d:
                reports[topo] = run(Path(d), rounds, seed, topo == "relay", strangers, say)
    bad = sum(len(r.violations) for r in reports.values())
    if as_json:
        print(json.dumps({k: asdict(v) for k, v in reports.items()}))
    else:
        from rich.console import Console
        from rich.table import Table

        t = Table(title=f"send-file's promise: {rounds} rounds, seed {seed}")
        t.add_column("")
        for topo in reports:
            t.add_column(topo, justify="right")
        cols = ("rounds", "concurrent_rounds", "sends", "delivered", "deflated", "granted", "nothing_sent", "refused",
                "failed", "senders_killed", "receivers_killed", "stranger_datagrams", "checks", "seconds")
        for c in cols:
            t.add_row(c.replace("_", " "), *(str(getattr(r, c)) for r in reports.values()))
        t.add_row("violations", *(str(len(r.violations)) for r in reports.values()))
        Console().print(t)
        for topo, r in reports.items():
            for v in r.violations:
                print(f"{topo}: VIOLATION: {v}")
    return 1 if bad else 0
