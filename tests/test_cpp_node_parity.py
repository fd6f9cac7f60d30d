"""The generated C++ onboard end makes the decisions ttctl's Python end makes, byte for byte, in
virtual time (the programs: tests/cpp_node_lib.py):

- the name rules' table of control and format characters is Python's unicodedata;
- on seeded random work, the C++ scheduler builds the packets Python's Scheduler builds, at the
  same moments;
- the node (node_driver, sans-IO) receiving an upload with commands, and serving a fetch, over a
  channel that loses 2 to 25 % of the packets, sends what Python's Endpoint sends at the same
  moments.
"""

from __future__ import annotations

import random
import subprocess
import unicodedata
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

import ttapi
from cpp_node_lib import ServingOnboards, needs_gxx, write

pytestmark = needs_gxx

TABLET = (255, 190)


# -- the name rules -----------------------------------------------------------------------------

def test_name_rules_refuse_the_characters_python_refuses(cpp_node_bins: dict[str, Path]) -> None:
    """The C++ table of control and format characters is Python's unicodedata (Cc, Cf): checked
    for every code point when Python's Unicode is the table's (14.0.0)."""
    run = subprocess.run([str(cpp_node_bins["plain"]), "--print-name-rules"], capture_output=True, text=True,
                         timeout=60)
    assert run.returncode == 0, run.stderr
    got = [tuple(int(x, 16) for x in line.split()) for line in run.stdout.splitlines()]
    if unicodedata.unidata_version != "14.0.0":
        pytest.skip(f"Python's Unicode is {unicodedata.unidata_version}, the C++ table's 14.0.0")
    want: list[list[int]] = []
    for cp in range(1, 0x110000):
        if 0xD800 <= cp <= 0xDFFF or unicodedata.category(chr(cp)) not in ("Cc", "Cf"):
            continue
        if want and want[-1][1] == cp - 1:
            want[-1][1] = cp
        else:
            want.append([cp, cp])
    assert got == [tuple(w) for w in want]


# -- the frame geometry ---------------------------------------------------------------------------

def test_frame_geometry_follows_the_packet_size(cpp_node_bins: dict[str, Path]) -> None:
    """For every packet size 1..300, unsigned and signed, the C++ Geometry is Python's
    (ttctl.proto.transfer.Geometry): the same narrow frame (TT_FILE_DATA 80/100 on DTT,
    TT_FILE_DATA_FIT 107/128 on the PSDK channel, 66/100 and 94/128 signed), wide frame, survival of
    10 % packet loss and loss inverted from a wide frame's; the same packets refused (below 22
    bytes, 35 signed)."""
    from ttctl.proto.transfer import Geometry

    run = subprocess.run([str(cpp_node_bins["plain"]), "--print-geometry"], capture_output=True, text=True,
                         timeout=60)
    assert run.returncode == 0, run.stderr
    rows = [line.split() for line in run.stdout.splitlines()]
    assert len(rows) == 600
    for row in rows:
        mtu, signed = int(row[0]), row[1] == "1"
        try:
            g = Geometry(mtu, signed)
        except ValueError:
            assert row[2:] == ["-"], row
            continue
        assert tuple(int(x) for x in row[2:6]) == (int(g.narrow_fit), g.narrow_cap, g.narrow_frame, g.wide_frame), row
        assert float(row[6]) == pytest.approx(g.survival_wide(0.1), abs=1e-9), row
        assert float(row[7]) == pytest.approx(g.packet_loss_from_wide(0.3), abs=1e-9), row
    got = {(int(r[0]), r[1]): tuple(int(x) for x in r[2:5]) for r in rows if r[2] != "-"}
    assert got[(100, "0")] == (0, 80, 100)
    assert got[(128, "0")] == (1, 107, 128)
    assert got[(100, "1")] == (1, 66, 100)
    assert got[(128, "1")] == (1, 94, 128)
    assert float(rows[2 * 99][6]) == pytest.approx(0.34 * 0.9 ** 3 + 0.66 * 0.9 ** 4, abs=1e-12)


# -- the scheduler: Python's decisions -----------------------------------------------------------

