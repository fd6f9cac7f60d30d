"""A second path beside the packet channel, sans-IO: a pipeline (DJI's MOP, "SDK
interconnection": a reliable byte stream between the onboard computer and the app, far faster
than the 128-byte low-speed channel, and known to close and time out in the field).

While a pipeline is open, file data goes on it, paced at the pipeline's rate in whole frames cut
for a stream (no packet size: the widest data frame), and the packets carry only control and
telemetry, so commands, acks and statuses keep their latency. When it closes, every running
transfer goes on over the packet channel at once, its frames cut for that channel's packets from
the next offset on: the transfer engine works by byte offset, so the bytes that were in flight on
the closed pipeline come back as gaps in the receiver's status and are resent, and nothing else
is. When it opens again, file data moves back.

Signed, the pipeline's frames carry link id `link_id ^ PIPE_LINK_BIT`: MAVLink signing orders
timestamps per (link id, system, component), and the two paths deliver with different delays, so
one stream of timestamps over both would make the faster path's frames look like replays.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from .transfer import Geometry

if TYPE_CHECKING:
    from .endpoint import Endpoint
    from .sender import FileSender

PIPE_MTU = 280  # the largest MAVLink 2 frame, signed: a stream takes any frame whole
PIPE_LINK_BIT = 0x80


class Pipe:
    """The endpoint's pipeline state: whether one is open, at what rate, and what it carried."""

    def __init__(self, ep: Endpoint) -> None:
        self.ep = ep
        self.rate_Bps: float | None = None
        self.opened_at: float | None = None  # None: closed
        self.opens = 0
        self.closes = 0
        self.geometry = Geometry(PIPE_MTU, ep.signing is not None)
        self._packet_rate = ep.scheduler.pacer.rate
        self._packet_inbound = ep.receiver.inbound_Bps if ep.receiver is not None else None
        if ep.signing is not None:
            s = ep.signing
            pipe_signing = ep.b.signing(s.key, s.link_id ^ PIPE_LINK_BIT, s.allow_unsigned)
            self._sign: Any = ep.b.sign(pipe_signing)
        else:
            self._sign = None

    @property
    def is_open(self) -> bool:
        return self.opened_at is not None

    def open(self, now: float, rate_Bps: float) -> None:
        """A pipeline opened: file data goes on it at `rate_Bps` from now."""
        self.rate_Bps = rate_Bps
        self.opened_at = now
        self.opens += 1
        self.ep.scheduler.open_pipe(rate_Bps, now, sign=self._sign)
        if self.ep.receiver is not None and self._packet_inbound is not None:
            self.ep.receiver.inbound_Bps = rate_Bps  # grants share the pipeline among transfers
        if self.ep.receiver is not None:
            self.ep.receiver.control_apart = True  # commands stay in the packets: they never wait behind data
        for s in self.ep.senders.values():
            self.adopt(s)

    def close(self, now: float) -> None:
        """The pipeline closed (or timed out): file data goes back into the packets."""
        if self.opened_at is None:
            return
        self.opened_at = None
        self.closes += 1
        self.ep.scheduler.close_pipe()
        if self.ep.receiver is not None:
            self.ep.receiver.inbound_Bps = self._packet_inbound
            self.ep.receiver.control_apart = False
        for s in self.ep.senders.values():
            self.adopt(s)

    def adopt(self, sender: FileSender) -> None:
        """Cut `sender`'s frames for the path file data takes now."""
        if self.is_open and self.rate_Bps:
            sender.use_path(self.geometry, 1.0 / self.rate_Bps, stream=True)
        else:
            sender.use_path(self.ep.geometry, 1.0 / self._packet_rate if self._packet_rate else 0.0, stream=False)

    def sign(self, frame: bytes) -> bytes:
        """`frame` as it goes on the pipeline (signed under the pipeline's link id, when signed)."""
        return self._sign(frame) if self._sign is not None else frame

    def poll(self, now: float) -> bytes | None:
        """The next frame for the pipeline, if one may leave now."""
        if not self.is_open:
            return None
        self.ep.now = now
        return self.ep.scheduler.next_pipe_frame(now, PIPE_MTU)

    def ready_at(self) -> float | None:
        """When the pipeline may take file data next (None: closed, or nothing to send)."""
        ep = self.ep
        pipe_at = ep.scheduler.pipe_ready_at()
        if pipe_at is None:
            return None
        # (a sender under a rate grant waits for its own slot as well)
        times = [max(pipe_at, s.pacer.ready_at() or 0.0) for s in ep.senders.values() if s._wants_data(ep.now)]
        return min(times) if times else None
