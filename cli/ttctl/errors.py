"""The one error type every command may raise for a clear one-line failure.

A leaf module: the library and the CLI both import it, so nothing below `app.py` ever
imports the CLI.
"""

from __future__ import annotations


class Fail(Exception):
    """A clear one-line failure: printed as `ttctl: error: ...`, exits with `code`."""

    def __init__(self, message: str, code: int = 2) -> None:
        super().__init__(message)
        self.code = code


__all__ = ["Fail"]
