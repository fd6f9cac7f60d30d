"""`ttctl emulate onboard`: the onboard computer's end, flying a simulated vehicle, on the tablet's
DTT link and on ground-station links at once."""

from __future__ import annotations

import asyncio
import contextlib
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import Fail
from .common import Signals, check_id, err, link_choice, load_signing, parse_endpoint, pipe_link
from .dialect import load_bindings

DEFAULT_DTT = "udpin:0.0.0.0:14560"
DEFAULT_GCS = ["udpout:127.0.0.1:14550", "udpout:127.0.0.1:14540"]  # QGroundControl/MAVProxy, MAVSDK


@dataclass
class OnboardOptions:
    listen: str = DEFAULT_DTT
    gcs: list[str] = field(default_factory=list)
    no_gcs: bool = False
    sysid: int = 1
    inbox: Path | None = None
    serve: Path | None = None
    home: str | None = None
    speed: float = 1.0
    rate: float | None = None
    profile: str | None = None
    distance: float = 10.0
    plugins: list[str] = field(default_factory=list)
    no_entry_points: bool = False
    telemetry_hz: float = 2.0
    orbit_hz: float = 10.0
    key: Path | None = None
    accept_unsigned: bool = False
    profile_file: Path | None = None
    dialect: Path | None = None
    include_dirs: list[Path] = field(default_factory=list)
    gcs_key: Path | None = None
    dtt_gcs_share: float = 0.5  # of the DTT downlink, for ground stations behind the tablet
    pipeline: str | None = None  # a MOP pipeline beside the DTT link (tcpin:/tcpout:)
    pipe_rate: float | None = None


def _home(text: str | None) -> Any:
    from ..ends.onboard.vehicle import Home

    if text is None:
        return Home()
    parts = text.split(",")
    try:
        if len(parts) != 3:
            raise ValueError
        lat, lon, alt = (float(p) for p in parts)
    except ValueError:
        raise Fail(f"--home wants LAT,LON,ALT (degrees, degrees, metres above sea level), not {text!r}") from None
    if not (-90 <= lat <= 90 and -180 <= lon <= 180 and -500 <= alt <= 9000):
        raise Fail(f"--home {text}: out of range")
    return Home(lat, lon, alt)


def _gcs_signing(key: Path | None, b: Any) -> Any:
    """--gcs-key: as --key, with its own words in errors."""
    try:
        return load_signing(key, False, b)
    except Fail as e:
        raise Fail(str(e).replace("--key", "--gcs-key", 1)) from None


def emulate_onboard(o: OnboardOptions) -> int:
    from ..ends.onboard.node import OnboardConfig, OnboardNode
    from ..ends.plugins import PluginError, entry_point_plugins, load_plugin
    from ..proto.storage import ReceiveDir, StorageError

    check_id(o.sysid, "--sysid")
    if not 1 <= o.sysid <= 254:
        raise Fail("--sysid must be in 1..254 (ground stations ignore 0 and 255)")
    if not 0 < o.speed <= 100:
        raise Fail("--speed must be in (0, 100]")
    if not 0 <= o.telemetry_hz <= 50:
        raise Fail("--telemetry-hz must be in 0..50")
    if o.no_gcs and o.gcs:
        raise Fail("--no-gcs and --gcs contradict each other: give one of them")
    dtt = parse_endpoint(o.listen, "udpin")
    gcs = [] if o.no_gcs else [parse_endpoint(g, "udpout") for g in (o.gcs or DEFAULT_GCS)]
    link = link_choice(o.rate, o.profile, o.distance, o.sysid, o.profile_file, o.pipe_rate)
    pipe, pipe_Bps = pipe_link(o.pipeline, link, err)
    if o.inbox is not None:
        try:
            ReceiveDir(o.inbox).check()
        except StorageError as e:
            raise Fail(f"--inbox: {e}") from None
    if o.serve is not None and not o.serve.is_dir():
        raise Fail(f"--serve {o.serve} is not a directory")
    b = load_bindings(o.dialect, o.include_dirs)  # before the plugins: they import its package
    cfg = OnboardConfig(sysid=o.sysid, dtt=dtt, gcs=gcs, inbox=o.inbox, serve=o.serve, home=_home(o.home),
                        speed=o.speed, rate_Bps=link.pace_Bps, mtu=link.mtu, inbound_Bps=link.recv_capacity,
                        telemetry_hz=o.telemetry_hz, orbit_hz=o.orbit_hz,
                        signing=load_signing(o.key, o.accept_unsigned, b),
                        gcs_signing=_gcs_signing(o.gcs_key, b), dtt_gcs_share=o.dtt_gcs_share,
                        pipe=pipe, pipe_Bps=pipe_Bps)
    try:
        plugins = [] if o.no_entry_points else entry_point_plugins()
        for spec in o.plugins:
            plugins.extend(load_plugin(spec))
        node = OnboardNode(b, cfg, plugins, log=lambda text: err(text))  # checks the plugins' messages
    except PluginError as e:
        raise Fail(f"--plugin {e}") from None

    async def main() -> None:
        from ..link.transport import TransportError

        loop = asyncio.get_running_loop()
        wake = asyncio.Event()
        sigs = Signals(loop, wake)
        try:
            try:
                await node.start()
            except (TransportError, StorageError) as e:
                raise Fail(str(e)) from None
            dtt_at = node.runner.transport.describe() if node.runner is not None else "none"
            gcs_at = ", ".join(t.describe() for t in node.gcs_links) or "none"
            names = ", ".join(type(p).__name__ for p in plugins)
            err(f"onboard {o.sysid}: tablet link {dtt_at}; ground stations {gcs_at}; home {cfg.home.lat:.5f}, "
                f"{cfg.home.lon:.5f}, {cfg.home.alt:g} m; dialect {b.name}" + (f"; plugins {names}" if names else ""))
            await node.run(sigs.stop)
        finally:
            sigs.remove()
            await node.close()

    with contextlib.suppress(KeyboardInterrupt):
        asyncio.run(main())
    print(f"ttctl: onboard {o.sysid} stopped", file=sys.stderr)
    return 0
