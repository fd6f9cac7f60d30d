"""One end of the link, sans-IO: packets and the time in; packets to send, and when to wake up,
out. It owns the packet receiver, the packet scheduler, file transfers (both directions,
several at once), downloads on request, and commands.

Drive it with `receive(now, packet)`, `poll(now)` (the next packet to send, if the pacer lets
one go) and `wakeup()`; the virtual-time simulator and the asyncio transport both do.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable
from pathlib import Path
from typing import Any

import ttapi
from ttapi import TtFileResult as R

from ..wire.packets import PacketReceiver
from .commands import Command, CommandClient, CommandServer
from .ranges import RangeSet
from .scheduler import BULK, CONTROL, TELEMETRY, Scheduler
from .storage import FileSource, ReceiveDir, Refused, StorageError, check_name
from .transfer import NARROW, WIDE, FileReceiver, FileSender, TransferConfig

TARGETED = "target_system"
STATUS_BYTES = 60  # typical TT_FILE_STATUS frame
REQUEST_PART = 80


class _Request:
    """A download we asked for."""

    def __init__(self, request_id: int, name: str, target: tuple[int, int], now: float,
                 config: TransferConfig) -> None:
        self.id = request_id
        self.name = name
        self.raw = name.encode("utf-8")
        self.target = target
        self.due = now
        self.interval = config.offer_interval
        self.interval_max = config.offer_interval_max
        self.give_up = now + config.give_up_after
        self.answered = False
        self.error: str | None = None
        self.key: tuple[int, int, int] | None = None

    def messages(self) -> list[ttapi.Message]:
        return [ttapi.TtFileRequest(target_system=self.target[0], target_component=self.target[1],
                                    request_id=self.id, name_length=len(self.raw), name_offset=off,
                                    name=self.raw[off:off + REQUEST_PART])
                for off in range(0, len(self.raw), REQUEST_PART)]


class _ServedRequest:
    def __init__(self) -> None:
        self.name = bytearray()
        self.have = RangeSet()
        self.length = 0


class Endpoint:
    def __init__(self, sysid: int, compid: int, *, mtu: int = 100, rate_Bps: float | None = None,
                 receive_dir: ReceiveDir | None = None, serve_dir: str | None = None,
                 config: TransferConfig | None = None, signing: ttapi.Signing | None = None,
                 action: Callable[[ttapi.TtActionCommand], int] | None = None,
                 on_message: Callable[[float, Any], None] | None = None,
                 on_event: Callable[[str, Any], None] | None = None, accept_commands: bool = True) -> None:
        self.sysid = sysid
        self.compid = compid
        self.cfg = config or TransferConfig()
        self.encoder = ttapi.Encoder(sysid, compid, signing)
        self.rx = PacketReceiver(signing=signing)
        self.stream_rx = ttapi.Parser(signing=signing)  # for byte-stream links (TCP): no packet boundaries
        self.scheduler = Scheduler(mtu, rate_Bps)
        self.receiver = (FileReceiver(receive_dir, sysid, compid, self.cfg, on_event=self._file_event)
                         if receive_dir is not None else None)
        if self.receiver is not None and rate_Bps:
            # statuses go back over our own link: on a slow one, fewer of them
            self.receiver.cfg = TransferConfig(**{
                **vars(self.cfg),
                # a status with a few gaps is about 50 bytes on the wire (its ranges truncate)
                "status_min_interval": max(self.cfg.status_min_interval, 3 * STATUS_BYTES / rate_Bps),
                "status_tail_interval": max(self.cfg.status_tail_interval, 1.2 * STATUS_BYTES / rate_Bps)})
        self.serve_dir = Path(serve_dir).resolve() if serve_dir else None
        self.senders: dict[int, FileSender] = {}
        self.requests: dict[int, _Request] = {}
        self._served: dict[tuple[int, int, int], _ServedRequest] = {}
        self.commands = CommandClient(sysid, compid)
        self.server = CommandServer(sysid, compid, action) if accept_commands else None
        self.on_message = on_message
        self.on_event = on_event
        self._ids = itertools.cycle(range(1, 256))
        self._req_ids = itertools.cycle(range(1, 256))
        self.now = 0.0
        self.ignored = 0
        self.peers: dict[tuple[int, int], float] = {}  # who we heard from, when

    # -- node interface -----------------------------------------------------------------------
    def receive(self, now: float, packet: bytes) -> None:
        self.now = now
        for msg in self.rx.feed(packet):
            self._handle(now, msg)

    def receive_stream(self, now: float, data: bytes) -> None:
        """Bytes from a stream link (TCP), where chunk boundaries mean nothing."""
        self.now = now
        for msg in self.stream_rx.feed(data):
            self._handle(now, msg)

    def flush(self, now: float) -> None:
        """The link has been quiet: give up on half-received long frames."""
        for msg in self.rx.flush() + self.stream_rx.flush():
            self._handle(now, msg)

    def poll(self, now: float) -> bytes | None:
        self.now = now
        self._tick(now)
        return self.scheduler.next_packet(now)

    def wakeup(self) -> float | None:
        times = [t for t in (self.commands.deadline(),
                             self.receiver.deadline() if self.receiver else None) if t is not None]
        times += [t for s in self.senders.values() if (t := s.deadline(self.now)) is not None]
        times += [r.due for r in self.requests.values() if not r.answered]
        if self.scheduler.busy or any(s.has_data(self.now) for s in self.senders.values()):
            times.append(self.scheduler.ready_at())
        return min(times) if times else None

    # -- what the user asks for ------------------------------------------------------------------
    def send_message(self, msg: ttapi.Message, priority: int = TELEMETRY) -> None:
        self.scheduler.send(self.encoder.encode(msg), priority)

    def send_file(self, path: str | Path, target: tuple[int, int], name: str | None = None,
                  overwrite: bool = False, request_id: int = 0,
                  on_progress: Callable[[FileSender], None] | None = None, source: Any = None) -> FileSender:
        src = source if source is not None else FileSource(path)
        tid = self._free_id()
        sender = FileSender(tid, src, name or Path(path).name, target, self.cfg, request_id, overwrite, self.now,
                            on_progress)
        rate = self.scheduler.pacer.rate
        sender.byte_time = 1.0 / rate if rate else 0.0
        self.senders[tid] = sender
        self.scheduler.add_source(self._puller(sender))
        return sender

    def request_file(self, name: str, target: tuple[int, int]) -> _Request:
        raw = name.encode("utf-8")
        if not raw or len(raw) > 255:
            raise ValueError("file names must be 1..255 bytes of UTF-8")
        if self.receiver is None:
            raise ValueError("this end has no receive directory")
        rid = next(self._req_ids)
        req = _Request(rid, name, target, self.now, self.cfg)
        self.requests[rid] = req
        self.receiver.expected_requests[(target[0], target[1], rid)] = name
        return req

    def command(self, msg: ttapi.TtActionCommand, target: tuple[int, int], retries: int = 3,
                timeout: float = 1.5, on_success: Callable[[Command], None] | None = None,
                on_failure: Callable[[Command], None] | None = None) -> Command:
        return self.commands.submit(Command(msg, target, retries, timeout, on_success, on_failure), self.now)

    def close(self) -> None:
        if self.receiver is not None:
            self.receiver.close()

    # -- internals ------------------------------------------------------------------------------
    def _free_id(self) -> int:
        for _ in range(255):
            tid = next(self._ids)
            s = self.senders.get(tid)
            if s is None or s.done:
                if s is not None:
                    self._retire(s)
                return tid
        raise RuntimeError("255 transfers are running: no free transfer id")

    def _retire(self, s: FileSender) -> None:
        self.senders.pop(s.id, None)
        self.scheduler.remove_source(getattr(s, "_pull", None))  # type: ignore[arg-type]

    def _puller(self, sender: FileSender) -> Callable[[float, int], bytes | None]:
        def pull(now: float, space: int) -> bytes | None:
            msg = sender.next_data(now, space)
            return None if msg is None else self.encoder.encode(msg)

        sender._pull = pull  # type: ignore[attr-defined]
        return pull

    def _tick(self, now: float) -> None:
        send = self.scheduler.send
        enc = self.encoder.encode
        for msg in self.commands.control(now):
            send(enc(msg), CONTROL)
        if self.receiver is not None:
            for msg, key in self.receiver.control(now):
                send(enc(msg), CONTROL, key=key)
        for s in list(self.senders.values()):
            for msg in s.control(now):
                send(enc(msg), CONTROL)
            if s.done and s.id in self.senders and now - (s.stats.finished or now) > 30:
                self._retire(s)
        for req in self.requests.values():
            if req.answered:
                continue
            if now >= req.give_up:
                req.answered, req.error = True, f"no answer to the request for {req.name}"
                self._event("request-failed", req)
                continue
            if now >= req.due:
                for msg in req.messages():
                    send(enc(msg), CONTROL)
                req.due = now + req.interval
                req.interval = min(req.interval * 1.5, req.interval_max)

    def _event(self, what: str, obj: Any) -> None:
        if self.on_event is not None:
            self.on_event(what, obj)

    def _file_event(self, what: str, incoming: Any) -> None:
        self._event(f"file-{what}", incoming)

    def _for_us(self, msg: Any) -> bool:
        if hasattr(msg, TARGETED):
            ts = msg.target_system
            if ts not in (0, self.sysid):
                return False
            tc = getattr(msg, "target_component", 0)
            if tc not in (0, self.compid):
                return False
        return True

    def _handle(self, now: float, msg: Any) -> None:
        self.peers[(msg.get_srcSystem(), msg.get_srcComponent())] = now
        if (msg.get_srcSystem(), msg.get_srcComponent()) == (self.sysid, self.compid):
            return  # our own frames, echoed
        if isinstance(msg, (ttapi.TtFileData, ttapi.TtFileDataWide)):
            if self.receiver is not None:
                self.receiver.on_data(now, msg, WIDE if isinstance(msg, ttapi.TtFileDataWide) else NARROW)
            return
        if not self._for_us(msg):
            self.ignored += 1
            return
        if isinstance(msg, ttapi.TtFileOffer):
            self._on_offer(now, msg)
        elif isinstance(msg, ttapi.TtFileStatus):
            self._on_status(now, msg)
        elif isinstance(msg, ttapi.TtFileRequest):
            self._on_request(now, msg)
        elif isinstance(msg, ttapi.TtCommandAck):
            self.commands.on_ack(now, msg)
        elif isinstance(msg, ttapi.TtActionCommand) and self.server is not None:
            ack = self.server.on_command(msg)
            if ack is not None:
                self.scheduler.send(self.encoder.encode(ack), CONTROL)
        if self.on_message is not None:
            self.on_message(now, msg)

    def _on_offer(self, now: float, msg: ttapi.TtFileOffer) -> None:
        if self.receiver is None:
            self.ignored += 1
            return
        src = (msg.get_srcSystem(), msg.get_srcComponent())
        if msg.request_id:
            req = self.requests.get(msg.request_id)
            if req is not None and req.target[0] == src[0]:
                req.answered = True
                req.key = (src[0], src[1], msg.transfer_id)
        self.receiver.on_offer(now, msg)

    def _on_status(self, now: float, msg: ttapi.TtFileStatus) -> None:
        src = (msg.get_srcSystem(), msg.get_srcComponent())
        if msg.result in (R.TT_FILE_RESULT_NOT_FOUND, R.TT_FILE_RESULT_REQUEST_REFUSED):
            req = self.requests.get(msg.transfer_id)
            if req is not None and req.target[0] == src[0] and not req.answered:
                req.answered = True
                req.error = ("no such file there" if msg.result == R.TT_FILE_RESULT_NOT_FOUND
                             else "the peer does not serve that file")
                self._event("request-failed", req)
            return
        sender = self.senders.get(msg.transfer_id)
        if sender is not None and sender.target[0] == src[0]:
            sender.on_status(now, msg)

    def _on_request(self, now: float, msg: ttapi.TtFileRequest) -> None:
        src = (msg.get_srcSystem(), msg.get_srcComponent())
        key = (src[0], src[1], msg.request_id)
        for s in self.senders.values():
            if s.request_id == msg.request_id and s.target == src and not s.done:
                s.control(now)  # already serving it: the offers repeat on their own
                return
        part = self._served.setdefault(key, _ServedRequest())
        if not part.length:
            part.length = msg.name_length
            part.name = bytearray(msg.name_length)
        off = msg.name_offset
        chunk = bytes(msg.name[: max(0, min(len(msg.name), part.length - off))])
        part.name[off:off + len(chunk)] = chunk
        part.have.add(off, off + len(chunk))
        if not part.length or not part.have.covers(0, part.length):
            return
        del self._served[key]
        refuse = R.TT_FILE_RESULT_REQUEST_REFUSED
        try:
            name = bytes(part.name).decode("utf-8")
            if self.serve_dir is None:
                raise Refused("NAME", "this end serves no files")
            check_name(name, 255)
            path = (self.serve_dir / name).resolve()
            if self.serve_dir not in path.parents:
                raise Refused("NAME", "outside the served directory")
            if not path.is_file():
                refuse = R.TT_FILE_RESULT_NOT_FOUND
                raise Refused("NOT_FOUND", "no such file")
            self.send_file(path, src, name=name, request_id=msg.request_id)
        except (UnicodeDecodeError, Refused, StorageError, ValueError):
            status = ttapi.TtFileStatus(target_system=src[0], target_component=src[1], transfer_id=msg.request_id,
                                        result=int(refuse))
            self.scheduler.send(self.encoder.encode(status), CONTROL)


__all__ = ["BULK", "CONTROL", "TELEMETRY", "Endpoint"]
