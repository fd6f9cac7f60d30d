"""`ttctl bench ...`: the benchmark command group (the work is in ttctl.bench)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from ..errors import Fail
from .options import PLOT_EXTRA, ProfileFileOpt
from .panels import LINK, OUTPUT, RUN, WORKLOAD

bench_app = typer.Typer(help="Benchmarks that print ratios against a named peer, measured in one run.\n\n"
                             "Start with ttctl bench link (the link model against the thesis's\n"
                             "measurements, in a second), then ttctl bench transfer --quick.",
                        no_args_is_help=True)


@bench_app.command("validate")
def bench_validate(
    dialect: Annotated[Path | None, typer.Argument(help="Dialect XML (default: pymavlink's all.xml).")] = None,
    runs: Annotated[int, typer.Option(help="Runs of each command.", min=1, max=200, rich_help_panel=RUN)] = 15,
    synthetic: Annotated[int | None, typer.Option("--synthetic", help="Time both on a made-up dialect of N "
                                                                      "messages instead (up to 60000: the 8 MiB "
                                                                      "input cap).", min=1, max=60_000,
                                                  show_default=False, rich_help_panel=WORKLOAD)] = None,
    json_out: Annotated[bool, typer.Option("--json", help="Print the result as JSON.", rich_help_panel=OUTPUT)] = False,
) -> None:
    """Whole-process time of `ttctl validate` against `mavgen.py --lang Python3 --wire-protocol 2.0`.

    Exit status:
      0    the ratio meets its floor
      1    the floor is missed
      2    bad options or a dialect it cannot read
      3    internal error (a bug; TTCTL_DEBUG=1 shows the traceback)
      130  interrupted (Ctrl-C)

    Example:
      ttctl bench validate dialects/ttapi.xml --runs 5
    """
    from ..bench.validate import run

    raise typer.Exit(run(str(dialect) if dialect else None, runs, json_out, synthetic))


@bench_app.command("gen")
def bench_gen(
    dialect: Annotated[Path | None, typer.Argument(help="Dialect XML (default: pymavlink's all.xml).")] = None,
    runs: Annotated[int, typer.Option(help="Runs of each command.", min=1, max=50, rich_help_panel=RUN)] = 5,
    json_out: Annotated[bool, typer.Option("--json", help="Print the result as JSON.", rich_help_panel=OUTPUT)] = False,
) -> None:
    """Whole-process time of `ttctl gen` (three languages) against mavgen's Python3 + C++11 + Java.

    Exit status:
      0    the ratio meets its floor
      1    the floor is missed
      2    bad options or a dialect gen refuses (its first error quoted)
      3    internal error (a bug; TTCTL_DEBUG=1 shows the traceback)
      130  interrupted (Ctrl-C)

    Example:
      ttctl bench gen dialects/ttapi.xml --runs 3
    """
    from ..bench.gen import run

    raise typer.Exit(run(str(dialect) if dialect else None, runs, json_out))


@bench_app.command("dialect")
def bench_dialect(
    dialect: Annotated[Path | None, typer.Argument(help="Dialect XML (default: the robolab example ttctl "
                                                        "ships).")] = None,
    runs: Annotated[int, typer.Option(help="Runs of each command.", min=1, max=100, rich_help_panel=RUN)] = 11,
    json_out: Annotated[bool, typer.Option("--json", help="Print the result as JSON.", rich_help_panel=OUTPUT)] = False,
) -> None:
    """What --dialect adds to a link command's start, whole process.

    The shipped dialect against the user's with a warm and a cold bindings
    cache (and `gen --lang python` for scale).

    Exit status:
      0    measured (no floor)
      2    bad options or a dialect it cannot use
      3    internal error (a bug; TTCTL_DEBUG=1 shows the traceback)
      130  interrupted (Ctrl-C)

    Example:
      ttctl bench dialect --runs 5
    """
    from ..bench.dialect import run

    run(str(dialect) if dialect else None, runs, json_out)


@bench_app.command("codec")
def bench_codec(
    seconds: Annotated[float, typer.Option(help="Approximate time budget per measurement.", min=0.05,
                                           rich_help_panel=RUN)] = 0.5,
    rounds: Annotated[int, typer.Option(help="Interleaved rounds; medians are reported.", min=1, max=50,
                                        rich_help_panel=RUN)] = 5,
    cpp: Annotated[bool, typer.Option("--cpp/--no-cpp", help="Also build and compare the C++ decoder with "
                                                             "mavgen's C library (needs g++).",
                                      rich_help_panel=WORKLOAD)] = True,
    json_out: Annotated[bool, typer.Option("--json", help="Print the result as JSON.", rich_help_panel=OUTPUT)] = False,
) -> None:
    """Generated Python decode/encode against pymavlink, and generated C++ decode against mavgen's C.

    Exit status:
      0    measured (no floor)
      2    bad options, fastcrc missing, or the C++ build or run failed
      3    internal error (a bug; TTCTL_DEBUG=1 shows the traceback)
      130  interrupted (Ctrl-C)

    Example:
      ttctl bench codec --no-cpp
    """
    from ..bench.codec import run

    run(seconds, rounds, cpp, json_out)


@bench_app.command("transfer")
def bench_transfer(
    profile: Annotated[str | None, typer.Option(help="Link profile (see cli/ttctl/link/profiles.toml); default "
                                                     "m100.", show_default=False, rich_help_panel=LINK)] = None,
    profile_file: ProfileFileOpt = None,
    distance: Annotated[float, typer.Option(help="Distance in metres.", min=0, rich_help_panel=LINK)] = 10.0,
    size: Annotated[int, typer.Option("--size", help="File size in bytes.", min=1, max=1 << 26,
                                      rich_help_panel=WORKLOAD)] = 65536,
    seeds: Annotated[int, typer.Option(help="Seeds per case; rows report the median.", min=1, max=99,
                                       rich_help_panel=RUN)] = 9,
    protocols: Annotated[str, typer.Option(help="Comma-separated: ttctl,ttctl-signed,thesis,mavftp (ttctl-signed: "
                                                "MAVLink 2 signing at both ends).", rich_help_panel=WORKLOAD)] \
    = "ttctl,ttctl-signed,thesis,mavftp",
    quick: Annotated[bool, typer.Option("--quick", help="Two cases only (a smoke test).", rich_help_panel=RUN)] = False,
    plot: Annotated[Path | None, typer.Option(help=f"Write a PNG of efficiency against loss ({PLOT_EXTRA}).",
                                              rich_help_panel=OUTPUT)] = None,
    json_out: Annotated[bool, typer.Option("--json", help="Print the report as JSON.", rich_help_panel=OUTPUT)] = False,
) -> None:
    """File transfer over the link model in virtual time, ttctl against the thesis and MAVLink FTP.

    At 0/10/30 % random and burst loss, both directions, plus command latency;
    the last table checks each figure against its floor or ceiling.

    Exit status:
      0    every transfer completed and every floor and ceiling held
      1    a transfer failed, or a floor or ceiling was missed
      2    bad options or an unusable profile
      3    internal error (a bug; TTCTL_DEBUG=1 shows the traceback)
      130  interrupted (Ctrl-C)

    Example:
      ttctl bench transfer --quick --protocols ttctl,mavftp
    """
    from ..bench.transfer import run
    from ..link.model import ProfileError, load_profile

    chosen = [p.strip() for p in protocols.split(",") if p.strip()]
    if not chosen:
        raise Fail("--protocols names none: give one or more of ttctl, ttctl-signed, thesis, mavftp")
    try:
        prof = load_profile(profile, str(profile_file) if profile_file else None)
        code = run(prof, distance, size, seeds, chosen, json_out,
                   str(plot) if plot else None, quick)
    except ProfileError as e:
        raise Fail(str(e)) from None
    raise typer.Exit(code)


@bench_app.command("link")
def bench_link(
    profile: Annotated[str | None, typer.Option(help="Link profile (default m100): the model's, or with --to the "
                                                     "uplink pace's.", show_default=False,
                                                rich_help_panel=LINK)] = None,
    profile_file: ProfileFileOpt = None,
    plot: Annotated[Path | None, typer.Option(help=f"Write a PNG ({PLOT_EXTRA}).", rich_help_panel=OUTPUT)] = None,
    json_out: Annotated[bool, typer.Option("--json", help="Print the report as JSON.", rich_help_panel=OUTPUT)] = False,
    to: Annotated[str | None, typer.Option("--to", help="Measure a live link instead of the model: the "
                                                        "udpout:HOST:PORT of a `ttctl bench serve` behind it.",
                                           show_default=False, rich_help_panel=LINK)] = None,
    direction: Annotated[str, typer.Option("--direction", help="With --to: up, down or both.",
                                           rich_help_panel=WORKLOAD)] = "both",
    sizes: Annotated[str, typer.Option("--sizes", help="With --to: uplink probe sizes in bytes, 10..100.",
                                       rich_help_panel=WORKLOAD)]
    = "10,50,100",
    rates: Annotated[str, typer.Option("--rates", help="With --to: downlink send rates in Hz (100-byte "
                                                       "probes).", rich_help_panel=WORKLOAD)] = "5,10,20",
    count: Annotated[int, typer.Option("--count", help="With --to: probes per size and per rate.",
                                       rich_help_panel=WORKLOAD)] = 100,
    rate: Annotated[float | None, typer.Option("--rate", help="With --to: pace the uplink at this many bytes "
                                                              "per second (default: the profile's uplink "
                                                              "capacity).", show_default=False,
                                               rich_help_panel=LINK)] = None,
    label: Annotated[str, typer.Option("--label", help="With --to: a note on the conditions, kept in the "
                                                       "output.", rich_help_panel=OUTPUT)] = "",
    output: Annotated[Path | None, typer.Option("-o", "--output", help="With --to: also write the report to "
                                                                       "FILE.json or FILE.csv.",
                                                show_default=False, rich_help_panel=OUTPUT)] = None,
    distance: Annotated[float | None, typer.Option("--distance", help="With --to: the distance in metres, kept "
                                                                      "with the measurement (for `ttctl link "
                                                                      "fit`); with --like: replay at this "
                                                                      "distance instead of the measurement's.",
                                                   show_default=False, rich_help_panel=LINK)] = None,
    like: Annotated[Path | None, typer.Option("--like", help="Replay this measurement (a `bench link --to -o "
                                                             "FILE.json`) on the model: the same packets at the "
                                                             "same moments, compared figure by figure; exit 1 if "
                                                             "any is outside its tolerance.",
                                              show_default=False, rich_help_panel=WORKLOAD)] = None,
) -> None:
    """The thesis's measurement method, on the link model or (--to) on a live link.

    Uplink packet sizes and distances, downlink send rates; with --to, the same
    against a live `ttctl bench serve`, whose report (-o) `ttctl link fit`
    reads; with --like, such a report replayed on the model.

    Exit status:
      0    measured (the model, or a live link that answered throughout)
      1    --to: the peer stopped answering midway (rows so far kept, marked
           partial); --like: a figure outside its tolerance
      2    bad options, an unusable profile, or no peer answers --to
      3    internal error (a bug; TTCTL_DEBUG=1 shows the traceback)
      130  interrupted (Ctrl-C)

    Examples (the model; then a live link, `ttctl bench serve` at the far end):
      ttctl bench link
      ttctl bench link --to udpout:192.168.1.20:14570 --distance 10 \\
          -o field-10m.json
    """
    from ..bench import linkbench
    from ..link.model import ProfileError, load_profile

    pfile = str(profile_file) if profile_file else None
    if to is not None:
        from ..bench import live

        if like is not None:
            raise Fail("--like replays a measurement on the model: leave out --to")
        o = live.Options(to, direction, live.parse_list(sizes, "--sizes", int),
                         live.parse_list(rates, "--rates", float), count, rate, profile, label, json_out,
                         str(output) if output else None, str(plot) if plot else None, pfile, distance)
        raise typer.Exit(live.run(o))
    given = [name for name, value, default in (("--direction", direction, "both"), ("--sizes", sizes, "10,50,100"),
                                               ("--rates", rates, "5,10,20"), ("--count", count, 100),
                                               ("--rate", rate, None), ("--label", label, ""),
                                               ("-o", output, None)) if value != default]
    if given:
        raise Fail(f"{', '.join(given)} measure a live link: give --to udpout:HOST:PORT (a `ttctl bench serve`)")
    if like is not None:
        from ..bench.replay_cli import run_like

        if plot is not None:
            raise Fail("--plot draws the thesis method's run (no --like) or a live one (--to), not a replay")

        raise typer.Exit(run_like(str(like), profile, pfile, distance, json_out))
    if distance is not None:
        raise Fail("--distance goes with --to (kept with the measurement) or --like (the replay's distance)")
    try:
        linkbench.run(load_profile(profile, pfile), json_out, str(plot) if plot else None)
    except ProfileError as e:
        raise Fail(str(e)) from None
    except RuntimeError as e:  # matplotlib missing
        raise Fail(str(e)) from None


@bench_app.command("serve")
def bench_serve(
    listen: Annotated[str, typer.Option("--listen", help="Where to listen (udpin:HOST:PORT).", rich_help_panel=LINK)]
    = "udpin:0.0.0.0:14570",
) -> None:
    """The peer of `ttctl bench link --to`, on the far side of the link under test.

    Counts probes, echoes round-trip probes, reports what arrived and sends
    downlink probes on request (plain UDP datagrams of at most 100 bytes), to
    whoever asks: run it on a network you trust.

    Exit status:
      0    stopped by Ctrl-C or SIGTERM
      2    bad options or an endpoint it cannot open
      3    internal error (a bug; TTCTL_DEBUG=1 shows the traceback)
      130  interrupted while starting (Ctrl-C)

    Example:
      ttctl bench serve --listen udpin:0.0.0.0:14570
    """
    from ..bench.serve import serve

    raise typer.Exit(serve(listen))


@bench_app.command("integrity")
def bench_integrity(
    rounds: Annotated[int, typer.Option("--rounds", help="Rounds per topology.", min=1, max=100_000,
                                        rich_help_panel=RUN)] = 50,
    seed: Annotated[int, typer.Option("--seed", help="Random seed: the same seed draws the same plan (senders, files, "
                                                         "kills); the counts depend on process timing and "
                                                         "differ run to run.", rich_help_panel=RUN)] = 1,
    topology: Annotated[str, typer.Option("--topology", help="direct, relay (lossy) or both.",
                                          rich_help_panel=WORKLOAD)] = "both",
    strangers: Annotated[bool, typer.Option("--strangers/--no-strangers",
                                            help="Garbage datagrams from other ports throughout.",
                                            rich_help_panel=WORKLOAD)] = True,
    keep: Annotated[Path | None, typer.Option("--keep", help="Keep every process's output in this (new or empty) "
                                                             "folder.", show_default=False,
                                              rich_help_panel=OUTPUT)] = None,
    json_out: Annotated[bool, typer.Option("--json", help="Print the report as JSON.", rich_help_panel=OUTPUT)] = False,
) -> None:
    """Soak send-file's promise on real processes: concurrent senders, kills, restarts, loss.

    Rounds of concurrent senders with equal ids, kills and restarts of senders
    and the receiver, relay loss, strangers.

    Exit status:
      0    every check held
      1    a sender exited 0 without the receiver holding its file, or a
           partial file was visible under its name (or another check failed)
      2    bad options or an unusable --keep
      3    internal error (a bug; TTCTL_DEBUG=1 shows the traceback)
      130  interrupted (Ctrl-C)

    Example:
      ttctl bench integrity --rounds 5 --topology direct
    """
    from ..bench.integrity import main as integrity_main

    raise typer.Exit(integrity_main(rounds, seed, topology, strangers, keep, json_out))


@bench_app.command("ends")
def bench_ends(
    seconds: Annotated[float, typer.Option("--seconds", help="Length of each phase.", min=2, max=600,
                                           rich_help_panel=RUN)] = 10.0,
    json_out: Annotated[bool, typer.Option("--json", help="Print the report as JSON.", rich_help_panel=OUTPUT)] = False,
) -> None:
    """The onboard end's cost on one core: core share and event-loop lag, idle and loaded.

    Idle at default telemetry, and loaded (50 Hz telemetry on both links plus a
    file download at full link rate).

    Exit status:
      0    every ceiling held
      1    a ceiling was missed
      2    bad options
      3    internal error (a bug; TTCTL_DEBUG=1 shows the traceback)
      130  interrupted (Ctrl-C)

    Example:
      ttctl bench ends --seconds 5
    """
    from ..bench.ends import run

    raise typer.Exit(run(seconds, json_out))


@bench_app.command("hmd")
def bench_hmd(
    seconds: Annotated[float, typer.Option("--seconds", help="Length of the long recording run.", min=4,
                                           max=600, rich_help_panel=RUN)] = 20.0,
    runs: Annotated[int, typer.Option("--runs", help="Runs of each measurement (the median is reported).", min=1,
                                      max=20, rich_help_panel=RUN)] = 3,
    replay_minutes: Annotated[float, typer.Option("--replay-minutes", help="Length of the recording replayed "
                                                                           "with --speed 0.", min=0.1,
                                                  max=60, rich_help_panel=WORKLOAD)] = 10.0,
    json_out: Annotated[bool, typer.Option("--json", help="Print the report as JSON.", rich_help_panel=OUTPUT)] = False,
) -> None:
    """What recording VR poses costs, in core share and replay time.

    `ttctl hmd dump` of the synthetic source (90 Hz headset, 2 x 250 Hz
    controllers) to MCAP as a share of one core (ceiling 10 %), and replaying a
    10-minute recording with --speed 0 (ceiling 10 s).

    Exit status:
      0    both ceilings held
      1    a ceiling was missed, or a dump it ran failed
      2    bad options
      3    internal error (a bug; TTCTL_DEBUG=1 shows the traceback)
      130  interrupted (Ctrl-C)

    Example:
      ttctl bench hmd --runs 1 --replay-minutes 1
    """
    from ..bench.hmd import run

    raise typer.Exit(run(seconds, runs, replay_minutes, json_out))

from .bench_latency_cli import bench_latency  # noqa: E402

bench_app.command("latency")(bench_latency)

from .bench_gcs_cli import bench_gcs  # noqa: E402

bench_app.command("gcs")(bench_gcs)
