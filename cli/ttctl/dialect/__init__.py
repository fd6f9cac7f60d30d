"""Dialect XML: loading, the model, validation."""

from .checks import CheckOptions, check_dialect
from .diagnostics import Diagnostic, Reporter
from .loader import LoadError, LoadResult, load_dialect
from .model import Dialect, Enum, EnumEntry, Field, Message

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
