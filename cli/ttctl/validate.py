"""`ttctl validate`: load, check, print diagnostics, choose the exit status."""

from __future__ import annotations

import functools
import os
import sys

from .dialect import CheckOptions, Dialect, LoadError, check_dialect, load_dialect
from .dialect.diagnostics import Diagnostic, Reporter, display_path
from .dialect.source import pymavlink_dialects_dir

EXIT_OK, EXIT_ERRORS, EXIT_UNREADABLE = 0, 1, 2


def include_dir_problem(path: str) -> str | None:
    """Why an -I directory cannot be searched, or None."""
    if not os.path.exists(path):
        return f"-I {path}: no such directory"
    if not os.path.isdir(path):
        return f"-I {path}: not a directory"
    return None


def load_and_check(path: str, include_dirs: list[str], mtu: int = 100,
                   signed: bool = False) -> tuple[Dialect, Reporter, list[str]]:
    """Load and check a dialect; LoadError if the root file is unreadable."""
    import gc

    # The model is a few objects per element, none of them garbage: the cyclic collector would
    # only walk the growing heap again and again (a tenth of the time on large dialects).
    collecting = gc.isenabled()
    gc.disable()
    try:
        result = load_dialect(path, include_dirs)
        assert result.dialect is not None
        check_dialect(result.dialect, result.reporter, CheckOptions(mtu=mtu, signed=signed))
    finally:
        if collecting:
            gc.enable()
    return result.dialect, result.reporter, result.file_order


def user_warnings(rep: Reporter, root: str) -> int:
    """Warnings the user can act on: not those inside pymavlink's own definitions (unless the
    root dialect is one of them)."""
    if _in_pymavlink(root):
        return rep.warnings
    return sum(1 for d in rep.items if d.severity == "warning" and not _in_pymavlink(d.path))


@functools.lru_cache(maxsize=64)
def _in_pymavlink(path: str) -> bool:  # cached: asked once per diagnostic, of a few paths
    pm = pymavlink_dialects_dir()
    return pm is not None and os.path.dirname(os.path.realpath(path)) == os.path.realpath(pm)


def run_validate(path: str, include_dirs: list[str], mtu: int, signed: bool, fmt: str,
                 all_warnings: bool = False) -> int:
    try:
        dialect, rep, order = load_and_check(path, include_dirs, mtu, signed)
    except LoadError as e:
        diag = Diagnostic(e.path, e.line, e.col, "error", e.code, e.message)
        _emit([diag], fmt, path, None, EXIT_UNREADABLE, 0)
        return EXIT_UNREADABLE
    diags = rep.sorted(order)
    hidden = 0
    if not all_warnings and not _in_pymavlink(path):
        # warnings inside the definitions pymavlink ships are not the user's to fix
        kept = [d for d in diags if d.severity != "warning" or not _in_pymavlink(d.path)]
        hidden = len(diags) - len(kept)
        diags = kept
    code = EXIT_ERRORS if rep.errors else EXIT_OK
    _emit(diags, fmt, path, dialect, code, hidden)
    return code


def _emit(diags: list[Diagnostic], fmt: str, path: str, dialect: Dialect | None, code: int, hidden: int) -> None:
    errors = sum(d.severity == "error" for d in diags)
    warnings = sum(d.severity == "warning" for d in diags)
    out = sys.stdout
    if fmt == "json":
        import json

        doc: dict[str, object] = {
            "dialect": display_path(path),
            "ok": errors == 0 and code != EXIT_UNREADABLE,
            "errors": errors,
            "warnings": warnings,
            "notes": len(diags) - errors - warnings,
            "hidden_warnings": hidden,
            "diagnostics": [d.as_json() for d in diags],
        }
        if dialect is not None:
            doc["files"] = [display_path(f.path) for f in dialect.files]
            doc["messages"] = len(dialect.messages)
            doc["own_messages"] = len(dialect.root.messages)
            doc["enums"] = len(dialect.enums)
        out.write(json.dumps(doc, indent=2) + "\n")
        return
    for d in diags:
        out.write(d.text() + "\n")
    if dialect is None:
        return
    own = len(dialect.root.messages)
    summary = (f"{display_path(path)}: {errors} error{'s' * (errors != 1)}, {warnings} warning{'s' * (warnings != 1)}"
               f" ({len(dialect.messages)} messages, {own} in this file; {len(dialect.enums)} enums; "
               f"{len(dialect.files)} file{'s' * (len(dialect.files) != 1)})")
    if hidden:
        summary += f"; {hidden} warning{'s' * (hidden != 1)} in pymavlink's own dialects hidden (--all-warnings)"
    out.write(summary + "\n")
