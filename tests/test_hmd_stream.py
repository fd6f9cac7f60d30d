"""Pose streaming (ttctl.hmd.stream) under the link's real scheduler and pacer: newest sample
wins, button changes are never dropped and stay in order, commands go first, the counts add up,
and the messages decode (pymavlink as the oracle) to what was offered."""

from __future__ import annotations

import random
from pathlib import Path
from types import ModuleType

import pytest

import ttapi
from conformance_lib import pymavlink_module
from conftest import shipped
from ttctl.hmd.model import BUTTONS, ControllerSample, Device, PoseSample
from ttctl.hmd.stream import PoseStream, button_bits
from ttctl.proto.endpoint import CONTROL, Endpoint

HMD = Device(0, "hmd", serial="HMD1")
LEFT = Device(3, "controller", "left", "CTL-L")
RIGHT = Device(4, "controller", "right", "CTL-R")
BASE = Device(1, "base_station", serial="LHB1")


def drive(ep: Endpoint, until: float, step: float = 0.001, offer=None, start: float = 0.0) -> list[bytes]:
    """Poll the endpoint like the Runner does, offering samples on the way; the packets out."""
    out = []
    t = start
    while t < until:
        if offer is not None:
            offer(t)
        while (pkt := ep.poll(t)) is not None:
            out.append(pkt)
        t += step
    return out


_PM: list[ModuleType] = []


@pytest.fixture(scope="module", autouse=True)
def pm(tmp_path_factory: pytest.TempPathFactory) -> None:
    """pymavlink's own ttapi module (mavgen), the oracle that decodes what was streamed."""
    _PM.append(pymavlink_module("ttapi", Path(tmp_path_factory.mktemp("pm"))))


def decode(packets: list[bytes]) -> list[object]:
    mav = _PM[0].MAVLink(None)
    mav.robust_parsing = True
    msgs = []
    for p in packets:
        msgs += mav.parse_buffer(p) or []
    return msgs


def test_newest_wins_at_link_rate_and_counts_add_up() -> None:
    ep = Endpoint(shipped(), 255, 190, rate_Bps=1000.0, accept_commands=False)
    stream = PoseStream(shipped(), max_hz=30)
    ep.add_stream(stream)
    rng = random.Random(1)

    def offer(t: float) -> None:
        if abs(t * 90 - round(t * 90)) < 0.045:  # ~90 Hz head
            stream.offer(PoseSample(t, HMD, position=(t, 0.0, 1.7), orientation=(0.0, 0.0, 0.0, 1.0)))
        if rng.random() < 0.25:  # ~250 Hz hands
            stream.offer(PoseSample(t, LEFT if rng.random() < 0.5 else RIGHT, position=(0.3, 0.2, 1.0)))

    packets = drive(ep, 10.0, offer=offer)
    ep.scheduler.sources.clear()  # stop pulling: what was pulled (one frame may wait for a packet) leaves
    packets += drive(ep, 11.0, start=10.0)
    msgs = decode(packets)
    poses = [m for m in msgs if m.get_type() == "TT_VR_POSE"]
    st = stream.stats
    assert st.sent == len(poses) > 0
    assert st.taken == st.sent + st.superseded + sum(s.pending is not None for s in stream._slots.values())
    assert sum(len(p) for p in packets) <= 1000 * 11 + 100  # the pacer held it to the link's rate
    rate = st.sent / 10.0
    assert 9 < rate < 15  # ~1000 B/s / 76-byte frames: what the link carries, not what the headset makes
    heads = [m for m in poses if m.device == ttapi.TtVrDevice.TT_VR_DEVICE_HMD]
    assert len(heads) > 0.4 * len(poses)  # the head (it steers the camera) gets the largest share
    ts = [m.time_usec for m in heads]
    assert ts == sorted(ts)
    # what left is the newest: each head pose sent is at most one link-frame time old when it left
    assert heads[-1].position[0] > 9.8


