"""The ground-station bridge's rules, sans-IO (ttctl.bridge): what the tablet's bridge queues
toward the vehicle (retries not twice, newest-wins sticks, a share of the uplink, bounded), where
the vehicle's answers go (by target; QGroundControl's 255/190 carried under a free id and given
back its own), RADIO_STATUS's quality, and the onboard end's streams fitted to its share of the
downlink with MESSAGE_INTERVAL telling the interval kept. The real-process tests are in
test_gcs_bridge.py and test_gcs_bridge_peers.py."""

from __future__ import annotations

from typing import Any

from conftest import shipped
from ttctl.bridge.classes import TABLET, from_ground_station, ground_station_protocol
from ttctl.bridge.downfit import StreamFit
from ttctl.bridge.routes import Routes
from ttctl.bridge.uplink import GcsUplink

B = shipped()


def frame(msg: Any, src: tuple[int, int] = (245, 190), seq: int = 0) -> bytes:
    return bytes(msg.pack(seq, *src))


def param_read(name: str = "MPC_XY_VEL_MAX") -> Any:
    return B.ParamRequestRead(target_system=1, target_component=1, param_id=name, param_index=-1)


def sticks(x: int) -> Any:
    return B.ManualControl(target=1, x=x, y=0, z=500, r=0, buttons=0)


def drain(q: GcsUplink, now: float, n: int = 1000) -> list[bytes]:
    out = []
    for _ in range(n):
        f = q.pull(now, 100)
        if f is None:
            break
        out.append(f)
    return out


def test_which_frames_are_a_ground_stations() -> None:
    for name in ("COMMAND_LONG", "COMMAND_INT", "PARAM_REQUEST_LIST", "MISSION_ITEM_INT", "SET_MODE",
                 "FILE_TRANSFER_PROTOCOL", "MANUAL_CONTROL", "SET_POSITION_TARGET_LOCAL_NED", "REQUEST_DATA_STREAM"):
        assert ground_station_protocol(name), name
        assert from_ground_station(name, TABLET, False), name  # whoever sends it (a naive bridge keeps 255/190)
    for name in ("TT_ACTION_COMMAND", "TT_FILE_OFFER", "DJI_POSE_STAMPED", "TT_LOG"):
        assert not from_ground_station(name, (245, 190), False), name
    # the user's own messages: a ground station's unless the tablet sends them (issue 28)
    assert from_ground_station("KR_MOTOR_CONTROL", (245, 190), False)
    assert not from_ground_station("KR_MOTOR_CONTROL", TABLET, False)
    assert not from_ground_station("HEARTBEAT", TABLET, True)  # the tablet's own heartbeat stays the tablet's
    assert from_ground_station("HEARTBEAT", (254, 190), True)
    assert not from_ground_station("HEARTBEAT", (254, 190), False)  # not a ground station's heartbeat


def test_a_retry_still_waiting_is_not_queued_twice_but_one_sent_may_go_again() -> None:
    q = GcsUplink(None)
    assert q.put(0.0, "PARAM_REQUEST_READ", frame(param_read(), seq=1)) == "queued"
    assert q.put(0.1, "PARAM_REQUEST_READ", frame(param_read(), seq=2)) == "duplicate"  # seq differs: still a retry
    assert q.put(0.1, "PARAM_REQUEST_READ", frame(param_read("NAV_DLL_ACT"), seq=3)) == "queued"
    assert q.put(0.1, "PARAM_REQUEST_READ", frame(param_read(), src=(255, 190))) == "queued"  # another station's
    assert len(drain(q, 0.2)) == 3 and q.stats.duplicates == 1
    assert q.put(0.3, "PARAM_REQUEST_READ", frame(param_read(), seq=4)) == "queued"  # the first left: may go again
    assert len(drain(q, 0.3)) == 1


