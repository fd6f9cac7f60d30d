"""`ttctl send-file`, `ttctl recv-file` and `ttctl link relay`: the file transfer protocol
between real processes, over UDP (DTT packets) or TCP (a MAVLink byte stream).

The receiving end is the onboard computer by default (1/240), the sending end the tablet
(255/190). Pacing: the capacity of the profile's direction this end sends in (up from the
tablet's 255, down otherwise) at --distance, or --rate, or unpaced when neither is given
(fine on loopback, not through a relay that models a slow radio).
"""

from __future__ import annotations

import asyncio
import contextlib
import json
import signal
import sys
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .errors import Fail

TABLET = (255, 190)
ONBOARD = (1, 240)
TICK = 0.25  # how often the command loops look at progress, timeouts and signals


# -- options shared by both ends ---------------------------------------------------------------

@dataclass
class LinkChoice:
    """How fast this end sends, and what the link carries each way (None: unknown)."""

    pace_Bps: float | None
    send_capacity: float | None
    recv_capacity: float | None
    quiet: float | None  # silence after which a half-received frame is given up

    def describe(self) -> str:
        return f"paced at {self.pace_Bps:.0f} B/s" if self.pace_Bps else "unpaced"


def link_choice(rate: float | None, profile: str | None, distance: float, sysid: int) -> LinkChoice:
    from .link.model import ProfileError, load_profile

    if rate is not None and rate <= 0:
        raise Fail("--rate must be a positive number of bytes per second")
    if distance < 0:
        raise Fail("--distance must not be negative")
    send_cap = recv_cap = None
    mtu = 100
    if profile is not None:
        try:
            prof = load_profile(profile)
        except ProfileError as e:
            raise Fail(str(e)) from None
        mine, other = ("up", "down") if sysid == TABLET[0] else ("down", "up")
        send_cap = prof.capacity_Bps(mine, distance)
        recv_cap = prof.capacity_Bps(other, distance)
        mtu = prof.mtu
    if rate is not None:
        send_cap = rate
        recv_cap = recv_cap or rate
    quiet = 3 * mtu / recv_cap if recv_cap else None
    return LinkChoice(send_cap, send_cap, recv_cap, quiet)


def _spec(text: str, udp: str) -> Any:
    from .link.transport import TransportError, parse_spec

    try:
        return parse_spec(text, udp=udp)
    except TransportError as e:
        raise Fail(str(e)) from None


def _check_id(value: int, what: str) -> None:
    if not 0 <= value <= 255:
        raise Fail(f"{what} must be in 0..255, not {value}")


class _Signals:
    """SIGINT/SIGTERM set `stop` (and `wake`) instead of raising in the middle of the loop."""

    def __init__(self, loop: asyncio.AbstractEventLoop, wake: asyncio.Event) -> None:
        loop.set_exception_handler(_loop_error)
        self.stop = asyncio.Event()
        self.got: int | None = None
        self._loop = loop
        self._wake = wake
        for sig in (signal.SIGINT, signal.SIGTERM):
            with contextlib.suppress(NotImplementedError, RuntimeError):  # not the main thread, or no signals
                loop.add_signal_handler(sig, self._on, sig)

    def _on(self, sig: int) -> None:
        self.got = sig
        self.stop.set()
        self._wake.set()

    def remove(self) -> None:
        for sig in (signal.SIGINT, signal.SIGTERM):
            with contextlib.suppress(NotImplementedError, RuntimeError):
                self._loop.remove_signal_handler(sig)


def _oversize_note(transport: Any) -> None:
    n = transport.stats.oversize
    if n:
        _err(f"dropped {n} datagram(s) longer than {transport.mtu} bytes (DJI's link refuses them)")


def _loop_error(loop: asyncio.AbstractEventLoop, context: dict[str, Any]) -> None:
    """Whatever asyncio would print with a traceback, as one line."""
    exc = context.get("exception")
    what = f"{type(exc).__name__}: {exc}" if exc is not None else ""
    _err(f"warning: {context.get('message', 'error in the event loop')}{': ' + what if what else ''}")


