"""The onboard end's MAVLink FTP server, sans-IO: requests in, replies out, against real folders
(the served one read-only, the inbox writable under its jail rules and quotas)."""

from __future__ import annotations

import errno
import hashlib
import os
import struct
import zlib
from pathlib import Path
from typing import Any

import pytest

from ttctl.ends.onboard import ftp
from ttctl.proto.storage import Quota, ReceiveDir

PEER = (255, 190)


class Client:
    """Just enough of a MAVLink FTP client to drive the server (seq counting up)."""

    def __init__(self, server: ftp.FtpServer) -> None:
        self.s = server
        self.seq = 0
        self.now = 0.0

    def send(self, opcode: int, data: bytes = b"", session: int = 0, offset: int = 0,
             size: int | None = None) -> list[tuple[Any, ...]]:
        self.seq += 1
        n = len(data) if size is None else size
        payload = ftp.HEADER.pack(self.seq, session, opcode, n, 0, 0, 0, offset) + data
        return [self.parse(r) for r in self.s.request(self.now, payload, PEER)]

    @staticmethod
    def parse(r: bytes) -> tuple[Any, ...]:
        assert len(r) == ftp.PAYLOAD
        seq, session, opcode, size, req, burst_complete, _, offset = ftp.HEADER.unpack_from(r)
        return opcode, r[12:12 + size], session, offset, burst_complete, seq, req

    def one(self, *a: Any, **k: Any) -> tuple[Any, ...]:
        replies = self.send(*a, **k)
        assert len(replies) == 1
        return replies[0]

    def ok(self, *a: Any, **k: Any) -> tuple[Any, ...]:
        r = self.one(*a, **k)
        assert r[0] == ftp.ACK, r
        return r

    def nak(self, *a: Any, **k: Any) -> bytes:
        r = self.one(*a, **k)
        assert r[0] == ftp.NAK, r
        return bytes(r[1])

    def listing(self, path: str) -> list[str]:
        out: list[str] = []
        while True:
            r = self.one(ftp.LIST, path.encode(), offset=len(out))
            if r[0] == ftp.NAK:
                assert r[1] == bytes([ftp.EOF])
                return out
            out += [e.decode() for e in bytes(r[1]).split(b"\0") if e]

    def get(self, path: str, burst: bool = True, packet: int = 239) -> bytes:
        _, data, sid, *_ = self.ok(ftp.OPEN_RO, path.encode())
        size = struct.unpack("<I", data)[0]
        got = bytearray()
        if burst:
            assert self.send(ftp.BURST, session=sid, size=packet) == []
            while True:
                sent = self.s.tick(self.now)
                assert sent and all(peer == PEER for _, peer in sent)
                packets = [self.parse(p) for p, _ in sent]
                for op, chunk, _, offset, _, *_ in packets:
                    assert op == ftp.ACK and offset == len(got)
                    got += chunk
                if packets[-1][4]:
                    break
        else:
            while True:
                r = self.one(ftp.READ, session=sid, offset=len(got), size=packet)
                if r[0] == ftp.NAK:
                    assert r[1] == bytes([ftp.EOF])
                    break
                got += r[1]
        self.ok(ftp.TERMINATE, session=sid)
        assert len(got) == size
        return bytes(got)

    def put(self, path: str, data: bytes) -> None:
        _, _, sid, *_ = self.ok(ftp.CREATE, path.encode())
        for ofs in range(0, len(data), 239):
            self.ok(ftp.WRITE, data[ofs:ofs + 239], session=sid, offset=ofs)
        self.ok(ftp.TERMINATE, session=sid)


@pytest.fixture
def tree(tmp_path: Path) -> tuple[Client, Path, Path]:
    serve, inbox = tmp_path / "serve", tmp_path / "inbox"
    (serve / "sub").mkdir(parents=True)
    (serve / "a.txt").write_bytes(b"hello")
    (serve / "sub" / "big.bin").write_bytes(os.urandom(239 * 30))  # ends on a packet's edge
    (tmp_path / "secret").write_text("outside")
    os.symlink(tmp_path / "secret", serve / "leak")
    store = ReceiveDir(inbox, Quota(max_file_bytes=10_000, max_dir_bytes=20_000))
    store.prepare()
    return Client(ftp.FtpServer(serve, store)), serve, inbox


