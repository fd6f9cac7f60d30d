"""The `ttctl` command line: parses options, calls the library, prints.

Heavy modules (lxml, jinja2, rich, pymavlink) are imported inside the commands that need
them, so that `ttctl validate` starts fast.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import Annotated

import typer

from . import __version__
from .errors import Fail

app = typer.Typer(
    name="ttctl",
    help="Toolchain for custom MAVLink 2 links over DJI Data Transparent Transmission.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
    context_settings={"help_option_names": ["-h", "--help"]},
)
bench_app = typer.Typer(help="Benchmarks that print ratios against a named peer, measured in one run.",
                        no_args_is_help=True)
app.add_typer(bench_app, name="bench")


# Commands that leave nothing to clean up set this: main() then skips interpreter teardown
# (freeing tens of thousands of objects), which is a tenth of `ttctl validate`'s run time.
_fast_exit = False


def _version(value: bool) -> None:
    if value:
        print(f"ttctl {__version__}")
        raise typer.Exit()


@app.callback()
def _root(
    version: Annotated[
        bool | None, typer.Option("--version", callback=_version, is_eager=True, help="Print the version.")
    ] = None,
) -> None:
    pass


IncludeOpt = Annotated[
    list[Path] | None,
    typer.Option("-I", "--include-dir", help="Extra directory to search for <include> files (repeatable)."),
]


@app.command()
def validate(
    dialect: Annotated[Path, typer.Argument(help="Dialect XML file.", show_default=False)],
    include: IncludeOpt = None,
    mtu: Annotated[int, typer.Option(help="Packet size budget in bytes; warn for messages of this dialect whose "
                                          "largest frame does not fit one packet (0: off).", min=0, max=65535)] = 100,
    signed: Annotated[bool, typer.Option("--signed", help="Budget for signed frames (+13 bytes).")] = False,
    fmt: Annotated[str, typer.Option("--format", help="text or json.")] = "text",
    all_warnings: Annotated[bool, typer.Option("--all-warnings",
                                               help="Also show warnings inside pymavlink's own dialects.")] = False,
) -> None:
    """Validate a MAVLink 2 dialect: XSD and semantic checks, all problems in one run.

    Exit status: 0 no errors (warnings allowed), 1 errors, 2 unreadable input or bad options.
    """
    if fmt not in ("text", "json"):
        raise Fail(f"--format must be 'text' or 'json', not '{fmt}'")
    from .validate import include_dir_problem, run_validate

    for d in include or []:
        problem = include_dir_problem(str(d))
        if problem:
            raise Fail(problem)

    global _fast_exit
    _fast_exit = True
    code = run_validate(str(dialect), [str(p) for p in include or []], mtu=mtu, signed=signed, fmt=fmt,
                        all_warnings=all_warnings)
    raise typer.Exit(code)


@app.command()
def gen(
    dialect: Annotated[Path | None, typer.Argument(help="Dialect XML file (default: dialects/ttapi.xml).",
                                                     show_default=False)] = None,
    lang: Annotated[str, typer.Option("--lang", help="Comma-separated: python,cpp,java.")] = "python,cpp,java",
    out: Annotated[Path, typer.Option("-o", "--out", help="Output directory.")] = Path("generated"),
    check: Annotated[bool, typer.Option("--check", help="Write nothing; list files that differ; exit 1 if any.")]
    = False,
    force_skeletons: Annotated[bool, typer.Option("--force-skeletons",
                                                  help="Overwrite skeletons (code you edit) too.")] = False,
    include: IncludeOpt = None,
    templates: Annotated[Path | None, typer.Option("--templates",
                                                      help="Folder of templates overriding ttctl's, by name.")] = None,
) -> None:
    """Generate Python, C++ and Java bindings, skeletons and conformance programs.

    Bindings are rewritten when they change; skeletons (handler and command stubs you fill in)
    are written once. Refuses a dialect with validation errors.
    """
    from .gen import GenError, run_gen

    global _fast_exit
    _fast_exit = True  # every file is written and closed before run_gen returns
    try:
        code = run_gen(str(dialect) if dialect else None, lang, str(out), check, force_skeletons,
                       [str(p) for p in include or []], str(templates) if templates else None)
    except GenError as e:
        raise Fail(str(e), e.code) from None
    raise typer.Exit(code)


@bench_app.command("validate")
def bench_validate(
    dialect: Annotated[Path | None, typer.Argument(help="Dialect XML (default: pymavlink's all.xml).")] = None,
    runs: Annotated[int, typer.Option(help="Runs of each command.", min=1, max=200)] = 15,
    synthetic: Annotated[int | None, typer.Option("--synthetic", help="Time both on a made-up dialect of N "
                                                                      "messages instead (up to 60000: the 8 MiB "
                                                                      "input cap).", min=1, max=60_000,
                                                  show_default=False)] = None,
    json_out: Annotated[bool, typer.Option("--json", help="Print the result as JSON.")] = False,
) -> None:
    """Whole-process time of `ttctl validate` against `mavgen.py --lang Python3 --wire-protocol 2.0`."""
    from .bench.validate import run

    run(str(dialect) if dialect else None, runs, json_out, synthetic)


@bench_app.command("gen")
def bench_gen(
    dialect: Annotated[Path | None, typer.Argument(help="Dialect XML (default: pymavlink's all.xml).")] = None,
    runs: Annotated[int, typer.Option(help="Runs of each command.", min=1, max=50)] = 5,
    json_out: Annotated[bool, typer.Option("--json", help="Print the result as JSON.")] = False,
) -> None:
    """Whole-process time of `ttctl gen` (three languages) against mavgen's Python3 + C++11 + Java."""
    from .bench.gen import run

    run(str(dialect) if dialect else None, runs, json_out)