def _lossy_onboard(stream: PoseStream, loss: float, seed: int):
    """The onboard end's VrControllerPlugin behind a link that loses `loss` of the packets each
    way: returns (deliver(packet), plugin, applied button states in order)."""
    from ttctl.ends.onboard.vr_controller import VrControllerPlugin
    from ttctl.ends.plugins import Context

    rng = random.Random(seed)
    plugin = VrControllerPlugin()
    applied: list[int] = []
    acks: list[object] = []
    ctx = Context(send=lambda msg, urgent=False: acks.append(msg), log=lambda text: None, dialect=shipped())

    def deliver(packet: bytes) -> None:
        if rng.random() < loss:
            return
        for m in decode([packet]):
            if m.get_type() == "TT_VR_CONTROLLER":
                before = plugin.changes
                plugin.on_controller(m, ctx)
                if plugin.changes != before:
                    applied.append(m.buttons)
        while acks:
            a = acks.pop(0)
            if rng.random() >= loss:
                name = a.name.decode() if isinstance(a.name, bytes) else a.name
                stream.on_ack(int(name[len("vrbtn"):]), a.value & 0xFFFFFFFF)

    return deliver, plugin, applied


@pytest.mark.parametrize("loss", [0.0, 0.1, 0.3])
def test_button_changes_survive_a_lossy_link_in_order_and_are_confirmed(loss: float) -> None:
    ep = Endpoint(shipped(), 255, 190, rate_Bps=300.0, accept_commands=False)  # a link far too slow for the flood
    stream = PoseStream(shipped())
    ep.add_stream(stream)
    deliver, _plugin, applied = _lossy_onboard(stream, loss, seed=3)
    rng = random.Random(7)
    changes: list[int] = []
    packet = 0
    sent: list[object] = []

    def offer(t: float) -> None:
        nonlocal packet
        stream.offer(PoseSample(t, HMD))
        stream.offer(PoseSample(t, LEFT))
        if rng.random() < 0.01:
            packet += 1
            buttons = {b: rng.random() < 0.3 for b in BUTTONS}
            s = ControllerSample(t, LEFT, packet, trigger=rng.random(), buttons=buttons)
            if button_bits(s) != (changes[-1] if changes else 0):  # nothing held at the start
                changes.append(button_bits(s))
            stream.offer(s)

    t = 0.0
    while t < 120.0 and (t < 8.0 or stream.unconfirmed()):
        if t < 8.0:
            offer(t)
        while (pkt := ep.poll(t)) is not None:
            sent.append(pkt)
            deliver(pkt)
        t += 0.001
    assert applied == changes and len(changes) > 20  # every change arrived, once, in order
    st = stream.stats
    assert st.buttons == st.confirmed == len(changes) and stream.unconfirmed() == 0
    assert (st.resent > 0) == (loss > 0)
    assert st.superseded > 100  # poses were superseded meanwhile
    assert st.taken == st.sent + st.superseded + stream.held()


def test_nobody_listening_confirms_nothing() -> None:
    ep = Endpoint(shipped(), 255, 190, rate_Bps=1000.0, accept_commands=False)
    stream = PoseStream(shipped(), rto=0.2)
    ep.add_stream(stream)
    for k in range(3):
        stream.offer(ControllerSample(0.0, LEFT, k + 1, buttons={"menu": k % 2 == 0}))
    out = drive(ep, 5.0)
    msgs = [m for m in decode(out) if m.get_type() == "TT_VR_CONTROLLER"]
    assert msgs and all(m.packet_num == 1 for m in msgs)  # the first, resent; the rest wait behind it
    assert stream.stats.confirmed == 0 and stream.unconfirmed() == 3
    assert not stream.on_ack(LEFT.index, 2)  # a confirmation of what is not in flight changes nothing
    assert stream.on_ack(LEFT.index, 1) and stream.unconfirmed() == 2


def test_commands_go_before_poses() -> None:
    ep = Endpoint(shipped(), 255, 190, rate_Bps=1000.0, accept_commands=False)
    stream = PoseStream(shipped())
    ep.add_stream(stream)
    for k in range(50):
        stream.offer(PoseSample(0.0, Device(k % 8, "tracker", serial=f"T{k % 8}")))
    ep.scheduler.send(ep.encoder.encode(ttapi.Heartbeat(type=6)), CONTROL)
    first = decode([ep.poll(0.0) or b""])
    assert first and first[0].get_type() == "HEARTBEAT"