def test_root_lists_the_served_folder_and_the_inbox(tree: tuple[Client, Path, Path]) -> None:
    c, serve, inbox = tree
    assert c.listing("/") == ["Dinbox", "Dserve"]
    assert c.listing("/serve") == ["Fa.txt\t5", "Dsub"]  # the link leading out is not shown
    assert c.listing("/inbox/") == []
    c.put("/inbox/x.txt", b"data")
    (inbox / ".ttctl-partial").mkdir(exist_ok=True)
    assert c.listing("inbox") == ["Fx.txt\t4"]  # the receiver's partial folder is not shown
    many = [f"{i:03d}-" + "n" * 40 for i in range(30)]
    for name in many:
        (serve / "sub" / name).write_text("")
    assert c.listing("/serve/sub") == [f"F{n}\t0" for n in many] + ["Fbig.bin\t7170"]  # pages by entry offset


def test_files_are_read_whole_by_read_and_by_burst(tree: tuple[Client, Path, Path]) -> None:
    c, serve, _ = tree
    big = (serve / "sub" / "big.bin").read_bytes()
    assert c.get("/serve/sub/big.bin") == big
    assert c.get("/serve/sub/big.bin", burst=False, packet=100) == big
    assert c.get("/serve/a.txt", packet=2) == b"hello"
    crc = c.ok(ftp.CRC32, b"/serve/sub/big.bin")[1]
    expect = zlib.crc32(big, 0xFFFFFFFF) ^ 0xFFFFFFFF  # PX4's: zero seed, no final inversion
    assert struct.unpack("<I", crc)[0] == expect


def test_written_files_appear_whole_when_the_session_ends(tree: tuple[Client, Path, Path]) -> None:
    c, _, inbox = tree
    data = os.urandom(5000)
    _, _, sid, *_ = c.ok(ftp.CREATE, b"/inbox/t.bin")
    c.ok(ftp.WRITE, data[:239], session=sid)
    assert not (inbox / "t.bin").exists()  # never visible half-written
    for ofs in range(239, len(data), 239):
        c.ok(ftp.WRITE, data[ofs:ofs + 239], session=sid, offset=ofs)
    c.ok(ftp.TERMINATE, session=sid)
    assert hashlib.sha256((inbox / "t.bin").read_bytes()).digest() == hashlib.sha256(data).digest()
    assert c.get("/inbox/t.bin") == data
    c.put("/inbox/t.bin", b"new")  # replaced, as PX4's CreateFile truncates
    assert (inbox / "t.bin").read_bytes() == b"new"
    c.ok(ftp.MKDIR, b"/inbox/d")
    assert c.nak(ftp.MKDIR, b"/inbox/d") == bytes([ftp.EXISTS])
    c.ok(ftp.RENAME, b"/inbox/t.bin\0/inbox/d/u.bin")
    c.ok(ftp.TRUNCATE, b"/inbox/d/u.bin", offset=1)
    assert (inbox / "d" / "u.bin").read_bytes() == b"n"
    assert c.nak(ftp.RMDIR, b"/inbox/d")[:1] == bytes([ftp.FAIL_ERRNO])  # not empty
    c.ok(ftp.REMOVE, b"/inbox/d/u.bin")
    c.ok(ftp.RMDIR, b"/inbox/d")
    assert sorted(p.name for p in inbox.iterdir()) == [".ttctl-partial"]
    assert list((inbox / ".ttctl-partial").iterdir()) == []
    # a session reset discards an unfinished write
    _, _, sid, *_ = c.ok(ftp.CREATE, b"/inbox/half.bin")
    c.ok(ftp.WRITE, b"abc", session=sid)
    c.ok(ftp.RESET)
    assert not (inbox / "half.bin").exists() and list((inbox / ".ttctl-partial").iterdir()) == []


@pytest.mark.parametrize("path", ["/serve/../secret", "/inbox/../secret", "/serve/leak", "serve/./a.txt",
                                  "/inbox/.ttctl-partial/x", "/inbox/a\\b", "/inbox/a\x01b"])
