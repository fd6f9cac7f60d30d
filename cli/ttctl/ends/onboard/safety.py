"""Safety as PX4 does it, sans-IO: the geofence, rally points, home, the battery failsafe and the
data-link-loss failsafe of the link that commands the flight. Parameters keep PX4's names and
meanings (PX4's geofence, battery and commander parameters), so ground stations set them as
they would on PX4.

- Geofence: the FENCE plan's inclusion and exclusion polygons (NAV_FENCE_POLYGON_VERTEX_*, param1
  the vertex count) and circles (NAV_FENCE_CIRCLE_*, param1 the radius), plus GF_MAX_HOR_DIST and
  GF_MAX_VER_DIST from home (0: off), tested where the vehicle would stop if it braked now (PX4's
  breach prediction). Inside at least one inclusion area (when there is one) and outside every
  exclusion area, or the fence is breached and GF_ACTION acts once per breach:
  0 none, 1 warning, 2 hold, 3 return, 5 land (4, flight termination, lands: a simulation does not
  drop out of the sky). SYS_STATUS reports the fence present, enabled and healthy until breached.
- Rally points (RALLY plan, NAV_RALLY_POINT): a return flies to the closest of home and the rally
  points (PX4's RTL_TYPE 0) and lands there.
- Home: set where the vehicle is when it arms, and by DO_SET_HOME (param1 1: here; else the
  given position); the simulated ground is at home's altitude.
- Battery: below BAT_LOW_THR a warning, below BAT_CRIT_THR and BAT_EMERGEN_THR COM_LOW_BAT_ACT
  acts (0 warnings only, 2 land at critical, 3 return at critical and land at emergency).
- Link loss: the link that last commanded the flight (the tablet, or the ground station of that
  system id) is watched; silent for COM_DL_LOSS_T seconds, NAV_DLL_ACT acts. A link that never
  commanded the flight never triggers it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from .params import INT32, REAL32, Param
from .vehicle import EARTH_RADIUS, Home

GF_ACTIONS = {0: "", 1: "warning", 2: "hold", 3: "return", 4: "land", 5: "land"}


def safety_params() -> list[Param]:
    return [
        Param("GF_ACTION", 2, INT32, 0, 5, "geofence breach: 0 none, 1 warning, 2 hold, 3 return, 4/5 land"),
        Param("GF_MAX_HOR_DIST", 0.0, REAL32, 0.0, 10000.0, "distance from home the fence allows, m (0 off)"),
        Param("GF_MAX_VER_DIST", 0.0, REAL32, 0.0, 1000.0, "height above home the fence allows, m (0 off)"),
        Param("BAT_LOW_THR", 0.15, REAL32, 0.12, 0.5, "battery low: a warning (fraction of charge)"),
        Param("BAT_CRIT_THR", 0.07, REAL32, 0.05, 0.25, "battery critical: COM_LOW_BAT_ACT acts"),
        Param("BAT_EMERGEN_THR", 0.05, REAL32, 0.03, 0.1, "battery emergency: land (with COM_LOW_BAT_ACT 3)"),
        Param("COM_LOW_BAT_ACT", 3, INT32, 0, 3,
              "battery failsafe: 0 warning, 2 land at critical, 3 return at critical, land at emergency"),
    ]


def local(home: Home, lat: float, lon: float) -> tuple[float, float]:
    """North and east metres of a position from home (the vehicle's projection)."""
    return (math.radians(lat - home.lat) * EARTH_RADIUS,
            math.radians(lon - home.lon) * EARTH_RADIUS * math.cos(math.radians(home.lat)))


@dataclass
class Area:
    inclusion: bool
    polygon: list[tuple[float, float]]  # lat, lon
    center: tuple[float, float] | None = None  # lat, lon of a circle
    radius: float = 0.0
    _home: tuple[float, float] | None = None
    _pts: list[tuple[float, float]] = field(default_factory=list)

    def contains(self, home: Home, n: float, e: float) -> bool:
        if self.center is not None:
            cn, ce = local(home, *self.center)
            return math.hypot(n - cn, e - ce) <= self.radius
        if self._home != (home.lat, home.lon):  # the vertices in metres, worked out once per home
            self._home = (home.lat, home.lon)
            self._pts = [local(home, lat, lon) for lat, lon in self.polygon]
        pts = self._pts
        inside = False
        j = len(pts) - 1
        for i in range(len(pts)):  # ray casting, north as x, east as y
            (ni, ei), (nj, ej) = pts[i], pts[j]
            if (ei > e) != (ej > e) and n < (nj - ni) * (e - ei) / (ej - ei) + ni:
                inside = not inside
            j = i
        return inside


def fence_areas(b: Any, items: list[Any]) -> list[Area]:
    """The FENCE plan's items as areas (consecutive vertices with the same command form a
    polygon of param1 vertices)."""
    C = b.MavCmd
    out: list[Area] = []
    i = 0
    while i < len(items):
        it = items[i]
        cmd = it.command
        if cmd in (int(C.MAV_CMD_NAV_FENCE_CIRCLE_INCLUSION), int(C.MAV_CMD_NAV_FENCE_CIRCLE_EXCLUSION)):
            out.append(Area(cmd == int(C.MAV_CMD_NAV_FENCE_CIRCLE_INCLUSION), [], (it.x / 1e7, it.y / 1e7),
                            float(it.param1)))
            i += 1
        elif cmd in (int(C.MAV_CMD_NAV_FENCE_POLYGON_VERTEX_INCLUSION),
                     int(C.MAV_CMD_NAV_FENCE_POLYGON_VERTEX_EXCLUSION)):
            count = max(3, int(it.param1))
            vertices = items[i:i + count]
            out.append(Area(cmd == int(C.MAV_CMD_NAV_FENCE_POLYGON_VERTEX_INCLUSION),
                            [(v.x / 1e7, v.y / 1e7) for v in vertices]))
            i += count
        else:  # nothing else is taken at upload
            i += 1
    return out


def breach(areas: list[Area], home: Home, n: float, e: float, alt: float, max_hor: float,
           max_ver: float) -> str | None:
    """Why the position (metres from home) is outside the fence, or None."""
    if max_hor > 0 and math.hypot(n, e) > max_hor:
        return f"{math.hypot(n, e):.0f} m from home, beyond GF_MAX_HOR_DIST {max_hor:g} m"
    if max_ver > 0 and alt > max_ver:
        return f"{alt:.0f} m up, above GF_MAX_VER_DIST {max_ver:g} m"
    inclusions = [a for a in areas if a.inclusion]
    if inclusions and not any(a.contains(home, n, e) for a in inclusions):
        return "outside the inclusion fence"
    if any(a.contains(home, n, e) for a in areas if not a.inclusion):
        return "inside an exclusion fence"
    return None


def braking_point(pos: list[float], vel: list[float], accel: float) -> tuple[float, float, float]:
    """Where the vehicle would come to rest braking at `accel` now (north, east, altitude): PX4's
    navigator tests this point, not the position, so a hold stops at the fence, not past it."""
    speed = math.hypot(vel[0], vel[1])
    ahead = speed / (2 * accel)  # braking distance / speed
    climb = max(0.0, -vel[2])
    return pos[0] + vel[0] * ahead, pos[1] + vel[1] * ahead, -pos[2] + climb * climb / (2 * accel)


def rally_points(items: list[Any]) -> list[tuple[float, float]]:
    return [(it.x / 1e7, it.y / 1e7) for it in items]


def move_home(vehicle: Any, home: Home) -> None:
    """Make `home` the vehicle's home (the origin of its local frame): its position, target and
    route are re-expressed so that it stays where it is."""
    old = vehicle.home
    dn, de = local(old, home.lat, home.lon)
    dalt = home.alt - old.alt if vehicle.state.airborne else 0.0  # on the ground, the ground moves with home
    vehicle.pos[0] -= dn
    vehicle.pos[1] -= de
    vehicle.pos[2] += dalt
    if vehicle.target is not None:
        tn, te, td = vehicle.target
        vehicle.target = (tn - dn, te - de, td + dalt)
    for w in vehicle.route:
        w.n, w.e, w.alt = w.n - dn, w.e - de, w.alt - dalt
    vehicle.rally = [(n - dn, e - de) for n, e in getattr(vehicle, "rally", [])]
    vehicle.home = home
