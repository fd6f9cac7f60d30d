"""Where received files go: a jail with quotas, partial state kept for resume, atomic
completion.

- Names are relative paths of at most `max_name_bytes` UTF-8 bytes, without `..`, `.` or
  empty components, control characters, backslashes, or a leading `/`; the resolved path must
  stay inside the directory (symlinks included).
- A file is received into `.ttctl-partial/<sha256>-<size>.part` beside a JSON record of the
  byte ranges already written; only when every byte is there and the SHA-256 matches is it
  renamed to its name: never visible half-written, never silently overwriting (unless the
  directory allows it and the sender asks).
- A full disk (ENOSPC/EDQUOT) stops the transfer with its partial state kept: offering the same
  file again resumes it.
"""

from __future__ import annotations

import contextlib
import errno
import hashlib
import json
import os
import time
import unicodedata
from dataclasses import dataclass
from pathlib import Path

from .ranges import RangeSet

PARTIAL_DIR = ".ttctl-partial"


class Refused(Exception):
    """An offer the directory will not take; `code` is a TT_FILE_RESULT name suffix."""

    def __init__(self, code: str, reason: str) -> None:
        super().__init__(reason)
        self.code = code
        self.reason = reason


class DiskFull(Exception):
    pass


class StorageError(Exception):
    pass


@dataclass
class Quota:
    max_name_bytes: int = 200
    max_file_bytes: int = 1 << 30  # per transfer
    max_dir_bytes: int = 8 << 30  # everything under the directory, partial files included
    overwrite: bool = False  # the directory allows replacing files (when the sender asks)


def check_name(name: str, max_bytes: int = 200) -> str:
    """The name as a safe relative path, or Refused('NAME', why)."""
    if not name:
        raise Refused("NAME", "empty name")
    raw = name.encode("utf-8", "surrogateescape")
    if len(raw) > max_bytes:
        raise Refused("NAME", f"name is {len(raw)} bytes; at most {max_bytes} allowed")
    if "\x00" in name:
        raise Refused("NAME", "name contains a NUL character")
    if any(unicodedata.category(c) in ("Cc", "Cf", "Cs") for c in name):
        raise Refused("NAME", "name contains control or undecodable characters")
    if "\\" in name:
        raise Refused("NAME", "name contains a backslash")
    if name.startswith("/"):
        raise Refused("NAME", "absolute paths are not allowed")
    parts = name.split("/")
    if any(p in ("", ".", "..") for p in parts):
        raise Refused("NAME", "name has an empty, '.' or '..' component")
    if parts[0] == PARTIAL_DIR:
        raise Refused("NAME", f"{PARTIAL_DIR} is reserved")
    if any(len(p.encode("utf-8", "surrogateescape")) > 255 for p in parts):
        raise Refused("NAME", "a path component is longer than 255 bytes")
    return name


class Partial:
    """One file being received."""

    def __init__(self, store: ReceiveDir, name: str, size: int, sha256: bytes) -> None:
        self.store = store
        self.name = name
        self.size = size
        self.sha256 = sha256
        key = f"{sha256.hex()}-{size}"
        self.data_path = store.partial_dir / f"{key}.part"
        self.state_path = store.partial_dir / f"{key}.json"
        self.ranges = RangeSet()
        self._unsaved = 0
        self.resumed = False
        self._load()
        self._fd: int | None = None

    def _load(self) -> None:
        try:
            state = json.loads(self.state_path.read_text())
        except (OSError, ValueError):
            return
        if state.get("name") != self.name or state.get("size") != self.size:
            return
        try:
            actual = self.data_path.stat().st_size
        except OSError:
            return
        for a, b in state.get("ranges", []):
            if 0 <= a < b <= min(self.size, actual):
                self.ranges.add(a, b)
        self.resumed = bool(self.ranges)

    def _open(self) -> int:
        if self._fd is None:
            self.store.partial_dir.mkdir(parents=True, exist_ok=True)
            self._fd = os.open(self.data_path, os.O_RDWR | os.O_CREAT, 0o644)
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
        if self._fd is not None:
            os.fsync(self._fd)
        state = {"name": self.name, "size": self.size, "sha256": self.sha256.hex(),
                 "ranges": self.ranges.to_list(), "updated": time.time()}
        tmp = self.state_path.with_suffix(".json.tmp")
        try:
            self.store.partial_dir.mkdir(parents=True, exist_ok=True)
            tmp.write_text(json.dumps(state))
            os.replace(tmp, self.state_path)
        except OSError:
            pass  # best effort: the data is safe, at worst it is received again
        self._unsaved = 0

    def close(self) -> None:
        if self._fd is not None:
            os.close(self._fd)
            self._fd = None

    def verify(self) -> bool:
        fd = self._open()
        h = hashlib.sha256()
        pos = 0
        while pos < self.size:
            chunk = os.pread(fd, min(1 << 20, self.size - pos), pos)
            if not chunk:
                break
            h.update(chunk)
            pos += len(chunk)
        if self.size == 0:
            return h.digest() == self.sha256
        return pos == self.size and h.digest() == self.sha256

    def finish(self, overwrite: bool) -> Path:
        """Move the verified file to its name; Refused('EXISTS') if it appeared meanwhile."""
        if self._fd is None:
            self._open()
        assert self._fd is not None
        os.fsync(self._fd)
        os.ftruncate(self._fd, self.size)
        self.close()
        final = self.store.final_path(self.name)
        final.parent.mkdir(parents=True, exist_ok=True)
        if overwrite:
            os.replace(self.data_path, final)
        else:
            try:
                os.link(self.data_path, final)  # fails if the name exists: no silent overwrite
            except FileExistsError:
                raise Refused("EXISTS", f"{self.name} appeared while it was being received") from None
            os.unlink(self.data_path)
        self.discard_state()
        return final

    def discard(self) -> None:
        self.close()
        for p in (self.data_path, self.state_path):
            with contextlib.suppress(FileNotFoundError):
                p.unlink()

    def discard_state(self) -> None:
        with contextlib.suppress(FileNotFoundError):
            self.state_path.unlink()