def test_sticks_are_newest_wins_and_protocol_frames_go_first() -> None:
    q = GcsUplink(None)
    for x in range(50):  # 50 Hz MANUAL_CONTROL for a second, nothing pulled
        q.put(x / 50, "MANUAL_CONTROL", frame(sticks(x), seq=x))
    q.put(1.0, "COMMAND_LONG", frame(B.CommandLong(target_system=1, target_component=1, command=400, param1=1)))
    out = drain(q, 1.0)
    assert len(out) == 2 and q.stats.replaced == 49
    parsed = [m for f in out for m in B.parser().feed(f)]
    assert parsed[0].NAME == "COMMAND_LONG" and parsed[1].NAME == "MANUAL_CONTROL" and parsed[1].x == 49


def test_the_queue_is_bounded_whatever_a_station_floods() -> None:
    q = GcsUplink(None, max_protocol=8, max_slots=4)
    for i in range(1000):
        q.put(0.0, "PARAM_REQUEST_READ", frame(B.ParamRequestRead(target_system=1, target_component=1,
                                                                  param_id="X", param_index=i)))
        q.put(0.0, "MANUAL_CONTROL", frame(sticks(i), src=(200 + i % 50, 190)))
    assert len(q.protocol) == 8 and len(q.slots) == 4 and len(q._waiting) == 8
    assert q.stats.overflow == (1000 - 8) + (1000 - 4)  # (50 sources in turn: each a new slot)
    got = [m.param_index for f in drain(q, 0.0) for m in B.parser().feed(f) if m.NAME == "PARAM_REQUEST_READ"]
    assert got == list(range(992, 1000))  # the newest kept, in order


def test_the_uplink_share_is_kept_over_time() -> None:
    q = GcsUplink(300.0)
    sent = 0
    t = 0.0
    while t < 10.0:
        for i in range(5):  # a flood far above the share
            q.put(t, "PARAM_REQUEST_READ", frame(B.ParamRequestRead(target_system=1, target_component=1,
                                                                    param_id=f"P{i}", param_index=int(t * 100))))
        while (f := q.pull(t, 100)) is not None:
            sent += len(f)
        t += 0.01
    assert 0.9 * 3000 <= sent <= 3000 + 100 + 60, sent  # 300 B/s for 10 s, one packet's burst


def test_answers_go_to_the_station_they_are_for_and_broadcasts_to_all() -> None:
    r = Routes(1)
    qgc_link, sdk_link = "qgc", "sdk"
    r.fixed = [qgc_link, sdk_link]
    assert r.destinations(0.0, None)[0] == [(qgc_link, None), (sdk_link, None)]  # reached before they speak
    carried = r.heard(0.0, qgc_link, ("127.0.0.1", 14550), TABLET)
    assert carried == (254, 190)  # QGroundControl's 255/190 is the tablet's: carried under a free id
    assert r.heard(0.1, sdk_link, ("127.0.0.1", 14540), (245, 190)) == (245, 190)
    dests, own = r.destinations(0.2, (254, 190))
    assert dests == [(qgc_link, ("127.0.0.1", 14550))] and own == TABLET
    dests, own = r.destinations(0.2, (245, 190))
    assert dests == [(sdk_link, ("127.0.0.1", 14540))] and own is None
    assert r.destinations(0.2, (245, 0))[0] == [(sdk_link, ("127.0.0.1", 14540))]  # compid 0: any component
    assert r.destinations(0.2, (77, 1))[0] == []  # nobody here is 77
    assert len(r.destinations(0.2, None)[0]) == 2
    second = r.heard(0.3, "other", ("127.0.0.1", 1), TABLET)  # a second QGroundControl, ids clashing too
    assert second == (253, 190)  # a free id of its own: the two do not get each other's answers
    assert r.destinations(0.4, second) == ([("other", ("127.0.0.1", 1))], TABLET)
    assert r.destinations(0.4, (254, 190))[0] == [(qgc_link, ("127.0.0.1", 14550))]
    assert r.destinations(0.4, TABLET)[0] == []  # the tablet's own ids: no station is that
    assert r.heard(5.0, qgc_link, ("127.0.0.1", 14550), TABLET) == (254, 190)  # the mapping, once made, stays


