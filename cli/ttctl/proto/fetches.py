"""Downloads, sans-IO: a file this end asks for (Request), and the files it serves (Serving).

A request (TT_FILE_REQUEST) names a file; the serving end answers it by offering the file
(FileSender) with the request's id, or with NOT_FOUND / REQUEST_REFUSED and its words. A
request is repeated until an offer answers it, and again whenever the offered transfer goes
quiet as an upload's sender would find it quiet (transfer.quiet_after): a server that restarted
has forgotten the transfer, and serves the request anew. That is the upload's resume turned
round: the new offer carries the file's SHA-256 and size, so this end's receiver resumes its
partial file of that very file, and a different file under the name gets a partial of its own
(receiver.py), never the old bytes. A server still serving the request ignores the repeat.
"""

from __future__ import annotations

import os
import stat
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ..wire.bindings import Bindings
from ..wire.contract import TtFileResult as R
from .names import Refused, check_name, encoded
from .ranges import RangeSet
from .scheduler import CONTROL
from .storage import StorageError, kind_of
from .transfer import REQUEST_PART, TransferConfig, quiet_after, reason_fit

if TYPE_CHECKING:
    from .endpoint import Endpoint
    from .incoming import Incoming
    from .receiver import FileReceiver

SERVE_DEFLATE_MAX = 16 << 20  # served files up to this size may go deflated (deflating blocks this end meanwhile)
MAX_PARTIAL_REQUESTS = 64  # TT_FILE_REQUEST names still arriving, kept at once (the stalest goes first)
ASK_AGAIN_MAX = 2.0  # s: the longest wait between requests repeated for a quiet transfer


class Request:
    """A download we asked for."""

    def __init__(self, bindings: Bindings, request_id: int, name: str, target: tuple[int, int], now: float,
                 config: TransferConfig) -> None:
        self.b = bindings
        self.id = request_id
        self.name = name
        self.raw = encoded(name)
        self.target = target
        self.cfg = config
        self.due = now
        self.interval = config.offer_interval
        self.interval_max = config.offer_interval_max
        self.give_up = now + config.give_up_after
        self.reason_wait = config.reason_wait
        self.answered = False
        self.code: str | None = None  # NOT_FOUND, REQUEST_REFUSED, TIMEOUT when it failed
        self.error: str | None = None
        self.reason: str | None = None
        self._refusal: tuple[str, float] | None = None
        self.key: tuple[int, int, int] | None = None  # the transfer that answers it (the latest offer's)
        self.offers = 0  # transfers that answered it: more than one, the server served it anew
        self.rtt = 0.5
        self._first_ask: float | None = None
        self._asks = 0
        self.asked_again = 0  # requests repeated because the transfer went quiet
        self.unanswered = 0  # of those, since the last offer

    def messages(self) -> list[Any]:
        return [self.b.TtFileRequest(target_system=self.target[0], target_component=self.target[1],
                                     request_id=self.id, name_length=len(self.raw), name_offset=off,
                                     name=self.raw[off:off + REQUEST_PART])
                for off in range(0, len(self.raw), REQUEST_PART)]

    def answer(self, now: float, key: tuple[int, int, int]) -> None:
        """An offer with this request's id, from its target: that transfer answers it now."""
        if key == self.key:
            return
        if not self.answered and self._asks == 1 and self._first_ask is not None:
            self.rtt = min(5.0, max(0.02, now - self._first_ask))  # Karn: an unrepeated request only
        self.answered, self.key = True, key
        self.offers += 1
        self.unanswered = 0
        self.interval = self.cfg.offer_interval

    def control(self, now: float, receiver: FileReceiver) -> list[Any]:
        """The request's messages, when due: until an offer answers it (with backoff), and once
        answered, while the transfer it started has gone quiet (the server may have restarted)."""
        if self.code is not None:
            return []
        if not self.answered:
            if now < self.due:
                return []
            self._first_ask = now if self._first_ask is None else self._first_ask
            self._asks += 1
            self.due = now + self.interval
            self.interval = min(self.interval * 1.5, self.interval_max)
            return self.messages()
        t = self._running(receiver)
        if t is None or now < max(self.due, t.last_activity + self._quiet(receiver)):
            return []
        self.asked_again += 1
        self.unanswered += 1
        self.due = now + self.interval
        self.interval = min(self.interval * 1.5, ASK_AGAIN_MAX)
        return self.messages()

    def _running(self, receiver: FileReceiver) -> Incoming | None:
        """The transfer answering this request, while it runs (not complete, refused or failed:
        the caller hears of those; nor forgotten)."""
        t = receiver.transfers.get(self.key) if self.key is not None else None
        if t is None or t.finished_at is not None or t.result != R.TT_FILE_RESULT_IN_PROGRESS:
            return None
        return t

    def _quiet(self, receiver: FileReceiver) -> float:
        return quiet_after(self.cfg, self.rtt, receiver.grant, receiver.packet)

    def deadline(self, receiver: FileReceiver) -> float | None:
        if self.code is not None:
            return None
        if self._refusal is not None:
            return self._refusal[1] + self.reason_wait
        if not self.answered:
            return min(self.due, self.give_up) if self._refusal is None else self._refusal[1] + self.reason_wait
        t = self._running(receiver)
        return None if t is None else max(self.due, t.last_activity + self._quiet(receiver))


