"""MAVLink FTP as a `ttctl bench transfer` baseline (see ttctl.bench.baselines.common).

The client is pymavlink's own MAVFTP class (pymavlink/mavftp.py, default settings),
driven in virtual time: a private copy of the module whose `time` is the simulation clock, with
its blocking `recv_match(timeout=0.1)` loop run in a thread that hands control back and forth
with the simulation, so exactly one of them runs at any moment and runs are deterministic. As
its command line does, it resets the sessions, then `cmd_put` (CreateFile, then WriteFile of
`write_size` = 80-byte blocks, i.e. 107-byte frames, two packets each, `write_qsize` = 5 in
flight, round-robin repeats with the same seq) and `process_ftp_reply("put")` (no overall timeout
here; the benchmark's limit applies), ending with TerminateSession. If the put fails (pymavlink
aborts a put when a write is refused, e.g. after its CreateFile was lost), the command is run
again, as a user would. The server is a model of ArduPilot's (AP_MAVLinkFTP ftp_worker): one
open file, sessions, a repeated request answered with the stored reply, ACK/NAK per request.
The simulator polls the tablet only when its radio is free, so on the uplink pymavlink's 0.1 s
idle ticks (which only drive its retry heuristics) can run up to one packet time late; replies
reach it on time.

"""

from __future__ import annotations

import importlib.util
import io
import logging
import math
import struct
import threading
from collections import deque
from dataclasses import dataclass
from types import ModuleType
from typing import Any

from ...link.model import Profile
from ..shipped import bindings
from ..transfer import Case
from .common import BaselineRun, End, Ids, Message, realised_loss, simulate

# -- MAVLink FTP: pymavlink's client in virtual time, an ArduPilot-like server --------------------

class _Abort(BaseException):
    """Ends the client thread from inside pymavlink's loop (not an Exception: nothing catches it)."""


class _Clock:
    """What the private copy of pymavlink.mavftp sees as the `time` module."""

    def __init__(self) -> None:
        self.now = 0.0

    def time(self) -> float:
        return self.now

    def monotonic(self) -> float:
        return self.now

    def sleep(self, seconds: float) -> None:
        self.now += seconds


def _load_mavftp(clock: _Clock) -> ModuleType:
    """A private copy of pymavlink.mavftp whose clock is `clock` and whose log is quiet; the
    real module is left untouched."""
    from pymavlink import mavftp  # type: ignore[import-untyped]

    spec = importlib.util.spec_from_file_location("_ttctl_bench_mavftp", mavftp.__file__)
    assert spec is not None and spec.loader is not None
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    quiet = logging.getLogger("ttctl.bench.mavftp")
    quiet.propagate = False
    if not quiet.handlers:
        quiet.addHandler(logging.NullHandler())
    mod.time = clock  # type: ignore[attr-defined]
    mod.logging = quiet  # type: ignore[attr-defined]
    return mod


def mavftp_defaults() -> dict[str, Any]:
    """pymavlink's MAVFTP settings as its command line defines them (the same values as the
    class's built-in defaults)."""
    from pymavlink.mavftp import create_argument_parser  # type: ignore[import-untyped]

    p = create_argument_parser()
    names = ("debug", "pkt_loss_tx", "pkt_loss_rx", "max_backlog", "burst_read_size", "write_size", "write_qsize",
             "idle_detection_time", "read_retry_time", "retry_time")
    return {n: p.get_default(n) for n in names}


