"""The baselines of `ttctl bench transfer`: the thesis file transfer and pymavlink's MAVLink FTP
put, in virtual time over the m100 link model."""

from __future__ import annotations

import importlib.util
import itertools
import random
import shutil
import struct
import threading
from pathlib import Path
from typing import Any

import pytest

import ttapi
from conftest import pymavlink_dialects, shipped
from ttctl.bench import baselines as bl
from ttctl.bench.transfer import ONBOARD, TABLET, Case, run_ttctl
from ttctl.link.model import load_profile
from ttctl.wire.packets import PacketReceiver, packetize

KIB16 = 16 * 1024
M100 = load_profile("m100")


def _data(seed: int = 5, n: int = KIB16) -> bytes:
    return random.Random(seed).randbytes(n)


# -- the thesis dialect --------------------------------------------------------------------------

def test_thesis_dialect_matches_reference() -> None:
    d = bl.thesis_dialect()
    assert (d.request.MSG_ID, d.ack.MSG_ID, d.part.MSG_ID, d.resend.MSG_ID) == (50000, 50001, 50002, 50003)
    assert d.part.PAYLOAD_LENGTH == 254  # target, file_id, u16 sequence, u8[250]
    assert d.resend.PAYLOAD_LENGTH == 6
    frame = ttapi.Encoder(*TABLET).encode(d.part(target_system=1, file_id=3, sequence=7, payload=bytes(range(1, 251))))
    assert len(frame) == 266
    assert [len(p) for p in packetize([frame])] == [100, 100, 66]


def test_thesis_frames_agree_with_pymavlink_mavgen(tmp_path: Path) -> None:
    """The run-time message classes (from ttctl's dialect model) against mavgen's bindings of
    the same XML: CRC_EXTRA, layout and truncation must agree byte for byte."""
    mavgen = pytest.importorskip("pymavlink.generator.mavgen")
    shutil.copy(bl.thesis_xml(), tmp_path / "dji_icg.xml")
    for name in ("common.xml", "standard.xml", "minimal.xml"):
        shutil.copy(pymavlink_dialects() / name, tmp_path / name)
    out = tmp_path / "dji_icg_pm.py"
    assert mavgen.mavgen(mavgen.Opts(str(out), wire_protocol="2.0", language="Python3", validate=False),
                         [str(tmp_path / "dji_icg.xml")])
    spec = importlib.util.spec_from_file_location("dji_icg_pm", out)
    assert spec is not None and spec.loader is not None
    pm = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(pm)
    assert pm.MAVLink_dji_pose_stamped_message.crc_extra == 70  # as in the thesis dialect

    d = bl.thesis_dialect()
    enc = ttapi.Encoder(*TABLET)
    mav = pm.MAVLink(None, srcSystem=TABLET[0], srcComponent=TABLET[1])
    mine = [d.request(target_system=1, file_size=123456, file_id=9, file_name=b"mission.yaml"),
            d.ack(target_system=255, file_id=9, result=0, progress=42),
            d.part(target_system=1, file_id=9, sequence=513, payload=bytes(range(1, 120))),
            d.resend(target_system=255, file_id=9, sequence_start=0xFFFF, sequence_end=0xFFFF)]
    theirs = [pm.MAVLink_dji_ftp_request_message(1, 123456, 9, list(b"mission.yaml".ljust(64, b"\0"))),
              pm.MAVLink_dji_ftp_request_ack_message(255, 9, 0, 42),
              pm.MAVLink_dji_ftp_message(1, 9, 513, list(bytes(range(1, 120)).ljust(250, b"\0"))),
              pm.MAVLink_dji_ftp_request_resend_message(255, 9, 0xFFFF, 0xFFFF)]
    for m, t in zip(mine, theirs, strict=True):
        assert d.registry[m.MSG_ID].crc_extra == t.crc_extra, m.NAME
        a = enc.encode(m)
        mav.seq = a[4]
        assert a == bytes(t.pack(mav)), m.NAME
        back = PacketReceiver(shipped(), registry=d.registry).feed(a)  # our receiver decodes mavgen's frames too
        assert len(back) == 1 and back[0].pack_payload() == m.pack_payload()


# -- both baselines deliver the file -------------------------------------------------------------

CASES = [Case("up", 0.0, "random"), Case("up", 0.1, "random"), Case("down", 0.0, "random"),
         Case("down", 0.1, "burst")]


@pytest.mark.parametrize("case", CASES, ids=lambda c: f"{c.direction}-{c.loss:.0%}-{c.loss_model}")
@pytest.mark.parametrize("runner", [bl.run_thesis, bl.run_mavftp], ids=["thesis", "mavftp"])
def test_baseline_delivers_16k(runner: Any, case: Case) -> None:
    data = _data()
    seconds, ok, lost = runner(M100, 10.0, case, data, 1)
    assert ok and (lost > 0) == (case.loss > 0)
    capacity = M100.capacity_Bps(case.direction, 10.0)
    assert len(data) / capacity < seconds < 3600  # never faster than the raw link


