"""A ground station that speaks MAVLink 1, for the bridge tests in Python and Java: pymavlink's
own MAVLink 1 codec (pymavlink.dialects.v10, used directly whatever MAVLINK20 other tests set)
on a UDP socket where the bridge sends."""

from __future__ import annotations

import socket
import threading
import time
from typing import Any

from pymavlink.dialects.v10 import common as v1

from e2e_lib import LOCAL


class V1Station:
    """pymavlink's MAVLink 1 codec on a UDP socket where the bridge sends."""

    def __init__(self, port: int) -> None:
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.sock.bind((LOCAL, port))
        self.sock.settimeout(0.5)
        self.mav = v1.MAVLink(None, srcSystem=246, srcComponent=190)
        self.mav.robust_parsing = True
        self.peer: tuple[str, int] | None = None
        self.v2_frames = 0  # MAVLink 2 that reached us after the first MAVLink 1 frame
        self.spoken_to = False
        self.stop = threading.Event()
        self.lock = threading.Lock()

    def send(self, msg: Any) -> None:
        with self.lock:
            if self.peer is not None:
                self.sock.sendto(msg.pack(self.mav), self.peer)

    def recv(self, kind: str, pred: Any = lambda x: True, timeout: float = 10.0) -> Any:
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            try:
                data, addr = self.sock.recvfrom(4096)
            except TimeoutError:
                continue
            self.peer = addr
            if data[:1] != b"\xfe":
                self.v2_frames += self.spoken_to
                continue
            self.spoken_to = True
            for m in self.mav.parse_buffer(data) or []:
                if m.get_type() == kind and pred(m):
                    return m
        raise AssertionError(f"no MAVLink 1 {kind} within {timeout} s")

    def beat(self) -> None:
        while not self.stop.is_set():
            self.send(self.mav.heartbeat_encode(6, 8, 0, 0, 0))
            self.stop.wait(1.0)