def _hello(sysid: int, compid: int, spec: Any) -> Callable[[], Any] | None:
    """For an end that reaches out over UDP: a HEARTBEAT each second until the peer is heard,
    so that a peer listening with udpin learns where to answer."""
    if spec.kind != "udpout":
        return None
    import ttapi

    kind = ttapi.MavType.MAV_TYPE_GCS if sysid == TABLET[0] else ttapi.MavType.MAV_TYPE_ONBOARD_CONTROLLER
    return lambda: ttapi.Heartbeat(type=int(kind), autopilot=int(ttapi.MavAutopilot.MAV_AUTOPILOT_INVALID))


async def _tick(wake: asyncio.Event, timeout: float = TICK) -> None:
    with contextlib.suppress(TimeoutError):
        await asyncio.wait_for(wake.wait(), timeout)
    wake.clear()


def _err(text: str) -> None:
    print(f"ttctl: {text}", file=sys.stderr, flush=True)


async def _start(runner: Any) -> None:
    from .link.transport import TransportError

    try:
        await runner.start()
    except TransportError as e:
        raise Fail(str(e)) from None


# -- recv-file ---------------------------------------------------------------------------------

@dataclass
class RecvOptions:
    listen: str
    dir: Path
    overwrite: bool = False
    max_file: int | None = None
    max_dir: int | None = None
    serve: Path | None = None
    count: int | None = None
    sysid: int = ONBOARD[0]
    compid: int = ONBOARD[1]
    rate: float | None = None
    profile: str | None = None
    distance: float = 10.0
    as_json: bool = False


def recv_file(o: RecvOptions) -> int:
    from .proto.storage import Quota, ReceiveDir, StorageError

    spec = _spec(o.listen, "udpin")
    _check_id(o.sysid, "--sysid")
    _check_id(o.compid, "--compid")
    if o.count is not None and o.count < 1:
        raise Fail("--count must be at least 1")
    link = link_choice(o.rate, o.profile, o.distance, o.sysid)
    if o.dir.exists() and not o.dir.is_dir():
        raise Fail(f"--dir {o.dir} is not a directory")
    q = Quota(overwrite=o.overwrite)
    if o.max_file is not None:
        if o.max_file < 0:
            raise Fail("--max-file must not be negative")
        q.max_file_bytes = o.max_file
    if o.max_dir is not None:
        if o.max_dir < 0:
            raise Fail("--max-dir must not be negative")
        q.max_dir_bytes = o.max_dir
    try:
        store = ReceiveDir(o.dir, q)
    except StorageError as e:
        raise Fail(f"--dir: {e}") from None
    if o.serve is not None and not o.serve.is_dir():
        raise Fail(f"--serve {o.serve} is not a directory")
    try:
        return asyncio.run(_recv(o, spec, link, store))
    except KeyboardInterrupt:  # before the signal handlers were in place
        _err("stopped")
        return 0


def _who(key: tuple[int, ...]) -> str:
    return f"{key[0]}/{key[1]}"


