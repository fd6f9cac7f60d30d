"""The sans-IO protocol cores in virtual time, over the link model: file transfer (both ways,
loss, jail, quotas, resume, concurrency, disk full, downloads) and commands (retries without
double execution, failure after retries)."""

from __future__ import annotations

import itertools
import json
import os
import random
import shutil
import subprocess
from pathlib import Path
from typing import Any

import pytest

import ttapi
from conftest import ROOT, shipped
from ttctl.link.model import Channel, Impairments, load_profile
from ttctl.link.sim import Simulation
from ttctl.proto.endpoint import Endpoint
from ttctl.proto.names import Refused
from ttctl.proto.storage import BytesSource, Quota, ReceiveDir, check_name
from ttctl.proto.transfer import TransferConfig

TABLET, ONBOARD = (255, 190), (1, 240)


def accept(msg: Any) -> int:
    """A vehicle that carries out every command (nothing to do in these tests)."""
    return int(ttapi.TtResult.TT_RESULT_ACCEPTED)


def data(n: int, seed: int = 1) -> bytes:
    return random.Random(seed).randbytes(n)


class World:
    """A tablet and an onboard end over m100 (or lan) channels, with event logs."""

    def __init__(self, tmp: Path, loss: float = 0.0, model: str = "random", profile: str = "m100", seed: int = 1,
                 tablet_dir: Path | None = None, onboard_dir: Path | None = None, quota: Quota | None = None,
                 config: TransferConfig | None = None, serve: Path | None = None, action: Any = None,
                 outages: list[tuple[float, float]] | None = None, key: bytes | None = None) -> None:
        prof = load_profile(profile)
        imp: dict[str, Any] = {"loss": loss, "loss_model": model, "outages": outages or []}
        self.up = Channel(prof, "up", 10, Impairments(**imp), seed=seed)
        self.down = Channel(prof, "down", 10, Impairments(**imp), seed=seed + 100)
        self.events: list[tuple[str, Any]] = []
        cfg = config or TransferConfig()

        def log(what: str, obj: Any) -> None:
            self.events.append((what, obj))

        self.tablet = Endpoint(shipped(), *TABLET, rate_Bps=self.up.capacity_Bps(), config=cfg, on_event=log,
                               receive_dir=ReceiveDir(tablet_dir, quota) if tablet_dir else None,
                               rng=random.Random(seed), signing=ttapi.Signing(key) if key else None)
        self.onboard = Endpoint(shipped(), *ONBOARD, rate_Bps=self.down.capacity_Bps(), config=cfg, on_event=log,
                                rng=random.Random(seed + 1),
                                receive_dir=ReceiveDir(onboard_dir, quota) if onboard_dir else None,
                                serve_dir=str(serve) if serve else None, action=action,
                                signing=ttapi.Signing(key) if key else None)
        self.sim = Simulation(self.tablet, self.onboard, self.up, self.down)

    def run(self, until: float, stop: Any = None) -> float:
        t = self.sim.run(until, stop)
        self.tablet.now = self.onboard.now = t
        return t

    def event(self, what: str) -> list[Any]:
        return [o for w, o in self.events if w == what]


@pytest.mark.parametrize(("direction", "loss", "model"), [("up", 0.1, "random"), ("down", 0.3, "burst")])
def test_file_arrives_intact_both_ways_under_loss(tmp_path: Path, direction: str, loss: float, model: str) -> None:
    payload = data(12_000)
    w = World(tmp_path, loss, model, onboard_dir=tmp_path / "on" if direction == "up" else None,
              tablet_dir=tmp_path / "tab" if direction == "down" else None)
    sender, target, where = ((w.tablet, ONBOARD, tmp_path / "on") if direction == "up"
                             else (w.onboard, TABLET, tmp_path / "tab"))
    s = sender.send_file("m.yaml", target, source=BytesSource(payload, "m.yaml"))
    w.run(600, stop=lambda: s.done)
    assert s.result is not None and s.result.ok, s.result
    assert (where / "m.yaml").read_bytes() == payload
    assert not any((where / ".ttctl-partial").glob("*.part"))
    assert s.stats.bytes_retransmitted > 0  # the loss was real


def test_check_name_accepts_plain_relative_paths() -> None:
    assert check_name("missions/day1/route.yaml") == "missions/day1/route.yaml"
    assert check_name("ünïcode.txt") == "ünïcode.txt"
    assert check_name("x" * 223) == "x" * 223


