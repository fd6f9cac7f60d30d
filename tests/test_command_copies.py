"""A command's copy (proto/commands.py): on a slow link a TT_ACTION_COMMAND whose ack has not come
two and a half packets' time after it (or a smoothed round trip, if longer) goes once more, so a
packet the link or a full radio buffer lost costs the command the copy's delay, not the 1.5 s
retry; the vehicle answers the copy as a retry and runs nothing twice. The client's schedule
sans-IO, then the M100 link in virtual time (the same seeded losses with and without copies)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import ttapi
from test_proto import ONBOARD, TABLET, World
from ttapi.mavlink import Encoder, Parser
from ttctl.bench.latency import percentile
from ttctl.proto.commands import Command, CommandClient
from ttctl.proto.endpoint import COPY_PACKETS


def hover() -> Any:
    return ttapi.TtActionCommand(action=int(ttapi.TtAction.TT_ACTION_HOVER))


def test_the_copy_goes_once_between_the_first_try_and_the_retry() -> None:
    c = CommandClient(*TABLET, first_id=5)
    cmd = c.submit(Command(hover(), ONBOARD, retries=2, timeout=1.5, copy_after=0.3), 10.0)
    assert c.control(10.0) == [cmd.msg] and c.deadline() == 10.3
    assert c.control(10.29) == []
    assert c.control(10.3) == [cmd.msg] and cmd.copies == 1 and cmd.sent_at == [10.0]  # a copy, not a try
    assert c.deadline() == 11.5 and c.control(11.0) == []
    assert c.control(11.5) == [cmd.msg] and cmd.sent_at == [10.0, 11.5]  # the retry: no copy after it
    assert c.control(11.9) == [] and c.deadline() == 14.5 and cmd.copies == 1


def test_no_copy_once_answered_or_when_the_retry_comes_first() -> None:
    c = CommandClient(*TABLET, first_id=5)
    answered = c.submit(Command(hover(), ONBOARD, timeout=1.5, copy_after=0.3), 0.0)
    late = c.submit(Command(hover(), ONBOARD, timeout=0.5, copy_after=0.6), 0.0)  # its retry is due first
    plain = c.submit(Command(hover(), ONBOARD, timeout=1.5), 0.0)  # none asked
    assert len(c.control(0.0)) == 3
    frame = Encoder(sysid=ONBOARD[0], compid=ONBOARD[1]).encode(ttapi.TtCommandAck(
        target_system=TABLET[0], target_component=TABLET[1], command_id=answered.id,
        result=int(ttapi.TtResult.TT_RESULT_ACCEPTED)))
    (ack,) = Parser().feed(frame)  # as it arrives, from the vehicle
    assert c.on_ack(0.2, ack) is answered and answered.ok
    assert c.control(0.45) == []
    assert c.control(0.5) == [late.msg] and late.copies == 0 and len(late.sent_at) == 2
    assert c.control(1.0) == [] and plain.copies == 0


def run_commands(tmp: Path, copies: bool, n: int = 60) -> tuple[list[float], list[Command], World]:
    """`n` HOVERs one after another over the M100 link at 10 % random loss (seeded): their
    latencies, the commands and the world."""
    w = World(tmp, loss=0.1, seed=4, action=lambda msg: int(ttapi.TtResult.TT_RESULT_ACCEPTED))
    if not copies:
        w.tablet._copy_after = None
    latencies: list[float] = []
    cmds: list[Command] = []
    for _ in range(n):
        cmd = w.tablet.command(hover(), ONBOARD, retries=6, timeout=1.5)
        w.run(w.tablet.now + 60, stop=lambda c=cmd: c.done)
        assert cmd.ok, cmd.error
        latencies.append(cmd.latency or 0.0)
        cmds.append(cmd)
        w.run(w.tablet.now + 0.5)
    return latencies, cmds, w


def test_copies_cut_what_a_lost_command_costs_on_the_m100_link(tmp_path: Path) -> None:
    """Measured here: idle round trip 0.165 s; without copies 10 of 60 commands took 1.66 s (a
    retry) and one 4.66 s; with copies those 10 took about 0.67 s (the copy) and the one 1.66 s."""
    with_copies, cmds, w = run_commands(tmp_path / "a", copies=True)
    without, cmds0, w0 = run_commands(tmp_path / "b", copies=False)
    copy_after = COPY_PACKETS * 100 / w.up.capacity_Bps()
    assert w.tablet._copy_after == copy_after == 0.5
    slow = [x for x in without if x > 1.5]  # lost on the way or its ack lost: the retry answered
    assert len(slow) >= 4, without  # 10 % each way: about one in five
    # with copies, a command whose first frame or ack was lost is answered after the copy, long
    # before a retry would be; only one whose copy was lost too waits for the retry
    assert sum(x > 1.5 for x in with_copies) <= len(slow) // 2, (with_copies, without)
    assert percentile(with_copies, 0.9) < 1.0 < percentile(without, 0.9), (with_copies, without)
    # a copy goes exactly when no ack came within its delay (at least 0.5 s; longer when the
    # smoothed round trip says so): an answered command costs nothing more
    assert all(c.copy_delay is not None and c.copy_delay >= copy_after for c in cmds)
    assert [c.copies for c in cmds] == [int(c.latency is not None and c.latency > c.copy_delay) for c in cmds]
    assert not any(c.copies for c in cmds0)
    for world, sent in ((w, cmds), (w0, cmds0)):  # nothing ran twice: a copy is answered as a retry
        server = world.onboard.server
        assert server is not None and server.executed == 60
        assert server.duplicates <= sum(c.copies + len(c.sent_at) - 1 for c in sent)
