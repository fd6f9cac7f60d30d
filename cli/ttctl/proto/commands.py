"""Commands with acknowledgement, sans-IO.

The client sends a TT_ACTION_COMMAND carrying a command id, at control priority (never behind
bulk data), and waits for the TT_COMMAND_ACK with the same id. It repeats the command with
backoff; after the last try it gives up and calls on_failure. Every command ends: on_success or
on_failure is called exactly once.

On a slow link (an Endpoint paced at 10 KB/s or less) a command whose ack has not come when it
should have goes once more: a copy, not a try. "Should have" is the round trip of the commands
answered at their first frame, smoothed as TCP smooths its (RFC 6298: SRTT + 4 RTTVAR), but never
less than two and a half packets' time (the Endpoint's `copy_after`: 0.5 s on the M100's uplink,
when the generated Java runtime's commands retry for the same reason). A radio buffer that other
senders' packets filled, or a lost packet, costs that command the copy's delay rather than the
retry's 1.5 s; the server answers the copy as it answers a retry. A command answered in time
costs nothing more, and a round trip that grows (a busy buffer) moves the copy later, so that
copies do not add to the queue they wait in.

The server executes a (peer, command id, issue time) once: a retry (the same message again) gets
the recorded ack without running the action twice, while a new command that happens to reuse an
id (another process of the same peer, or one started again, numbers its commands afresh) has
another issue time and runs. Clients start their ids at random and stamp each command with the
wall-clock time it was issued (time_usec) when the caller did not.
"""

from __future__ import annotations

import random
import time
from collections import OrderedDict
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from ..wire.bindings import Bindings
from ..wire.contract import TtResult

FINAL_OK = {TtResult.TT_RESULT_ACCEPTED, TtResult.TT_RESULT_IN_PROGRESS, TtResult.TT_RESULT_DONE}


@dataclass
class Command:
    msg: Any  # the dialect's TtActionCommand
    target: tuple[int, int]
    retries: int = 3
    timeout: float = 1.5  # first wait for the ack; doubles per retry
    on_success: Callable[[Command], None] | None = None
    on_failure: Callable[[Command], None] | None = None
    copy_after: float | None = None  # s after the first send that a copy goes if no ack came (None: none)
    # filled in
    submitted_at: float = 0.0
    sent_at: list[float] = field(default_factory=list)
    copies: int = 0  # copies sent (not tries)
    copy_delay: float | None = None  # when after its first frame its copy was due (None: none)
    acked_at: float | None = None
    ack: Any = None  # the TtCommandAck that ended it
    error: str | None = None
    _due: float = 0.0
    _wait: float = 0.0
    _copy_due: float | None = None

    @property
    def id(self) -> int:
        return int(self.msg.command_id)

    @property
    def done(self) -> bool:
        return self.acked_at is not None or self.error is not None

    @property
    def ok(self) -> bool:
        return self.ack is not None and self.ack.result in FINAL_OK

    @property
    def latency(self) -> float | None:
        """From the moment the command was issued to its ack."""
        return None if self.acked_at is None else self.acked_at - self.submitted_at


class CommandClient:
    def __init__(self, sysid: int, compid: int, first_id: int | None = None,
                 clock: Callable[[], float] = time.time) -> None:
        self.sysid = sysid
        self.compid = compid
        self.pending: dict[int, Command] = {}
        self._next_id = first_id if first_id is not None else random.randint(1, 65535)
        self.clock = clock
        self.srtt: float | None = None  # round trips of commands answered at their first frame (Karn)
        self.rttvar = 0.0

    def submit(self, cmd: Command, now: float) -> Command:
        if cmd.msg.command_id == 0:
            cmd.msg.command_id = self._next_id
            self._next_id = self._next_id % 65535 + 1
        if cmd.msg.time_usec == 0:
            cmd.msg.time_usec = int(self.clock() * 1e6)
        if cmd.msg.command_id in self.pending:
            raise ValueError(f"command id {cmd.msg.command_id} is already pending")
        cmd.msg.target_system, cmd.msg.target_component = cmd.target
        cmd.submitted_at = now
        cmd._due = now
        cmd._wait = cmd.timeout
        self.pending[cmd.id] = cmd
        return cmd

    def control(self, now: float) -> list[Any]:
        out: list[Any] = []
        for cmd in list(self.pending.values()):
            if now < cmd._due:
                if cmd._copy_due is not None and now >= cmd._copy_due:
                    cmd._copy_due = None
                    cmd.copies += 1
                    out.append(cmd.msg)
                continue
            if len(cmd.sent_at) > cmd.retries:
                self._fail(cmd, f"no ack after {len(cmd.sent_at)} tries")
                continue
            copy = self.copy_wait(cmd) if not cmd.sent_at else None
            if copy is not None and copy < cmd._wait:
                cmd.copy_delay = copy
                cmd._copy_due = now + copy
            else:
                cmd._copy_due = None  # a retry goes instead
            cmd.sent_at.append(now)
            cmd._due = now + cmd._wait
            cmd._wait *= 2
            out.append(cmd.msg)
        return out

    def on_ack(self, now: float, ack: Any) -> Command | None:
        if (ack.target_system, ack.target_component) not in ((self.sysid, self.compid), (self.sysid, 0), (0, 0)):
            return None
        cmd = self.pending.get(ack.command_id)
        if cmd is None or ((ack.get_srcSystem(), ack.get_srcComponent()) != cmd.target and cmd.target[1] != 0):
            return None
        del self.pending[cmd.id]
        cmd.ack = ack
        cmd.acked_at = now
        if len(cmd.sent_at) == 1 and not cmd.copies:  # which frame was answered is known: a sample
            rtt = now - cmd.sent_at[0]
            if self.srtt is None:
                self.srtt, self.rttvar = rtt, rtt / 2
            else:
                self.rttvar = 0.75 * self.rttvar + 0.25 * abs(self.srtt - rtt)
                self.srtt = 0.875 * self.srtt + 0.125 * rtt
        if cmd.ok:
            if cmd.on_success:
                cmd.on_success(cmd)
        else:
            try:
                cmd.error = f"refused: {TtResult(ack.result).name.removeprefix('TT_RESULT_')}"
            except ValueError:
                cmd.error = f"refused: result {ack.result}"
            if cmd.on_failure:
                cmd.on_failure(cmd)
        return cmd

    def copy_wait(self, cmd: Command) -> float | None:
        """When after its first frame a command's copy goes (None: no copy)."""
        if cmd.copy_after is None:
            return None
        if self.srtt is None:
            return cmd.copy_after
        return max(cmd.copy_after, self.srtt + 4 * self.rttvar)

    def _fail(self, cmd: Command, why: str) -> None:
        self.pending.pop(cmd.id, None)
        cmd.error = why
        if cmd.on_failure:
            cmd.on_failure(cmd)

    def hurry(self, now: float) -> None:
        """The peer is heard again after a silence: each command already sent goes again at
        once, not when its doubled wait ends (a retry, counted as one)."""
        for cmd in self.pending.values():
            if cmd.sent_at:
                cmd._due = min(cmd._due, now)

    def cancel_all(self, why: str) -> None:
        for cmd in list(self.pending.values()):
            self._fail(cmd, why)

    def deadline(self) -> float | None:
        return min((c._due if c._copy_due is None else min(c._due, c._copy_due) for c in self.pending.values()),
                   default=None)

    def next_send(self) -> float | None:
        """When a command next goes again (a copy or a retry; not a last wait that ends in failure)."""
        times = []
        for c in self.pending.values():
            if c._copy_due is not None:
                times.append(c._copy_due)
            if len(c.sent_at) <= c.retries:
                times.append(c._due)
        return min(times, default=None)