NAME_VECTORS = json.loads((ROOT / "tests" / "data" / "names.json").read_text(encoding="utf-8"))["names"]


@pytest.mark.parametrize("case", NAME_VECTORS, ids=[c["what"] for c in NAME_VECTORS])
def test_name_rules_shared_vectors(case: dict[str, Any]) -> None:
    """tests/data/names.json, the name vectors every runtime's tests read (the C++ node's in
    test_cpp_node_hostile.py): what the receiver decides of the name bytes an offer carries
    (strict UTF-8, then check_name), in the same words."""
    raw = bytes.fromhex(case["hex"])
    try:
        name = raw.decode("utf-8")
    except UnicodeDecodeError:
        assert case["refused"] == "the name is not valid UTF-8"
        return
    try:
        check_name(name)
        said = None
    except Refused as e:
        assert e.code == "NAME"
        said = e.reason
    assert said == case["refused"]


def test_a_keyed_control_frame_replaces_only_a_queued_frame_of_its_key() -> None:
    """A newer status replaces the one of its key still waiting, and nothing else. (Keys once
    tracked the queued frame's id(): once a keyed frame had left and been freed, CPython could
    give its id to a new, unrelated frame, an ack say, which the next frame of that key then
    replaced. Found by the C++ scheduler's differential test; an object queued twice shows it.)"""
    from ttctl.proto.scheduler import CONTROL, Scheduler

    s = Scheduler(100)
    status = bytes(30)
    s.send(status, CONTROL, key=("status", 1))
    assert s.next_packet(0.0) == status
    s.send(status, CONTROL)  # the same object, unkeyed now: its id is the one the key saw
    s.send(b"\x01" * 30, CONTROL, key=("status", 1))
    assert s.next_packet(0.0) == status + b"\x01" * 30
    s.send(b"\x02" * 20, CONTROL, key=("status", 2))
    s.send(b"\x03" * 20, CONTROL, key=("status", 2))  # replaces the queued one of its key
    assert s.next_packet(0.0) == b"\x03" * 20


def test_no_silent_overwrite(tmp_path: Path) -> None:
    on = tmp_path / "on"
    on.mkdir()
    (on / "m.yaml").write_bytes(b"original")
    w = World(tmp_path, onboard_dir=on)
    s = w.tablet.send_file("m.yaml", ONBOARD, source=BytesSource(b"new contents", "m.yaml"))
    w.run(60, stop=lambda: s.done)
    assert s.result is not None and s.result.code == "REFUSED_EXISTS"
    assert s.result.message == "m.yaml exists and overwriting is not allowed here"  # the receiver's words
    assert s.stats.bytes_sent == 0  # refused at the offer: no data moved
    assert (on / "m.yaml").read_bytes() == b"original"
    # a directory that allows overwriting, and a sender that asks
    w2 = World(tmp_path, onboard_dir=on, quota=Quota(overwrite=True))
    s2 = w2.tablet.send_file("m.yaml", ONBOARD, overwrite=True, source=BytesSource(b"new contents", "m.yaml"))
    w2.run(60, stop=lambda: s2.done)
    assert s2.result is not None and s2.result.ok
    assert (on / "m.yaml").read_bytes() == b"new contents"


def test_quotas(tmp_path: Path) -> None:
    w = World(tmp_path, onboard_dir=tmp_path / "on", quota=Quota(max_file_bytes=1000, max_dir_bytes=1500))
    big = w.tablet.send_file("big", ONBOARD, source=BytesSource(data(1001), "big"))
    w.run(60, stop=lambda: big.done)
    assert big.result is not None and big.result.code == "REFUSED_QUOTA"
    first = w.tablet.send_file("a", ONBOARD, source=BytesSource(data(900), "a"))
    w.run(120, stop=lambda: first.done)
    second = w.tablet.send_file("b", ONBOARD, source=BytesSource(data(900, 2), "b"))
    w.run(240, stop=lambda: second.done)
    assert first.result and first.result.ok
    assert second.result is not None and second.result.code == "REFUSED_QUOTA"


def test_partial_file_is_never_visible_under_its_name(tmp_path: Path) -> None:
    on = tmp_path / "on"
    payload = data(6000)
    w = World(tmp_path, onboard_dir=on)
    s = w.tablet.send_file("m.bin", ONBOARD, source=BytesSource(payload, "m.bin"))
    t = 0.0
    looked = 0
    while not s.done:
        t += 0.5
        w.run(t, stop=lambda: s.done)
        final = on / "m.bin"
        if final.exists():  # whenever the name exists, it holds the whole verified file
            assert final.read_bytes() == payload
        else:
            looked += 1
    assert looked > 5 and (on / "m.bin").read_bytes() == payload


