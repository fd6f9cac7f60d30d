"""CSV recordings (the columns are described in `text`, with JSONL): one header row, then one
row per sample, numbers in Python's shortest round-trip form. Kept apart from the JSONL code only
to keep files short; both share `text`'s line writer and field checks."""

from __future__ import annotations

import csv
from collections.abc import Callable, Iterator
from typing import Any

from ttctl.errors import Fail

from ..model import BUTTONS, FRAMES, ControllerSample, PoseSample, Sample
from .base import Recording
from .text import (
    COLUMNS,
    CONTROLLER_COLUMNS,
    DEFAULT_PARENT,
    POSE_COLUMNS,
    _Bad,
    _json_device,
    _last_line,
    _lines,
    _LineWriter,
)


class CsvWriter(_LineWriter):
    def __init__(self, path: str | None, frame: str, parent_frame: str, meta: dict[str, Any]) -> None:
        super().__init__(path)
        self.frame, self.parent = frame, parent_frame
        # csv.writer hands each whole row (terminator included) to one write() call
        self._csv = csv.writer(_RowSink(self.write_line), lineterminator="\n")
        try:
            self._csv.writerow(COLUMNS)
        except BaseException:
            self.abort()
            raise

    def write(self, s: Sample) -> None:
        self._check_open()
        d = s.device
        head = [repr(s.t), "pose" if isinstance(s, PoseSample) else "controller", self.frame, self.parent, d.frame,
                d.kind, str(d.index), d.role, d.serial]
        if isinstance(s, PoseSample):
            row = [*head, _b(s.valid), _b(s.connected),
                   *(repr(float(v)) for v in (*s.position, *s.orientation, *s.velocity, *s.angular_velocity)),
                   *([""] * len(CONTROLLER_COLUMNS))]
        else:
            row = [*head, "", "", *([""] * len(POSE_COLUMNS)), str(s.packet), repr(float(s.trigger)),
                   repr(float(s.pad_x)), repr(float(s.pad_y)), *(_b(s.buttons.get(b, False)) for b in BUTTONS)]
        self._csv.writerow(row)
        self._count(row[1])


class _RowSink:
    """What csv.writer writes to: each row arrives whole, in one call."""

    def __init__(self, write: Callable[[str], None]) -> None:
        self.write = write


def _b(v: bool) -> str:
    return "1" if v else "0"


# ---------------------------------------------------------------------------------------------- reading


def read_csv(path: str) -> Recording:
    with open(path, "rb") as f:
        rows = csv.reader(text for _, text, _ in _lines(f, path, {}))
        columns = _csv_header(rows, path)
        first = next(rows, None)
    if first is not None and len(first) == len(columns):
        row = dict(zip(columns, first, strict=True))
        frame, parent = row["frame"], row["parent"]
    else:
        frame, parent = "ros", DEFAULT_PARENT
    if frame not in FRAMES:
        raise Fail(f"{path} line 2: frame {frame!r}, expected one of {', '.join(FRAMES)}")
    truncated = False
    last = _last_line(path)
    if last is not None:
        try:
            cells = next(csv.reader([last.decode("utf-8")]))
            _csv_sample(dict(zip(columns, cells, strict=True)), frame, parent)
        except (ValueError, UnicodeDecodeError, _Bad, StopIteration, csv.Error):
            truncated = True
    return Recording(frame, parent, {}, _csv_samples(path, frame, parent, truncated), "csv", truncated)


def _csv_header(rows: Iterator[list[str]], path: str) -> list[str]:
    try:
        columns = next(rows)
    except StopIteration:
        raise Fail(f"{path}: empty file") from None
    except csv.Error as e:
        raise Fail(f"{path} line 1: not CSV ({e})") from None
    missing = [c for c in COLUMNS if c not in columns]
    if missing:
        raise Fail(f"{path}: not a ttctl hmd CSV: the header lacks {', '.join(missing[:6])}"
                   f"{' ...' if len(missing) > 6 else ''} (expected {','.join(COLUMNS[:6])},...)")
    return columns


def _csv_samples(path: str, frame: str, parent: str, truncated: bool) -> Iterator[Sample]:
    state = {"partial": False}
    with open(path, "rb") as f:
        rows = csv.reader(text for _, text, _ in _lines(f, path, state))
        columns = _csv_header(rows, path)
        while True:
            try:
                cells = next(rows)
            except StopIteration:
                return
            except csv.Error as e:
                raise Fail(f"{path} line {rows.line_num}: not CSV ({e})") from None
            if state["partial"] and truncated:
                return
            if not cells:
                continue
            if len(cells) != len(columns):
                raise Fail(f"{path} line {rows.line_num}: {len(cells)} fields, the header has {len(columns)}")
            try:
                yield _csv_sample(dict(zip(columns, cells, strict=True)), frame, parent)
            except (_Bad, ValueError) as e:
                raise Fail(f"{path} line {rows.line_num}: {e}") from None


def _cbool(row: dict[str, str], key: str) -> bool:
    v = row[key].strip().lower()
    if v in ("1", "true"):
        return True
    if v in ("0", "false"):
        return False
    raise _Bad(f"bad {key!r}: {row[key]!r} (expected 1 or 0)")


def _cnum(row: dict[str, str], key: str) -> float:
    try:
        return float(row[key])
    except ValueError:
        raise _Bad(f"bad {key!r}: {row[key]!r} is not a number") from None


def _csv_sample(row: dict[str, str], frame: str, parent: str) -> Sample:
    kind = row["type"]
    if kind not in ("pose", "controller"):
        raise _Bad(f"bad 'type': {kind!r} (expected pose or controller)")
    if row["frame"] != frame:
        raise _Bad(f"frame {row['frame']!r} but the recording is in {frame!r}")
    if row["parent"] != parent:
        raise _Bad(f"parent {row['parent']!r} but the recording's parent frame is {parent!r}")
    try:
        index = int(row["index"])
    except ValueError:
        raise _Bad(f"bad 'index': {row['index']!r}") from None
    device = _json_device({"device": row["device"], "role": row["role"] or "none", "index": index,
                           "serial": row["serial"]}, "hmd")
    t = _cnum(row, "t")
    if kind == "pose":
        p = [_cnum(row, c) for c in POSE_COLUMNS]
        return PoseSample(t, device, _cbool(row, "valid"), _cbool(row, "connected"), (p[0], p[1], p[2]),
                          (p[3], p[4], p[5], p[6]), (p[7], p[8], p[9]), (p[10], p[11], p[12]))
    try:
        packet = int(row["packet"])
    except ValueError:
        raise _Bad(f"bad 'packet': {row['packet']!r}") from None
    return ControllerSample(t, device, packet, _cnum(row, "trigger"), _cnum(row, "pad_x"), _cnum(row, "pad_y"),
                            {b: _cbool(row, b) for b in BUTTONS})


__all__ = ["CsvWriter", "read_csv"]