def scheduler_script(rng: random.Random) -> list[str]:
    """Random work for a scheduler: control frames (some keyed, as statuses are), telemetry,
    bulk sources of narrow (100-byte) and wide (267-byte) data frames coming and going, and
    packets asked for at rising times."""
    enc = ttapi.Encoder(sysid=1, compid=240)
    ops: list[str] = []
    live: list[int] = []
    now = 0.0
    queued = 0
    for _ in range(600):
        r = rng.random()
        if r < 0.15 and queued < 40:
            msg = rng.choice([ttapi.TtCommandAck(command_id=rng.randrange(65536), result=0, progress=100),
                              ttapi.TtFileStatus(transfer_id=rng.randrange(1, 4), result=0,
                                                 received_contiguous=rng.randrange(10**6), range_count=1,
                                                 ranges=[rng.randrange(100), 200] + [0] * 12),
                              ttapi.TtLog(id=0, severity=6, text="x" * rng.randint(1, 79))])
            key = rng.choice([0, 0, 1, 2, 3])
            ops.append(f"C {enc.encode(msg).hex()} {key}")
            queued += 1
        elif r < 0.25:
            msg = rng.choice([ttapi.Heartbeat(type=18, custom_mode=rng.randrange(2**32)),
                              ttapi.TtOdometry(time_usec=rng.randrange(2**40), position=[rng.random(), 0, 1])])
            ops.append(f"T {enc.encode(msg).hex()} 0")  # (Python's telemetry has no keys: the C++ one's are extra)
        elif r < 0.3 and len(live) < 3:
            sid = rng.randrange(1000)
            if sid not in live:
                live.append(sid)
                ops.append(f"S {sid}")
        elif r < 0.32 and live:
            ops.append(f"R {live.pop(rng.randrange(len(live)))}")
        elif r < 0.5 and live:
            sid = rng.choice(live)
            data = ttapi.TtFileDataWide(transfer_id=sid, offset=rng.randrange(10**6), data=rng.randbytes(247)) \
                if rng.random() < 0.4 else ttapi.TtFileData(transfer_id=sid, offset=rng.randrange(10**6),
                                                            data=rng.randbytes(80))
            ops.append(f"B {sid} {enc.encode(data).hex()}")
        else:
            now += rng.choice([0.0, 0.001, 0.005, 0.015, 0.05])
            ops.append(f"P {now!r}")
            queued = max(0, queued - 3)
    return ops


def python_packets(ops: list[str], mtu: int, rate: float) -> list[str]:
    from collections import deque

    from ttctl.proto.scheduler import CONTROL, TELEMETRY, Scheduler

    sched = Scheduler(mtu, rate)
    sources: dict[int, tuple[deque[bytes], Any]] = {}
    out = []
    for op in ops:
        parts = op.split()
        if parts[0] in ("C", "T"):
            key = int(parts[2])
            sched.send(bytes.fromhex(parts[1]), CONTROL if parts[0] == "C" else TELEMETRY, key=key or None)
        elif parts[0] == "S":
            q: deque[bytes] = deque()

            def pull(now: float, space: int, q: deque[bytes] = q) -> bytes | None:
                if not q or (len(q[0]) == 100 and space < 100):
                    return None
                return q.popleft()

            sources[int(parts[1])] = (q, pull)
            sched.add_source(pull)
        elif parts[0] == "R":
            sched.remove_source(sources[int(parts[1])][1])
        elif parts[0] == "B":
            sources[int(parts[1])][0].append(bytes.fromhex(parts[2]))
        else:
            pkt = sched.next_packet(float(parts[1]))
            out.append(pkt.hex() if pkt else "-")
    return out


@pytest.mark.parametrize("mtu,rate", [(100, 6700.0), (100, 0.0), (64, 500.0)])
def test_the_scheduler_builds_the_packets_pythons_builds(cpp_node_bins: dict[str, Path], mtu: int, rate: float) -> None:
    """On seeded random work (control frames keyed and not, telemetry, bulk sources coming and
    going, narrow and wide data frames, packets asked for at paced times), the C++ scheduler
    builds byte for byte the packets ttctl's Python one builds, at the same moments."""
    for seed in range(4):
        ops = scheduler_script(random.Random(seed))
        run = subprocess.run([str(cpp_node_bins["scheduler"]), str(mtu), str(rate)], input="\n".join(ops) + "\n",
                             capture_output=True, text=True, timeout=60)
        assert run.returncode == 0, run.stderr
        got = run.stdout.splitlines()
        want = python_packets(ops, mtu, rate)
        assert len(got) == len(want)
        for i, (g, w) in enumerate(zip(got, want, strict=True)):
            assert g == w, (seed, i, g, w)
        assert sum(p != "-" for p in want) > 30  # packets were built, not just refused