def test_resume_after_both_ends_restart(tmp_path: Path) -> None:
    on = tmp_path / "on"
    payload = data(20_000)
    w = World(tmp_path, onboard_dir=on)
    s = w.tablet.send_file("big.bin", ONBOARD, source=BytesSource(payload, "big.bin"))
    w.run(25)  # about half of it at 500 B/s
    assert not s.done and s.acked_bytes > 5000
    w.tablet.close()
    w.onboard.close()  # both ends go away; the partial state stays on disk
    assert not (on / "big.bin").exists() and list((on / ".ttctl-partial").glob("*.json"))
    w2 = World(tmp_path, onboard_dir=on, seed=2)
    s2 = w2.tablet.send_file("big.bin", ONBOARD, source=BytesSource(payload, "big.bin"))
    w2.run(600, stop=lambda: s2.done)
    assert s2.result is not None and s2.result.ok
    assert (on / "big.bin").read_bytes() == payload
    assert s2.stats.bytes_sent < len(payload) * 0.8  # resumed: only the rest (plus the first RTT) was sent
    assert s2.stats.resumed_bytes > 5000


def test_channel_outage_drops_everything_inside_the_window() -> None:
    ch = Channel(load_profile("lan"), "up", 10, Impairments(loss=0.0, outages=[(1.0, 2.0)]))
    arrived = [bool(ch.submit(t / 10, bytes(50))) for t in range(50)]  # one packet every 0.1 s for 5 s
    assert arrived[:10] == [True] * 10
    assert not any(arrived[10:30])
    assert all(arrived[31:])
    assert ch.stats.lost == 20


def test_transfer_rides_out_an_outage(tmp_path: Path) -> None:
    """The radio goes dark both ways for 20 s mid-file (out of range, a turn behind a building):
    nothing is given up, and sending resumes from where the receiver got to."""
    payload = data(20_000)
    w = World(tmp_path, onboard_dir=tmp_path / "on", outages=[(15.0, 20.0)])
    s = w.tablet.send_file("m.bin", ONBOARD, source=BytesSource(payload, "m.bin"))
    w.run(600, stop=lambda: s.done)
    assert s.result is not None and s.result.ok, s.result
    assert (tmp_path / "on" / "m.bin").read_bytes() == payload
    assert 20_000 / 500 + 20 <= s.result.seconds <= 20_000 / 500 + 20 + 15
    assert w.up.stats.lost > 0 and w.down.stats.lost > 0


def test_outage_longer_than_the_patience_fails_then_resumes(tmp_path: Path) -> None:
    payload = data(20_000)
    cfg = TransferConfig(give_up_after=10.0)
    w = World(tmp_path, onboard_dir=tmp_path / "on", outages=[(15.0, 1000.0)], config=cfg)
    s = w.tablet.send_file("m.bin", ONBOARD, source=BytesSource(payload, "m.bin"))
    w.run(600, stop=lambda: s.done)
    assert s.result is not None and s.result.code == "TIMEOUT"
    assert 24.0 <= s.result.seconds <= 40.0  # the last word came just before the outage, at 15 s
    assert not (tmp_path / "on" / "m.bin").exists()
    w.tablet.close()
    w.onboard.close()
    w2 = World(tmp_path, onboard_dir=tmp_path / "on", config=cfg)  # back in range
    s2 = w2.tablet.send_file("m.bin", ONBOARD, source=BytesSource(payload, "m.bin"))
    w2.run(600, stop=lambda: s2.done)
    assert s2.result is not None and s2.result.ok
    assert (tmp_path / "on" / "m.bin").read_bytes() == payload
    assert s2.stats.resumed_bytes >= 5000


def test_several_transfers_at_once(tmp_path: Path) -> None:
    w = World(tmp_path, loss=0.05, onboard_dir=tmp_path / "on", tablet_dir=tmp_path / "tab")
    files = {f"f{i}.bin": data(3000 + 500 * i, i) for i in range(3)}
    senders = [w.tablet.send_file(n, ONBOARD, source=BytesSource(b, n)) for n, b in files.items()]
    down = w.onboard.send_file("result.csv", TABLET, source=BytesSource(data(4000, 9), "result.csv"))
    w.run(600, stop=lambda: all(s.done for s in [*senders, down]))
    assert all(s.result and s.result.ok for s in [*senders, down])
    for n, b in files.items():
        assert (tmp_path / "on" / n).read_bytes() == b
    assert (tmp_path / "tab" / "result.csv").read_bytes() == data(4000, 9)