@bench_app.command("codec")
def bench_codec(
    seconds: Annotated[float, typer.Option(help="Approximate time budget per measurement.", min=0.05)] = 0.5,
    rounds: Annotated[int, typer.Option(help="Interleaved rounds; medians are reported.", min=1, max=50)] = 5,
    cpp: Annotated[bool, typer.Option("--cpp/--no-cpp", help="Also build and compare the C++ decoder with "
                                                             "mavgen's C library (needs g++).")] = True,
    json_out: Annotated[bool, typer.Option("--json", help="Print the result as JSON.")] = False,
) -> None:
    """Generated Python decode/encode against pymavlink, and generated C++ decode against mavgen's C."""
    from .bench.codec import run

    run(seconds, rounds, cpp, json_out)


link_app = typer.Typer(help="The emulated DJI link between processes.", no_args_is_help=True)
app.add_typer(link_app, name="link")

RateOpt = Annotated[float | None, typer.Option("--rate", help="Pacing rate in bytes per second (overrides the "
                                                              "profile's).", show_default=False)]
ProfileOpt = Annotated[str | None, typer.Option("--profile", help="Link profile (m100, psdk, lan): pace at its "
                                                                  "capacity in this end's sending direction.",
                                                show_default=False)]
DistanceOpt = Annotated[float, typer.Option("--distance", help="Distance in metres, for --profile.")]
JsonOpt = Annotated[bool, typer.Option("--json", help="Machine-readable output (JSON).")]


PLOT_EXTRA = "needs the plot extra: pip install 'ttctl\\[plot]'"  # \\[ keeps rich from reading a style tag


@bench_app.command("transfer")
def bench_transfer(
    profile: Annotated[str, typer.Option(help="Link profile (see cli/ttctl/link/profiles.toml).")] = "m100",
    distance: Annotated[float, typer.Option(help="Distance in metres.", min=0)] = 10.0,
    size: Annotated[int, typer.Option("--size", help="File size in bytes.", min=1, max=1 << 26)] = 65536,
    seeds: Annotated[int, typer.Option(help="Seeds per case; rows report the median.", min=1, max=99)] = 9,
    protocols: Annotated[str, typer.Option(help="Comma-separated: ttctl,thesis,mavftp.")] = "ttctl,thesis,mavftp",
    quick: Annotated[bool, typer.Option("--quick", help="Two cases only (a smoke test).")] = False,
    plot: Annotated[Path | None, typer.Option(help=f"Write a PNG of efficiency against loss ({PLOT_EXTRA}).")] = None,
    json_out: Annotated[bool, typer.Option("--json", help="Print the report as JSON.")] = False,
) -> None:
    """File transfer over the link model in virtual time: ttctl against the thesis protocol and
    MAVLink FTP at 0/10/30 % random and burst loss, both directions, plus command latency."""
    from .bench.transfer import run
    from .link.model import ProfileError

    try:
        run(profile, distance, size, seeds, [p.strip() for p in protocols.split(",") if p.strip()], json_out,
            str(plot) if plot else None, quick)
    except ProfileError as e:
        raise Fail(str(e)) from None


