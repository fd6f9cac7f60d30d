"""`ttctl link fit` on real measurements: `ttctl bench link --to` through `ttctl link relay`
processes whose settings are known, then the fit must give those settings back; the fitted
profile must replay the measurement (`bench link --like`) and, driving a relay of its own,
measure like the original link. And the same through Linux netem where a network namespace
with netem can be made."""

from __future__ import annotations

import json
import shutil
import subprocess
import tomllib
from pathlib import Path

import pytest

from conftest import assert_no_traceback, run_ttctl, ttctl_cmd
from e2e_lib import LOCAL, Start, free_port

RATE = 4000


def serve(start: Start, name: str) -> int:
    port = free_port()
    start(name, "bench", "serve", "--listen", f"udpin:{LOCAL}:{port}").wait_for("listening on")
    return port


def relay(start: Start, name: str, to: int, *extra: str) -> int:
    port = free_port()
    p = start(name, "link", "relay", "--listen", f"udpin:{LOCAL}:{port}", "--to", f"udpout:{LOCAL}:{to}",
              "--stats-interval", "0", *extra)
    p.wait_for("relay: udpin")
    return port


def measure_bg(port: int, out: Path, *args: str) -> subprocess.Popen[str]:
    return subprocess.Popen(ttctl_cmd() + ["bench", "link", "--to", f"udpout:{LOCAL}:{port}", "-o", str(out),
                                           *args], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)


def finish(p: subprocess.Popen[str], timeout: float = 90) -> None:
    _, err = p.communicate(timeout=timeout)
    assert p.returncode == 0, err


def fit(tmp: Path, *files: Path) -> tuple[dict, dict]:
    out = tmp / "fitted.toml"
    proc = run_ttctl("link", "fit", *map(str, files), "-o", str(out), "--json")
    assert_no_traceback(proc)
    assert proc.returncode == 0, proc.stderr
    report = json.loads(proc.stdout)
    assert tomllib.loads(out.read_text())["fitted"]["up"]["rate_Bps"] == report["profile"]["up"]["rate_Bps"]
    return report, tomllib.loads(out.read_text())["fitted"]