def test_peer_that_never_answers_fails_cleanly(tmp_path: Path) -> None:
    w = World(tmp_path, config=TransferConfig(give_up_after=10.0))  # the onboard end has no receive dir
    s = w.tablet.send_file("x", ONBOARD, source=BytesSource(b"hello", "x"))
    w.run(60, stop=lambda: s.done)
    assert s.result is not None and s.result.code == "TIMEOUT" and "no answer" in s.result.message


def test_source_that_never_matches_its_sha256_fails_the_checksum_after_two_fresh_starts(tmp_path: Path) -> None:
    class Fickle(BytesSource):
        def read(self, offset: int, length: int) -> bytes:
            chunk = super().read(offset, length)
            return bytes(b ^ 1 for b in chunk) if offset == 0 else chunk

    on = tmp_path / "on"
    w = World(tmp_path, onboard_dir=on)
    s = w.tablet.send_file("x.bin", ONBOARD, source=Fickle(data(2000), "x.bin"))
    w.run(120, stop=lambda: s.done)
    assert s.result is not None and s.result.code == "FAILED_CHECKSUM"
    assert s.stats.restarts == 2
    assert "differs from the offer" in s.result.message
    assert not (on / "x.bin").exists() and not list((on / ".ttctl-partial").glob("*.part"))


def test_bytes_corrupted_once_are_healed_by_a_fresh_start(tmp_path: Path) -> None:
    """A corruption the CRC-16 let through (1 in 65536 corrupted frames) or a flaky read: the
    receiver discards what it had and the sender starts again under a new id, once."""
    class Once(BytesSource):
        spoiled = False

        def read(self, offset: int, length: int) -> bytes:
            chunk = super().read(offset, length)
            if offset == 0 and not self.spoiled:
                self.spoiled = True
                return bytes(b ^ 0x40 for b in chunk)
            return chunk

    on = tmp_path / "on"
    payload = data(3000)
    w = World(tmp_path, onboard_dir=on)
    s = w.tablet.send_file("x.bin", ONBOARD, source=Once(payload, "x.bin"), compress=False)  # spoil the first send
    first_id = s.id
    w.run(120, stop=lambda: s.done)
    assert s.result is not None and s.result.ok, s.result
    assert s.stats.restarts == 1 and s.id != first_id
    assert (on / "x.bin").read_bytes() == payload


def test_download_on_request_and_not_found(tmp_path: Path) -> None:
    serve = tmp_path / "results"
    serve.mkdir()
    (serve / "log.csv").write_bytes(data(5000, 4))
    w = World(tmp_path, tablet_dir=tmp_path / "tab", serve=serve)
    (serve / "sub").mkdir()
    (serve / "away").symlink_to(tmp_path)
    req = w.tablet.request_file("log.csv", ONBOARD)
    w.run(120, stop=lambda: bool(w.event("file-complete")))
    assert (tmp_path / "tab" / "log.csv").read_bytes() == data(5000, 4)
    assert req.answered and req.error is None
    asks = {name: w.tablet.request_file(name, ONBOARD) for name in ("nope.csv", "sub", "away/x")}
    w.run(w.sim.now + 30, stop=lambda: all(r.error is not None for r in asks.values()))
    # the server's own reasons, not a guess from the code
    assert (asks["nope.csv"].code, asks["nope.csv"].error) == ("NOT_FOUND", "there is no nope.csv in the served folder")
    assert (asks["sub"].code, asks["sub"].error) == ("REQUEST_REFUSED", "sub is a directory, not a file")
    assert (asks["away/x"].code, asks["away/x"].error) == ("REQUEST_REFUSED", "away/x leads outside the served folder")
    with pytest.raises(ValueError, match="absolute paths are not allowed"):
        w.tablet.request_file("/etc/passwd", ONBOARD)


