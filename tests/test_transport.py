"""Endpoint specs, the asyncio UDP/TCP transports and the runtime that drives an Endpoint."""

from __future__ import annotations

import asyncio
import json
import os
import socket
import sys

import pytest

import ttapi
from conftest import shipped
from ttctl.ends.runtime import Runner
from ttctl.link.transport import (
    DTT_MTU,
    Spec,
    TcpTransport,
    TransportError,
    UdpTransport,
    make_transport,
    parse_spec,
)
from ttctl.proto.endpoint import Endpoint

LOCAL = "127.0.0.1"


def free_port(kind: int = socket.SOCK_DGRAM) -> int:
    with socket.socket(socket.AF_INET, kind) as s:
        s.bind((LOCAL, 0))
        return s.getsockname()[1]


# -- specs -------------------------------------------------------------------------------------

@pytest.mark.parametrize("text, udp, want", [
    ("udpin:0.0.0.0:14550", "udpin", Spec("udpin", "0.0.0.0", 14550)),
    ("udpout:192.168.1.20:14560", "udpin", Spec("udpout", "192.168.1.20", 14560)),
    ("tcp:localhost:5760", "udpin", Spec("tcp", "localhost", 5760)),
    ("tcpin:127.0.0.1:5760", "udpin", Spec("tcpin", "127.0.0.1", 5760)),
    ("udp:127.0.0.1:14550", "udpin", Spec("udpin", "127.0.0.1", 14550)),
    ("udp:127.0.0.1:14550", "udpout", Spec("udpout", "127.0.0.1", 14550)),
    ("UDPIN::14550", "udpin", Spec("udpin", "0.0.0.0", 14550)),
    ("udpin:[::1]:14550", "udpin", Spec("udpin", "::1", 14550)),
    ("tcpin:127.0.0.1:0", "udpin", Spec("tcpin", "127.0.0.1", 0)),
])
def test_good_specs(text: str, udp: str, want: Spec) -> None:
    assert parse_spec(text, udp=udp) == want


def test_spec_round_trips() -> None:
    for text in ("udpin:0.0.0.0:14550", "tcp:example.org:5760", "udpout:[::1]:9"):
        assert str(parse_spec(text)) == text


@pytest.mark.parametrize("text, why", [
    ("", "expected udpin:HOST:PORT"),
    ("localhost:14550", "unknown kind 'localhost'"),
    ("serial:/dev/ttyUSB0:57600", "unknown kind 'serial'"),
    ("udpin:14550", "expected udpin:HOST:PORT"),
    ("udpout:host:port", "port 'port' is not a number"),
    ("udpout:127.0.0.1:70000", "port must be in 1..65535"),
    ("udpout:127.0.0.1:0", "port must be in 1..65535"),
    ("tcp::5760", "which host?"),
    ("udpin:::1:14550", "in brackets"),
    ("udpin:[::1:14550", "[IPv6 address]:PORT"),
    ("udpout:a b:1", "is not a host name"),
    ("udpin:127.0.0.1:-1", "is not a number"),
])
def test_bad_specs(text: str, why: str) -> None:
    with pytest.raises(TransportError) as e:
        parse_spec(text)
    assert why in str(e.value)
    assert "\n" not in str(e.value)


def test_kinds_can_be_restricted() -> None:
    with pytest.raises(TransportError, match="tcp is not possible here"):
        parse_spec("tcp:127.0.0.1:1", allowed=("udpin",))


# -- UDP ---------------------------------------------------------------------------------------

