"""`ttctl bench gcs`: a QGroundControl-like ground station through the tablet end's bridge and
through the naive forwarder, on real processes (onboard end, relay with 10 % loss, tablet end)
on 127.0.0.1. The runs are short (--quick); the tests check that the figures are real (measured,
the mission really went up and came back) and that the report says what it measured."""

from __future__ import annotations

import io
import json
import re
from pathlib import Path
from typing import Any

import pytest

from conftest import assert_no_traceback, run_ttctl
from ttctl.bench.gcs_report import FLOORS, print_report

FIGURES = ("connect_s", "params_s", "upload_s", "download_s", "age_p50_ms", "age_p95_ms", "idle_p50_ms",
           "idle_p95_ms", "gcs_p50_ms", "gcs_p95_ms")


def _bench(*extra: str) -> dict[str, Any]:
    proc = run_ttctl("bench", "gcs", "--quick", "--json", *extra, timeout=150)
    assert_no_traceback(proc)
    assert proc.returncode in (0, 1), proc.stderr  # 1: a floor missed; never 2 or a crash
    rep = json.loads(proc.stdout)
    counted = [c for c in rep["checks"] if c["counts"]]
    assert proc.returncode == (0 if all(c["ok"] for c in counted) else 1)
    return rep


@pytest.fixture(scope="module")
def both() -> dict[str, Any]:
    return _bench()


def test_bridge_figures_are_measured_and_the_mission_went_up_and_came_back(both: dict[str, Any]) -> None:
    runs = {r["mode"]: r for r in both["runs"]}
    assert set(runs) == {"bridge", "naive"}
    b = runs["bridge"]
    assert b["started"] and b["failed"] == {}, b
    for key in FIGURES:
        assert isinstance(b[key], float) and b[key] > 0, (key, b[key])
    assert b["items_checked"]  # the 10 items downloaded are the 10 uploaded
    assert b["param_count"] > 0 and b["ages"] > 0
    assert "SYSTEM_TIME" in b["age_method"]
    assert b["connect_s"] >= b["params_s"] + b["heartbeat_s"]
    assert b["age_p50_ms"] <= b["age_p95_ms"] and b["idle_p50_ms"] <= b["idle_p95_ms"]
    assert len(b["idle_ms"]) == both["commands"] == 4
    assert b["gcs_commands"] >= 4 and len(b["gcs_ms"]) + b["gcs_failed"] == b["gcs_commands"]


def test_naive_forwarder_with_qgcs_ids_fails_and_the_checks_say_so(both: dict[str, Any]) -> None:
    """QGroundControl's default 255/190 is the tablet's own id: through a plain forwarder its
    HEARTBEAT is taken for the tablet's, so the vehicle never answers it as a ground station;
    the bridge carries it under a free id. The checks count the naive forwarder as failed."""
    n = next(r for r in both["runs"] if r["mode"] == "naive")
    assert n["started"]
    assert "no HEARTBEAT" in n["failed"]["connect"]
    assert n["connect_s"] is None and n["upload_s"] is None
    assert n["idle_p50_ms"] is not None  # the app itself gets through the forwarder
    vs = {c["check"]: c for c in both["checks"] if c["kind"] == "vs naive"}
    assert vs["connect_s"]["naive"] == "failed" and vs["connect_s"]["ok"]
    floors = {c["check"]: c for c in both["checks"] if c["kind"] == "floor"}
    assert set(floors) == {*FLOORS, "gcs_p95_ms"}
    assert all(c["counts"] for c in floors.values())  # 10 m, 10 % random loss: the conditions
    assert floors["gcs_p95_ms"]["floor"] == pytest.approx(
        next(r for r in both["runs"] if r["mode"] == "bridge")["idle_p95_ms"] + 200, abs=0.1)


def test_the_table_shows_both_columns_and_the_floors(both: dict[str, Any]) -> None:
    out = io.StringIO()
    print_report(both, out)
    text = out.getvalue()
    assert "bridge" in text and "naive/bridge" in text
    assert re.search(r"connect, QGC-like \(s\) .*\d+\.\d .*failed .*naive failed .*<= 10, 3x", text)
    assert re.search(r"mission upload, 10 items \(s\) .*\d+\.\d", text)
    assert "naive: connect failed: no HEARTBEAT" in text
    assert "SYSTEM_TIME" in text and "not MAVSDK" in text


def test_naive_forwarder_with_another_id_gets_through() -> None:
    """The naive forwarder really forwards: with a ground-station id other than the tablet's
    it connects and moves the mission, so its figures are measurements, not a broken pipe."""
    rep = _bench("--only", "naive", "--gcs-id", "254/190")
    (n,) = rep["runs"]
    assert n["mode"] == "naive" and n["failed"] == {}, n
    assert n["connect_s"] > 0 and n["upload_s"] > 0 and n["items_checked"]
    assert rep["gcs_id"] == "254/190"


@pytest.mark.parametrize(("args", "words"), [
    (["--distance", "ten"], "--distance: 'ten' is not a number"),
    (["--gcs-id", "300/1"], "--gcs-id: 300/1 is outside"),
    (["--only", "both,naive"], "--only must be"),
    (["--loss-model", "bursty"], "--loss-model must be"),
])
def test_bad_options_are_one_line_and_exit_2(args: list[str], words: str) -> None:
    proc = run_ttctl("bench", "gcs", *args, timeout=30)
    assert_no_traceback(proc)
    assert proc.returncode == 2 and words in proc.stderr, proc.stderr


def test_sigterm_stops_the_runs_processes(tmp_path: Any) -> None:
    """Stopped mid-run (SIGTERM, as a CI's timeout does), the bench ends its relay, onboard and
    tablet processes with it, in one line and exit 130."""
    import os
    import signal
    import subprocess
    import time

    from conftest import ttctl_cmd

    args = ["bench", "gcs", "--quick", "--only", "bridge", "--keep", str(tmp_path / "k")]
    proc = subprocess.Popen([*ttctl_cmd(), *args],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    children: set[int] = set()
    end = time.monotonic() + 30
    while time.monotonic() < end and len(children) < 3:  # onboard, relay, tablet
        out = subprocess.run(["pgrep", "-P", str(proc.pid)], capture_output=True, text=True).stdout
        children |= {int(x) for x in out.split()}
        time.sleep(0.2)
    assert len(children) >= 3, children
    proc.send_signal(signal.SIGTERM)
    _, err = proc.communicate(timeout=30)
    assert proc.returncode == 130 and "interrupted" in err and "Traceback" not in err, err
    for pid in children:
        try:
            os.kill(pid, 0)
        except ProcessLookupError:
            continue
        # a zombie is gone too (its parent has not reaped it yet): only a live one fails
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
        assert state == "Z", f"process {pid} outlived the bench"