def test_garbage_and_foreign_traffic_are_ignored(tmp_path: Path) -> None:
    on = tmp_path / "on"
    w = World(tmp_path, onboard_dir=on)
    rng = random.Random(3)
    for _ in range(200):
        w.onboard.receive(0.0, rng.randbytes(rng.randint(0, 100)))
    other = ttapi.Encoder(9, 9).encode(ttapi.TtActionCommand(target_system=77, command_id=5, action=1))
    w.onboard.receive(0.0, other)
    assert w.onboard.server is not None and w.onboard.server.executed == 0 and w.onboard.ignored >= 1
    s = w.tablet.send_file("ok.bin", ONBOARD, source=BytesSource(b"still works", "ok.bin"))
    w.run(60, stop=lambda: s.done)
    assert s.result is not None and s.result.ok


def test_commands_retry_without_running_twice(tmp_path: Path) -> None:
    ran: list[int] = []

    def action(msg: ttapi.TtActionCommand) -> int:
        ran.append(msg.command_id)
        return int(ttapi.TtResult.TT_RESULT_ACCEPTED)

    w = World(tmp_path, loss=0.4, action=action)
    done: list[Any] = []
    cmds = [w.tablet.command(ttapi.TtActionCommand(action=int(ttapi.TtAction.TT_ACTION_HOVER)), ONBOARD, retries=8,
                             timeout=1.0, on_success=done.append, on_failure=done.append) for _ in range(20)]
    w.run(600, stop=lambda: all(c.done for c in cmds))
    assert len(done) == 20  # every command ended, exactly once
    assert sorted(ran) == sorted(set(ran))  # no command ran twice
    assert w.onboard.server is not None and w.onboard.server.duplicates > 0  # retries did arrive
    assert sum(c.ok for c in cmds) >= 18


def test_commands_fail_after_retries_and_on_refusal(tmp_path: Path) -> None:
    w = World(tmp_path, action=lambda msg: int(ttapi.TtResult.TT_RESULT_DENIED))
    failed: list[Any] = []
    denied = w.tablet.command(ttapi.TtActionCommand(action=0), ONBOARD, on_failure=failed.append)
    lost = w.tablet.command(ttapi.TtActionCommand(action=0), (42, 1), retries=2, timeout=0.5,
                            on_failure=failed.append)
    w.run(60, stop=lambda: denied.done and lost.done)
    assert denied.error == "refused: DENIED"
    assert lost.error is not None and "no ack after 3 tries" in lost.error
    assert len(failed) == 2


def test_a_command_is_not_queued_behind_a_file(tmp_path: Path) -> None:
    w = World(tmp_path, onboard_dir=tmp_path / "on", action=accept)
    w.tablet.send_file("bulk.bin", ONBOARD, source=BytesSource(data(40_000), "bulk.bin"))
    w.run(30)
    cmd = w.tablet.command(ttapi.TtActionCommand(action=int(ttapi.TtAction.TT_ACTION_LAND)), ONBOARD)
    w.run(60, stop=lambda: cmd.done)
    assert cmd.ok and cmd.latency is not None
    # at most the packet on the air (0.2 s at 500 B/s) plus the command's own round trip
    assert cmd.latency < 0.2 + 0.3



class _Filler:
    """A bulk source that always has a 90-byte frame (a ground station's uplink, say)."""

    def pull(self, now: float, space: int) -> bytes:
        return bytes(90)

    def has_data(self, now: float) -> bool:
        return True

    def deadline(self, now: float) -> None:
        return None


@pytest.mark.parametrize("offset", [0.0, 0.03, 0.07, 0.11, 0.16])
def test_a_commands_copy_and_retry_do_not_wait_behind_bulk(offset: float) -> None:
    """A command's first try may wait for the packet on the air; the copy (0.5 s later on the
    M100's uplink) and the retry (1.5 s) go at their time: bulk packets before them are cut to
    leave the radio by then, and the link is not left idle for it."""
    ep = Endpoint(shipped(), *TABLET, rate_Bps=500.0)
    ep.add_stream(_Filler())
    sent: list[tuple[float, bytes]] = []
    cmd = None
    t, start = 0.0, 1.0 + offset
    while t < 4.0:
        if cmd is None and t >= start:
            cmd = ep.command(ttapi.TtActionCommand(action=int(ttapi.TtAction.TT_ACTION_HOVER)), ONBOARD)
        pkt = ep.poll(t)
        if pkt:
            sent.append((t, pkt))
            continue
        nxt = ep.wakeup()
        assert nxt is not None
        t = max(nxt, t) if nxt > t else t + 1e-4  # (never a spin at one time)
        if cmd is None:
            t = min(t, start)
    assert cmd is not None and cmd.sent_at[0] == pytest.approx(start)
    tries = [at for at, pkt in sent if pkt[0] == 0xFD]  # control frames go first in their packet
    assert len(tries) == 3, tries
    assert tries[0] - start <= 90 / 500 + 1e-6  # the packet on the air
    assert tries[1] == pytest.approx(start + 0.5, abs=1e-6)  # the copy
    assert tries[2] == pytest.approx(start + 1.5, abs=1e-6)  # the retry
    filler = sum(len(pkt) for at, pkt in sent if pkt[0] != 0xFD)
    assert filler >= 0.95 * 500 * 4.0 - sum(len(pkt) for at, pkt in sent if pkt[0] == 0xFD) - 100

