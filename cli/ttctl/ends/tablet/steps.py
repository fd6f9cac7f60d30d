"""The tablet's steps, the same for a `--script` file and the interactive prompt.

A script is a YAML list; each item is one step, a name with its argument:

    - takeoff: 5                    # metres above home (0 or none: the vehicle's default)
    - wait: {until: altitude >= 4.5, timeout: 30}
    - send: mission.yaml            # a file next to the script, by the file transfer
    - fly: mission.yaml             # TT_ACTION_FLY_TRAJECTORY with that file
    - wait: {until: state == hovering, timeout: 120}
    - goto: [10, 0, 5]              # a set-point: north, east, altitude above home
    - move: [0, 5, 0]               # relative to where the vehicle is
    - hover
    - return
    - land
    - fetch: results.csv            # from the vehicle's served folder
    - wait: 2                       # seconds
    - status
    - watch: 10                     # a live view of the vehicle and the link for 10 s
    - msg: KR_MOTOR_CONTROL dir=FORWARD speed=40   # any message of the dialect (ttctl.ends.tablet.usermsg), once
    - msg: {send: KR_MOTOR_CONTROL seq=7 dir=STOP}  # the same, once
    - wait: {until: KR_MOTOR_STATUS.seq == 7, timeout: 30}
    - msg: {send: KR_MOTOR_CONTROL seq=8 dir=STOP, until: KR_MOTOR_STATUS.seq == 8, every: 1, timeout: 30}
                                    # again every second until the vehicle's answer says it arrived

`until` is one or more `FIELD OP VALUE` joined by `and`; fields: state, armed, altitude, n, e,
speed, and MESSAGE.field (or MESSAGE.field[i]) of the latest such message from the vehicle
(false until one came); operators >=, <=, >, <, ==, !=. Every step is checked against the
dialect before the first one runs. A step fails with a reason; the script stops at the first
failure.
"""

from __future__ import annotations

import asyncio
import math
import re
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ...wire.contract import TtAction as A
from .session import TabletSession
from .usermsg import MessageError, Operand, build, compare, describe, operand

NAMES = ("takeoff", "land", "hover", "return", "goto", "move", "fly", "send", "fetch", "wait", "status", "watch",
         "msg")
FIELDS = ("state", "armed", "altitude", "n", "e", "speed")
_COND = re.compile(r"^\s*([\w.\[\]]+)\s*(>=|<=|==|!=|>|<)\s*(.+?)\s*$")


class StepError(Exception):
    pass


@dataclass
class Step:
    name: str
    arg: Any
    where: str  # "step 3" or "line 12"

    def describe(self) -> str:
        if self.arg is None:
            return self.name
        if isinstance(self.arg, dict):
            timeout = f" (timeout {self.arg['timeout']:g} s)" if "timeout" in self.arg else ""
            send = f" {self.arg['send']}" if "send" in self.arg else ""
            until = f" until {self.arg['until']}" if "until" in self.arg else ""
            return f"{self.name}{send}{until}{timeout}"
        if isinstance(self.arg, list):
            return f"{self.name} {' '.join(f'{x:g}' for x in self.arg)}"
        if isinstance(self.arg, float):
            return f"{self.name} {self.arg:g}"
        return f"{self.name} {self.arg}"


# a number as YAML 1.2 and JSON write it: PyYAML (YAML 1.1) reads 1e9 as the text "1e9"
_NUMBER = re.compile(r"^[-+]?(\.[0-9]+|[0-9]+(\.[0-9]*)?)([eE][-+]?[0-9]+)?$")
FLOAT32_MAX = 3.4028234663852886e38  # a TT_ACTION_COMMAND's param is a float


def _number(x: Any, what: str) -> float:
    """`x` as a finite number (StepError names `what` and the value that is not one)."""
    if isinstance(x, bool) or not isinstance(x, (int, float, str)) or (
            isinstance(x, str) and not _NUMBER.match(x.strip())):
        raise StepError(f"{what}: {x!r} is not a number")
    v = float(x)
    if not math.isfinite(v):
        raise StepError(f"{what}: {x!r} is not a finite number")
    return v


def _numbers(arg: Any, n: int, what: str) -> list[float]:
    if not isinstance(arg, (list, tuple)) or len(arg) != n:
        raise StepError(f"{what} wants {n} numbers")
    return [_number(x, what) for x in arg]


Clause = tuple[str | Operand, str, Any]  # (field or MESSAGE.field, operator, the value compared with)


