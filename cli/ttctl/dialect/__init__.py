"""Dialect XML: loading, the model, validation.

The names below load their modules on first use, so that a command that needs one small piece
(the include rule, say) does not pay for the checks and the schema."""

from __future__ import annotations

from importlib import import_module
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from .checks import CheckOptions, check_dialect
    from .diagnostics import Diagnostic, Reporter
    from .loader import LoadError, LoadResult, load_dialect
    from .model import Dialect, Enum, EnumEntry, Field, Message

_WHERE = {
    "CheckOptions": "checks", "check_dialect": "checks",
    "Diagnostic": "diagnostics", "Reporter": "diagnostics",
    "LoadError": "loader", "LoadResult": "loader", "load_dialect": "loader",
    "Dialect": "model", "Enum": "model", "EnumEntry": "model", "Field": "model", "Message": "model",
}


def __getattr__(name: str) -> Any:
    module = _WHERE.get(name)
    if module is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return getattr(import_module(f".{module}", __name__), name)


__all__ = [
    "CheckOptions",
    "Diagnostic",
    "Dialect",
    "Enum",
    "EnumEntry",
    "Field",
    "LoadError",
    "LoadResult",
    "Message",
    "Reporter",
    "check_dialect",
    "load_dialect",
]
