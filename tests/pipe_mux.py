"""A MOP pipeline's far end for the Java tablet tests, before `ttctl ... --pipeline` (and beside
it): it sits between the tablet and an onboard end that has only its low-speed UDP link, and
carries the tablet's pipeline (the stand-in MSDK v5's TCP connection) the way an onboard end's
pipeline does. pymavlink is the oracle: every byte is parsed by pymavlink, with a fresh parser per
TCP connection.

- tablet -> onboard: UDP datagrams go on as they are; frames from the pipeline go on cut to the
  onboard link's packet, as DJI's DTT cuts a long frame (counted by name);
- onboard -> tablet: file-data frames (TT_FILE_DATA, _WIDE, _FIT) go on the pipeline while it is
  connected, everything else (and file data while it is not) by UDP;
- `drops`: byte counts of the tablet's pipeline data at which the mux closes the connection (a
  drop, from the onboard side), `refuse` seconds during which it then refuses connections;
- `garbage`: the mux floods each connection with random bytes instead;
- `split`: the first connection gets the first half of a frame and is closed, the second the rest
  of it and then one whole frame (a reader that glued the two connections' bytes would find two).
"""

from __future__ import annotations

import random
import socket
import threading
import time
from collections import Counter
from types import ModuleType

DATA = {"TT_FILE_DATA", "TT_FILE_DATA_WIDE", "TT_FILE_DATA_FIT"}


class PipeMux:
    def __init__(self, pm: ModuleType, onboard_port: int, drops: tuple[int, ...] = (), refuse: float = 0.0,
                 garbage: bool = False, mtu: int = 100, split: bool = False) -> None:
        self.split = split
        self.mtu = mtu  # the onboard link's packet: the pipeline's frames are cut to it, in order
        self.pm = pm
        self.onboard = ("127.0.0.1", onboard_port)
        self.tab = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.tab.bind(("127.0.0.1", 0))
        self.air = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.air.bind(("127.0.0.1", 0))
        for s in (self.tab, self.air):
            s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 1 << 22)
            s.settimeout(0.2)
        self.srv = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        self.srv.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        self.srv.bind(("127.0.0.1", 0))
        self.srv.listen(4)
        self.srv.settimeout(0.2)
        self.udp_port = self.tab.getsockname()[1]
        self.pipe_port = self.srv.getsockname()[1]
        self.drops = list(drops)
        self.refuse = refuse
        self.garbage = garbage
        self.tablet: tuple[str, int] | None = None
        self.conn: socket.socket | None = None
        self.lock = threading.Lock()
        self.air_lock = threading.Lock()  # a cut frame's pieces go back to back
        self.stop = threading.Event()
        self.pipe_up = Counter()  # frames from the tablet's pipeline, by name
        self.pipe_up_bytes = 0
        self.pipe_down = Counter()  # frames put on the pipeline toward the tablet
        self.low_up = Counter()  # frames from the tablet by UDP
        self.low_down = Counter()
        self.connections = 0
        self.dropped_at: list[int] = []
        self.bad_up = 0
        self.garbage_bytes = 0
        self.threads = [threading.Thread(target=f, daemon=True)
                        for f in (self._from_tablet, self._from_air, self._pipe)]
        for t in self.threads:
            t.start()

    def parser(self) -> object:
        mav = self.pm.MAVLink(None, 1, 240)
        mav.robust_parsing = True
        return mav

    def _frames(self, mav: object, data: bytes) -> list[object]:
        out = mav.parse_buffer(data) or []  # type: ignore[attr-defined]
        return [m for m in out if not isinstance(m, self.pm.MAVLink_bad_data)]

    def _from_tablet(self) -> None:
        mav = self.parser()
        while not self.stop.is_set():
            try:
                data, addr = self.tab.recvfrom(65536)
            except TimeoutError:
                continue
            except OSError:
                return
            self.tablet = addr
            for m in self._frames(mav, data):
                self.low_up[m.get_type()] += 1
            with self.air_lock:
                self.air.sendto(data, self.onboard)

    def _from_air(self) -> None:
        mav = self.parser()
        while not self.stop.is_set():
            try:
                data, _ = self.air.recvfrom(65536)
            except TimeoutError:
                continue
            except OSError:
                return
            for m in self._frames(mav, data):
                name, frame = m.get_type(), bytes(m.get_msgbuf())
                with self.lock:
                    c = self.conn if name in DATA and not self.garbage else None
                    if c is not None:
                        try:
                            c.sendall(frame)
                            self.pipe_down[name] += 1
                            continue
                        except OSError:
                            self.conn = None
                if self.tablet is not None:
                    self.low_down[name] += 1
                    self.tab.sendto(frame, self.tablet)

    def _pipe(self) -> None:
        while not self.stop.is_set():
            try:
                c, _ = self.srv.accept()
            except TimeoutError:
                continue
            except OSError:
                return
            self.connections += 1
            c.settimeout(0.2)
            if self.garbage:
                self._flood(c)
                continue
            if self.split:
                self._split(c)
                continue
            with self.lock:
                self.conn = c
            mav = self.parser()  # a fresh parser per connection
            dropped = False
            while not self.stop.is_set() and not dropped:
                try:
                    data = c.recv(65536)
                except TimeoutError:
                    continue
                except OSError:
                    break
                if not data:
                    break
                for m in self._frames(mav, data):
                    frame = bytes(m.get_msgbuf())
                    self.pipe_up[m.get_type()] += 1
                    if m.get_type() in DATA:
                        self.pipe_up_bytes += len(frame)
                    with self.air_lock:
                        for i in range(0, len(frame), self.mtu):
                            self.air.sendto(frame[i:i + self.mtu], self.onboard)
                if self.drops and self.pipe_up_bytes >= self.drops[0]:
                    self.drops.pop(0)
                    self.dropped_at.append(self.pipe_up_bytes)
                    dropped = True
            with self.lock:
                if self.conn is c:
                    self.conn = None
            c.close()
            if dropped and self.refuse > 0:
                until = time.monotonic() + self.refuse
                while time.monotonic() < until:
                    try:
                        r, _ = self.srv.accept()
                        r.close()
                    except (TimeoutError, OSError):
                        pass

    def _split(self, c: socket.socket) -> None:
        mav = self.pm.MAVLink(None, 1, 240)
        x = mav.heartbeat_encode(18, 8, 0, 0, 4).pack(mav)
        y = mav.heartbeat_encode(18, 8, 0, 0, 3).pack(mav)
        half = len(x) // 2
        if self.connections == 1:
            c.sendall(x[:half])
        else:
            c.sendall(x[half:] + y)
            time.sleep(3)  # open a while: the tablet reads it
        c.close()

    def _flood(self, c: socket.socket) -> None:
        rnd = random.Random(27)
        c.settimeout(2.0)
        try:
            while not self.stop.is_set():
                block = rnd.randbytes(65536)
                c.sendall(block)
                self.garbage_bytes += len(block)
        except OSError:
            pass
        c.close()

    def close(self) -> None:
        self.stop.set()
        for s in (self.tab, self.air, self.srv):
            s.close()
        with self.lock:
            if self.conn is not None:
                self.conn.close()
        for t in self.threads:
            t.join(2)
