"""The simulated vehicle, the trajectory files it flies, and the autopilot's link-loss behaviour:
pure functions of commands and time steps."""

from __future__ import annotations

import math

import pytest

from conftest import shipped
from ttctl.ends.onboard.autopilot import Autopilot
from ttctl.ends.onboard.trajectory import TrajectoryError, parse_trajectory
from ttctl.ends.onboard.vehicle import Refused, SimVehicle, State, Waypoint


def fly(v: SimVehicle, until: State, limit: float = 300.0, dt: float = 0.05) -> float:
    t = 0.0
    top_h = top_v = 0.0
    while v.state is not until and t < limit:
        v.step(dt)
        t += dt
        top_h = max(top_h, math.hypot(v.vel[0], v.vel[1]))
        top_v = max(top_v, abs(v.vel[2]))
    assert v.state is until, (v.state, t)
    assert top_h <= v.limits.h_speed + 1e-9 and top_v <= v.limits.v_speed + 1e-9
    return t


def test_a_flight_obeys_the_limits_and_ends_disarmed_at_home() -> None:
    v = SimVehicle()
    with pytest.raises(Refused, match="not armed"):
        v.takeoff(5)
    v.arm()
    v.takeoff(5)
    assert 5.0 <= fly(v, State.HOVERING) <= 10.0  # 5 m at 1 m/s, plus acceleration
    assert -v.pos[2] == pytest.approx(5.0, abs=0.2)
    v.goto(30, 0, 5)
    t = fly(v, State.HOVERING)
    assert 30 / 1.5 <= t <= 30 / 1.5 + 4
    assert math.degrees(v.yaw) == pytest.approx(0.0, abs=2)  # faced where it flew
    v.fly([Waypoint(30, 30, 8, hold=3), Waypoint(0, 30, 8, yaw=math.radians(-90))])
    assert v.snapshot().waypoint == 0
    fly(v, State.HOVERING)
    assert (v.pos[0], v.pos[1], -v.pos[2]) == pytest.approx((0, 30, 8), abs=0.2)
    assert math.degrees(v.yaw) == pytest.approx(-90, abs=2)
    v.return_home()
    fly(v, State.LANDED)
    assert (v.pos[0], v.pos[1], v.pos[2]) == pytest.approx((0, 0, 0), abs=0.2)
    assert not v.armed and v.battery_pct < 100


def test_the_same_commands_give_the_same_flight_at_any_step_size() -> None:
    def run(dt: float) -> tuple[float, ...]:
        v = SimVehicle()
        v.arm()
        v.takeoff(3)
        t = 0.0
        while t < 20.0:
            v.step(dt)
            t += dt
            if abs(t - 6.0) < dt / 2:
                v.goto(10, 5, 4)
        s = v.snapshot()
        return (round(s.n, 3), round(s.e, 3), round(s.d, 3), round(s.battery_pct, 3))

    assert run(0.05) == run(0.05)
    assert run(0.05) == pytest.approx(run(0.025), abs=0.05)


@pytest.mark.parametrize("bad", [math.nan, math.inf, -1.0, 1e6])
def test_absurd_setpoints_are_refused_and_the_vehicle_holds(bad: float) -> None:
    v = SimVehicle()
    v.arm()
    v.takeoff(3)
    fly(v, State.HOVERING)
    with pytest.raises(Refused):
        v.goto(bad, 0, 3) if math.isfinite(bad) is False else v.goto(0, 0, bad)
    assert v.state is State.HOVERING
    with pytest.raises(Refused):
        v.fly([Waypoint(0, 0, 3, speed=-1)])
    with pytest.raises(Refused):
        v.fly([])
    v.land()
    with pytest.raises(Refused, match="busy landing") as e:
        v.goto(5, 0, 3)
    assert e.value.temporary


def test_link_loss_hovers_then_returns_and_lands() -> None:
    v = SimVehicle()
    said: list[str] = []
    ap = Autopilot(shipped(), v, say=lambda sev, text: said.append(text))
    v.arm()
    v.takeoff(5)
    fly(v, State.HOVERING)
    t = 0.0
    ap.commanded_by("tablet", 0.0)  # the tablet commands the flight: its link is watched
    v.goto(20, 0, 5)
    while t < 200 and v.state is not State.LANDED:
        t += 0.05
        ap.step(t, 0.05)
        if t < 3.0:
            ap.heard_tablet(t)  # the tablet falls silent at 3 s
    assert any("tablet link lost" in s for s in said) and any("returning home" in s for s in said)
    lost = next(i for i, s in enumerate(said) if "tablet link lost" in s)
    assert "hovering" in said[lost + 1:]
    assert v.state is State.LANDED and math.hypot(v.pos[0], v.pos[1]) < 0.3
    assert t > 3.0 + 10.0 + 15.0  # COM_DL_LOSS_T, then COM_RTL_AFTER_T of hovering, then the way home


def test_trajectory_files() -> None:
    route = parse_trajectory("speed: 1.0\nwaypoints:\n  - position: [0, 0, 5]\n  - position: {n: 10, e: 2, alt: 6}\n"
                             "    yaw: 90\n    hold: 2\n")
    assert [(w.n, w.e, w.alt, w.speed, w.hold) for w in route] == [(0, 0, 5, 1.0, 0.0), (10, 2, 6, 1.0, 2.0)]
    assert route[1].yaw == pytest.approx(math.pi / 2)
    bad = [("- position: [0, 0]\n", "line 1, column 13"),
           ("waypoints:\n  - position: [0, 0, x]\n", "line 2, column 22"),
           ("- {position: [0, 0, 5], hover: 3}\n", "line 1, column 3"),
           ("- position: [0, 0, 500]\n", "altitude 500 m"),
           ("[oops\n", "line 2, column 1"), ("", "empty")]
    for text, where in bad:
        with pytest.raises(TrajectoryError, match=where):
            parse_trajectory(text)
