"""Endpoint specs and the asyncio transports between processes.

Specs are spelled as MAVLink tools (mavutil, MAVProxy) spell them:

- `udpin:HOST:PORT`: bind HOST:PORT and listen; what is sent goes to every peer address heard
  from lately, where a peer is an address that sent at least one valid MAVLink frame (the
  layer above says which: `confirm`). Garbage, from anywhere, never makes a peer.
- `udpout:HOST:PORT`: send to HOST:PORT from an ephemeral port, and hear replies there.
- `tcp:HOST:PORT`: connect to a TCP server (reconnecting if the connection drops).
- `tcpin:HOST:PORT`: listen for TCP connections; what is sent goes to every connection.
- `udp:HOST:PORT` means udpin where the command listens and udpout where it sends.

A UDP datagram is one DTT packet: at most `mtu` bytes (100, as on DJI's link); larger
datagrams are dropped and counted, as DJI would refuse them. TCP carries the plain MAVLink 2
byte stream, so a ground station or pymavlink can connect and read it; there packets are
only a unit of pacing, up to a whole frame (280 bytes) so a frame never straddles two.
"""

from __future__ import annotations

import asyncio
import contextlib
import errno
import os
import socket
from collections import OrderedDict
from collections.abc import Callable, Hashable
from dataclasses import dataclass, field

KINDS = ("udpin", "udpout", "tcp", "tcpin")
LISTENING = ("udpin", "tcpin")
DTT_MTU = 100
STREAM_MTU = 280  # the longest MAVLink 2 frame: 10 + 255 + 2 + 13
TCP_BUFFER_LIMIT = 256 * 1024  # a TCP client this far behind loses packets instead of growing our memory
UDP_SOCKET_BUFFER = 1 << 20
PEER_TIMEOUT = 60.0  # a udpin peer silent this long is no longer sent to
MAX_PEERS = 16  # udpin peers kept (the least recently heard goes first)

FORMS = "udpin:HOST:PORT, udpout:HOST:PORT, tcp:HOST:PORT or tcpin:HOST:PORT"


class TransportError(Exception):
    """A spec that cannot work: malformed, unresolvable, unreachable, or a port in use."""


@dataclass(frozen=True)
class Spec:
    kind: str  # udpin | udpout | tcp | tcpin
    host: str
    port: int

    @property
    def udp(self) -> bool:
        return self.kind.startswith("udp")

    @property
    def stream(self) -> bool:
        return self.kind.startswith("tcp")

    @property
    def listening(self) -> bool:
        return self.kind in LISTENING

    def __str__(self) -> str:
        host = f"[{self.host}]" if ":" in self.host else self.host
        return f"{self.kind}:{host}:{self.port}"


def parse_spec(text: str, udp: str = "udpin", allowed: tuple[str, ...] = KINDS) -> Spec:
    """Parse an endpoint spec; `udp` says what a bare `udp:` means here (udpin or udpout).
    Raises TransportError with a one-line explanation."""
    raw = text.strip()
    kind, sep, rest = raw.partition(":")
    kind = kind.lower()
    if not sep:
        raise TransportError(f"bad endpoint {text!r}: expected {FORMS}")
    if kind == "udp":
        kind = udp
    if kind not in KINDS:
        raise TransportError(f"bad endpoint {text!r}: unknown kind {kind!r} (expected {FORMS})")
    if kind not in allowed:
        raise TransportError(f"bad endpoint {text!r}: {kind} is not possible here (use {' or '.join(allowed)})")
    if rest.startswith("["):  # [IPv6]:PORT
        host, close, tail = rest[1:].partition("]")
        if not close or not tail.startswith(":"):
            raise TransportError(f"bad endpoint {text!r}: expected [IPv6 address]:PORT after {kind}:")
        port_text = tail[1:]
    else:
        host, colon, port_text = rest.rpartition(":")
        if not colon:
            raise TransportError(f"bad endpoint {text!r}: expected {kind}:HOST:PORT")
        if ":" in host:
            raise TransportError(f"bad endpoint {text!r}: write an IPv6 address in brackets, {kind}:[ADDR]:PORT")
    if not port_text.isdigit():
        raise TransportError(f"bad endpoint {text!r}: port {port_text!r} is not a number")
    port = int(port_text)
    lowest = 0 if kind in LISTENING else 1
    if not lowest <= port <= 65535:
        raise TransportError(f"bad endpoint {text!r}: port must be in {lowest}..65535")
    if not host:
        if kind not in LISTENING:
            raise TransportError(f"bad endpoint {text!r}: which host? ({kind}:HOST:PORT)")
        host = "0.0.0.0"
    if any(c.isspace() or c in "/@" for c in host):
        raise TransportError(f"bad endpoint {text!r}: {host!r} is not a host name or address")
    return Spec(kind, host, port)


