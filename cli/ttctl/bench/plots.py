"""PNG plots of the benchmark reports. matplotlib is optional (`pip install 'ttctl[plot]'`): it is
imported only here, only when a plot is asked for, and figures are drawn on an Agg canvas (no
display, no change to pyplot's global backend)."""

from __future__ import annotations

import contextlib
import os
import tempfile
from collections.abc import Callable
from typing import Any, BinaryIO

from ..safeio import output_problem

INSTALL_HINT = "plotting needs matplotlib: pip install 'ttctl[plot]'"


def _missing() -> RuntimeError:
    """A RuntimeError that the command line also prints as a clean one-line error."""
    try:
        from ..errors import Fail
    except ImportError:  # pragma: no cover - the CLI's dependencies are ttctl's
        return RuntimeError(INSTALL_HINT)

    class PlotUnavailable(Fail, RuntimeError):
        pass

    return PlotUnavailable(INSTALL_HINT)


def require_matplotlib(path: str | None = None) -> None:
    """Fail early (before a long benchmark) if plots cannot be drawn, or not to `path`."""
    _figure()
    if path is not None:
        problem = output_problem(path)
        if problem:
            from ..errors import Fail

            raise Fail(problem)


def save_atomically(fig: Any, path: str) -> None:
    """Write the PNG beside its final name, then rename: never a partial file under it."""
    write_atomically(path, lambda fh: fig.savefig(fh, format="png", dpi=110))


def write_atomically(path: str, write: Callable[[BinaryIO], Any]) -> None:
    """`write` fills a temporary file beside `path`, which is then renamed to it: never a
    partial file under the final name. It gets the mode an ordinary new file would (mkstemp's
    are 0600)."""
    folder = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(prefix=f".{os.path.basename(path)}.", suffix=".tmp", dir=folder)
    try:
        with os.fdopen(fd, "wb") as fh:
            write(fh)
        mask = os.umask(0)
        os.umask(mask)
        os.chmod(tmp, 0o666 & ~mask)
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise


def _figure(**kw: Any) -> Any:
    try:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure
    except ImportError:
        raise _missing() from None
    fig = Figure(**kw)
    FigureCanvasAgg(fig)  # Agg for this figure only: no global backend switch, no display
    return fig


def _save(fig: Any, path: str) -> None:
    save_atomically(fig, path)


def plot_transfer(report: dict[str, Any], path: str) -> None:
    """Efficiency (goodput / capacity) per protocol against loss: up and down by random and
    burst loss, with the floor ttctl must meet (0.88 without loss, 0.80 x (1 - p) with it)."""
    fig = _figure(figsize=(11, 8), layout="constrained")
    rows = report["rows"]
    protocols = list(dict.fromkeys(r["protocol"] for r in rows))
    losses = sorted({r["loss"] for r in rows})
    top = max(losses) if losses else 0.3
    axes = fig.subplots(2, 2, sharex=True, sharey=True, squeeze=False)
    for i, direction in enumerate(("up", "down")):
        for j, model in enumerate(("random", "burst")):
            ax = axes[i][j]
            for p in protocols:
                pts = sorted((r["loss"], r["efficiency"], r["ok"]) for r in rows
                             if r["protocol"] == p and r["direction"] == direction
                             and (r["loss_model"] == model or r["loss"] == 0))
                if not pts:
                    continue
                xs = [x for x, _, _ in pts]
                ys = [y for _, y, _ in pts]
                (line,) = ax.plot(xs, ys, marker="o", label=p)
                bad = [(x, y) for x, y, ok in pts if not ok]
                if bad:
                    ax.plot([x for x, _ in bad], [y for _, y in bad], linestyle="none", marker="x", markersize=10,
                            color=line.get_color(), label=f"{p} (failed)")
            xs = [0.0, top]
            ax.plot(xs, [0.80 * (1 - x) for x in xs], linestyle="--", color="grey", label="floor 0.80 x (1 - p)")
            ax.plot([0.0], [0.88], marker="_", markersize=18, color="grey", linestyle="none",
                    label="floor at 0% loss (0.88)")
            ax.set_title(f"{direction}link, {model} loss")
            ax.set_ylim(0, 1.05)
            ax.grid(True, alpha=0.3)
            if i == 1:
                ax.set_xlabel("packet loss p")
            if j == 0:
                ax.set_ylabel("efficiency (goodput / capacity)")
    seen: dict[str, Any] = {}
    for row in axes:
        for ax in row:
            for h, label in zip(*ax.get_legend_handles_labels(), strict=True):
                seen.setdefault(label, h)
    fig.legend(list(seen.values()), list(seen), loc="outside lower center", ncols=min(len(seen), 4),
               fontsize="small")
    fig.suptitle(f"{report.get('file_bytes', 0) // 1024} KiB over {report.get('profile', '?')} at "
                 f"{report.get('distance_m', 0):g} m (virtual time)")
    _save(fig, path)


def plot_link(report: dict[str, Any], path: str) -> None:
    """Uplink throughput and loss against packet size per distance; downlink loss and
    throughput against the onboard send rate per distance."""
    fig = _figure(figsize=(11, 8), layout="constrained")
    (a, b), (c, d) = fig.subplots(2, 2, squeeze=False)
    up = report["uplink"]
    for dist in up["distances_m"]:
        rows = sorted((r for r in up["rows"] if r["distance_m"] == dist), key=lambda r: r["size"])
        sizes = [r["size"] for r in rows]
        a.plot(sizes, [r["throughput_Bps"] for r in rows], marker="o", label=f"{dist:g} m")
        b.plot(sizes, [r["lost"] for r in rows], marker="o", label=f"{dist:g} m")
    if up.get("advertised_Bps"):
        a.axhline(up["advertised_Bps"], linestyle="--", color="grey", label="advertised")
    a.set(title="uplink throughput (tablet's count)", xlabel="packet size (B)", ylabel="B/s")
    b.set(title=f"uplink packets lost of {up['packets']}", xlabel="packet size (B)", ylabel="lost")
    down = report["downlink"]
    for dist in down["distances_m"]:
        rows = sorted((r for r in down["rows"] if r["distance_m"] == dist), key=lambda r: r["rate_hz"])
        rates = [r["rate_hz"] for r in rows]
        c.plot(rates, [r["lost"] for r in rows], marker="o", label=f"{dist:g} m")
        d.plot(rates, [r["throughput_Bps"] for r in rows], marker="o", label=f"{dist:g} m")
    if down.get("advertised_Bps"):
        d.axhline(down["advertised_Bps"], linestyle="--", color="grey", label="advertised")
    c.set(title=f"downlink packets lost of {down['packets']} ({down['size']} B each)", xlabel="send loop (Hz)",
          ylabel="lost")
    d.set(title="downlink throughput (received)", xlabel="send loop (Hz)", ylabel="B/s")
    for ax in (a, b, c, d):
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="small")
    fig.suptitle(f"DTT link model '{report.get('profile', '?')}': the thesis's measurement (ch. 3.9)")
    _save(fig, path)
