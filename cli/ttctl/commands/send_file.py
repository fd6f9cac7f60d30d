"""`ttctl send-file`: send a file to a receiver (--to), or fetch one it serves (--from).

Exit 0 means the receiver said COMPLETE for this very transfer (its id and its metadata check:
this file's SHA-256 under this name), so it holds the file. Everything else is exit 1 (refused,
failed, timed out: with the receiver's reason when it gave one) or 2 (bad input, before
anything is sent), and leaves nothing behind but what is kept on purpose for a resume.
"""

from __future__ import annotations

import asyncio
import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import Fail
from .common import (
    ONBOARD,
    TABLET,
    Bar,
    LinkChoice,
    Signals,
    await_peer,
    check_id,
    check_pipeline,
    link_choice,
    load_signing,
    oversize_note,
    parse_endpoint,
    pipe_link,
    start,
    tick,
    who,
)
from .dialect import load_bindings


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
    key: Path | None = None
    accept_unsigned: bool = False
    profile_file: Path | None = None
    dialect: Path | None = None
    include_dirs: list[Path] = field(default_factory=list)
    compress: bool = True
    pipeline: str | None = None
    pipe_rate: float | None = None


@dataclass
class Outcome:
    ok: bool
    report: dict[str, Any]
    error: str | None = None
    interrupted: bool = False


def send_file(o: SendOptions) -> int:
    """Exit status: 0 delivered, 1 refused / failed / timed out (Fail), 2 bad input (Fail), 130
    interrupted (app.main says so, for every command)."""
    printed: list[bool] = []
    try:
        return _send_file(o, printed)
    except KeyboardInterrupt:
        return 130
    except Fail as e:
        if o.as_json and not printed:  # a refusal before any transfer: JSON too (and the line on stderr)
            print(json.dumps({"ok": False, "code": "BAD_INPUT" if e.code == 2 else "REFUSED", "message": str(e),
                              "name": o.name or Path(o.file).name, "exit": e.code,
                              "direction": "send" if o.to is not None else "fetch"}), flush=True)
        raise


def _send_file(o: SendOptions, printed: list[bool]) -> int:
    if (o.to is None) == (o.from_ is None):
        raise Fail("give --to ENDPOINT (send FILE) or --from ENDPOINT (fetch REMOTE_NAME), not both or neither")
    for v, what in ((o.sysid, "--sysid"), (o.compid, "--compid"), (o.target_sysid, "--target-sysid"),
                    (o.target_compid, "--target-compid")):
        check_id(v, what)
    if o.timeout <= 0:
        raise Fail("--timeout must be positive")
    link = link_choice(o.rate, o.profile, o.distance, o.sysid, o.profile_file, o.pipe_rate)
    check_pipeline(o.pipeline)
    if o.to is not None and o.dir is not None:
        raise Fail("--dir is where --from downloads go; with --to, FILE is the file to send")
    if o.to is None and (o.name is not None or o.overwrite):
        raise Fail("--name and --overwrite apply to sending (--to), not to --from")
    b = load_bindings(o.dialect, o.include_dirs)
    signing = load_signing(o.key, o.accept_unsigned, b)  # a bad --key is refused before anything starts
    side = _End(b, signing)
    outcome = _upload_prepare(o, link, side) if o.to is not None else _download_prepare(o, link, side)
    if outcome.interrupted:
        return 130
    if o.as_json:
        print(json.dumps(outcome.report), flush=True)
        printed.append(True)
    elif outcome.ok:
        print(_summary(outcome.report), flush=True)
    if not outcome.ok:
        raise Fail(outcome.error or "failed", 1)
    return 0


def _checked_name(name: str, what: str) -> str:
    """The name if a receiver would take it (the rules both ends share), else Fail (exit 2)."""
    from ..proto.names import Refused, check_name

    try:
        return check_name(name)
    except Refused as e:
        raise Fail(f"{what} {name!r} would be refused: {e.reason}") from None


# -- upload --------------------------------------------------------------------------------------

