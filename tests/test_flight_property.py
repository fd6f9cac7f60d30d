"""A property of the emulated vehicle, over random sequences of ground-station commands
(COMMAND_LONG, DO_SET_MODE to every PX4 mode and some that are none, set-point and stick streams
started and stopped) and the tablet's actions: every ACCEPTED is followed by the state it
promises (at once for the mode and arming; a take-off at its altitude within alt / MPC_Z_VEL_MAX_UP
+ 5 s, a landing or a return on the ground, disarmed, within 60 s), every refusal says why, and
nothing ever throws or leaves the vehicle somewhere impossible."""

from __future__ import annotations

import math
from typing import Any

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from flight_lib import NAN, Sim
from ttctl.ends.onboard.modes import ALTCTL, AUTO, LAND, LOITER, MANUAL, MISSION, OFFBOARD, POSCTL, RTL, TAKEOFF
from ttctl.ends.onboard.vehicle import State
from ttctl.wire.contract import TtAction as TT

ACCEPTED = 0
MODES = [(MANUAL, 0), (ALTCTL, 0), (POSCTL, 0), (AUTO, LOITER), (AUTO, TAKEOFF), (AUTO, MISSION), (AUTO, RTL),
         (AUTO, LAND), (OFFBOARD, 0), (5, 0), (7, 0), (AUTO, 1), (AUTO, 9), (99, 0)]

step = st.one_of(
    st.tuples(st.just("arm"), st.booleans()),
    st.tuples(st.just("takeoff"), st.sampled_from([NAN, 1.0, 5.0, 150.0, -3.0, math.inf])),  # m above home
    st.tuples(st.just("land"), st.none()),
    st.tuples(st.just("rtl"), st.none()),
    st.tuples(st.just("mode"), st.sampled_from(MODES)),
    st.tuples(st.just("reposition"),
              st.tuples(st.floats(-30, 30), st.floats(-30, 30), st.sampled_from([3.0, 8.0, NAN]))),
    st.tuples(st.just("tablet"), st.sampled_from(["takeoff", "land", "hover", "return"])),
    st.tuples(st.just("setpoints"), st.booleans()),
    st.tuples(st.just("sticks"), st.booleans()),
    st.tuples(st.just("wait"), st.sampled_from([0.2, 1.5, 12.0, 60.0])),
)