@bench_app.command("link")
def bench_link(
    profile: Annotated[str, typer.Option(help="Link profile.")] = "m100",
    plot: Annotated[Path | None, typer.Option(help=f"Write a PNG ({PLOT_EXTRA}).")] = None,
    json_out: Annotated[bool, typer.Option("--json", help="Print the report as JSON.")] = False,
) -> None:
    """The thesis's measurement method replayed on the link model: uplink packet sizes and
    distances, downlink send rates."""
    from .bench import linkbench
    from .link.model import ProfileError

    try:
        linkbench.run(profile, json_out, str(plot) if plot else None)
    except ProfileError as e:
        raise Fail(str(e)) from None
    except RuntimeError as e:  # matplotlib missing
        raise Fail(str(e)) from None


@bench_app.command("integrity")
def bench_integrity(
    rounds: Annotated[int, typer.Option("--rounds", help="Rounds per topology.", min=1, max=100_000)] = 50,
    seed: Annotated[int, typer.Option("--seed", help="Random seed (the same seed, the same plan).")] = 1,
    topology: Annotated[str, typer.Option("--topology", help="direct, relay (lossy) or both.")] = "both",
    strangers: Annotated[bool, typer.Option("--strangers/--no-strangers",
                                            help="Garbage datagrams from other ports throughout.")] = True,
    keep: Annotated[Path | None, typer.Option("--keep", help="Keep every process's output in this (new or empty) "
                                                             "folder.", show_default=False)] = None,
    json_out: Annotated[bool, typer.Option("--json", help="Print the report as JSON.")] = False,
) -> None:
    """Soak send-file's promise on real processes: rounds of concurrent senders with equal ids, kills
    and restarts of senders and the receiver, relay loss, strangers; exit 1 if any sender exited 0
    without the receiver holding its file, or a partial file was ever visible under its name."""
    from .bench.integrity import main as integrity_main

    raise typer.Exit(integrity_main(rounds, seed, topology, strangers, keep, json_out))


@app.command("recv-file")
def recv_file_cmd(
    listen: Annotated[str, typer.Option("--listen", help="Endpoint: udpin:HOST:PORT (udp: means udpin), "
                                                         "tcpin:HOST:PORT, or udpout:/tcp: to reach out.",
                                        show_default=False)],
    folder: Annotated[Path, typer.Option("--dir", help="Where received files go (created if missing).",
                                         show_default=False)],
    overwrite: Annotated[bool, typer.Option("--overwrite", help="Allow replacing files, when the sender asks "
                                                                "for it too.")] = False,
    max_file: Annotated[int | None, typer.Option("--max-file", help="Largest file accepted, bytes "
                                                                    "(default 1 GiB).", show_default=False)] = None,
    max_dir: Annotated[int | None, typer.Option("--max-dir", help="Quota for everything in --dir, partial files "
                                                                  "included, bytes (default 8 GiB).",
                                                show_default=False)] = None,
    serve: Annotated[Path | None, typer.Option("--serve", help="Offer the files in this folder for download "
                                                               "(send-file --from).", show_default=False)] = None,
    count: Annotated[int | None, typer.Option("--count", help="Exit 0 after this many files completed.",
                                              show_default=False)] = None,
    sysid: Annotated[int, typer.Option("--sysid", help="This end's MAVLink system id.")] = 1,
    compid: Annotated[int, typer.Option("--compid", help="This end's MAVLink component id.")] = 240,
    rate: RateOpt = None,
    profile: ProfileOpt = None,
    distance: DistanceOpt = 10.0,
    json_out: JsonOpt = False,
) -> None:
    """Receive files (the onboard end, 1/240, by default) until interrupted or --count files are in.

    Prints a line per file accepted, refused (with the reason), completed or failed (--json: JSON lines).
    Files land in DIR/.ttctl-partial first and are renamed into place once their SHA-256 matches.
    On SIGINT/SIGTERM (exit 0) or a crash, what arrived stays there: offering the file again resumes it.

    Example: ttctl recv-file --listen udpin:0.0.0.0:14560 --dir inbox --profile m100
    """
    from .commands.recv_file import RecvOptions, recv_file

    code = recv_file(RecvOptions(listen, folder, overwrite, max_file, max_dir, serve, count, sysid, compid, rate,
                                 profile, distance, json_out))
    raise typer.Exit(code)


