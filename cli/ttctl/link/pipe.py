"""A pipeline's byte stream as ttctl's ends open it, over TCP: `tcpin:HOST:PORT` accepts, as the
onboard computer's `DjiMopChannel_Accept` does; `tcpout:HOST:PORT` (or `tcp:`) connects, as the app's
`PipelineManager.connectPipeline` does, and connects again a second after the pipeline closes
or cannot open, for as long as the end runs.

Each connection is numbered; its bytes go to `on_data(data, n)` and its end to `on_close(n,
words)`, so the endpoint parses each connection with a parser of its own and a half frame left
by a closed one never meets the next one's bytes. Frames are written whole (`write`); what a
connection had not yet sent when it closes goes with it. The socket's send buffer is kept small
so that what a close loses is what the pacer had let go, not megabytes a kernel held.

On `tcpin`, a connection becomes the pipeline only once a valid frame came on it (`confirm`,
called by the driver when the endpoint parsed one): a stranger who connects to the port gets no
file data and takes nothing over. A newer confirmed connection replaces the older one (a peer
that reconnects after a silent drop is not locked out by its own dead connection). The side that
connects says hello at once (`on_connect`: the driver writes a HEARTBEAT), so that the accepting
side can confirm it before any file moves.
"""

from __future__ import annotations

import asyncio
import contextlib
import socket
import struct

try:
    import fcntl
    import termios

    _OUTQ: int | None = termios.TIOCOUTQ  # the same request as SIOCOUTQ for a socket (Linux)
except (ImportError, AttributeError):  # pragma: no cover - not Linux
    _OUTQ = None
from collections.abc import Callable

from .transport import Spec, TransportError, _os_reason, addr_text, parse_spec

RETRY_S = 1.0
SNDBUF = 32 * 1024
NEVER_OPEN_S = 10.0  # a pipeline not open after this long is told once
MAX_PENDING = 8  # tcpin connections kept while they prove who they are


def parse_pipe(text: str) -> Spec:
    """`--pipeline`'s value: tcpin:HOST:PORT or tcpout:HOST:PORT (TransportError otherwise)."""
    raw = text.strip()
    if raw.lower().startswith("tcpout:"):
        raw = "tcp:" + raw[len("tcpout:"):]
    try:
        return parse_spec(raw, allowed=("tcp", "tcpin"))
    except TransportError as e:
        raise TransportError(f"--pipeline: {e} (a pipeline is tcpin:HOST:PORT or tcpout:HOST:PORT)") from None