def _tmpfs(path: Path, size: str) -> bool:
    if os.geteuid() != 0 or shutil.which("mount") is None:
        return False
    path.mkdir(parents=True, exist_ok=True)
    return subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs", str(path)],
                          capture_output=True).returncode == 0


def test_full_disk_stops_cleanly_and_resumes(tmp_path: Path) -> None:
    disk = tmp_path / "small"
    if not _tmpfs(disk, "64k"):
        pytest.skip("cannot mount a small tmpfs here (needs root)")
    try:
        payload = data(120_000)
        w = World(tmp_path, onboard_dir=disk, profile="lan")
        s = w.tablet.send_file("huge.bin", ONBOARD, source=BytesSource(payload, "huge.bin"))
        w.run(120, stop=lambda: s.done)
        assert s.result is not None and s.result.code == "FAILED_DISK_FULL"
        assert not (disk / "huge.bin").exists()
        state = list((disk / ".ttctl-partial").glob("*.json"))
        assert state, "the partial state is kept for a resume"
    finally:
        subprocess.run(["umount", str(disk)], capture_output=True)


def test_a_new_process_reusing_a_command_id_is_not_answered_with_the_old_ack(tmp_path: Path) -> None:
    """Every process numbers its commands afresh: a second tablet process whose first command
    has the id an earlier one used must have its command run, not get the earlier ack."""
    from ttctl.proto.commands import Command, CommandClient, CommandServer

    ran: list[int] = []
    server = CommandServer(shipped(), 1, 240, action=lambda msg: ran.append(msg.action) or 0)
    take_off, land = int(ttapi.TtAction.TT_ACTION_TAKE_OFF), int(ttapi.TtAction.TT_ACTION_LAND)
    for action, clock in ((take_off, 1000.0), (land, 1060.0)):
        client = CommandClient(*TABLET, first_id=1, clock=lambda c=clock: c)  # both start at id 1
        cmd = client.submit(Command(ttapi.TtActionCommand(action=action), ONBOARD), 0.0)
        (msg,) = client.control(0.0)
        wire = ttapi.decode(ttapi.Encoder(*TABLET).encode(msg))
        ack = server.on_command(wire)
        assert ack is not None and ack.command_id == 1
        assert server.on_command(wire) is ack  # the retry of that very command: the same ack, not run again
        assert cmd.id == 1
    assert ran == [take_off, land]


def test_a_signed_link_loses_nothing_to_its_own_reordering(tmp_path: Path) -> None:
    """Priorities reorder frames (commands overtake telemetry and file data, statuses replace
    older ones) and a long TT_FILE_DATA_WIDE frame spans packets: with signing, every frame is
    signed as it is placed, and nothing is slipped between a long frame's pieces, so the
    receiver's replay check never refuses one of ours."""
    key = bytes(range(32))
    w = World(tmp_path, onboard_dir=tmp_path / "on", tablet_dir=tmp_path / "tab", key=key, action=accept)
    up, down = data(20_000, 3), data(30_000, 4)
    s1 = w.tablet.send_file("up.bin", ONBOARD, source=BytesSource(up, "up.bin"))
    s2 = w.onboard.send_file("down.bin", TABLET, source=BytesSource(down, "down.bin"))
    cmds = []
    for k in range(12):
        w.run(0.25 * (k + 1))
        cmds.append(w.tablet.command(ttapi.TtActionCommand(action=int(ttapi.TtAction.TT_ACTION_HOVER)), ONBOARD))
        w.onboard.send_message(ttapi.Statustext(severity=6, text=f"note {k}"))
    w.run(300, stop=lambda: s1.done and s2.done and all(c.done for c in cmds))
    assert s1.result is not None and s1.result.ok and s2.result is not None and s2.result.ok
    assert (tmp_path / "on" / "up.bin").read_bytes() == up and (tmp_path / "tab" / "down.bin").read_bytes() == down
    assert all(c.ok for c in cmds)
    assert s1.stats.wide_frames > 0  # long frames did span packets
    for ep in (w.tablet, w.onboard):
        stats = [rx.stats for rx in ep._rxs.values()]
        assert stats and sum(st.frames for st in stats) > 100
        assert sum(st.bad_frames for st in stats) == 0, [st.as_dict() for st in stats]