Outcome = int | tuple[int, str]
Action = Callable[[Any], Outcome]
"""Runs an action; returns a TtResult value, or (value, words): why it refused, what it does.
The words go to the commanding end as a TT_LOG line just ahead of the ack."""

NO_COMMANDS = "no commands are carried out here"


def log_chunks(b: Bindings, text: str, severity: int, boot_ms: int, line_id: int) -> list[Any]:
    """A TT_LOG line: one message (id 0) if it fits 80 bytes with room for its NUL, else chunks of
    80 bytes with one id and rising chunk_seq, the last one NUL-terminated (an empty one if the
    text divides evenly)."""
    raw = text.encode("utf-8")
    if len(raw) < 80:
        return [b.TtLog(time_boot_ms=boot_ms & 0xFFFFFFFF, id=0, severity=severity, chunk_seq=0, text=text)]
    pieces = [raw[i:i + 80] for i in range(0, len(raw), 80)]
    if len(pieces[-1]) == 80:
        pieces.append(b"")
    return [b.TtLog(time_boot_ms=boot_ms & 0xFFFFFFFF, id=line_id, severity=severity, chunk_seq=k,
                    text=piece.decode("utf-8", "surrogateescape")) for k, piece in enumerate(pieces[:256])]


class CommandServer:
    def __init__(self, bindings: Bindings, sysid: int, compid: int, action: Action | None = None,
                 memory: int = 512) -> None:
        self.b = bindings
        self.sysid = sysid
        self.compid = compid
        # no action: nothing here carries commands out, so none is acknowledged as accepted
        self.action: Action = action or (lambda msg: (int(TtResult.TT_RESULT_UNSUPPORTED), NO_COMMANDS))
        self.memory = memory
        self.done: OrderedDict[tuple[int, int, int, int], tuple[Any, str]] = OrderedDict()
        self.executed = 0
        self.duplicates = 0

    def on_command(self, msg: Any) -> Any:
        """The ack for `msg` (None: not ours); see `answer`."""
        return self.answer(msg)[0]

    def answer(self, msg: Any) -> tuple[Any, str]:
        """(the ack to send, the words to send just ahead of it, or ""). A command seen before
        (a retry: the same peer, id and issue time) gets its recorded ack without running
        again, and a refusal's recorded words with it: the retry may be the commanding end
        asking again because the words were lost on the way."""
        if msg.target_system not in (self.sysid, 0) or msg.target_component not in (self.compid, 0):
            return None, ""
        key = (msg.get_srcSystem(), msg.get_srcComponent(), msg.command_id, msg.time_usec)
        done = self.done.get(key)
        if done is not None:
            self.duplicates += 1
            self.done.move_to_end(key)
            ack, words = done
            return ack, ("" if ack.result in FINAL_OK else words)
        try:
            outcome = self.action(msg)
            result, words = (int(outcome[0]), str(outcome[1])) if isinstance(outcome, tuple) else (int(outcome), "")
        except Exception as e:
            result, words = int(TtResult.TT_RESULT_FAILED), f"the action failed: {type(e).__name__}: {e}"
        self.executed += 1
        ack = self.b.TtCommandAck(target_system=key[0], target_component=key[1], command_id=msg.command_id,
                                  action=msg.action, result=result, progress=100 if result != 1 else 0)
        self.done[key] = (ack, words)
        if len(self.done) > self.memory:
            self.done.popitem(last=False)
        return ack, words