def test_paths_leading_out_are_protected(tree: tuple[Client, Path, Path], path: str) -> None:
    c, _, inbox = tree
    for op in (ftp.OPEN_RO, ftp.CREATE, ftp.REMOVE, ftp.CRC32, ftp.LIST, ftp.MKDIR):
        assert c.nak(op, path.encode()) == bytes([ftp.PROTECTED]), (op, path)
    assert c.s.sessions == {} and list(inbox.iterdir()) == []
    assert (inbox.parent / "secret").read_text() == "outside"


def test_hostile_requests_get_the_protocol_s_own_errors(tree: tuple[Client, Path, Path]) -> None:
    c, serve, _ = tree
    assert c.nak(ftp.OPEN_RO, b"/etc/passwd") == bytes([ftp.NOT_FOUND])  # absolute: in the vehicle's tree
    assert c.nak(ftp.OPEN_RO, b"@PARAM/param.pck?withdefaults=1") == bytes([ftp.NOT_FOUND])
    assert c.nak(ftp.OPEN_RO, b"/serve/none") == bytes([ftp.NOT_FOUND])
    assert c.nak(ftp.CREATE, b"/serve/new.txt") == bytes([ftp.PROTECTED])  # the served folder is read-only
    assert c.nak(ftp.REMOVE, b"/serve/a.txt") == bytes([ftp.PROTECTED])
    assert c.nak(ftp.CREATE, b"/x.txt") == bytes([ftp.NOT_FOUND])
    assert c.nak(ftp.RMDIR, b"/inbox") == bytes([ftp.PROTECTED])
    assert c.nak(ftp.CREATE, b"/inbox/" + b"n" * 232) == bytes([ftp.PROTECTED])  # too long a name for the inbox
    assert c.nak(ftp.CREATE, b"/inbox/no/such/dir.txt") == bytes([ftp.FAIL_ERRNO, errno.ENOENT])
    assert c.nak(ftp.OPEN_RO, b"x" * 10, size=240) == bytes([ftp.INVALID_SIZE])
    assert c.nak(ftp.READ, session=7) == bytes([ftp.INVALID_SESSION])
    assert c.nak(ftp.WRITE, b"x", session=200) == bytes([ftp.INVALID_SESSION])
    assert c.nak(ftp.TERMINATE, session=9) == bytes([ftp.INVALID_SESSION])
    assert c.nak(99) == bytes([ftp.UNKNOWN])
    assert c.nak(16, b"/") == bytes([ftp.UNKNOWN])  # list with times: PX4 does not know it either
    assert c.nak(ftp.OPEN_RO, b"/serve/sub") == bytes([ftp.FAIL_ERRNO, errno.EISDIR])
    # quotas: per file (10 000 bytes) and for the folder (20 000)
    _, _, sid, *_ = c.ok(ftp.CREATE, b"/inbox/q.bin")
    assert c.nak(ftp.WRITE, b"x", session=sid, offset=10_000) == bytes([ftp.FAIL_ERRNO, errno.EFBIG])
    assert c.nak(ftp.WRITE, b"x", session=sid, offset=2**32 - 1) == bytes([ftp.FAIL_ERRNO, errno.EFBIG])
    c.ok(ftp.TERMINATE, session=sid)
    for i in range(2):
        c.put(f"/inbox/f{i}", b"x" * 9000)
    _, _, sid, *_ = c.ok(ftp.CREATE, b"/inbox/f2")
    assert c.nak(ftp.WRITE, b"x" * 200, session=sid, offset=2000 + 239 * 4) == bytes([ftp.FAIL_ERRNO, errno.ENOSPC])
    c.ok(ftp.TERMINATE, session=sid)
    assert c.nak(ftp.TRUNCATE, b"/inbox/f0", offset=20_000) == bytes([ftp.FAIL_ERRNO, errno.EFBIG])
    # sessions run out, and come back with a reset
    sids = [c.ok(ftp.OPEN_RO, b"/serve/a.txt", session=10 + i)[2] for i in range(ftp.MAX_SESSIONS)]
    assert sids == [10, 11, 12, 13]  # the ids the client chose (MAVProxy routes replies by them)
    assert c.nak(ftp.OPEN_RO, b"/serve/a.txt", session=10) == bytes([ftp.FAIL])  # in use
    assert c.nak(ftp.OPEN_RO, b"/serve/a.txt", session=99) == bytes([ftp.NO_SESSIONS])
    c.ok(ftp.RESET)
    assert c.get("/serve/a.txt") == b"hello"
    # nothing was written outside the inbox
    assert sorted(p.name for p in serve.parent.iterdir()) == ["inbox", "secret", "serve"]