def check_condition(text: str, b: Any = None) -> list[Clause]:
    """The clauses of a `wait until` condition, every name and value checked (StepError);
    MESSAGE.field operands need the dialect `b`."""
    parts: list[Clause] = []
    for clause in re.split(r"\s+and\s+", str(text).strip()):
        m = _COND.match(clause)
        if m is None:
            raise StepError(f"cannot read condition {clause!r}: FIELD OP VALUE, FIELD one of {', '.join(FIELDS)} "
                            "or MESSAGE.field")
        name, op, raw = m.group(1), m.group(2), m.group(3)
        try:
            lhs = operand(b, name) if b is not None else None
            if lhs is not None:
                want = lhs.target(raw)
                if isinstance(want, str) and op not in ("==", "!="):
                    raise MessageError(f"{name} is text: compare it with == or !=")
                parts.append((lhs, op, want))
                continue
        except MessageError as e:
            raise StepError(f"cannot read condition {clause!r}: {e}") from None
        if name not in FIELDS:
            raise StepError(f"cannot read condition {clause!r}: FIELD OP VALUE, FIELD one of {', '.join(FIELDS)} "
                            "or MESSAGE.field")
        if name in ("state", "armed") and op not in ("==", "!="):
            raise StepError(f"cannot read condition {clause!r}: {name} can only be compared with == or !=")
        if name not in ("state", "armed"):
            try:
                float(raw)
            except ValueError:
                raise StepError(f"cannot read condition {clause!r}: {name} is a number, not {raw!r}") from None
        parts.append((name, op, raw))
    return parts


def holds(parts: list[Clause], fields: dict[str, Any], latest: dict[str, Any] | None = None) -> bool:
    for name, op, raw in parts:
        if isinstance(name, Operand):
            have = name.value(latest or {})
            if have is None or not compare(have, op, raw):
                return False
            continue
        have = fields[name]
        if isinstance(have, (bool, str)):
            want: Any = raw.lower() in ("true", "yes", "1") if isinstance(have, bool) else raw.replace("_", " ")
            ok = {"==": have == want, "!=": have != want}.get(op)
            if ok is None:
                raise StepError(f"{name} can only be compared with == or !=")
        else:
            try:
                want = float(raw)
            except ValueError:
                raise StepError(f"{name} is a number, not {raw!r}") from None
            ok = {">=": have >= want, "<=": have <= want, ">": have > want, "<": have < want,
                  "==": abs(have - want) < 1e-9, "!=": abs(have - want) >= 1e-9}[op]
        if not ok:
            return False
    return True


def _heard(s: TabletSession, parts: list[Clause]) -> str:
    """What the vehicle last said of the messages a condition names, for a timeout's words."""
    out = []
    loop = asyncio.get_running_loop()
    for name, _, _ in parts:
        if isinstance(name, Operand):
            n = name.cls.NAME
            if n not in s.latest:
                out.append(f"no {n} heard")
            else:
                out.append(f"{name.text} = {name.value(s.latest)!r} {loop.time() - s.latest_at[n]:.1f} s ago")
    return "; ".join(dict.fromkeys(out))


def parse_script(text: str, b: Any = None) -> list[Step]:
    """The steps of a script, every one checked (against the dialect `b`, for messages) before
    any runs (StepError names the line)."""
    import yaml

    try:
        root = yaml.compose(text, Loader=yaml.SafeLoader)
    except yaml.YAMLError as e:
        mark = getattr(e, "problem_mark", None)
        where = f"line {mark.line + 1}: " if mark is not None else ""
        raise StepError(f"{where}not valid YAML ({getattr(e, 'problem', None) or e})") from None
    except RecursionError:  # PyYAML's composer recurses once per level
        raise StepError("nested too deeply to be a script") from None
    if not isinstance(root, yaml.SequenceNode) or not root.value:
        raise StepError("a script is a non-empty YAML list of steps")
    steps = []
    for node in root.value:
        where = f"line {node.start_mark.line + 1}"
        value = yaml.safe_load(yaml.serialize(node))
        if isinstance(value, str):
            name, arg = value, None
        elif isinstance(value, dict) and len(value) == 1:
            ((name, arg),) = value.items()
        else:
            raise StepError(f"{where}: a step is one name, or one name: argument")
        try:
            steps.append(check_step(str(name), arg, where, b))
        except StepError as e:
            raise StepError(f"{where}: {e}") from None
    return steps


