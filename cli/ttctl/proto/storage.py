"""Where received files go: a jail with quotas, partial state kept for resume, atomic
completion; and where sent files come from.

- Names follow names.py (the rules both ends share); the resolved path must stay inside the
  directory (symlinks included), every parent that exists must be a directory, and a file
  that exists under the name must be a regular file.
- A file is received into `.ttctl-partial/<key>.part` beside a JSON record of the byte ranges
  already written, the key made of its SHA-256, name and size; only when every byte is there
  and the SHA-256 matches is it renamed to its name: never visible half-written, never
  silently overwriting (unless the directory allows it and the sender asks).
- A deflated offer (TT_FILE_FLAGS_DEFLATE) is received the same way as its zlib stream (its
  own partial, never shared with the file sent raw); when the stream is whole it is inflated
  into `<key>.out`, bounded by the original size offered, and only that file, its SHA-256
  checked, takes the name.
- A full disk (ENOSPC/EDQUOT) stops the transfer with its partial state kept: offering the same
  file again resumes it.
- One receiving process per directory (an advisory lock on it), so that two never write the
  same partial file.
"""

from __future__ import annotations

import contextlib
import errno
import fcntl
import hashlib
import json
import os
import stat
import time
import weakref
from dataclasses import dataclass
from pathlib import Path

from .deflate import inflate_to
from .names import PARTIAL_DIR, Refused, check_name, encoded
from .ranges import RangeSet

__all__ = ["PARTIAL_DIR", "BytesSource", "DiskFull", "FileSource", "Partial", "Quota", "ReceiveDir", "Refused",
           "StorageError", "file_sha256", "kind_of"]


class DiskFull(Exception):
    pass


class StorageError(Exception):
    pass


@dataclass
class Quota:
    max_file_bytes: int = 1 << 30  # per transfer
    max_dir_bytes: int = 8 << 30  # everything under the directory, partial files included
    overwrite: bool = False  # the directory allows replacing files (when the sender asks)


def kind_of(mode: int) -> str:
    """What a file of this mode is, in words."""
    for test, word in ((stat.S_ISREG, "a file"), (stat.S_ISDIR, "a directory"), (stat.S_ISFIFO, "a FIFO"),
                       (stat.S_ISSOCK, "a socket"), (stat.S_ISCHR, "a character device"),
                       (stat.S_ISBLK, "a block device"), (stat.S_ISLNK, "a symbolic link")):
        if test(mode):
            return word
    return "not a regular file"


def file_sha256(fd: int, size: int) -> tuple[bytes, int]:
    """SHA-256 of the first `size` bytes of an open file, and how many bytes there were."""
    h = hashlib.sha256()
    pos = 0
    while pos < size:
        chunk = os.pread(fd, min(1 << 20, size - pos), pos)
        if not chunk:
            break
        h.update(chunk)
        pos += len(chunk)
    return h.digest(), pos


def partial_key(name: str, size: int, sha256: bytes, original: int | None = None) -> str:
    """One partial file per (content, name): two transfers of one file under two names never
    share a partial file, two of the same file under the same name always do (and the file and
    its zlib stream, `original` being the file's size, never do)."""
    key = f"{hashlib.sha256(sha256 + encoded(name)).hexdigest()[:40]}-{size}"
    return key if original is None else f"{key}-z{original}"


