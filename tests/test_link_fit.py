"""`ttctl link fit` and `--profile-file`: fits of measurements the model made from known
profiles (every parameter must come back), the written TOML, `bench link --like`, and bad
input of every kind (one line, exit 2, nothing written)."""

from __future__ import annotations

import dataclasses
import json
import os
import tomllib
from pathlib import Path
from typing import Any

import pytest

from conftest import assert_no_traceback, run_ttctl
from ttctl.bench import fit as F
from ttctl.bench import replay as R
from ttctl.errors import Fail
from ttctl.link.model import DirectionProfile, Profile, ProfileError, load_profile


def known(loss_model: str = "random", burst: float = 3.0, pacing: tuple[int, float] = (0, 0.0), queue: int = 3,
          latency: float = 0.03) -> Profile:
    up = DirectionProfile(rate_Bps=[[0, 3000], [200, 1000]], loss=[[0, 0.02], [200, 0.2]], latency_s=latency,
                          queue_packets=queue, pacing_bytes=pacing[0], pacing_interval_s=pacing[1],
                          loss_model=loss_model, burst_mean=burst, feedback=True)
    down = dataclasses.replace(up, rate_Bps=[[0, 6000], [200, 5000]], pacing_bytes=0, pacing_interval_s=0.0,
                               feedback=False)
    return Profile("known", "", 100, up, down)


def measurement(prof: Profile, dist: float, pace: float, sizes: list[int], rates: list[float], count: int,
                seed: int) -> dict[str, Any]:
    """What `bench link --to ... -o FILE.json` writes, made by the model itself, one-way delays
    biased as the live run's NTP-style clock offset biases them."""
    rtts = R.echoes_once(prof, dist, 20, seed)
    ups = [R.uplink_once(prof, dist, s, count, pace, seed + i) for i, s in enumerate(sizes)]
    downs = [R.downlink_once(prof, dist, r, count, seed + 50 + i) for i, r in enumerate(rates)]
    bias = R.offset_error(prof, dist) * 1e3
    for rows, sign in ((ups, -1), (downs, 1)):
        for row in rows:
            for k in ("owd_p50_ms", "owd_p95_ms", "owd_min_ms"):
                if k in row:
                    row[k] += sign * bias
    return {"conditions": {"count": count, "distance_m": dist, "label": f"{dist:g} m", "endpoint": "model",
                           "time": "", "ttctl_version": "test"},
            "partial": False, "latency": {"echoes": len(rtts), "rtt_p50_ms": round(R._pct(rtts, 0.5) * 1e3, 2)},
            "uplink": {"pace_Bps": pace, "sizes": sizes, "rows": ups},
            "downlink": {"size": 100, "rates_hz": rates, "rows": downs}}


def field_day(prof: Profile, distances: tuple[float, ...] = (50.0, 150.0), count: int = 400) -> list[F.Measurement]:
    """Per distance: one run that outpaces the link, one that does not (as the README's guide)."""
    out = []
    for d in distances:
        fast = measurement(prof, d, 6000, [20, 40, 60, 80, 100], [10, 30, 90], count, int(d) * 7)
        slow = measurement(prof, d, 0.6 * prof.up.rate_at(d), [100], [], count, int(d) * 7 + 1)
        out += [F.Measurement(f"fast{d:g}.json", fast, d), F.Measurement(f"slow{d:g}.json", slow, d)]
    return out


def test_fit_recovers_a_known_profile_with_random_loss() -> None:
    truth = known()
    f = F.fit(field_day(truth), load_profile("m100"), "fitted")
    for d in ("up", "down"):
        got, want = f.profile.direction(d), truth.direction(d)
        for dist in (50.0, 150.0):
            assert got.rate_at(dist) == pytest.approx(want.rate_at(dist), rel=0.03), (d, dist, got.rate_Bps)
            assert got.loss_at(dist) == pytest.approx(want.loss_at(dist), abs=0.04), (d, dist, got.loss)
        assert got.queue_packets == want.queue_packets
        assert got.latency_s == pytest.approx(want.latency_s, abs=0.002)
        assert got.loss_model == "random", f.notes
        assert got.pacing_bytes == 0
    assert all(r["ok"] for r in f.residuals), [r for r in f.residuals if not r["ok"]]