def test_radio_quality_counts_what_the_vehicle_sent_and_is_zero_when_silent() -> None:
    r = Routes(1)
    assert r.quality(0.0) == 0
    seq = 0
    for i in range(100):
        seq = (seq + (2 if i % 10 == 0 else 1)) & 0xFF  # one frame in ten lost
        r.vehicle_frame(i * 0.04, 1, seq)
    assert 0.85 * 254 <= r.quality(4.0) <= 0.95 * 254 and r.lost == 9
    assert r.quality(4.0 + 3.6) == 0  # silent past the link-loss time
    late = Routes(1)
    for t, seq in enumerate((1, 2, 4, 3, 5, 6)):  # 3 overtaken by 4 (a frame held for the next packet)
        late.vehicle_frame(t * 0.1, 1, seq)
    assert late.lost == 0 and late.quality(0.6) == 254


def test_streams_fit_the_downlink_share_and_say_the_interval_kept() -> None:
    asked = {0: 1.0, 33: 0.02, 30: 0.02}  # HEARTBEAT 1 Hz, GLOBAL_POSITION_INT and ATTITUDE at 50 Hz
    # (40 and 40 bytes a frame: 4 KB/s asked for, 1 KB/s of room)
    enc = B.encoder(1, 1)
    fit = StreamFit(1000.0, asked=asked.get, encode=enc.encode)
    s = B.encoder(1, 1)  # sizes
    gpi = B.GlobalPositionInt(time_boot_ms=1, lat=460503000, lon=144686000, alt=300000, relative_alt=5000, hdg=9000)
    att = B.Attitude(time_boot_ms=1, roll=0.1, pitch=0.2, yaw=0.3, rollspeed=0.01, pitchspeed=0.02, yawspeed=0.03)
    hb = B.Heartbeat(type=2, autopilot=12)
    sent: dict[int, int] = {0: 0, 33: 0, 30: 0}
    nbytes = 0
    t = 0.0
    while t < 20.0:
        for mid, msg in ((33, gpi), (30, att)):
            fit.put(t, mid, msg)
        if abs(t - round(t)) < 1e-6:
            fit.put(t, 0, hb)
        while (f := fit.pull(t, 100)) is not None:
            m = B.parser().feed(f)[0]
            sent[m.MSG_ID] += 1
            if t >= 10:
                nbytes += len(f)
        t = round(t + 0.005, 3)
    assert len(s.encode(gpi)) * 50 + len(s.encode(att)) * 50 > 3000  # asked for: far more than 1000 B/s
    assert 0.8 * 1000 <= nbytes / 10 <= 1000 * 1.05, nbytes / 10
    assert 19 <= sent[0] <= 21  # the heartbeat keeps its 1 Hz
    assert abs(sent[33] - sent[30]) <= 0.25 * sent[33]  # slowed by the same factor
    kept = fit.interval_us(33, 20000)
    assert kept > 20000 and abs(kept / 1e6 - 20 / sent[33]) < 0.3 * kept / 1e6, (kept, sent)
    assert fit.interval_us(0, 1_000_000) == 1_000_000 and fit.interval_us(99, 5000) == 5000  # unknown: as asked
    roomy = StreamFit(100000.0, asked=asked.get, encode=enc.encode)
    roomy.put(0.0, 33, gpi)
    assert roomy.interval_us(33, 20000) == 20000  # it fits: as asked


def item(seq: int, count_lat: int = 0) -> Any:
    return B.MissionItemInt(target_system=1, target_component=1, seq=seq, frame=6, command=16, autocontinue=1,
                            x=460503000 + seq * 100 + count_lat, y=144686000, z=20.0)