@app.command("send-file")
def send_file_cmd(
    file: Annotated[str, typer.Argument(help="The file to send (with --to), or the name to fetch (with --from).",
                                        show_default=False)],
    to: Annotated[str | None, typer.Option("--to", help="Send FILE to this endpoint: udpout:HOST:PORT (udp: "
                                                        "means udpout), tcp:HOST:PORT, udpin:/tcpin: to wait "
                                                        "for the peer.", show_default=False)] = None,
    from_: Annotated[str | None, typer.Option("--from", help="Fetch FILE from a receiver started with --serve "
                                                             "at this endpoint.", show_default=False)] = None,
    name: Annotated[str | None, typer.Option("--name", help="Name at the receiver (default: FILE's base name); "
                                                            "a relative path.", show_default=False)] = None,
    overwrite: Annotated[bool, typer.Option("--overwrite", help="Ask the receiver to replace an existing "
                                                                "file.")] = False,
    folder: Annotated[Path | None, typer.Option("--dir", help="With --from: where the file goes (default: .).",
                                                show_default=False)] = None,
    json_out: JsonOpt = False,
    rate: RateOpt = None,
    profile: ProfileOpt = None,
    distance: DistanceOpt = 10.0,
    sysid: Annotated[int, typer.Option("--sysid", help="This end's MAVLink system id.")] = 255,
    compid: Annotated[int, typer.Option("--compid", help="This end's MAVLink component id.")] = 190,
    target_sysid: Annotated[int, typer.Option("--target-sysid", help="The receiver's system id.")] = 1,
    target_compid: Annotated[int, typer.Option("--target-compid", help="The receiver's component id.")] = 240,
    timeout: Annotated[float, typer.Option("--timeout", help="Give up after this many seconds without a word "
                                                             "from the peer.")] = 60.0,
) -> None:
    """Send a file to a receiver (ttctl recv-file, or the onboard end), or fetch one with --from.

    A progress bar on stderr when it is a terminal; at the end a summary: bytes, seconds, goodput,
    efficiency against the link capacity (known from --rate or --profile), retransmitted bytes.
    --json prints one JSON object instead: ok, code, message, name, bytes, seconds, goodput_Bps,
    capacity_Bps, efficiency, retransmitted_bytes, frames_sent, bytes_sent, resumed_bytes.
    Sending a file again after an interruption resumes where the receiver got to.

    Exit status: 0 delivered and verified, 1 refused (with the receiver's reason), failed or timed out,
    2 bad options, a missing file or an unusable endpoint, 130 interrupted.

    Example: ttctl send-file photo.jpg --to udpout:192.168.1.20:14560 --profile m100 --distance 50
    """
    from .commands.send_file import SendOptions, send_file

    code = send_file(SendOptions(file, to, from_, name, overwrite, json_out, rate, profile, distance, sysid, compid,
                                 target_sysid, target_compid, timeout, folder))
    raise typer.Exit(code)


