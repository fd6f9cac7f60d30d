"""`ttctl emulate tablet`: the Android app's role, from a prompt or a script."""

from __future__ import annotations

import asyncio
import contextlib
import json
import os
import sys
import threading
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import Fail
from .common import ONBOARD, Signals, check_id, err, link_choice, load_signing, parse_endpoint, pipe_link
from .dialect import load_bindings

HELP = ("takeoff [ALT] | land | hover | return | goto N E ALT | move DN DE DALT | fly FILE | send FILE | "
        "fetch NAME | msg MESSAGE field=value... [until CONDITION [every S] [timeout S]] | wait SECONDS | "
        "wait until FIELD OP VALUE [timeout S] "
        "(FIELD: state, armed, altitude, n, e, speed or MESSAGE.field) | status | watch [SECONDS] | quit")


READING = threading.Event()  # the prompt's reader is inside input(): see emulate_tablet
HEARTBEAT_WAIT = 3.0  # s after the vehicle's first frame, for its first HEARTBEAT (it sends one a second)


@dataclass
class TabletOptions:
    to: str = "udpout:127.0.0.1:14560"
    script: Path | None = None
    as_json: bool = False
    dir: Path | None = None
    rate: float | None = None
    profile: str | None = None
    distance: float = 10.0
    target_sysid: int = ONBOARD[0]
    connect_timeout: float = 15.0
    key: Path | None = None
    accept_unsigned: bool = False
    profile_file: Path | None = None
    dialect: Path | None = None
    include_dirs: list[Path] = field(default_factory=list)
    plugins: list[str] = field(default_factory=list)
    gcs: list[str] = field(default_factory=list)
    gcs_share: float = 0.8
    pipeline: str | None = None  # a MOP pipeline beside the link (tcpout:, as the app connects)
    pipe_rate: float | None = None


def _prompt_msg(text: str) -> Any:
    """`msg NAME field=value ... [until CONDITION [every S] [timeout S]]` as the step's argument."""
    body, sep, cond = text.partition(" until ")
    if not sep:
        return text
    arg: dict[str, Any] = {"send": body.strip()}
    for key in ("timeout", "every"):
        if f" {key} " in f" {cond} ":
            cond, _, value = cond.rpartition(f" {key} ")
            arg[key] = float(value)
    arg["until"] = cond.strip()
    return arg


def _prompt_step(line: str, b: Any = None) -> Any:
    """A prompt line as a step (StepError if it is not one); `b`: the link's dialect."""
    from ..ends.tablet.steps import StepError, check_step

    words = line.split()
    name, rest = words[0].lower(), words[1:]
    try:
        if name == "msg":
            arg: Any = _prompt_msg(line.strip()[len(words[0]):].strip())
        elif name in ("goto", "move"):
            arg = [float(x) for x in rest]
        elif name == "takeoff":
            arg = float(rest[0]) if rest else None
        elif name == "wait" and rest and rest[0] == "until":
            text = " ".join(rest[1:])
            timeout = None
            if " timeout " in f" {text} ":
                text, _, t = text.rpartition(" timeout ")
                timeout = float(t)
            arg = {"until": text} | ({"timeout": timeout} if timeout is not None else {})
        elif name == "wait":
            arg = float(rest[0]) if rest else 1.0
        elif name == "watch":
            arg = float(rest[0]) if rest else 10.0
        elif name in ("fly", "send", "fetch"):
            arg = " ".join(rest) or None
        else:
            arg = None if not rest else " ".join(rest)
    except (ValueError, IndexError):
        raise StepError(f"cannot read {line!r}: {HELP}") from None
    return check_step(name, arg, "prompt", b)


def emulate_tablet(o: TabletOptions) -> int:
    """The command; with --json a failure is also a JSON line on stdout ({"event": "error"})."""
    try:
        code = _emulate_tablet(o)
    except Fail as e:
        if o.as_json:
            print(json.dumps({"event": "error", "error": str(e), "exit": e.code}), flush=True)
        raise
    if READING.is_set():  # ended (Ctrl-C, SIGTERM) while the prompt's reader waits in input(): the
        sys.stdout.flush()  # interpreter could not finish with stdin held by it, so end here (all is closed)
        sys.stderr.flush()
        os._exit(code)
    return code