def test_mission_relay_pipelines_an_upload_and_acknowledges_nothing_itself() -> None:
    from ttctl.bridge.missions import MissionRelay

    queued: list[bytes] = []  # the bridge's uplink queue: frames not yet on the link
    relay = MissionRelay(lambda who, seq, kind: ("req", who, seq), ahead=2, waiting=lambda f: f in queued,
                         window=6)
    who = (245, 190)
    count = B.MissionCount(target_system=1, target_component=1, count=8, mission_type=0)
    pending = relay.from_gcs(0.0, count, who, b"count")
    assert pending == [("req", who, 0)]  # asked at once, not after a round trip over the link
    given: list[int] = []

    def station_answers(t: float) -> None:  # a ground station gives what it is asked for; it goes up
        while pending:
            _, _, seq = pending.pop(0)
            given.append(seq)
            queued.append(f"item{seq}".encode())
            pending.extend(relay.from_gcs(t, item(seq), who, f"item{seq}".encode()))

    def link_takes(t: float) -> None:
        queued.clear()
        pending.extend(req for _, req in relay.ahead_requests(t))
        station_answers(t)

    station_answers(0.01)
    assert given == [0, 1]  # as many as the uplink queue holds: AHEAD waiting, not a round trip each
    link_takes(0.1)
    assert given == [0, 1, 2, 3]  # the next ones as the link takes them, whatever the vehicle said yet
    link_takes(0.2)
    link_takes(0.3)
    assert given == [0, 1, 2, 3, 4, 5]  # no further than the window (6) ahead of the vehicle, silent so far

    def vehicle_asks(t: float, seq: int) -> tuple[bool, list[bytes]]:
        req = B.MissionRequestInt(target_system=245, target_component=190, seq=seq, mission_type=0)
        passed, again, reqs = relay.from_vehicle(t, req, who)
        pending.extend(reqs)
        station_answers(t)
        return passed, again

    assert vehicle_asks(0.35, 0) == (False, [])  # on its way: swallowed, nothing resent
    assert given == [0, 1, 2, 3, 4, 5, 6]  # and one more may go; the last (7) waits: it starts the station's clock
    link_takes(0.4)
    assert given[-1] == 6
    link_takes(1.4)
    assert given[-1] == 7  # but asked for nothing for 1 s the station would give up: the last one goes anyway
    assert vehicle_asks(1.5, 0) == (False, [b"item0"])  # asked again: it was lost, it goes once more
    assert vehicle_asks(1.55, 0) == (False, [])  # and not again while that one is in flight
    assert vehicle_asks(1.8, 4) == (False, [b"item4"])  # first asked for 1.6 s after it went up: it was lost
    assert vehicle_asks(1.95, 12) == (False, [])  # an item never asked of the station: a stale request, swallowed
    assert relay.uploads[who].wanted == 4
    assert vehicle_asks(2.0, 7) == (False, [])  # the last item asked for: on its way
    queued.clear()
    assert relay.tick(2.5) == [] and relay.tick(2.7) == [b"item7"]  # no verdict 0.6 s later: the last item again
    assert relay.ahead_requests(3.0) == []  # (the station is not asked again: MAVSDK counts that a retry)
    ack = B.MissionAck(target_system=245, target_component=190, type=0, mission_type=0)
    assert relay.from_vehicle(3.0, ack, who) == (True, [], [])  # the vehicle's own verdict, passed on
    assert who not in relay.uploads
    late = B.MissionRequestInt(target_system=245, target_component=190, seq=7, mission_type=0)
    assert relay.from_vehicle(3.1, late, who)[0] is False  # a request sent before the verdict: not the station's
    # a count the vehicle never answers (lost, or its answer was) goes again, and what followed it right
    # behind it, as the first time (the vehicle starts afresh with the count: one round trip an item
    # if it had to ask for each)
    relay.from_gcs(10.0, count, who, b"count")
    relay.from_gcs(10.01, item(0), who, b"item0")
    relay.from_gcs(10.02, item(1), who, b"item1")
    queued.append(b"item1")  # (still waiting in the uplink: it goes behind the count anyway)
    assert relay.tick(10.3) == [] and relay.tick(10.7) == [b"count", b"item0"]
    req = B.MissionRequestInt(target_system=245, target_component=190, seq=0, mission_type=0)
    assert relay.from_vehicle(10.9, req, who)[1] == []  # on its way again: not sent a third time
    other = B.MissionRequestInt(target_system=245, target_component=190, seq=0, mission_type=1)
    assert relay.from_vehicle(11.0, other, who)[0]  # another plan's request: not this upload's