def test_a_retry_gets_the_same_answer_and_floods_stay_bounded(tree: tuple[Client, Path, Path]) -> None:
    c, _, _ = tree
    first = c.send(ftp.OPEN_RO, b"/serve/a.txt")
    c.seq -= 1
    again = c.send(ftp.OPEN_RO, b"/serve/a.txt")  # the reply was lost: the same seq, the same session
    assert first == again and len(c.s.sessions) == 1
    assert first[0][5] == c.seq + 1 and first[0][6] == ftp.OPEN_RO
    sid = first[0][2]
    for _ in range(1000):  # a flood of burst requests: one burst under way, bounded packets per tick
        c.send(ftp.BURST, session=sid, size=1)
    assert len(c.s.tick(0.0)) <= ftp.BURST_PACKETS
    for _ in range(500):
        c.send(ftp.LIST, b"/serve")
    assert len(c.s._cache) <= ftp.CACHE
    # garbage payloads
    import random

    rnd = random.Random(7)
    for _ in range(3000):
        c.s.request(0.0, bytes(rnd.getrandbits(8) for _ in range(rnd.randrange(0, 260))), PEER)
    c.s.tick(0.0)
    c.s.close()


def test_a_big_file_s_crc32_is_computed_a_step_per_tick(tree: tuple[Client, Path, Path]) -> None:
    c, serve, _ = tree
    big = os.urandom(ftp.CRC_STEP * 2 + 1234)
    (serve / "big.img").write_bytes(big)
    assert c.send(ftp.CRC32, b"/serve/big.img") == []  # under way: the vehicle keeps flying meanwhile
    c.seq -= 1
    assert c.send(ftp.CRC32, b"/serve/big.img") == []  # a retry while it runs: still one job
    replies = []
    for _ in range(5):
        replies += c.s.tick(0.0)
    assert len(replies) == 1 and replies[0][1] == PEER
    op, data, *_ = Client.parse(replies[0][0])
    assert op == ftp.ACK and struct.unpack("<I", data)[0] == zlib.crc32(big, 0xFFFFFFFF) ^ 0xFFFFFFFF
    c.seq -= 1
    assert c.send(ftp.CRC32, b"/serve/big.img")[0][:2] == (ftp.ACK, data)  # the retry after: the cached answer
    assert c.s.wakeup() is None


def test_a_big_folder_is_read_once_per_listing(tree: tuple[Client, Path, Path], monkeypatch: Any) -> None:
    c, serve, _ = tree
    for i in range(300):
        (serve / "sub" / f"f{i:04d}.txt").write_text("x")
    reads = []
    real = os.listdir
    monkeypatch.setattr(ftp.os, "listdir", lambda p: reads.append(p) or real(p))
    names = c.listing("/serve/sub")
    assert len(names) == 301 and len(reads) == 1
    c.listing("/serve/sub")  # a new listing (offset 0) reads the folder again
    assert len(reads) == 2


def test_a_session_whose_file_cannot_land_still_ends(tree: tuple[Client, Path, Path]) -> None:
    c, _, inbox = tree
    _, _, sid, *_ = c.ok(ftp.CREATE, b"/inbox/x")
    c.ok(ftp.WRITE, b"abc", session=sid)
    (inbox / "x").mkdir()  # meanwhile a folder took the name
    assert c.nak(ftp.TERMINATE, session=sid) == bytes([ftp.FAIL_ERRNO, errno.EISDIR])
    assert c.s.sessions == {} and list((inbox / ".ttctl-partial").iterdir()) == []
    assert c.nak(ftp.TERMINATE, session=sid) == bytes([ftp.INVALID_SESSION])