class Partial:
    """One file being received. Several transfers of the same file under the same name (a
    sender and its restarted self, say) share one Partial; FileReceiver sees to that."""

    def __init__(self, store: ReceiveDir, name: str, size: int, sha256: bytes, original: int | None = None) -> None:
        self.store = store
        self.name = name
        self.size = size  # of what arrives: the file, or its zlib stream
        self.sha256 = sha256  # of the file
        self.original = original  # the file's size when what arrives is its zlib stream
        self.key = partial_key(name, size, sha256, original)
        self.data_path = store.partial_dir / f"{self.key}.part"
        self.out_path = store.partial_dir / f"{self.key}.out"  # the inflated file, before it takes its name
        self.state_path = store.partial_dir / f"{self.key}.json"
        self.ranges = RangeSet()
        self._unsaved = 0
        self.resumed = False
        self._fd: int | None = None
        self._load()

    def _load(self) -> None:
        try:
            state = json.loads(self.state_path.read_text())
        except (OSError, ValueError, RecursionError):  # damaged state: start afresh
            return
        if not isinstance(state, dict) or state.get("name") != self.name or state.get("size") != self.size \
                or state.get("sha256") != self.sha256.hex() or state.get("original") != self.original:
            return
        try:
            actual = self.data_path.stat().st_size
        except OSError:
            return
        ranges = state.get("ranges", [])
        if not isinstance(ranges, list):
            return
        for pair in ranges:
            if isinstance(pair, list) and len(pair) == 2 and all(isinstance(x, int) for x in pair):
                a, b = pair
                if 0 <= a < b <= min(self.size, actual):
                    self.ranges.add(a, b)
        self.resumed = bool(self.ranges)

    def _open(self) -> int:
        if self._fd is None:
            self.store.make_partial_dir()
            self._fd = os.open(self.data_path, os.O_RDWR | os.O_CREAT | os.O_CLOEXEC, 0o644)
            self._record()  # before any data: a record the disk can always rewrite, even when full
        return self._fd

    def write(self, offset: int, data: bytes) -> bool:
        """Write a chunk; False if it was already there. DiskFull if the disk is full."""
        end = offset + len(data)
        if self.ranges.covers(offset, end):
            return False
        try:
            os.pwrite(self._open(), data, offset)
        except OSError as e:
            if e.errno in (errno.ENOSPC, errno.EDQUOT):
                self.save()
                raise DiskFull(str(e)) from None
            raise StorageError(f"{self.data_path}: {e.strerror or e}") from None
        self.ranges.add(offset, end)
        self._unsaved += len(data)
        if self._unsaved >= 64 * 1024:
            self.save()
        return True

    @property
    def complete(self) -> bool:
        return self.size == 0 or self.ranges.covers(0, self.size)

    def save(self) -> None:
        """Persist the ranges written so far (after flushing the data they describe)."""
        if self._fd is None and not self.ranges:
            return  # nothing was written: leave no state behind
        if self._fd is not None:
            with contextlib.suppress(OSError):
                os.fsync(self._fd)
        self._record()
        self._unsaved = 0

    def _record(self) -> None:
        state = {"name": self.name, "size": self.size, "sha256": self.sha256.hex(), "original": self.original,
                 "ranges": self.ranges.to_list(), "updated": time.time()}
        text = json.dumps(state).encode()
        tmp = self.state_path.with_name(self.state_path.name + ".tmp")
        try:
            self.store.make_partial_dir()
            tmp.write_bytes(text)
            os.replace(tmp, self.state_path)
            return
        except (OSError, StorageError):
            with contextlib.suppress(OSError):
                tmp.unlink()
        try:  # the disk is full: rewrite the record in place (its blocks are ours already)
            fd = os.open(self.state_path, os.O_WRONLY | os.O_CLOEXEC)
        except OSError:
            return  # best effort: the data is safe, at worst it is received again
        try:
            os.pwrite(fd, text, 0)
            os.ftruncate(fd, len(text))
        except OSError:
            pass
        finally:
            os.close(fd)

    def close(self) -> None:
        if self._fd is not None:
            os.close(self._fd)
            self._fd = None

    def verify(self) -> bool:
        """Whether the bytes received are the file offered. A zlib stream is inflated into
        `out_path` first (InflateError, with the reason, if it is not the file; OSError if it
        cannot be written)."""
        if self.original is not None:
            os.fsync(self._open())
            inflate_to(self._open(), self.size, self.out_path, self.original, self.sha256)
            return True
        digest, got = file_sha256(self._open(), self.size)
        return got == self.size and digest == self.sha256

    def finish(self, overwrite: bool) -> Path:
        """Move the verified file to its name. Refused('EXISTS') if a different file appeared
        there meanwhile (an identical one is fine: the data is then dropped)."""
        fd = self._open()
        os.fsync(fd)
        os.ftruncate(fd, self.size)
        self.close()
        done = self.data_path if self.original is None else self.out_path
        size = self.size if self.original is None else self.original
        final = self.store.final_path(self.name)
        self.store.check_parents(self.name)
        try:
            final.parent.mkdir(parents=True, exist_ok=True)
        except (FileExistsError, NotADirectoryError):
            raise Refused("NAME", f"a parent of {self.name} is not a directory here") from None
        if overwrite:
            self.store.check_target(self.name, final, overwrite=True)
            os.replace(done, final)
        else:
            try:
                os.link(done, final)  # fails if the name exists: no silent overwrite
            except FileExistsError:
                if not self.store.identical(final, size, self.sha256):
                    raise Refused("EXISTS", f"{self.name} appeared here while it was being received") from None
            os.unlink(done)
        if done != self.data_path:
            with contextlib.suppress(FileNotFoundError):
                os.unlink(self.data_path)
        self.discard_state()
        self.store.forget_others(self.name, self.key)
        self.store.tidy()
        return final

    def discard(self) -> None:
        self.close()
        for p in (self.data_path, self.state_path, self.out_path):
            with contextlib.suppress(FileNotFoundError):
                p.unlink()
        self.ranges = RangeSet()
        self.store.tidy()

    def discard_state(self) -> None:
        with contextlib.suppress(FileNotFoundError):
            self.state_path.unlink()