@link_app.command("relay")
def link_relay(
    listen: Annotated[str, typer.Option("--listen", help="udp:HOST:PORT where the tablet side sends (udpin).",
                                        show_default=False)],
    to: Annotated[str, typer.Option("--to", help="udp:HOST:PORT of the onboard side (udpout).",
                                    show_default=False)],
    profile: Annotated[str, typer.Option("--profile", help="Link profile: m100, psdk or lan.")] = "m100",
    distance: Annotated[float, typer.Option("--distance", help="Distance in metres.")] = 10.0,
    loss: Annotated[float | None, typer.Option("--loss", help="Packet loss probability, both directions "
                                                              "(default: the profile's at --distance).",
                                               show_default=False)] = None,
    loss_model: Annotated[str, typer.Option("--loss-model", help="random or burst (Gilbert-Elliott).")] = "random",
    corrupt: Annotated[float, typer.Option("--corrupt", help="Probability that a packet has bytes flipped.")] = 0.0,
    duplicate: Annotated[float, typer.Option("--duplicate", help="Probability that a packet arrives twice.")]
    = 0.0,
    reorder: Annotated[float, typer.Option("--reorder", help="Probability that a packet is held back behind "
                                                             "later ones.")] = 0.0,
    seed: Annotated[int, typer.Option("--seed", help="Random seed.")] = 0,
    rate: Annotated[float | None, typer.Option("--rate", help="Override the profile's rate, both directions, "
                                                              "bytes per second.", show_default=False)] = None,
    stats_interval: Annotated[float, typer.Option("--stats-interval", help="Seconds between stats lines on "
                                                                           "stderr (0: only at the end).")] = 5.0,
    outage: Annotated[list[str] | None, typer.Option("--outage", help="START:SECONDS: nothing gets through, "
                                                                      "either way, for SECONDS from START seconds "
                                                                      "after the relay starts (repeatable).",
                                                     show_default=False)] = None,
) -> None:
    """The emulated DJI radio link, as a process between the two ends, in real time.

    Packets arriving on --listen (the tablet side) go through the profile's uplink model (rate, SDK
    buffer, loss, latency) and reach --to after the modelled time, or are lost, corrupted, duplicated
    or reordered as asked. Packets from --to go through the downlink model to the address last heard
    on --listen. Datagrams over the profile's MTU (100 bytes) are dropped, as DJI refuses them.
    A stats line goes to stderr every --stats-interval seconds, and a last one on SIGINT/SIGTERM (exit 0).

    Example, three shells:
    ttctl link relay --listen udp:127.0.0.1:14550 --to udp:127.0.0.1:14560 --loss 0.1
    ttctl recv-file --listen udpin:127.0.0.1:14560 --dir inbox --profile m100
    ttctl send-file FILE --to udpout:127.0.0.1:14550 --profile m100
    """
    from .commands.relay import RelayOptions, relay

    code = relay(RelayOptions(listen, to, profile, distance, loss, loss_model, corrupt, duplicate, reorder, seed,
                              rate, stats_interval, outage or []))
    raise typer.Exit(code)


emulate_app = typer.Typer(help="Both ends of the link, runnable without a drone.", no_args_is_help=True)
app.add_typer(emulate_app, name="emulate")


@emulate_app.command("onboard")
def emulate_onboard_cmd(
    listen: Annotated[str, typer.Option("--listen", help="The tablet's DTT link: udpin:HOST:PORT (or udpout:, tcp:, "
                                                         "tcpin:).")] = "udpin:0.0.0.0:14560",
    gcs: Annotated[list[str] | None, typer.Option("--gcs", help="A ground-station link (repeatable; default "
                                                                "udpout:127.0.0.1:14550 and udpout:127.0.0.1:14540, "
                                                                "where QGroundControl, MAVProxy and MAVSDK listen).",
                                                  show_default=False)] = None,
    no_gcs: Annotated[bool, typer.Option("--no-gcs", help="No ground-station links.")] = False,
    sysid: Annotated[int, typer.Option("--sysid", help="The vehicle's MAVLink system id.")] = 1,
    inbox: Annotated[Path | None, typer.Option("--inbox", help="Receive files (trajectories) from the tablet into "
                                                               "this folder.", show_default=False)] = None,
    serve: Annotated[Path | None, typer.Option("--serve", help="Let the tablet fetch the files of this folder.",
                                               show_default=False)] = None,
    home: Annotated[str | None, typer.Option("--home", help="LAT,LON,ALT of home (default 46.0503,14.4686,295).",
                                             show_default=False)] = None,
    speed: Annotated[float, typer.Option("--speed", help="Run the vehicle's clock this many times faster.")] = 1.0,
    plugin: Annotated[list[str] | None, typer.Option("--plugin", help="path/to/plugin.py or module:attr "
                                                                      "(repeatable).", show_default=False)] = None,
    no_entry_points: Annotated[bool, typer.Option("--no-entry-points", help="Do not load the plugins installed "
                                                                            "packages declare (ttctl.plugins).")]
    = False,
    telemetry_hz: Annotated[float, typer.Option("--telemetry-hz", help="TT_NAV_SAT_FIX and TT_ODOMETRY to the "
                                                                       "tablet, per second.")] = 2.0,
    rate: RateOpt = None,
    profile: ProfileOpt = None,
    distance: DistanceOpt = 10.0,
) -> None:
    """The onboard computer's end, flying a simulated multicopter: the tablet's DTT link (commands,
    telemetry, files) and ground-station links (HEARTBEAT, telemetry, commands, parameters,
    missions) to the same vehicle. Runs until interrupted (exit 0).

    Example: ttctl emulate onboard --inbox inbox   (then open QGroundControl)
    """
    from .commands.emulate import OnboardOptions, emulate_onboard

    raise typer.Exit(emulate_onboard(OnboardOptions(listen, gcs or [], no_gcs, sysid, inbox, serve, home, speed,
                                                    rate, profile, distance, plugin or [], no_entry_points,
                                                    telemetry_hz)))