@dataclass
class TransportStats:
    rx_packets: int = 0
    rx_bytes: int = 0
    tx_packets: int = 0
    tx_bytes: int = 0
    oversize: int = 0  # datagrams longer than the MTU, dropped
    unsent: int = 0  # nobody to send to yet (udpin before hearing anyone, tcpin without clients)
    errors: int = 0  # ICMP errors, failed sends, TCP clients too far behind

    def as_dict(self) -> dict[str, int]:
        return dict(vars(self))


def _os_reason(e: OSError) -> str:
    if isinstance(e, socket.gaierror):
        return f"cannot resolve the host name ({e.strerror or e})"
    if e.errno == errno.EADDRINUSE:
        return "address already in use"
    if e.errno == errno.EADDRNOTAVAIL:
        return "no such local address"
    if e.errno in (errno.EACCES, errno.EPERM):
        return "permission denied"
    if e.errno:
        return os.strerror(e.errno).lower()  # asyncio's own strerror texts are less clear
    return (e.strerror or str(e) or type(e).__name__).lower()


def addr_text(addr: object) -> str:
    """A peer's address as people write it (host:port, [v6]:port)."""
    if isinstance(addr, tuple) and len(addr) >= 2:
        host = str(addr[0])
        return f"[{host}]:{addr[1]}" if ":" in host else f"{host}:{addr[1]}"
    return str(addr)


Receive = Callable[[bytes, Hashable], None]


@dataclass
class Peer:
    """An address a udpin end answers: it sent a valid frame as one of `ids` at `last`."""

    addr: tuple[str, int]
    last: float
    ids: set[tuple[int, int]] = field(default_factory=set)


class Transport:
    """What the runtime and the relay see of a link to another process. `on_receive(data,
    source)` gets each datagram (UDP, source the sender's address) or chunk of the byte stream
    (TCP, source the connection); `on_close(source)` hears that a connection ended."""

    stream = False

    def __init__(self, spec: Spec, mtu: int, log: Callable[[str], None] | None = None) -> None:
        self.spec = spec
        self.mtu = mtu
        self.log = log
        self.stats = TransportStats()
        self.on_receive: Receive = lambda data, source: None
        self.on_close: Callable[[Hashable], None] = lambda source: None
        self.local = ""  # the address we are bound to, once open

    async def open(self) -> None:
        raise NotImplementedError

    def send(self, data: bytes) -> bool:
        raise NotImplementedError

    def close(self) -> None:
        raise NotImplementedError

    @property
    def peer(self) -> str | None:
        return None

    def confirm(self, source: Hashable, ids: set[tuple[int, int]]) -> None:
        """Valid frames from (sysid, compid) `ids` came from `source` (a listening UDP end
        answers only such sources)."""

    def describe(self) -> str:
        """The spec, with the port actually bound when it was 0."""
        if self.spec.listening and self.local:
            port = self.local.rsplit(":", 1)[1]
            return str(Spec(self.spec.kind, self.spec.host, int(port)))
        return str(self.spec)

    def _note(self, text: str) -> None:
        if self.log is not None:
            self.log(text)


class _Datagrams(asyncio.DatagramProtocol):
    def __init__(self, owner: UdpTransport) -> None:
        self.owner = owner

    def datagram_received(self, data: bytes, addr: tuple[str, int]) -> None:
        self.owner._received(data, addr)

    def error_received(self, exc: Exception) -> None:
        self.owner.stats.errors += 1  # e.g. ICMP port unreachable: nobody listens there (yet)


