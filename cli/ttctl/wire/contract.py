"""The runtime's contract with a dialect: the messages ttctl's ends make and read (ttapi.xml's own,
and the common.xml messages the ends and the emulated vehicle use), with the ids and CRC_EXTRA
they must keep, and the values of the ttapi enums the protocol cores are written against.

A user's dialect gets all of this by including ttapi.xml (which includes common.xml); a dialect
used on the link without it is refused by `problem()` in one line that says so. The tables are
checked against the shipped dialect by the tests, so they cannot drift from dialects/ttapi.xml.
"""

from __future__ import annotations

from enum import IntEnum, IntFlag
from typing import Any

RUNTIME_MESSAGES: dict[str, tuple[int, int]] = {
    "HEARTBEAT": (0, 50),
    "SYS_STATUS": (1, 124),
    "SYSTEM_TIME": (2, 137),
    "PING": (4, 237),
    "SET_MODE": (11, 89),
    "PARAM_REQUEST_READ": (20, 214),
    "PARAM_REQUEST_LIST": (21, 159),
    "PARAM_VALUE": (22, 220),
    "PARAM_SET": (23, 168),
    "GPS_RAW_INT": (24, 24),
    "SCALED_IMU": (26, 170),
    "SCALED_PRESSURE": (29, 115),
    "ATTITUDE": (30, 39),
    "ATTITUDE_QUATERNION": (31, 246),
    "LOCAL_POSITION_NED": (32, 185),
    "GLOBAL_POSITION_INT": (33, 104),
    "MISSION_ITEM": (39, 254),
    "MISSION_REQUEST": (40, 230),
    "MISSION_SET_CURRENT": (41, 28),
    "MISSION_CURRENT": (42, 28),
    "MISSION_REQUEST_LIST": (43, 132),
    "MISSION_COUNT": (44, 221),
    "MISSION_CLEAR_ALL": (45, 232),
    "MISSION_ITEM_REACHED": (46, 11),
    "MISSION_ACK": (47, 153),
    "MISSION_REQUEST_INT": (51, 196),
    "REQUEST_DATA_STREAM": (66, 148),
    "MANUAL_CONTROL": (69, 243),
    "MISSION_ITEM_INT": (73, 38),
    "VFR_HUD": (74, 20),
    "COMMAND_INT": (75, 158),
    "COMMAND_LONG": (76, 152),
    "COMMAND_ACK": (77, 143),
    "SET_ATTITUDE_TARGET": (82, 49),
    "SET_POSITION_TARGET_LOCAL_NED": (84, 143),
    "POSITION_TARGET_LOCAL_NED": (85, 140),
    "SET_POSITION_TARGET_GLOBAL_INT": (86, 5),
    "POSITION_TARGET_GLOBAL_INT": (87, 150),
    "HIGHRES_IMU": (105, 93),
    "RADIO_STATUS": (109, 185),  # the ground-station bridge (emulate tablet --gcs), from the telemetry radio
    "FILE_TRANSFER_PROTOCOL": (110, 84),
    "TIMESYNC": (111, 34),
    "HIL_STATE_QUATERNION": (115, 4),
    "LOG_REQUEST_LIST": (117, 128),
    "LOG_ENTRY": (118, 56),
    "LOG_REQUEST_DATA": (119, 116),
    "LOG_DATA": (120, 134),
    "LOG_ERASE": (121, 237),
    "LOG_REQUEST_END": (122, 203),
    "ALTITUDE": (141, 47),
    "BATTERY_STATUS": (147, 154),
    "AUTOPILOT_VERSION": (148, 178),
    "WIND_COV": (231, 105),
    "HOME_POSITION": (242, 104),
    "MESSAGE_INTERVAL": (244, 95),
    "EXTENDED_SYS_STATE": (245, 130),
    "NAMED_VALUE_INT": (252, 44),
    "STATUSTEXT": (253, 83),
    "CAMERA_FOV_STATUS": (271, 22),
    "ODOMETRY": (331, 91),
    "TT_FILE_OFFER": (50000, 88),
    "TT_FILE_STATUS": (50001, 193),
    "TT_FILE_DATA": (50002, 203),
    "TT_FILE_REQUEST": (50003, 129),
    "DJI_POSE_STAMPED": (50004, 70),
    "TT_ACTION_COMMAND": (50005, 160),
    "TT_NAV_SAT_FIX": (50006, 164),
    "TT_ODOMETRY": (50007, 124),
    "TT_LOG": (50008, 215),
    "TT_FILE_DATA_WIDE": (50009, 100),
    "TT_COMMAND_ACK": (50010, 209),
    "TT_VR_POSE": (50011, 230),
    "TT_VR_CONTROLLER": (50012, 229),
    "TT_FILE_REASON": (50013, 210),
    "TT_FILE_DATA_FIT": (50014, 50),
    "TT_FILE_MAP": (50015, 2),
}


