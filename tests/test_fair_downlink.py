"""The onboard end's downlink to ground stations behind the tablet is fair (issue 29), sans-IO in
virtual time: the DTT scheduler at the M100's downlink (100-byte packets, 6.7 KB/s) pulling
ends/onboard/dtt_gcs.py while one station downloads 64 KB by MAVLink FTP and another lists the
parameters. Every station keeps the vehicle's HEARTBEAT (no gap near 1 s, let alone MAVSDK's 3 s
timeout) and its position stream at the idle rate; the file and the list still arrive whole.
The real processes are in test_gcs_bridge_peers.py (test_an_ftp_download_does_not_cost_another_
station_the_vehicle)."""

from __future__ import annotations

import itertools
from types import SimpleNamespace
from typing import Any

from conftest import shipped
from ttctl.bridge.downmux import FairDownlink
from ttctl.ends.onboard.dtt_gcs import DttGroundStations
from ttctl.proto.scheduler import Scheduler

B = shipped()
DOWN_Bps = 6700.0
STEP = 0.005
FTP_STATION = (245, 190)
HB, GPI, ATT, SYS = 0, 33, 30, 1
RATES = {HB: 1.0, GPI: 0.25, ATT: 0.25, SYS: 1.0}


class Endpoint:
    def __init__(self) -> None:
        self.scheduler = Scheduler(mtu=100, rate_Bps=DOWN_Bps)

    def add_stream(self, stream: Any) -> None:
        self.scheduler.add_source(stream.pull)


def vehicle(t: float) -> dict[int, Any]:
    return {HB: B.Heartbeat(type=2, autopilot=12, base_mode=81, custom_mode=0, system_status=4),
            GPI: B.GlobalPositionInt(time_boot_ms=int(t * 1000), lat=460503000, lon=144686000, alt=300000,
                                     relative_alt=5000, hdg=9000),
            ATT: B.Attitude(time_boot_ms=int(t * 1000), roll=0.1, pitch=0.2, yaw=0.3),
            SYS: B.SysStatus(voltage_battery=16000, battery_remaining=90)}


def ftp_answer(seq: int) -> Any:
    payload = bytes([seq & 0xFF, seq >> 8, 0, 0, 128, 1, 15, 0]) + bytes(4) + bytes([seq % 251] * 239)
    return B.FileTransferProtocol(target_network=0, target_system=FTP_STATION[0], target_component=FTP_STATION[1],
                                  payload=payload)


def run(seconds: float, ftp_at: float | None, params_at: float | None) -> dict[str, Any]:
    """The vehicle's streams at RATES for `seconds`; at `ftp_at` a 64 KB burst read's answers (to one
    station), at `params_at` a 300-parameter list (to every station, as PARAM_VALUE is). What the
    stations got, with the time each frame's last byte left."""
    builders = dict.fromkeys(RATES)
    gcs = SimpleNamespace(rates=SimpleNamespace(interval=dict(RATES), builders=builders))
    dtt = DttGroundStations(B, gcs, 1, 1, 0.5, DOWN_Bps)  # type: ignore[arg-type]
    ep = Endpoint()
    dtt.attach(ep)  # type: ignore[arg-type]
    parser = B.parser()
    got: list[tuple[float, Any]] = []
    due = dict.fromkeys(RATES, 0.0)
    t = 0.0
    while t < seconds:
        for mid, msg in vehicle(t).items():
            if t >= due[mid] - 1e-9:
                dtt.send(t, msg, True)
                due[mid] += RATES[mid]
        if ftp_at is not None and abs(t - ftp_at) < STEP / 2:
            for seq in range(275):  # 275 x 239 bytes: 64 KB
                dtt.send(t, ftp_answer(seq), False)
        if params_at is not None and abs(t - params_at) < STEP / 2:
            for i in range(300):
                dtt.send(t, B.ParamValue(param_id=f"P{i}", param_value=float(i), param_type=9, param_count=300,
                                         param_index=i), True)
        while (pkt := ep.scheduler.next_packet(t)) is not None:
            got += [(t, m) for m in parser.feed(pkt)]
        t = round(t + STEP, 3)
    by: dict[str, list[tuple[float, Any]]] = {}
    for when, m in got:
        by.setdefault(m.NAME, []).append((when, m))
    return by


def gaps(times: list[float]) -> float:
    return max(b - a for a, b in itertools.pairwise(times))


def test_an_ftp_burst_and_a_parameter_list_cost_no_station_the_heartbeat_or_its_position() -> None:
    idle = run(20.0, None, None)
    busy = run(20.0, 2.0, 3.0)
    ftp = [m for _, m in busy["FILE_TRANSFER_PROTOCOL"]]
    assert [m.payload[0] | m.payload[1] << 8 for m in ftp] == list(range(275))  # whole, in order
    assert len(busy["PARAM_VALUE"]) == 300
    done = max(busy["FILE_TRANSFER_PROTOCOL"][-1][0], busy["PARAM_VALUE"][-1][0])
    assert done < 2.0 + 15.0  # the rest of the link carried them (about 80 KB at what the streams leave)
    beats = [w for w, _ in busy["HEARTBEAT"]]
    window = [w for w in beats if 2.0 <= w <= done]
    assert window and gaps([2.0, *window, done]) <= 0.4, beats  # three a second: two lost are no 1 s gap
    idle_gpi = sum(1 for w, _ in idle["GLOBAL_POSITION_INT"] if 2.0 <= w <= done) / (done - 2.0)
    busy_gpi = sum(1 for w, _ in busy["GLOBAL_POSITION_INT"] if 2.0 <= w <= done) / (done - 2.0)
    assert busy_gpi >= 0.9 * idle_gpi, (busy_gpi, idle_gpi)
    # the list (to every station) and the file (to one) share the rest: neither waits for the other
    first_param = busy["PARAM_VALUE"][0][0]
    assert first_param < 3.5, first_param
    assert busy["FILE_TRANSFER_PROTOCOL"][-1][0] > busy["PARAM_VALUE"][0][0] + 1.0


def test_short_answers_pass_bulk_and_bulk_lanes_share_by_bytes() -> None:
    from ttctl.bridge.downfit import StreamFit

    enc = B.encoder(1, 1)
    down = FairDownlink(StreamFit(None, asked=lambda mid: None, encode=enc.encode), enc.encode)
    for seq in range(20):
        down.put(ftp_answer(seq))
    for i in range(20):
        down.put(B.MissionItemInt(target_system=200, target_component=190, seq=i, frame=6, command=16, x=i, y=0,
                                  z=10.0))
    ack = B.CommandAck(command=400, result=0, target_system=200, target_component=190)
    assert down.put(ack) and not down.put(ack)  # the same answer twice waits once
    p = B.parser()
    out = [p.feed(f)[0] for f in iter(lambda: down.pull(0.0, 100), None)]
    assert out[0].NAME == "COMMAND_ACK"
    names = [m.NAME for m in out[1:]]
    ftp_bytes = items_bytes = 0
    for m in out[1:21]:  # while both lanes wait, bytes alternate evenly: several items to each FTP frame
        if m.NAME == "FILE_TRANSFER_PROTOCOL":
            ftp_bytes += len(enc.encode(m))
        else:
            items_bytes += len(enc.encode(m))
    assert abs(ftp_bytes - items_bytes) <= 300, (names, ftp_bytes, items_bytes)
    assert len(out) == 41