def test_a_flood_of_incomplete_offers_does_not_lock_real_senders_out(tmp_path: Path) -> None:
    """Offers whose metadata never completes take at most MAX_PENDING_OFFERS places, the stalest
    going first: a real sender right after a flood of 400 is answered (it used to be dropped
    until the flood was forgotten, 120 s later)."""
    from ttctl.proto.receiver import MAX_PENDING_OFFERS

    on = tmp_path / "on"
    w = World(tmp_path, onboard_dir=on)
    enc = ttapi.Encoder(*TABLET)
    for i in range(400):
        w.onboard.receive(0.0, enc.encode(ttapi.TtFileOffer(
            target_system=ONBOARD[0], target_component=ONBOARD[1], transfer_id=1000 + i, size=10,
            meta_length=200, meta_offset=0, meta=b"\x01" * 71)))
    rx = w.onboard.receiver
    assert rx is not None and sum(not t.decided for t in rx.transfers.values()) <= MAX_PENDING_OFFERS
    assert rx.evicted == 400 - MAX_PENDING_OFFERS
    s = w.tablet.send_file("real.bin", ONBOARD, source=BytesSource(b"after the flood", "real.bin"))
    w.run(10, stop=lambda: s.done)
    assert s.result is not None and s.result.ok and (on / "real.bin").read_bytes() == b"after the flood"


def test_a_flood_of_incomplete_requests_is_bounded(tmp_path: Path) -> None:
    """TT_FILE_REQUEST names that never complete are kept for at most MAX_PARTIAL_REQUESTS
    requests (memory grew with every one), and a real request after them is served."""
    from ttctl.proto.fetches import MAX_PARTIAL_REQUESTS

    serve = tmp_path / "serve"
    serve.mkdir()
    (serve / "log.txt").write_bytes(b"served")
    w = World(tmp_path, tablet_dir=tmp_path / "tab", serve=serve)
    enc = ttapi.Encoder(*TABLET)
    for i in range(2000):
        w.onboard.receive(0.0, enc.encode(ttapi.TtFileRequest(
            target_system=ONBOARD[0], target_component=ONBOARD[1], request_id=1 + i, name_length=200,
            name_offset=0, name=b"x" * 80)))
    assert len(w.onboard.serving.partial) <= MAX_PARTIAL_REQUESTS
    got = tmp_path / "tab" / "log.txt"
    w.tablet.request_file("log.txt", ONBOARD)
    w.run(10, stop=got.exists)
    assert got.read_bytes() == b"served"


def test_a_duplicated_signed_packet_is_not_called_a_wrong_key(tmp_path: Path) -> None:
    """A replayed timestamp (a duplicated packet, a replay) is refused but is not reported as
    'frames whose signatures do not verify' (the same --key at both ends?); another key is."""
    key = bytes(range(32))
    w = World(tmp_path, onboard_dir=tmp_path / "on", key=key)
    frame = ttapi.Encoder(*TABLET, signing=ttapi.Signing(key)).encode(ttapi.Heartbeat())
    w.onboard.receive(0.0, frame, source="a")
    w.onboard.receive(0.0, frame, source="a")  # the same packet again
    assert not w.event("link-refused")
    other = ttapi.Encoder(*TABLET, signing=ttapi.Signing(bytes(32))).encode(ttapi.Heartbeat())
    w.onboard.receive(0.0, other, source="b")
    assert w.event("link-refused") == [("b", "frames whose signatures do not verify")]


def test_an_end_that_carries_out_no_commands_accepts_none(tmp_path: Path) -> None:
    """Without an action (ttctl recv-file, send-file) a command is answered UNSUPPORTED: an
    ACCEPTED would promise what nothing here does (it used to say ACCEPTED)."""
    w = World(tmp_path)
    c = w.tablet.command(ttapi.TtActionCommand(action=int(ttapi.TtAction.TT_ACTION_TAKE_OFF)), ONBOARD)
    w.run(10, stop=lambda: c.done)
    assert c.done and not c.ok and c.ack is not None
    assert c.ack.result == int(ttapi.TtResult.TT_RESULT_UNSUPPORTED) and c.error == "refused: UNSUPPORTED"