@emulate_app.command("tablet")
def emulate_tablet_cmd(
    to: Annotated[str, typer.Option("--to", help="The onboard end's DTT link: udpout:HOST:PORT (or tcp:, udpin:).")]
    = "udpout:127.0.0.1:14560",
    script: Annotated[Path | None, typer.Option("--script", help="Run these steps (a YAML list) instead of a prompt; "
                                                                 "exit 0 only if every one succeeds.",
                                                show_default=False)] = None,
    json_out: JsonOpt = False,
    folder: Annotated[Path | None, typer.Option("--dir", help="Where fetched files go.", show_default=False)] = None,
    target_sysid: Annotated[int, typer.Option("--target-sysid", help="The vehicle's system id.")] = 1,
    rate: RateOpt = None,
    profile: ProfileOpt = None,
    distance: DistanceOpt = 10.0,
) -> None:
    """The tablet's end: commands (take-off, land, hover, return, set-points, trajectories),
    files both ways and the vehicle's state, from a prompt (history, completion) or a --script.

    Example: ttctl emulate tablet --to udpout:127.0.0.1:14560 --script flight.yaml
    """
    from .commands.tablet import TabletOptions, emulate_tablet

    raise typer.Exit(emulate_tablet(TabletOptions(to, script, json_out, folder, rate, profile, distance,
                                                  target_sysid)))


def main() -> None:
    """Console entry point: clean one-line errors instead of tracebacks."""
    try:  # typer >= 0.26 vendors click
        from typer._click.exceptions import ClickException
    except ImportError:
        from click.exceptions import ClickException

    try:
        code = app(standalone_mode=False)
    except ClickException as e:
        # usage errors as one line, not a box
        ctx = getattr(e, "ctx", None)
        where = ctx.command_path if ctx is not None else "ttctl"
        msg = e.format_message()
        hint = " Did you mean"
        if msg.count(hint) > 1:  # typer and click both add the suggestion
            msg = msg[: msg.rindex(hint)]
        if msg.strip():  # a group called without a command has printed its help already
            print(f"ttctl: error: {msg} (see '{where} --help')", file=sys.stderr)
        sys.exit(e.exit_code)
    except typer.Abort:  # click's word for a KeyboardInterrupt inside a command
        print("ttctl: interrupted", file=sys.stderr)
        sys.exit(130)
    except Fail as e:
        print(f"ttctl: error: {e}", file=sys.stderr)
        sys.exit(e.code)
    except KeyboardInterrupt:
        print("ttctl: interrupted", file=sys.stderr)
        sys.exit(130)
    except BrokenPipeError:
        sys.stderr.close()
        sys.exit(1)
    except Exception as e:
        if os.environ.get("TTCTL_DEBUG"):
            raise
        print(f"ttctl: internal error: {type(e).__name__}: {e} (set TTCTL_DEBUG=1 for a traceback)",
              file=sys.stderr)
        sys.exit(3)
    code = code if isinstance(code, int) else 0
    if code == 130:  # typer turns Ctrl-C into a quiet exit 130
        print("ttctl: interrupted", file=sys.stderr)
    if _fast_exit:
        try:
            sys.stdout.flush()
            sys.stderr.flush()
        except BrokenPipeError:
            code = code or 1
        os._exit(code)
    sys.exit(code)