async def _recv(o: RecvOptions, spec: Any, link: LinkChoice, store: Any) -> int:
    from .ends.runtime import Runner
    from .link.transport import make_transport
    from .proto.endpoint import Endpoint

    loop = asyncio.get_running_loop()
    wake = asyncio.Event()
    completed = 0

    def out(event: str, text: str, **fields: Any) -> None:
        if o.as_json:
            print(json.dumps({"event": event, **fields}), flush=True)
        else:
            print(text, flush=True)

    def on_event(what: str, t: Any) -> None:
        nonlocal completed
        who = _who(t.key)
        name = t.name or "?"
        if what == "file-accepted":
            have = t.partial.ranges.total() if t.partial is not None else 0
            resumed = f", resuming with {have} bytes already here" if have else ""
            out("accepted", f"accepted {name} ({t.size} bytes) from {who}{resumed}", name=name, bytes=t.size,
                peer=who, resumed_bytes=have)
        elif what == "file-refused":
            out("refused", f"refused {name} from {who}: {t.reason}", name=name, bytes=t.size, peer=who,
                reason=t.reason)
        elif what == "file-complete":
            completed += 1
            secs = (t.finished_at or loop.time()) - t.started
            out("complete", f"complete {name}: {t.size} bytes in {secs:.2f} s from {who} -> {t.final_path}",
                name=name, bytes=t.size, seconds=round(secs, 3), peer=who, path=t.final_path)
        elif what == "file-failed":
            out("failed", f"failed {name} from {who}: {t.reason}", name=name, bytes=t.size, peer=who,
                reason=t.reason)
        wake.set()

    transport = make_transport(spec, log=lambda text: _err(f"{spec.kind}: {text}"))
    ep = Endpoint(o.sysid, o.compid, mtu=transport.mtu, rate_Bps=link.pace_Bps, receive_dir=store,
                  serve_dir=str(o.serve) if o.serve is not None else None, on_event=on_event)
    runner = Runner(ep, transport, quiet=link.quiet, hello=_hello(o.sysid, o.compid, spec))
    await _start(runner)
    sigs = _Signals(loop, wake)
    serve = f", serving {o.serve}" if o.serve is not None else ""
    _err(f"receiving into {o.dir} as {o.sysid}/{o.compid} on {transport.describe()}{serve} ({link.describe()})")
    served: dict[int, Any] = {}
    done_at: float | None = None
    try:
        while not sigs.stop.is_set():
            await _tick(wake)
            if runner.failed is not None:
                raise runner.failed
            _report_served(ep, served, out)
            now = loop.time()
            if o.count is not None and completed >= o.count:
                # linger until the peer has heard COMPLETE: the link has been quiet a moment
                done_at = done_at or now
                quiet_since = max(runner.last_rx or 0.0, done_at)
                if (not ep.scheduler.busy and now - quiet_since >= 1.0) or now - done_at > 10.0:
                    break
    finally:
        sigs.remove()
        ep.close()  # partial state saved for resume
        await runner.close()
        _oversize_note(transport)
    if sigs.stop.is_set():
        _err(f"stopped after {completed} file(s); partial transfers are kept for resume")
    return 0


def _report_served(ep: Any, served: dict[int, Any], out: Callable[..., None]) -> None:
    """Lines for downloads this end serves (they have no receiver events)."""
    for s in list(ep.senders.values()):
        if not s.request_id:
            continue
        seen = served.get(id(s))
        who = _who(s.target)
        if seen is None:
            served[id(s)] = "started"
            out("serving", f"serving {s.name} ({s.size} bytes) to {who}", name=s.name, bytes=s.size, peer=who)
        if s.done and served.get(id(s)) != "done":
            served[id(s)] = "done"
            r = s.result
            if r.ok:
                out("served", f"served {s.name}: {s.size} bytes in {r.seconds:.2f} s to {who}", name=s.name,
                    bytes=s.size, seconds=round(r.seconds, 3), peer=who)
            else:
                out("serve-failed", f"serving {s.name} to {who} failed: {r.message}", name=s.name, peer=who,
                    reason=r.message)


# -- send-file ---------------------------------------------------------------------------------

@dataclass
class SendOptions:
    file: str
    to: str | None = None
    from_: str | None = None
    name: str | None = None
    overwrite: bool = False
    as_json: bool = False
    rate: float | None = None
    profile: str | None = None
    distance: float = 10.0
    sysid: int = TABLET[0]
    compid: int = TABLET[1]
    target_sysid: int = ONBOARD[0]
    target_compid: int = ONBOARD[1]
    timeout: float = 60.0
    dir: Path | None = None


@dataclass
class Outcome:
    ok: bool
    report: dict[str, Any]
    error: str | None = None
    interrupted: bool = False


def send_file(o: SendOptions) -> int:
    """Exit status: 0 delivered, 1 refused / failed / timed out (Fail), 2 bad input (Fail), 130
    interrupted (app.main says so, for every command)."""
    try:
        return _send_file(o)
    except KeyboardInterrupt:
        return 130


