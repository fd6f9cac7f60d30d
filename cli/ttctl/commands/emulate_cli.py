"""`ttctl emulate ...`: both ends of the link, runnable without a drone (the work is in ttctl.ends)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from .options import (
    AcceptUnsignedOpt,
    DialectIncludeOpt,
    DialectOpt,
    DistanceOpt,
    JsonOpt,
    KeyOpt,
    PipelineOpt,
    PipeRateOpt,
    ProfileFileOpt,
    ProfileOpt,
    RateOpt,
)
from .panels import FILES, GCS, LINK, PLUGINS, RUN, SIGNING, VEHICLE

emulate_app = typer.Typer(help="Both ends of the link, runnable without a drone.", no_args_is_help=True)


@emulate_app.command("onboard")
def emulate_onboard_cmd(
    listen: Annotated[str, typer.Option("--listen", help="The tablet's DTT link: udpin:HOST:PORT (or udpout:, tcp:, "
                                                         "tcpin:).", rich_help_panel=LINK)] = "udpin:0.0.0.0:14560",
    gcs: Annotated[list[str] | None, typer.Option("--gcs", help="A ground-station link: udpout:HOST:PORT, udpin:, "
                                                                "tcpin: or tcp: (repeatable; default "
                                                                "udpout:127.0.0.1:14550 and udpout:127.0.0.1:14540, "
                                                                "where QGroundControl, MAVProxy and MAVSDK listen).",
                                                  show_default=False, rich_help_panel=GCS)] = None,
    no_gcs: Annotated[bool, typer.Option("--no-gcs", help="No ground-station links.", rich_help_panel=GCS)] = False,
    sysid: Annotated[int, typer.Option("--sysid", help="The vehicle's MAVLink system id.",
                                       rich_help_panel=VEHICLE)] = 1,
    inbox: Annotated[Path | None, typer.Option("--inbox", help="Receive files (trajectories) from the tablet into "
                                                               "this folder.", show_default=False,
                                               rich_help_panel=FILES)] = None,
    serve: Annotated[Path | None, typer.Option("--serve", help="Let the tablet fetch the files of this folder.",
                                               show_default=False, rich_help_panel=FILES)] = None,
    home: Annotated[str | None, typer.Option("--home", help="LAT,LON,ALT of home (default 46.0503,14.4686,295).",
                                             show_default=False, rich_help_panel=VEHICLE)] = None,
    speed: Annotated[float, typer.Option("--speed", help="Run the vehicle's clock this many times faster.",
                                         rich_help_panel=VEHICLE)] = 1.0,
    plugin: Annotated[list[str] | None, typer.Option("--plugin", help="path/to/plugin.py or module:attr "
                                                                      "(repeatable).", show_default=False,
                                                     rich_help_panel=PLUGINS)] = None,
    no_entry_points: Annotated[bool, typer.Option("--no-entry-points", help="Do not load the plugins installed "
                                                                            "packages declare (ttctl.plugins).",
                                                  rich_help_panel=PLUGINS)]
    = False,
    telemetry_hz: Annotated[float, typer.Option("--telemetry-hz", help="TT_NAV_SAT_FIX and TT_ODOMETRY to the "
                                                                       "tablet, per second.",
                                                rich_help_panel=VEHICLE)] = 2.0,
    orbit_hz: Annotated[float, typer.Option("--orbit-hz", help="The orbit camera (steered by head poses from "
                                                               "`ttctl hmd dump --to`): published this many times "
                                                               "a second while they arrive; 0 turns it off.",
                                            min=0, max=50, rich_help_panel=VEHICLE)] = 10.0,
    rate: RateOpt = None,
    profile: ProfileOpt = None,
    profile_file: ProfileFileOpt = None,
    distance: DistanceOpt = 10.0,
    key: KeyOpt = None,
    accept_unsigned: AcceptUnsignedOpt = False,
    gcs_key: Annotated[Path | None, typer.Option("--gcs-key", help="Sign the ground-station links' frames (MAVLink 2 "
                                                                   "signing) and accept only frames signed with this "
                                                                   "key (a file as for --key).",
                                                 show_default=False, rich_help_panel=SIGNING)] = None,
    dialect: DialectOpt = None,
    include: DialectIncludeOpt = None,
    dtt_gcs_share: Annotated[float, typer.Option("--dtt-gcs-share", help="For ground stations behind the tablet "
                                                                         "(`emulate tablet --gcs`): the share of the "
                                                                         "DTT downlink their streams may use.",
                                                 min=0.05, max=1.0, rich_help_panel=GCS)] = 0.5,
    pipeline: PipelineOpt = None,
    pipe_rate: PipeRateOpt = None,
) -> None:
    """The onboard computer's end, flying a simulated multicopter.

    The tablet's DTT link (commands, telemetry, files) and ground-station links
    (HEARTBEAT, telemetry, commands, parameters, missions) to the same vehicle.
    Runs until interrupted.

    Exit status:
      0    stopped by Ctrl-C or SIGTERM
      2    bad options, a bad plugin, or an endpoint it cannot open
      3    internal error (a bug; TTCTL_DEBUG=1 shows the traceback)
      130  interrupted while starting (Ctrl-C)

    Example (then open QGroundControl, or run emulate tablet):
      ttctl emulate onboard --inbox inbox
    """
    from .emulate import OnboardOptions, emulate_onboard

    raise typer.Exit(emulate_onboard(OnboardOptions(listen, gcs or [], no_gcs, sysid, inbox, serve, home, speed,
                                                    rate, profile, distance, plugin or [], no_entry_points,
                                                    telemetry_hz, orbit_hz, key, accept_unsigned, profile_file,
                                                    dialect, include or [], gcs_key=gcs_key,
                                                    dtt_gcs_share=dtt_gcs_share, pipeline=pipeline,
                                                    pipe_rate=pipe_rate)))


@emulate_app.command("tablet")
def emulate_tablet_cmd(
    to: Annotated[str, typer.Option("--to", help="The onboard end's DTT link: udpout:HOST:PORT (or tcp:, udpin:).",
                                    rich_help_panel=LINK)]
    = "udpout:127.0.0.1:14560",
    script: Annotated[Path | None, typer.Option("--script", help="Run these steps (a YAML list) instead of a prompt; "
                                                                 "exit 0 only if every one succeeds.",
                                                show_default=False, rich_help_panel=RUN)] = None,
    json_out: JsonOpt = False,
    folder: Annotated[Path | None, typer.Option("--dir", help="Where fetched files go.", show_default=False,
                                                rich_help_panel=FILES)] = None,
    target_sysid: Annotated[int, typer.Option("--target-sysid", help="The vehicle's system id.",
                                              rich_help_panel=VEHICLE)] = 1,
    rate: RateOpt = None,
    profile: ProfileOpt = None,
    profile_file: ProfileFileOpt = None,
    distance: DistanceOpt = 10.0,
    key: KeyOpt = None,
    accept_unsigned: AcceptUnsignedOpt = False,
    dialect: DialectOpt = None,
    include: DialectIncludeOpt = None,
    plugin: Annotated[list[str] | None, typer.Option("--plugin", help="path/to/plugin.py or module:attr "
                                                                      "(repeatable): handlers of the vehicle's "
                                                                      "messages, as on the onboard end.",
                                                     show_default=False, rich_help_panel=PLUGINS)] = None,
    gcs: Annotated[list[str] | None, typer.Option("--gcs", help="Carry a ground station to the vehicle over the link, "
                                                                "as a telemetry radio does: udpout:HOST:PORT "
                                                                "(udpout:127.0.0.1:14550 QGroundControl and MAVProxy, "
                                                                ":14540 MAVSDK) or udpin:HOST:PORT (repeatable).",
                                                  show_default=False, rich_help_panel=GCS)] = None,
    gcs_share: Annotated[float, typer.Option("--gcs-share", help="The share of the DTT uplink ground stations' frames "
                                                                 "may use (the app's commands go first anyway).",
                                             min=0.05, max=1.0, rich_help_panel=GCS)] = 0.8,
    pipeline: PipelineOpt = None,
    pipe_rate: PipeRateOpt = None,
) -> None:
    """The tablet's end: commands, files and messages to the vehicle, from a prompt or a --script.

    Commands (take-off, land, hover, return, set-points, trajectories), files
    both ways, any message of the --dialect (msg NAME field=value) and the
    vehicle's state and messages, from a prompt (history, completion) or a
    --script. With --gcs, ground stations fly the same vehicle through it
    meanwhile, and it runs until interrupted.

    At the prompt try `takeoff 5`, `status`, `land`; a --script is a YAML list
    of the same steps (`- takeoff: 5`).

    Exit status:
      0    every --script step succeeded; the prompt ended (quit, Ctrl-D);
           with --gcs, stopped by Ctrl-C or SIGTERM
      1    a --script step failed (why, in the vehicle's words), or no vehicle
           answered
      2    bad options or an unreadable --script
      3    internal error (a bug; TTCTL_DEBUG=1 shows the traceback)
      130  Ctrl-C (at the prompt, a first one cancels a waiting command)

    Examples (with emulate onboard running):
      ttctl emulate tablet
      ttctl emulate tablet --script flight.yaml
    """
    from .tablet import TabletOptions, emulate_tablet

    raise typer.Exit(emulate_tablet(TabletOptions(to, script, json_out, folder, rate, profile, distance,
                                                  target_sysid, key=key, accept_unsigned=accept_unsigned,
                                                  profile_file=profile_file, dialect=dialect,
                                                  include_dirs=include or [], plugins=plugin or [],
                                                  gcs=gcs or [], gcs_share=gcs_share, pipeline=pipeline,
                                                  pipe_rate=pipe_rate)))