def _emulate_tablet(o: TabletOptions) -> int:
    from ..ends.plugins import PluginError, load_plugin
    from ..ends.tablet.steps import StepError, parse_script

    check_id(o.target_sysid, "--target-sysid")
    spec = parse_endpoint(o.to, "udpout")
    gcs = [parse_endpoint(g, "udpout", "--gcs") for g in o.gcs]
    link = link_choice(o.rate, o.profile, o.distance, 255, o.profile_file, o.pipe_rate)
    pipe = pipe_link(o.pipeline, link, err)
    b = load_bindings(o.dialect, o.include_dirs)  # before the plugins: they import its package
    if gcs:
        for name in ("HEARTBEAT", "RADIO_STATUS", "COMMAND_LONG"):
            try:
                b.message(name)
            except KeyError:
                raise Fail(f"--gcs: dialect {b.name} has no {name}: ground stations speak common.xml's "
                           "messages (include it, or ttapi.xml, which brings it)") from None
    plugins = []
    try:
        for p in o.plugins:
            plugins.extend(load_plugin(p))
    except PluginError as e:
        raise Fail(f"--plugin {e}") from None
    steps = None
    if o.script is not None:
        from ..safeio import MiB, read_text_capped

        text = read_text_capped(o.script, f"--script {o.script}", MiB)
        try:
            steps = parse_script(text, b)
        except StepError as e:
            raise Fail(f"--script {o.script}: {e}") from None
    try:
        return asyncio.run(_run(o, b, spec, link, steps, plugins, gcs, pipe))
    except KeyboardInterrupt:
        return 130


async def _run(o: TabletOptions, b: Any, spec: Any, link: Any, steps: Any, plugins: list[Any],
               gcs: list[Any], pipe: tuple[Any, float | None] = (None, None)) -> int:
    from ..ends.tablet.session import TabletSession
    from ..ends.tablet.steps import StepError, run_step
    from ..link.transport import TransportError
    from ..proto.storage import StorageError

    def event(what: str, fields: dict[str, Any]) -> None:
        if o.as_json:
            print(json.dumps({"event": what, **fields}), flush=True)
        elif what == "log":
            print(f"vehicle: {fields['text']}", flush=True)
        elif what == "link" and fields["state"] == "lost":
            err(f"tablet: link lost: nothing heard from the vehicle for {fields['silent']:g} s")
        elif what == "link":
            err(f"tablet: link back after {fields['silent']:g} s of silence")

    loop = asyncio.get_running_loop()
    wake = asyncio.Event()
    sigs = Signals(loop, wake)
    from ..ends.plugins import PluginError

    try:
        s = TabletSession(b, spec, (o.target_sysid, ONBOARD[1]), rate_Bps=link.pace_Bps, mtu=link.mtu, inbox=o.dir,
                          on_event=event, log=err, signing=load_signing(o.key, o.accept_unsigned, b),
                          plugins=plugins, gcs=gcs, gcs_share=o.gcs_share, pipe=pipe[0], pipe_Bps=pipe[1])
    except PluginError as e:
        raise Fail(f"--plugin {e}") from None
    try:
        try:
            await s.start()
        except (TransportError, StorageError) as e:
            raise Fail(str(e)) from None
        if s.bridge is not None:
            err(f"tablet: carrying ground stations at {s.bridge.describe()} to vehicle {o.target_sysid}")
        end = loop.time() + o.connect_timeout
        first: float | None = None  # when the first frame of the vehicle came
        while s.vehicle.state == "unknown":  # connected once a HEARTBEAT said what the vehicle is doing
            now = loop.time()
            first = now if first is None and s.vehicle.heard is not None else first
            if now >= end or (first is not None and now - first >= HEARTBEAT_WAIT):
                break  # (or once its other frames came, and no HEARTBEAT for a while)
            if sigs.stop.is_set():
                return 130
            await s.changed(0.2)
        if s.vehicle.heard is None:
            raise Fail(f"no vehicle answered at {spec} within {o.connect_timeout:g} s: {heard_note(s)}", 1)
        who = f"{o.target_sysid}/{ONBOARD[1]}"
        if s.vehicle.state == "unknown":  # its frames came, but no HEARTBEAT: no state to show or wait for
            err(f"tablet: connected to {who} at {spec}, but no HEARTBEAT from it in {HEARTBEAT_WAIT:g} s "
                f"(heard {', '.join(s.latest)}): its state stays unknown")
        else:
            err(f"tablet: connected to {who} at {spec}")
        base = o.script.parent if o.script is not None else Path(".")
        if steps is not None:
            for i, step in enumerate(steps, 1):
                if sigs.stop.is_set():
                    return 130
                try:
                    words = await run_step(s, step, base)
                except StepError as e:
                    if o.as_json:
                        print(json.dumps({"event": "step", "step": i, "what": step.describe(), "ok": False,
                                          "reason": str(e)}), flush=True)
                    raise Fail(f"step {i} ({step.where}: {step.describe()}) failed: {e}", 1) from None
                if o.as_json:
                    print(json.dumps({"event": "step", "step": i, "what": step.describe(), "ok": True,
                                      "result": words}), flush=True)
                else:
                    print(f"step {i} {step.describe()}: {words}", flush=True)
            return await _carry_on(s, sigs, 0)
        return await _carry_on(s, sigs, await _prompt(s, sigs, base, b, o.as_json))
    finally:
        sigs.remove()
        if s.bridge is not None and s.bridge.running:
            err(f"tablet: {s.bridge.summary()}")
        await s.close()