def _send_file(o: SendOptions) -> int:
    if (o.to is None) == (o.from_ is None):
        raise Fail("give --to ENDPOINT (send FILE) or --from ENDPOINT (fetch REMOTE_NAME), not both or neither")
    for v, what in ((o.sysid, "--sysid"), (o.compid, "--compid"), (o.target_sysid, "--target-sysid"),
                    (o.target_compid, "--target-compid")):
        _check_id(v, what)
    if o.timeout <= 0:
        raise Fail("--timeout must be positive")
    link = link_choice(o.rate, o.profile, o.distance, o.sysid)
    if o.to is not None:
        if o.dir is not None:
            raise Fail("--dir is where --from downloads go; with --to, FILE is the file to send")
        outcome = _upload_prepare(o, link)
    else:
        if o.name is not None or o.overwrite:
            raise Fail("--name and --overwrite apply to sending (--to), not to --from")
        outcome = _download_prepare(o, link)
    if outcome.interrupted:
        return 130
    if o.as_json:
        print(json.dumps(outcome.report), flush=True)
    elif outcome.ok:
        print(_summary(outcome.report), flush=True)
    if not outcome.ok:
        raise Fail(outcome.error or "failed", 1)
    return 0


def _upload_prepare(o: SendOptions, link: LinkChoice) -> Outcome:
    from .proto.storage import FileSource, StorageError
    from .proto.transfer import MAX_NAME_BYTES

    spec = _spec(o.to or "", "udpout")
    name = o.name if o.name is not None else Path(o.file).name
    raw = name.encode("utf-8", "surrogateescape")
    if not raw or len(raw) > MAX_NAME_BYTES:
        raise Fail(f"the name must be 1..{MAX_NAME_BYTES} bytes of UTF-8 ({len(raw)} given)")
    if Path(o.file).is_dir():
        raise Fail(f"{o.file} is a directory")
    try:
        src = FileSource(o.file)  # reads the file once for its SHA-256, before the link starts
    except StorageError as e:
        raise Fail(str(e)) from None
    try:
        return asyncio.run(_upload(o, spec, link, src, name))
    finally:
        src.close()


class _Bar:
    """A rich progress bar on stderr, only when stderr is a terminal."""

    def __init__(self, label: str, total: int) -> None:
        self.p: Any = None
        if not sys.stderr.isatty():
            return
        from rich.console import Console
        from rich.progress import (
            BarColumn,
            DownloadColumn,
            Progress,
            TextColumn,
            TimeRemainingColumn,
            TransferSpeedColumn,
        )

        self.p = Progress(TextColumn("{task.description}"), BarColumn(), DownloadColumn(), TransferSpeedColumn(),
                          TimeRemainingColumn(), TextColumn("{task.fields[extra]}"),
                          console=Console(stderr=True), transient=True)
        self.task = self.p.add_task(label, total=total, extra="")
        self.p.start()

    def log(self, text: str) -> None:
        if self.p is not None:
            self.p.console.print(f"ttctl: {text}", markup=False, highlight=False)
        else:
            _err(text)

    def update(self, done: int, total: int, extra: str = "") -> None:
        if self.p is not None:
            self.p.update(self.task, completed=done, total=total, extra=extra)

    def stop(self) -> None:
        if self.p is not None:
            self.p.stop()
            self.p = None


async def _await_peer(runner: Any, wake: asyncio.Event, sigs: _Signals, timeout: float) -> bool:
    """A listening end (udpin, tcpin) has nowhere to send until the peer reaches it: wait for
    that (False if interrupted; Fail after `timeout`)."""
    transport = runner.transport
    if not transport.spec.listening:
        return True
    loop = asyncio.get_running_loop()
    end = loop.time() + timeout
    while transport.peer is None:
        if sigs.stop.is_set():
            return False
        if loop.time() >= end:
            raise Fail(f"timed out: nobody reached {transport.describe()} within {timeout:g} s", 1)
        await _tick(wake, 0.05)
    return True


def _refusal_text(code: str, name: str, message: str) -> str:
    """The receiver's reason: the status carries only a code; names are refused by rules this
    end knows too (it says which one), the rest by the code's meaning."""
    if code == "REFUSED_NAME":
        from .proto.storage import Refused, check_name

        try:
            check_name(name, 255)
        except Refused as e:
            return e.reason
        return f"{message} (its rules may be stricter: a shorter name, or other characters)"
    if code == "REFUSED_EXISTS":
        return f"{name} exists there (to replace it, send with --overwrite to a receiver started with --overwrite)"
    return message