class PipeLink:
    """One pipeline end. Callbacks: `on_open(n)`, `on_data(data, n)`, `on_close(n, words)`."""

    def __init__(self, spec: Spec, log: Callable[[str], None]) -> None:
        if spec.kind not in ("tcpin", "tcp"):
            raise TransportError(f"--pipeline must be tcpin:HOST:PORT or tcpout:HOST:PORT, not {spec.kind}:")
        self.spec = spec
        self.log = log
        self.on_open: Callable[[int], None] = lambda n: None
        self.on_data: Callable[[bytes, int], None] = lambda data, n: None
        self.on_close: Callable[[int, str], None] = lambda n, words: None
        self.on_forget: Callable[[int], None] = lambda n: None  # an unproven connection ended
        self.on_connect: Callable[[Callable[[bytes], None]], None] = lambda write: None  # (tcpout) say hello
        self.connection = 0  # the open connection's number (0: none open)
        self.opened = 0
        self.bytes_out = 0
        self.bytes_in = 0
        self._transport: asyncio.Transport | None = None
        self._pending: dict[int, asyncio.Transport] = {}  # tcpin connections not yet proven to be the peer
        self._numbers = 0
        self._server: asyncio.base_events.Server | None = None
        self._task: asyncio.Task[None] | None = None
        self._closed = False
        self._last_failure = ""

    @property
    def is_open(self) -> bool:
        return self._transport is not None

    def where(self) -> str:
        kind = "tcpout" if self.spec.kind == "tcp" else self.spec.kind
        return f"{kind}:{self.spec.host}:{self.spec.port}"

    async def open(self) -> None:
        """Listen (tcpin: TransportError if the address cannot be had) or start connecting (tcpout)."""
        loop = asyncio.get_running_loop()
        if self.spec.kind == "tcpin":
            try:
                self._server = await loop.create_server(lambda: _Conn(self), self.spec.host, self.spec.port)
            except OSError as e:
                raise TransportError(f"--pipeline {self.where()}: {_os_reason(e)}") from None
        else:
            self._task = loop.create_task(self._connect_loop())
        loop.call_later(NEVER_OPEN_S, self._tell_if_never_open)

    def _tell_if_never_open(self) -> None:
        if not self.opened and not self._closed:
            why = f" ({self._last_failure})" if self._last_failure else ""
            self.log(f"pipeline {self.where()}: not open after {NEVER_OPEN_S:.0f} s{why}; file data stays on the "
                     f"low-speed channel")

    async def _connect_loop(self) -> None:
        loop = asyncio.get_running_loop()
        while not self._closed:
            if self._transport is None:
                try:
                    await loop.create_connection(lambda: _Conn(self), self.spec.host, self.spec.port)
                except OSError as e:
                    self._last_failure = _os_reason(e)
            await asyncio.sleep(RETRY_S)

    def backlog(self) -> int:
        """Bytes written and not yet taken by the peer: what asyncio holds, and what the kernel
        sent and the peer has not acknowledged or has not sent yet (SIOCOUTQ, on Linux)."""
        t = self._transport
        if t is None:
            return 0
        held = t.get_write_buffer_size()
        sock = t.get_extra_info("socket")
        if sock is not None and _OUTQ is not None:
            with contextlib.suppress(OSError, ValueError):
                held += struct.unpack("i", fcntl.ioctl(sock.fileno(), _OUTQ, b"\0\0\0\0"))[0]
        return held

    def write(self, frame: bytes) -> None:
        t = self._transport
        if t is not None:
            t.write(frame)
            self.bytes_out += len(frame)

    def drop(self, words: str) -> None:
        """End the open connection ourselves (it timed out), in `words`."""
        t, n = self._transport, self.connection
        if t is None:
            return
        self._transport, self.connection = None, 0
        self.log(f"pipeline closed ({words}): file data back on the low-speed channel")
        self.on_close(n, words)
        t.abort()

    def close(self) -> None:
        self._closed = True
        if self._task is not None:
            self._task.cancel()
        if self._server is not None:
            self._server.close()
        if self._transport is not None:
            self._transport.abort()
        for t in self._pending.values():
            t.abort()
        self._pending.clear()

    # -- from the connections -----------------------------------------------------------------
    def _made(self, conn: _Conn, transport: asyncio.Transport) -> None:
        if self._closed:
            transport.abort()
            return
        sock = transport.get_extra_info("socket")
        if sock is not None:
            with contextlib.suppress(OSError):
                sock.setsockopt(socket.SOL_SOCKET, socket.SO_SNDBUF, SNDBUF)
                sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        self._numbers += 1
        conn.number = self._numbers
        if self.spec.kind == "tcpin":
            self._pending[conn.number] = transport
            while len(self._pending) > MAX_PENDING:  # the oldest unproven one goes
                old = next(iter(self._pending))
                self._pending.pop(old).abort()
            return
        self.on_connect(transport.write)
        self._take(conn.number, transport)

    def confirm(self, n: int) -> None:
        """A valid frame came on connection `n`: on tcpin it becomes the pipeline."""
        transport = self._pending.pop(n, None)
        if transport is not None and not self._closed:
            self._take(n, transport)

    def _take(self, n: int, transport: asyncio.Transport) -> None:
        if self._transport is not None:  # a newer connection replaces the older one
            old, old_n = self._transport, self.connection
            self._transport, self.connection = None, 0
            self.on_close(old_n, "replaced by a newer connection")
            old.abort()
        self.opened += 1
        self.connection = n
        self._transport = transport
        peer = transport.get_extra_info("peername")
        self.log(f"pipeline open ({self.where()}, {addr_text(peer) if peer else 'peer'}): file data goes on it")
        self.on_open(n)

    def _lost(self, conn: _Conn, words: str) -> None:
        if self._pending.pop(conn.number, None) is not None:
            self.on_forget(conn.number)  # never proven: its half frame, if any, goes
            return
        if conn.number == 0 or conn.number != self.connection:
            return  # replaced, or never taken
        self._transport = None
        self.connection = 0
        if not self._closed:  # (our own close at the end is no news)
            self.log(f"pipeline closed ({words}): file data back on the low-speed channel")
            self.on_close(conn.number, words)

    def _data(self, conn: _Conn, data: bytes) -> None:
        if conn.number and (conn.number == self.connection or conn.number in self._pending):
            self.bytes_in += len(data)
            self.on_data(data, conn.number)


class _Conn(asyncio.Protocol):
    def __init__(self, pipe: PipeLink) -> None:
        self.pipe = pipe
        self.number = 0

    def connection_made(self, transport: asyncio.BaseTransport) -> None:
        assert isinstance(transport, asyncio.Transport)
        self.pipe._made(self, transport)

    def data_received(self, data: bytes) -> None:
        self.pipe._data(self, data)

    def connection_lost(self, exc: Exception | None) -> None:
        words = _os_reason(exc) if isinstance(exc, OSError) else "the peer closed it"
        self.pipe._lost(self, words)
