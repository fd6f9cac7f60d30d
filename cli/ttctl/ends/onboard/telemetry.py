"""Telemetry: MAVLink messages built from one vehicle snapshot, and the rates they are sent at.

Every message of one round is built from the same `Snapshot`, so position, velocity, attitude
and battery agree across GLOBAL_POSITION_INT, VFR_HUD, ATTITUDE, SYS_STATUS and the rest. Rates
follow what ground stations ask: SET_MESSAGE_INTERVAL per message, REQUEST_DATA_STREAM (MAVProxy)
for all of them, REQUEST_MESSAGE for one now.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any, ClassVar

from ...wire.bindings import Bindings
from . import modes
from .vehicle import Snapshot, State

INT16_MAX, UINT16_MAX = 32767, 65535


def _sensors(b: Bindings) -> int:
    S = b.MavSysStatusSensor
    return int(S.MAV_SYS_STATUS_SENSOR_3D_GYRO | S.MAV_SYS_STATUS_SENSOR_3D_ACCEL | S.MAV_SYS_STATUS_SENSOR_3D_MAG
               | S.MAV_SYS_STATUS_SENSOR_ABSOLUTE_PRESSURE | S.MAV_SYS_STATUS_SENSOR_GPS
               | S.MAV_SYS_STATUS_SENSOR_BATTERY)


def capabilities(b: Bindings) -> int:
    C = b.MavProtocolCapability
    return int(C.MAV_PROTOCOL_CAPABILITY_MAVLINK2 | C.MAV_PROTOCOL_CAPABILITY_MISSION_INT
               | C.MAV_PROTOCOL_CAPABILITY_COMMAND_INT | C.MAV_PROTOCOL_CAPABILITY_PARAM_ENCODE_BYTEWISE)


def _deg7(x: float) -> int:
    return round(x * 1e7)


def heartbeat(b: Bindings, s: Snapshot, custom: int | None = None) -> Any:
    """`custom`: the PX4 custom mode ground stations see (flight.FlightModes); None: the state as
    the tablet's link encodes it."""
    flags = b.MavModeFlag
    custom_mode = modes.custom_mode(s.state) if custom is None else custom
    base = modes.base_flags(b, custom_mode)
    if s.armed:
        base |= int(flags.MAV_MODE_FLAG_SAFETY_ARMED)
    status = b.MavState.MAV_STATE_ACTIVE if s.armed else b.MavState.MAV_STATE_STANDBY
    return b.Heartbeat(type=int(b.MavType.MAV_TYPE_QUADROTOR),
                           autopilot=int(b.MavAutopilot.MAV_AUTOPILOT_PX4), base_mode=base,
                           custom_mode=custom_mode, system_status=int(status), mavlink_version=3)


def sys_status(b: Bindings, s: Snapshot) -> Any:
    # the pre-arm check (MAVSDK's is_armable) passes while the battery allows arming
    sensors, prearm = _sensors(b), int(b.MavSysStatusSensor.MAV_SYS_STATUS_PREARM_CHECK)
    health = sensors | (prearm if s.battery_pct >= 10.0 and not s.state.airborne else 0)
    health |= int(b.MavSysStatusSensor.MAV_SYS_STATUS_GEOFENCE)  # no fence, none breached (MAVProxy says so otherwise)
    return b.SysStatus(onboard_control_sensors_present=sensors | prearm,
                           onboard_control_sensors_enabled=sensors | prearm,
                           onboard_control_sensors_health=health, load=150,
                           voltage_battery=int(s.battery_v * 1000), current_battery=int(s.current_a * 100),
                           battery_remaining=round(s.battery_pct))


def global_position_int(b: Bindings, s: Snapshot, boot_ms: int) -> Any:
    return b.GlobalPositionInt(time_boot_ms=boot_ms, lat=_deg7(s.lat), lon=_deg7(s.lon),
                                   alt=round(s.alt_msl * 1000), relative_alt=round(s.alt_rel * 1000),
                                   vx=round(s.vn * 100), vy=round(s.ve * 100), vz=round(s.vd * 100),
                                   hdg=round(s.heading_deg * 100) % 36000)


def local_position_ned(b: Bindings, s: Snapshot, boot_ms: int) -> Any:
    return b.LocalPositionNed(time_boot_ms=boot_ms, x=s.n, y=s.e, z=s.d, vx=s.vn, vy=s.ve, vz=s.vd)


def attitude(b: Bindings, s: Snapshot, boot_ms: int) -> Any:
    return b.Attitude(time_boot_ms=boot_ms, roll=s.roll, pitch=s.pitch, yaw=s.yaw, yawspeed=s.yaw_rate)


def gps_raw_int(b: Bindings, s: Snapshot, unix_us: int) -> Any:
    cog = round(math.degrees(math.atan2(s.ve, s.vn)) % 360 * 100) if s.ground_speed > 0.2 else UINT16_MAX
    return b.GpsRawInt(time_usec=unix_us, fix_type=int(b.GpsFixType.GPS_FIX_TYPE_3D_FIX), lat=_deg7(s.lat),
                           lon=_deg7(s.lon), alt=round(s.alt_msl * 1000), eph=80, epv=120,
                           vel=round(s.ground_speed * 100), cog=cog, satellites_visible=14)