async def _open_end(o: SendOptions, spec: Any, link: LinkChoice, bar: _Bar, **endpoint: Any) -> tuple[Any, Any]:
    """This end of a send-file or fetch: its endpoint and runner, started (Fail, with the bar
    stopped, if the transport cannot open)."""
    from .ends.runtime import Runner
    from .link.transport import make_transport
    from .proto.endpoint import Endpoint
    from .proto.transfer import TransferConfig

    transport = make_transport(spec, log=bar.log)
    ep = Endpoint(o.sysid, o.compid, mtu=transport.mtu, rate_Bps=link.pace_Bps,
                  config=TransferConfig(give_up_after=o.timeout), **endpoint)
    runner = Runner(ep, transport, quiet=link.quiet)
    try:
        await _start(runner)
    except Fail:
        bar.stop()
        raise
    return ep, runner


async def _upload(o: SendOptions, spec: Any, link: LinkChoice, src: Any, name: str) -> Outcome:
    loop = asyncio.get_running_loop()
    wake = asyncio.Event()
    target = (o.target_sysid, o.target_compid)
    bar = _Bar(f"{name} → {target[0]}/{target[1]}", src.size)
    ep, runner = await _open_end(o, spec, link, bar)
    transport = runner.transport
    sigs = _Signals(loop, wake)
    sender = None
    try:
        if not await _await_peer(runner, wake, sigs, o.timeout):
            return Outcome(False, {}, interrupted=True)
        runner.sync()
        sender = ep.send_file(src.path, target, name=name, overwrite=o.overwrite, source=src,
                              on_progress=lambda s: wake.set())
        runner.kick()
        while not sender.done and not sigs.stop.is_set():
            await _tick(wake)
            if runner.failed is not None:
                raise runner.failed
            retx = sender.stats.bytes_retransmitted
            bar.update(sender.acked_bytes, sender.size, f"retx {retx} B" if retx else "")
    finally:
        bar.stop()
        sigs.remove()
        if sender is not None and not sender.done:
            sender.cancel(runner.now())
        ep.close()
        await runner.close()
        _oversize_note(transport)
    r = sender.result
    assert r is not None
    st = r.stats
    # bytes the receiver already had: never sent by us (first sends are new bytes; the
    # protocol's own figure is 0 when data streamed before the first status, as it does)
    resumed = max(st.resumed_bytes, r.size - (st.bytes_sent - st.bytes_retransmitted)) if r.ok else 0
    moved = max(0, r.size - resumed)
    goodput = moved / r.seconds if r.seconds > 0 else 0.0
    cap = link.send_capacity
    report = {
        "ok": r.ok, "code": r.code, "message": r.message, "name": r.name, "bytes": r.size,
        "seconds": round(r.seconds, 3), "goodput_Bps": round(goodput, 1) if r.ok else None,
        "capacity_Bps": round(cap, 1) if cap else None,
        "efficiency": round(goodput / cap, 4) if cap and r.ok else None,
        "retransmitted_bytes": st.bytes_retransmitted, "frames_sent": st.frames_sent, "bytes_sent": st.bytes_sent,
        "resumed_bytes": resumed, "peer": f"{target[0]}/{target[1]}", "endpoint": transport.describe(),
        "direction": "send",
    }
    if sigs.stop.is_set() and not r.ok:
        return Outcome(False, report, interrupted=True)
    if r.ok:
        return Outcome(True, report)
    who = f"{target[0]}/{target[1]}"
    if r.code == "TIMEOUT":
        if st.statuses == 0:
            err = (f"timed out: no answer from {who} at {spec} within {o.timeout:g} s "
                   "(is a receiver running there?)")
        else:
            err = f"timed out: {r.message}"
    elif r.code.startswith("REFUSED"):
        err = f"refused by {who}: {_refusal_text(r.code, name, r.message)}"
    else:
        err = f"transfer failed at {who}: {r.message}"
    return Outcome(False, report, err)