class ReceiveDir:
    def __init__(self, root: str | os.PathLike[str], quota: Quota | None = None) -> None:
        self.root = Path(root)
        self.quota = quota or Quota()
        try:
            self.root.mkdir(parents=True, exist_ok=True)
        except OSError as e:
            raise StorageError(f"cannot create {self.root}: {e.strerror or e}") from None
        if not os.access(self.root, os.W_OK | os.X_OK):
            raise StorageError(f"{self.root} is not writable")
        self.partial_dir = self.root / PARTIAL_DIR

    def final_path(self, name: str) -> Path:
        path = (self.root / name).resolve()
        root = self.root.resolve()
        if root != path and root not in path.parents:
            raise Refused("NAME", "the name leads outside the receive directory")
        return path

    def usage(self) -> int:
        total = 0
        for dirpath, _, files in os.walk(self.root):
            for f in files:
                with contextlib.suppress(OSError):
                    total += os.lstat(os.path.join(dirpath, f)).st_size
        return total

    def admit(self, name: str, size: int, wants_overwrite: bool) -> str:
        """Check an offer; returns the checked name or raises Refused."""
        q = self.quota
        name = check_name(name, q.max_name_bytes)
        final = self.final_path(name)
        if size > q.max_file_bytes:
            raise Refused("QUOTA", f"{size} bytes exceed the per-file quota of {q.max_file_bytes}")
        if final.exists() or final.is_symlink():
            if not (q.overwrite and wants_overwrite):
                why = "overwriting is not allowed here" if not q.overwrite else "the sender did not ask to overwrite"
                raise Refused("EXISTS", f"{name} exists and {why}")
            if final.is_dir():
                raise Refused("EXISTS", f"{name} is a directory")
        if self.usage() + size > q.max_dir_bytes:
            raise Refused("QUOTA", f"the directory quota of {q.max_dir_bytes} bytes would be exceeded")
        return name

    def partial(self, name: str, size: int, sha256: bytes) -> Partial:
        return Partial(self, name, size, sha256)


class FileSource:
    """A file to send: read by offset, its size and SHA-256 known up front."""

    def __init__(self, path: str | os.PathLike[str]) -> None:
        self.path = Path(path)
        try:
            self._fd = os.open(self.path, os.O_RDONLY)
        except IsADirectoryError:
            raise StorageError(f"{path} is a directory") from None
        except OSError as e:
            raise StorageError(f"{path}: {e.strerror or e}") from None
        st = os.fstat(self._fd)
        import stat

        if not stat.S_ISREG(st.st_mode):
            os.close(self._fd)
            raise StorageError(f"{path} is not a regular file")
        self.size = st.st_size
        if self.size >= 1 << 32:
            os.close(self._fd)
            raise StorageError(f"{path} is {self.size} bytes; at most 4 GiB - 1 can be sent")
        h = hashlib.sha256()
        pos = 0
        while pos < self.size:
            chunk = os.pread(self._fd, 1 << 20, pos)
            if not chunk:
                break
            h.update(chunk)
            pos += len(chunk)
        self.sha256 = h.digest()

    def read(self, offset: int, length: int) -> bytes:
        return os.pread(self._fd, length, offset)

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

    def close(self) -> None:
        pass