def test_a_refusals_words_are_recorded_and_repeated_with_its_ack() -> None:
    """The action's words go ahead of its ack; a retry gets a refusal's words again with the
    recorded ack (they may be what was lost), an acceptance's words only once; nothing runs twice."""
    from ttctl.proto.commands import CommandServer

    ran: list[int] = []

    def action(msg: Any) -> Any:
        ran.append(msg.action)
        return (4, "refused: not flying") if msg.action == 1 else (0, "taking off")

    server = CommandServer(shipped(), 1, 240, action=action)
    enc = ttapi.Encoder(*TABLET)
    land = ttapi.decode(enc.encode(ttapi.TtActionCommand(target_system=1, command_id=5, time_usec=9, action=1)))
    up = ttapi.decode(enc.encode(ttapi.TtActionCommand(target_system=1, command_id=6, time_usec=9, action=0)))
    ack, words = server.answer(land)
    assert ack.result == 4 and words == "refused: not flying"
    assert server.answer(land) == (ack, "refused: not flying")
    ack, words = server.answer(up)
    assert ack.result == 0 and words == "taking off"
    assert server.answer(up) == (ack, "")
    assert ran == [1, 0]
    bare = CommandServer(shipped(), 1, 240)
    ack, words = bare.answer(land)
    assert ack.result == int(ttapi.TtResult.TT_RESULT_UNSUPPORTED) and words == "no commands are carried out here"


def test_a_deadline_met_exactly_is_acted_on_whatever_the_float_rounding(tmp_path: Path) -> None:
    """`now - a >= b` can be false at now == a + b ((124.31526306379114 + 30) - 124.31526306379114
    is less than 30): an end that computes its deadline as a + b and checks it as
    now - a >= b asks to wake at `now` for ever and does nothing (`bench transfer --profile lan`
    stopped there: "simulation stuck"). Each check compares as its deadline adds."""
    a = 124.31526306379114
    assert (a + 30.0) - a < 30.0  # the trap is real
    w = World(tmp_path, onboard_dir=tmp_path / "in", outages=[(1.0, 1e9)],
              config=TransferConfig(give_up_after=30.0, idle_timeout=30.0))
    s = w.tablet.send_file("x", ONBOARD, source=BytesSource(data(20_000), "x"))
    w.run(0.9)
    assert w.onboard.receiver is not None and w.onboard.receiver.transfers, "the offer arrived"
    for t in w.onboard.receiver.transfers.values():
        t.last_activity = a  # silent since a: forgotten at a + idle_timeout
    s.last_progress = s.last_heard = a  # no progress since a: gives up at a + give_up_after
    w.run(400, stop=lambda: s.done and not w.onboard.receiver.transfers)  # type: ignore[union-attr]
    assert s.done and s.result is not None and s.result.code == "TIMEOUT"
    assert not w.onboard.receiver.transfers


def test_complete_is_said_again_shortly_so_a_receiver_that_exits_is_still_heard(tmp_path: Path) -> None:
    """A receiver process may end right after its file is complete (`send-file --from` drains a
    moment and exits): its COMPLETE status goes three times, 50 ms apart, so one lost packet does
    not leave the sender (a server) recording a delivered, verified file as failed when the next
    process on that port refuses its probe."""
    w = World(tmp_path, onboard_dir=tmp_path / "on")
    rx = w.onboard.receiver
    assert rx is not None
    said: list[float] = []
    real = rx.control

    def spy(now: float) -> list[tuple[Any, object]]:
        out = real(now)
        said.extend(now for m, _ in out if type(m).__name__ == "TtFileStatus"
                    and m.result == ttapi.TtFileResult.TT_FILE_RESULT_COMPLETE)
        return out

    rx.control = spy  # type: ignore[method-assign]
    s = w.tablet.send_file("a.bin", ONBOARD, source=BytesSource(b"x" * 500, "a.bin"))
    end = w.run(60, stop=lambda: s.done)
    assert s.result is not None and s.result.ok
    w.run(end + 2.0)
    assert len(said) == 3, said
    assert all(b - a >= 0.05 - 1e-9 for a, b in itertools.pairwise(said)), said
