"""Trajectory files: what TT_ACTION_FLY_TRAJECTORY flies, sent beforehand with the file transfer.

A YAML document, a list of waypoints (or a mapping with a `waypoints` list and optional
`speed`), each with a position in metres from home (north, east, altitude above home: `[n, e,
alt]` or `{n:, e:, alt:}`), and optionally `yaw` (degrees, clockwise from north), `speed` (m/s)
and `hold` (seconds):

    speed: 1.0
    waypoints:
      - position: [0, 0, 5]
      - position: [10, 0, 5]
        yaw: 90
        hold: 2
      - {position: {n: 10, e: 10, alt: 8}, speed: 0.5}

`TrajectoryError` names the line and column of what is wrong.
"""

from __future__ import annotations

import math
from typing import Any

from .vehicle import Waypoint

MAX_WAYPOINTS = 1000


class TrajectoryError(Exception):
    pass


def _where(node: Any) -> str:
    mark = getattr(node, "start_mark", None)
    return f"line {mark.line + 1}, column {mark.column + 1}: " if mark is not None else ""


def parse_trajectory(text: str, max_alt: float = 120.0) -> list[Waypoint]:
    try:
        import yaml
    except ImportError:  # pragma: no cover - PyYAML is a dependency
        raise TrajectoryError("reading trajectories needs PyYAML") from None
    try:
        root = yaml.compose(text, Loader=yaml.SafeLoader)
    except yaml.YAMLError as e:
        mark = getattr(e, "problem_mark", None)
        where = f"line {mark.line + 1}, column {mark.column + 1}: " if mark is not None else ""
        raise TrajectoryError(f"{where}not valid YAML ({getattr(e, 'problem', None) or e})") from None
    except RecursionError:  # PyYAML's composer recurses once per level
        raise TrajectoryError("nested too deeply to be a trajectory") from None
    if root is None:
        raise TrajectoryError("the file is empty")
    speed: float | None = None
    items = root
    if isinstance(root, yaml.MappingNode):
        keys = {k.value: v for k, v in root.value}
        unknown = set(keys) - {"waypoints", "speed"}
        if unknown:
            raise TrajectoryError(f"{_where(root)}unknown key {sorted(unknown)[0]!r} (waypoints, speed)")
        if "speed" in keys:
            speed = _number(keys["speed"], "speed", positive=True)
        if "waypoints" not in keys:
            raise TrajectoryError(f"{_where(root)}no 'waypoints' list")
        items = keys["waypoints"]
    if not isinstance(items, yaml.SequenceNode):
        raise TrajectoryError(f"{_where(items)}expected a list of waypoints")
    if not items.value:
        raise TrajectoryError(f"{_where(items)}the list of waypoints is empty")
    if len(items.value) > MAX_WAYPOINTS:
        raise TrajectoryError(f"{_where(items)}more than {MAX_WAYPOINTS} waypoints")
    out = []
    for node in items.value:
        if not isinstance(node, yaml.MappingNode):
            raise TrajectoryError(f"{_where(node)}a waypoint is a mapping with a 'position'")
        fields = {k.value: v for k, v in node.value}
        unknown = set(fields) - {"position", "yaw", "speed", "hold"}
        if unknown:
            raise TrajectoryError(f"{_where(node)}unknown key {sorted(unknown)[0]!r} (position, yaw, speed, hold)")
        if "position" not in fields:
            raise TrajectoryError(f"{_where(node)}a waypoint needs a 'position'")
        north, east, alt = _position(fields["position"])
        if not 0 <= alt <= max_alt:
            raise TrajectoryError(f"{_where(fields['position'])}altitude {alt:g} m is outside 0..{max_alt:g} m")
        yaw = math.radians(_number(fields["yaw"], "yaw")) if "yaw" in fields else None
        wspeed = _number(fields["speed"], "speed", positive=True) if "speed" in fields else speed
        hold = _number(fields["hold"], "hold") if "hold" in fields else 0.0
        if hold < 0:
            raise TrajectoryError(f"{_where(fields['hold'])}hold must not be negative")
        out.append(Waypoint(north, east, alt, yaw=yaw, speed=wspeed, hold=hold))
    return out


def _number(node: Any, what: str, positive: bool = False) -> float:
    try:
        value = float(node.value)
    except (TypeError, ValueError):
        raise TrajectoryError(f"{_where(node)}{what} must be a number") from None
    if not math.isfinite(value):
        raise TrajectoryError(f"{_where(node)}{what} must be finite")
    if positive and value <= 0:
        raise TrajectoryError(f"{_where(node)}{what} must be positive")
    return value


def _position(node: Any) -> tuple[float, float, float]:
    import yaml

    if isinstance(node, yaml.SequenceNode):
        if len(node.value) != 3:
            raise TrajectoryError(f"{_where(node)}position is [north, east, altitude]")
        n, e, a = (_number(v, "position") for v in node.value)
        return n, e, a
    if isinstance(node, yaml.MappingNode):
        f = {k.value: v for k, v in node.value}
        if set(f) != {"n", "e", "alt"}:
            raise TrajectoryError(f"{_where(node)}position is {{n:, e:, alt:}}")
        return _number(f["n"], "n"), _number(f["e"], "e"), _number(f["alt"], "alt")
    raise TrajectoryError(f"{_where(node)}position is [north, east, altitude]")
