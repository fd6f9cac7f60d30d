"""Code generation: Python, C++ and Java bindings, skeletons and conformance programs; and the
cache of Python bindings generated on the fly for the link commands (cache.py). The engine's
names load on first use, so that a warm cache lookup does not import the renderer."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from .engine import LANGUAGES, Output, WriteReport, render, write_tree


def __getattr__(name: str) -> Any:
    if name in __all__:
        from . import engine

        return getattr(engine, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = ["LANGUAGES", "Output", "WriteReport", "render", "write_tree"]
