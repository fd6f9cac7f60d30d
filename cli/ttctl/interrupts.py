"""Ctrl-C, remembered. A KeyboardInterrupt that lands while Python runs a finalizer or a
weakref callback (the import system's module locks have one) is printed as "Exception ignored"
and then lost: the program would go on as if nothing happened. The handler here records the
interrupt before raising it, so that a long-running command can still stop when its loop starts
(`commands.common.Signals`), and the hook keeps such a lost one quiet. A leaf module: cheap to
import before anything else.
"""

from __future__ import annotations

import sys
from typing import Any

_seen = False


def on_sigint(signum: int, frame: object) -> None:
    """The SIGINT handler while no loop of our own handles it: remember, then raise."""
    global _seen
    _seen = True
    raise KeyboardInterrupt


def seen() -> bool:
    """Has a Ctrl-C arrived (even one Python swallowed)?"""
    return _seen


def _quiet_lost_interrupt(unraisable: Any) -> None:
    if isinstance(unraisable.exc_value, KeyboardInterrupt):
        return  # recorded by on_sigint; the command stops when it next looks
    _default_hook(unraisable)


_default_hook = sys.unraisablehook


def install() -> None:
    import _signal  # not `signal`: its wrapper converts the old handler to an enum after the new one is live

    _signal.signal(_signal.SIGINT, on_sigint)
    sys.unraisablehook = _quiet_lost_interrupt


__all__ = ["install", "on_sigint", "seen"]
