"""What every recording format shares: the Writer interface, the Recording a reader returns,
and the atomic file a writer fills.

A recording is written under a hidden temporary name in the destination folder
(`.NAME.XXXXXXXX.tmp`) and renamed to NAME only when it is complete and on disk (fsync), so
Ctrl-C, a crash or a kill never leaves a half-written, unreadable file under the name the user
asked for. The rename is atomic within one folder, which is why the temporary file lives next
to the final one rather than in /tmp. After a hard kill (SIGKILL, power loss) the temporary file
stays behind with whatever had reached the disk; readers accept it by content (magic bytes), so
it can still be replayed (an MCAP one up to its last complete chunk).
"""

from __future__ import annotations

import contextlib
import os
import secrets
import sys
from collections.abc import Iterator
from dataclasses import dataclass
from types import TracebackType
from typing import IO, Any

from ttctl.errors import Fail

from ..model import Sample

# ordinary new files get 0666 & ~umask (like `touch`), not mkstemp's 0600
_FILE_MODE = 0o666


@dataclass
class Recording:
    """A recording opened for replay. `samples` is lazy (the file is read as it is consumed) and
    in recording order, which is time order for every ttctl source. `truncated` is True when the
    file ended early (a crash while recording): the samples stop at the last complete piece;
    `damage` says in words what is wrong with a file that can still be partly read."""

    frame: str  # "ros" (REP-103) or "openvr": the axes every pose in the file is expressed in
    parent_frame: str  # the world frame poses are relative to (tf parent)
    meta: dict[str, Any]
    samples: Iterator[Sample]
    format: str = ""  # one of FORMATS
    truncated: bool = False
    damage: str = ""  # what is wrong with a file that can still be partly read ("" when nothing is)

    def __post_init__(self) -> None:
        if self.truncated and not self.damage:
            self.damage = "cut short (the recording was interrupted): its last line is incomplete"


class Writer:
    """Writes samples to one recording. Use `close()` to finish it (only then does the file
    appear under its final name) or `abort()` to throw it away; as a context manager it closes
    on success and aborts on any exception, Ctrl-C included."""

    def __init__(self) -> None:
        self.counts: dict[str, int] = {}  # messages/rows written, per topic (ROS) or kind (text)
        self._done = False

    def write(self, s: Sample) -> None:
        raise NotImplementedError

    def close(self) -> None:
        raise NotImplementedError

    def abort(self) -> None:
        raise NotImplementedError

    def _count(self, key: str) -> None:
        self.counts[key] = self.counts.get(key, 0) + 1

    def _check_open(self) -> None:
        if self._done:
            raise RuntimeError("write() after close() or abort()")

    def __enter__(self) -> Writer:
        return self

    def __exit__(self, exc_type: type[BaseException] | None, exc: BaseException | None,
                 tb: TracebackType | None) -> None:
        if exc_type is None:
            self.close()
        else:
            self.abort()


class AtomicFile:
    """A temporary file next to `final`, renamed over it by `commit()`, removed by `discard()`.

    With `create=False` only a free temporary name is chosen and the caller's library creates
    the file itself (rosbags' bag writer insists on creating its file, exclusively)."""

    def __init__(self, final: str, *, create: bool = True) -> None:
        self.final = os.path.abspath(final)
        self.file: IO[bytes] | None = None
        folder, name = os.path.split(self.final)
        for _ in range(100):
            tmp = os.path.join(folder, f".{name}.{secrets.token_hex(4)}.tmp")
            if not create:
                if os.path.lexists(tmp):
                    continue
                self.tmp = tmp
                return
            try:
                fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_BINARY", 0), _FILE_MODE)
            except FileExistsError:
                continue
            except OSError as e:
                raise Fail(f"cannot create a file in {folder}: {e.strerror}") from None
            self.tmp = tmp
            self.file = os.fdopen(fd, "wb")
            return
        raise Fail(f"cannot find a free temporary name in {folder}")

    def commit(self) -> None:
        """Flush and fsync the data, then rename it to the final name (and fsync the folder, so
        the rename itself survives a power cut)."""
        if self.file is not None:
            self.file.flush()
            os.fsync(self.file.fileno())
            self.file.close()
            self.file = None
        else:  # written and closed by a library: fsync through a descriptor of our own
            fd = os.open(self.tmp, os.O_RDWR | getattr(os, "O_BINARY", 0))
            try:
                os.fsync(fd)
            finally:
                os.close(fd)
        os.replace(self.tmp, self.final)
        _fsync_folder(os.path.dirname(self.final))

    def discard(self) -> None:
        if self.file is not None:
            with contextlib.suppress(OSError):
                self.file.close()
            self.file = None
        with contextlib.suppress(FileNotFoundError):
            os.unlink(self.tmp)


def _fsync_folder(folder: str) -> None:
    if sys.platform == "win32":
        return
    try:
        fd = os.open(folder, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)


def check_frames(frame: str, parent_frame: str) -> None:
    from ..model import FRAMES

    if frame not in FRAMES:
        raise Fail(f"unknown frame {frame!r}: choose from {', '.join(FRAMES)}")
    if not parent_frame or any(c.isspace() for c in parent_frame):
        raise Fail(f"bad parent frame {parent_frame!r}: a tf frame name has no spaces")


__all__ = ["AtomicFile", "Recording", "Writer", "check_frames"]
