"""MAVLink 2 signing on the DTT link between ttctl's ends (`--key`, `--accept-unsigned`), real
processes on loopback: signed ends fly together; an unsigned or wrong-key peer gets no answer at
all; frames of a signed vehicle verify in pymavlink and pymavlink's signed frames are answered;
bad key options are one line, exit 2."""

from __future__ import annotations

import hashlib
import socket
import time
from pathlib import Path

from pymavlink.dialects.v20 import common as pm

from conftest import assert_no_traceback, run_ttctl
from e2e_lib import LOCAL, Start, data_file, free_port, one_line, receiver, send
from machine import scaled

PASSPHRASE = "field day 2026"
KEY = hashlib.sha256(PASSPHRASE.encode()).digest()
STATUS = "- status\n"
FLY = "- takeoff: 3\n- wait: {until: state == hovering, timeout: 40}\n- land\n"


def _keys(tmp_path: Path) -> tuple[Path, Path, Path]:
    """The same key as a passphrase and as hex, and another key."""
    phrase, hexkey, other = tmp_path / "phrase.key", tmp_path / "hex.key", tmp_path / "other.key"
    phrase.write_text(PASSPHRASE + "\n")
    hexkey.write_text(KEY.hex().upper())
    other.write_text("another passphrase")
    return phrase, hexkey, other


def _vehicle(start: Start, tmp_path: Path, port: int, *extra: str) -> object:
    node = start("onboard", "emulate", "onboard", "--no-gcs", "--listen", f"udpin:{LOCAL}:{port}",
                 "--no-entry-points", "--speed", "4", *extra)
    node.wait_for("onboard 1:")  # type: ignore[attr-defined]
    return node


def _tablet(tmp_path: Path, port: int, script: str, *extra: str) -> object:
    (tmp_path / "s.yaml").write_text(script)
    proc = run_ttctl("emulate", "tablet", "--to", f"udpout:{LOCAL}:{port}", "--script", str(tmp_path / "s.yaml"),
                     *extra, timeout=120)
    assert_no_traceback(proc)
    return proc


def test_signed_ends_fly_and_strangers_get_no_answer(tmp_path: Path, start: Start) -> None:
    phrase, hexkey, other = _keys(tmp_path)
    port = free_port()
    node = _vehicle(start, tmp_path, port, "--key", str(phrase))
    ok = _tablet(tmp_path, port, FLY, "--key", str(hexkey))
    assert ok.returncode == 0, ok.stderr  # type: ignore[attr-defined]
    for extra in ([], ["--key", str(other)]):
        t0 = time.monotonic()
        refused = _tablet(tmp_path, port, STATUS, *extra)
        assert refused.returncode == 1 and "no vehicle answered" in one_line(refused.stderr)  # type: ignore
        assert time.monotonic() - t0 < 40
    assert "unsigned frames (the same --key at both ends?)" in node.stderr  # type: ignore[attr-defined]
    assert "frames whose signatures do not verify" in node.stderr  # type: ignore[attr-defined]


def test_a_keyed_tablet_names_the_vehicles_key_problem_and_takes_nothing_off(tmp_path: Path, start: Start) -> None:
    """The tablet with --key and a vehicle without one (which acts on signed frames, as MAVLink
    lets a system without a key, and answers unsigned), or with another key (silent): the tablet
    never takes a vehicle it cannot verify for connected, sends it no command, and says which."""
    phrase, _, other = _keys(tmp_path)
    port = free_port()
    node = _vehicle(start, tmp_path, port)
    proc = _tablet(tmp_path, port, FLY, "--key", str(phrase))
    said = one_line(proc.stderr)  # type: ignore[attr-defined]
    assert proc.returncode == 1 and "no vehicle answered" in said, said  # type: ignore[attr-defined]
    assert "their frames unsigned and refused for --key: the vehicle answers unsigned (it has no key?)" in said, said
    assert "taking off" not in node.stderr  # type: ignore[attr-defined]
    node.kill()  # type: ignore[attr-defined]
    port = free_port()
    _vehicle(start, tmp_path, port, "--key", str(other))
    proc = _tablet(tmp_path, port, FLY, "--key", str(phrase))
    said = one_line(proc.stderr)  # type: ignore[attr-defined]
    assert proc.returncode == 1 and "a vehicle with another key drops them unanswered (the same --key at both " \
        "ends?)" in said, said


def test_accept_unsigned_lets_an_unsigned_tablet_in(tmp_path: Path, start: Start) -> None:
    phrase, _, _ = _keys(tmp_path)
    port = free_port()
    _vehicle(start, tmp_path, port, "--key", str(phrase), "--accept-unsigned")
    proc = _tablet(tmp_path, port, STATUS)
    assert proc.returncode == 0 and "landed" in proc.stdout, proc.stderr  # type: ignore[attr-defined]


