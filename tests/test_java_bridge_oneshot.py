"""One-shot requests through the Java runtime's GcsBridge (issue 29, item 2), real processes:

    pymavlink GCS (udpin, 255/190) <-> [BridgeDriver: Session + GcsBridge on a UdpLink]
        <-> ttctl link relay --profile m100 --loss 0.1 <-> ttctl emulate onboard --no-gcs

Each request is sent ONCE, as MAVProxy sends them: the bridge resends what the link lost
(runtime.GcsResend), so at least 19 of 20 of each kind are answered (75-90 % were without)."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from e2e_lib import LOCAL, Start, free_port, relay
from test_gcs_bridge_oneshot import ack_and
from test_java_bridge_e2e import RELAY, Driver, Gcs, classes  # noqa: F401  (the module's fixture)

pytestmark = pytest.mark.skipif(not (shutil.which("javac") and shutil.which("java")),
                                reason="needs a JDK (javac, java)")

WAIT = 6.0  # s a station waits for the answer to its one request (the bridge's bound is 4 s)


def test_java_bridge_answers_one_shot_requests_at_10_percent_loss(classes: Path, tmp_path: Path,  # noqa: F811
                                                                  start: Start) -> None:
    from conftest import shipped
    from ttctl.ends.onboard.autopilot import Autopilot
    from ttctl.ends.onboard.vehicle import SimVehicle

    a, b, gcs_port, listen = free_port(), free_port(), free_port(), free_port()
    node = start("onboard", "emulate", "onboard", "--no-gcs", "--listen", f"udpin:{LOCAL}:{b}", "--no-entry-points",
                 "--profile", "m100")
    node.wait_for("onboard 1:")
    relay(start, a, b, *RELAY[:-4], "--seed", "8", "--stats-interval", "0")
    qgc = Gcs(f"udpin:{LOCAL}:{gcs_port}", 255, 190)
    drv = Driver(classes, tmp_path, a, gcs_port, listen)
    try:
        hb = qgc.wait(lambda m: m.get_type() == "HEARTBEAT" and m.get_srcSystem() == 1, 20)
        assert hb is not None
        names = [p.name for p in Autopilot(shipped(), SimVehicle()).params.params][:20]
        commands = params = lists = 0
        for i in range(20):
            qgc.m.mav.command_long_send(1, 1, 512, 0, 242, 0, 0, 0, 0, 0, 0)  # REQUEST_MESSAGE(HOME_POSITION)
            commands += qgc.wait(ack_and(512, "HOME_POSITION"), WAIT) is not None  # (the ack and the message)
            n = names[i]
            qgc.m.mav.param_request_read_send(1, 1, n.encode(), -1)
            params += qgc.wait(lambda m, n=n: m.get_type() == "PARAM_VALUE" and m.param_id == n, WAIT) is not None
            qgc.m.mav.mission_request_list_send(1, 1, 0)
            lists += qgc.wait(lambda m: m.get_type() == "MISSION_COUNT", WAIT) is not None
        stats = drv.stats()
    finally:
        if drv.p.poll() is None:
            drv.close()
        qgc.m.close()
    assert min(commands, params, lists) >= 19, (commands, params, lists, stats)
    assert stats["resent"] > 0, stats  # the link did lose some