def test_fit_tells_bursts_and_finds_pacing() -> None:
    truth = known("burst", burst=3.0, pacing=(40, 0.03))
    f = F.fit(field_day(truth), load_profile("m100"), "fitted")
    up = f.profile.up
    assert (up.pacing_bytes, up.pacing_interval_s) == (40, pytest.approx(0.03, rel=0.01)), f.notes
    for d in ("up", "down"):
        got = f.profile.direction(d)
        assert got.loss_model == "burst" and 2.0 <= got.burst_mean <= 4.5, (d, f.notes)
        assert got.queue_packets == 3
    # the pacing floor binds for every size here: service times, not the nominal rate, must match
    for size in (20, 60, 100):
        assert up.service_time(size, 50.0) == pytest.approx(truth.up.service_time(size, 50.0), rel=0.03)
    assert all(r["ok"] for r in f.residuals), [r for r in f.residuals if not r["ok"]]


def test_fit_without_outpaced_rows_says_the_rate_is_a_lower_bound() -> None:
    truth = known()
    m = measurement(truth, 50.0, 500, [100], [5], 300, 3)
    f = F.fit([F.Measurement("gentle.json", m, 50.0)], load_profile("m100"), "fitted")
    assert any("never outpaced" in n and "lower bound" in n for n in f.notes), f.notes
    assert f.profile.up.rate_at(50.0) >= 500
    assert any("no saturated rows" in n for n in f.notes)


def test_the_replay_check_can_fail() -> None:
    """The residuals are a real test: ttctl's m100 does not reproduce this link."""
    truth = known()
    m = measurement(truth, 50.0, 6000, [50, 100], [20, 90], 300, 5)
    model = R.replay(load_profile("m100"), m, 50.0)
    checks = R.compare(m, model, load_profile("m100"), 50.0)
    assert not all(c["ok"] for c in checks)
    assert {c["figure"] for c in checks if not c["ok"]} >= {"capacity_Bps", "rtt_p50_ms"}
    model = R.replay(truth, m, 50.0)
    assert all(c["ok"] for c in R.compare(m, model, truth, 50.0))


def test_offset_error_correction() -> None:
    """An echo takes 36 ms up and 3 ms down on m100 at 10 m, so an NTP-style offset is 16.5 ms
    wrong, and a measured uplink delay reads that much low."""
    m100 = load_profile("m100")
    assert R.offset_error(m100, 10.0) == pytest.approx((18 / 500 - 18 / 6700) / 2)
    row = {"direction": "up", "owd_p50_ms": 100.0}
    assert R.true_delay_ms(row, 0.0165) == pytest.approx(116.5)
    assert R.true_delay_ms({**row, "direction": "down"}, 0.0165) == pytest.approx(83.5)


# ---- the command line ------------------------------------------------------------------------

def write(path: Path, report: dict[str, Any]) -> Path:
    path.write_text(json.dumps(report))
    return path


@pytest.fixture
def files(tmp_path: Path) -> list[Path]:
    return [write(tmp_path / m.path, m.report) for m in field_day(known("burst"), count=200)]


def test_cli_writes_a_profile_every_command_takes(files: list[Path], tmp_path: Path) -> None:
    out = tmp_path / "site.toml"
    proc = run_ttctl("link", "fit", *map(str, files), "-o", str(out))
    assert_no_traceback(proc)
    assert proc.returncode == 0, proc.stderr
    assert "residuals" in proc.stdout and "figures within tolerance" in proc.stdout
    text = out.read_text()
    assert text.startswith("# Link profile 'site', fitted by `ttctl link fit`")
    table = tomllib.loads(text)
    assert list(table) == ["site"] and table["site"]["up"]["loss_model"] == "burst"
    prof = load_profile(None, str(out))
    assert prof.name == "site" and prof.up.rate_at(50) == pytest.approx(2500, rel=0.05)
    # --profile-file where --profile is: the model bench, the replay, the latency bench
    proc = run_ttctl("bench", "link", "--profile-file", str(out), "--json")
    assert proc.returncode == 0, proc.stderr
    assert json.loads(proc.stdout)["profile"] == "site"
    proc = run_ttctl("bench", "link", "--like", str(files[0]), "--profile-file", str(out), "--json")
    assert proc.returncode == 0, proc.stdout[-2000:]
    assert json.loads(proc.stdout)["ok"] is True
    proc = run_ttctl("bench", "latency", "--profile-file", str(out), "--count", "5", "--size", "4000", "--json")
    assert_no_traceback(proc)
    assert json.loads(proc.stdout)["profile"] == "site", proc.stdout[-2000:]
    # and --profile picks one of several profiles in a file
    both = tmp_path / "both.toml"
    both.write_text(text + "\n" + text.replace("[site", "[other"))
    assert load_profile("other", str(both)).name == "other"