class UdpTransport(Transport):
    def __init__(self, spec: Spec, mtu: int = DTT_MTU, log: Callable[[str], None] | None = None) -> None:
        super().__init__(spec, mtu, log)
        self._tr: asyncio.DatagramTransport | None = None
        self.peers: OrderedDict[tuple[str, int], Peer] = OrderedDict()
        self.clock: Callable[[], float] = lambda: asyncio.get_running_loop().time()

    async def open(self) -> None:
        loop = asyncio.get_running_loop()
        s = self.spec
        try:
            if s.kind == "udpin":
                tr, _ = await loop.create_datagram_endpoint(lambda: _Datagrams(self), local_addr=(s.host, s.port))
            else:
                tr, _ = await loop.create_datagram_endpoint(lambda: _Datagrams(self), remote_addr=(s.host, s.port))
        except OSError as e:
            verb = "listen on" if s.kind == "udpin" else "send to"
            raise TransportError(f"cannot {verb} {s}: {_os_reason(e)}") from None
        self._tr = tr
        sock = tr.get_extra_info("socket")
        if sock is not None:
            for opt in (socket.SO_RCVBUF, socket.SO_SNDBUF):
                with contextlib.suppress(OSError):
                    sock.setsockopt(socket.SOL_SOCKET, opt, UDP_SOCKET_BUFFER)
        self.local = addr_text(tr.get_extra_info("sockname"))

    def _received(self, data: bytes, addr: tuple[str, int]) -> None:
        if len(data) > self.mtu:
            self.stats.oversize += 1  # DJI would refuse it: so do we
            return
        self.stats.rx_packets += 1
        self.stats.rx_bytes += len(data)
        self.on_receive(data, addr)

    def confirm(self, source: Hashable, ids: set[tuple[int, int]]) -> None:
        if self.spec.kind != "udpin" or not isinstance(source, tuple) or not ids:
            return
        now = self.clock()
        p = self.peers.get(source)
        if p is None:
            p = self.peers[source] = Peer(source, now)
            who = ", ".join(f"{s}/{c}" for s, c in sorted(ids))
            self._note(f"answering {addr_text(source)} ({who})")
            while len(self.peers) > MAX_PEERS:
                self.peers.popitem(last=False)
        else:
            self.peers.move_to_end(source)
        p.last = now
        p.ids |= ids

    def _live_peers(self) -> list[tuple[str, int]]:
        now = self.clock()
        return [a for a, p in self.peers.items() if now - p.last < PEER_TIMEOUT]

    @property
    def peer(self) -> str | None:
        if self.spec.kind == "udpin":
            live = self._live_peers()
            return ", ".join(addr_text(a) for a in live) or None
        return str(self.spec)

    def send(self, data: bytes) -> bool:
        return self._send(data, None)

    def send_to(self, data: bytes, source: Hashable) -> bool:
        """To one peer only: the address a datagram came from (udpin: if it is a live peer)."""
        return self._send(data, source)

    def _send(self, data: bytes, only: Hashable) -> bool:
        """To every live peer (udpin), or only to `only` if it is one; to the peer (udpout)."""
        tr = self._tr
        if tr is None or tr.is_closing():
            self.stats.unsent += 1
            return False
        if self.spec.kind == "udpin":
            to = [a for a in self._live_peers() if only is None or a == only]
            if not to:
                self.stats.unsent += 1
                return False
            for addr in to:
                tr.sendto(data, addr)
        else:
            tr.sendto(data)
        self.stats.tx_packets += 1
        self.stats.tx_bytes += len(data)
        return True

    def close(self) -> None:
        if self._tr is not None:
            self._tr.close()


class _Stream(asyncio.Protocol):
    def __init__(self, owner: TcpTransport) -> None:
        self.owner = owner
        self.tr: asyncio.Transport | None = None
        self.name = ""

    def connection_made(self, transport: asyncio.BaseTransport) -> None:
        assert isinstance(transport, asyncio.Transport)
        self.tr = transport
        self.name = addr_text(transport.get_extra_info("peername"))
        self.owner._connected(self)

    def data_received(self, data: bytes) -> None:
        self.owner.stats.rx_packets += 1
        self.owner.stats.rx_bytes += len(data)
        self.owner.on_receive(data, self)

    def connection_lost(self, exc: Exception | None) -> None:
        self.owner._lost(self)