def test_a_lost_mission_ack_after_items_the_vehicle_never_asked_for_brings_the_last_item_again() -> None:
    """Pipelined, the items can all reach the vehicle before it asks for the later ones: it asks
    for item 0 only, stores the plan and acknowledges. When that MISSION_ACK is lost the bridge had
    waited for a request for the last item that never comes, and MAVSDK (which resends nothing once
    its items are given) said TIMEOUT of an upload the vehicle stored: 1 to 2 in 20 uploads at 10 %
    loss (tests/soak_gcs_uploads.py). Now every item having gone up is enough to send the last one
    again, which the vehicle answers with its verdict again."""
    from ttctl.bridge.missions import MissionRelay

    relay = MissionRelay(lambda who, seq, kind: ("req", who, seq))
    who = (245, 190)
    pending = relay.from_gcs(0.0, B.MissionCount(target_system=1, target_component=1, count=3, mission_type=0),
                             who, b"count")
    t = 0.0
    while pending:  # the station gives each item as the bridge asks
        _, _, seq = pending.pop(0)
        t += 0.01
        pending.extend(relay.from_gcs(t, item(seq), who, f"item{seq}".encode()))
    req = B.MissionRequestInt(target_system=245, target_component=190, seq=0, mission_type=0)
    assert relay.from_vehicle(0.2, req, who)[:2] == (False, [])  # on its way; the vehicle asks for no other
    assert relay.tick(0.5) == [] and relay.tick(1.3) == [b"item2"]  # no verdict: the last item again
    assert relay.tick(1.5) == [] and relay.tick(2.4) == [b"item2"]  # and again, a few times at most
    ack = B.MissionAck(target_system=245, target_component=190, type=0, mission_type=0)
    assert relay.from_vehicle(2.6, ack, who)[0] and relay.tick(5.0) == []
    # the vehicle answers the resends too: those verdicts are the bridge's, never the station's (to
    # MAVSDK, already on its next upload, one would be that upload's end: PROTOCOL_ERROR)
    assert relay.from_vehicle(2.8, ack, who)[0] is False
    relay.from_gcs(2.9, B.MissionCount(target_system=1, target_component=1, count=3, mission_type=0), who, b"c2")
    assert relay.from_vehicle(3.0, ack, who)[0] is False  # the next upload has not been asked for anything yet
    assert relay.from_vehicle(3.1, ack, who)[0] is True  # two resends, two echoes: this one is a verdict


def test_the_verdict_on_a_last_item_sent_again_for_the_vehicles_request_is_not_the_next_uploads() -> None:
    """The vehicle asks for the last item again (PX4 asks every 0.25 s) while the first send of it
    is on its way: the bridge sends it again, and the vehicle answers both with its verdict. The
    second came during the station's next upload and was passed on as that upload's verdict: an
    ACCEPTED for a plan the vehicle did not have yet (seen in a trace of 15 uploads at 10 % loss).
    Every send of the last item counts: its extra verdicts are the bridge's."""
    from ttctl.bridge.missions import MissionRelay

    relay = MissionRelay(lambda who, seq, kind: ("req", who, seq))
    who = (245, 190)
    count = B.MissionCount(target_system=1, target_component=1, count=2, mission_type=0)
    pending = relay.from_gcs(0.0, count, who, b"count")
    t = 0.0
    while pending:
        _, _, seq = pending.pop(0)
        t += 0.01
        pending.extend(relay.from_gcs(t, item(seq), who, f"item{seq}".encode()))
    last = B.MissionRequestInt(target_system=245, target_component=190, seq=1, mission_type=0)
    assert relay.from_vehicle(0.2, last, who)[1] == []
    assert relay.from_vehicle(0.45, last, who)[1] == [b"item1"]  # asked again: sent again
    ack = B.MissionAck(target_system=245, target_component=190, type=0, mission_type=0)
    assert relay.from_vehicle(0.5, ack, who)[0] is True  # the verdict, passed on
    relay.from_gcs(0.51, count, who, b"count")  # the station's next upload
    assert relay.from_vehicle(0.6, ack, who)[0] is False  # the verdict on the second send: swallowed
    relay.from_vehicle(0.7, B.MissionRequestInt(target_system=245, target_component=190, seq=0, mission_type=0),
                       who)
    assert relay.from_vehicle(2.0, ack, who)[0] is True  # the next upload's own


