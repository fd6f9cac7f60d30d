"""The dialect a link command speaks: `--dialect FILE.xml` with `-I DIR`, or $TTCTL_DIALECT
(and $TTCTL_INCLUDE, folders separated by the path separator) set once; ttctl's shipped ttapi
without either."""

from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import Any

from ..errors import Fail
from .common import err

ENV_DIALECT = "TTCTL_DIALECT"
ENV_INCLUDE = "TTCTL_INCLUDE"


def load_bindings(dialect: Path | None, include_dirs: list[Path] | None = None) -> Any:
    """The dialect a link command speaks (a ttctl.wire.bindings.Bindings): ttctl's shipped ttapi
    without --dialect, else the user's, generated on first use and cached (ttctl.codegen.cache).
    Refused in one line (Fail, exit 2), after the dialect's own diagnostics, if it does not
    validate, lacks the runtime's messages, or cannot be imported beside ttctl. The package's
    folder goes first on sys.path, so that plugins import it by its name, as their skeleton
    does."""
    from ..wire.bindings import Bindings

    include = [str(d) for d in include_dirs or []]
    if dialect is None:
        if include:
            raise Fail("-I is for --dialect: give the dialect it is for")
        import ttapi

        return Bindings(ttapi)
    for d in include:
        if not os.path.isdir(d):
            raise Fail(f"-I {d}: {'not a directory' if os.path.exists(d) else 'no such directory'}")
    shown = str(dialect)
    if os.path.isfile(shown) and _same_file(shown, _shipped("ttapi")):
        import ttapi

        return Bindings(ttapi, source=shown)
    from ..codegen.cache import DialectRefused, python_bindings
    from ..wire import contract

    def check(model: Any) -> str | None:
        messages = {m.name: (m.id, m.crc_extra) for m in model.messages if m.complete}
        return contract.problem(messages, f"--dialect {shown}")

    try:
        found = python_bindings(shown, include, check)
    except DialectRefused as e:
        for line in e.lines:
            print(line, file=sys.stderr)
        raise Fail(e.message if e.message.startswith("--dialect") else f"--dialect {e.message}") from None
    except OSError as e:
        raise Fail(f"--dialect {shown}: the bindings cache: {e.strerror or e}") from None
    for note in found.notes:
        err(f"note: {note}")
    import importlib

    folder = str(found.folder)
    if folder not in sys.path:
        sys.path.insert(0, folder)
    try:
        package = importlib.import_module(found.package)
    except Exception as e:  # a damaged cache entry: say where, never a traceback
        raise Fail(f"--dialect {shown}: cannot import its bindings from {folder}: {type(e).__name__}: {e} "
                   "(delete that folder to have them made again)") from None
    where = os.path.realpath(os.path.dirname(package.__file__ or ""))
    if where != os.path.realpath(os.path.join(folder, found.package)):
        raise Fail(f"--dialect {shown}: its package {found.package} is already imported from elsewhere "
                   f"({package.__file__}); rename the dialect file")
    package.__ttctl_cached__ = True  # type: ignore[attr-defined]
    b = Bindings(package, source=shown)
    problem = contract.problem(contract.of_registry(b.registry), f"--dialect {shown}")
    if problem:
        raise Fail(problem)
    return b


def _shipped(name: str) -> str:
    from ..resources import shipped_dialect

    return str(shipped_dialect(name))


def _same_file(a: str, b: str) -> bool:
    try:
        return os.path.samefile(a, b)
    except OSError:
        return False