class ReceiveDir:
    """The jail files are received into. Nothing is created on disk until a file needs it
    (or `prepare()`, which also takes the directory's lock)."""

    def __init__(self, root: str | os.PathLike[str], quota: Quota | None = None) -> None:
        self.root = Path(root)
        self.quota = quota or Quota()
        self.partial_dir = self.root / PARTIAL_DIR
        self.created: list[Path] = []  # directories this process created, outermost first
        self._lock_fd: int | None = None
        self._live: weakref.WeakValueDictionary[str, Partial] = weakref.WeakValueDictionary()

    # -- life cycle ---------------------------------------------------------------------------
    def check(self) -> None:
        """StorageError unless the directory exists and is writable, or can be created."""
        p = self.root
        if p.exists():
            if not p.is_dir():
                raise StorageError(f"{p} is not a directory")
            if not os.access(p, os.W_OK | os.X_OK):
                raise StorageError(f"{p} is not writable")
            return
        parent = p.absolute().parent
        while not parent.exists():
            parent = parent.parent
        if not parent.is_dir() or not os.access(parent, os.W_OK | os.X_OK):
            raise StorageError(f"cannot create {p}: {parent} is not a writable directory")

    def prepare(self) -> None:
        """Create the directory if missing and lock it for this process (StorageError if
        another receiver holds it)."""
        self.check()
        self._mkdirs(self.root)
        fd = os.open(self.root, os.O_RDONLY | os.O_DIRECTORY | os.O_CLOEXEC)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            os.close(fd)
            self.release(failed=True)
            raise StorageError(f"{self.root} is in use by another ttctl receiver") from None
        self._lock_fd = fd

    def release(self, failed: bool) -> None:
        """Unlock; after a failure, remove the directories this process created if they are
        empty (a failed command leaves nothing behind). An empty partial folder goes in any case:
        a receive that finished leaves only the files it received."""
        if self._lock_fd is not None:
            with contextlib.suppress(OSError):
                self.partial_dir.rmdir()  # only if empty; still under the lock, so no receiver is using it
            os.close(self._lock_fd)
            self._lock_fd = None
        if failed:
            self.remove_created()

    def remove_created(self) -> None:
        for d in [self.partial_dir, *reversed(self.created)]:
            if d == self.partial_dir and d not in self.created:
                continue
            with contextlib.suppress(OSError):
                d.rmdir()  # only if empty
        self.created = [d for d in self.created if d.exists()]

    def _mkdirs(self, path: Path) -> None:
        missing = []
        p = path
        while not p.exists():
            missing.append(p)
            p = p.parent
        for d in reversed(missing):
            try:
                d.mkdir()
            except FileExistsError:
                continue
            except OSError as e:
                raise StorageError(f"cannot create {d}: {e.strerror or e}") from None
            self.created.append(d)

    def tidy(self) -> None:
        """Remove the partial folder when nothing is left in it (a file finished or was
        discarded): a long-running receiver leaves only the files it received. Every writer
        makes the folder again before it writes (`make_partial_dir`)."""
        with contextlib.suppress(OSError):
            self.partial_dir.rmdir()  # only if empty
        self.created = [d for d in self.created if d != self.partial_dir or d.exists()]

    def make_partial_dir(self) -> None:
        if not self.partial_dir.is_dir():
            self._mkdirs(self.partial_dir)

    # -- names ----------------------------------------------------------------------------------
    def final_path(self, name: str) -> Path:
        path = (self.root / name).resolve()
        root = self.root.resolve()
        if root != path and root not in path.parents:
            raise Refused("NAME", "the name leads outside the receive directory")
        return path

    def check_parents(self, name: str) -> None:
        """Every parent of the name that exists must be a directory (inside the jail)."""
        parts = name.split("/")[:-1]
        p = self.root
        for i, part in enumerate(parts):
            p = p / part
            try:
                st = os.stat(p)
            except FileNotFoundError:
                return
            except NotADirectoryError:
                raise Refused("NAME", f"{'/'.join(parts[:i])} exists here and is not a directory") from None
            except OSError as e:
                raise Refused("NAME", f"{'/'.join(parts[:i + 1])}: {e.strerror or e}") from None
            if not stat.S_ISDIR(st.st_mode):
                raise Refused("NAME", f"{'/'.join(parts[:i + 1])} exists here and is {kind_of(st.st_mode)}, "
                                      "not a directory")

    def check_target(self, name: str, final: Path, overwrite: bool) -> bool:
        """Whether a file exists under the name (Refused if it may not be replaced)."""
        try:
            st = os.lstat(final)
        except FileNotFoundError:
            return False
        if not stat.S_ISREG(st.st_mode):
            raise Refused("EXISTS", f"{name} exists here and is {kind_of(st.st_mode)}")
        if not (self.quota.overwrite and overwrite):
            why = ("overwriting is not allowed here" if not self.quota.overwrite
                   else "the sender did not ask to overwrite")
            raise Refused("EXISTS", f"{name} exists and {why}")
        return True

    def identical(self, path: Path, size: int, sha256: bytes) -> bool:
        """Whether the regular file at `path` has this size and SHA-256."""
        try:
            fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_CLOEXEC)
        except OSError:
            return False
        try:
            st = os.fstat(fd)
            if not stat.S_ISREG(st.st_mode) or st.st_size != size:
                return False
            digest, got = file_sha256(fd, size)
            return got == size and digest == sha256
        finally:
            os.close(fd)

    def usage(self) -> int:
        total = 0
        for dirpath, _, files in os.walk(self.root):
            for f in files:
                with contextlib.suppress(OSError):
                    total += os.lstat(os.path.join(dirpath, f)).st_size
        return total

    def admit(self, name: str, size: int, wants_overwrite: bool, sha256: bytes, stream: int = 0) -> bool:
        """Check an offer. True if a file with this size and SHA-256 is there already under the
        name (nothing to receive); False if it may be received; Refused otherwise. `stream`:
        the size of the zlib stream a deflated offer sends (on disk beside the file while it
        is inflated)."""
        q = self.quota
        check_name(name)
        final = self.final_path(name)
        self.check_parents(name)
        if size > q.max_file_bytes:
            raise Refused("QUOTA", f"{size} bytes exceed the per-file quota of {q.max_file_bytes} bytes")
        if stream > q.max_file_bytes:  # a stream larger than its file: nothing a real deflater writes
            raise Refused("QUOTA", f"a {stream}-byte stream exceeds the per-file quota of {q.max_file_bytes} bytes")
        if os.path.lexists(final) and self.identical(final, size, sha256):
            return True
        self.check_target(name, final, wants_overwrite)
        if self.usage() + size + stream > q.max_dir_bytes:
            raise Refused("QUOTA", f"the directory quota of {q.max_dir_bytes} bytes would be exceeded")
        return False

    def partial(self, name: str, size: int, sha256: bytes, original: int | None = None) -> Partial:
        p = Partial(self, name, size, sha256, original)
        self._live[p.key] = p
        return p

    def forget_others(self, name: str, keep: str) -> None:
        """After a file took `name`: the partial state of other contents under that name (a transfer
        killed, then another file sent under its name) would stay forever; remove it, unless a
        transfer of this process still writes it."""
        try:
            states = list(self.partial_dir.glob("*.json"))
        except OSError:
            return
        for path in states:
            key = path.stem
            if key == keep or key in self._live:
                continue
            try:
                with open(path, "rb") as f:
                    state = json.loads(f.read(1 << 16))
            except (OSError, ValueError, RecursionError):
                continue
            if not isinstance(state, dict) or state.get("name") != name:
                continue
            for suffix in (".part", ".out", ".json"):
                with contextlib.suppress(OSError):
                    (self.partial_dir / f"{key}{suffix}").unlink()