@dataclass
class _End:
    bindings: Any  # the link's dialect
    signing: Any


def _upload_prepare(o: SendOptions, link: LinkChoice, side: _End) -> Outcome:
    from ..proto.storage import FileSource, StorageError

    spec = parse_endpoint(o.to or "", "udpout")
    name = _checked_name(o.name if o.name is not None else Path(o.file).name, "the name")
    try:
        src = FileSource(o.file)  # reads the file once for its SHA-256, before the link starts
    except StorageError as e:
        raise Fail(str(e)) from None
    stream = None
    try:
        if o.compress:  # deflated (when that saves) before the link starts too
            from ..proto.deflate import deflated
            from ..proto.names import encoded

            stream = deflated(src, encoded(name))
        return asyncio.run(_upload(o, side, spec, link, src, name, stream or False))
    finally:
        if stream is not None:
            stream.close()
        src.close()


async def _open_end(o: SendOptions, side: _End, spec: Any, link: LinkChoice, bar: Bar,
                    **endpoint: Any) -> tuple[Any, Any]:
    """This end of a send-file or fetch: its endpoint and runner, started (Fail, with the bar
    stopped, if the transport cannot open)."""
    from ..ends.runtime import Runner, unknown_note
    from ..link.transport import make_transport
    from ..proto.endpoint import Endpoint
    from ..proto.transfer import TransferConfig

    given = endpoint.pop("on_event", None)

    def on_event(what: str, obj: Any) -> None:
        if what == "unknown-message":
            bar.log(unknown_note(side.bindings, obj))
        elif given is not None:
            given(what, obj)

    transport = make_transport(spec, log=bar.log, mtu=link.mtu if spec.udp else None)
    ep = Endpoint(side.bindings, o.sysid, o.compid, mtu=transport.mtu, rate_Bps=link.pace_Bps,
                  config=TransferConfig(give_up_after=o.timeout), signing=side.signing, on_event=on_event, **endpoint)
    pipe, pipe_rate = pipe_link(o.pipeline, link, bar.log)
    runner = Runner(ep, transport, quiet=link.quiet, pipe=pipe, pipe_rate_Bps=pipe_rate)
    try:
        await start(runner)
    except Fail:
        bar.stop()
        raise
    return ep, runner


def _pipe_report(runner: Any) -> dict[str, Any]:
    """What a --pipeline did: how often it opened and closed, and the bytes it carried each way."""
    pipe = runner.pipe
    if pipe is None:
        return {}
    return {"pipeline_opens": pipe.opened, "pipeline_closes": runner.ep.pipe.closes,
            "pipeline_bytes_out": pipe.bytes_out, "pipeline_bytes_in": pipe.bytes_in}