async def _carry_on(s: Any, sigs: Signals, code: int) -> int:
    """With ground stations behind the tablet (--gcs), the end of the script or of the prompt's
    input is not the end of the session: it carries them until interrupted."""
    if s.bridge is None or code != 0 or sigs.stop.is_set():
        return code
    err("tablet: still carrying ground stations (Ctrl-C ends)")
    await sigs.stop.wait()
    return 0


def heard_note(s: Any) -> str:
    """What the tablet heard while it waited for a vehicle that never answered."""
    peers = sorted(p for p in s.ep.peers if p != s.target)
    packets = s.runner.stats.packets_in
    if peers:
        who = ", ".join(f"{a}/{c}" for a, c in peers[:4])
        return (f"frames came only from {who}, not from {s.target[0]}/{s.target[1]} "
                f"(--target-sysid {s.target[0]}: is that the vehicle's system id?)")
    refused = getattr(s, "key_refused", None)
    if packets and refused == "unsigned frames":  # a vehicle without a key acts on signed frames: say so
        return (f"{packets} packets came, their frames unsigned and refused for --key: the vehicle answers "
                "unsigned (it has no key?); give it the same --key, or the tablet none")
    if packets and refused:
        return f"{packets} packets came, {refused} (the same --key at both ends?)"
    if packets:
        return (f"{packets} packets came but no frame of the dialect in them (another dialect, or signed "
                "frames without the same --key?)")
    if getattr(s, "signs", False):
        return ("nothing came back; the tablet signs its frames (--key): a vehicle with another key drops "
                "them unanswered (the same --key at both ends?)")
    return ("nothing came back (the tablet needs a HEARTBEAT, or any frame, from the vehicle's onboard "
            "component, which answers the address the tablet's own heartbeats come from)")


def completions(b: Any, line: str, text: str) -> list[str]:
    """What may follow at the prompt: step names first, then a message of the dialect after
    `msg` and its field=, or FIELD and MESSAGE.field after `wait until`."""
    from ..ends.tablet.steps import FIELDS, NAMES

    words = line[: len(line) - len(text)].split()
    if not words:
        return [n for n in (*NAMES, "quit") if n.startswith(text)]
    names = sorted(b.by_name) if b is not None else []
    if words[0] == "msg":
        if len(words) == 1:
            return [n for n in names if n.startswith(text.upper())] if text else names
        try:
            cls = b.message(words[1])
        except KeyError:
            return []
        return [f"{f}=" for f in cls.FIELDS if f.startswith(text)]
    if words[:2] == ["wait", "until"] or (words[0] == "wait" and "until".startswith(text) and len(words) == 1):
        if len(words) == 1:
            return ["until"]
        if "." in text:
            head, _, tail = text.partition(".")
            try:
                cls = b.message(head)
            except KeyError:
                return []
            return [f"{cls.NAME}.{f}" for f in cls.FIELDS if f.startswith(tail)]
        return [f for f in FIELDS if f.startswith(text)] + [f"{n}." for n in names if n.startswith(text.upper())]
    return []


