"""Diagnostics: `path:line:col: error|warning|note: [CODE] message`, and their JSON form. A note
informs (which shipped file an include used, say): it is neither an error nor a warning."""

from __future__ import annotations

import os
import re
from typing import Literal, NamedTuple

Severity = Literal["error", "warning", "note"]


class SourceText:
    """The text of one dialect file, kept to turn element lines into precise columns."""

    __slots__ = ("_data", "_lines", "path")

    def __init__(self, path: str, data: bytes | None) -> None:
        self.path = path
        self._data = data
        self._lines: list[str] | None = None

    def lines(self) -> list[str]:
        if self._lines is None:
            self._lines = (self._data or b"").decode("utf-8", "replace").splitlines()
        return self._lines

    def locate(self, line: int, tag: str | None, attr: str | None) -> tuple[int, int]:
        """Line and column (1-based) of `<tag` (or of its attribute `attr`) whose start tag ends
        on or before `line` (lxml reports the line where the start tag closes)."""
        lines = self.lines()
        if not tag or not (1 <= line <= len(lines)):
            return line, 1
        start_line, start_col = line, 1
        needle = re.compile(r"<" + re.escape(tag) + r"(?=[\s/>]|$)")
        for ln in range(line, max(0, line - 40), -1):
            hits = list(needle.finditer(lines[ln - 1]))
            if hits:
                start_line, start_col = ln, hits[-1].start() + 1
                break
        else:
            return line, 1
        if attr:
            attr_re = re.compile(r"(?<![\w:.-])" + re.escape(attr) + r"\s*=")
            ln, col0 = start_line, start_col - 1
            while ln <= min(len(lines), line + 1):
                m = attr_re.search(lines[ln - 1], col0)
                if m:
                    return ln, m.start() + 1
                ln, col0 = ln + 1, 0
        return start_line, start_col


class Loc(NamedTuple):
    """Where something is defined: a file, the line lxml gave, and what to point at.
    (A tuple: the loader makes tens of thousands of these.)"""

    source: SourceText
    line: int
    tag: str | None = None
    attr: str | None = None

    @property
    def path(self) -> str:
        return self.source.path

    def position(self) -> tuple[int, int]:
        return self.source.locate(self.line, self.tag, self.attr)

    def at(self, attr: str | None) -> Loc:
        return Loc(self.source, self.line, self.tag, attr)

    def short(self) -> str:
        line, col = self.position()
        return f"{display_path(self.path)}:{line}:{col}"


class Diagnostic(NamedTuple):
    path: str
    line: int
    col: int
    severity: Severity
    code: str
    message: str
    name: str | None = None

    def text(self) -> str:
        return f"{display_path(self.path)}:{self.line}:{self.col}: {self.severity}: [{self.code}] {self.message}"

    def as_json(self) -> dict[str, object]:
        return {
            "path": display_path(self.path),
            "line": self.line,
            "col": self.col,
            "severity": self.severity,
            "code": self.code,
            "message": self.message,
            "name": self.name,
        }


def display_path(path: str) -> str:
    """Paths under the working directory are shown relative to it, as compilers do."""
    if not os.path.isabs(path):
        return path
    try:
        rel = os.path.relpath(path)
    except ValueError:
        return path
    return path if rel.startswith("..") else rel


class Reporter:
    """Collects diagnostics; cheap when there are none."""

    def __init__(self) -> None:
        self.items: list[Diagnostic] = []

    def add(self, loc: Loc, severity: Severity, code: str, message: str, name: str | None = None) -> None:
        line, col = loc.position()
        self.items.append(Diagnostic(loc.path, line, col, severity, code, message, name))

    def error(self, loc: Loc, code: str, message: str, name: str | None = None) -> None:
        self.add(loc, "error", code, message, name)

    def warning(self, loc: Loc, code: str, message: str, name: str | None = None) -> None:
        self.add(loc, "warning", code, message, name)

    def note(self, loc: Loc, code: str, message: str, name: str | None = None) -> None:
        self.add(loc, "note", code, message, name)

    def raw(self, path: str, line: int, col: int, severity: Severity, code: str, message: str,
            name: str | None = None) -> None:
        self.items.append(Diagnostic(path, line, col, severity, code, message, name))

    @property
    def errors(self) -> int:
        return sum(1 for d in self.items if d.severity == "error")

    @property
    def warnings(self) -> int:
        return sum(1 for d in self.items if d.severity == "warning")

    @property
    def notes(self) -> int:
        return sum(1 for d in self.items if d.severity == "note")

    def sorted(self, file_order: list[str]) -> list[Diagnostic]:
        rank = {p: i for i, p in enumerate(file_order)}
        return sorted(self.items, key=lambda d: (rank.get(d.path, len(rank)), d.path, d.line, d.col))
