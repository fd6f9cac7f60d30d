"""Ground stations behind the tablet: their frames come over the DTT link (the tablet's bridge,
`emulate tablet --gcs`, or the Java runtime's GcsBridge) and the vehicle answers them there as on
its own ground-station links, as the autopilot (compid 1).

Which DTT frames are a ground station's: bridge/classes.py. While one was heard within PRESENCE
seconds, the vehicle's broadcasts go down DTT too (its HEARTBEAT always). All of it leaves through
one fair source below the tablet's own commands and acks (bridge/downmux.py): the HEARTBEAT first
(three times a second), then the streams newest-wins per type, fitted to `share` of the downlink
(bridge/downfit.py), then short answers (acks, STATUSTEXT) in order, then bulk answers (FTP,
parameter and mission lists) fair by bytes between the stations they are for; an answer equal to
one still waiting not twice (bridge/answers.py). An FTP burst to one station so never holds back
the HEARTBEAT or the position every station gets. Plugins' answers to a station's own messages
(the user's dialect) wait in a small queue of their own beside those, a source of the scheduler
like them: a station flooding its own messages cannot delay the vehicle's acks or HEARTBEAT.
"""

from __future__ import annotations

from typing import Any

from ...bridge.answers import AnswerQueue
from ...bridge.classes import PRESENCE, from_ground_station
from ...bridge.downfit import StreamFit
from ...bridge.downmux import FairDownlink
from ...proto.endpoint import Endpoint
from ...wire.bindings import Bindings
from .gcs import GroundStations

DTT = "dtt"  # the ground stations' link key for those behind the tablet
USER_LIMIT = 32  # plugins' answers waiting for the downlink (beyond it the oldest goes, counted)


class DttGroundStations:
    def __init__(self, b: Bindings, gcs: GroundStations, sysid: int, compid: int, share: float,
                 downlink_Bps: float | None) -> None:
        self.b = b
        self.gcs = gcs
        self.encoder = b.encoder(sysid, compid)  # unsigned: the DTT scheduler signs as frames leave
        self.fit = StreamFit(share * downlink_Bps if downlink_Bps else None,
                             asked=lambda mid: gcs.rates.interval.get(mid), encode=self.encoder.encode)
        self.down = FairDownlink(self.fit, self.encoder.encode)
        self.user = AnswerQueue(self.encoder.encode, limit=USER_LIMIT)
        self.endpoint: Endpoint | None = None
        self.heard_at: float | None = None  # loop time of the last ground-station frame over DTT
        self.frames_in = 0
        self.frames_out = 0

    def attach(self, endpoint: Endpoint) -> None:
        self.endpoint = endpoint
        endpoint.add_stream(self.down)
        endpoint.add_stream(self.user)

    def takes(self, msg: Any) -> bool:
        b = self.b
        gcs_type = isinstance(msg, b.Heartbeat) and msg.type == b.MavType.MAV_TYPE_GCS
        return from_ground_station(msg.NAME, (msg.get_srcSystem(), msg.get_srcComponent()), gcs_type)

    def heard(self, now: float) -> None:
        self.heard_at = now
        self.frames_in += 1

    def present(self, now: float) -> bool:
        return self.heard_at is not None and now - self.heard_at <= PRESENCE

    def send(self, now: float, msg: Any, broadcast: bool) -> None:
        """A frame for the ground stations behind the tablet (`broadcast`: for every one)."""
        if self.endpoint is None:
            return
        b = self.b
        msgid = msg.MSG_ID
        # (HEARTBEAT is not fitted: it goes first, so a ground station learns the autopilot type
        # before the first PARAM_VALUE, which MAVProxy decodes by it, and never waits for a burst)
        if isinstance(msg, b.Heartbeat):
            self.down.put_heartbeat(now, msg)
            self.frames_out += 1
            return
        if broadcast and msgid in self.gcs.rates.builders and msgid != b.Heartbeat.MSG_ID:
            self.fit.put(now, msgid, msg)  # a stream: newest wins, fitted
            return
        if isinstance(msg, b.MessageInterval):  # the interval this link keeps, not the one asked
            msg = b.MessageInterval(message_id=msg.message_id,
                                    interval_us=int(self.fit.interval_us(msg.message_id, msg.interval_us)))
        if self.down.put(msg):
            self.frames_out += 1

    def send_user(self, msg: Any) -> None:
        """A plugin's answer to a station behind the tablet (addressed by its target fields, if any)."""
        if self.endpoint is not None and self.user.put(msg):
            self.frames_out += 1
