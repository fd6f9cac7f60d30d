"""`ttctl bench latency`: command latency idle and during transfers (the work is in ttctl.bench.latency)."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer

from ..errors import Fail
from .common import err
from .options import DialectIncludeOpt, DialectOpt, ProfileFileOpt
from .panels import LINK, OUTPUT, RUN, WORKLOAD

if TYPE_CHECKING:
    from ..bench.latency import Phase
    from ..link.model import Profile



def bench_latency(
    to: Annotated[str | None, typer.Option("--to", help="Measure live: the onboard end (ttctl emulate onboard, "
                                                        "recv-file), or a relay in front of it, as udpout:HOST:PORT "
                                                        "(or tcp:, udpin:). Without it: the link model, in virtual "
                                                        "time.", show_default=False, rich_help_panel=LINK)] = None,
    profile: Annotated[str | None, typer.Option("--profile", help="Link profile: the model's (without --to), or this "
                                                                  "end's pacing (with --to); default m100.",
                                                show_default=False, rich_help_panel=LINK)] = None,
    profile_file: ProfileFileOpt = None,
    distance: Annotated[float, typer.Option("--distance", help="Distance in metres.", min=0,
                                            rich_help_panel=LINK)] = 10.0,
    count: Annotated[int, typer.Option("--count", help="Commands per phase (idle, upload, download).", min=1,
                                       max=10_000, rich_help_panel=WORKLOAD)] = 50,
    interval: Annotated[float, typer.Option("--interval", help="One command every this many seconds (at a random "
                                                               "moment in the first half).", min=0.05,
                                            max=60, rich_help_panel=WORKLOAD)] = 1.0,
    size: Annotated[int | None, typer.Option("--size", help="Bytes of the file moved during the transfer phases "
                                                            "(sent again while commands remain; default 64 KiB, "
                                                            "2 MB on a profile with a MOP pipeline).", min=1,
                                             max=1 << 26, show_default=False, rich_help_panel=WORKLOAD)] = None,
    seed: Annotated[int, typer.Option("--seed", help="Random seed (model: the same seed, the same numbers).",
                                      rich_help_panel=RUN)] = 1,
    fetch: Annotated[str | None, typer.Option("--fetch", help="With --to: a file the peer serves (emulate onboard "
                                                              "--serve DIR), fetched during the download phase; "
                                                              "without it that phase is skipped.",
                                              show_default=False, rich_help_panel=WORKLOAD)] = None,
    timeout: Annotated[float, typer.Option("--timeout", help="With --to: seconds to wait for the peer's first "
                                                             "ack before giving up (exit 2).", min=0.1,
                                           max=600, rich_help_panel=RUN)] = 10.0,
    json_out: Annotated[bool, typer.Option("--json", help="Print the report as JSON.", rich_help_panel=OUTPUT)] = False,
    dialect: DialectOpt = None,
    include: DialectIncludeOpt = None,
) -> None:
    """Command latency (TT_ACTION_COMMAND -> TT_COMMAND_ACK): idle, during an upload and a download.

    p50/p95/max, retries, and during/idle ratios. On the link model in virtual
    time, or live (--to) against a real onboard end.

    Exit status:
      0    every transfer phase's p95 is within idle p95 + a packet time +
           a margin (what the scheduler promises)
      1    one is not, or a phase could not run (a refused fetch, a peer that
           takes no files)
      2    bad options, an unusable profile or dialect, or no peer (--to)
      3    internal error (a bug; TTCTL_DEBUG=1 shows the traceback)
      130  interrupted (Ctrl-C)

    Examples (the model; then live, with emulate onboard running):
      ttctl bench latency --count 20
      ttctl bench latency --to udpout:127.0.0.1:14560 --count 20 --interval 0.5
    """
    from ..bench import latency as lat
    from ..link.model import ProfileError, load_profile

    try:
        prof = load_profile(profile, str(profile_file) if profile_file else None)
    except ProfileError as e:
        raise Fail(str(e)) from None
    if fetch is not None and to is None:
        raise Fail("--fetch applies to live runs (--to); the model's download phase needs no file")
    if size is None:  # a file that lasts on the link it takes: the pipeline moves 64 KiB in under a second
        size = 2_000_000 if prof.pipe is not None else 65536
    extrapolated = prof.extrapolated(distance)
    if extrapolated and to is None:  # live, link_choice says it
        err(f"warning: {extrapolated}")
    bound = lat.bound_s(prof, distance, live=to is not None)
    meta: dict[str, Any] = {"mode": "live" if to else "model", "profile": prof.name, "distance_m": distance,
                            "extrapolated": extrapolated,
                            "count": count, "interval_s": interval, "file_bytes": size, "seed": seed,
                            "packet_time_ms": round(1000 * lat.packet_time(prof, distance), 1),
                            "bound_ms": round(1000 * bound, 1)}
    from .dialect import load_bindings

    b = load_bindings(dialect, include or [])  # the model too: a dialect that cannot be read is refused
    if to is None:
        phases = lat.run_model(prof, distance, count, seed, interval, size)
    else:
        phases, extra = _live(to, prof, distance, count, interval, size, seed, fetch, timeout, profile_file, b)
        meta.update(extra)
    rep = lat.report(phases, meta, bound)
    if json_out:
        print(lat.dumps(rep), flush=True)
    else:
        lat.print_report(rep)
    broken = [p for p in rep["phases"] if p["note"] and not p["note"].startswith("skipped")]
    missed = [c for c in rep["checks"] if not c["ok"]]
    if broken or missed:  # the verdict, last, on stderr too (as the other benches' misses)
        why = [f"{c['check']} {c['value']} ms over its ceiling {c['ceiling']} ms" for c in missed]
        why += [f"{p['phase']}: {p['note']}" for p in broken]
        err(f"error: {'; '.join(why)}")
        raise typer.Exit(1)


def _live(to: str, prof: Profile, distance: float, count: int, interval: float, size: int, seed: int,
          fetch: str | None, timeout: float, profile_file: Path | None, b: Any) -> tuple[list[Phase], dict[str, Any]]:
    from ..bench import latency as lat
    from .common import TABLET, link_choice, parse_endpoint

    parse_endpoint(to, "udpout")  # refused in one line before anything starts
    if fetch is not None:
        from ..proto.names import Refused, check_name

        try:
            check_name(fetch)
        except Refused as e:
            raise Fail(f"--fetch {fetch!r}: {e.reason}") from None
    link = link_choice(None, prof.name, distance, TABLET[0], profile_file)
    o = lat.LiveOptions(to, count, interval, size, link.pace_Bps, link.quiet, fetch, timeout, seed, b, link.mtu)
    tty = sys.stderr.isatty()

    def progress(text: str) -> None:
        if tty:
            print(f"\rttctl: {text}\033[K", end="", file=sys.stderr, flush=True)
        elif text.endswith(f"{count}/{count}") or "skipped" in text:
            print(f"ttctl: {text}", file=sys.stderr, flush=True)

    from ..link.transport import TransportError

    try:
        phases, extra = lat.run_live(o, progress)
    except lat.Unreachable as e:
        if tty:
            print("\r\033[K", end="", file=sys.stderr)
        raise Fail(str(e)) from None
    except TransportError as e:
        raise Fail(str(e)) from None
    finally:
        if tty:
            print("\r\033[K", end="", file=sys.stderr, flush=True)
    return phases, extra