def test_cli_json(files: list[Path], tmp_path: Path) -> None:
    proc = run_ttctl("link", "fit", *map(str, files), "-o", str(tmp_path / "x.toml"), "--json", "--name", "field-1")
    assert proc.returncode == 0, proc.stderr
    rep = json.loads(proc.stdout)
    assert rep["profile"]["name"] == "field-1" and rep["residuals"] and rep["notes"]
    assert "field-1" in tomllib.loads((tmp_path / "x.toml").read_text())


def one_line_exit_2(proc: Any, match: str) -> None:
    assert_no_traceback(proc)
    assert proc.returncode == 2, (proc.returncode, proc.stdout, proc.stderr)
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("ttctl: error:"), proc.stderr
    assert match in lines[0], lines[0]


def _good(tmp: Path) -> dict[str, Any]:
    return json.loads(json.dumps(field_day(known(), distances=(50.0,), count=50)[0].report))


BAD_MEASUREMENTS = [
    ("notjson.json", b"{nope", "not JSON"),
    ("array.json", b"[1, 2]", "not a JSON object"),
    ("binary.json", b"\xff\xfe\x00", "not JSON"),
    ("empty.json", b"", "not JSON"),
    ("rows.csv", b"direction,size\nup,100\n", "the CSV has no round trips"),
]


@pytest.mark.parametrize(("name", "data", "match"), BAD_MEASUREMENTS)
def test_malformed_measurement_files(tmp_path: Path, name: str, data: bytes, match: str) -> None:
    bad = tmp_path / name
    bad.write_bytes(data)
    out = tmp_path / "out.toml"
    one_line_exit_2(run_ttctl("link", "fit", str(bad), "-o", str(out)), match)
    assert os.listdir(tmp_path) == [name]  # nothing written, not even a temporary file


MUTATIONS = [
    ("no conditions", lambda r: r.pop("conditions"), "no 'conditions' object"),
    ("count missing", lambda r: r["conditions"].pop("count"), "conditions.count"),
    ("pace zero", lambda r: r["uplink"].update(pace_Bps=0), "uplink.pace_Bps"),
    ("rows not a list", lambda r: r["downlink"].update(rows={}), "downlink.rows is not a list"),
    ("size a string", lambda r: r["uplink"]["rows"][0].update(size="big"), "uplink.rows[0].size"),
    ("received > sent", lambda r: r["uplink"]["rows"][0].update(received=10_000), "impossible values"),
    ("NaN loss", lambda r: r["uplink"]["rows"][0].update(loss=float("nan")), "uplink.rows[0].loss"),
    ("no rows", lambda r: (r["uplink"].update(rows=[]), r["downlink"].update(rows=[])), "no rows measured"),
    ("negative distance", lambda r: r["conditions"].update(distance_m=-5), "distance_m"),
    ("bad latency", lambda r: r.update(latency={"echoes": 3}), "latency has no rtt_p50_ms"),
    ("zero rate", lambda r: r["downlink"]["rows"][0].update(rate_hz=0), "rate_hz must be positive"),
    ("negative latency", lambda r: r.update(latency={"echoes": 3, "rtt_p50_ms": -5}), "a round trip takes a "
     "positive time"),
    ("negative capacity", lambda r: r["uplink"]["rows"][0].update(capacity_Bps=-1), "impossible values"),
]