def test_fit_recovers_a_bursty_relay_and_the_fit_measures_like_it(start: Start, tmp_path: Path) -> None:
    """Relay: 4000 B/s both ways, m100's 40 ms latency and 2-packet buffer, 10 % loss in
    Gilbert-Elliott bursts of mean 3."""
    port = relay(start, "relay", serve(start, "serve"), "--profile", "m100", "--rate", str(RATE), "--loss", "0.1",
                 "--loss-model", "burst", "--burst-mean", "3", "--seed", "5")
    fast, slow = tmp_path / "fast.json", tmp_path / "slow.json"
    # outpaced both ways (rate, buffer), and a downlink rate that is not (the radio's loss runs)
    finish(measure_bg(port, fast, "--rate", str(2 * RATE), "--sizes", "50,100", "--rates", "20,80", "--count",
                      "200", "--distance", "10", "--label", "relay, bursts"))
    # paced below the link's rate: the uplink radio's own loss runs
    finish(measure_bg(port, slow, "--rate", str(RATE // 2), "--sizes", "100", "--direction", "up", "--count",
                      "300", "--distance", "10"))
    report, prof = fit(tmp_path, fast, slow)
    for d in ("up", "down"):
        p = prof[d]
        assert abs(p["rate_Bps"][0][1] - RATE) <= 0.1 * RATE, p
        assert abs(p["loss"][0][1] - 0.1) <= 0.06, p
        assert p["queue_packets"] == 2, p
        assert abs(p["latency_s"] - 0.04) <= 0.005, p
        assert p["loss_model"] == "burst" and 1.8 <= p["burst_mean"] <= 5.0, (p, report["notes"])
    assert all(r["ok"] for r in report["residuals"]), [r for r in report["residuals"] if not r["ok"]]
    # the fitted profile replays the measurement; ttctl's m100 (500 B/s up) does not
    fitted = tmp_path / "fitted.toml"
    like = run_ttctl("bench", "link", "--like", str(fast), "--profile-file", str(fitted), "--json")
    assert like.returncode == 0, like.stdout[-3000:]
    assert json.loads(like.stdout)["ok"] is True
    stock = run_ttctl("bench", "link", "--like", str(fast), "--profile", "m100", "--json")
    assert stock.returncode == 1 and json.loads(stock.stdout)["ok"] is False
    # the loop closed: a relay driven by the fitted profile measures like the original link
    port2 = relay(start, "relay2", serve(start, "serve2"), "--profile-file", str(fitted), "--seed", "9")
    again = tmp_path / "again.json"
    finish(measure_bg(port2, again, "--rate", str(2 * RATE), "--sizes", "100", "--direction", "up", "--count",
                      "150"))
    row = json.loads(again.read_text())["uplink"]["rows"][0]
    assert abs(row["capacity_Bps"] - prof["up"]["rate_Bps"][0][1]) <= 0.1 * RATE, row


def test_fit_recovers_rate_and_loss_against_distance_and_random_loss(start: Start, tmp_path: Path) -> None:
    """A profile file with rate and loss falling with distance, random loss, a 4-packet buffer
    and 25 ms latency, relayed at 50 m and 150 m at once."""
    known = tmp_path / "known.toml"
    known.write_text("""[field]
mtu = 100
[field.up]
rate_Bps = [[0, 4000], [200, 2000]]
loss = [[0, 0.02], [200, 0.2]]
latency_s = 0.025
queue_packets = 4
[field.down]
rate_Bps = [[0, 4000], [200, 2000]]
loss = [[0, 0.02], [200, 0.2]]
latency_s = 0.025
queue_packets = 4
""")
    runs = []
    for dist in (50, 150):
        port = relay(start, f"relay{dist}", serve(start, f"serve{dist}"), "--profile-file", str(known),
                     "--distance", str(dist), "--seed", str(dist))
        out = tmp_path / f"at{dist}.json"
        runs.append((out, measure_bg(port, out, "--rate", "6000", "--sizes", "50,100", "--rates", "20,90",
                                     "--count", "200", "--distance", str(dist), "--label", f"{dist} m")))
    for _, p in runs:
        finish(p)
    report, prof = fit(tmp_path, *(out for out, _ in runs))
    for d in ("up", "down"):
        p = prof[d]
        rates, losses = dict(map(tuple, p["rate_Bps"])), dict(map(tuple, p["loss"]))
        assert sorted(rates) == [50.0, 150.0]
        assert abs(rates[50.0] - 3500) <= 350 and abs(rates[150.0] - 2500) <= 250, p
        assert abs(losses[50.0] - 0.065) <= 0.05 and abs(losses[150.0] - 0.155) <= 0.06, p
        assert losses[150.0] > losses[50.0]
        assert p["queue_packets"] == 4, p
        assert abs(p["latency_s"] - 0.025) <= 0.005, p
        assert p["loss_model"] == "random", (p, report["notes"])
    assert all(r["ok"] for r in report["residuals"]), [r for r in report["residuals"] if not r["ok"]]


def _netem_problem() -> str | None:
    """Why netem in a fresh network namespace cannot be had here, or None."""
    if not (shutil.which("unshare") and shutil.which("tc") and shutil.which("ip")):
        return "needs unshare, tc and ip (iproute2)"
    p = subprocess.run(["unshare", "-rn", "sh", "-c", "ip link set lo up && tc qdisc add dev lo root netem delay 1ms"],
                       capture_output=True, text=True, timeout=20)
    if p.returncode != 0:
        why = (p.stderr or p.stdout).strip().splitlines()
        return f"no netem in a network namespace here ({why[-1] if why else f'exit {p.returncode}'})"
    return None


def test_bench_link_through_netem_recovers_its_delay_and_loss(tmp_path: Path) -> None:
    """Linux netem on the loopback of a private network namespace: 30 ms each way (60 ms round
    trip on lo, which both directions cross), 10 % loss, 4000 B/s. `bench serve` and `bench link`
    run inside it; the fit gives the delay and loss back."""
    problem = _netem_problem()
    if problem:
        pytest.skip(problem)
    out = tmp_path / "netem.json"
    cmd = " ".join(ttctl_cmd())
    script = f"""set -e
ip link set lo up
tc qdisc add dev lo root netem delay 30ms loss 10% rate 32kbit
{cmd} bench serve --listen udpin:127.0.0.1:14570 2>/dev/null &
S=$!
trap 'kill $S' EXIT
sleep 1.5
{cmd} bench link --to udpout:127.0.0.1:14570 --rate 8000 --sizes 100 --rates 20,80 --count 200 -o {out} \
  >/dev/null
"""
    p = subprocess.run(["unshare", "-rn", "sh", "-c", script], capture_output=True, text=True, timeout=180)
    assert p.returncode == 0, p.stderr
    rep = json.loads(out.read_text())
    # every datagram leaves through lo's one qdisc: 30 ms each way, plus its time at 32 kbit/s
    # (headers included: an 18-byte echo is 46 bytes on the wire, 11.5 ms)
    assert 55 <= rep["latency"]["rtt_p50_ms"] <= 120, rep["latency"]
    for row in rep["uplink"]["rows"] + rep["downlink"]["rows"]:
        if row["capacity_Bps"] >= 0.9 * row["throughput_Bps"]:  # not outpaced: the loss is netem's
            assert abs(row["loss"] - 0.1) <= 0.08, row
    proc = run_ttctl("link", "fit", str(out), "-o", str(tmp_path / "netem.toml"), "--json")
    assert proc.returncode == 0, proc.stderr
    prof = json.loads(proc.stdout)["profile"]
    assert 0.02 <= prof["up"]["latency_s"] <= 0.045, prof