class MavftpClient(End):
    """pymavlink's MAVFTP put, run in a thread that only runs while the simulation waits."""

    def __init__(self, ids: Ids, peer: Ids, data: bytes, rate_Bps: float | None, mtu: int = 100,
                 name: str = "bench.bin", settings: dict[str, Any] | None = None, max_attempts: int = 50) -> None:
        super().__init__(ids, rate_Bps, mtu, bindings().registry)
        self.peer = peer
        self.data = data
        self.name = name
        self.clock = _Clock()
        self.mod = _load_mavftp(self.clock)
        self.overrides = dict(settings or {})
        self.settings: dict[str, Any] = {}  # what the client ran with, read back from pymavlink
        self.max_attempts = max_attempts
        self.attempts = 0
        self.result: int | None = None  # pymavlink's FtpError of the last put
        self.error: BaseException | None = None
        self.finished = False
        self.writes_sent = 0
        self.write_frames: dict[tuple[int, int, int], int] = {}  # (data bytes, frame bytes, packets) -> count
        self.ops_sent: dict[int, int] = {}
        self._inbox: deque[Any] = deque()
        self._deadline: float | None = None
        self._abort = False
        self._go = threading.Semaphore(0)
        self._back = threading.Semaphore(0)
        self._thread: threading.Thread | None = None

    # -- what pymavlink sees as `master` ---------------------------------------------------------
    @property
    def source_system(self) -> int:
        return self.ids[0]

    @property
    def source_component(self) -> int:
        return self.ids[1]

    @property
    def mav(self) -> MavftpClient:
        return self

    def file_transfer_protocol_send(self, target_network: int, target_system: int, target_component: int,
                                    payload: Any) -> None:
        p = bytes(payload)
        op = p[3]
        self.ops_sent[op] = self.ops_sent.get(op, 0) + 1
        sent = self.send(bindings().FileTransferProtocol(target_network=target_network, target_system=target_system,
                                                    target_component=target_component, payload=p))
        if op == self.mod.OP_WriteFile:
            self.writes_sent += 1
            key = (p[4], *sent)  # (data bytes, frame bytes, packets)
            self.write_frames[key] = self.write_frames.get(key, 0) + 1

    def recv_match(self, type: Any = None, timeout: float | None = None, blocking: bool = False,
                   condition: Any = None) -> Any:
        if self._inbox:
            return self._inbox.popleft()
        self._deadline = self.clock.now + max(timeout or 0.0, 1e-3)
        self._back.release()
        self._go.acquire()
        self._deadline = None
        if self._abort:
            raise _Abort
        return self._inbox.popleft() if self._inbox else None

    # -- the client thread -----------------------------------------------------------------------
    def _main(self) -> None:
        mod = self.mod
        try:
            while self.attempts < self.max_attempts:
                self.attempts += 1
                ftp = mod.MAVFTP(self, self.peer[0], self.peer[1])  # pymavlink's own defaults
                for k, v in self.overrides.items():  # the put reads these (write_size, write_qsize...) later
                    setattr(ftp.ftp_settings, k, v)
                self.settings = {k: getattr(ftp.ftp_settings, k) for k in ftp.ftp_settings._vars}
                ret = ftp.cmd_put([self.name], fh=io.BytesIO(self.data))
                if ret.error_code == mod.FtpError.Success:
                    ret = ftp.process_ftp_reply("put", timeout=0)
                self.result = int(ret.error_code)
                if ret.error_code == mod.FtpError.Success:
                    break
        except _Abort:
            pass
        except Exception as e:  # a pymavlink we do not know how to drive: report, do not hang
            self.error = e
        finally:
            self.finished = True
            self._deadline = None
            self._back.release()

    def _resume(self, now: float) -> None:
        self.clock.now = max(self.clock.now, now)
        self._go.release()
        self._back.acquire()

    def start(self) -> None:
        self._thread = threading.Thread(target=self._main, name="ttctl-bench-mavftp", daemon=True)
        self._thread.start()
        self._back.acquire()  # until it first waits for a reply (or ends)

    def close(self) -> None:
        if self._thread is None:
            return
        if not self.finished:
            self._abort = True
            self._go.release()
            self._back.acquire()
        self._thread.join(timeout=5)
        self._thread = None

    # -- node hooks ------------------------------------------------------------------------------
    def on_message(self, now: float, msg: Message) -> None:
        if isinstance(msg, bindings().FileTransferProtocol) and msg.target_system == self.ids[0]:
            self._inbox.append(msg)

    def on_time(self, now: float) -> None:
        if self.finished or self._deadline is None:
            return
        if self._inbox or now >= self._deadline - 1e-9:
            self._resume(now)

    def next_timer(self) -> float | None:
        return None if self.finished else self._deadline