def test_limit_is_respected_and_nothing_is_left_running() -> None:
    before = threading.active_count()
    for runner in (bl.run_thesis, bl.run_mavftp):
        seconds, ok, _ = runner(M100, 10.0, Case("up", 0.1, "random"), _data(), 1, limit=5.0)
        assert (seconds, ok) == (5.0, False)
    assert threading.active_count() == before


@pytest.mark.parametrize("size", [0, 1, 250, 251])
def test_edge_sizes(size: int) -> None:
    data = _data(n=size)
    for runner in (bl.run_thesis, bl.run_mavftp):
        _, ok, _ = runner(M100, 10.0, Case("down", 0.0, "random"), data, 1)
        assert ok, runner.__name__


# -- the thesis protocol's defining behaviour ----------------------------------------------------

def test_thesis_waits_out_its_3s_timer_for_every_missing_range() -> None:
    case = Case("up", 0.1, "random")
    data = _data()
    r = bl.thesis_transfer(M100, 10.0, case, data, 1)
    assert r.ok
    log = r.stats["resend_log"]
    assert len(log) >= 5
    # each request asks for one range only, and only after 3 s without a part
    times = [t for t, _, _ in log]
    assert all(b - a >= bl.THESIS_TIMEOUT - 1e-9 for a, b in itertools.pairwise(times))
    assert all(0 <= a <= b < 66 for _, a, b in log)
    # most of the time the radio is idle: the sender waits for the receiver's timer
    assert _idle(r, "up") > 0.5
    # and its goodput is far below ttctl's on the same case, file and seed
    t_ttctl, ok, _ = run_ttctl(M100, 10.0, case, data, 1)
    assert ok
    assert r.seconds / t_ttctl >= 2.0
    down = Case("down", 0.1, "random")
    r_down = bl.thesis_transfer(M100, 10.0, down, data, 1)
    t_down, ok, _ = run_ttctl(M100, 10.0, down, data, 1)
    assert r_down.ok and ok
    assert _idle(r_down, "down") > 0.8
    assert r_down.seconds / t_down >= 4.0


def _idle(r: bl.BaselineRun, direction: str) -> float:
    """The share of the transfer's time the sender's radio had nothing to send."""
    part = sum(M100.direction(direction).service_time(n, 10.0) for n in (100, 100, 66))
    return 1 - r.stats["parts_sent"] * part / r.seconds


def test_thesis_lossless_is_one_pass_and_completion_reaches_the_sender() -> None:
    data = _data()
    r = bl.thesis_transfer(M100, 10.0, Case("up", 0.0, "random"), data, 1, until_sender_done=True)
    assert r.ok
    assert r.stats["sender_state"] == "done"  # it got the 0xFFFF..0xFFFF resend request
    assert r.stats["parts_sent"] == 66 and r.stats["resend_requests"] == 0
    assert r.stats["packets_sent"] == 1 + 3 * 65 + 2  # request, 65 full parts, the last part (134 bytes)
    # 66 parts of 3 packets paced at the link's capacity: the lossless time is the radio time
    assert r.seconds == pytest.approx(65 * (0.2 + 0.2 + 0.132) + 0.2 + 0.068 + 0.3, abs=0.5)


def test_thesis_receiver_fixes_the_original_defects() -> None:
    d = bl.thesis_dialect()
    rx = bl.ThesisReceiver(ONBOARD, None)
    enc = ttapi.Encoder(*TABLET)

    def feed(now: float, msg: Any) -> None:
        for p in packetize([enc.encode(msg)]):
            rx.receive(now, p)

    data = _data(n=600)  # 3 parts, the last one 100 bytes
    feed(0.0, d.request(target_system=1, file_size=600, file_id=4, file_name=b"a.yaml"))
    feed(0.1, d.part(target_system=1, file_id=4, sequence=2, payload=data[500:]))
    feed(0.2, d.part(target_system=1, file_id=4, sequence=9, payload=b"x" * 250))  # out of range: ignored
    feed(0.3, d.request(target_system=1, file_size=600, file_id=4, file_name=b"a.yaml"))  # a repeat: no reset
    assert rx.missing == 2
    rx.poll(3.2)  # the 3 s timer: ask for the first missing range only
    assert rx.resend_log == [(3.2, 0, 1)]
    feed(4.0, d.part(target_system=1, file_id=4, sequence=1, payload=data[250:500]))  # keeps its number
    feed(4.1, d.part(target_system=1, file_id=4, sequence=0, payload=data[:250]))
    assert rx.complete_at == 4.1 and rx.content == data
    done = PacketReceiver(shipped(), registry=d.registry)
    msgs = [m for p in list(rx.fifo) for m in done.feed(p)]
    assert (msgs[-1].sequence_start, msgs[-1].sequence_end) == (0xFFFF, 0xFFFF)


