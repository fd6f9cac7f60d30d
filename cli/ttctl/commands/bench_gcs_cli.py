"""`ttctl bench gcs`: a ground station through the tablet end, bridge against a naive forwarder
(the work is in ttctl.bench.gcs)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from ..errors import Fail
from .panels import GCS, IMPAIRMENTS, LINK, OUTPUT, RUN, WORKLOAD


def _distances(text: str) -> list[float]:
    out = []
    for part in text.split(","):
        part = part.strip()
        try:
            d = float(part)
        except ValueError:
            raise Fail(f"--distance: {part!r} is not a number of metres (e.g. 10 or 10,150)") from None
        if not 0 <= d <= 10_000:
            raise Fail(f"--distance: {part} m is outside 0..10000")
        out.append(d)
    if not out:
        raise Fail("--distance: give at least one distance (e.g. 10 or 10,150)")
    return out


def _ids(text: str) -> tuple[int, int]:
    parts = text.split("/")
    try:
        sysid, compid = (int(p) for p in parts)
    except ValueError:
        raise Fail(f"--gcs-id: {text!r} is not SYSID/COMPID (e.g. 255/190)") from None
    if not (1 <= sysid <= 255 and 0 <= compid <= 255):
        raise Fail(f"--gcs-id: {text} is outside 1..255/0..255")
    return sysid, compid


def bench_gcs(
    distance: Annotated[str, typer.Option("--distance", help="Distances in metres, comma-separated (e.g. "
                                                             "10,150).", rich_help_panel=LINK)] = "10",
    loss: Annotated[float, typer.Option("--loss", help="Packet loss probability of the relay, both "
                                                       "directions.", min=0.0, max=0.9,
                                        rich_help_panel=IMPAIRMENTS)] = 0.1,
    loss_model: Annotated[str, typer.Option("--loss-model", help="random or burst.",
                                            rich_help_panel=IMPAIRMENTS)] = "random",
    items: Annotated[int, typer.Option("--items", help="Mission items uploaded and downloaded.", min=1,
                                       max=200, rich_help_panel=WORKLOAD)] = 20,
    commands: Annotated[int, typer.Option("--commands", help="App commands idle (and at least as many with the "
                                                             "ground station on).", min=1, max=1000,
                                          rich_help_panel=WORKLOAD)] = 50,
    interval: Annotated[float, typer.Option("--interval", help="Seconds between app commands.", min=0.1,
                                            max=60, rich_help_panel=WORKLOAD)] = 0.5,
    step_timeout: Annotated[float, typer.Option("--step-timeout", help="Seconds a ground-station step may "
                                                                       "wait in all before it counts as "
                                                                       "failed.", min=5, max=600,
                                                rich_help_panel=RUN)] = 60.0,
    seed: Annotated[int, typer.Option("--seed", help="The relay's random seed.", rich_help_panel=RUN)] = 1,
    repeat: Annotated[int, typer.Option("--repeat", help="Runs of each, on seeds --seed, --seed + 1, ...: the "
                                                         "figures and the floors are their medians.", min=1,
                                        max=20, rich_help_panel=RUN)] = 1,
    gcs_id: Annotated[str, typer.Option("--gcs-id", help="The ground station's SYSID/COMPID (QGroundControl's "
                                                         "default, which is also the tablet's).",
                                        rich_help_panel=GCS)] = "255/190",
    sticks: Annotated[float, typer.Option("--sticks", help="The ground station also sends MANUAL_CONTROL this "
                                                           "many times a second once it hears the vehicle (a "
                                                           "joystick; 0: none).", min=0, max=100,
                                          rich_help_panel=GCS)] = 0.0,
    ftp: Annotated[int, typer.Option("--ftp", help="After the mission the ground station fetches a file of this "
                                                   "many KB by MAVLink FTP (pymavlink's mavftp): its longest "
                                                   "HEARTBEAT gap and position rate during it against idle "
                                                   "(0: no).", min=0, max=1024, rich_help_panel=WORKLOAD)] = 0,
    only: Annotated[str, typer.Option("--only", help="bridge, naive or both.", rich_help_panel=WORKLOAD)] = "both",
    quick: Annotated[bool, typer.Option("--quick", help="A smoke test: 10 items, 4 commands, 20 s steps.",
                                        rich_help_panel=RUN)]
    = False,
    keep: Annotated[Path | None, typer.Option("--keep", help="Keep every process's stderr in this (new or "
                                                             "empty) folder.", show_default=False,
                                              rich_help_panel=OUTPUT)] = None,
    json_out: Annotated[bool, typer.Option("--json", help="Print the report as JSON.", rich_help_panel=OUTPUT)] = False,
) -> None:
    """A ground station through the tablet end (the bridge) against a naive forwarder.

    A QGroundControl-like ground station through `emulate tablet --gcs` and
    through a naive forwarder, side by side over `link relay --profile m100`
    with loss, to `emulate onboard`: connect sequence, parameter list, mission
    upload and download, position age at the ground station, and the app's
    command latency idle and with the ground station on.

    Exit status:
      0    the floors hold (they count at 10 m, 10 % random loss)
      1    a floor is missed
      2    bad options or an unusable --keep
      3    internal error (a bug; TTCTL_DEBUG=1 shows the traceback)
      130  interrupted (Ctrl-C)

    Example:
      ttctl bench gcs --quick
    """
    from ..bench.gcs import MODES, Options, run

    if loss_model not in ("random", "burst"):
        raise Fail(f"--loss-model must be random or burst, not {loss_model!r}")
    if only not in ("bridge", "naive", "both"):
        raise Fail(f"--only must be bridge, naive or both, not {only!r}")
    if keep is not None and keep.exists() and (not keep.is_dir() or any(keep.iterdir())):
        raise Fail(f"--keep: {keep} is not a new or empty folder")
    o = Options(_distances(distance), loss, loss_model, items, commands, interval, step_timeout, seed,
                gcs_id=_ids(gcs_id), sticks_hz=sticks, json_out=json_out, quick=quick, keep=str(keep) if keep else None,
                modes=MODES if only == "both" else (only,), ftp_kb=ftp, repeat=repeat)
    if quick:
        o.items, o.commands, o.interval, o.step_timeout = min(items, 10), min(commands, 4), min(interval, 0.5), 20.0
    raise typer.Exit(run(o))