FTP_HEADER = struct.Struct("<HBBBBBBI")  # seq, session, opcode, size, req_opcode, burst_complete, pad, offset
FTP_DATA_MAX = 239
FTP_SESSION_TIMEOUT = 3.0  # AP_MAVLinkFTP


@dataclass
class _Reply:
    seq: int
    session: int
    opcode: int
    size: int
    req_opcode: int
    offset: int = 0
    data: bytes = b""
    sysid: int = 0
    compid: int = 0


class FtpServer(End):
    """MAVLink FTP server, after ArduPilot's ftp_worker (CreateFile/OpenFileWO, WriteFile,
    TerminateSession, ResetSessions; one open file). `expect` is the benchmark's oracle: the
    moment the file holds exactly those bytes is recorded in complete_at."""

    def __init__(self, ids: Ids, rate_Bps: float | None, expect: bytes, mtu: int = 100) -> None:
        super().__init__(ids, rate_Bps, mtu, bindings().registry)
        from pymavlink import mavftp_op as op  # type: ignore[import-untyped]

        self.op = op
        self.expect = expect
        self.disk = bytearray()  # the one file this model serves, as stored
        self.open = False
        self.session = -1
        self.last: _Reply | None = None
        self.last_send = -math.inf
        self.complete_at: float | None = None
        self._mask = bytearray(len(expect))
        self._covered = 0
        self.requests = 0
        self.repeats_answered = 0

    @property
    def content(self) -> bytes:
        return bytes(self.disk)

    def _nak(self, r: _Reply, error: int) -> None:
        r.opcode, r.size, r.data = self.op.OP_Nack, 1, bytes((error,))

    def _push(self, now: float, r: _Reply) -> None:
        payload = FTP_HEADER.pack(r.seq & 0xFFFF, r.session & 0xFF, r.opcode, r.size, r.req_opcode, 0, 0,
                                  r.offset) + r.data
        self.send(bindings().FileTransferProtocol(target_network=0, target_system=r.sysid, target_component=r.compid,
                                             payload=payload.ljust(251, b"\x00")))
        self.last_send = now

    def on_message(self, now: float, msg: Message) -> None:
        if not isinstance(msg, bindings().FileTransferProtocol) or msg.target_system != self.ids[0]:
            return
        p = bytes(msg.payload)
        seq, session, opcode, size, _req, _burst, _pad, offset = FTP_HEADER.unpack_from(p)
        data = p[12:12 + min(size, FTP_DATA_MAX)]
        sysid, compid = msg.get_srcSystem(), msg.get_srcComponent()
        self.requests += 1
        last = self.last
        if (last is not None and last.sysid == sysid and last.compid == compid and last.session == session
                and (seq + 1) & 0xFFFF == last.seq):
            self.repeats_answered += 1  # a re-request: send the stored reply again
            self._push(now, last)
            return
        op = self.op
        r = _Reply(seq=(seq + 1) & 0xFFFF, session=session, opcode=op.OP_Ack, size=0, req_opcode=opcode,
                   sysid=sysid, compid=compid)
        open_ = self.open
        if size > FTP_DATA_MAX:
            self._nak(r, 3)  # InvalidDataSize
        elif session != self.session and opcode in (op.OP_TerminateSession, op.OP_ResetSessions):
            pass  # terminating another session: just ack
        elif open_ and session != self.session and now - self.last_send < FTP_SESSION_TIMEOUT:
            self._nak(r, 4)  # InvalidSession
        else:
            if open_ and session != self.session:
                self.open, self.session = False, -1  # the old session went quiet: close it
            if opcode in (op.OP_TerminateSession, op.OP_ResetSessions):
                self.open, self.session = False, -1
            elif opcode in (op.OP_CreateFile, op.OP_OpenFileWO):
                name = data.split(b"\x00", 1)[0]
                if self.open:
                    self._nak(r, 1)  # Fail: one open file
                elif not name or len(name) != size:
                    self._nak(r, 3)
                else:
                    self._open(now, truncate=opcode == op.OP_CreateFile)
                    self.session = session
            elif opcode == op.OP_WriteFile:
                if not self.open:
                    self._nak(r, 10)  # FileNotFound
                else:
                    self._write(now, offset, data)
                    r.offset = offset
            elif opcode in (op.OP_Ack, op.OP_Nack):
                return
            elif opcode != op.OP_None:
                self._nak(r, 7)  # UnknownCommand (what this model does not serve)
        self.last = r
        self._push(now, r)

    def _open(self, now: float, truncate: bool) -> None:
        self.open = True
        if truncate:
            self.disk = bytearray()
            self._mask = bytearray(len(self.expect))
            self._covered = 0
            if not self.expect and self.complete_at is None:
                self.complete_at = now

    def _write(self, now: float, offset: int, data: bytes) -> None:
        f = self.disk
        end = offset + len(data)
        if len(f) < end:
            f.extend(bytes(end - len(f)))
        f[offset:end] = data
        lo, hi = min(offset, len(self._mask)), min(end, len(self._mask))
        if hi > lo:
            self._covered += self._mask[lo:hi].count(0)
            self._mask[lo:hi] = b"\x01" * (hi - lo)
        if (self.complete_at is None and self._covered == len(self.expect) and len(f) == len(self.expect)
                and f == self.expect):
            self.complete_at = now