async def _upload(o: SendOptions, side: _End, spec: Any, link: LinkChoice, src: Any, name: str,
                  compress: Any) -> Outcome:
    loop = asyncio.get_running_loop()
    wake = asyncio.Event()
    target = (o.target_sysid, o.target_compid)
    bar = Bar(f"{name} → {who(target)}", src.size)
    ep, runner = await _open_end(o, side, spec, link, bar)
    transport = runner.transport
    sigs = Signals(loop, wake)
    sender = None
    try:
        if not await await_peer(runner, wake, sigs, o.timeout):
            return Outcome(False, {}, interrupted=True)
        runner.sync()
        sender = ep.send_file(src.path, target, name=name, overwrite=o.overwrite, source=src,
                              on_progress=lambda s: wake.set(), compress=compress)
        runner.kick()
        while not sender.done and not sigs.stop.is_set():
            await tick(wake)
            if runner.failed is not None:
                raise runner.failed
            retx = sender.stats.bytes_retransmitted
            extra = f"retx {retx} B" if retx else ("waiting: " + sender.busy if sender.busy else "")
            bar.update(sender.acked_bytes, sender.size, extra)
    finally:
        bar.stop()
        sigs.remove()
        if sender is not None and not sender.done:
            sender.cancel(runner.now())
        ep.close()
        await runner.close()
        oversize_note(transport)
    r = sender.result
    assert r is not None
    st = r.stats
    resumed = min(st.resumed_bytes, r.deflated or r.size) if r.ok else 0
    if r.deflated:  # the receiver's bytes count the stream: the file's share of them
        resumed = round(resumed * r.size / r.deflated)
    moved = max(0, r.size - resumed)
    goodput = moved / r.seconds if r.seconds > 0 else 0.0
    cap = link.send_capacity
    pipe = runner.pipe
    if pipe is not None and pipe.opened:
        cap = runner.pipe_rate_Bps  # the data went on the pipeline (all of it, or but what a close moved)
    report = {
        "ok": r.ok, "code": r.code, "message": r.message, "name": r.name, "bytes": r.size,
        "sha256": src.sha256.hex(), "seconds": round(r.seconds, 3),
        "goodput_Bps": round(goodput, 1) if r.ok else None,
        "capacity_Bps": round(cap, 1) if cap else None,
        "efficiency": round(goodput / cap, 4) if cap and r.ok and moved else None,
        "retransmitted_bytes": st.bytes_retransmitted, "frames_sent": st.frames_sent, "bytes_sent": st.bytes_sent,
        "resumed_bytes": resumed, "nothing_sent": r.nothing_sent, "restarts": st.restarts,
        "deflated_bytes": r.deflated, "deflate_fallback": r.fallback, "rate_grant_Bps": st.min_grant,
        "peer": who(target), "endpoint": transport.describe(), "direction": "send",
        **_pipe_report(runner),
    }
    if sigs.stop.is_set() and not r.ok:
        return Outcome(False, report, interrupted=True)
    if r.ok:
        return Outcome(True, report)
    peer = who(target)
    if r.code == "TIMEOUT":
        heard = ep.heard.get(target, 0)
        if st.statuses == 0 and heard:
            # the receiver is there (answering others, or its heartbeats): our offers or their answers were lost
            ago = runner.now() - ep.peers.get(target, 0.0)
            err = (f"timed out: {peer} at {spec} did not answer this transfer's {st.offers_sent} offers within "
                   f"{o.timeout:g} s, though {heard} other frames came from it (the last {ago:.1f} s ago): it "
                   "takes no files there (an onboard end without --inbox?), or the link lost every one")
        elif st.statuses == 0:
            err = f"timed out: no answer from {peer} at {spec} within {o.timeout:g} s (is a receiver running there?)"
        else:
            err = f"timed out: {r.message}"
    elif r.code.startswith("REFUSED"):
        err = f"refused by {peer}: {r.message}"
        if r.code == "REFUSED_EXISTS" and "overwrit" in r.message:
            err += " (to replace it: --overwrite here, and a receiver started with --overwrite)"
    elif r.code == "CANCELLED":
        err = "cancelled"
    else:
        err = f"transfer failed at {peer}: {r.message}"
    return Outcome(False, report, err)


# -- download ------------------------------------------------------------------------------------

def _download_prepare(o: SendOptions, link: LinkChoice, side: _End) -> Outcome:
    from ..proto.storage import ReceiveDir, StorageError

    spec = parse_endpoint(o.from_ or "", "udpout")
    name = _checked_name(o.file, "REMOTE_NAME")
    folder = o.dir if o.dir is not None else Path(".")
    store = ReceiveDir(folder)
    try:
        store.check()
    except StorageError as e:
        raise Fail(f"--dir: {e}") from None
    from ..proto.names import Refused

    try:
        local = store.final_path(name)
        store.check_parents(name)
    except Refused as e:
        raise Fail(f"cannot fetch into {folder}: {e.reason}", 1) from None
    if local.exists() or local.is_symlink():
        raise Fail(f"{folder / name} exists here: remove it first, or fetch into another --dir", 1)
    return asyncio.run(_download(o, side, spec, link, store, name))


