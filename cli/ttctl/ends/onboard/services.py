"""The services a ground station expects of a PX4-like vehicle besides flying, sans-IO: TIMESYNC
answered, GET_MESSAGE_INTERVAL, MAVLink FTP (ftp.py), the log list (LOG_REQUEST_LIST: this vehicle
keeps no flight logs, so it says so at once, as PX4 does with an empty SD card), and the extra
telemetry streams MAVSDK's getters read (ATTITUDE_QUATERNION, ODOMETRY, ALTITUDE, SYSTEM_TIME, HIGHRES_IMU,
SCALED_PRESSURE, WIND_COV; SCALED_IMU and HIL_STATE_QUATERNION, the simulation's truth, when
asked for), built from the same snapshot as the rest.

`Services.on_message(now, msg, reply)` takes a message meant for the vehicle and returns True if
it was one of these (answers go to `reply`); `command(msg)` answers the commands it owns
(None: not one of them); `tick(now)` returns (message, peer) pairs still to send (an FTP burst's
packets), `wakeup()` when to call it again.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Hashable
from typing import Any

from ...wire.bindings import Bindings
from . import telemetry
from .ftp import FtpServer
from .vehicle import Snapshot

Reply = Callable[[Any], None]


Builders = dict[int, Callable[[Snapshot], Any]]


def streams(b: Bindings, boot_ms: Callable[[], int], unix_us: Callable[[], int]) -> Builders:
    """The builders of the streams these services add (msgid -> build(snapshot))."""
    return {
        b.AttitudeQuaternion.MSG_ID: lambda s: telemetry.attitude_quaternion(b, s, boot_ms()),
        b.Odometry.MSG_ID: lambda s: telemetry.odometry(b, s, boot_ms() * 1000),
        b.Altitude.MSG_ID: lambda s: telemetry.altitude(b, s, boot_ms() * 1000),
        b.SystemTime.MSG_ID: lambda s: telemetry.system_time(b, unix_us(), boot_ms()),
        b.HighresImu.MSG_ID: lambda s: telemetry.highres_imu(b, s, boot_ms() * 1000),
        b.ScaledImu.MSG_ID: lambda s: telemetry.scaled_imu(b, s, boot_ms()),
        b.ScaledPressure.MSG_ID: lambda s: telemetry.scaled_pressure(b, s, boot_ms()),
        b.WindCov.MSG_ID: lambda s: telemetry.wind_cov(b, s, boot_ms() * 1000),
        b.HilStateQuaternion.MSG_ID: lambda s: telemetry.hil_state_quaternion(b, s, boot_ms() * 1000),
    }


class Services:
    def __init__(self, b: Bindings, boot_ms: Callable[[], int], unix_us: Callable[[], int],
                 rates: Callable[[], telemetry.Rates], warn: Callable[[str], Any] | None = None) -> None:
        self.b = b
        self.warn = warn or (lambda text: None)  # a refusal's words: the log and a STATUSTEXT
        self.boot_ms = boot_ms
        self.unix_us = unix_us
        self.rates = rates
        self.ftp = FtpServer()  # the node gives it the served folder and the inbox

    def on_message(self, now: float, msg: Any, reply: Reply, peer: Hashable = None) -> bool:
        b = self.b
        if isinstance(msg, b.FileTransferProtocol):
            if msg.target_network == 0:
                for payload in self.ftp.request(now, msg.payload, peer):
                    reply(self._ftp_message(payload, peer))
            return True
        if isinstance(msg, b.Timesync):
            if msg.tc1 == 0:  # a request: ts1 mirrored, our time in tc1 (ns on the boot clock; never 0, a request)
                reply(b.Timesync(tc1=max(1, self.boot_ms() * 1_000_000), ts1=msg.ts1))
            return True  # an answer to someone else's request is not for us to act on
        if isinstance(msg, b.LogRequestList):
            # no logs: one LOG_ENTRY with num_logs 0 (id 0), which PX4 sends and MAVSDK reads as an empty list
            reply(b.LogEntry(id=0, num_logs=0, last_log_num=0, time_utc=0, size=0))
            return True
        if isinstance(msg, b.LogRequestData):
            reply(b.LogData(id=msg.id, ofs=msg.ofs, count=0, data=bytes(90)))  # no such log: nothing to read
            return True
        return isinstance(msg, (b.LogRequestEnd, b.LogErase))  # nothing being sent, nothing to erase

    def _ftp_message(self, payload: bytes, peer: Hashable) -> Any:
        ts, tc = peer if isinstance(peer, tuple) else (0, 0)
        return self.b.FileTransferProtocol(target_network=0, target_system=ts, target_component=tc, payload=payload)

    def tick(self, now: float) -> list[tuple[Any, Hashable]]:
        return [(self._ftp_message(p, peer), peer) for p, peer in self.ftp.tick(now)]

    def wakeup(self) -> float | None:
        return self.ftp.wakeup()

    def command(self, msg: Any) -> tuple[int, list[Any]] | None:
        b = self.b
        C, A = b.MavCmd, b.MavResult
        if msg.command == C.MAV_CMD_GET_MESSAGE_INTERVAL:
            p1 = msg.param1
            if p1 is None or not math.isfinite(p1) or not 0 <= p1 < 1 << 24 or p1 != int(p1):
                self.warn(f"refused: GET_MESSAGE_INTERVAL wants a message id, not {p1}")
                return int(A.MAV_RESULT_DENIED), []
            msgid = int(p1)
            rates = self.rates()
            if msgid not in rates.builders:
                # a message this vehicle never streams: interval 0 means "not available" (MESSAGE_INTERVAL)
                return int(A.MAV_RESULT_ACCEPTED), [b.MessageInterval(message_id=msgid, interval_us=0)]
            iv = rates.interval[msgid]
            us = -1 if iv is None else round(iv * 1e6)
            return int(A.MAV_RESULT_ACCEPTED), [b.MessageInterval(message_id=msgid, interval_us=us)]
        return None


__all__ = ["Services", "streams"]
