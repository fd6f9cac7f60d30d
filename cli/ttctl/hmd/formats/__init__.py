"""Recordings of VR pose streams: JSONL, CSV, ROS 2 MCAP and ROS 1 bag writers, and the readers
that replay them.

    fmt = format_for(path, fmt)         # --format wins, else the extension; stdout is jsonl
    check_output(path, fmt)             # before any work: the file can be written
    with open_writer(path, fmt, "ros", "world", meta) as w:
        for s in samples: w.write(s)    # closed on success, thrown away on an exception
    rec = read_recording(path)          # rec.frame, rec.parent_frame, rec.meta, rec.samples

Files are written atomically (see `base`); the field lists of each format are in `text`
(JSONL, CSV) and `ros` (the topics of MCAP and bag). The ROS messages are encoded by `codecs`,
MCAP chunks written and walked by `mcapio`: both exist for speed (the reasons are in each).
MCAP and bag need the `record` extra (rosbags, mcap); JSONL and CSV need nothing beyond ttctl.
"""

from __future__ import annotations

import errno
import os
import stat
import time
from collections.abc import Callable, Iterator
from typing import Any

from ttctl.errors import Fail

from ..model import Sample
from .base import Recording, Writer, check_frames

FORMATS = ("jsonl", "csv", "mcap", "bag")
EXTENSIONS = {".jsonl": "jsonl", ".ndjson": "jsonl", ".csv": "csv", ".mcap": "mcap", ".bag": "bag"}
_EXTRA = "pip install 'ttctl[record]'"
MAX_BYTES = 64 * 2**30  # a recording bigger than this is not one (10 minutes of MCAP are ~45 MB)
_A = {"jsonl": "a JSONL file", "csv": "a CSV file", "mcap": "an MCAP file", "bag": "a ROS 1 bag"}


def format_for(path: str | None, fmt: str | None) -> str:
    """The format to write: `fmt` if given, else from the extension; no path (stdout) is jsonl."""
    if fmt:
        name = fmt.strip().lower()
        if name not in FORMATS:
            raise Fail(f"unknown format {fmt!r}: choose from {', '.join(FORMATS)}")
    elif path is None:
        name = "jsonl"
    else:
        ext = os.path.splitext(path)[1].lower()
        if ext not in EXTENSIONS:
            raise Fail(f"cannot tell the format of {path!r} from its extension: name it .jsonl, .csv, .mcap or "
                       f".bag, or give --format ({', '.join(FORMATS)})")
        name = EXTENSIONS[ext]
    if path is None and name in ("mcap", "bag"):
        raise Fail(f"--format {name} writes a file, not a stream: give -o FILE.{name}")
    return name


def _extra_missing(fmt: str) -> str | None:
    """Why the record extra cannot be used (None when it can)."""
    modules = ("rosbags.typesys", "rosbags.rosbag1") if fmt == "bag" else ("rosbags.typesys", "mcap.writer")
    for module in modules:
        try:
            __import__(module)
        except ImportError as e:
            return f"{e.name or module} is missing"
    return None


def check_output(path: str | None, fmt: str) -> None:
    """Refuse, before any work is done, an output that cannot be written. Creates nothing."""
    if fmt not in FORMATS:
        raise Fail(f"unknown format {fmt!r}: choose from {', '.join(FORMATS)}")
    if fmt in ("mcap", "bag"):
        if path is None:
            raise Fail(f"--format {fmt} writes a file, not a stream: give -o FILE.{fmt}")
        why = _extra_missing(fmt)
        if why:
            raise Fail(f"--format {fmt} needs the recording extra ({why}): {_EXTRA}")
    if path is None:
        return
    if not path or path.endswith(os.sep) or os.path.isdir(path):
        raise Fail(f"{path}: is a directory; give a file name")
    if fmt in ("mcap", "bag") and os.path.exists(path) and not os.path.isfile(path):
        raise Fail(f"{path}: not a regular file ({fmt} files are written with seeks and renamed into place)")
    folder = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(folder):
        raise Fail(f"{path}: folder {folder} does not exist")
    if not os.access(folder, os.W_OK | os.X_OK):
        raise Fail(f"{path}: cannot write in folder {folder} (permission denied)")


def await_reader(path: str | None, stopped: Callable[[], bool]) -> int | None:
    """When `path` is a FIFO, wait (interruptibly: `stopped` is polled) until a reader opens it and
    return a write descriptor that keeps it open until the writer has opened it too; None for
    anything else. A blocking open() would wait in the kernel, deaf to Ctrl-C. Fail when stopped."""
    if path is None:
        return None
    try:
        if not stat.S_ISFIFO(os.stat(path).st_mode):
            return None
    except OSError:
        return None
    while True:
        try:
            return os.open(path, os.O_WRONLY | os.O_NONBLOCK | getattr(os, "O_CLOEXEC", 0))
        except OSError as e:
            if e.errno != errno.ENXIO:  # ENXIO: no reader yet
                raise Fail(f"{path}: cannot write ({e.strerror})") from None
        if stopped():
            raise Fail(f"{path}: stopped while waiting for a reader of this FIFO (nothing recorded)", 130)
        time.sleep(0.05)


