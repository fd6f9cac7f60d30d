"""`ttctl bench serve`: the peer of `ttctl bench link --to` for measurements on a real link: the
probe protocol (ttctl.link.probes) on a UDP socket of its own. `ttctl emulate onboard` answers
the same probes on its DTT link (ttctl.link.probes.LinkProbes)."""

from __future__ import annotations

import asyncio
import contextlib
from collections.abc import Callable
from typing import Any

from ..link.probes import DEFAULT_LISTEN, PROBE_HDR, DownRun, Server, now_us, probe, send_down


class _Proto(asyncio.DatagramProtocol):
    def __init__(self, owner: Serve) -> None:
        self.owner = owner

    def datagram_received(self, data: bytes, addr: Any) -> None:
        self.owner.received(data, addr)

    def error_received(self, exc: Exception) -> None:
        pass  # an ICMP error from a client gone away


class Serve:
    """The server on a UDP socket."""

    def __init__(self, host: str, port: int, log: Callable[[str], None]) -> None:
        self.host, self.port, self.log = host, port, log
        self.tr: asyncio.DatagramTransport | None = None
        self.core = Server(start_down=self._start_down)
        self.tasks: set[asyncio.Task[None]] = set()

    async def open(self) -> str:
        loop = asyncio.get_running_loop()
        tr, _ = await loop.create_datagram_endpoint(lambda: _Proto(self), local_addr=(self.host, self.port))
        self.tr = tr
        name = tr.get_extra_info("sockname")
        return f"udpin:{name[0]}:{name[1]}"

    def received(self, data: bytes, addr: Any) -> None:
        t_rx = now_us()
        for reply in self.core.handle(data, t_rx, addr):
            self._send(reply, addr)

    def _send(self, data: bytes, addr: Any) -> None:
        if self.tr is not None and not self.tr.is_closing():
            self.tr.sendto(data, addr)

    def _start_down(self, run: int, job: DownRun, addr: Any) -> bool:
        if addr is None:
            return False
        self.log(f"downlink run {run}: {job.count} x {job.size} B at {job.rate_hz:g} Hz to {addr[0]}:{addr[1]}")
        task = asyncio.get_running_loop().create_task(self._send_down(run, job, addr))
        self.tasks.add(task)
        task.add_done_callback(self.tasks.discard)
        return True

    async def _send_down(self, run: int, job: DownRun, addr: Any) -> None:
        await send_down(self.core, run, job, lambda data: self._send(data, addr))

    def close(self) -> None:
        for t in list(self.tasks):
            t.cancel()
        if self.tr is not None:
            self.tr.close()


def serve(listen: str) -> int:
    """Run until SIGINT/SIGTERM; exit status 0."""
    import sys

    from ..commands.common import Signals, err
    from ..errors import Fail
    from ..link.transport import TransportError, _os_reason, parse_spec

    try:
        spec = parse_spec(listen, udp="udpin", allowed=("udpin",))
    except TransportError as e:
        raise Fail(f"{e} (bench serve speaks plain UDP datagrams)") from None

    async def main() -> None:
        loop = asyncio.get_running_loop()
        wake = asyncio.Event()
        sigs = Signals(loop, wake)
        s = Serve(spec.host, spec.port, lambda text: err(f"serve: {text}"))
        try:
            try:
                where = await s.open()
            except OSError as e:
                raise Fail(f"cannot listen on {spec}: {_os_reason(e)}") from None
            print(f"ttctl: serve: listening on {where}", file=sys.stderr, flush=True)
            await sigs.stop.wait()
            err(f"serve: stopped ({s.core.probes} probes counted, {s.core.ignored} datagrams ignored)")
        finally:
            s.close()
            sigs.remove()

    with contextlib.suppress(KeyboardInterrupt):
        asyncio.run(main())
    return 0


__all__ = ["DEFAULT_LISTEN", "PROBE_HDR", "Server", "now_us", "probe", "serve"]