@pytest.mark.parametrize(("what", "mutate", "match"), MUTATIONS, ids=[m[0] for m in MUTATIONS])
def test_measurement_files_with_wrong_fields(tmp_path: Path, what: str, mutate: Any, match: str) -> None:
    rep = _good(tmp_path)
    mutate(rep)
    bad = tmp_path / "m.json"
    bad.write_text(json.dumps(rep))
    one_line_exit_2(run_ttctl("link", "fit", str(bad), "-o", str(tmp_path / "out.toml")), match)
    assert not (tmp_path / "out.toml").exists()


def test_bad_outputs_and_options(tmp_path: Path, files: list[Path]) -> None:
    args = [str(f) for f in files]
    one_line_exit_2(run_ttctl("link", "fit", *args, "-o", str(tmp_path / "nowhere" / "x.toml")), "no folder")
    one_line_exit_2(run_ttctl("link", "fit", *args, "-o", str(tmp_path)), "must end in .toml")
    (tmp_path / "dir.toml").mkdir()
    one_line_exit_2(run_ttctl("link", "fit", *args, "-o", str(tmp_path / "dir.toml")), "is a directory")
    one_line_exit_2(run_ttctl("link", "fit", *args, "-o", str(tmp_path / "x.json")), "must end in .toml")
    one_line_exit_2(run_ttctl("link", "fit", *args, "-o", str(tmp_path / "x.toml"), "--name", "a b"),
                    "a profile name is")
    one_line_exit_2(run_ttctl("link", "fit", *args, "-o", str(tmp_path / "x.toml"), "--base", "nope"),
                    "unknown link profile 'nope'")
    one_line_exit_2(run_ttctl("link", "fit", str(tmp_path / "missing.json"), "-o", str(tmp_path / "x.toml")),
                    "No such file")
    # a file without a distance among files with one
    rep = json.loads(files[0].read_text())
    rep["conditions"].update(distance_m=None, label="somewhere")
    write(tmp_path / "nodist.json", rep)
    one_line_exit_2(run_ttctl("link", "fit", *args, str(tmp_path / "nodist.json"), "-o", str(tmp_path / "x.toml")),
                    "no distance")
    assert not (tmp_path / "x.toml").exists()
    assert not [p for p in os.listdir(tmp_path) if p.endswith(".tmp")]


def test_output_over_an_existing_profile_is_replaced_whole(tmp_path: Path, files: list[Path]) -> None:
    out = tmp_path / "site.toml"
    out.write_text("# the old one\n")
    proc = run_ttctl("link", "fit", *map(str, files), "-o", str(out), "--force")
    assert proc.returncode == 0, proc.stderr
    assert "the old one" not in out.read_text()
    # the input is never the output
    one_line_exit_2(run_ttctl("link", "fit", str(out), "-o", str(out)), "one of the measurements")
    assert "the old one" not in out.read_text() and out.read_text().startswith("# Link profile")


PROFILE_FILES = [
    ("missing", None, "No such file"),
    ("bad toml", "[x\n", "not TOML"),
    ("no profile", "a = 1\n", "holds no profile"),
    ("two profiles", "[a.up]\n[a.down]\n[b.up]\n[b.down]\n", "holds 2 profiles: pick one with --profile"),
    ("no down", "[a]\n[a.up]\nrate_Bps = [[0, 100]]\nloss = [[0, 0]]\n", "has no [a.down] table"),
    ("unknown field", "[a.up]\nrate_Bps = [[0, 100]]\nloss = [[0, 0]]\nspeed = 3\n[a.down]\n", "unknown or missing "
     "field 'speed'"),
    ("negative rate", "[a.up]\nrate_Bps = [[0, -1]]\nloss = [[0, 0]]\n[a.down]\nrate_Bps = [[0, 1]]\nloss = [[0, 0]]\n",
     "rates must be positive"),
    ("loss above 1", "[a.up]\nrate_Bps = [[0, 1]]\nloss = [[0, 1.5]]\n[a.down]\nrate_Bps = [[0, 1]]\nloss = [[0, 0]]\n",
     "loss must be in 0..1"),
    ("queue 0", "[a.up]\nrate_Bps = [[0, 1]]\nloss = [[0, 0]]\nqueue_packets = 0\n[a.down]\nrate_Bps = [[0, 1]]\n"
     "loss = [[0, 0]]\n", "queue_packets must be a whole number >= 1"),
    ("bad points", "[a.up]\nrate_Bps = 5\nloss = [[0, 0]]\n[a.down]\nrate_Bps = [[0, 1]]\nloss = [[0, 0]]\n",
     "list of [metres, value] pairs"),
    ("bad loss model", "[a.up]\nrate_Bps = [[0, 1]]\nloss = [[0, 0]]\nloss_model = \"gauss\"\n[a.down]\n"
     "rate_Bps = [[0, 1]]\nloss = [[0, 0]]\n", "loss_model must be one of"),
    ("mtu", "[a]\nmtu = 300\n[a.up]\nrate_Bps = [[0, 1]]\nloss = [[0, 0]]\n[a.down]\nrate_Bps = [[0, 1]]\n"
     "loss = [[0, 0]]\n", "mtu must be a whole number of bytes in 22..255"),
]


