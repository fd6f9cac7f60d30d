"""`ttctl bench serve` and `ttctl bench link --to`: real processes on 127.0.0.1, through
`ttctl link relay` where the link's rate, loss and latency are known."""

from __future__ import annotations

import json
import signal
import socket
import subprocess
import time
import tomllib
from pathlib import Path

import pytest

from conftest import ROOT, assert_no_traceback, run_ttctl, ttctl_cmd
from e2e_lib import LOCAL, Proc, Start, free_port
from machine import scaled

PROFILE = tomllib.loads((ROOT / "cli" / "ttctl" / "link" / "profiles.toml").read_text())["m100"]
RATE = 4000  # B/s, the relay's --rate both ways


def server(start: Start, name: str = "serve") -> tuple[Proc, int]:
    port = free_port()
    p = start(name, "bench", "serve", "--listen", f"udpin:{LOCAL}:{port}")
    p.wait_for("listening on")
    return p, port


def relay(start: Start, name: str, to: int, *extra: str) -> int:
    port = free_port()
    p = start(name, "link", "relay", "--listen", f"udpin:{LOCAL}:{port}", "--to", f"udpout:{LOCAL}:{to}",
              "--profile", "m100", "--rate", str(RATE), "--stats-interval", "0", *extra)
    p.wait_for("relay: udpin")
    return port


def bench(port: int, *args: str, timeout: float = 40) -> tuple[subprocess.CompletedProcess[str], dict]:
    proc = run_ttctl("bench", "link", "--to", f"udpout:{LOCAL}:{port}", "--json", *args, timeout=timeout)
    assert_no_traceback(proc)
    return proc, (json.loads(proc.stdout) if proc.stdout.strip() else {})


def bench_bg(tmp: Path, port: int, *args: str) -> tuple[subprocess.Popen[str], Path]:
    err = tmp / "bench.err"
    p = subprocess.Popen(ttctl_cmd() + ["bench", "link", "--to", f"udpout:{LOCAL}:{port}", "--json", *args],
                         stdout=subprocess.PIPE, stderr=err.open("w"), text=True)
    return p, err


