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
               | C.MAV_PROTOCOL_CAPABILITY_COMMAND_INT | C.MAV_PROTOCOL_CAPABILITY_PARAM_ENCODE_BYTEWISE
               | C.MAV_PROTOCOL_CAPABILITY_FTP)


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
        "LOCAL_POSITION_NED": 0.5, "MISSION_CURRENT": 1.0,
        "ATTITUDE_QUATERNION": 0.25, "ODOMETRY": 0.5, "ALTITUDE": 1.0, "SYSTEM_TIME": 1.0, "HIGHRES_IMU": 0.5,
        "SCALED_PRESSURE": 1.0, "WIND_COV": 1.0}  # SCALED_IMU, HIL_STATE_QUATERNION: when asked for

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
        """REQUEST_DATA_STREAM(ALL): every stream but the heartbeat at `hz` (0: stop); the
        messages sent only when asked for (no default rate) stay off."""
        heartbeat_id = 0  # HEARTBEAT
        for mid in self.builders:
            if mid != heartbeat_id and self.default[mid] is not None:
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


# -- the streams MAVSDK's telemetry getters read besides the ones above -------------------------
def quaternion(s: Snapshot) -> list[float]:
    """w, x, y, z of the body (FRD) attitude in the local NED frame, from roll, pitch and yaw."""
    cy, sy = math.cos(s.yaw / 2), math.sin(s.yaw / 2)
    cp, sp = math.cos(s.pitch / 2), math.sin(s.pitch / 2)
    cr, sr = math.cos(s.roll / 2), math.sin(s.roll / 2)
    return [cr * cp * cy + sr * sp * sy, sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
            cr * cp * sy - sr * sp * cy]


def attitude_quaternion(b: Bindings, s: Snapshot, boot_ms: int) -> Any:
    w, x, y, z = quaternion(s)
    return b.AttitudeQuaternion(time_boot_ms=boot_ms, q1=w, q2=x, q3=y, q4=z, rollspeed=0.0, pitchspeed=0.0,
                                yawspeed=s.yaw_rate, repr_offset_q=[0.0, 0.0, 0.0, 0.0])


def odometry(b: Bindings, s: Snapshot, boot_us: int) -> Any:
    """As PX4 sends it: position in local NED (frame LOCAL_NED), velocity and angular rates in
    the body frame (child frame BODY_FRD), attitude as a quaternion; covariances unknown (NaN in
    the first element, as MAVLink defines)."""
    F = b.MavFrame
    unknown = [math.nan] + [0.0] * 20
    vx, vy, vz = to_body(s, (s.vn, s.ve, s.vd))
    p, q, r = body_rates(s)
    return b.Odometry(time_usec=boot_us, frame_id=int(F.MAV_FRAME_LOCAL_NED), child_frame_id=int(F.MAV_FRAME_BODY_FRD),
                      x=s.n, y=s.e, z=s.d, q=quaternion(s), vx=vx, vy=vy, vz=vz, rollspeed=p, pitchspeed=q,
                      yawspeed=r, pose_covariance=unknown, velocity_covariance=unknown, reset_counter=0,
                      estimator_type=int(b.MavEstimatorType.MAV_ESTIMATOR_TYPE_UNKNOWN), quality=100)


# -- the inertial sensors, as an ideal multicopter's would read: thrust along the body's z axis
# balancing gravity, the earth's field turned into the body frame, the standard atmosphere --------
G = 9.80665
EARTH_FIELD = (0.22, 0.01, 0.42)  # gauss, north/east/down: about central Europe's (WMM)
TEMPERATURE = 20.0  # degrees C


def to_body(s: Snapshot, v: tuple[float, float, float]) -> tuple[float, float, float]:
    """A vector in local NED turned into the body frame (FRD) by yaw, then pitch, then roll."""
    cy, sy = math.cos(s.yaw), math.sin(s.yaw)
    cp, sp = math.cos(s.pitch), math.sin(s.pitch)
    cr, sr = math.cos(s.roll), math.sin(s.roll)
    x1, y1, z1 = cy * v[0] + sy * v[1], -sy * v[0] + cy * v[1], v[2]
    x2, z2 = cp * x1 - sp * z1, sp * x1 + cp * z1
    return x2, cr * y1 + sr * z2, -sr * y1 + cr * z2