@pytest.mark.parametrize(("what", "text", "match"), PROFILE_FILES, ids=[p[0] for p in PROFILE_FILES])
def test_bad_profile_files_are_one_line_everywhere(tmp_path: Path, what: str, text: str | None,
                                                    match: str) -> None:
    path = tmp_path / "p.toml"
    if text is not None:
        path.write_text(text)
    with pytest.raises(ProfileError, match=match.replace("[", r"\[").replace("(", r"\(")):
        load_profile(None, str(path))
    if what in ("missing", "two profiles", "negative rate"):  # through each command that takes one
        for cmd in (["bench", "link"], ["bench", "transfer", "--quick"], ["bench", "latency"],
                    ["link", "relay", "--listen", "udpin:127.0.0.1:0", "--to", "udpout:127.0.0.1:9"],
                    ["send-file", "x", "--to", "udpout:127.0.0.1:9"],
                    ["recv-file", "--listen", "udpin:127.0.0.1:0", "--dir", str(tmp_path / "in")],
                    ["emulate", "onboard", "--no-gcs"], ["emulate", "tablet"],
                    ["hmd", "dump", "--to", "udpout:127.0.0.1:9", "--duration", "0.1"]):
            one_line_exit_2(run_ttctl(*cmd, "--profile-file", str(path), timeout=60), match.split(":")[0])
        assert not (tmp_path / "in").exists()


def test_unknown_profile_in_a_file_names_the_file(tmp_path: Path) -> None:
    path = tmp_path / "p.toml"
    path.write_text("[a.up]\nrate_Bps = [[0, 1]]\nloss = [[0, 0]]\n[a.down]\nrate_Bps = [[0, 1]]\nloss = [[0, 0]]\n")
    assert load_profile(None, str(path)).name == "a"
    with pytest.raises(ProfileError, match=r"unknown link profile 'b' in .*p\.toml \(known: a\)"):
        load_profile("b", str(path))
    with pytest.raises(Fail, match="no 'conditions'"):
        F.load_measurement(str(write(tmp_path / "m.json", {"uplink": {}})))


def test_a_negative_clock_offset_is_a_measurement_not_an_error(tmp_path: Path) -> None:
    """The two ends' clock offset has a sign (CI: `bench link` measured -0.02 ms and `link fit`
    refused it as "a time cannot be negative"); a negative round trip is still refused."""
    rep = _good(tmp_path)
    rep["latency"] = {"echoes": 20, "sent": 20, "rtt_p50_ms": 90.0, "rtt_p95_ms": 95.0, "rtt_min_ms": 85.0,
                      "owd_rtt_half_ms": 45.0, "clock_offset_ms": -0.02}
    good = tmp_path / "m.json"
    good.write_text(json.dumps(rep))
    proc = run_ttctl("link", "fit", str(good), "-o", str(tmp_path / "out.toml"))
    assert proc.returncode == 0, proc.stderr
    rep["latency"]["rtt_min_ms"] = -1.0
    good.write_text(json.dumps(rep))
    one_line_exit_2(run_ttctl("link", "fit", str(good), "-o", str(tmp_path / "out2.toml")), "latency.rtt_min_ms is -1")
