"""`ttctl bench link`: the thesis's measurement method on the link model reproduces what the
thesis measured and DJI documents; plots of both benchmark reports."""

from __future__ import annotations

import json
import statistics
import sys
from pathlib import Path
from typing import Any

import pytest

from ttctl.bench import linkbench
from ttctl.errors import Fail
from ttctl.link.model import ProfileError, load_profile

PNG = b"\x89PNG\r\n\x1a\n"


@pytest.fixture(scope="module")
def report() -> dict[str, Any]:
    return linkbench.measure(load_profile("m100"))


def _up(report: dict[str, Any], distance: float, size: int | None = None) -> list[dict[str, Any]]:
    return [r for r in report["uplink"]["rows"] if r["distance_m"] == distance and (size in (None, r["size"]))]


def _down(report: dict[str, Any], distance: float, rate: int) -> dict[str, Any]:
    return next(r for r in report["downlink"]["rows"] if r["distance_m"] == distance and r["rate_hz"] == rate)


def test_method_is_the_theses(report: dict[str, Any]) -> None:
    up, down = report["uplink"], report["downlink"]
    assert up["sizes"] == [1, 10, 20, 30, 40, 50, 60, 70, 80, 90, 100]
    assert up["distances_m"] == [10, 50, 100, 150, 200]
    assert down["rates_hz"] == list(range(10, 101, 10)) and down["distances_m"] == [10, 200]
    assert len(up["rows"]) == 55 and len(down["rows"]) == 20
    assert all(r["sent"] == 100 for r in up["rows"] + down["rows"])
    assert down["size"] == 100


def test_uplink_at_best_half_the_advertised_rate(report: dict[str, Any]) -> None:
    best = max(r["throughput_Bps"] for r in report["uplink"]["rows"])
    assert report["uplink"]["advertised_Bps"] == 1000
    assert 450 <= best <= 550
    assert best == max(r["throughput_Bps"] for r in _up(report, 10))


def test_uplink_throughput_falls_about_4x_with_distance(report: dict[str, Any]) -> None:
    near = _up(report, 10, 100)[0]["throughput_Bps"]
    far = _up(report, 200, 100)[0]["throughput_Bps"]
    assert 3.5 <= near / far <= 4.5
    thr = [_up(report, d, 100)[0]["throughput_Bps"] for d in (10, 50, 100, 150, 200)]
    assert thr == sorted(thr, reverse=True)
    # and it falls before losses do: at 150 m throughput is already halved, losses still few
    assert _up(report, 150, 100)[0]["throughput_Bps"] <= 0.5 * near


def test_uplink_losses_few_to_150m_then_plummet(report: dict[str, Any]) -> None:
    for d in (10, 50, 100, 150):
        lost = [r["lost"] for r in _up(report, d)]
        assert statistics.mean(lost) <= 3 and max(lost) <= 8, (d, lost)
    far = [r["lost"] for r in _up(report, 200)]
    assert statistics.mean(far) >= 30 and min(far) >= 20


def test_packet_size_has_little_effect_on_loss(report: dict[str, Any]) -> None:
    for d in (10, 50, 100, 150, 200):
        rows = _up(report, d)
        small = statistics.mean(r["lost"] for r in rows if r["size"] <= 40)
        large = statistics.mean(r["lost"] for r in rows if r["size"] >= 60)
        assert abs(small - large) <= (10 if d == 200 else 3), d


def test_downlink_a_third_lost_at_100hz_but_more_throughput(report: dict[str, Any]) -> None:
    for d in (10, 200):
        top = _down(report, d, 100)
        assert 25 <= top["lost"] <= 40
        assert top["overflow"] >= 20  # the SDK's queue drops them, not the radio
        for rate in (10, 20, 30, 40, 50):
            low = _down(report, d, rate)
            assert low["lost"] <= 3
            assert top["throughput_Bps"] > 1.2 * low["throughput_Bps"]
        assert top["throughput_Bps"] >= 0.95 * max(_down(report, d, r)["throughput_Bps"] for r in range(10, 101, 10))
        assert top["throughput_Bps"] < report["downlink"]["advertised_Bps"]


def test_downlink_distance_hardly_matters(report: dict[str, Any]) -> None:
    for rate in range(10, 101, 10):
        a, b = _down(report, 10, rate), _down(report, 200, rate)
        assert abs(a["throughput_Bps"] - b["throughput_Bps"]) <= 0.1 * a["throughput_Bps"]
        assert abs(a["lost"] - b["lost"]) <= 10


def test_all_facts_hold(report: dict[str, Any]) -> None:
    assert len(report["facts"]) >= 9
    assert all(f["ok"] for f in report["facts"]), [f for f in report["facts"] if not f["ok"]]


def test_run_prints_json_and_tables(capsys: pytest.CaptureFixture[str]) -> None:
    rep = linkbench.run(load_profile("m100"), True, None)
    out = json.loads(capsys.readouterr().out)
    assert out == json.loads(json.dumps(rep))
    linkbench.run(load_profile("m100"), False, None)
    text = capsys.readouterr().out
    assert "uplink" in text and "downlink" in text and "200 m" in text


def test_run_unknown_profile_is_a_clean_error() -> None:
    with pytest.raises(ProfileError, match="unknown link profile"):
        linkbench.run(load_profile("nope"), True, None)


def test_plots_without_matplotlib_say_what_to_install(monkeypatch: pytest.MonkeyPatch) -> None:
    from ttctl.bench import plots

    for name in [m for m in sys.modules if m == "matplotlib" or m.startswith("matplotlib.")]:
        monkeypatch.delitem(sys.modules, name)
    monkeypatch.setitem(sys.modules, "matplotlib", None)  # import matplotlib -> ImportError
    with pytest.raises(RuntimeError, match=r"ttctl\[plot\]") as e:
        plots.plot_link({}, "unused.png")
    assert isinstance(e.value, Fail)  # the command line prints it as one line
    with pytest.raises(RuntimeError, match=r"pip install 'ttctl\[plot\]'"):
        plots.require_matplotlib()


def test_plot_link_writes_png(report: dict[str, Any], tmp_path: Path) -> None:
    pytest.importorskip("matplotlib")
    from ttctl.bench.plots import plot_link

    out = tmp_path / "link.png"
    plot_link(report, str(out))
    assert out.read_bytes()[:8] == PNG and out.stat().st_size > 10_000


def test_run_with_plot(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    pytest.importorskip("matplotlib")
    out = tmp_path / "link.png"
    linkbench.run(load_profile("psdk"), True, str(out))
    assert out.read_bytes()[:8] == PNG
    assert json.loads(capsys.readouterr().out)["profile"] == "psdk"


def test_plot_transfer_writes_png(tmp_path: Path) -> None:
    pytest.importorskip("matplotlib")
    from ttctl.bench.plots import plot_transfer

    rows = []
    for direction in ("up", "down"):
        for loss, model in ((0.0, "random"), (0.1, "random"), (0.1, "burst"), (0.3, "random"), (0.3, "burst")):
            for proto, eff in (("ttctl", 0.9 * (1 - loss)), ("thesis", 0.9 - 2 * loss), ("mavftp", 0.7 - loss)):
                rows.append({"protocol": proto, "direction": direction, "loss": loss, "loss_model": model,
                             "efficiency": eff, "ok": proto != "thesis" or loss < 0.3})
    out = tmp_path / "transfer.png"
    plot_transfer({"profile": "m100", "distance_m": 10.0, "file_bytes": 65536, "rows": rows}, str(out))
    assert out.read_bytes()[:8] == PNG and out.stat().st_size > 10_000