def body_rates(s: Snapshot) -> tuple[float, float, float]:
    """Roll, pitch and yaw rates about the body axes of a vehicle turning about the vertical."""
    return (-math.sin(s.pitch) * s.yaw_rate, math.sin(s.roll) * math.cos(s.pitch) * s.yaw_rate,
            math.cos(s.roll) * math.cos(s.pitch) * s.yaw_rate)


def specific_force(s: Snapshot) -> tuple[float, float, float]:
    tilt = max(0.2, math.cos(s.roll) * math.cos(s.pitch))
    return 0.0, 0.0, -G / tilt


def pressure_hpa(alt_msl: float) -> float:
    return 1013.25 * (1.0 - 2.25577e-5 * alt_msl) ** 5.25588


def highres_imu(b: Bindings, s: Snapshot, boot_us: int) -> Any:
    ax, ay, az = specific_force(s)
    gx, gy, gz = body_rates(s)
    mx, my, mz = to_body(s, EARTH_FIELD)
    return b.HighresImu(time_usec=boot_us, xacc=ax, yacc=ay, zacc=az, xgyro=gx, ygyro=gy, zgyro=gz, xmag=mx,
                        ymag=my, zmag=mz, abs_pressure=pressure_hpa(s.alt_msl), diff_pressure=0.0,
                        pressure_alt=s.alt_msl, temperature=TEMPERATURE, fields_updated=0x1FFF, id=0)


def scaled_imu(b: Bindings, s: Snapshot, boot_ms: int) -> Any:
    a = [round(x / G * 1000) for x in specific_force(s)]  # mG
    g = [round(x * 1000) for x in body_rates(s)]  # mrad/s
    m = [round(x * 1000) for x in to_body(s, EARTH_FIELD)]  # mgauss
    return b.ScaledImu(time_boot_ms=boot_ms, xacc=a[0], yacc=a[1], zacc=a[2], xgyro=g[0], ygyro=g[1], zgyro=g[2],
                       xmag=m[0], ymag=m[1], zmag=m[2], temperature=round(TEMPERATURE * 100))


def scaled_pressure(b: Bindings, s: Snapshot, boot_ms: int) -> Any:
    return b.ScaledPressure(time_boot_ms=boot_ms, press_abs=pressure_hpa(s.alt_msl), press_diff=0.0,
                            temperature=round(TEMPERATURE * 100), temperature_press_diff=0)


def hil_state_quaternion(b: Bindings, s: Snapshot, boot_us: int) -> Any:
    """The simulation's true state (MAVSDK's ground_truth), sent only when asked for."""
    p, q, r = body_rates(s)
    a = [round(x / G * 1000) for x in specific_force(s)]
    return b.HilStateQuaternion(time_usec=boot_us, attitude_quaternion=quaternion(s), rollspeed=p, pitchspeed=q,
                                yawspeed=r, lat=_deg7(s.lat), lon=_deg7(s.lon), alt=round(s.alt_msl * 1000),
                                vx=round(s.vn * 100), vy=round(s.ve * 100), vz=round(s.vd * 100),
                                ind_airspeed=round(s.ground_speed * 100), true_airspeed=round(s.ground_speed * 100),
                                xacc=a[0], yacc=a[1], zacc=a[2])


def wind_cov(b: Bindings, s: Snapshot, boot_us: int) -> Any:
    """The simulation has no wind: zero, and known to be zero."""
    return b.WindCov(time_usec=boot_us, wind_x=0.0, wind_y=0.0, wind_z=0.0, var_horiz=0.0, var_vert=0.0,
                     wind_alt=s.alt_msl, horiz_accuracy=0.0, vert_accuracy=0.0)


def altitude(b: Bindings, s: Snapshot, boot_us: int) -> Any:
    """ALTITUDE: monotonic, AMSL, local (up from the local origin, which is home), relative to
    home; no terrain source (NaN) and the ground assumed flat at home's height."""
    return b.Altitude(time_usec=boot_us, altitude_monotonic=s.alt_msl, altitude_amsl=s.alt_msl,
                      altitude_local=-s.d, altitude_relative=s.alt_rel, altitude_terrain=math.nan,
                      bottom_clearance=max(0.0, s.alt_rel))


def system_time(b: Bindings, unix_us: int, boot_ms: int) -> Any:
    return b.SystemTime(time_unix_usec=unix_us, time_boot_ms=boot_ms)
