"""A ground station and a tablet talking to the onboard end's sans-IO core (Autopilot +
GroundStations + the tablet's actions) under a simulated clock: messages go through the real
encoder and parser, so what is tested is what crosses the wire."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from conftest import shipped
from ttctl.ends.onboard.autopilot import Autopilot
from ttctl.ends.onboard.gcs import GroundStations
from ttctl.ends.onboard.vehicle import SimVehicle

NAN = math.nan
VEL_YAW_MASK = 0b1001_1100_0111  # SET_POSITION_TARGET: velocity and yaw flown (MAVSDK's set_velocity_ned)
POS_YAW_MASK = 0b1001_1111_1000  # position and yaw (MAVSDK's set_position_ned)


class Sim:
    def __init__(self, dt: float = 0.05, tablet: bool = False) -> None:
        self.b = b = shipped()
        self.enc = b.encoder(255, 190)
        self.parser = b.parser()
        self.said: list[str] = []
        if tablet:  # the whole node's core, so that the tablet's actions are the node's own
            from ttctl.ends.onboard.node import OnboardConfig, OnboardNode

            self.node: Any = OnboardNode(b, OnboardConfig(orbit_hz=0), log=self.said.append)
            self.v, self.ap, self.g = self.node.vehicle, self.node.ap, self.node.gcs
        else:
            self.v = SimVehicle()
            self.ap = Autopilot(b, self.v, 1, say=lambda severity, text: self.said.append(text))
            self.g = GroundStations(b, self.ap, 1)
        self.t = 0.0
        self.dt = dt
        self.sent: list[Any] = []
        self.feeds: list[Callable[[float], None]] = []

    def wire(self, msg: Any) -> Any:
        (m,) = self.parser.feed(self.enc.encode(msg))
        return m

    def send(self, msg: Any) -> None:
        self.g.on_message(self.t, self.wire(msg))

    def run(self, seconds: float) -> None:
        end = self.t + seconds
        while self.t < end - 1e-9:
            self.t += self.dt
            for feed in self.feeds:
                feed(self.t)
            self.ap.step(self.t, self.dt)
            self.sent.extend(m for m, _ in self.g.tick(self.t))

    def command(self, cmd: int, *params: float) -> int:
        p = [*params] + [0.0] * (7 - len(params))
        self.g.out.clear()
        self.send(self.b.CommandLong(target_system=1, target_component=1, command=cmd, confirmation=0,
                                     param1=p[0], param2=p[1], param3=p[2], param4=p[3], param5=p[4], param6=p[5],
                                     param7=p[6]))
        acks = [m for m, _ in self.g.out if m.NAME == "COMMAND_ACK" and m.command == cmd]
        self.said.extend(m.text for m, _ in self.g.out if m.NAME == "STATUSTEXT")
        self.g.out.clear()
        assert len(acks) == 1
        return int(acks[0].result)

    def tablet(self, action: int, *params: float) -> int:
        """A TT_ACTION_COMMAND from the tablet (Sim(tablet=True)): its TT_RESULT."""
        p = [*params] + [0.0] * (4 - len(params))
        outcome = self.node.tablet_action(self.b.TtActionCommand(target_system=1, target_component=240,
                                                                 command_id=1, action=action, param=p))
        return int(outcome if isinstance(outcome, int) else outcome[0])

    def set_mode(self, main: int, sub: int = 0) -> int:
        return self.command(int(self.b.MavCmd.MAV_CMD_DO_SET_MODE), 1, main, sub)

    def mode(self) -> tuple[int, int]:
        c = self.ap.flight.custom_mode(self.v.snapshot())
        return (c >> 16) & 0xFF, (c >> 24) & 0xFF

    def velocity(self, vn: float, ve: float, vd: float, yaw_deg: float = NAN, frame: int = 1) -> Any:
        mask = VEL_YAW_MASK | (1024 if math.isnan(yaw_deg) else 0)
        return self.b.SetPositionTargetLocalNed(
            time_boot_ms=0, target_system=1, target_component=1, coordinate_frame=frame, type_mask=mask,
            x=0, y=0, z=0, vx=vn, vy=ve, vz=vd, afx=0, afy=0, afz=0,
            yaw=0.0 if math.isnan(yaw_deg) else math.radians(yaw_deg), yaw_rate=0)

    def position(self, n: float, e: float, d: float, yaw_deg: float = 0.0, frame: int = 1) -> Any:
        return self.b.SetPositionTargetLocalNed(
            time_boot_ms=0, target_system=1, target_component=1, coordinate_frame=frame, type_mask=POS_YAW_MASK,
            x=n, y=e, z=d, vx=0, vy=0, vz=0, afx=0, afy=0, afz=0, yaw=math.radians(yaw_deg), yaw_rate=0)

    def sticks(self, x: int = 0, y: int = 0, z: int = 500, r: int = 0) -> Any:
        return self.b.ManualControl(target=1, x=x, y=y, z=z, r=r, buttons=0)

    def stream(self, msg: Any, hz: float = 20.0) -> Callable[[float], None]:
        """Send `msg` at `hz` from now on (until `stop`)."""
        due = [self.t]

        def feed(now: float) -> None:
            if now >= due[0]:
                due[0] = now + 1.0 / hz
                self.g.on_message(now, self.wire(msg))

        self.feeds.append(feed)
        return feed

    def stop(self, feed: Callable[[float], None] | None = None) -> None:
        self.feeds = [f for f in self.feeds if feed is not None and f is not feed]

    def takeoff(self, alt: float = 3.0) -> None:
        C = self.b.MavCmd
        assert self.command(int(C.MAV_CMD_COMPONENT_ARM_DISARM), 1) == 0
        assert self.command(int(C.MAV_CMD_NAV_TAKEOFF), 0, 0, 0, NAN, NAN, NAN, self.v.home.alt + alt) == 0
        self.run(alt / self.v.limits.v_speed + 3)