class _ServedRequest:
    def __init__(self, now: float) -> None:
        self.name = bytearray()
        self.have = RangeSet()
        self.length = 0
        self.last = now  # when a part last came


class Serving:
    """The files an endpoint serves from its `serve_dir`: requests assembled from their parts,
    answered with an offer (the endpoint's send_file) or a refusal in words."""

    def __init__(self, ep: Endpoint, serve_dir: str | None) -> None:
        self.ep = ep
        self.serve_dir = Path(serve_dir).resolve() if serve_dir else None
        self.partial: dict[tuple[int, int, int], _ServedRequest] = {}  # request names still arriving

    def on_request(self, now: float, msg: Any) -> None:
        if msg.request_id == 0:
            return
        ep = self.ep
        src = (msg.get_srcSystem(), msg.get_srcComponent())
        key = (src[0], src[1], msg.request_id)
        for s in ep.senders.values():
            if s.request_id == msg.request_id and s.target == src and not s.done:
                return  # already serving it: the offers repeat on their own
        part = self.partial.get(key)
        if part is None:
            if len(self.partial) >= MAX_PARTIAL_REQUESTS:
                # a flood of request names that never complete: the stalest goes (a real
                # requester's name is whole in one or two messages, and repeated until answered)
                del self.partial[min(self.partial, key=lambda k: self.partial[k].last)]
            part = self.partial[key] = _ServedRequest(now)
        part.last = now
        if not part.length:
            part.length = msg.name_length
            part.name = bytearray(msg.name_length)
        off = msg.name_offset
        chunk = bytes(msg.name[: max(0, min(len(msg.name), part.length - off))])
        part.name[off:off + len(chunk)] = chunk
        part.have.add(off, off + len(chunk))
        if not part.length or not part.have.covers(0, part.length):
            return
        del self.partial[key]
        try:
            path, name = self.servable(bytes(part.name))
            try:
                small = os.stat(path).st_size <= SERVE_DEFLATE_MAX
            except OSError:
                small = False  # opening it says what is wrong
            ep.send_file(path, src, name=name, request_id=msg.request_id, compress=ep.compress and small)
        except Refused as e:
            result = R.TT_FILE_RESULT_NOT_FOUND if e.code == "NOT_FOUND" else R.TT_FILE_RESULT_REQUEST_REFUSED
            self.refuse(src, msg.request_id, result, e.reason)
        except (StorageError, ValueError) as e:
            self.refuse(src, msg.request_id, R.TT_FILE_RESULT_REQUEST_REFUSED, str(e))

    def servable(self, raw: bytes) -> tuple[Path, str]:
        """The served file a request names, or Refused with the reason."""
        try:
            name = raw.decode("utf-8")
        except UnicodeDecodeError:
            raise Refused("REQUEST_REFUSED", "the name is not valid UTF-8") from None
        if self.serve_dir is None:
            raise Refused("REQUEST_REFUSED", "this end serves no files")
        try:
            check_name(name)
        except Refused as e:
            raise Refused("REQUEST_REFUSED", e.reason) from None
        path = (self.serve_dir / name).resolve()
        if self.serve_dir not in path.parents:
            raise Refused("REQUEST_REFUSED", f"{name} leads outside the served folder")
        try:
            st = os.stat(path)
        except (FileNotFoundError, NotADirectoryError):
            raise Refused("NOT_FOUND", f"there is no {name} in the served folder") from None
        except OSError as e:
            raise Refused("REQUEST_REFUSED", f"{name}: {e.strerror or e}") from None
        if not stat.S_ISREG(st.st_mode):
            raise Refused("REQUEST_REFUSED", f"{name} is {kind_of(st.st_mode)}, not a file")
        return path, name

    def refuse(self, src: tuple[int, int], request_id: int, result: R, reason: str) -> None:
        b, enc, send = self.ep.b, self.ep.encoder.encode, self.ep.scheduler.send
        why = b.TtFileReason(target_system=src[0], target_component=src[1], transfer_id=request_id,
                             result=int(result), text=reason_fit(reason))
        status = b.TtFileStatus(target_system=src[0], target_component=src[1], transfer_id=request_id,
                                result=int(result))
        send(enc(why), CONTROL, key=("request-reason", src, request_id))
        send(enc(status), CONTROL, key=("request-status", src, request_id))


__all__ = ["MAX_PARTIAL_REQUESTS", "SERVE_DEFLATE_MAX", "Request", "Serving"]
