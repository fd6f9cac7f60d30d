"""MAVLink FTP (FILE_TRANSFER_PROTOCOL, message 110) as PX4 serves it, sans-IO, over a small tree:

    /serve/...   the --serve folder, read-only (what the tablet may fetch)
    /inbox/...   the --inbox folder, readable and writable (where received files go)

`FtpServer.request(now, payload, peer)` takes a request's 251-byte payload and returns the reply
payloads; a burst read streams its data from `tick(now)` a few packets at a time (as PX4 paces its
bursts), `wakeup()` saying when. The payload is PX4's: a 12-byte header (seq, session, opcode,
size, req_opcode, burst_complete, padding, offset) and up to 239 bytes of data; a reply carries
the request's seq + 1, ACK (128) or NAK (129) with the error code (and errno for FailErrno).

Names follow the inbox's jail rules (ttctl.proto.names, storage.ReceiveDir): no `..`, `.`,
empty or backslashed component, nothing through a symbolic link leading out, the receiver's
`.ttctl-partial` folder neither listed nor reachable. A file written over FTP goes to a partial
file and appears under its name only when its session ends (TerminateSession), so nothing reads
it half-written; replacing an existing file is allowed, as PX4's CreateFile truncates. Quotas
are the inbox's (per file and for the whole folder): a write beyond them is refused with
FailErrno EFBIG or ENOSPC.
"""

from __future__ import annotations

import contextlib
import errno
import os
import stat
import struct
import zlib
from collections import OrderedDict
from collections.abc import Hashable
from dataclasses import dataclass, field
from pathlib import Path

from ...proto.names import PARTIAL_DIR, check_name
from ...proto.names import Refused as NameRefused
from ...proto.storage import ReceiveDir, StorageError

PAYLOAD = 251
HEADER = struct.Struct("<HBBBBBBI")  # seq, session, opcode, size, req_opcode, burst_complete, padding, offset
DATA = PAYLOAD - HEADER.size  # 239

# opcodes
NONE, TERMINATE, RESET, LIST, OPEN_RO, READ, CREATE, WRITE, REMOVE, MKDIR, RMDIR, OPEN_WO, TRUNCATE, RENAME, \
    CRC32, BURST = range(16)
ACK, NAK = 128, 129
# errors
FAIL, FAIL_ERRNO, INVALID_SIZE, INVALID_SESSION, NO_SESSIONS, EOF, UNKNOWN, EXISTS, PROTECTED, NOT_FOUND = range(1, 11)

MAX_SESSIONS = 4
SESSION_IDLE = 30.0  # s without a request: the session is closed (a write in it discarded)
BURST_PACKETS = 8  # per tick
BURST_PERIOD = 0.005  # s between ticks of a burst
CACHE = 16  # replies remembered for a client's retry with the same seq
CRC_STEP = 4 << 20  # bytes of a file's CRC32 computed per tick: a big file does not stall the vehicle
MAX_CRC_JOBS = 2
LISTING_KEEP = 10.0  # s a folder's listing is kept for the pages after its first


class FtpError(Exception):
    def __init__(self, code: int, err: int = 0) -> None:
        super().__init__(code)
        self.code = code
        self.errno = err


def _oserror(e: OSError) -> FtpError:
    if isinstance(e, FileNotFoundError):
        return FtpError(NOT_FOUND)
    return FtpError(FAIL_ERRNO, (e.errno or errno.EIO) & 0xFF)


@dataclass
class Session:
    fd: int
    peer: Hashable
    writable: bool
    last: float
    final: Path | None = None  # a write: where the partial file goes when the session ends
    partial: Path | None = None
    size: int = 0  # a read: the file's size when opened
    base_usage: int = 0  # a write: the inbox's usage without this file
    burst: tuple[int, int, int] | None = None  # next offset, packet size, next seq


@dataclass
class CrcJob:
    """The CRC32 of a file too big to compute in one go, a step per tick."""

    fd: int
    size: int
    peer: Hashable
    head: tuple[int, int, int, int]
    done: int = 0
    crc: int = 0


def crc32(data: bytes, crc: int = 0) -> int:
    """PX4's and ArduPilot's CRC32: the reflected table from a zero seed, no final inversion."""
    return zlib.crc32(data, crc ^ 0xFFFFFFFF) ^ 0xFFFFFFFF