def _from(who: tuple[int, int], msg: Any) -> Any:
    msg._mav_sysid, msg._mav_compid = who
    return msg


def test_the_vehicle_keeps_items_that_come_ahead_and_acks_a_repeated_last_item_again() -> None:
    from ttctl.ends.onboard.missions import Missions

    sent: list[Any] = []
    m = Missions(B, 1, 1, lambda msg, peer: sent.append(msg))
    gcs = (245, 190)

    def from_gcs(msg: Any, t: float) -> None:
        msg._mav_sysid, msg._mav_compid = gcs
        m.on_message(t, msg)

    from_gcs(B.MissionCount(target_system=1, target_component=1, count=5, mission_type=0), 0.0)
    for t, seq in ((0.1, 0), (0.2, 2), (0.4, 3), (0.6, 1), (0.7, 4)):  # 1 lost once, then came
        from_gcs(item(seq), t)
    asks = [x.seq for x in sent if x.NAME == "MISSION_REQUEST_INT"]
    acks = [x for x in sent if x.NAME == "MISSION_ACK"]
    assert acks and acks[-1].type == 0 and [i.seq for i in m.mission()] == [0, 1, 2, 3, 4]
    assert asks.count(1) == 2 and 2 not in asks and 3 not in asks  # 1 asked again once; 2 and 3 never
    from_gcs(item(4), 1.5)  # the last item again: the ground station did not hear the ack
    assert [x.NAME for x in sent[-1:]] == ["MISSION_ACK"] and len([x for x in sent if x.NAME == "MISSION_ACK"]) == 2
    # another station's upload has begun meanwhile: the first station's repeat is still acked
    m.on_message(1.6, _from((200, 190), B.MissionCount(target_system=1, target_component=1, count=3, mission_type=0)))
    from_gcs(item(4), 2.0)
    assert sent[-1].NAME == "MISSION_ACK" and sent[-1].type == 0, sent[-1]
    assert m.upload is not None and m.upload.peer == (200, 190)  # and the other upload goes on


def test_download_relay_answers_from_the_vehicles_own_items() -> None:
    """The bridge prefetches a download's items and answers the station from them; the item the
    station waits for goes up ahead of the prefetch, and one the link lost (its request or its
    answer: an item asked for later came first) is asked again at once, ahead."""
    from ttctl.bridge.downloads import DownloadRelay

    in_uplink: set[bytes] = set()  # requests still waiting in the bridge's uplink
    relay = DownloadRelay(lambda who, seq, kind: f"ask{seq}".encode(), window=3, waiting=in_uplink.__contains__)
    who = (245, 190)

    def item(seq: int) -> Any:
        return B.MissionItemInt(target_system=245, target_component=190, seq=seq, x=seq, mission_type=0)

    def ask(t: float, seq: int, legacy: bool = False) -> tuple[bool, list[Any], list[bytes], list[bytes]]:
        kind = B.MissionRequest if legacy else B.MissionRequestInt
        return relay.from_gcs(t, kind(target_system=1, target_component=1, seq=seq, mission_type=0), who)

    count = B.MissionCount(target_system=245, target_component=190, count=6, mission_type=0)
    assert relay.from_vehicle(0.0, count, who) == (True, [], [b"ask0", b"ask1", b"ask2"])  # a window ahead
    assert relay.from_vehicle(0.2, item(0), who) == (False, [], [])  # held for the station's request
    assert relay.from_vehicle(0.21, item(2), who) == (False, [b"ask1"], [])  # 1 was lost: asked again, ahead
    up, answers, first, more = ask(0.25, 0)
    assert not up and [a.seq for a in answers] == [0] and first == [] and more == [b"ask3"]  # at once
    assert ask(0.3, 1) == (False, [], [], [b"ask4"])  # asked again 0.09 s ago: on its way
    assert ask(0.45, 1) == (False, [], [b"ask1"], [])  # the station asks again 0.24 s later: ahead it goes
    in_uplink.add(b"ask3")
    assert ask(0.5, 3) == (False, [], [b"ask3"], [b"ask5"])  # the bridge's own, still waiting: moved ahead
    in_uplink.clear()
    assert relay.from_vehicle(0.6, item(1), who) == (True, [], [])  # the station waits for it: passed on
    assert relay.from_vehicle(0.7, item(3), who) == (True, [], [])  # 0..2 all came: nothing lost
    assert relay.from_vehicle(0.8, item(5), who) == (False, [b"ask4"], [])  # 4, asked before 5, lost
    assert relay.from_vehicle(0.85, item(5), who) == (False, [], [])  # (5 again: 4 asked after it was)
    in_uplink.add(b"ask4")
    assert ask(0.9, 4) == (False, [], [b"ask4"], [])  # moved ahead, not sent twice
    assert ask(1.0, 4, legacy=True) == (True, [], [], [])  # a legacy request: as the station sent it
    assert relay.from_gcs(2.0, B.MissionAck(target_system=1, target_component=1, type=0, mission_type=0), who)[0]
    assert who not in relay.downloads