def _download_prepare(o: SendOptions, link: LinkChoice) -> Outcome:
    from .proto.storage import ReceiveDir, StorageError

    spec = _spec(o.from_ or "", "udpout")
    raw = o.file.encode("utf-8", "surrogateescape")
    if not raw or len(raw) > 255:
        raise Fail("REMOTE_NAME must be 1..255 bytes of UTF-8")
    folder = o.dir if o.dir is not None else Path(".")
    if folder.exists() and not folder.is_dir():
        raise Fail(f"--dir {folder} is not a directory")
    try:
        store = ReceiveDir(folder)
    except StorageError as e:
        raise Fail(f"--dir: {e}") from None
    local = folder / o.file
    if local.exists() or local.is_symlink():
        raise Fail(f"{local} exists here: remove it first, or fetch into another --dir", 1)
    return asyncio.run(_download(o, spec, link, store))


async def _download(o: SendOptions, spec: Any, link: LinkChoice, store: Any) -> Outcome:
    from .proto.transfer import result_name

    loop = asyncio.get_running_loop()
    wake = asyncio.Event()
    target = (o.target_sysid, o.target_compid)
    who = f"{target[0]}/{target[1]}"
    state: dict[str, Any] = {"t": None, "error": None, "code": None, "done": False}
    req: Any = None

    def on_event(what: str, obj: Any) -> None:
        if what == "request-failed" and obj is req:
            state["error"] = obj.error or "failed"
            state["code"] = _REQUEST_CODES.get(state["error"], "TIMEOUT")
        elif what.startswith("file-") and req is not None and getattr(obj, "request_id", 0) == req.id \
                and obj.key[0] == target[0]:
            state["t"] = obj
            if what == "file-complete":
                state["done"] = True
            elif what in ("file-refused", "file-failed"):
                state["error"] = f"could not store {obj.name or o.file} here: {obj.reason}"
                state["code"] = result_name(int(obj.result))
        wake.set()

    bar = _Bar(f"{o.file} ← {who}", 0)
    ep, runner = await _open_end(o, spec, link, bar, receive_dir=store, on_event=on_event)
    transport = runner.transport
    sigs = _Signals(loop, wake)
    started = loop.time()
    try:
        if not await _await_peer(runner, wake, sigs, o.timeout):
            return Outcome(False, {}, interrupted=True)
        runner.sync()
        started = loop.time()
        req = ep.request_file(o.file, target)
        runner.kick()
        while not state["done"] and state["error"] is None and not sigs.stop.is_set():
            await _tick(wake)
            if runner.failed is not None:
                raise runner.failed
            t = state["t"]
            if t is not None:
                have = t.partial.ranges.total() if t.partial is not None else 0
                bar.update(have, t.size)
                quiet_for = loop.time() - (runner.last_rx or started)
                if not state["done"] and quiet_for > o.timeout:
                    state["error"] = (f"timed out: nothing from {who} for {o.timeout:g} s "
                                      "(what arrived is kept here: fetch again to resume)")
                    state["code"] = "TIMEOUT"
        if state["done"]:
            await runner.drain(2.0)  # let our COMPLETE status leave, so the peer stops too
    finally:
        bar.stop()
        sigs.remove()
        ep.close()
        await runner.close()
        _oversize_note(transport)
    t = state["t"]
    end = t.finished_at if t is not None and t.finished_at else loop.time()
    secs = end - started
    size = t.size if t is not None else 0
    ok = bool(state["done"])
    goodput = size / secs if ok and secs > 0 else None
    cap = link.recv_capacity
    report = {
        "ok": ok, "code": "COMPLETE" if ok else (state["code"] or "FAILED"),
        "message": f"{o.file}: {size} bytes received and verified" if ok else (state["error"] or ""),
        "name": o.file, "bytes": size, "seconds": round(secs, 3),
        "goodput_Bps": round(goodput, 1) if goodput is not None else None,
        "capacity_Bps": round(cap, 1) if cap else None,
        "efficiency": round(goodput / cap, 4) if cap and goodput is not None else None,
        "retransmitted_bytes": None, "frames_sent": None, "frames_received": t.frames if t is not None else 0,
        "path": t.final_path if t is not None else None, "peer": who, "endpoint": transport.describe(),
        "direction": "fetch",
    }
    if sigs.stop.is_set() and not ok:
        return Outcome(False, report, interrupted=True)
    if ok:
        return Outcome(True, report)
    err = state["error"] or "failed"
    if state["code"] == "NOT_FOUND":
        err = f"{who} has no file {o.file!r} to send"
    elif state["code"] == "REQUEST_REFUSED":
        err = f"refused by {who}: it does not serve {o.file!r} (is recv-file running with --serve?)"
    elif state["code"] == "TIMEOUT" and t is None:
        err = f"timed out: no answer from {who} at {spec} within {o.timeout:g} s (is a peer with --serve running?)"
    return Outcome(False, report, err)