# -- the node: the Python endpoint's decisions ----------------------------------------------------

def receiving_script(tmp: Path, seed: int, loss: float, size: int, mtu: int = 100, key: bytes | None = None,
                     start: int = 0, lose: Callable[[int, float], bool] | None = None,
                     tablet_rate: float = 500.0, onboard_rate: float = 6700.0,
                     inbound: float | None = None, maps: bool = True) -> tuple[list[str], list[str]]:
    """A Python tablet (Endpoint 255/190, seeded, paced at `tablet_rate`) uploads a file and sends
    commands to a Python onboard Endpoint (1/240, paced at `onboard_rate`) over a channel of `mtu`-byte
    packets that loses `loss` of them either way (and the tablet's i-th packet sent at `now` when
    `lose(i, now)`), in virtual time (5 ms steps), both ends signing with `key` from timestamp
    `start` if given; the onboard end grants rates on an `inbound` B/s link if given; without
    `maps` the tablet's offer does not say it reads TT_FILE_MAP (a sender from before it). Returns
    the onboard end's input as a node_driver script, and what it sent at each poll."""
    from ttctl.proto.endpoint import Endpoint
    from ttctl.proto.storage import BytesSource, ReceiveDir

    b = shipped_bindings()
    rng = random.Random(seed)
    def signing() -> Any:
        return b.mavlink.Signing(key, 0, False, start) if key is not None else None

    tx = Endpoint(b, *TABLET, mtu=mtu, rate_Bps=tablet_rate, rng=random.Random(seed), signing=signing())
    # an action that accepts every command, as node_driver's (without one, both ends answer UNSUPPORTED)
    rx = Endpoint(b, 1, 240, mtu=mtu, rate_Bps=onboard_rate, receive_dir=ReceiveDir(tmp / "python"), signing=signing(),
                  action=lambda msg: int(ttapi.TtResult.TT_RESULT_ACCEPTED), inbound_Bps=inbound)
    data = random.Random(seed + 1).randbytes(size)
    sender = tx.send_file("f.bin", (1, 240), source=BytesSource(data, "f.bin"))
    if not maps:
        from ttctl.proto.sender import MAP

        sender._flags &= ~MAP
        sender._use(sender.deflated)
    script: list[str] = []
    sent: list[str] = []
    now = 0.0
    commands = 0
    up = 0  # the tablet's packets so far
    while not sender.done and now < 300:
        if commands < 6 and rng.random() < 0.01:
            tx.command(b.TtActionCommand(action=commands % 5), (1, 240))
            commands += 1
        while (pkt := tx.poll(now)) is not None:
            up += 1
            if rng.random() >= loss and not (lose is not None and lose(up - 1, now)):
                script.append(f"R {now!r} {pkt.hex()}")
                rx.receive(now, pkt)
        out = []
        while (pkt := rx.poll(now)) is not None:
            out.append(pkt)
        script.append(f"P {now!r}")
        sent.append(" ".join(p.hex() for p in out) or "-")
        for pkt in out:
            if rng.random() >= loss:
                tx.receive(now, pkt)
        now = round(now + 0.005, 6)
    assert sender.result is not None and sender.result.ok, sender.result
    assert (tmp / "python" / "f.bin").read_bytes() == data
    return script, sent


def shipped_bindings() -> Any:
    from conftest import shipped

    return shipped()


@pytest.mark.parametrize("seed,loss,mtu,signed,inbound", [(1, 0.1, 100, False, None), (2, 0.25, 100, False, None),
                                                         (6, 0.1, 128, False, None), (11, 0.1, 100, True, None),
                                                         (12, 0.1, 128, True, None), (13, 0.1, 100, False, 500.0),
                                                         (14, 0.1, 100, True, 500.0)])