def test_a_station_request_moves_its_waiting_copy_to_the_head_of_the_uplink() -> None:
    """`first` with an equal frame waiting: that one goes ahead (not a second copy)."""
    from ttctl.bridge.uplink import GcsUplink

    q = GcsUplink(None)
    frames = [bytes([0xFD, 5, 0, 0, i, 245, 190, 51, 0, 0, i, 0, 1, 1, 0, 0, 0]) for i in range(4)]
    for f in frames:
        q.put(0.0, "MISSION_REQUEST_INT", f)
    again = bytearray(frames[2])
    again[4] = 99  # (another sequence number: the same request)
    assert q.put(0.1, "MISSION_REQUEST_INT", bytes(again), first=True) == "duplicate"
    assert [q.pull(0.2, 100) for _ in range(5)] == [frames[2], frames[0], frames[1], frames[3], None]


def test_a_parameter_list_the_link_lost_part_of_is_completed_by_reads() -> None:
    """A list of 5 values loses index 2 and 4 on the way down: once the stream is quiet the bridge
    reads them by index (as the station would, 3 s later), at most TRIES times each, and stops when
    the list is whole or its bound passes."""
    from ttctl.bridge.params import QUIET, READ_AGAIN, TRIES, ParamLists

    lists = ParamLists()
    who = (254, 190)
    lists.request(0.0, who)
    assert lists.tick(0.2) == []  # nothing heard yet: the request's own resend covers a lost one
    for i in (0, 1, 3):
        lists.value(0.3 + i / 100, i, 5)
    assert lists.tick(0.35) == []  # the stream goes on
    assert lists.tick(0.33 + QUIET) == [(who, 2), (who, 4)]  # quiet: the missing ones, read
    assert lists.tick(0.4 + QUIET) == []  # their answers have a round trip
    lists.value(1.0, 2, 5)
    assert lists.tick(1.0 + READ_AGAIN - 0.01) == []  # (a read's answer: within a round trip)
    assert lists.tick(1.0 + READ_AGAIN) == [(who, 4)]  # one read came back; the other again, soon
    for t in range(TRIES):
        lists.tick(2.0 + t)
    assert lists.tick(9.0) == [] and not lists.lists  # given up after TRIES reads of it
    lists.request(20.0, who)
    for i in range(5):
        lists.value(20.1, i, 5)
    assert lists.tick(21.0) == [] and not lists.lists and lists.read == 1 + TRIES  # whole: nothing read
    lists.value(21.0, 7, 5)  # an index beyond the count (a stranger's): ignored
    lists.request(30.0, who)
    lists.value(30.1, 0, 100_000)  # a count no vehicle has: not followed
    assert lists.tick(31.0) == []