class FileSource:
    """A file to send: read by offset, its size and SHA-256 known up front. Only regular files:
    a FIFO, device, socket or directory is refused without blocking on it."""

    def __init__(self, path: str | os.PathLike[str]) -> None:
        self.path = Path(path)
        try:
            st = os.stat(self.path)
        except OSError as e:
            raise StorageError(f"{path}: {e.strerror or e}") from None
        if not stat.S_ISREG(st.st_mode):
            raise StorageError(f"{path} is {kind_of(st.st_mode)}, not a regular file")
        try:
            self._fd = os.open(self.path, os.O_RDONLY | os.O_NONBLOCK | os.O_CLOEXEC)
        except OSError as e:
            raise StorageError(f"{path}: {e.strerror or e}") from None
        st = os.fstat(self._fd)
        if not stat.S_ISREG(st.st_mode):  # swapped between the two looks
            os.close(self._fd)
            raise StorageError(f"{path} is {kind_of(st.st_mode)}, not a regular file")
        self.size = st.st_size
        if self.size >= 1 << 32:
            os.close(self._fd)
            raise StorageError(f"{path} is {self.size} bytes; at most 4 GiB - 1 can be sent")
        self._stamp = (st.st_ino, st.st_size, st.st_mtime_ns)
        self.sha256, got = file_sha256(self._fd, self.size)
        if got != self.size:
            os.close(self._fd)
            raise StorageError(f"{path} shrank while it was being read")

    def read(self, offset: int, length: int) -> bytes:
        return os.pread(self._fd, length, offset)

    def changed(self) -> bool:
        """Whether the file changed since its SHA-256 was taken (then what was sent may not
        match it)."""
        try:
            st = os.stat(self.path)
        except OSError:
            return True
        if (st.st_ino, st.st_size, st.st_mtime_ns) != self._stamp:
            return True
        digest, got = file_sha256(self._fd, self.size)
        return got != self.size or digest != self.sha256

    def close(self) -> None:
        os.close(self._fd)


class BytesSource:
    """An in-memory file (benchmarks, tests)."""

    def __init__(self, data: bytes, name: str = "data.bin") -> None:
        self.data = data
        self.size = len(data)
        self.sha256 = hashlib.sha256(data).digest()
        self.path = Path(name)

    def read(self, offset: int, length: int) -> bytes:
        return self.data[offset:offset + length]

    def changed(self) -> bool:
        return False

    def close(self) -> None:
        pass
