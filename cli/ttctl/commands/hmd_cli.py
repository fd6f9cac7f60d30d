"""`ttctl hmd ...`: VR headset and controller pose streams (the work is in ttctl.hmd)."""

from __future__ import annotations

from typing import Annotated

import typer

from .options import DialectIncludeOpt, DialectOpt, DistanceOpt, ProfileFileOpt, ProfileOpt, RateOpt
from .panels import LINK, OUTPUT, POSES, RUN

hmd_app = typer.Typer(help="VR headset and controller pose streams: record, replay, stream to the drone.",
                      no_args_is_help=True)


@hmd_app.command("dump")
def hmd_dump_cmd(
    source: Annotated[str, typer.Option("--source", help="openvr (a headset, through SteamVR; needs ttctl\\[vr]), "
                                                         "synthetic (seeded head and hand motion), or replay FILE "
                                                         "(a recording of ours).",
                                        rich_help_panel=POSES)] = "synthetic",
    file: Annotated[str | None, typer.Argument(help="The recording, with --source replay.", show_default=False)]
    = None,
    rate_hmd: Annotated[float, typer.Option("--rate-hmd", help="Headset poses per second.",
                                            rich_help_panel=POSES)] = 90.0,
    rate_controllers: Annotated[float, typer.Option("--rate-controllers", help="Controller and tracker poses per "
                                                                               "second.",
                                                    rich_help_panel=POSES)] = 250.0,
    duration: Annotated[float | None, typer.Option("--duration", help="Stop after this many seconds (default: "
                                                                      "until Ctrl-C, or the recording's end).",
                                                   show_default=False, rich_help_panel=RUN)] = None,
    fmt: Annotated[str | None, typer.Option("--format", help="jsonl, csv, mcap (ROS 2) or bag (ROS 1); default "
                                                             "from -o's extension, else jsonl.",
                                            show_default=False, rich_help_panel=OUTPUT)] = None,
    output: Annotated[str | None, typer.Option("-o", "--output", help="Write here (default: stdout, jsonl/csv "
                                                                      "only).", show_default=False,
                                               rich_help_panel=OUTPUT)] = None,
    frame: Annotated[str, typer.Option("--frame", help="ros (REP-103: x forward, y left, z up) or openvr "
                                                       "(raw: y up, -z forward).", rich_help_panel=POSES)] = "ros",
    parent_frame: Annotated[str, typer.Option("--parent-frame", help="The tf parent of every device's "
                                                                     "frame.", rich_help_panel=POSES)] = "vr_world",
    seed: Annotated[int, typer.Option("--seed", help="The synthetic source's seed.", rich_help_panel=RUN)] = 0,
    speed: Annotated[float, typer.Option("--speed", help="Synthetic and replay: this many times real time; 0 as "
                                                         "fast as possible.", rich_help_panel=RUN)] = 1.0,
    to: Annotated[str | None, typer.Option("--to", help="Also stream the poses over the link to the onboard end "
                                                        "(udpout:HOST:PORT...) as TT_VR_POSE / TT_VR_CONTROLLER.",
                                           show_default=False, rich_help_panel=LINK)] = None,
    stream_hz: Annotated[float, typer.Option("--stream-hz", help="With --to: at most this many poses per second "
                                                                 "per device (the link's pacing limits "
                                                                 "further).", rich_help_panel=LINK)] = 30.0,
    rate: RateOpt = None,
    profile: ProfileOpt = None,
    profile_file: ProfileFileOpt = None,
    distance: DistanceOpt = 10.0,
    quiet: Annotated[bool, typer.Option("--quiet", "-q", help="No summary on stderr.", rich_help_panel=OUTPUT)] = False,
    salvage: Annotated[bool, typer.Option("--salvage", help="Replay what can be read of a recording that is cut "
                                                            "short or damaged (refused otherwise, exit 1).",
                                          rich_help_panel=POSES)] = False,
    force: Annotated[bool, typer.Option("--force", help="Let -o replace an existing file.",
                                        rich_help_panel=OUTPUT)] = False,
    dialect: DialectOpt = None,
    include: DialectIncludeOpt = None,
) -> None:
    """Record VR poses: JSONL to stdout, or CSV, a ROS 2 MCAP file or a ROS 1 bag.

    Optionally streamed to the drone (--to; paced for --profile, m100 by
    default). Ctrl-C finishes the file.

    Exit status:
      0    recorded (--duration, the recording's end, or Ctrl-C)
      1    a damaged recording without --salvage; with --to, the onboard end
           never answered or did not confirm a button change
      2    bad options, an unreadable recording, or -o exists (--force)
      3    internal error (a bug; TTCTL_DEBUG=1 shows the traceback)
      130  interrupted while starting (Ctrl-C)

    Example (10 s of the synthetic headset):
      ttctl hmd dump --duration 10 -o poses.mcap
    """
    from .hmd import DumpOptions, dump

    raise typer.Exit(dump(DumpOptions(source, file, rate_hmd, rate_controllers, duration, fmt, output, frame,
                                      parent_frame, seed, speed, to, rate, profile, distance, stream_hz, quiet,
                                      profile_file=profile_file, dialect=dialect, include_dirs=include or [],
                                      salvage=salvage, force=force)))


@hmd_app.command("pulse")
def hmd_pulse_cmd(
    device: Annotated[str, typer.Option("--device", help="left or right controller.", rich_help_panel=POSES)] = "right",
    us: Annotated[int, typer.Option("--us", help="Pulse length in microseconds, 0..3999 (clamped).",
                                    rich_help_panel=POSES)] = 2000,
) -> None:
    """A haptic pulse on a controller (the openvr source; needs ttctl\\[vr] and SteamVR).

    Exit status:
      0    pulsed
      2    bad options, or no headset (the VR extra, SteamVR, a controller)
      3    internal error (a bug; TTCTL_DEBUG=1 shows the traceback)
      130  interrupted (Ctrl-C)

    Example:
      ttctl hmd pulse --device left --us 3000
    """
    from .hmd import pulse

    raise typer.Exit(pulse(device, us))