def test_messages_decode_to_what_was_offered() -> None:
    stream = PoseStream(shipped())
    s = PoseSample(1700000000.25, RIGHT, valid=False, connected=True, position=(1.0, -2.0, 3.5),
                   orientation=(0.5, -0.5, 0.5, 0.5), velocity=(0.1, 0.2, 0.3), angular_velocity=(1.0, 2.0, 3.0))
    stream.offer(s)
    msg = stream.pull(0.0, 100)
    frame = ttapi.Encoder(255, 190).encode(msg)
    assert len(frame) <= 100
    m = decode([frame])[0]
    assert m.get_type() == "TT_VR_POSE"
    assert m.time_usec == 1700000000250000 and m.index == 4 and m.role == ttapi.TtVrRole.TT_VR_ROLE_RIGHT
    assert m.flags == ttapi.TtVrPoseFlags.TT_VR_POSE_FLAGS_CONNECTED  # not VALID
    assert list(m.position) == pytest.approx([1.0, -2.0, 3.5])
    assert list(m.orientation) == pytest.approx([0.5, -0.5, 0.5, 0.5])
    c = ControllerSample(5.0, LEFT, 77, trigger=1.0, pad_x=-0.5, pad_y=0.25,
                         buttons={"trigger_click": True, "pad_touched": True, "pad_pressed": False,
                                  "menu": False, "grip": True})
    stream.offer(c)
    m = decode([ttapi.Encoder(255, 190).encode(stream.pull(1.0, 100))])[0]
    assert m.get_type() == "TT_VR_CONTROLLER" and m.packet_num == 77
    assert m.buttons == (ttapi.TtVrButtons.TT_VR_BUTTONS_TRIGGER | ttapi.TtVrButtons.TT_VR_BUTTONS_PAD_TOUCHED
                         | ttapi.TtVrButtons.TT_VR_BUTTONS_GRIP)
    assert (m.trigger, m.pad_x, m.pad_y) == (1.0, -0.5, 0.25)


def test_a_base_station_is_sent_rarely_and_max_hz_caps_a_fast_link() -> None:
    ep = Endpoint(shipped(), 255, 190, rate_Bps=None, accept_commands=False)  # unpaced (LAN)
    stream = PoseStream(shipped(), max_hz=20)
    ep.add_stream(stream)

    def offer(t: float) -> None:
        stream.offer(PoseSample(t, HMD))
        stream.offer(PoseSample(t, BASE))

    msgs = decode(drive(ep, 10.0, offer=offer))
    heads = [m for m in msgs if m.device == ttapi.TtVrDevice.TT_VR_DEVICE_HMD]
    bases = [m for m in msgs if m.device == ttapi.TtVrDevice.TT_VR_DEVICE_TRACKING_REFERENCE]
    assert 190 <= len(heads) <= 201
    assert 2 <= len(bases) <= 3


def test_a_restarted_tablet_is_not_stuck_on_a_change_the_onboard_end_already_has() -> None:
    """The onboard end saw the menu held (a previous dump); a new dump's first change is the menu
    held: the onboard end applies nothing new but confirms it, and the next change goes through."""
    ep = Endpoint(shipped(), 255, 190, rate_Bps=1000.0, accept_commands=False)
    stream = PoseStream(shipped())
    ep.add_stream(stream)
    deliver, _plugin, applied = _lossy_onboard(stream, 0.0, seed=1)
    earlier = PoseStream(shipped())
    earlier.offer(ControllerSample(0.0, LEFT, 900, buttons={"menu": True}))
    deliver(ttapi.Encoder(255, 190).encode(earlier.pull(0.0, 100)))
    assert applied == [int(ttapi.TtVrButtons.TT_VR_BUTTONS_MENU)]
    stream.offer(ControllerSample(1.0, LEFT, 1, buttons={"menu": True}))
    stream.offer(ControllerSample(1.1, LEFT, 2, buttons={}))
    t = 1.0
    while t < 5.0 and stream.unconfirmed():
        while (pkt := ep.poll(t)) is not None:
            deliver(pkt)
        t += 0.001
    assert stream.unconfirmed() == 0 and stream.stats.confirmed == 2 and stream.stats.resent == 0
    assert applied == [int(ttapi.TtVrButtons.TT_VR_BUTTONS_MENU), 0]