async def _download(o: SendOptions, side: _End, spec: Any, link: LinkChoice, store: Any, name: str) -> Outcome:
    from ..proto.storage import StorageError
    from ..proto.transfer import result_name

    loop = asyncio.get_running_loop()
    wake = asyncio.Event()
    target = (o.target_sysid, o.target_compid)
    peer = who(target)
    state: dict[str, Any] = {"t": None, "error": None, "code": None, "done": False, "accepted": None,
                             "resumed": 0, "restarts": 0}
    req: Any = None

    def on_event(what: str, obj: Any) -> None:
        if what == "request-failed" and obj is req:
            state["error"], state["code"] = obj.error or "failed", obj.code or "FAILED"
        elif what.startswith("file-") and req is not None and obj.key[:2] == target \
                and getattr(obj, "request_id", 0) == req.id and not obj.offered_again:
            state["t"] = obj
            if what == "file-accepted":
                _accepted(obj, state, peer, bar.log)
            elif what == "file-complete":
                state["done"] = True
            elif what in ("file-refused", "file-failed"):
                state["error"] = f"could not store {obj.name or name} here: {obj.reason}"
                state["code"] = result_name(int(obj.result))
        wake.set()

    bar = Bar(f"{name} ← {peer}", 0)
    ep, runner = await _open_end(o, side, spec, link, bar, receive_dir=store, on_event=on_event, unsolicited=False)
    transport = runner.transport
    try:
        store.prepare()
    except StorageError as e:
        bar.stop()
        await runner.close()
        raise Fail(f"--dir: {e}") from None
    sigs = Signals(loop, wake)
    started = loop.time()
    progress_at, have, seen = started, 0, None
    try:
        if not await await_peer(runner, wake, sigs, o.timeout):
            return Outcome(False, {}, interrupted=True)
        runner.sync()
        started = progress_at = loop.time()
        req = ep.request_file(name, target)
        runner.kick()
        while not state["done"] and state["error"] is None and not sigs.stop.is_set():
            await tick(wake)
            if runner.failed is not None:
                raise runner.failed
            t = state["t"]
            now = loop.time()
            got = t.partial.ranges.total() if t is not None and t.partial is not None else 0
            if t is not seen:  # served anew: its progress counts from what it found here
                seen, have, progress_at = t, got, now
            if got > have:
                have, progress_at = got, now
            if t is not None:
                bar.update(got, t.size)
                if now - progress_at > o.timeout:
                    why = f"timed out: no progress for {o.timeout:g} s"
                    if req.unanswered:  # the server went quiet, and did not serve the file again
                        why += f" ({peer} went quiet and did not answer {req.unanswered} requests since)"
                    state["error"] = why
                    state["code"] = "TIMEOUT"
        if state["done"]:
            await runner.drain(2.0)  # let our COMPLETE status leave, so the peer stops too
    finally:
        bar.stop()
        sigs.remove()
        t = state["t"]
        kept = t is not None and t.partial is not None and t.partial.ranges.total() > 0
        ep.close()  # partial state saved for a resume
        await runner.close()
        store.release(failed=not state["done"])
        oversize_note(transport)
    t = state["t"]
    end = t.finished_at if t is not None and t.finished_at else loop.time()
    secs = end - started
    size = t.file_size if t is not None else 0
    ok = bool(state["done"])
    goodput = size / secs if ok and secs > 0 else None
    cap = link.recv_capacity
    if runner.pipe is not None and runner.pipe.opened:
        cap = runner.pipe_rate_Bps
    report = {
        "ok": ok, "code": "COMPLETE" if ok else (state["code"] or "FAILED"),
        "message": f"{name}: {size} bytes received and verified" if ok else (state["error"] or ""),
        "name": name, "bytes": size, "sha256": t.sha256.hex() if t is not None and t.sha256 else None,
        "seconds": round(secs, 3),
        "goodput_Bps": round(goodput, 1) if goodput is not None else None,
        "capacity_Bps": round(cap, 1) if cap else None,
        "efficiency": round(goodput / cap, 4) if cap and goodput is not None else None,
        "retransmitted_bytes": None, "frames_sent": None, "frames_received": t.frames if t is not None else 0,
        "path": t.final_path if t is not None else None, "peer": peer, "endpoint": transport.describe(),
        "direction": "fetch", "deflated_bytes": t.size if t is not None and t.original is not None else None,
        "resumed_bytes": state["resumed"] if ok else 0, "server_restarts": state["restarts"],
        **_pipe_report(runner),
    }
    if sigs.stop.is_set() and not ok:
        return Outcome(False, report, interrupted=True)
    if ok:
        return Outcome(True, report)
    err = state["error"] or "failed"
    if state["code"] == "NOT_FOUND":
        err = f"not found at {peer}: {err}"
    elif state["code"] == "REQUEST_REFUSED":
        err = f"refused by {peer}: {err}"
    elif state["code"] == "TIMEOUT" and t is None:
        err = f"timed out: no answer from {peer} at {spec} within {o.timeout:g} s (is a peer with --serve running?)"
    if kept:
        err += f" (what arrived is kept in {store.partial_dir}: fetch again to resume)"
    report["message"] = err
    return Outcome(False, report, err)