def test_udpin_answers_only_confirmed_peers_and_every_one_of_them() -> None:
    """Datagrams alone never make a peer (garbage from anywhere moves nothing); an address the
    layer above confirmed (it sent a valid frame) is answered, and so is every other one."""
    async def main() -> None:
        t = UdpTransport(parse_spec(f"udpin:{LOCAL}:0"))
        got: list[tuple[bytes, object]] = []
        notes: list[str] = []
        t.on_receive = lambda data, source: got.append((data, source))
        t.log = notes.append
        await t.open()
        port = int(t.local.rsplit(":", 1)[1])
        assert t.describe() == f"udpin:{LOCAL}:{port}"
        assert not t.send(b"nobody yet")  # nobody heard: nowhere to send
        assert t.stats.unsent == 1
        a, b, c = (socket.socket(socket.AF_INET, socket.SOCK_DGRAM) for _ in range(3))
        try:
            for s in (a, b, c):
                s.bind((LOCAL, 0))
                s.settimeout(0.5)
            a.sendto(b"from a", (LOCAL, port))
            await _until(lambda: len(got) == 1)
            assert got[0] == (b"from a", a.getsockname())
            assert not t.send(b"unconfirmed") and t.peer is None
            t.confirm(a.getsockname(), {(255, 190)})
            assert t.send(b"to a")
            assert a.recv(200) == b"to a"
            b.sendto(b"from b", (LOCAL, port))
            c.sendto(b"garbage", (LOCAL, port))
            await _until(lambda: len(got) == 3)
            t.confirm(b.getsockname(), {(255, 190)})  # the same ids from another process: both are answered
            t.confirm(a.getsockname(), {(255, 190)})
            assert t.send(b"to all")
            assert a.recv(200) == b"to all" and b.recv(200) == b"to all"
            with pytest.raises(TimeoutError):
                c.recv(200)
            assert notes == [f"answering {LOCAL}:{a.getsockname()[1]} (255/190)",
                             f"answering {LOCAL}:{b.getsockname()[1]} (255/190)"]  # once per new peer
        finally:
            for s in (a, b, c):
                s.close()
            t.close()

    asyncio.run(main())


def test_udpout_sends_and_hears_replies() -> None:
    async def main() -> None:
        server = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        server.bind((LOCAL, 0))
        server.settimeout(2.0)
        t = UdpTransport(parse_spec(f"udpout:{LOCAL}:{server.getsockname()[1]}"))
        got: list[bytes] = []
        t.on_receive = lambda data, source: got.append(data)
        await t.open()
        try:
            assert t.send(b"hello")
            data, addr = server.recvfrom(200)
            assert data == b"hello"
            server.sendto(b"reply", addr)
            await _until(lambda: got == [b"reply"])
        finally:
            t.close()
            server.close()

    asyncio.run(main())


def test_oversize_datagrams_are_dropped_and_counted() -> None:
    async def main() -> None:
        t = UdpTransport(parse_spec(f"udpin:{LOCAL}:0"))
        got: list[bytes] = []
        t.on_receive = lambda data, source: got.append(data)
        await t.open()
        port = int(t.local.rsplit(":", 1)[1])
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
            s.sendto(b"x" * (DTT_MTU + 1), (LOCAL, port))
            s.sendto(b"y" * 1000, (LOCAL, port))
            s.sendto(b"z" * DTT_MTU, (LOCAL, port))
            await _until(lambda: len(got) == 1)
        t.close()
        assert got == [b"z" * DTT_MTU]
        assert t.stats.oversize == 2
        assert t.stats.rx_packets == 1
        assert t.peer is None  # datagrams alone never make a peer

    asyncio.run(main())


def test_port_in_use_is_one_clear_line() -> None:
    async def main() -> None:
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
            s.bind((LOCAL, 0))
            port = s.getsockname()[1]
            with pytest.raises(TransportError, match=f"cannot listen on udpin:{LOCAL}:{port}: address already in use"):
                await UdpTransport(parse_spec(f"udpin:{LOCAL}:{port}")).open()
        with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
            s.bind((LOCAL, 0))
            s.listen()
            port = s.getsockname()[1]
            with pytest.raises(TransportError, match="address already in use"):
                await TcpTransport(parse_spec(f"tcpin:{LOCAL}:{port}")).open()

    asyncio.run(main())


def test_unreachable_tcp_and_unresolvable_host() -> None:
    async def main() -> None:
        port = free_port(socket.SOCK_STREAM)
        with pytest.raises(TransportError, match=f"cannot connect to tcp:{LOCAL}:{port}: connection refused"):
            await TcpTransport(parse_spec(f"tcp:{LOCAL}:{port}")).open()
        with pytest.raises(TransportError, match="cannot resolve"):
            await UdpTransport(parse_spec("udpout:no-such-host.invalid:9")).open()

    asyncio.run(main())


# -- the runtime -------------------------------------------------------------------------------

def test_runner_does_not_spin_when_idle() -> None:
    async def main() -> Runner:
        ep = Endpoint(shipped(), 1, 240)
        runner = Runner(ep, make_transport(parse_spec(f"udpin:{LOCAL}:0")))
        await runner.start()
        await asyncio.sleep(0.5)
        await runner.close()
        return runner

    runner = asyncio.run(main())
    assert runner.stats.wakeups < 10, runner.stats