def open_writer(path: str | None, fmt: str, frame: str, parent_frame: str, meta: dict[str, Any]) -> Writer:
    """A writer for samples already expressed in `frame` ("ros" or "openvr"); path None is stdout
    (jsonl and csv only), and so is a path that exists and is no regular file (/dev/null, a FIFO):
text is written straight into it."""
    check_frames(frame, parent_frame)
    if path is not None and os.path.isdir(path):
        raise Fail(f"{path}: is a directory; give a file name")
    if fmt == "jsonl":
        from .text import JsonlWriter

        return JsonlWriter(path, frame, parent_frame, meta)
    if fmt == "csv":
        from .csvtext import CsvWriter

        return CsvWriter(path, frame, parent_frame, meta)
    if fmt not in FORMATS:
        raise Fail(f"unknown format {fmt!r}: choose from {', '.join(FORMATS)}")
    if path is None:
        raise Fail(f"--format {fmt} writes a file, not a stream: give -o FILE.{fmt}")
    why = _extra_missing(fmt)
    if why:
        raise Fail(f"--format {fmt} needs the recording extra ({why}): {_EXTRA}")
    if os.path.exists(path) and not os.path.isfile(path):
        raise Fail(f"{path}: not a regular file ({fmt} files are written with seeks and renamed into place)")
    if fmt == "mcap":
        from .mcapfile import McapWriter

        return McapWriter(path, frame, parent_frame, meta)
    from .bagfile import BagWriter

    return BagWriter(path, frame, parent_frame, meta)


def sniff(head: bytes) -> str | None:
    """The format a file's first bytes show, if any."""
    from .bagfile import MAGIC as BAG
    from .mcapfile import MAGIC as MCAP
    from .text import COLUMNS

    if head.startswith(MCAP):
        return "mcap"
    if head.startswith(BAG):
        return "bag"
    text = head.lstrip(b"\xef\xbb\xbf \t\r\n")
    if text.startswith(b"{"):
        return "jsonl"
    if text.startswith(",".join(COLUMNS[:4]).encode()):
        return "csv"
    return None


def read_recording(path: str) -> Recording:
    """Open a recording for replay: the format from the extension, else from the content. A file
    that cannot be read is one clear Fail naming it and what is wrong, when opened or while its
    samples are read."""
    try:
        rec = _open_recording(path)
    except Fail as e:
        raise Fail(_one_line(str(e)), e.code) from None
    rec.samples = _one_line_fails(rec.samples)
    return rec


def _one_line(text: str) -> str:
    """Damaged files put arbitrary bytes into names the messages quote: keep them one line."""
    return text.replace("\r", "\\r").replace("\n", "\\n")


def _one_line_fails(samples: Iterator[Sample]) -> Iterator[Sample]:
    try:
        yield from samples  # delegation: no per-sample cost in this frame
    except Fail as e:
        raise Fail(_one_line(str(e)), e.code) from None


def _open_recording(path: str) -> Recording:
    if os.path.isdir(path):
        if not os.path.isfile(os.path.join(path, "metadata.yaml")):
            raise Fail(f"{path}: is a directory without metadata.yaml: not a ROS 2 bag folder")
        why = _extra_missing("mcap")
        if why:
            raise Fail(f"reading {path} needs the recording extra ({why}): {_EXTRA}")
        from .rosreplay import read_ros_folder

        return read_ros_folder(path)
    if os.path.exists(path) and not os.path.isfile(path):
        raise Fail(f"{path}: not a regular file (a recording is a file, or a ROS 2 bag folder)")
    try:
        size = os.path.getsize(path)
    except OSError:
        size = 0
    if size > MAX_BYTES:
        raise Fail(f"{path}: {size} bytes, more than the {MAX_BYTES // 2**30} GiB a recording may have")
    try:
        with open(path, "rb") as f:
            head = f.read(64)
    except IsADirectoryError:
        raise Fail(f"{path}: is a directory") from None
    except FileNotFoundError:
        raise Fail(f"{path}: no such file") from None
    except OSError as e:
        raise Fail(f"{path}: cannot read ({e.strerror})") from None
    if not head:
        raise Fail(f"{path}: empty file")
    seen = sniff(head)
    fmt = EXTENSIONS.get(os.path.splitext(path)[1].lower()) or seen
    if fmt is None:
        raise Fail(f"{path}: not a recording ttctl reads (JSONL, CSV, MCAP or ROS 1 bag)")
    if fmt in ("mcap", "bag") and seen != fmt:
        looks = f"; it looks like {_A[seen]}" if seen else ""
        raise Fail(f"{path}: not {_A[fmt]} (wrong magic bytes at its start{looks})")
    if fmt in ("jsonl", "csv") and seen in ("mcap", "bag"):
        raise Fail(f"{path}: not {_A[fmt]}: it is {_A[seen]}")
    if fmt in ("mcap", "bag"):
        why = _extra_missing(fmt)
        if why:
            raise Fail(f"reading {path} needs the recording extra ({why}): {_EXTRA}")
    if fmt == "jsonl":
        from .text import read_jsonl

        return read_jsonl(path)
    if fmt == "csv":
        from .csvtext import read_csv

        return read_csv(path)
    if fmt == "mcap":
        from .mcapfile import read_mcap

        return read_mcap(path)
    from .bagfile import read_bag

    return read_bag(path)


__all__ = ["EXTENSIONS", "FORMATS", "Recording", "Writer", "check_output", "format_for", "open_writer",
           "read_recording", "sniff"]
