"""`ttctl recv-file`: the receiving end (the onboard computer, 1/240, by default), a line per
file accepted, refused, waiting, completed or failed; with --serve, downloads too."""

from __future__ import annotations

import asyncio
import json
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import Fail
from .common import (
    ONBOARD,
    LinkChoice,
    Signals,
    check_id,
    check_pipeline,
    err,
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
    key: Path | None = None
    accept_unsigned: bool = False
    profile_file: Path | None = None
    dialect: Path | None = None
    include_dirs: list[Path] = field(default_factory=list)
    pipeline: str | None = None
    pipe_rate: float | None = None


def recv_file(o: RecvOptions) -> int:
    try:
        return _recv_file(o)
    except Fail as e:
        if o.as_json:  # --json: the refusal as a JSON line too (and the one line on stderr)
            print(json.dumps({"event": "error", "message": str(e), "exit": e.code, "time": round(time.time(), 3)}),
                  flush=True)
        raise


def _recv_file(o: RecvOptions) -> int:
    from ..proto.storage import Quota, ReceiveDir, StorageError

    spec = parse_endpoint(o.listen, "udpin")
    check_id(o.sysid, "--sysid")
    check_id(o.compid, "--compid")
    if o.count is not None and o.count < 1:
        raise Fail("--count must be at least 1")
    link = link_choice(o.rate, o.profile, o.distance, o.sysid, o.profile_file, o.pipe_rate)
    check_pipeline(o.pipeline)
    b = load_bindings(o.dialect, o.include_dirs)
    signing = load_signing(o.key, o.accept_unsigned, b)
    q = Quota(overwrite=o.overwrite)
    if o.max_file is not None:
        if o.max_file < 0:
            raise Fail("--max-file must not be negative")
        q.max_file_bytes = o.max_file
    if o.max_dir is not None:
        if o.max_dir < 0:
            raise Fail("--max-dir must not be negative")
        q.max_dir_bytes = o.max_dir
    store = ReceiveDir(o.dir, q)
    try:
        store.check()
    except StorageError as e:
        raise Fail(f"--dir: {e}") from None
    if o.serve is not None and not o.serve.is_dir():
        raise Fail(f"--serve {o.serve} is not a directory")
    try:
        return asyncio.run(_recv(o, b, spec, link, store, signing))
    except KeyboardInterrupt:  # before the signal handlers were in place
        err("stopped")
        return 0


async def _recv(o: RecvOptions, b: Any, spec: Any, link: LinkChoice, store: Any, signing: Any) -> int:
    from ..ends.runtime import Runner, hello, unknown_note
    from ..link.transport import addr_text, make_transport
    from ..proto.endpoint import Endpoint
    from ..proto.storage import StorageError

    loop = asyncio.get_running_loop()
    wake = asyncio.Event()
    completed = 0  # distinct files (path and content) completed
    seen: set[tuple[str, bytes]] = set()
    latest: dict[str, bytes] = {}  # path -> the SHA-256 last completed there

    def out(event: str, text: str, **fields: Any) -> None:
        if o.as_json:
            print(json.dumps({"event": event, **fields, "time": round(time.time(), 3)}), flush=True)
        else:
            print(text, flush=True)

    def on_event(what: str, t: Any) -> None:
        nonlocal completed
        if what == "link-refused":
            err(f"ignoring {addr_text(t[0])}: {t[1]} (the same --key at both ends?)")
            return
        if what == "unknown-message":
            err(unknown_note(b, t))
            return
        if not what.startswith("file-"):
            return
        peer = who(t.key)
        name = t.name or "?"
        if what == "file-accepted":
            have = t.partial.ranges.total() if t.partial is not None else 0
            resumed = f", resuming with {have} bytes already here" if have else ""
            if t.original is not None:
                resumed = f", deflated to {t.size} B on the link{resumed}"
            out("accepted", f"accepted {name} ({t.file_size} bytes) from {peer}{resumed}", name=name,
                bytes=t.file_size, peer=peer, resumed_bytes=have,
                deflated_bytes=t.size if t.original is not None else None)
        elif what == "file-busy":
            out("waiting", f"{name} from {peer} waits: {t.reason}", name=name, bytes=t.file_size, peer=peer,
                reason=t.reason)
        elif what == "file-refused":
            out("refused", f"refused {name} from {peer}: {t.reason}", name=name, bytes=t.file_size, peer=peer,
                reason=t.reason)
        elif what == "file-complete":
            secs = (t.finished_at or loop.time()) - t.started
            key = (str(t.final_path), t.sha256)
            again = key in seen and latest.get(key[0]) == t.sha256
            latest[key[0]] = t.sha256
            if again:  # the sender asked again (it had not heard COMPLETE): one file, counted once
                out("complete-again", f"{name} from {peer} is complete already -> {t.final_path} (sent again; "
                    f"counted once)", name=name, bytes=t.file_size, peer=peer, path=t.final_path,
                    sha256=t.sha256.hex())
                wake.set()
                return
            if key not in seen:  # content that was there before another replaced it: a completion, counted once
                seen.add(key)
                completed += 1
            how = " (an identical file was there already)" if t.identical else ""
            out("complete", f"complete {name}: {t.file_size} bytes in {secs:.2f} s from {peer} -> "
                f"{t.final_path}{how}",
                name=name, bytes=t.file_size, seconds=round(secs, 3), peer=peer, path=t.final_path,
                sha256=t.sha256.hex())
        elif what == "file-failed":
            out("failed", f"failed {name} from {peer}: {t.reason}", name=name, bytes=t.file_size, peer=peer,
                reason=t.reason)
        wake.set()

    transport = make_transport(spec, log=lambda text: err(f"{spec.kind}: {text}"),
                               mtu=link.mtu if spec.udp else None)
    ep = Endpoint(b, o.sysid, o.compid, mtu=transport.mtu, rate_Bps=link.pace_Bps, receive_dir=store,
                  inbound_Bps=link.recv_capacity,
                  serve_dir=str(o.serve) if o.serve is not None else None, on_event=on_event, signing=signing)
    pipe, pipe_rate = pipe_link(o.pipeline, link, err)
    runner = Runner(ep, transport, quiet=link.quiet, hello=hello(o.sysid, spec, b), pipe=pipe,
                    pipe_rate_Bps=pipe_rate)
    await start(runner)  # the port first: a refusal leaves no directory behind
    try:
        store.prepare()
    except StorageError as e:
        await runner.close()
        raise Fail(f"--dir: {e}") from None
    sigs = Signals(loop, wake)
    serve = f", serving {o.serve}" if o.serve is not None else ""
    signed = ", signed" + (" (unsigned frames accepted too)" if o.accept_unsigned else "") if signing else ""
    err(f"receiving into {o.dir} as {o.sysid}/{o.compid} on {transport.describe()}{serve} ({link.describe()}"
        f"{signed})")
    served: dict[int, Any] = {}
    done_at: float | None = None
    failed = True
    try:
        while not sigs.stop.is_set():
            await tick(wake)
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
        failed = False
    finally:
        sigs.remove()
        ep.close()  # partial state saved for resume
        await runner.close()
        store.release(failed=failed)
        oversize_note(transport)
    if sigs.stop.is_set():
        err(f"stopped after {completed} file(s); partial transfers are kept for resume")
    return 0


def _report_served(ep: Any, served: dict[int, Any], out: Callable[..., None]) -> None:
    """Lines for downloads this end serves (they have no receiver events)."""
    for s in list(ep.senders.values()):
        if not s.request_id:
            continue
        seen = served.get(id(s))
        peer = who(s.target)
        if seen is None:
            served[id(s)] = "started"
            out("serving", f"serving {s.name} ({s.file_size} bytes) to {peer}", name=s.name, bytes=s.file_size,
                peer=peer)
        if s.done and served.get(id(s)) != "done":
            served[id(s)] = "done"
            r = s.result
            if r.ok:
                out("served", f"served {s.name}: {s.file_size} bytes in {r.seconds:.2f} s to {peer}", name=s.name,
                    bytes=s.file_size, seconds=round(r.seconds, 3), peer=peer)
            else:
                out("serve-failed", f"serving {s.name} to {peer} failed: {r.message}", name=s.name, peer=peer,
                    reason=r.message)
