"""Reading a file a user named, safely: only a regular file (a FIFO, a device such as /dev/zero
or a directory is refused in one line, never blocked on or read forever), and never more than a
cap, counted while reading (a file that grows, or lies about its size, stops at the cap). And
writing one: `output_problem` says why a file cannot be written (then renamed into place) at a
path: a folder missing or read-only, a directory, or a FIFO or device there (renaming over
/dev/null as root would replace the system's own).

A leaf module (it imports only `errors`), so the library and the CLI both use it.
"""

from __future__ import annotations

import os
import stat

from .errors import Fail

KiB = 1 << 10
MiB = 1 << 20


def _size(n: int) -> str:
    return f"{n >> 20} MiB" if n >= MiB and n % MiB == 0 else f"{n >> 10} KiB" if n % KiB == 0 else f"{n} bytes"


def regular_file_problem(path: str | os.PathLike[str], what: str) -> str | None:
    """Why `path` cannot be read as a regular file (one line, starting with `what`), or None."""
    try:
        st = os.stat(path)
    except OSError as e:
        return f"{what}: {e.strerror or e}"
    if stat.S_ISDIR(st.st_mode):
        return f"{what}: is a directory, not a file"
    if not stat.S_ISREG(st.st_mode):
        return f"{what}: not a regular file (a FIFO or a device is refused)"
    return None


def read_capped(path: str | os.PathLike[str], what: str, limit: int, *, code: int = 2) -> bytes:
    """The bytes of the regular file `path`, at most `limit` of them; otherwise `Fail(code)` in
    one line that starts with `what` (e.g. "--key FILE"). The file is opened without blocking
    (a FIFO with no writer would wait forever), checked on the open descriptor, then read in
    chunks until the cap."""
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0) | getattr(os, "O_BINARY", 0)
    try:
        fd = os.open(path, flags)
    except IsADirectoryError:
        raise Fail(f"{what}: is a directory, not a file", code) from None
    except OSError as e:
        raise Fail(f"{what}: {e.strerror or e}", code) from None
    try:
        st = os.fstat(fd)
        if stat.S_ISDIR(st.st_mode):
            raise Fail(f"{what}: is a directory, not a file", code)
        if not stat.S_ISREG(st.st_mode):
            raise Fail(f"{what}: not a regular file (a FIFO or a device is refused)", code)
        if st.st_size > limit:
            raise Fail(f"{what}: {st.st_size} bytes; more than {_size(limit)} is refused", code)
        chunks: list[bytes] = []
        got = 0
        while True:
            try:
                chunk = os.read(fd, min(1 * MiB, limit + 1 - got))
            except OSError as e:
                raise Fail(f"{what}: {e.strerror or e}", code) from None
            if not chunk:
                break
            chunks.append(chunk)
            got += len(chunk)
            if got > limit:
                raise Fail(f"{what}: more than {_size(limit)} (it grew while being read); refused", code)
        return b"".join(chunks)
    finally:
        os.close(fd)


def read_text_capped(path: str | os.PathLike[str], what: str, limit: int, *, code: int = 2) -> str:
    """As `read_capped`, decoded as UTF-8 (a file that is not UTF-8 is refused in one line)."""
    raw = read_capped(path, what, limit, code=code)
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError as e:
        raise Fail(f"{what}: not UTF-8 text (byte {e.start})", code) from None


__all__ = ["KiB", "MiB", "read_capped", "read_text_capped", "regular_file_problem"]


def output_problem(path: str) -> str | None:
    """Why a regular file cannot be written at `path` and renamed into place (its folder missing
    or read-only, a directory there, or something that is no regular file: a FIFO, a device, a
    socket, which a rename would replace), or None."""
    target = os.path.abspath(path)
    folder = os.path.dirname(target)
    if os.path.isdir(target):
        return f"{path} is a directory"
    try:
        st = os.stat(target)
    except OSError:
        st = None
    if st is not None and not stat.S_ISREG(st.st_mode):
        return f"cannot write {path}: not a regular file (a FIFO or a device is never replaced)"
    if not os.path.isdir(folder):
        return f"cannot write {path}: {folder} is not a directory" if os.path.exists(folder) \
            else f"cannot write {path}: no folder {folder}"
    if not os.access(folder, os.W_OK | os.X_OK):
        return f"cannot write {path}: {folder} is not writable"
    return None
