"""`ttctl link ...`: the emulated link between processes (relay) and profiles fitted from
measurements (fit). The work is in ttctl.commands.relay and ttctl.bench.fit."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from .options import DialectIncludeOpt, DialectOpt, ProfileFileOpt
from .panels import IMPAIRMENTS, LINK, OUTPUT, PIPELINE, RUN

link_app = typer.Typer(help="The emulated DJI link between processes, and link profiles fitted from measurements.",
                       no_args_is_help=True)


@link_app.command("relay")
def link_relay(
    listen: Annotated[str, typer.Option("--listen", help="udp:HOST:PORT where the tablet side sends (udpin).",
                                        show_default=False, rich_help_panel=LINK)],
    to: Annotated[str, typer.Option("--to", help="udp:HOST:PORT of the onboard side (udpout).",
                                    show_default=False, rich_help_panel=LINK)],
    profile: Annotated[str | None, typer.Option("--profile", help="Link profile: m100, m300, psdk, mop or lan "
                                                                  "(default m100), or one in --profile-file.",
                                                show_default=False, rich_help_panel=LINK)] = None,
    profile_file: ProfileFileOpt = None,
    distance: Annotated[float, typer.Option("--distance", help="Distance in metres.", rich_help_panel=LINK)] = 10.0,
    loss: Annotated[float | None, typer.Option("--loss", help="Packet loss probability, both directions "
                                                              "(default: the profile's at --distance).",
                                               show_default=False, rich_help_panel=IMPAIRMENTS)] = None,
    loss_model: Annotated[str | None, typer.Option("--loss-model", help="random or burst (Gilbert-Elliott); "
                                                                        "default: the profile's (random in ttctl's "
                                                                        "own).", show_default=False,
                                                   rich_help_panel=IMPAIRMENTS)] = None,
    burst_mean: Annotated[float | None, typer.Option("--burst-mean", help="With burst loss: the mean burst, in "
                                                                          "slots (a full packet's time on the "
                                                                          "radio): the mean run of lost packets on "
                                                                          "a saturated link; a sparse flow sees "
                                                                          "the same burst in time (default: the "
                                                                          "profile's, 3).", show_default=False,
                                                     rich_help_panel=IMPAIRMENTS)]
    = None,
    corrupt: Annotated[float, typer.Option("--corrupt", help="Probability that a packet has bytes flipped.",
                                           rich_help_panel=IMPAIRMENTS)] = 0.0,
    duplicate: Annotated[float, typer.Option("--duplicate", help="Probability that a packet arrives twice.",
                                             rich_help_panel=IMPAIRMENTS)]
    = 0.0,
    reorder: Annotated[float, typer.Option("--reorder", help="Probability that a packet is held back behind "
                                                             "later ones.", rich_help_panel=IMPAIRMENTS)] = 0.0,
    seed: Annotated[int, typer.Option("--seed", help="Random seed.", rich_help_panel=RUN)] = 0,
    rate: Annotated[float | None, typer.Option("--rate", help="Override the profile's rate, both directions, "
                                                              "bytes per second.", show_default=False,
                                               rich_help_panel=LINK)] = None,
    stats_interval: Annotated[float, typer.Option("--stats-interval", help="Seconds between stats lines on "
                                                                           "stderr (0: only at the end).",
                                                  rich_help_panel=OUTPUT)] = 5.0,
    outage: Annotated[list[str] | None, typer.Option("--outage", help="START:SECONDS: nothing gets through, "
                                                                      "either way, for SECONDS from START seconds "
                                                                      "after the relay starts (repeatable).",
                                                     show_default=False, rich_help_panel=IMPAIRMENTS)] = None,
    dialect: DialectOpt = None,
    include: DialectIncludeOpt = None,
    pipe_listen: Annotated[str | None, typer.Option(
        "--pipe-listen", metavar="tcp:HOST:PORT", show_default=False,
        help="Also emulate a MOP pipeline (--profile mop): the tablet side's --pipeline tcpout: connects here.",
        rich_help_panel=PIPELINE)]
    = None,
    pipe_to: Annotated[str | None, typer.Option(
        "--pipe-to", metavar="tcp:HOST:PORT", show_default=False,
        help="The onboard side's --pipeline tcpin:, which the relay connects to for each pipeline.",
        rich_help_panel=PIPELINE)] = None,
    pipe_drop: Annotated[list[str] | None, typer.Option(
        "--pipe-drop", metavar="START:SECONDS", show_default=False,
        help="Close the pipeline START seconds after the relay starts, losing what is in flight, and refuse it "
             "for SECONDS (repeatable; --outage closes it too).", rich_help_panel=PIPELINE)] = None,
    pipe_rate: Annotated[float | None, typer.Option(
        "--pipe-rate", show_default=False,
        help="The pipeline's rate each way, bytes per second (default: the profile's).",
        rich_help_panel=PIPELINE)] = None,
    pipe_stall: Annotated[list[str] | None, typer.Option(
        "--pipe-stall", metavar="START:SECONDS", show_default=False,
        help="Stop the pipeline START seconds after the relay starts for SECONDS without closing it, as DJI's "
             "send timeouts do (repeatable).", rich_help_panel=PIPELINE)] = None,
) -> None:
    """The emulated DJI radio link, as a process between the two ends, in real time.

    Packets arriving on --listen (the tablet side) go through the profile's
    uplink model (rate, SDK buffer, loss, latency) and reach --to after the
    modelled time, or are lost, corrupted, duplicated or reordered as asked.
    Packets from --to go through the downlink model to every address that sent
    a valid frame to --listen lately. Datagrams over the profile's MTU (100
    bytes) are dropped, as DJI refuses them. A stats line goes to stderr every
    --stats-interval seconds, and a last one on SIGINT/SIGTERM. The relay
    carries packets, whatever they hold; it learns who is behind an address
    only from valid frames of the --dialect (so strangers cannot divert it).

    With --profile mop and --pipe-listen/--pipe-to it also carries a MOP
    pipeline (a byte stream at the profile's pipeline rate) between the ends'
    --pipeline options; --pipe-drop and --outage close it.

    Exit status:
      0    stopped by Ctrl-C or SIGTERM
      2    bad options or an endpoint it cannot open
      3    internal error (a bug; TTCTL_DEBUG=1 shows the traceback)
      130  interrupted while starting (Ctrl-C)

    Example, in three shells:
      ttctl link relay --listen udp:127.0.0.1:14550 --to udp:127.0.0.1:14560 \\
          --loss 0.1
      ttctl recv-file --listen udpin:127.0.0.1:14560 --dir inbox
      ttctl send-file FILE --to udpout:127.0.0.1:14550 --profile m100
    """
    from .relay import RelayOptions, relay

    code = relay(RelayOptions(listen, to, profile, distance, loss, loss_model, corrupt, duplicate, reorder, seed,
                              rate, stats_interval, outage or [], profile_file, burst_mean, dialect, include or [],
                              pipe_listen, pipe_to, pipe_drop or [], pipe_rate, pipe_stall or []))
    raise typer.Exit(code)


@link_app.command("fit")
def link_fit(
    measurements: Annotated[list[Path], typer.Argument(help="JSON reports of `ttctl bench link --to ... -o "
                                                            "FILE.json`, at one or more distances.",
                                                       show_default=False)],
    output: Annotated[Path, typer.Option("-o", "--output", help="Where the profile goes (FILE.toml, written "
                                                                "whole or not at all).", show_default=False,
                                         rich_help_panel=OUTPUT)],
    name: Annotated[str | None, typer.Option("--name", help="The profile's name in the file (default: the output "
                                                            "file's stem).", show_default=False,
                                             rich_help_panel=OUTPUT)] = None,
    base: Annotated[str, typer.Option("--base", help="ttctl's profile whose figures fill in what the "
                                                     "measurements cannot show (MTU, feedback, an unmeasured "
                                                     "direction).", rich_help_panel=LINK)] = "m100",
    json_out: Annotated[bool, typer.Option("--json", help="Print the fit (profile, notes, residuals) as JSON.",
                                           rich_help_panel=OUTPUT)]
    = False,
    force: Annotated[bool, typer.Option("--force", help="Replace -o's file if it exists (refused otherwise).",
                                        rich_help_panel=OUTPUT)]
    = False,
) -> None:
    """A link profile fitted from your own measurements (of `ttctl bench link --to`).

    Rate and loss against distance, pacing, SDK buffer depth, latency and
    burstiness (Gilbert-Elliott from the loss runs). Each measurement is then
    replayed on the fitted profile and compared figure by figure (the
    residuals). Use the profile with --profile-file wherever --profile is
    accepted.

    Exit status:
      0    the profile is written
      2    unreadable or unusable measurements, bad options, or -o exists
           (--force replaces it) or cannot be written
      3    internal error (a bug; TTCTL_DEBUG=1 shows the traceback)
      130  interrupted (Ctrl-C); nothing written

    Example:
      ttctl link fit field-10m.json field-150m.json -o myfield.toml
    """
    from .link_fit import fit_command

    raise typer.Exit(fit_command([str(m) for m in measurements], str(output), name, base, json_out, force=force))