def _promise(s: Sim, what: str, arg: Any) -> tuple[int, int] | None:
    """The mode an accepted command promises at once (None: no mode promised)."""
    if what in ("takeoff",) or (what == "tablet" and arg == "takeoff"):
        return AUTO, TAKEOFF
    if what == "land" or (what == "tablet" and arg == "land"):
        return AUTO, LAND
    if what == "rtl" or (what == "tablet" and arg == "return"):
        return AUTO, RTL
    if what == "tablet" and arg == "hover":
        return AUTO, LOITER
    if what == "reposition":
        return AUTO, LOITER
    if what == "mode":
        return tuple(arg)  # type: ignore[return-value]
    return None


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(step, min_size=1, max_size=18))
@example([("arm", True), ("takeoff", NAN), ("land", None), ("arm", False), ("land", None), ("arm", True)])  # CI
def test_every_accepted_command_is_followed_by_what_it_promises(steps: list[tuple[str, Any]]) -> None:
    s = Sim(dt=0.1, tablet=True)
    C = s.b.MavCmd
    feeds: dict[str, Any] = {}
    pending: list[tuple[str, float, float]] = []  # (what, by when, altitude) promised later
    for what, arg in steps:
        s.said.clear()
        result: int | None = None
        selected = (s.ap.flight.ground, s.ap.flight.takeoff_alt, s.v.state, s.v.armed)
        if what == "arm":
            result = s.command(int(C.MAV_CMD_COMPONENT_ARM_DISARM), 1.0 if arg else 0.0)
        elif what == "takeoff":
            result = s.command(int(C.MAV_CMD_NAV_TAKEOFF), 0, 0, 0, NAN, NAN, NAN, s.v.home.alt + arg)
        elif what == "land":
            result = s.command(int(C.MAV_CMD_NAV_LAND))
        elif what == "rtl":
            result = s.command(int(C.MAV_CMD_NAV_RETURN_TO_LAUNCH))
        elif what == "mode":
            result = s.set_mode(*arg)
        elif what == "reposition":
            n, e, alt = arg
            home = s.v.home
            lat = home.lat + math.degrees(n / 6_378_137.0)
            lon = home.lon + math.degrees(e / (6_378_137.0 * math.cos(math.radians(home.lat))))
            result = s.command(int(C.MAV_CMD_DO_REPOSITION), -1, 1, 0, NAN, lat, lon, home.alt + alt)
        elif what == "tablet":
            action = {"takeoff": TT.TT_ACTION_TAKE_OFF, "land": TT.TT_ACTION_LAND, "hover": TT.TT_ACTION_HOVER,
                      "return": TT.TT_ACTION_RETURN_HOME}[arg]
            result = s.tablet(int(action), 4.0 if arg == "takeoff" else 0.0)
        elif what in ("setpoints", "sticks"):
            if feeds.get(what) is not None:
                s.feeds.remove(feeds.pop(what))
            if arg:
                feeds[what] = s.stream(s.velocity(0.5, 0, 0, 45) if what == "setpoints" else s.sticks(x=300))
        elif what == "wait":
            s.run(arg)
        if result is not None:
            if result == ACCEPTED:
                mode = _promise(s, what, arg)
                if mode is not None:
                    assert s.mode() == mode, (what, arg, s.mode(), s.v.state)
                if what == "arm":
                    assert s.v.armed is bool(arg)
                if what == "reposition":
                    assert s.v.state is State.MOVING
                minimum = s.ap.params["MIS_TAKEOFF_ALT"]
                if what == "takeoff" or (what == "tablet" and arg == "takeoff"):
                    alt = 4.0 if what == "tablet" else (max(arg, minimum) if math.isfinite(arg) else minimum)
                    if s.v.armed:
                        pending = [("hover", s.t + alt / s.v.limits.v_speed + 5, alt)]
                    else:  # PX4: TAKEOFF selected, flown when armed
                        assert s.v.state is State.LANDED and s.ap.flight.takeoff_alt == pytest.approx(alt)
                        pending = []
                elif what == "arm" and arg and selected[0] == (AUTO, TAKEOFF) and selected[2:] == (State.LANDED, False):
                    alt = selected[1] if selected[1] is not None else minimum
                    assert s.v.state is State.TAKING_OFF
                    pending = [("hover", s.t + alt / s.v.limits.v_speed + 5, alt)]
                elif what == "arm" and arg and selected[2:] == (State.LANDED, False):
                    pending = []  # a "landed and disarmed" promise was kept when this arm came: a new order
                elif what in ("land", "rtl") or (what == "tablet" and arg in ("land", "return")):
                    pending = [("landed", s.t + 60, 0.0)]
                elif what != "arm":
                    pending = []
            else:
                assert any("refused" in t for t in s.said), (what, arg, result, s.said)
                if what == "mode":
                    assert s.mode() != arg or s.v.state is not State.LANDED or arg == (AUTO, LOITER)
            s.run(0.1)
        if what in ("setpoints", "sticks"):
            pending = []  # a stream may change the vehicle's mind, as it is meant to
        pending = _check(s, pending)
    if pending:  # the last promise, kept in time
        s.run(max(0.0, pending[0][1] - s.t) + 0.1)
        assert not _check(s, pending)


def _check(s: Sim, pending: list[tuple[str, float, float]]) -> list[tuple[str, float, float]]:
    assert all(math.isfinite(x) for x in (*s.v.pos, *s.v.vel, s.v.yaw)) and s.v.pos[2] <= 1e-9
    for kind, by, alt in pending:
        if s.t >= by:
            if kind == "hover":
                assert s.v.state is State.HOVERING and -s.v.pos[2] == pytest.approx(alt, abs=0.3), s.v.state
            else:
                assert s.v.state is State.LANDED and not s.v.armed, s.v.state
            return []
    return pending