def test_the_node_answers_what_pythons_endpoint_answers(cpp_node_bins: dict[str, Path], tmp_path: Path, seed: int,
                                                        loss: float, mtu: int, signed: bool,
                                                        inbound: float | None) -> None:
    """The C++ node and ttctl's Python Endpoint, as the onboard end of an upload with commands
    over a lossy channel in virtual time, given the same packets at the same moments, send the
    same packets byte for byte at the same moments: the same statuses (when, how many, which
    gaps, hold times), the same acks, the same pacing; and store the same file. On DJI's DTT
    (100-byte packets) and the Payload SDK channel (128: TT_FILE_DATA_FIT frames come in), and
    signed (one-packet TT_FILE_DATA_FIT frames; signings started ahead of the clock sign alike).
    With an inbound rate (the M100's 500 B/s uplink) both grant the lone upload CONTROL_FILL of
    it once the tablet's commands are heard (sharing.py): the same grants in the same statuses."""
    key = random.Random(seed).randbytes(32) if signed else None
    start = shipped_bindings().mavlink.Signing.now() + 10**11
    script, want = receiving_script(tmp_path, seed, loss, 20_000, mtu, key, start, inbound=inbound)
    if mtu != 100 or signed:
        assert sum("5ec300" in line for line in script if line.startswith("R")) > 20  # TT_FILE_DATA_FIT's msgid
    signing = [key.hex(), str(start)] if key is not None else []
    run = subprocess.run([str(cpp_node_bins["driver"]), str(tmp_path / "cpp"), "-", "6700", str(inbound or 0), str(mtu),
                          *signing], input="\n".join(script) + "\n", capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    got = run.stdout.splitlines()
    if inbound:  # a lone upload, granted because commands came: 0.75 of 500 B/s less room for the commands
        from ttctl.proto.sharing import CONTROL_FILL, MIN_FILL, share

        grants = {s.rate_grant for _, s in status_frames(got)} - {0}
        assert grants and all(MIN_FILL * inbound <= g <= CONTROL_FILL * inbound for g in grants), grants
        assert share(inbound, 1, 0.0, control=True) == int(CONTROL_FILL * inbound)
    assert len(got) == len(want)
    polls = [line for line in script if line.startswith("P")]
    for i, (g, w) in enumerate(zip(got, want, strict=True)):
        assert g == w, (i, polls[i], g, w)
    assert (tmp_path / "cpp" / "f.bin").read_bytes() == (tmp_path / "python" / "f.bin").read_bytes()
    assert sum(w != "-" for w in want) > 20


def status_frames(sent: list[str], msgid: int = ttapi.TtFileStatus.MSG_ID) -> list[tuple[int, Any]]:
    """The TT_FILE_STATUS (or `msgid`) frames in what an end sent (node_driver's lines: each poll's
    packets in hex, '-' for none; a frame may go on in the next packet): (the whole frame's length, it)."""
    from ttapi.mavlink import decode

    stream = b"".join(bytes.fromhex(p) for line in sent if line != "-" for p in line.split())
    out = []
    i = 0
    while i < len(stream):
        assert stream[i] == 0xFD, (i, stream[i:i + 16].hex())
        n = 12 + stream[i + 1] + (13 if stream[i + 2] & 1 else 0)
        frame = stream[i:i + n]
        if frame[7] | frame[8] << 8 | frame[9] << 16 == msgid:
            out.append((n, decode(frame)))
        i += n
    return out


@pytest.mark.parametrize("maps", [False, True])
@pytest.mark.parametrize("seed,mtu,signed,per,rate", [(21, 100, True, 5, 6700), (22, 100, False, 6, 6700),
                                                      (23, 128, True, 7, 6700), (24, 128, False, 7, 6700),
                                                      (25, 100, True, 5, 500), (26, 100, False, 6, 500)])
def test_the_nodes_statuses_fit_one_packet(cpp_node_bins: dict[str, Path], tmp_path: Path, seed: int, mtu: int,
                                           signed: bool, per: int, rate: int, maps: bool) -> None:
    """As ttctl's Python receiver (proto/endpoint.py ranges_per_status, RANGES_MORE): the node's
    statuses list only the gaps that fit one packet of its link (a 7-gap status is 102 bytes, 115
    signed: two DTT packets, lost when either is), as many in a report as three 7-gap statuses
    would hold, with range_count's top bit on every status of a burst but the last (more gaps
    follow past received_end): an upload whose every other packet is lost for its first 1.5 s
    leaves dozens of gaps; the node sends what Python's Endpoint sends, byte for byte, and the
    transfer completes. On a 500 B/s link (the M100's uplink) statuses come as often as Python's:
    at least 1.5 statuses' bytes at the link's rate apart (a signature counted), 0.8 near the end.
    To a sender that reads maps (`maps`: TT_FILE_FLAGS_MAP in its offer, as ttctl's senders) the
    reports that need more than one status are TT_FILE_MAPs instead, each in one packet too."""
    from ttctl.proto.transfer import MAP_MORE, MAX_RANGES, RANGES_MORE, ranges_per_status

    assert ranges_per_status(mtu, signed) == per
    key = random.Random(seed).randbytes(32) if signed else None
    start = shipped_bindings().mavlink.Signing.now() + 10**11
    script, want = receiving_script(tmp_path, seed, 0.0, 20_000, mtu, key, start,
                                    lose=lambda i, now: now < 1.5 and i % 2 == 1, tablet_rate=20_000.0,
                                    onboard_rate=float(rate), maps=maps)
    signing = [key.hex(), str(start)] if key is not None else []
    run = subprocess.run([str(cpp_node_bins["driver"]), str(tmp_path / "cpp"), "-", str(rate), "0", str(mtu), *signing],
                         input="\n".join(script) + "\n", capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    got = run.stdout.splitlines()
    assert len(got) == len(want)
    for i, (g, w) in enumerate(zip(got, want, strict=True)):
        assert g == w, (i, g, w)
    assert (tmp_path / "cpp" / "f.bin").read_bytes() == (tmp_path / "python" / "f.bin").read_bytes()
    statuses = status_frames(got)
    if maps:
        found = status_frames(got, ttapi.TtFileMap.MSG_ID)
        assert len(found) >= 3, len(found)
        for n, m in found:
            assert n <= mtu and m.chunk > 0 and m.region_start <= m.received_contiguous + 8 * 52 * m.chunk, (n, m)
        assert any(m.flags & MAP_MORE for _, m in found) or all(m.received_end - m.region_start
                                                                  <= 8 * 52 * m.chunk for _, m in found)
        assert all(s.range_count & ~RANGES_MORE <= per for _, s in statuses)  # (few gaps: a status)
        return

    bursts: list[list[Any]] = []
    for n, s in statuses:
        assert n <= mtu, (n, s)
        assert s.range_count & ~RANGES_MORE <= per, s
        if s.region_start == s.received_contiguous:  # the first of a burst
            bursts.append([])
        bursts[-1].append(s)
    full = -(-3 * MAX_RANGES // per)  # statuses in a burst that lists as many gaps as it may
    several = [b for b in bursts if len(b) > 1]
    assert several, [len(b) for b in bursts]
    # (at 500 B/s a burst waits in the scheduler, and the next one's statuses replace its own by key)
    for b in bursts if rate > 1000 else []:
        assert len(b) <= full, b
        more = [bool(s.range_count & RANGES_MORE) for s in b]
        assert more[:-1] == [True] * (len(b) - 1), b
        assert not more[-1] or len(b) == full, b


@pytest.mark.parametrize("seed,loss,mtu,signed,old", [(3, 0.02, 100, False, False), (4, 0.1, 100, False, False),
                                                     (5, 0.25, 100, False, False), (7, 0.02, 128, False, False),
                                                     (8, 0.1, 128, False, False), (9, 0.1, 100, True, False),
                                                     (10, 0.02, 128, True, False), (14, 0.25, 100, False, True)])
def test_the_node_serves_what_pythons_endpoint_serves(cpp_node_bins: dict[str, Path], tmp_path: Path, seed: int,
                                                      loss: float, mtu: int, signed: bool, old: bool) -> None:
    """Two worlds in virtual time, alike but for the onboard end: a Python tablet fetches a file
    (TT_FILE_REQUEST) over a channel that loses `loss` of the packets either way, from ttctl's
    Python Endpoint in one world and from the C++ node (drawing the same transfer ids) in the
    other. At every 5 ms step both onboard ends send the same packets byte for byte: the same
    offers, the same narrow and wide data frames chosen from the same loss estimates, the same
    repeats, at the same pace; and both fetches complete. In 100-byte packets (TT_FILE_DATA) and
    128-byte ones (TT_FILE_DATA_FIT, 107 file bytes filling each packet); signed, in
    TT_FILE_DATA_FIT frames of one packet (66 and 94 file bytes), every frame signed both ways
    (the signings start ahead of the clock, so their timestamps, and so the signatures, are
    the same in both worlds). An `old` tablet (from before TT_FILE_MAP) refuses the offer's
    TT_FILE_FLAGS_MAP by name: both ends offer again without it and serve the file by ranges."""
    from ttctl.proto.endpoint import Endpoint
    from ttctl.proto.receiver import MAP
    from ttctl.proto.storage import ReceiveDir

    b = shipped_bindings()
    serve = write(tmp_path / "serve" / "s.bin", 30_000, seed).parent
    key = random.Random(seed).randbytes(32) if signed else None
    start = b.mavlink.Signing.now() + 10**11  # about 12 days ahead: timestamps count from here
    onboard = ServingOnboards(cpp_node_bins["driver"], tmp_path, serve, b, seed + 100, mtu, key, start)
    worlds = []
    for name in ("python", "cpp"):
        done: list[bool] = []
        signing = b.mavlink.Signing(key, 0, False, start) if key is not None else None
        tab = Endpoint(b, *TABLET, mtu=mtu, rate_Bps=500.0, signing=signing,
                       receive_dir=ReceiveDir(tmp_path / f"tablet_{name}"),
                       unsolicited=False, accept_commands=False, rng=random.Random(seed),
                       on_event=lambda what, obj, done=done: done.append(True) if what == "file-complete" else None)
        if old:
            assert tab.receiver is not None
            tab.receiver.known_flags &= ~MAP
        tab.request_file("s.bin", (1, 240))
        worlds.append((name, tab, random.Random(seed), done))
    offer_flags: set[int] = set()
    now = 0.0
    steps = sent = wide = fit = 0
    try:
        while not all(w[3] for w in worlds) and now < 120:
            outs = {}
            for name, tab, lose, _ in worlds:
                while (pkt := tab.poll(now)) is not None:
                    if lose.random() >= loss:
                        onboard.receive(name, now, pkt)
                out = outs[name] = onboard.poll(name, now)
                for pkt in out:
                    if lose.random() >= loss:
                        tab.receive(now, pkt)
            assert outs["cpp"] == outs["python"], (now, [p.hex() for p in outs["cpp"]],
                                                   [p.hex() for p in outs["python"]])
            sent += len(outs["python"])
            offer_flags |= {m.flags for p in outs["python"] for m in b.parser().feed(p) if m.NAME == "TT_FILE_OFFER"}
            wide += sum(p.count(bytes.fromhex("59c300")) for p in outs["python"])  # TT_FILE_DATA_WIDE's msgid
            fit += sum(p.count(bytes.fromhex("5ec300")) for p in outs["python"])  # TT_FILE_DATA_FIT's msgid
            steps += 1
            now = round(now + 0.005, 6)
    finally:
        onboard.close()
    assert all(w[3] for w in worlds), "a fetch did not complete"
    for name in ("python", "cpp"):
        assert (tmp_path / f"tablet_{name}" / "s.bin").read_bytes() == (serve / "s.bin").read_bytes()
    assert sent > 200 and steps > 300
    if not signed:  # signed, narrow frames carry less and wide ones more: either may win at 10 % loss
        assert (wide > 20) == (loss < 0.05), wide  # little loss: wide frames (the choice is the same too)
    assert (fit > 20) == (mtu == 128 or signed), fit
    assert {f & MAP for f in offer_flags} == ({MAP, 0} if old else {MAP}), offer_flags  # (refused: again without)

