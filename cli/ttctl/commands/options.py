"""Option types several command groups share."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from .panels import DIALECT, LINK, OUTPUT, PIPELINE, SIGNING

RateOpt = Annotated[float | None, typer.Option("--rate", help="Pacing rate in bytes per second (overrides the "
                                                              "profile's).", show_default=False, rich_help_panel=LINK)]
ProfileOpt = Annotated[str | None, typer.Option("--profile", help="Link profile (m100, m300, psdk, mop, lan): pace "
                                                                  "at its capacity in this end's sending direction.",
                                                show_default=False, rich_help_panel=LINK)]
ProfileFileOpt = Annotated[Path | None, typer.Option("--profile-file", help="Take --profile from this TOML file "
                                                                         "(the schema of ttctl's profiles.toml, "
                                                                         "e.g. written by `ttctl link fit`); "
                                                                         "--profile may be left out when it holds "
                                                                         "one profile.", show_default=False,
                                                     rich_help_panel=LINK)]
PipelineOpt = Annotated[str | None, typer.Option(
    "--pipeline", metavar="tcpin:HOST:PORT|tcpout:HOST:PORT", show_default=False,
    help="A MOP pipeline beside the link (DJI's SDK interconnection, or `ttctl link relay --profile mop`), for "
         "file data while it is open: tcpin accepts (the onboard computer), tcpout connects (the app), again "
         "after every close.",
    rich_help_panel=PIPELINE)]
PipeRateOpt = Annotated[float | None, typer.Option(
    "--pipe-rate", show_default=False,
    help="The pipeline's rate in bytes per second, each way (default: the profile's pipeline, 100000 with "
         "--profile mop or without a profile).", rich_help_panel=PIPELINE)]
DistanceOpt = Annotated[float, typer.Option("--distance", help="Distance in metres, for --profile.",
                                            rich_help_panel=LINK)]
JsonOpt = Annotated[bool, typer.Option("--json", help="Machine-readable output (JSON).", rich_help_panel=OUTPUT)]
KeyOpt = Annotated[Path | None, typer.Option("--key", help="Sign the DTT link's frames (MAVLink 2 signing) and "
                                                            "accept only frames signed with this key: a file holding "
                                                            "64 hex digits, or a passphrase (its SHA-256 is the key, "
                                                            "as MAVProxy's `signing setup`).", show_default=False,
                                             rich_help_panel=SIGNING)]
AcceptUnsignedOpt = Annotated[bool, typer.Option("--accept-unsigned", help="With --key: accept unsigned frames "
                                                                          "too.", rich_help_panel=SIGNING)]
PLOT_EXTRA = "needs the plot extra: pip install 'ttctl\\[plot]'"  # \\[ keeps rich from reading a style tag
DialectOpt = Annotated[Path | None, typer.Option(
    "--dialect", envvar="TTCTL_DIALECT", metavar="FILE.xml", show_default=False,
    help="The dialect on the link: yours, which includes ttapi.xml (its Python bindings are generated on first "
         "use and cached); default ttctl's ttapi. Set $TTCTL_DIALECT once instead.", rich_help_panel=DIALECT)]
DialectIncludeOpt = Annotated[list[Path] | None, typer.Option(
    "-I", "--include-dir", envvar="TTCTL_INCLUDE", metavar="DIR", show_default=False,
    help="Extra directory to search for the --dialect's <include> files (repeatable; $TTCTL_INCLUDE).",
    rich_help_panel=DIALECT)]