def test_two_endpoints_over_loopback_udp_exchange_a_command() -> None:
    """A command and its ack through two runners: the wake-up loop and receive path both work."""
    async def main() -> tuple[object, Runner]:
        onboard = Endpoint(shipped(), 1, 240, rate_Bps=50_000, action=lambda cmd: 0)
        a = Runner(onboard, make_transport(parse_spec(f"udpin:{LOCAL}:0")))
        await a.start()
        tablet = Endpoint(shipped(), 255, 190, rate_Bps=50_000)
        b = Runner(tablet, make_transport(parse_spec(f"udpout:{a.transport.local}")))
        await b.start()
        b.sync()
        cmd = tablet.command(ttapi.TtActionCommand(action=int(ttapi.TtAction.TT_ACTION_HOVER)), (1, 240))
        b.kick()
        await _until(lambda: cmd.done, 5.0)
        await a.close()
        await b.close()
        return cmd, b

    cmd, b = asyncio.run(main())
    assert cmd.ok, vars(cmd)  # type: ignore[attr-defined]
    assert b.stats.packets_out >= 1 and b.stats.packets_in >= 1


# -- TCP: a plain MAVLink stream that pymavlink reads --------------------------------------------

PYMAVLINK_CLIENT = r"""
import json, sys
from pymavlink import mavutil
m = mavutil.mavlink_connection(sys.argv[1], source_system=42, source_component=7)
for _ in range(20):
    m.mav.heartbeat_send(mavutil.mavlink.MAV_TYPE_GCS, mavutil.mavlink.MAV_AUTOPILOT_INVALID, 0, 0, 0)
    hb = m.recv_match(type="HEARTBEAT", blocking=True, timeout=0.5)
    if hb is not None:
        print(json.dumps({"src": [hb.get_srcSystem(), hb.get_srcComponent()], "type": hb.type,
                          "autopilot": hb.autopilot}))
        break
"""


def test_tcp_stream_carries_frames_pymavlink_parses() -> None:
    async def main() -> tuple[str, int, list[object]]:
        heard: list[object] = []
        ep = Endpoint(shipped(), 1, 240, on_message=lambda now, msg: heard.append(msg))
        runner = Runner(ep, make_transport(parse_spec(f"tcpin:{LOCAL}:0")))
        await runner.start()
        assert runner.transport.stream and runner.transport.mtu >= 280
        env = dict(os.environ, MAVLINK20="1")
        proc = await asyncio.create_subprocess_exec(
            sys.executable, "-c", PYMAVLINK_CLIENT, f"tcp:{runner.transport.local}",
            stdout=asyncio.subprocess.PIPE, stderr=asyncio.subprocess.PIPE, env=env)
        try:
            async def beat() -> None:
                while True:
                    ep.send_message(ttapi.Heartbeat(type=int(ttapi.MavType.MAV_TYPE_ONBOARD_CONTROLLER),
                                                    autopilot=int(ttapi.MavAutopilot.MAV_AUTOPILOT_INVALID),
                                                    base_mode=0, custom_mode=0, system_status=0))
                    runner.kick()
                    await asyncio.sleep(0.1)

            beating = asyncio.create_task(beat())
            out, _ = await asyncio.wait_for(proc.communicate(), 30)
            beating.cancel()
        finally:
            if proc.returncode is None:
                proc.kill()
                await proc.wait()
            await runner.close()
        return out.decode(), proc.returncode or 0, heard

    out, code, heard = asyncio.run(main())
    assert code == 0
    got = json.loads(out.strip().splitlines()[-1])
    assert got["src"] == [1, 240]
    assert got["type"] == int(ttapi.MavType.MAV_TYPE_ONBOARD_CONTROLLER)
    # and the other way: pymavlink's heartbeats reached the endpoint through receive_stream
    assert any(isinstance(m, ttapi.Heartbeat) and m.get_srcSystem() == 42 for m in heard)


async def _until(cond, timeout: float = 3.0) -> None:  # type: ignore[no-untyped-def]
    loop = asyncio.get_running_loop()
    end = loop.time() + timeout
    while not cond():
        if loop.time() > end:
            raise AssertionError("timed out waiting")
        await asyncio.sleep(0.005)