def check_step(name: str, arg: Any, where: str = "", b: Any = None) -> Step:
    if name not in NAMES:
        raise StepError(f"unknown step {name!r} (one of {', '.join(NAMES)})")
    if name == "takeoff" and arg is not None:
        arg = _number(arg, "takeoff")
        if not 0 <= arg <= FLOAT32_MAX:
            raise StepError(f"takeoff: altitude {arg:g} m is below 0 (0 or none: the vehicle's default)"
                            if arg < 0 else f"takeoff: altitude {arg:g} m is too large")
    elif name in ("goto", "move"):
        arg = _numbers(arg, 3, name)
        if name == "goto" and arg[2] < 0:
            raise StepError(f"goto: altitude {arg[2]:g} m is below home (goto N E ALT, ALT above home)")
    elif name in ("fly", "send", "fetch") and (not isinstance(arg, str) or not arg):
        raise StepError(f"{name} wants a file name")
    elif name == "wait":
        if isinstance(arg, (int, float)) and not isinstance(arg, bool):
            if not 0 <= float(arg) <= 86400:
                raise StepError("wait wants 0..86400 seconds")
        elif isinstance(arg, dict) and "until" in arg and set(arg) <= {"until", "timeout"}:
            check_condition(arg["until"], b)
            if "timeout" in arg:
                arg = {**arg, "timeout": _number(arg["timeout"], "timeout")}
                if not 0 < arg["timeout"] <= 86400:
                    raise StepError("wait: timeout wants 0..86400 seconds")
        else:
            raise StepError("wait wants seconds, or {until: CONDITION, timeout: SECONDS}")
    elif name == "watch" and arg is not None and not (isinstance(arg, (int, float)) and not isinstance(arg, bool)
                                                      and 0 < float(arg) <= 3600):
        raise StepError("watch wants 1..3600 seconds")
    elif name in ("land", "hover", "return", "status") and arg not in (None, {}):
        raise StepError(f"{name} takes no argument")
    elif name == "msg":
        _check_msg(arg, b)
    return Step(name, arg, where)


MSG_FORMS = ("msg wants a message of the dialect, NAME field=value ..., or {send: NAME field=value ...} (once), "
             "or {send: ..., until: CONDITION, every: SECONDS, timeout: SECONDS}")


def _check_msg(arg: Any, b: Any) -> None:
    if b is None:
        raise StepError("msg needs the link's dialect")
    if isinstance(arg, dict):
        if not {"send"} <= set(arg) <= {"send", "until", "every", "timeout"}:
            raise StepError(MSG_FORMS)
        if "until" not in arg and set(arg) != {"send"}:
            raise StepError(f"msg: {' and '.join(sorted(set(arg) - {'send'}))} go with until (without it, "
                            "msg sends once)")
        if "until" in arg:
            check_condition(arg["until"], b)
            every = _numbers([arg.get("every", 1.0)], 1, "every")[0]
            timeout = _numbers([arg.get("timeout", 30.0)], 1, "timeout")[0]
            if not 0.05 <= every <= 3600 or not 0 < timeout <= 86400:
                raise StepError("msg: every wants 0.05..3600 s and timeout 0..86400 s")
        arg = arg["send"]
    if not isinstance(arg, str) or not arg.strip():
        raise StepError(MSG_FORMS)
    try:
        build(b, arg, (1, 240))
    except MessageError as e:
        raise StepError(str(e)) from None


async def run_step(s: TabletSession, step: Step, base: Path) -> str:
    """Carry out one step; its result in words, or StepError."""
    name, arg = step.name, step.arg
    if name in ("takeoff", "land", "hover", "return", "fly"):
        action = {"takeoff": A.TT_ACTION_TAKE_OFF, "land": A.TT_ACTION_LAND, "hover": A.TT_ACTION_HOVER,
                  "return": A.TT_ACTION_RETURN_HOME, "fly": A.TT_ACTION_FLY_TRAJECTORY}[name]
        params = [float(arg)] if name == "takeoff" and arg is not None else []
        ok, words = await s.command(int(action), params, argument=str(arg) if name == "fly" else "")
        if not ok:
            raise StepError(words)  # with the vehicle's own words
        await s.fresh_state()
        return words
    if name in ("goto", "move"):
        n, e, alt = _numbers(arg, 3, name)
        if name == "move":
            v = s.vehicle
            n, e, alt = v.n + n, v.e + e, v.altitude + alt
        ok, words = await s.setpoint(n, e, alt)
        if not ok:
            raise StepError(words)  # with the vehicle's own words
        await s.fresh_state()
        return words
    if name == "send":
        path = (base / arg) if not Path(arg).is_absolute() else Path(arg)
        ok, words = await s.send_file(path, Path(arg).name)
        if not ok:
            raise StepError(words)
        return words
    if name == "fetch":
        ok, words = await s.fetch_file(arg)
        if not ok:
            raise StepError(words)
        return words
    if name == "wait":
        if not isinstance(arg, dict):
            await asyncio.sleep(float(arg))
            return f"waited {float(arg):g} s"
        parts = check_condition(arg["until"], s.b)
        timeout = float(arg.get("timeout", 60))
        end = time.monotonic() + timeout
        while not holds(parts, s.vehicle.fields(), s.latest):
            if time.monotonic() >= end:
                v = s.vehicle
                said = _heard(s, parts)
                raise StepError(f"{arg['until']} not reached within {timeout:g} s (" + (
                    said if said else f"state {v.state}, altitude {v.altitude:.1f} m") + ")" + s.link_note())
            await s.changed(0.25)
        return f"{arg['until']}"
    if name == "msg":
        return await _send(s, arg)
    if name == "status":
        return status_line(s)
    if name == "watch":
        return await watch(s, float(arg) if arg is not None else 10.0)
    raise StepError(f"unknown step {name!r}")