_REQUEST_CODES = {"no such file there": "NOT_FOUND", "the peer does not serve that file": "REQUEST_REFUSED"}


def _summary(r: dict[str, Any]) -> str:
    verb = "sent" if r["direction"] == "send" else "received"
    parts = [f"{verb} {r['name']} {'to' if verb == 'sent' else 'from'} {r['peer']}: {r['bytes']} bytes in "
             f"{r['seconds']:.2f} s, goodput {r['goodput_Bps']:.0f} B/s"]
    if r.get("efficiency") is not None:
        parts.append(f"efficiency {r['efficiency']:.0%} of {r['capacity_Bps']:.0f} B/s")
    if r.get("retransmitted_bytes") is not None:
        parts.append(f"{r['retransmitted_bytes']} bytes retransmitted")
    if r.get("resumed_bytes"):
        parts.append(f"resumed: {r['resumed_bytes']} bytes were already there")
    text = ", ".join(parts)
    if r.get("path"):
        text += f" -> {r['path']}"
    return text


# -- link relay --------------------------------------------------------------------------------

@dataclass
class RelayOptions:
    listen: str
    to: str
    profile: str = "m100"
    distance: float = 10.0
    loss: float | None = None
    loss_model: str = "random"
    corrupt: float = 0.0
    duplicate: float = 0.0
    reorder: float = 0.0
    seed: int = 0
    rate: float | None = None
    stats_interval: float = 5.0
    outages: list[str] = field(default_factory=list)  # START:SECONDS, from the relay's start


def _outage(text: str) -> tuple[float, float]:
    start, sep, length = text.partition(":")
    try:
        if not sep:
            raise ValueError
        return float(start), float(length)
    except ValueError:
        raise Fail(f"--outage wants START:SECONDS (seconds from the relay's start), not {text!r}") from None


def relay(o: RelayOptions) -> int:
    from .link.model import Impairments, ProfileError, load_profile
    from .link.relay import Relay, with_rate
    from .link.transport import TransportError, parse_spec

    try:
        listen = parse_spec(o.listen, udp="udpin", allowed=("udpin",))
        to = parse_spec(o.to, udp="udpout", allowed=("udpout",))
    except TransportError as e:
        raise Fail(f"{e} (the relay carries DTT packets: UDP only)") from None
    if o.distance < 0:
        raise Fail("--distance must not be negative")
    if o.stats_interval < 0:
        raise Fail("--stats-interval must not be negative")
    try:
        prof = load_profile(o.profile)
        if o.rate is not None:
            if o.rate <= 0:
                raise Fail("--rate must be a positive number of bytes per second")
            prof = with_rate(prof, o.rate)
        imp = Impairments(loss=o.loss, loss_model=o.loss_model, corrupt=o.corrupt, duplicate=o.duplicate,
                          reorder=o.reorder, outages=[_outage(text) for text in o.outages])
        imp.check()
        r = Relay(listen, to, prof, o.distance, imp, seed=o.seed, log=lambda text: _err(f"relay: {text}"))
    except ProfileError as e:
        raise Fail(str(e)) from None

    async def main() -> None:
        loop = asyncio.get_running_loop()
        wake = asyncio.Event()
        sigs = _Signals(loop, wake)
        try:
            from .link.relay import run_relay

            await run_relay(r, sigs.stop, o.stats_interval, lambda text: print(text, file=sys.stderr, flush=True))
        except TransportError as e:
            raise Fail(str(e)) from None
        finally:
            sigs.remove()

    try:
        asyncio.run(main())
    except KeyboardInterrupt:  # before the signal handlers were in place
        _err("relay: stopped")
    return 0
