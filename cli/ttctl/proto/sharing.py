"""Several transfers on one link, sans-IO: the receiver grants each transfer a share of what
it can take, the senders pace to their grant (TT_FILE_STATUS.rate_grant).

Each sender paces to its own link rate; five of them, in five processes, each at the full
rate of a link they share overflow its buffer, and most of what they send is lost and sent
again. Only the receiver sees them all, so it divides its inbound capacity (known from its
link: `--profile`, `--rate`) equally among the transfers it is receiving and has heard from
lately, and says each one's share in every status; a change in who shares (a transfer starts,
ends or goes quiet) is told to every other at once. GRANT_FILL of the capacity goes to file
data; the rest keeps room for offers, polls and commands. A lone transfer gets no grant (0): it
paces to its own rate, as before.

Commands from another process (the tablet beside `send-file` processes) meet the senders'
packets in the radio's two-packet buffer, first come first served. At 0.97 of the link a packet
that waits takes some 30 packet times to drain, so a command found one or two packets waiting
(0.5 s instead of 0.25) or a full buffer (dropped: a 3 s retry); a lone transfer, paced to the
whole link with three-packet frames, kept it full. So once a control frame (a command, a
setpoint, a VR pose, a ground station's request taken over DTT; not the other end's telemetry)
has come in within CONTROL_WINDOW (endpoint.py), the grants
share CONTROL_FILL of the capacity and a lone transfer is granted too: a backlog drains in a few
packet times and a command waits about the packet on the air (tests/test_commands_beside_files).
While a pipeline carries the file data (pipeline.py) commands stay in the packets and never wait
behind it, so there the control grant does not apply (Receiver.control_apart).

Two sender habits change under a grant: it sends one-packet frames only (a wide frame's three
packets back to back fill the radio's buffer for the others, and an overflow takes the whole
frame), and it waits three frames' time at its grant longer before polling a quiet receiver;
the receiver, likewise, keeps reporting while frames come at the granted pace (sender.py
`_quiet_after`, receiver.py `_flow_window`).

The shares are equal (max-min fair when every sender can use its share); a transfer that sends
slower than its share leaves the rest of it unused until the receiver stops hearing from it.
"""

from __future__ import annotations

from collections import deque

GRANT_FILL = 0.97  # of the inbound capacity granted to file data when transfers share it
ACTIVE_WINDOW = 3.0  # s: a receiving transfer heard from within this shares the link
MIN_GRANT = 1  # B/s: a grant is never 0 (0 on the wire means "no grant")
MAX_GRANT = 65535  # what TT_FILE_STATUS.rate_grant holds


OTHER_ROOM = 2.0  # B/s kept free per B/s of other traffic measured coming in (commands, offers, polls)
MIN_FILL = 0.5  # of the capacity granted, whatever else comes in
LOAD_WINDOW = 5.0  # s over which the other traffic is measured
REGRANT = 0.1  # a grant changes (and is told) when the share moves by more than this fraction


CONTROL_FILL = 0.75  # of the capacity granted to file data while control traffic shares the link
CONTROL_WINDOW = 60.0  # s: a command (or other control frame) heard within this: the link carries control traffic


def share(capacity_Bps: float | None, sharing: int, other_Bps: float = 0.0, control: bool = False) -> int:
    """Each transfer's grant when `sharing` transfers share `capacity_Bps`, of which `other_Bps`
    is taken by frames that are not file data (0: no grant). With `control` (commands heard
    lately) a lone transfer is granted too: paced to its link it would fill the radio's buffer
    for the commands of another process."""
    if capacity_Bps is None or capacity_Bps <= 0 or sharing < 1 or (sharing < 2 and not control):
        return 0
    fill = CONTROL_FILL if control else GRANT_FILL
    budget = max(MIN_FILL * capacity_Bps, fill * capacity_Bps - OTHER_ROOM * other_Bps)
    return max(MIN_GRANT, min(MAX_GRANT, int(budget / sharing)))


class InboundLoad:
    """What comes in that is not file data, in B/s over the last LOAD_WINDOW seconds: packet
    bytes less data frames' bytes."""

    def __init__(self) -> None:
        self._events: deque[tuple[float, int]] = deque()  # (time, bytes: + packets, - data frames)
        self._sum = 0

    def packet(self, now: float, nbytes: int) -> None:
        self._add(now, nbytes)

    def data(self, now: float, nbytes: int) -> None:
        self._add(now, -nbytes)

    def _add(self, now: float, n: int) -> None:
        self._events.append((now, n))
        self._sum += n
        self._trim(now)

    def _trim(self, now: float) -> None:
        while self._events and self._events[0][0] < now - LOAD_WINDOW:
            self._sum -= self._events.popleft()[1]

    def other_Bps(self, now: float) -> float:
        self._trim(now)
        return max(0, self._sum) / LOAD_WINDOW


class GrantPacer:
    """A sender's pace under its grant: a frame of n bytes may leave n / grant seconds after
    the one before (no credit is saved up while it waits for other reasons)."""

    def __init__(self) -> None:
        self.grant = 0  # B/s, 0: none
        self.next_free = 0.0

    def update(self, grant: int, now: float) -> None:
        grant = max(0, int(grant))
        if grant != self.grant:
            self.next_free = now  # a new grant: the next frame leaves now, in the slot its status set
        self.grant = grant

    def ready(self, now: float) -> bool:
        return self.grant == 0 or now >= self.next_free - 1e-9

    def ready_at(self) -> float | None:
        return self.next_free if self.grant else None

    def sent(self, now: float, nbytes: int) -> None:
        if self.grant:
            self.next_free = max(now, self.next_free) + nbytes / self.grant


__all__ = ["ACTIVE_WINDOW", "CONTROL_WINDOW", "GRANT_FILL", "GrantPacer", "InboundLoad", "share"]