# -- MAVLink FTP as pymavlink does it ------------------------------------------------------------

def test_mavftp_uses_pymavlinks_client_and_defaults() -> None:
    r = bl.mavftp_transfer(M100, 10.0, Case("up", 0.0, "random"), _data(), 1, until_client_done=True)
    assert r.ok and r.stats["result"] == 0 and r.stats["attempts"] == 1
    used = r.stats["settings"]  # read back from pymavlink's MAVFTP instance
    assert used["write_size"] == 80 and used["write_qsize"] >= 1
    assert used == bl.mavftp_defaults()  # the class's defaults are its command line's
    ops = r.stats["ops_sent"]
    assert ops[2] == 1 and ops[6] == 1 and ops[1] == 1  # ResetSessions, CreateFile, TerminateSession
    # every 80-byte write is a 107-byte FILE_TRANSFER_PROTOCOL frame: two DTT packets
    frames = r.stats["write_frames"]
    assert frames[(80, 107, 2)] >= KIB16 // 80
    assert set(frames) == {(80, 107, 2), (KIB16 % 80, 12 + 12 + 3 + KIB16 % 80, 1)}
    writes = sum(frames.values())
    assert r.up["submitted"] == 2 * frames[(80, 107, 2)] + (writes - frames[(80, 107, 2)]) + 3


def test_mavftp_lockstep_is_slower_than_pymavlinks_window() -> None:
    data = _data()
    case = Case("up", 0.1, "random")
    windowed = bl.mavftp_transfer(M100, 10.0, case, data, 1)
    lockstep = bl.mavftp_transfer(M100, 10.0, case, data, 1, settings={"write_qsize": 1})
    assert windowed.ok and lockstep.ok
    assert lockstep.stats["settings"]["write_qsize"] == 1
    assert lockstep.seconds > windowed.seconds


def _ftp(seq: int, session: int, opcode: int, offset: int = 0, data: bytes = b"") -> ttapi.FileTransferProtocol:
    payload = struct.pack("<HBBBBBBI", seq, session, opcode, len(data), 0, 0, 0, offset) + data
    return ttapi.FileTransferProtocol(target_network=0, target_system=ONBOARD[0], target_component=ONBOARD[1],
                                      payload=payload.ljust(251, b"\0"))


def test_ftp_server_answers_like_ardupilot() -> None:
    from pymavlink import mavftp_op as op

    srv = bl.FtpServer(ONBOARD, None, b"hello world!")
    enc = ttapi.Encoder(*TABLET)
    replies = PacketReceiver(shipped())

    def ask(now: float, msg: Any) -> tuple[int, ...]:
        for p in packetize([enc.encode(msg)]):
            srv.receive(now, p)
        out = [m for p in list(srv.fifo) for m in replies.feed(p)]
        srv.fifo.clear()
        assert len(out) == 1
        return struct.unpack_from("<HBBBBBBI", bytes(out[-1].payload)) + (bytes(out[-1].payload)[12],)

    # a write before any CreateFile: NAK FileNotFound (pymavlink then aborts its put)
    seq, _, opcode, size, req, _, _, _, err = ask(0.0, _ftp(5, 0, op.OP_WriteFile, 0, b"hello"))
    assert (seq, opcode, size, req, err) == (6, op.OP_Nack, 1, op.OP_WriteFile, 10)
    assert ask(0.1, _ftp(7, 0, op.OP_CreateFile, 0, b"f.bin"))[2] == op.OP_Ack
    r = ask(0.2, _ftp(8, 0, op.OP_WriteFile, 6, b"world!"))
    assert (r[0], r[2], r[7]) == (9, op.OP_Ack, 6)  # the ack carries the offset
    assert ask(0.3, _ftp(8, 0, op.OP_WriteFile, 6, b"world!"))[0] == 9  # a repeat: the stored reply
    assert srv.repeats_answered == 1
    assert ask(0.4, _ftp(9, 1, op.OP_WriteFile, 0, b"hello "))[8] == 4  # wrong session: InvalidSession
    ask(0.5, _ftp(10, 0, op.OP_WriteFile, 0, b"hello "))
    assert srv.complete_at == 0.5 and srv.content == b"hello world!"
    assert ask(0.6, _ftp(11, 0, op.OP_TerminateSession))[2] == op.OP_Ack
    assert srv.content == b"hello world!" and not srv.open
