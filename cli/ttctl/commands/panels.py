"""The names of the option panels of every command's --help, one list for all commands.

Each option of each command sits in one of these panels (typer's `rich_help_panel`), so that
the same kind of option is found under the same heading everywhere; only --help stays in
typer's own "Options" panel. tests/test_help.py holds every command to this list.
"""

from __future__ import annotations

LINK = "Link"  # where this end connects and how it paces: --listen, --to, --profile, --rate, --distance
PIPELINE = "MOP pipeline"  # --pipeline, --pipe-*
IMPAIRMENTS = "Impairments"  # what the emulated link does to packets: --loss, --corrupt, --outage...
DIALECT = "Dialect"  # --dialect, -I
CHECKS = "Checks"  # what validate checks: --mtu, --signed
CODE = "Code generation"  # gen's languages, templates and names
SIGNING = "Signing"  # --key, --accept-unsigned, --gcs-key
FILES = "Files"  # what is received, served, sent: --dir, --serve, --overwrite...
GCS = "Ground stations"  # --gcs, --no-gcs, shares of the link
VEHICLE = "Vehicle"  # the emulated vehicle: --home, --speed, --telemetry-hz...
IDS = "MAVLink ids"  # --sysid, --compid, --target-*
PLUGINS = "Plugins"  # --plugin, --no-entry-points
POSES = "Headset"  # hmd: where poses come from, how they are framed; the controllers
WORKLOAD = "Workload"  # what a benchmark measures: sizes, counts, protocols, distances
OUTPUT = "Output"  # --json, -o, --plot, --quiet, --format, --force, --keep
RUN = "Run"  # how long and how reproducibly: --timeout, --seed, --duration, --runs, --quick

PANELS = (LINK, PIPELINE, IMPAIRMENTS, DIALECT, CHECKS, CODE, SIGNING, FILES, GCS, VEHICLE, IDS, PLUGINS, POSES,
          WORKLOAD, OUTPUT, RUN)

__all__ = ["CHECKS", "CODE", "DIALECT", "FILES", "GCS", "IDS", "IMPAIRMENTS", "LINK", "OUTPUT", "PANELS", "PIPELINE",
           "PLUGINS", "POSES", "RUN", "SIGNING", "VEHICLE", "WORKLOAD"]