async def _prompt(s: Any, sigs: Signals, base: Path, b: Any = None, as_json: bool = False) -> int:
    """Commands from the terminal (history and completion with readline) or from piped lines,
    run one after another. The prompt stays responsive while a command waits: Ctrl-C cancels
    it (and what was typed behind it), `status` typed meanwhile is answered at once at a
    terminal; Ctrl-C with nothing running, or quit, ends the session."""
    import signal

    from ..ends.tablet.steps import StepError, run_step, status_line

    interactive = sys.stdin.isatty()
    if interactive:
        try:
            import readline

            readline.parse_and_bind("tab: complete")
            readline.set_completer_delims(" \t")
            readline.set_completer(lambda text, i: (completions(b, readline.get_line_buffer(), text) + [None])[i])
        except ImportError:
            pass
        print(f"commands: {HELP}", file=sys.stderr)
    loop = asyncio.get_running_loop()
    lines: asyncio.Queue[str | None] = asyncio.Queue()

    want = threading.Semaphore(1)  # a line asked for: the reader waits in input() only then (not after quit)

    def read() -> None:  # a thread of its own, so that the loop runs while it waits for a line
        while True:
            want.acquire()
            READING.set()
            try:
                line: str | None = input("tablet> " if interactive else "")
            except (EOFError, OSError, ValueError):
                line = None
            finally:
                READING.clear()
            loop.call_soon_threadsafe(lines.put_nowait, line)
            if line is None:
                return

    threading.Thread(target=read, name="tablet-prompt", daemon=True).start()

    def said(step: Any, ok: bool, words: str) -> None:
        if as_json:
            what = step.describe() if not isinstance(step, str) else step
            print(json.dumps({"event": "step", "what": what, "ok": ok, "result" if ok else "reason": words}),
                  flush=True)
        elif ok:
            print(words, flush=True)
        else:
            print(f"ttctl: {words}", file=sys.stderr, flush=True)

    def waiting(step: Any) -> None:
        """A command waits while the link is lost: said at once (not after its tries run out), with
        how to give it up."""
        quiet = s.silence()
        what = step.describe() if not isinstance(step, str) else step
        if as_json:
            print(json.dumps({"event": "waiting", "what": what, "silent": round(quiet or 0.0, 1)}), flush=True)
        else:
            print(f"ttctl: {what}: waiting for the link (nothing heard from the vehicle for {quiet or 0.0:.1f} s); "
                  f"Ctrl-C gives it up", file=sys.stderr, flush=True)

    backlog: list[str] = []
    current: asyncio.Task[str] | None = None
    told_waiting = False
    step: Any = None
    eof = False
    getter: asyncio.Task[str | None] = loop.create_task(lines.get())
    stopper = loop.create_task(sigs.stop.wait())
    try:
        while True:
            while current is None and backlog:
                line = backlog.pop(0)
                if line in ("quit", "exit"):
                    sigs.stop.set()  # the session ends here (with --gcs too, which outlives the input's end)
                    return 0
                try:
                    step = _prompt_step(line, b)
                except StepError as e:
                    said(line, False, str(e))
                    continue
                current = loop.create_task(run_step(s, step, base))
                told_waiting = False
            if current is None and eof:
                return 0
            waits: set[asyncio.Future[Any]] = {stopper}
            waits |= {getter} if not eof else set()
            waits |= {current} if current is not None else set()
            done, _ = await asyncio.wait(waits, return_when=asyncio.FIRST_COMPLETED,
                                         timeout=0.25 if current is not None and not told_waiting else None)
            if current is not None and current not in done and not told_waiting and s.silence() is not None:
                told_waiting = True
                waiting(step)
            if current is not None and current in done:
                try:
                    said(step, True, current.result())
                except StepError as e:
                    said(step, False, str(e))
                current = None
            if stopper in done:
                if sigs.got != signal.SIGINT or current is None:
                    return 130
                current.cancel()  # Ctrl-C: the waiting command, and what was typed behind it
                with contextlib.suppress(asyncio.CancelledError, StepError):
                    await current
                dropped = f" (and {len(backlog)} line(s) typed behind it)" if backlog else ""
                said(step, False, f"{step.describe()}: cancelled{dropped}")
                current, backlog = None, []
                sigs.stop.clear()
                sigs.got = None
                stopper = loop.create_task(sigs.stop.wait())
            if getter in done:
                got = getter.result()
                if got is None:
                    eof = True
                else:
                    getter = loop.create_task(lines.get())
                    got = got.strip()
                    if got not in ("quit", "exit"):
                        want.release()  # the next line
                    if not got or got.startswith("#"):
                        continue
                    if interactive and current is not None and got == "status":
                        print(status_line(s), flush=True)  # a look at the vehicle while a command waits
                        continue
                    backlog.append(got)
    finally:
        for t in (getter, stopper, current):
            if t is not None:
                t.cancel()