def test_recovers_the_relays_rate_loss_and_latency(start: Start, tmp_path: Path) -> None:
    _, sport = server(start)
    loss = 0.1
    port = relay(start, "relay", sport, "--loss", str(loss), "--seed", "7")
    # uplink paced at twice the link's rate: the capacity; downlink at 80 Hz x 100 B = 8000 B/s too
    fast, fast_out = bench_bg(tmp_path, port, "--direction", "both", "--sizes", "100", "--rates", "80",
                              "--count", "100", "--rate", str(2 * RATE), "--label", "fast")
    fast_stdout, _ = fast.communicate(timeout=40)
    assert fast.returncode == 0, fast_out.read_text()
    rep = json.loads(fast_stdout)
    assert rep["conditions"]["label"] == "fast" and rep["partial"] is False
    up, down = rep["uplink"]["rows"][0], rep["downlink"]["rows"][0]
    for row in (up, down):
        assert abs(row["capacity_Bps"] - RATE) <= 0.15 * RATE, row
        assert row["rx_rate_Bps"] <= 1.05 * RATE, row  # never more than the link carries
        assert row["lost"] > 30, row  # the SDK buffer overflows: half the offered packets cannot go
    # paced below the link's rate: the loss is the radio's
    proc, rep = bench(port, "--direction", "both", "--sizes", "50", "--rates", "30", "--count", "200",
                      "--rate", str(RATE // 2))
    assert proc.returncode == 0, proc.stderr
    up, down = rep["uplink"]["rows"][0], rep["downlink"]["rows"][0]
    for row in (up, down):
        assert row["sent"] == 200 and row["received"] + row["lost"] == 200
        assert abs(row["loss"] - loss) <= 0.07, row  # 3.3 sigma of a binomial of 200 at 0.1
        assert row["loss_runs"] >= 5
    # latency: the profile's latency each way plus the time to send one packet at the rate
    lat = rep["latency"]
    lat_up, lat_down = PROFILE["up"]["latency_s"] * 1e3, PROFILE["down"]["latency_s"] * 1e3
    echo = 18 / RATE * 1e3
    rtt = lat_up + lat_down + 2 * echo
    assert rtt - 2 <= lat["rtt_p50_ms"] <= rtt + 15, lat
    assert abs(lat["owd_rtt_half_ms"] - rtt / 2) <= 8, lat
    assert abs(lat["clock_offset_ms"]) <= 5, lat  # one host, one clock
    assert lat_up + 50 / RATE * 1e3 - 2 <= up["owd_p50_ms"] <= lat_up + 50 / RATE * 1e3 + 15, up
    assert lat_down + 100 / RATE * 1e3 - 2 <= down["owd_p50_ms"] <= lat_down + 100 / RATE * 1e3 + 15, down


def test_burst_loss_gives_longer_loss_runs_than_random(start: Start) -> None:
    _, sport = server(start)
    ports = {model: relay(start, f"relay-{model}", sport, "--loss", "0.2", "--loss-model", model, "--seed", "3")
             for model in ("random", "burst")}
    args = ("--direction", "up", "--sizes", "20", "--count", "300", "--rate", str(RATE // 2))
    procs = {m: subprocess.Popen(ttctl_cmd() + ["bench", "link", "--to", f"udpout:{LOCAL}:{p}", "--json", *args],
                                 stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
             for m, p in ports.items()}
    rows = {}
    for m, p in procs.items():
        out, err = p.communicate(timeout=40)
        assert p.returncode == 0, err
        rows[m] = json.loads(out)["uplink"]["rows"][0]
    rnd, burst = rows["random"], rows["burst"]
    for row in (rnd, burst):
        assert 0.08 <= row["loss"] <= 0.35, row
    assert rnd["loss_run_mean"] < 1.6, rnd  # random: 1 / (1 - p) = 1.25
    assert burst["loss_run_mean"] >= 2.0, burst  # Gilbert-Elliott bursts of 3 on average
    assert burst["loss_run_max"] > rnd["loss_run_max"]


def test_relay_bursts_last_a_time_not_a_number_of_packets(start: Start) -> None:
    """Bursts of mean 8 slots (8 x 25 ms at 4000 B/s) at 20 % loss: probes 0.4 slots apart lose
    long runs, probes 10 slots apart (a command or an ack now and then) mostly lose one at a time,
    as the chain's memory after 10 slots says (runs of mean 1.5; the relay once stepped the
    chain per packet, and gave the sparse flow runs of 8 too)."""
    _, sport = server(start)
    ports = [relay(start, f"relay-{k}", sport, "--loss", "0.2", "--loss-model", "burst", "--burst-mean", "8",
                   "--seed", str(k)) for k in (11, 12)]
    runs = {"dense": ("--sizes", "20", "--count", "1000", "--rate", str(RATE // 2)),  # 10 ms apart
            "sparse": ("--sizes", "100", "--count", "120", "--rate", str(RATE // 10))}  # 250 ms apart
    procs = {name: subprocess.Popen(ttctl_cmd() + ["bench", "link", "--to", f"udpout:{LOCAL}:{port}", "--json",
                                                   "--direction", "up", *args],
                                    stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
             for (name, args), port in zip(runs.items(), ports, strict=True)}
    rows = {}
    for name, p in procs.items():
        out, err = p.communicate(timeout=90)
        assert p.returncode == 0, err
        rows[name] = json.loads(out)["uplink"]["rows"][0]
    assert rows["dense"]["loss_run_mean"] >= 4.0, rows
    assert rows["sparse"]["loss_runs"] >= 5 and rows["sparse"]["loss_run_mean"] <= 2.5, rows
    # the loss is the loss whatever the spacing (the dense flow sees few, long bursts: wider)
    assert 0.08 <= rows["sparse"]["loss"] <= 0.35 and 0.05 <= rows["dense"]["loss"] <= 0.45, rows


@pytest.mark.parametrize("args, message", [
    (("--sizes", "10,101"), "101 is not a probe size"),
    (("--sizes", "5"), "5 is not a probe size"),
    (("--sizes", "0"), "0 is not a probe size"),
    (("--sizes", "ten"), "--sizes wants comma-separated numbers"),
    (("--direction", "sideways"), "--direction must be up, down or both"),
    (("--rates", "0"), "--rates: 0 Hz"),
    (("--count", "0"), "--count must be in"),
    (("-o", "{tmp}/no/such/dir/out.json"), "no folder"),
    (("-o", "{tmp}/out.txt"), "must end in .json or .csv"),
    (("-o", "{tmp}"), "must end in .json or .csv"),
    (("--plot", "{tmp}/no/such/dir/p.png"), "no folder"),
    (("--to", "tcp:127.0.0.1:1"), "plain UDP"),
])
def test_bad_input_is_one_line_before_measuring(tmp_path: Path, args: tuple[str, ...], message: str) -> None:
    listener = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)  # a silent peer: it hears what is sent
    listener.bind((LOCAL, 0))
    listener.setblocking(False)
    argv = [a.replace("{tmp}", str(tmp_path)) for a in args]
    proc = run_ttctl("bench", "link", "--to", f"udpout:{LOCAL}:{listener.getsockname()[1]}", *argv, timeout=20)
    assert proc.returncode == 2, proc.stderr
    assert message in proc.stderr, proc.stderr
    assert len(proc.stderr.strip().splitlines()) == 1, proc.stderr
    with pytest.raises(BlockingIOError):  # refused before measuring: not one probe was sent
        listener.recv(2048)
    listener.close()
    assert list(tmp_path.iterdir()) == []


def test_live_options_without_to_are_refused() -> None:
    proc = run_ttctl("bench", "link", "--sizes", "10", "--count", "5", timeout=20)
    assert proc.returncode == 2 and "give --to" in proc.stderr, proc.stderr


def test_unreachable_peer_is_one_line_exit_2(tmp_path: Path) -> None:
    out = tmp_path / "r.json"
    proc = run_ttctl("bench", "link", "--to", f"udpout:{LOCAL}:{free_port()}", "-o", str(out), timeout=20)
    assert_no_traceback(proc)
    assert proc.returncode == 2, proc.stderr
    assert "no answer from" in proc.stderr and len(proc.stderr.strip().splitlines()) == 1, proc.stderr
    assert list(tmp_path.iterdir()) == []


def test_server_killed_midway_keeps_rows_marked_partial(start: Start, tmp_path: Path) -> None:
    pytest.importorskip("matplotlib")
    srv, sport = server(start)
    out = tmp_path / "rows.csv"
    png = tmp_path / "rows.png"
    p, err = bench_bg(tmp_path, sport, "--direction", "up", "--sizes", "20,50,100", "--count", "100", "--rate",
                      "2000", "-o", str(out), "--plot", str(png))
    end = time.monotonic() + scaled(20)
    while "up 20 B:" not in err.read_text():
        assert time.monotonic() < end and p.poll() is None, err.read_text()
        time.sleep(0.02)
    srv.kill()
    stdout, _ = p.communicate(timeout=20)
    assert p.returncode == 1, err.read_text()
    rep = json.loads(stdout)
    assert rep["partial"] is True
    assert [r["size"] for r in rep["uplink"]["rows"]] == [20]
    assert rep["uplink"]["rows"][0]["lost"] == 0
    assert "stopped answering" in err.read_text()
    lines = out.read_text().splitlines()
    assert lines[0].startswith("direction,size,") and len(lines) == 2 and lines[1].startswith("up,20,")
    assert ",True," in lines[1]  # the partial column
    assert png.read_bytes().startswith(b"\x89PNG")
    assert [f.name for f in tmp_path.iterdir() if f.name.startswith(".")] == []  # no temp file left


def test_server_ignores_garbage_and_strangers_and_stops_on_sigint(start: Start) -> None:
    from ttctl.link import probes as P

    srv, sport = server(start)
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.settimeout(0.3)
        s.connect((LOCAL, sport))
        for junk in (b"", b"\xb7", b"hello", bytes(100), P.probe(4242, 1, 50, 0), P.header(b"Q", 4242, 0),
                     P.header(b"Z", 1, 1), bytes([0xB7]) * 100):
            s.send(junk)
        with pytest.raises(TimeoutError):
            s.recv(200)
        s.send((P.header(b"E", 9, 3) + P.STAMP.pack(123)).ljust(18, b"\x55"))
        reply = s.recv(200)
        assert P.parse(reply) == (b"e", 9, 3) and P.ECHO_REPLY.unpack(reply)[4] == 123
    srv.signal(signal.SIGINT)
    assert srv.wait(10) == 0
    assert "stopped" in srv.stderr and "Traceback" not in srv.stderr


def test_server_core_bounds_its_memory_and_reports_ranges() -> None:
    from ttctl.link import probes as P

    core = P.Server(clock=lambda: 0)
    for run in range(1, P.MAX_RUNS + 10):
        assert core.handle(P.header(b"O", run, 50), 0) == [P.header(b"o", run, 50)]
    assert len(core.runs) == P.MAX_RUNS and 1 not in core.runs
    assert core.handle(P.header(b"O", 7, P.MAX_COUNT + 1), 0) == []  # too many probes asked for
    run = P.MAX_RUNS + 9
    for seq in (*range(0, 10), *range(13, 40), 45, 45):  # 45 twice: counted once
        core.handle(P.probe(run, seq, 30, 0), 1000 + seq * 10)
    summary = P.SUMMARY.unpack(core.handle(P.header(b"Q", run, 0), 0)[0])
    assert summary[4] == 38 and summary[5] == 1  # received, one page of ranges
    page = core.handle(P.header(b"Q", run, 1), 0)[0]
    got = [P.RANGE.unpack_from(page, k) for k in range(P.HDR.size, len(page), P.RANGE.size)]
    assert got == [(0, 9), (13, 39), (45, 45)]
    from ttctl.bench.live import loss_runs

    assert loss_runs(got, 50) == [3, 5, 4]


def test_link_probes_beside_a_node_take_only_whole_probes() -> None:
    """The onboard end's embedded service: a packet that parses as a probe is not one while a
    frame from its source is half received (it is that frame's continuation), and a downlink
    run needs an echo from the same source first (so a stray continuation cannot start one)."""
    from ttctl.link import probes as P

    mid: set[str] = set()
    sent: list[tuple[bytes, object]] = []
    lp = P.LinkProbes(lambda data, src: sent.append((data, src)), lambda src: src in mid, lambda _: None)
    echo = (P.header(b"E", 5, 1) + P.STAMP.pack(7)).ljust(18, b"\x55")
    mid.add("a")
    assert lp.take(echo, "a") is False and sent == []
    assert lp.take(b"\xfd\x09" + bytes(20), "b") is False  # a MAVLink frame: the node's
    down = P.DOWN_REQ.pack(P.MAGIC, b"D", 9, 10, 50, 10_000)
    assert lp.take(down, "b") is True and sent == []  # no echo from b yet: refused
    assert lp.take(echo, "b") is True and P.parse(sent[-1][0]) == (b"e", 5, 1) and sent[-1][1] == "b"


def test_emulate_onboard_answers_bench_link_beside_its_link(start: Start, tmp_path: Path) -> None:
    """`bench link --to` a running onboard end through the relay: the m100 uplink's 500 B/s is
    measured, and a file sent over the same link meanwhile arrives whole."""
    from e2e_lib import data_file

    dtt = free_port()
    onboard = start("onboard", "emulate", "onboard", "--listen", f"udpin:{LOCAL}:{dtt}", "--no-gcs", "--inbox",
                    str(tmp_path / "inbox"), "--profile", "m100")
    onboard.wait_for("tablet link")
    port = free_port()
    start("relay", "link", "relay", "--listen", f"udpin:{LOCAL}:{port}", "--to", f"udpout:{LOCAL}:{dtt}",
          "--profile", "m100", "--stats-interval", "0").wait_for("relay: udpin")
    b, err = bench_bg(tmp_path, port, "--sizes", "100", "--rates", "10", "--count", "40", "--rate", "1000")
    f = data_file(tmp_path, "f.bin", 3000)
    sent = run_ttctl("send-file", str(f), "--to", f"udpout:{LOCAL}:{port}", "--profile", "m100", "--json",
                     timeout=90)
    out, _ = b.communicate(timeout=90)
    assert b.returncode == 0, err.read_text()
    assert sent.returncode == 0, sent.stdout + sent.stderr
    assert (tmp_path / "inbox" / "f.bin").read_bytes() == f.read_bytes()
    rep = json.loads(out)
    up, down = rep["uplink"]["rows"][0], rep["downlink"]["rows"][0]
    assert 350 <= up["capacity_Bps"] <= 560, up  # the file shares the uplink part of the time
    assert down["received"] >= 36, down
    assert "bench: downlink run" in onboard.stderr


def test_emulate_onboard_with_a_key_answers_no_probes(start: Start, tmp_path: Path) -> None:
    key = tmp_path / "key"
    key.write_text("correct horse battery staple")
    dtt = free_port()
    start("onboard", "emulate", "onboard", "--listen", f"udpin:{LOCAL}:{dtt}", "--no-gcs", "--key",
          str(key)).wait_for("tablet link")
    proc, _ = bench(dtt, "--count", "5", "--sizes", "50", "--rates", "10")
    assert proc.returncode == 2 and "no answer" in proc.stderr, proc.stderr