async def _send(s: TabletSession, arg: Any) -> str:
    """`msg`: send once ("sent": the link may lose it), or with `until` send again every `every`
    seconds until the condition holds on messages that arrived since the first send (a stale
    answer does not count), so that the answer is the proof of delivery."""
    text = arg["send"] if isinstance(arg, dict) else str(arg)
    try:
        msg = build(s.b, text, s.target)
    except MessageError as e:
        raise StepError(str(e)) from None
    if not isinstance(arg, dict) or "until" not in arg:
        s.send_message(msg)
        return f"sent {describe(msg, b=s.b)}"
    parts = check_condition(arg["until"], s.b)
    every, timeout = float(arg.get("every", 1.0)), float(arg.get("timeout", 30.0))
    loop = asyncio.get_running_loop()
    since = loop.time()
    end, sends = since + timeout, 0
    while True:
        s.send_message(msg)
        sends += 1
        again = min(end, loop.time() + every)
        while loop.time() < again:
            fresh = {n: m for n, m in s.latest.items() if s.latest_at.get(n, 0.0) >= since}
            if holds(parts, s.vehicle.fields(), fresh):
                return f"answered after {sends} send{'s' * (sends > 1)} in {loop.time() - since:.1f} s"
            await s.changed(min(0.25, max(0.0, again - loop.time())))
        if loop.time() >= end:
            said = _heard(s, parts)
            raise StepError(f"{arg['until']} not reached within {timeout:g} s of sending {msg.NAME} ({sends} times)"
                            + (f"; {said}" if said else "") + s.link_note())


async def watch(s: TabletSession, seconds: float) -> str:
    """A live view of the vehicle and the link for `seconds` (a table redrawn four times a
    second where the output is a terminal; lines otherwise)."""
    from rich.console import Console
    from rich.live import Live
    from rich.table import Table

    console = Console()

    def view() -> Table:
        v, link = s.vehicle, s.link
        loop = asyncio.get_running_loop()
        t = Table(title="vehicle and link", show_header=False)
        t.add_row("state", f"{v.state}{' (armed)' if v.armed else ''}")
        t.add_row("position", f"{v.n:.1f} m N, {v.e:.1f} m E, {v.altitude:.1f} m up, {v.speed:.1f} m/s")
        t.add_row("GNSS", f"{v.lat:.6f}, {v.lon:.6f}")
        t.add_row("heard", f"{loop.time() - v.heard:.1f} s ago" if v.heard is not None else "never")
        t.add_row("link", f"{link.frames} frames in, {s.runner.stats.packets_in} packets in, "
                          f"{s.runner.stats.packets_out} out" + (f", command RTT {link.rtt_ms:.0f} ms"
                                                                 if link.rtt_ms is not None else ""))
        transfers = [f"{x.name}: {x.acked_bytes}/{x.size} B" for x in s.ep.senders.values() if not x.done]
        t.add_row("transfers", ", ".join(transfers) or "none")
        t.add_row("last log", v.log[-1] if v.log else "")
        for name in s.user_messages():
            t.add_row(name, f"{describe(s.latest[name], b=s.b)} ({loop.time() - s.latest_at[name]:.1f} s ago)")
        return t

    end = asyncio.get_running_loop().time() + seconds
    if console.is_terminal:
        with Live(view(), console=console, refresh_per_second=4) as live:
            while asyncio.get_running_loop().time() < end:
                await asyncio.sleep(0.25)
                live.update(view())
    else:
        while asyncio.get_running_loop().time() < end:
            await asyncio.sleep(min(1.0, max(0.0, end - asyncio.get_running_loop().time())))
            print(status_line(s), flush=True)
            for name in s.user_messages():
                print(f"  {describe(s.latest[name], b=s.b)}", flush=True)
    return status_line(s)


def status_line(s: TabletSession) -> str:
    v, link = s.vehicle, s.link
    loop = asyncio.get_running_loop()
    age = f"{loop.time() - v.heard:.1f} s ago" if v.heard is not None else "never"
    age += " (link lost)" if s.link.lost_at is not None else ""
    rtt = f", command round trip {link.rtt_ms:.0f} ms" if link.rtt_ms is not None else ""
    unknown = f" (and {s.ep.unknown} of messages dialect {s.b.name} lacks)" if s.ep.unknown else ""
    return (f"{v.state}{' (armed)' if v.armed else ''}: {v.n:.1f} N {v.e:.1f} E {v.altitude:.1f} m, "
            f"{v.speed:.1f} m/s; heard {age}, {link.frames} frames{unknown}{rtt}")