@dataclass
class FtpServer:
    serve: Path | None = None
    inbox: ReceiveDir | None = None
    sessions: dict[int, Session] = field(default_factory=dict)
    now: float = 0.0
    _cache: OrderedDict[tuple[Hashable, int, int, int], list[bytes]] = field(default_factory=OrderedDict)
    _jobs: dict[tuple[Hashable, int, int, int], CrcJob] = field(default_factory=dict)
    _listing: tuple[tuple[str, str], float, list[bytes]] | None = None

    # -- in -----------------------------------------------------------------------------------
    def request(self, now: float, payload: bytes, peer: Hashable) -> list[bytes]:
        self.now = now
        payload = bytes(payload[:PAYLOAD]).ljust(PAYLOAD, b"\0")
        seq, session, opcode, size, _, _, _, offset = HEADER.unpack_from(payload)
        key = (peer, seq, opcode, session)
        if opcode != BURST and key in self._cache:
            return self._cache[key]  # a retry: the same answer again (MAVLink FTP: re-send the response)
        if key in self._jobs:
            return []  # a retry of a CRC32 under way: its answer comes when it is done
        head = (seq, session, opcode, offset)
        try:
            if size > DATA:
                raise FtpError(INVALID_SIZE)
            data = payload[HEADER.size:HEADER.size + size]
            if opcode == CRC32:
                replies = self._crc32(self._path(data), key, head)
            else:
                replies = self._work(opcode, session, offset, data, peer, head, size or DATA)
        except FtpError as e:
            body = bytes([e.code, e.errno]) if e.code == FAIL_ERRNO else bytes([e.code])
            replies = [self._reply(head, NAK, body)]
        if opcode != BURST and replies:
            self._remember(key, replies)
        return replies

    def _remember(self, key: tuple[Hashable, int, int, int], replies: list[bytes]) -> None:
        self._cache[key] = replies
        while len(self._cache) > CACHE:
            self._cache.popitem(last=False)

    @staticmethod
    def _reply(head: tuple[int, int, int, int], opcode: int, data: bytes = b"", session: int | None = None,
               offset: int | None = None, seq: int | None = None, burst_complete: int = 0) -> bytes:
        rseq, rsession, req, roffset = head
        h = HEADER.pack((rseq + 1 if seq is None else seq) & 0xFFFF, rsession if session is None else session,
                        opcode, len(data), req, burst_complete, 0, roffset if offset is None else offset)
        return (h + data).ljust(PAYLOAD, b"\0")

    def _work(self, opcode: int, sid: int, offset: int, data: bytes, peer: Hashable,
              head: tuple[int, int, int, int], want: int) -> list[bytes]:
        """`want`: the bytes a read asks for (its size field; 0 means as many as fit)."""
        if opcode == NONE:
            return [self._reply(head, ACK)]
        if opcode == TERMINATE:
            session = self._session(sid)
            del self.sessions[sid]  # ended even if its file cannot be put in place (the NAK says why)
            self._close(session, keep=True)
            return [self._reply(head, ACK)]
        if opcode == RESET:
            for s in [s for s in self.sessions.values() if s.peer == peer]:
                self._close(s, keep=False)
            self.sessions = {k: s for k, s in self.sessions.items() if s.peer != peer}
            return [self._reply(head, ACK)]
        if opcode == LIST:
            return [self._list(self._path(data), offset, head)]
        if opcode == OPEN_RO:
            opened, size = self._open_read(self._path(data), peer, sid)
            return [self._reply(head, ACK, struct.pack("<I", min(size, 0xFFFFFFFF)), session=opened)]
        if opcode == READ:
            s = self._session(sid)
            if s.writable:
                raise FtpError(FAIL)
            chunk = self._pread(s, offset, offset + want)
            return [self._reply(head, ACK, chunk)]
        if opcode in (CREATE, OPEN_WO):
            return [self._reply(head, ACK, session=self._open_write(self._path(data), peer, opcode == OPEN_WO, sid))]
        if opcode == WRITE:
            self._write(self._session(sid), offset, data)
            return [self._reply(head, ACK)]
        if opcode == BURST:
            s = self._session(sid)
            if s.writable:
                raise FtpError(FAIL)
            if offset >= s.size:
                return [self._reply(head, NAK, bytes([EOF]), burst_complete=1)]
            s.burst = (offset, want, head[0] + 1)
            return []
        if opcode == REMOVE:
            self._remove(self._path(data))
            return [self._reply(head, ACK)]
        if opcode == MKDIR:
            self._mkdir(self._path(data))
            return [self._reply(head, ACK)]
        if opcode == RMDIR:
            self._rmdir(self._path(data))
            return [self._reply(head, ACK)]
        if opcode == TRUNCATE:
            self._truncate(self._path(data), offset)
            return [self._reply(head, ACK)]
        if opcode == RENAME:
            old, _, new = data.partition(b"\0")
            self._rename(self._path(old), self._path(new))
            return [self._reply(head, ACK)]
        raise FtpError(UNKNOWN)

    # -- names --------------------------------------------------------------------------------
    def _path(self, raw: bytes) -> tuple[str, str]:
        """(area, name) for a path: area '' (the root), 'serve' or 'inbox'; name '' for the
        area itself. FtpError PROTECTED for a name the jail refuses, NOT_FOUND for one that
        names nothing here."""
        raw = raw.split(b"\0", 1)[0]
        try:
            text = raw.decode("utf-8")
        except UnicodeDecodeError:
            raise FtpError(PROTECTED) from None
        text = text.strip("/")
        if not text or text == ".":
            return "", ""
        area, _, name = text.partition("/")
        if area not in ("serve", "inbox"):
            raise FtpError(NOT_FOUND)
        if (area == "serve" and self.serve is None) or (area == "inbox" and self.inbox is None):
            raise FtpError(NOT_FOUND)
        if name:
            try:
                check_name(name)
            except NameRefused:
                raise FtpError(PROTECTED) from None
        return area, name

    def _real(self, where: tuple[str, str]) -> Path:
        """The file system path of (area, name), which must stay inside the area's folder."""
        area, name = where
        if area == "inbox":
            assert self.inbox is not None
            try:
                return self.inbox.final_path(name) if name else self.inbox.root.resolve()
            except NameRefused:
                raise FtpError(PROTECTED) from None
        if area == "serve":
            assert self.serve is not None
            root = self.serve.resolve()
            path = (root / name).resolve()
            if path != root and root not in path.parents:
                raise FtpError(PROTECTED)
            return path
        raise FtpError(NOT_FOUND)

    def _writable(self, where: tuple[str, str]) -> Path:
        area, name = where
        if area != "inbox" or not name:
            raise FtpError(PROTECTED)  # the root, /serve and /inbox itself are not to be changed
        assert self.inbox is not None
        try:
            self.inbox.check_parents(name)
        except NameRefused:
            raise FtpError(FAIL_ERRNO, errno.ENOTDIR) from None
        return self._real(where)

    # -- listing and reading ------------------------------------------------------------------
    def _entries(self, where: tuple[str, str]) -> list[bytes]:
        area, name = where
        if not area:
            return [b"D" + a.encode() for a, root in (("inbox", self.inbox), ("serve", self.serve)) if root is not None]
        path = self._real(where)
        try:
            names = sorted(os.listdir(path))
        except OSError as e:
            raise _oserror(e) from None
        out = []
        for n in names:
            if area == "inbox" and not name and n == PARTIAL_DIR:
                continue
            try:
                check_name(n)
                st = os.stat(path / n)
                self._real((area, f"{name}/{n}" if name else n))
            except (NameRefused, OSError, FtpError):
                continue  # not a name served here, or leading out of the folder
            if stat.S_ISDIR(st.st_mode):
                entry = b"D" + n.encode()
            elif stat.S_ISREG(st.st_mode):
                entry = b"F" + n.encode() + b"\t" + str(st.st_size).encode()
            else:
                continue
            if len(entry) + 1 <= DATA:
                out.append(entry)
        return out

    def _list(self, where: tuple[str, str], offset: int, head: tuple[int, int, int, int]) -> bytes:
        """One page of a listing. The pages after the first come from the listing the first one
        read (for LISTING_KEEP seconds), so a big folder is read once, not once a page."""
        kept = self._listing
        if offset > 0 and kept is not None and kept[0] == where and self.now - kept[1] < LISTING_KEEP:
            entries = kept[2]
        else:
            entries = self._entries(where)
            self._listing = (where, self.now, entries)
        if offset >= len(entries):
            raise FtpError(EOF)
        data = b""
        for entry in entries[offset:]:
            if len(data) + len(entry) + 1 > DATA:
                break
            data += entry + b"\0"
        return self._reply(head, ACK, data)

    def _new_session(self, wanted: int) -> int:
        """The session id the client put in its open request (ArduPilot's rule, which MAVProxy
        routes replies by; PX4's clients, MAVSDK among them, take whatever id comes back)."""
        self._expire()
        if wanted in self.sessions:
            raise FtpError(FAIL)  # already open: a client reusing an id it has not terminated
        if len(self.sessions) >= MAX_SESSIONS:
            raise FtpError(NO_SESSIONS)
        return wanted

    def _open_regular(self, where: tuple[str, str]) -> tuple[int, os.stat_result]:
        """A descriptor on a regular file to read (never blocking on a FIFO), and its stat."""
        path = self._real(where)
        try:
            fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_CLOEXEC)
        except OSError as e:
            raise _oserror(e) from None
        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode):
            os.close(fd)
            raise FtpError(FAIL_ERRNO, errno.EISDIR if stat.S_ISDIR(st.st_mode) else errno.EINVAL)
        return fd, st

    def _open_read(self, where: tuple[str, str], peer: Hashable, wanted: int) -> tuple[int, int]:
        if not where[1]:
            raise FtpError(FAIL_ERRNO, errno.EISDIR)
        sid = self._new_session(wanted)
        fd, st = self._open_regular(where)
        self.sessions[sid] = Session(fd, peer, writable=False, last=self.now, size=st.st_size)
        return sid, st.st_size

    def _pread(self, s: Session, offset: int, end: int) -> bytes:
        s.last = self.now
        if offset >= s.size:
            raise FtpError(EOF)
        try:
            return os.pread(s.fd, min(end, s.size) - offset, offset)
        except OSError as e:
            raise _oserror(e) from None

    def _crc32(self, where: tuple[str, str], key: tuple[Hashable, int, int, int],
               head: tuple[int, int, int, int]) -> list[bytes]:
        """The file's CRC32 now, or, for a file over CRC_STEP bytes, from tick() when computed."""
        if not where[1]:
            raise FtpError(FAIL_ERRNO, errno.EISDIR)
        fd, st = self._open_regular(where)
        job = CrcJob(fd, st.st_size, key[0], head)
        if st.st_size > CRC_STEP:
            if len(self._jobs) >= MAX_CRC_JOBS:
                os.close(fd)
                raise FtpError(FAIL_ERRNO, errno.EBUSY)
            self._jobs[key] = job
            return []
        return [self._crc_step(job)]

    def _crc_step(self, job: CrcJob) -> bytes:
        """One step of the job; its reply once it is done (ACK with the CRC, or NAK)."""
        err: FtpError | None = None
        try:
            chunk = os.pread(job.fd, min(CRC_STEP, job.size - job.done), job.done)
        except OSError as e:
            chunk, err = b"", _oserror(e)
        if not chunk and job.done < job.size and err is None:
            err = FtpError(FAIL_ERRNO, errno.EIO)  # the file shrank while its CRC was computed
        job.crc, job.done = crc32(chunk, job.crc), job.done + len(chunk)
        if err is None and job.done < job.size:
            return b""
        os.close(job.fd)
        if err is not None:
            return self._reply(job.head, NAK, bytes([err.code, err.errno]))
        return self._reply(job.head, ACK, struct.pack("<I", job.crc))

    # -- writing ------------------------------------------------------------------------------
    def _open_write(self, where: tuple[str, str], peer: Hashable, existing: bool, wanted: int) -> int:
        final = self._writable(where)
        if final.is_dir():
            raise FtpError(FAIL_ERRNO, errno.EISDIR)
        if existing and not final.is_file():
            raise FtpError(NOT_FOUND)
        if not final.parent.is_dir():
            raise FtpError(FAIL_ERRNO, errno.ENOENT)
        sid = self._new_session(wanted)
        assert self.inbox is not None
        try:
            self.inbox.make_partial_dir()
        except StorageError:
            raise FtpError(FAIL_ERRNO, errno.EACCES) from None
        partial = self.inbox.partial_dir / f"ftp-{os.getpid()}-{sid}.part"
        try:
            fd = os.open(partial, os.O_RDWR | os.O_CREAT | os.O_TRUNC | os.O_CLOEXEC, 0o644)
            if existing:
                with open(final, "rb") as src:
                    while chunk := src.read(1 << 16):
                        os.write(fd, chunk)
        except OSError as e:
            with contextlib.suppress(OSError):
                partial.unlink()
            raise _oserror(e) from None
        usage = self.inbox.usage() - os.fstat(fd).st_size
        self.sessions[sid] = Session(fd, peer, writable=True, last=self.now, final=final, partial=partial,
                                     base_usage=usage)
        return sid

    def _write(self, s: Session, offset: int, data: bytes) -> None:
        if not s.writable:
            raise FtpError(FAIL)
        s.last = self.now
        assert self.inbox is not None
        q = self.inbox.quota
        end = offset + len(data)
        if end > q.max_file_bytes:
            raise FtpError(FAIL_ERRNO, errno.EFBIG)
        size = os.fstat(s.fd).st_size
        if s.base_usage + max(size, end) > q.max_dir_bytes:
            raise FtpError(FAIL_ERRNO, errno.ENOSPC)
        try:
            os.pwrite(s.fd, data, offset)
        except OSError as e:
            raise _oserror(e) from None

    def _close(self, s: Session, keep: bool) -> None:
        with contextlib.suppress(OSError):
            os.close(s.fd)
        if s.partial is None or s.final is None:
            return
        try:
            if keep:
                if s.final.is_dir():
                    raise FtpError(FAIL_ERRNO, errno.EISDIR)
                os.replace(s.partial, s.final)
        except OSError as e:
            raise _oserror(e) from None
        finally:
            with contextlib.suppress(OSError):
                s.partial.unlink()

    def _remove(self, where: tuple[str, str]) -> None:
        path = self._writable(where)
        try:
            if path.is_dir():
                raise FtpError(FAIL_ERRNO, errno.EISDIR)
            path.unlink()
        except OSError as e:
            raise _oserror(e) from None

    def _mkdir(self, where: tuple[str, str]) -> None:
        path = self._writable(where)
        if os.path.lexists(path):
            raise FtpError(EXISTS)
        try:
            path.mkdir()
        except OSError as e:
            raise _oserror(e) from None

    def _rmdir(self, where: tuple[str, str]) -> None:
        path = self._writable(where)
        try:
            path.rmdir()
        except OSError as e:
            raise _oserror(e) from None

    def _truncate(self, where: tuple[str, str], length: int) -> None:
        path = self._writable(where)
        assert self.inbox is not None
        if length > self.inbox.quota.max_file_bytes:
            raise FtpError(FAIL_ERRNO, errno.EFBIG)
        try:
            if not path.is_file():
                raise FtpError(NOT_FOUND if not path.exists() else FAIL_ERRNO, errno.EISDIR)
            grow = length - path.stat().st_size
            if grow > 0 and self.inbox.usage() + grow > self.inbox.quota.max_dir_bytes:
                raise FtpError(FAIL_ERRNO, errno.ENOSPC)
            os.truncate(path, length)
        except OSError as e:
            raise _oserror(e) from None

    def _rename(self, old: tuple[str, str], new: tuple[str, str]) -> None:
        src, dst = self._writable(old), self._writable(new)
        if not os.path.lexists(src):
            raise FtpError(NOT_FOUND)
        if dst.is_dir():
            raise FtpError(FAIL_ERRNO, errno.EISDIR)
        try:
            os.replace(src, dst)
        except OSError as e:
            raise _oserror(e) from None

    # -- sessions and bursts ------------------------------------------------------------------
    def _session(self, sid: int) -> Session:
        s = self.sessions.get(sid)
        if s is None:
            raise FtpError(INVALID_SESSION)
        s.last = self.now
        return s

    def _expire(self) -> None:
        for sid, s in list(self.sessions.items()):
            if self.now - s.last > SESSION_IDLE:
                with contextlib.suppress(FtpError):
                    self._close(s, keep=False)
                del self.sessions[sid]

    def tick(self, now: float) -> list[tuple[bytes, Hashable]]:
        """The next packets of the bursts under way (burst_complete on a burst's last)."""
        self.now = now
        out: list[tuple[bytes, Hashable]] = []
        for key, job in list(self._jobs.items()):
            reply = self._crc_step(job)
            if reply:
                del self._jobs[key]
                self._remember(key, [reply])
                out.append((reply, job.peer))
        for sid, s in self.sessions.items():
            if s.burst is None:
                continue
            offset, want, seq = s.burst
            for _ in range(BURST_PACKETS):
                try:
                    chunk = self._pread(s, offset, offset + want)
                except FtpError as e:  # a read error ends the burst with its NAK
                    out.append((self._reply((seq - 1, sid, BURST, offset), NAK, bytes([e.code])
                                            if e.code != FAIL_ERRNO else bytes([e.code, e.errno]),
                                            burst_complete=1), s.peer))
                    s.burst = None
                    break
                last = offset + len(chunk) >= s.size
                out.append((self._reply((seq - 1, sid, BURST, offset), ACK, chunk, burst_complete=int(last)),
                            s.peer))
                offset, seq = offset + len(chunk), seq + 1
                s.burst = None if last else (offset, want, seq)
                if last:
                    break
        return out

    def wakeup(self) -> float | None:
        """When the bursts under way send their next packets (None: no burst). Idle sessions
        are closed when a new one is opened, or when the node stops."""
        if self._jobs:
            return self.now
        if any(s.burst is not None for s in self.sessions.values()):
            return self.now + BURST_PERIOD
        return None

    def close(self) -> None:
        for job in self._jobs.values():
            with contextlib.suppress(OSError):
                os.close(job.fd)
        self._jobs.clear()
        for s in self.sessions.values():
            with contextlib.suppress(FtpError):
                self._close(s, keep=False)
        self.sessions.clear()


__all__ = ["FtpServer"]