def test_pymavlink_talks_to_a_signed_vehicle(tmp_path: Path, start: Start) -> None:
    """pymavlink (the oracle) signs a HEARTBEAT as a tablet would; the vehicle answers with frames
    that pymavlink verifies with the same key, and ignores the same HEARTBEAT unsigned."""
    phrase, _, _ = _keys(tmp_path)
    port = free_port()
    _vehicle(start, tmp_path, port, "--key", str(phrase))
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind((LOCAL, 0))
        s.settimeout(0.2)
        plain = pm.MAVLink(None, srcSystem=255, srcComponent=190)
        s.sendto(bytes(pm.MAVLink_heartbeat_message(6, 8, 0, 0, 4, 3).pack(plain)), (LOCAL, port))
        deadline = time.monotonic() + 3
        while time.monotonic() < deadline:  # an unsigned tablet: never answered
            try:
                data = s.recv(2048)
            except TimeoutError:
                continue
            raise AssertionError(f"a signed vehicle answered an unsigned heartbeat: {data.hex()}")
        mav = pm.MAVLink(None, srcSystem=255, srcComponent=190)
        mav.signing.secret_key = KEY
        mav.signing.sign_outgoing = True
        mav.signing.link_id = 1
        mav.signing.timestamp = int((time.time() - 1420070400) * 100_000)
        got: list[object] = []
        deadline = time.monotonic() + scaled(15)
        while time.monotonic() < deadline and len(got) < 5:
            s.sendto(bytes(pm.MAVLink_heartbeat_message(6, 8, 0, 0, 4, 3).pack(mav)), (LOCAL, port))
            try:
                data = s.recv(2048)
            except TimeoutError:
                continue
            got += [m for m in mav.parse_buffer(data) or [] if m.get_srcSystem() == 1]
    assert len(got) >= 5, got
    assert all(m.get_signed() for m in got)  # type: ignore[attr-defined]
    assert mav.signing.goodsig_count >= 5 and mav.signing.badsig_count == 0


def test_bad_key_options_are_one_line(tmp_path: Path) -> None:
    (tmp_path / "empty.key").write_text("  \n")
    cases = {("--key", str(tmp_path / "missing.key")): "--key",
             ("--key", str(tmp_path / "empty.key")): "is empty",
             ("--accept-unsigned",): "--accept-unsigned needs --key"}
    for args, want in cases.items():
        proc = run_ttctl("emulate", "onboard", "--no-gcs", "--listen", f"udpin:{LOCAL}:{free_port()}", *args,
                         timeout=30)
        assert proc.returncode == 2 and want in one_line(proc.stderr), proc.stderr


def test_signed_send_file_and_fetch_and_an_unsigned_sender_times_out(tmp_path: Path, start: Start) -> None:
    phrase, hexkey, other = _keys(tmp_path)
    served = tmp_path / "served"
    served.mkdir()
    up, down = data_file(tmp_path, "up.bin", 30_000, seed=4), data_file(served, "down.bin", 20_000, seed=5)
    port = free_port()
    recv = receiver(start, tmp_path, f"udpin:{LOCAL}:{port}", "--serve", str(served), "--key", str(phrase))
    proc, r = send(str(up), "--to", f"udpout:{LOCAL}:{port}", "--key", str(hexkey))
    assert proc.returncode == 0 and r["ok"], proc.stderr
    assert (tmp_path / "inbox" / "up.bin").read_bytes() == up.read_bytes()
    proc, r = send("down.bin", "--from", f"udpout:{LOCAL}:{port}", "--dir", str(tmp_path / "dl"), "--key",
                   str(phrase))
    assert proc.returncode == 0 and r["ok"], proc.stderr
    assert (tmp_path / "dl" / "down.bin").read_bytes() == down.read_bytes()
    for extra in ([], ["--key", str(other)]):
        proc = run_ttctl("send-file", str(up), "--name", "again.bin", "--to", f"udpout:{LOCAL}:{port}", "--timeout",
                         "2", *extra, timeout=30)
        assert proc.returncode == 1 and "timed out: no answer" in one_line(proc.stderr), proc.stderr
    assert not (tmp_path / "inbox" / "again.bin").exists()
    assert recv.p.poll() is None  # type: ignore[attr-defined]
    # the receiver says why it stays silent, once per peer
    assert recv.stderr.count(": unsigned frames (the same --key at both ends?)") == 1, recv.stderr
    assert recv.stderr.count(": frames whose signatures do not verify (the same --key at both ends?)") == 1
