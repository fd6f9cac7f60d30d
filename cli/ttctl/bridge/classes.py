"""Which frames on the DTT link are a ground station's, and how each kind is queued.

The tablet end is 255/190, which is also QGroundControl's default: the bridge carries a ground
station with those ids under another system id (routes.py), so that at the onboard end the
source tells the tablet's traffic from a ground station's. Frames of the ground-station protocols
(commands, parameters, missions, FTP, set-points...) are a ground station's whoever sends them:
the tablet's own traffic is TT_* messages, its set-points and its HEARTBEAT. Any other message
(the user's own dialect's) is a ground station's when it comes from other ids than the tablet's:
the bridge carries every station under ids of its own.
"""

from __future__ import annotations

TABLET = (255, 190)
ONBOARD_COMPID = 240  # the onboard end on the DTT link; the vehicle as ground stations see it is compid 1
RADIO_COMPID = 68  # MAV_COMP_ID_TELEMETRY_RADIO: RADIO_STATUS comes from here, as from SiK and mLRS radios
PRESENCE = 5.0  # s: a ground station heard over DTT this recently gets the vehicle's broadcasts there

PROTOCOL_PREFIXES = ("COMMAND_", "PARAM_", "MISSION_", "LOG_REQUEST_", "SET_")
PROTOCOL_NAMES = frozenset({"FILE_TRANSFER_PROTOCOL", "PING", "TIMESYNC", "MANUAL_CONTROL", "RC_CHANNELS_OVERRIDE",
                            "REQUEST_DATA_STREAM", "SYSTEM_TIME", "LOG_ERASE", "GPS_RTCM_DATA", "GPS_INJECT_DATA"})

# one slot each per (source, message): a newer frame replaces the one still waiting
NEWEST = frozenset({"HEARTBEAT", "MANUAL_CONTROL", "RC_CHANNELS_OVERRIDE", "SET_POSITION_TARGET_LOCAL_NED",
                    "SET_POSITION_TARGET_GLOBAL_INT", "SET_ATTITUDE_TARGET", "TIMESYNC", "SYSTEM_TIME"})


def ground_station_protocol(name: str) -> bool:
    """A message of the protocols ground stations speak to a vehicle (not the tablet's own)."""
    return name in PROTOCOL_NAMES or name.startswith(PROTOCOL_PREFIXES)


TABLET_PREFIXES = ("TT_", "DJI_")  # the tablet protocol's own messages (ttapi.xml), whoever sends them


def from_ground_station(name: str, src: tuple[int, int], gcs_type: bool) -> bool:
    """At the onboard end: is this DTT frame a ground station's? `gcs_type`: a HEARTBEAT of
    MAV_TYPE_GCS. The tablet's own HEARTBEAT stays the tablet's; any other end's GCS heartbeat,
    and every frame of the ground-station protocols, is a ground station's; so is any other
    message (the user's own) from ids other than the tablet's."""
    if name == "HEARTBEAT":
        return gcs_type and src != TABLET
    if ground_station_protocol(name):
        return True
    return src != TABLET and not name.startswith(TABLET_PREFIXES)
