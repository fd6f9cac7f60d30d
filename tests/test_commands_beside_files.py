"""Commands never lost to bulk, on the link model in virtual time (sans-IO): uploads from other
processes (send-file) share the m100 uplink's two-packet buffer with the tablet's commands, and
the receiver's rate grants leave the commands room: once a command has been heard the transfers
are granted CONTROL_FILL of the uplink (a lone one too, which would otherwise pace to the whole
link with three-packet frames and keep the buffer full), so a command waits at most about the
packet on the air, as `bench latency` promises. Before: 5 senders, command p95 543 ms over the
423 ms bound; a lone sender kept no room at all."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from conftest import shipped
from ttctl.bench.latency import bound_s, percentile
from ttctl.bench.sharing import run_senders
from ttctl.link.model import load_profile
from ttctl.proto.endpoint import Endpoint
from ttctl.proto.sharing import CONTROL_FILL, GRANT_FILL, share
from ttctl.proto.storage import ReceiveDir

B = shipped()
SEEDS = [1, 2, 3, 4, 5]


def test_a_lone_transfer_is_granted_room_once_commands_are_heard() -> None:
    assert share(500, 1) == 0  # no control traffic: a lone transfer paces to its link, as before
    assert share(500, 1, control=True) == int(CONTROL_FILL * 500)
    assert share(500, 3, control=True) == int(CONTROL_FILL * 500 / 3) < share(500, 3) == int(GRANT_FILL * 500 / 3)


def test_the_receiver_hears_commands_but_not_hellos_or_telemetry(tmp_path: Path) -> None:
    ep = Endpoint(B, 1, 240, mtu=255, receive_dir=ReceiveDir(tmp_path), inbound_Bps=500)
    tablet = B.encoder(255, 190)
    assert ep.receiver is not None
    ep.receive(1.0, tablet.encode(B.Heartbeat(type=6, autopilot=8)), "a")  # every sender's hello
    assert ep.receiver.control_at is None
    vehicle = B.encoder(1, 240)  # the other end's telemetry (a fetch from the onboard end) is not control traffic
    ep.receive(1.5, vehicle.encode(B.TtNavSatFix(time_usec=1, latitude=460503000, longitude=144686000)), "a")
    assert ep.receiver.control_at is None
    ep.receive(2.0, tablet.encode(B.TtActionCommand(target_system=1, target_component=240, action=1)), "a")
    assert ep.receiver.control_at == 2.0
    ep.close()


def test_no_control_grant_while_a_pipeline_carries_the_data(tmp_path: Path) -> None:
    """Commands stay in the packets while file data goes on a pipeline: they never wait behind it,
    so a lone transfer keeps the pipeline's whole rate (the control grant would cap it at 0.75 of
    the rate, or at what TT_FILE_STATUS.rate_grant holds); when the pipeline closes the data is back
    beside the commands and the control grant returns."""
    ep = Endpoint(B, 1, 240, mtu=255, receive_dir=ReceiveDir(tmp_path), inbound_Bps=500)
    rx = ep.receiver
    assert rx is not None
    ep.receive(2.0, B.encoder(255, 190).encode(B.TtActionCommand(target_system=1, target_component=240, action=1)),
               "a")
    ep.pipe.open(2.5, 100_000)
    assert rx.control_apart and rx.inbound_Bps == 100_000
    ep.pipe.close(3.0)
    assert not rx.control_apart and rx.inbound_Bps == 500
    ep.close()


@pytest.mark.parametrize("senders", [1, 3, 5])
def test_commands_keep_their_bound_while_transfers_from_other_processes_run(senders: int) -> None:
    prof = load_profile("m100")
    idle: list[float] = []
    during: list[Any] = []
    for seed in SEEDS:
        r = run_senders(prof, 10.0, senders, None, "random", 4096, seed, commands=True)
        assert all(r["ok"]), r
        idle += r["idle"]
        during += r["during"]
    assert None not in idle + during  # no command failed
    ceiling = percentile(idle, 0.95) + bound_s(prof, 10.0)
    p95 = percentile(during, 0.95)
    assert p95 <= ceiling, f"{senders} senders: command p95 {1000 * p95:.0f} ms over {1000 * ceiling:.0f} ms"