def _accepted(t: Any, state: dict[str, Any], peer: str, log: Any) -> None:
    """A fetch's transfer accepted here: the first says what was here already (resumed_bytes,
    in the file's bytes); a later one is the request served anew, after the server restarted,
    resumed from this end's partial file if it is the same file, or the new file from the start."""
    have = t.partial.ranges.total() if t.partial is not None else 0
    if t.original is not None and t.size:  # a zlib stream's bytes: the file's share of them
        have = round(have * t.original / t.size)
    before = state["accepted"]
    state["accepted"] = t
    if before is None:
        state["resumed"] = have
        return
    if before is t:
        return
    state["restarts"] += 1
    if (before.sha256, before.file_size) == (t.sha256, t.file_size):
        log(f"{peer} served {t.name} anew (it restarted): resuming at {have} of {t.file_size} bytes")
        return
    state["resumed"] = have  # (here before this run: nothing of the old file counts towards the new one)
    start = "from the start" if not have else f"from the {have} bytes of it already here"
    log(f"{peer} now serves a different {t.name} (another SHA-256, {t.file_size} bytes): fetching it again {start}; "
        "what came of the old one is not used")


def _summary(r: dict[str, Any]) -> str:
    verb = "sent" if r["direction"] == "send" else "received"
    if r.get("nothing_sent"):
        return (f"{r['name']} is already at {r['peer']}: {r['bytes']} bytes, the same SHA-256; nothing needed "
                "sending")
    parts = [f"{verb} {r['name']} {'to' if verb == 'sent' else 'from'} {r['peer']}: {r['bytes']} bytes in "
             f"{r['seconds']:.2f} s, goodput {r['goodput_Bps']:.0f} B/s"]
    if r.get("efficiency") is not None:
        parts.append(f"efficiency {r['efficiency']:.0%} of {r['capacity_Bps']:.0f} B/s")
    if r.get("retransmitted_bytes") is not None:
        parts.append(f"{r['retransmitted_bytes']} bytes retransmitted")
    if r.get("resumed_bytes"):
        parts.append(f"resumed: {r['resumed_bytes']} bytes were already {'there' if verb == 'sent' else 'here'}")
    if r.get("server_restarts"):
        n = r["server_restarts"]
        parts.append(f"{r['peer']} restarted {n} time{'s' if n > 1 else ''} and served it anew")
    if r.get("deflated_bytes"):
        parts.append(f"deflate {r['bytes'] / r['deflated_bytes']:.1f}x: {r['deflated_bytes']:,} B on the link for "
                     f"{r['bytes']:,} B")
    elif r.get("deflate_fallback"):
        parts.append(f"sent as it is: {r['deflate_fallback']}")
    text = ", ".join(parts)
    if r.get("path"):
        text += f" -> {r['path']}"
    return text
