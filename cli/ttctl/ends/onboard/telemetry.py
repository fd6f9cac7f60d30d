"""Telemetry: MAVLink messages built from one vehicle snapshot, and the rates they are sent at.

Every message of one round is built from the same `Snapshot`, so position, velocity, attitude
and battery agree across GLOBAL_POSITION_INT, VFR_HUD, ATTITUDE, SYS_STATUS and the rest. Rates
follow what ground stations ask: SET_MESSAGE_INTERVAL per message, REQUEST_DATA_STREAM (MAVProxy)
for all of them, REQUEST_MESSAGE for one now.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import ClassVar

import ttapi

from . import modes
from .vehicle import Snapshot, State

S = ttapi.MavSysStatusSensor
SENSORS = int(S.MAV_SYS_STATUS_SENSOR_3D_GYRO | S.MAV_SYS_STATUS_SENSOR_3D_ACCEL | S.MAV_SYS_STATUS_SENSOR_3D_MAG
              | S.MAV_SYS_STATUS_SENSOR_ABSOLUTE_PRESSURE | S.MAV_SYS_STATUS_SENSOR_GPS
              | S.MAV_SYS_STATUS_SENSOR_BATTERY)
CAPABILITIES = int(ttapi.MavProtocolCapability.MAV_PROTOCOL_CAPABILITY_MAVLINK2
                   | ttapi.MavProtocolCapability.MAV_PROTOCOL_CAPABILITY_MISSION_INT
                   | ttapi.MavProtocolCapability.MAV_PROTOCOL_CAPABILITY_COMMAND_INT
                   | ttapi.MavProtocolCapability.MAV_PROTOCOL_CAPABILITY_PARAM_ENCODE_BYTEWISE)
INT16_MAX, UINT16_MAX = 32767, 65535


def _deg7(x: float) -> int:
    return round(x * 1e7)


def heartbeat(s: Snapshot) -> ttapi.Heartbeat:
    flags = ttapi.MavModeFlag
    base = int(flags.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED | flags.MAV_MODE_FLAG_STABILIZE_ENABLED
               | flags.MAV_MODE_FLAG_GUIDED_ENABLED)
    if s.armed:
        base |= int(flags.MAV_MODE_FLAG_SAFETY_ARMED)
    status = ttapi.MavState.MAV_STATE_ACTIVE if s.armed else ttapi.MavState.MAV_STATE_STANDBY
    return ttapi.Heartbeat(type=int(ttapi.MavType.MAV_TYPE_QUADROTOR),
                           autopilot=int(ttapi.MavAutopilot.MAV_AUTOPILOT_GENERIC), base_mode=base,
                           custom_mode=modes.custom_mode(s.state), system_status=int(status), mavlink_version=3)


PREARM = int(S.MAV_SYS_STATUS_PREARM_CHECK)


def sys_status(s: Snapshot) -> ttapi.SysStatus:
    # the pre-arm check (MAVSDK's is_armable) passes while the battery allows arming
    health = SENSORS | (PREARM if s.battery_pct >= 10.0 and not s.state.airborne else 0)
    health |= int(S.MAV_SYS_STATUS_GEOFENCE)  # no fence, so none breached (MAVProxy says so otherwise)
    return ttapi.SysStatus(onboard_control_sensors_present=SENSORS | PREARM,
                           onboard_control_sensors_enabled=SENSORS | PREARM,
                           onboard_control_sensors_health=health, load=150,
                           voltage_battery=int(s.battery_v * 1000), current_battery=int(s.current_a * 100),
                           battery_remaining=round(s.battery_pct))


def global_position_int(s: Snapshot, boot_ms: int) -> ttapi.GlobalPositionInt:
    return ttapi.GlobalPositionInt(time_boot_ms=boot_ms, lat=_deg7(s.lat), lon=_deg7(s.lon),
                                   alt=round(s.alt_msl * 1000), relative_alt=round(s.alt_rel * 1000),
                                   vx=round(s.vn * 100), vy=round(s.ve * 100), vz=round(s.vd * 100),
                                   hdg=round(s.heading_deg * 100) % 36000)


def local_position_ned(s: Snapshot, boot_ms: int) -> ttapi.LocalPositionNed:
    return ttapi.LocalPositionNed(time_boot_ms=boot_ms, x=s.n, y=s.e, z=s.d, vx=s.vn, vy=s.ve, vz=s.vd)


def attitude(s: Snapshot, boot_ms: int) -> ttapi.Attitude:
    return ttapi.Attitude(time_boot_ms=boot_ms, roll=s.roll, pitch=s.pitch, yaw=s.yaw, yawspeed=s.yaw_rate)


def gps_raw_int(s: Snapshot, unix_us: int) -> ttapi.GpsRawInt:
    cog = round(math.degrees(math.atan2(s.ve, s.vn)) % 360 * 100) if s.ground_speed > 0.2 else UINT16_MAX
    return ttapi.GpsRawInt(time_usec=unix_us, fix_type=int(ttapi.GpsFixType.GPS_FIX_TYPE_3D_FIX), lat=_deg7(s.lat),
                           lon=_deg7(s.lon), alt=round(s.alt_msl * 1000), eph=80, epv=120,
                           vel=round(s.ground_speed * 100), cog=cog, satellites_visible=14)


def home_position(s: Snapshot, unix_us: int) -> ttapi.HomePosition:
    return ttapi.HomePosition(latitude=_deg7(s.home.lat), longitude=_deg7(s.home.lon),
                              altitude=round(s.home.alt * 1000), q=[1.0, 0.0, 0.0, 0.0], time_usec=unix_us)


def extended_sys_state(s: Snapshot) -> ttapi.ExtendedSysState:
    L = ttapi.MavLandedState
    landed = {State.LANDED: L.MAV_LANDED_STATE_ON_GROUND, State.TAKING_OFF: L.MAV_LANDED_STATE_TAKEOFF,
              State.LANDING: L.MAV_LANDED_STATE_LANDING}.get(s.state, L.MAV_LANDED_STATE_IN_AIR)
    return ttapi.ExtendedSysState(vtol_state=0, landed_state=int(landed))


def battery_status(s: Snapshot) -> ttapi.BatteryStatus:
    cell = int(s.battery_v / 4 * 1000)
    used_mah = int((100.0 - s.battery_pct) / 100.0 * 4000)
    return ttapi.BatteryStatus(id=0, battery_function=int(ttapi.MavBatteryFunction.MAV_BATTERY_FUNCTION_ALL),
                               type=int(ttapi.MavBatteryType.MAV_BATTERY_TYPE_LIPO), temperature=INT16_MAX,
                               voltages=[cell] * 4 + [UINT16_MAX] * 6, current_battery=int(s.current_a * 100),
                               current_consumed=used_mah, energy_consumed=-1,
                               battery_remaining=round(s.battery_pct))


def vfr_hud(s: Snapshot) -> ttapi.VfrHud:
    throttle = 50 if s.state is not State.LANDED else 0
    return ttapi.VfrHud(airspeed=s.ground_speed, groundspeed=s.ground_speed, heading=int(s.heading_deg) % 360,
                        throttle=throttle, alt=s.alt_msl, climb=-s.vd)


def autopilot_version(sysid: int) -> ttapi.AutopilotVersion:
    return ttapi.AutopilotVersion(capabilities=CAPABILITIES, flight_sw_version=0x01000000, vendor_id=0,
                                  product_id=0, uid=0x7474_6374_6C00 + sysid)


def mission_current(s: Snapshot, total: int) -> ttapi.MissionCurrent:
    return ttapi.MissionCurrent(seq=max(0, s.waypoint), total=total)


class Rates:
    """When each telemetry message is due. `builders` maps msgid -> build(snapshot); intervals
    in seconds (None: off)."""

    DEFAULTS: ClassVar[dict[str, float]] = {
        "HEARTBEAT": 1.0, "SYS_STATUS": 1.0, "GLOBAL_POSITION_INT": 0.25, "ATTITUDE": 0.25, "GPS_RAW_INT": 1.0,
        "HOME_POSITION": 2.0, "EXTENDED_SYS_STATE": 1.0, "BATTERY_STATUS": 1.0, "VFR_HUD": 0.5,
        "LOCAL_POSITION_NED": 0.5, "MISSION_CURRENT": 1.0}

    def __init__(self, builders: dict[int, Callable[[Snapshot], ttapi.Message]],
                 defaults: dict[str, float] | None = None) -> None:
        self.builders = builders
        names = {cls.MSG_ID: cls.NAME for cls in ttapi.ALL}
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
        heartbeat_id = ttapi.Heartbeat.MSG_ID
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
