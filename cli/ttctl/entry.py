"""The console entry point: an interrupt at any moment after the interpreter has started, even
while the heavy modules (typer, rich) are still being imported, ends the program quietly with
exit 130, never a traceback. (`_signal`, the C module, not `signal`: it costs no import time.)"""

import _signal
import os
import sys


def _interrupted(signum: int, frame: object) -> None:
    try:
        sys.stderr.write("ttctl: interrupted\n")
        sys.stderr.flush()
    finally:
        os._exit(130)


def main() -> None:
    try:
        _signal.signal(_signal.SIGINT, _interrupted)  # until the CLI can turn Ctrl-C into a clean exit itself
    except KeyboardInterrupt:  # a Ctrl-C that came while Python was loading this very module
        _interrupted(_signal.SIGINT, None)
    from .app import main as app_main

    app_main()  # installs its own handler inside the block that turns a KeyboardInterrupt into exit 130


__all__ = ["main"]