class TcpTransport(Transport):
    stream = True

    def __init__(self, spec: Spec, mtu: int = STREAM_MTU, log: Callable[[str], None] | None = None,
                 connect_timeout: float = 5.0, reconnect: bool = True) -> None:
        super().__init__(spec, mtu, log)
        self.clients: list[_Stream] = []
        self._server: asyncio.Server | None = None
        self._closed = False
        self.connect_timeout = connect_timeout
        self.reconnect = reconnect
        self._reconnecting: asyncio.Task[None] | None = None

    async def open(self) -> None:
        loop = asyncio.get_running_loop()
        s = self.spec
        if s.kind == "tcpin":
            try:
                self._server = await loop.create_server(lambda: _Stream(self), s.host, s.port)
            except OSError as e:
                raise TransportError(f"cannot listen on {s}: {_os_reason(e)}") from None
            socks = self._server.sockets
            self.local = addr_text(socks[0].getsockname()) if socks else ""
            return
        await self._connect(loop)

    async def _connect(self, loop: asyncio.AbstractEventLoop) -> None:
        s = self.spec
        try:
            tr, _ = await asyncio.wait_for(loop.create_connection(lambda: _Stream(self), s.host, s.port),
                                           self.connect_timeout)
        except TimeoutError:
            raise TransportError(f"cannot connect to {s}: no answer within {self.connect_timeout:g} s") from None
        except OSError as e:
            raise TransportError(f"cannot connect to {s}: {_os_reason(e)}") from None
        self.local = addr_text(tr.get_extra_info("sockname"))

    def _connected(self, client: _Stream) -> None:
        self.clients.append(client)
        if self.spec.kind == "tcpin":
            self._note(f"connection from {client.name}")

    def _lost(self, client: _Stream) -> None:
        if client in self.clients:
            self.clients.remove(client)
        self.on_close(client)
        if self._closed:
            return
        self._note(f"connection {'from' if self.spec.kind == 'tcpin' else 'to'} {client.name} closed")
        if self.spec.kind == "tcp" and self.reconnect and self._reconnecting is None:
            self._reconnecting = asyncio.get_running_loop().create_task(self._redial())

    async def _redial(self) -> None:
        delay = 0.5
        loop = asyncio.get_running_loop()
        try:
            while not self._closed and not self.clients:
                await asyncio.sleep(delay)
                try:
                    await self._connect(loop)
                    self._note(f"reconnected to {self.spec}")
                except TransportError:
                    delay = min(delay * 2, 5.0)
        finally:
            self._reconnecting = None

    @property
    def peer(self) -> str | None:
        return ", ".join(c.name for c in self.clients) or None

    def send(self, data: bytes) -> bool:
        if not self.clients:
            self.stats.unsent += 1
            return False
        sent = False
        for c in self.clients:
            tr = c.tr
            if tr is None or tr.is_closing():
                continue
            if tr.get_write_buffer_size() > TCP_BUFFER_LIMIT:
                self.stats.errors += 1  # a reader this slow misses packets rather than stalling the link
                continue
            tr.write(data)
            sent = True
        if sent:
            self.stats.tx_packets += 1
            self.stats.tx_bytes += len(data)
        else:
            self.stats.unsent += 1
        return sent

    def close(self) -> None:
        self._closed = True
        if self._reconnecting is not None:
            self._reconnecting.cancel()
        if self._server is not None:
            self._server.close()
        for c in list(self.clients):
            if c.tr is not None:
                c.tr.close()


def make_transport(spec: Spec, log: Callable[[str], None] | None = None, mtu: int | None = None) -> Transport:
    """A transport for the spec (not open yet: `await t.open()`)."""
    if spec.udp:
        return UdpTransport(spec, mtu or DTT_MTU, log)
    return TcpTransport(spec, mtu or STREAM_MTU, log)


__all__ = ["DTT_MTU", "KINDS", "STREAM_MTU", "Peer", "Spec", "TcpTransport", "Transport", "TransportError",
           "TransportStats", "UdpTransport", "make_transport", "parse_spec"]