def mavftp_transfer(profile: Profile, distance: float, case: Case, data: bytes, seed: int, limit: float = 7200.0,
                    settings: dict[str, Any] | None = None, until_client_done: bool = False) -> BaselineRun:
    clients: list[MavftpClient] = []

    def make(s_ids: Ids, r_ids: Ids, s_rate: float, r_rate: float, mtu: int) -> tuple[End, End]:
        c = MavftpClient(s_ids, r_ids, data, s_rate, mtu, settings=settings)
        clients.append(c)
        srv = FtpServer(r_ids, r_rate, data, mtu)
        c.start()
        return c, srv

    def done(c: Any, srv: Any) -> bool:
        if until_client_done:
            return bool(c.finished)
        return srv.complete_at is not None or c.finished

    try:
        sim, c, srv, up, down = simulate(make, profile, distance, case, seed, limit, done)
    finally:
        for cl in clients:
            cl.close()
    assert isinstance(c, MavftpClient) and isinstance(srv, FtpServer)
    if c.error is not None:
        raise RuntimeError(f"pymavlink's MAVFTP could not be driven: {type(c.error).__name__}: {c.error}") \
            from c.error
    ok = srv.complete_at is not None and srv.content == data
    stats = {"attempts": c.attempts, "result": c.result, "writes_sent": c.writes_sent, "ops_sent": dict(c.ops_sent),
             "write_frames": dict(c.write_frames),
             "frames_sent": c.frames_sent, "packets_sent": c.packets_sent, "server_requests": srv.requests,
             "repeats_answered": srv.repeats_answered, "settings": c.settings, "ended_at": sim.now}
    return BaselineRun(srv.complete_at if ok and srv.complete_at is not None else limit, ok, stats,
                       up.stats.as_dict(), down.stats.as_dict())


def run_mavftp(profile: Profile, distance: float, case: Case, data: bytes, seed: int,
               limit: float = 7200.0) -> tuple[float, bool, float]:
    """MAVLink FTP upload by pymavlink's MAVFTP with its defaults (see the module
    documentation): (seconds, ok, realised loss)."""
    r = mavftp_transfer(profile, distance, case, data, seed, limit)
    return r.seconds, r.ok, realised_loss(r, case)