class TtFileResult(IntEnum):
    TT_FILE_RESULT_IN_PROGRESS = 0
    TT_FILE_RESULT_COMPLETE = 1
    TT_FILE_RESULT_REFUSED_NAME = 2
    TT_FILE_RESULT_REFUSED_EXISTS = 3
    TT_FILE_RESULT_REFUSED_QUOTA = 4
    TT_FILE_RESULT_REFUSED_BUSY = 5
    TT_FILE_RESULT_FAILED_CHECKSUM = 6
    TT_FILE_RESULT_FAILED_DISK_FULL = 7
    TT_FILE_RESULT_FAILED_IO = 8
    TT_FILE_RESULT_CANCELLED = 9
    TT_FILE_RESULT_UNKNOWN_TRANSFER = 10
    TT_FILE_RESULT_NOT_FOUND = 11
    TT_FILE_RESULT_REQUEST_REFUSED = 12
    TT_FILE_RESULT_REFUSED_UNSUPPORTED = 13


class TtFileFlags(IntFlag):
    TT_FILE_FLAGS_OVERWRITE = 1
    TT_FILE_FLAGS_CANCEL = 2
    TT_FILE_FLAGS_DEFLATE = 4
    TT_FILE_FLAGS_MAP = 8


class TtResult(IntEnum):
    TT_RESULT_ACCEPTED = 0
    TT_RESULT_IN_PROGRESS = 1
    TT_RESULT_DONE = 2
    TT_RESULT_FAILED = 3
    TT_RESULT_DENIED = 4
    TT_RESULT_UNSUPPORTED = 5
    TT_RESULT_BUSY = 6


class TtAction(IntEnum):
    TT_ACTION_TAKE_OFF = 0
    TT_ACTION_LAND = 1
    TT_ACTION_FLY_TRAJECTORY = 2
    TT_ACTION_HOVER = 3
    TT_ACTION_SYNC_TIME = 4
    TT_ACTION_RETURN_HOME = 5


class TtVrDevice(IntEnum):
    TT_VR_DEVICE_HMD = 1
    TT_VR_DEVICE_CONTROLLER = 2
    TT_VR_DEVICE_TRACKER = 3
    TT_VR_DEVICE_TRACKING_REFERENCE = 4


class TtVrRole(IntEnum):
    TT_VR_ROLE_NONE = 0
    TT_VR_ROLE_LEFT = 1
    TT_VR_ROLE_RIGHT = 2


class TtVrButtons(IntFlag):
    TT_VR_BUTTONS_TRIGGER = 1
    TT_VR_BUTTONS_PAD_TOUCHED = 2
    TT_VR_BUTTONS_PAD_PRESSED = 4
    TT_VR_BUTTONS_MENU = 8
    TT_VR_BUTTONS_GRIP = 16


class TtVrPoseFlags(IntFlag):
    TT_VR_POSE_FLAGS_VALID = 1
    TT_VR_POSE_FLAGS_CONNECTED = 2


def problem(messages: dict[str, tuple[int, int]], dialect: str) -> str | None:
    """Why a dialect (its messages: name -> (id, CRC_EXTRA)) cannot carry ttctl's runtime, or
    None. `dialect` names it in the answer."""
    missing = sorted((name for name in RUNTIME_MESSAGES if name not in messages),
                     key=lambda n: (RUNTIME_MESSAGES[n][0] < 50000, RUNTIME_MESSAGES[n][0]))  # ttapi's own first
    changed = [name for name, want in RUNTIME_MESSAGES.items() if name in messages and messages[name] != want]
    if missing:
        shown = ", ".join(missing[:4]) + (f" and {len(missing) - 4} more" if len(missing) > 4 else "")
        return (f"{dialect} lacks the runtime's messages ({shown}): add <include>ttapi.xml</include> to it "
                "(ttctl's file transfer, commands, acks and logs; it brings common.xml)")
    if changed:
        name = changed[0]
        (msgid, crc), (want_id, want_crc) = messages[name], RUNTIME_MESSAGES[name]
        return (f"{dialect} defines the runtime's {name} otherwise (id {msgid}, CRC_EXTRA {crc}; ttctl's is id "
                f"{want_id}, CRC_EXTRA {want_crc}): include ttapi.xml rather than a copy of its messages")
    return None


def of_registry(registry: dict[int, Any]) -> dict[str, tuple[int, int]]:
    """name -> (id, CRC_EXTRA) of a generated package's registry."""
    return {info.cls.NAME: (msgid, info.crc_extra) for msgid, info in registry.items()}
