"""Benchmarks tell the truth (issue 20): a missed bound exits 1, a broken dialect is refused
before anything is timed, `bench transfer` and `bench latency` judge command latency by one
rule, each protocol's rows do not depend on which others run, a profile used outside the
distances it was measured at says so, `bench integrity --keep` takes what users type (real
processes)."""

from __future__ import annotations

import json
from pathlib import Path

from conftest import ROOT, assert_no_traceback, run_ttctl
from ttctl.bench import latency as lat
from ttctl.link.model import load_profile

BROKEN = ROOT / "tests" / "dialects" / "broken" / "keywords.xml"
FAR = "[far]\n[far.up]\nrate_Bps = [[120, 300]]\nloss = [[120, 0.01]]\n[far.down]\nrate_Bps = [[120, 3000]]\n" \
      "loss = [[120, 0.01]]\n"


def _transfer(*args: str) -> tuple[int, dict]:
    proc = run_ttctl("bench", "transfer", "--quick", "--seeds", "1", "--json", *args, timeout=300)
    assert_no_traceback(proc)
    return proc.returncode, json.loads(proc.stdout)


def test_bench_transfer_exits_1_on_a_missed_bound_and_judges_latency_by_bench_latencys_rule() -> None:
    code, rep = _transfer("--protocols", "ttctl,thesis")
    missed = [c["check"] for c in rep["checks"] if not c["ok"]]
    assert missed, rep["checks"]  # one seed, virtual time: the 10 % row misses its floors (deterministic)
    assert code == 1
    idle, _ = rep["latency"]
    check = next(c for c in rep["checks"] if c["check"] == "command p95 during upload")
    bound_ms = 1000 * lat.bound_s(load_profile("m100"), 10.0)  # what `bench latency` allows on the model
    assert check["ceiling"] == round(idle["p95_ms"] + bound_ms, 1)
    # ... and `bench latency` states the same ceiling for the same profile and distance
    proc = run_ttctl("bench", "latency", "--count", "10", "--json", timeout=120)
    assert json.loads(proc.stdout)["bound_ms"] == round(bound_ms, 1)
    # each protocol's rows are its own: ttctl's are the same alone
    _, alone = _transfer("--protocols", "ttctl")
    assert [r for r in rep["rows"] if r["protocol"] == "ttctl"] == alone["rows"]


def test_bench_gen_refuses_a_broken_dialect_before_timing(tmp_path: Path) -> None:
    proc = run_ttctl("bench", "gen", str(BROKEN), "--runs", "1", timeout=120)
    assert proc.returncode == 2, proc.stderr
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("ttctl: error: ") and "gen refuses this dialect" in lines[0]
    assert "[KEYWORD]" in lines[0]


def test_a_profile_used_outside_its_measured_distances_says_it_is_extrapolated(tmp_path: Path) -> None:
    far = tmp_path / "far.toml"
    far.write_text(FAR)
    for d, said in (("10", True), ("120", False), ("150", True)):
        proc = run_ttctl("bench", "latency", "--count", "5", "--profile-file", str(far), "--distance", d, "--json",
                         timeout=120)
        assert ("is extrapolated at" in proc.stderr) == said, (d, proc.stderr)
        assert (json.loads(proc.stdout)["extrapolated"] is not None) == said
        proc = run_ttctl("send-file", "nope", "--to", "udpout:127.0.0.1:9", "--profile-file", str(far),
                         "--distance", d)
        assert ("ttctl: warning: profile 'far' is extrapolated at" in proc.stderr) == said, proc.stderr
    assert load_profile("m100").extrapolated(10.0) is None and load_profile("lan").extrapolated(500.0) is None
    assert "m100" in (load_profile("m100").extrapolated(250.0) or "")


def test_bench_integrity_keep_takes_a_relative_folder_and_refuses_a_file(tmp_path: Path) -> None:
    (tmp_path / "a-file").write_text("x")
    proc = run_ttctl("bench", "integrity", "--rounds", "1", "--keep", "a-file", cwd=tmp_path, timeout=60)
    assert proc.returncode == 2 and proc.stderr.strip() == \
        "ttctl: error: --keep a-file is not a folder (it keeps every process's output)"
    proc = run_ttctl("bench", "integrity", "--rounds", "1", "--topology", "direct", "--keep", "kept", "--json",
                     cwd=tmp_path, timeout=120)
    assert_no_traceback(proc)
    rep = json.loads(proc.stdout)
    assert proc.returncode == 0 and rep["direct"]["violations"] == [], proc.stdout
    assert (tmp_path / "kept" / "direct").is_dir()
