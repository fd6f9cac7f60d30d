"""`ttctl emulate tablet`: the Android app's role, from a prompt or a script."""

from __future__ import annotations

import asyncio
import json
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import Fail
from .common import ONBOARD, Signals, err, link_choice, load_signing, parse_endpoint
from .dialect import load_bindings

HELP = ("takeoff [ALT] | land | hover | return | goto N E ALT | move DN DE DALT | fly FILE | send FILE | "
        "fetch NAME | msg MESSAGE field=value... [until CONDITION [every S] [timeout S]] | wait SECONDS | "
        "wait until FIELD OP VALUE [timeout S] "
        "(FIELD: state, armed, altitude, n, e, speed or MESSAGE.field) | status | watch [SECONDS] | quit")


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
    from ..ends.plugins import PluginError, load_plugin
    from ..ends.tablet.steps import StepError, parse_script

    spec = parse_endpoint(o.to, "udpout")
    link = link_choice(o.rate, o.profile, o.distance, 255, o.profile_file)
    b = load_bindings(o.dialect, o.include_dirs)  # before the plugins: they import its package
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
        return asyncio.run(_run(o, b, spec, link, steps, plugins))
    except KeyboardInterrupt:
        return 130


async def _run(o: TabletOptions, b: Any, spec: Any, link: Any, steps: Any, plugins: list[Any]) -> int:
    from ..ends.tablet.session import TabletSession
    from ..ends.tablet.steps import StepError, run_step
    from ..link.transport import TransportError
    from ..proto.storage import StorageError

    def event(what: str, fields: dict[str, Any]) -> None:
        if o.as_json:
            print(json.dumps({"event": what, **fields}), flush=True)
        elif what == "log":
            print(f"vehicle: {fields['text']}", flush=True)

    loop = asyncio.get_running_loop()
    wake = asyncio.Event()
    sigs = Signals(loop, wake)
    from ..ends.plugins import PluginError

    try:
        s = TabletSession(b, spec, (o.target_sysid, ONBOARD[1]), rate_Bps=link.pace_Bps, inbox=o.dir,
                          on_event=event, log=err, signing=load_signing(o.key, o.accept_unsigned, b),
                          plugins=plugins)
    except PluginError as e:
        raise Fail(f"--plugin {e}") from None
    try:
        try:
            await s.start()
        except (TransportError, StorageError) as e:
            raise Fail(str(e)) from None
        end = loop.time() + o.connect_timeout
        while s.vehicle.state == "unknown":  # connected once a HEARTBEAT said what the vehicle is doing
            if loop.time() >= end:
                raise Fail(f"no vehicle answered at {spec} within {o.connect_timeout:g} s", 1)
            if sigs.stop.is_set():
                return 130
            await s.changed(0.2)
        err(f"tablet: connected to {o.target_sysid}/{ONBOARD[1]} at {spec}")
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
            return 0
        return await _prompt(s, sigs, base, b)
    finally:
        sigs.remove()
        await s.close()


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


async def _prompt(s: Any, sigs: Signals, base: Path, b: Any = None) -> int:
    """Commands from the terminal (history and completion with readline) or from piped lines."""
    from ..ends.tablet.steps import StepError, run_step

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
    while not sigs.stop.is_set():
        try:
            line = await loop.run_in_executor(None, lambda: input("tablet> " if interactive else ""))
        except EOFError:
            return 0
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        if line in ("quit", "exit"):
            return 0
        try:
            step = _prompt_step(line, b)
            print(await run_step(s, step, base), flush=True)
        except StepError as e:
            print(f"ttctl: {e}", file=sys.stderr, flush=True)
    return 130