def home_position(b: Bindings, s: Snapshot, unix_us: int) -> Any:
    return b.HomePosition(latitude=_deg7(s.home.lat), longitude=_deg7(s.home.lon),
                              altitude=round(s.home.alt * 1000), q=[1.0, 0.0, 0.0, 0.0], time_usec=unix_us)


def extended_sys_state(b: Bindings, s: Snapshot) -> Any:
    L = b.MavLandedState
    landed = {State.LANDED: L.MAV_LANDED_STATE_ON_GROUND, State.TAKING_OFF: L.MAV_LANDED_STATE_TAKEOFF,
              State.LANDING: L.MAV_LANDED_STATE_LANDING}.get(s.state, L.MAV_LANDED_STATE_IN_AIR)
    return b.ExtendedSysState(vtol_state=0, landed_state=int(landed))


def battery_status(b: Bindings, s: Snapshot) -> Any:
    cell = int(s.battery_v / 4 * 1000)
    used_mah = int((100.0 - s.battery_pct) / 100.0 * 4000)
    return b.BatteryStatus(id=0, battery_function=int(b.MavBatteryFunction.MAV_BATTERY_FUNCTION_ALL),
                               type=int(b.MavBatteryType.MAV_BATTERY_TYPE_LIPO), temperature=INT16_MAX,
                               voltages=[cell] * 4 + [UINT16_MAX] * 6, current_battery=int(s.current_a * 100),
                               current_consumed=used_mah, energy_consumed=-1,
                               battery_remaining=round(s.battery_pct))


def vfr_hud(b: Bindings, s: Snapshot) -> Any:
    throttle = 50 if s.state is not State.LANDED else 0
    return b.VfrHud(airspeed=s.ground_speed, groundspeed=s.ground_speed, heading=int(s.heading_deg) % 360,
                        throttle=throttle, alt=s.alt_msl, climb=-s.vd)


# the PX4 release whose behaviour the vehicle follows, as AUTOPILOT_VERSION packs it (major, minor,
# patch, FIRMWARE_VERSION_TYPE_OFFICIAL): QGroundControl's PX4 plugin warns below 1.4
PX4_VERSION = (1 << 24) | (15 << 16) | (0 << 8) | 255


def autopilot_version(b: Bindings, sysid: int) -> Any:
    return b.AutopilotVersion(capabilities=capabilities(b), flight_sw_version=PX4_VERSION, vendor_id=0,
                                  product_id=0, uid=0x7474_6374_6C00 + sysid)


def mission_current(b: Bindings, s: Snapshot, total: int) -> Any:
    return b.MissionCurrent(seq=max(0, s.waypoint), total=total)


class Rates:
    """When each telemetry message is due. `builders` maps msgid -> build(snapshot); intervals
    in seconds (None: off)."""

    DEFAULTS: ClassVar[dict[str, float]] = {
        "HEARTBEAT": 1.0, "SYS_STATUS": 1.0, "GLOBAL_POSITION_INT": 0.25, "ATTITUDE": 0.25, "GPS_RAW_INT": 1.0,
        "HOME_POSITION": 2.0, "EXTENDED_SYS_STATE": 1.0, "BATTERY_STATUS": 1.0, "VFR_HUD": 0.5,
        "LOCAL_POSITION_NED": 0.5, "MISSION_CURRENT": 1.0}

    def __init__(self, b: Bindings, builders: dict[int, Callable[[Snapshot], Any]],
                 defaults: dict[str, float] | None = None) -> None:
        self.builders = builders
        names = {mid: info.cls.NAME for mid, info in b.registry.items()}
        table = defaults or self.DEFAULTS
        self.default: dict[int, float | None] = {mid: table.get(names.get(mid, ""), None) for mid in builders}
        self.interval: dict[int, float | None] = dict(self.default)
        self.due: dict[int, float] = {mid: 0.0 for mid in builders}

    def set_interval(self, msgid: int, interval_us: float) -> bool:
        """SET_MESSAGE_INTERVAL: -1 off, 0 default, else microseconds. False if unknown."""
        if msgid not in self.builders:
            return False
        if interval_us < 0:
            self.interval[msgid] = None
        elif interval_us == 0:
            self.interval[msgid] = self.default[msgid]
        else:
            self.interval[msgid] = max(0.01, interval_us / 1e6)
        self.due[msgid] = 0.0
        return True

    def set_all(self, hz: float) -> None:
        """REQUEST_DATA_STREAM(ALL): everything but the heartbeat at `hz` (0: stop)."""
        heartbeat_id = 0  # HEARTBEAT
        for mid in self.builders:
            if mid != heartbeat_id:
                self.interval[mid] = 1.0 / hz if hz > 0 else None

    def take_due(self, now: float) -> list[int]:
        out = []
        for mid, iv in self.interval.items():
            if iv is not None and now >= self.due[mid]:
                out.append(mid)
                self.due[mid] = max(self.due[mid] + iv, now)  # no burst to catch up after a stall
        return out

    def next_due(self) -> float | None:
        times = [self.due[m] for m, iv in self.interval.items() if iv is not None]
        return min(times) if times else None
