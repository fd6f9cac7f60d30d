"""The `ttctl` command line: parses options, calls the library, prints.

Heavy modules (lxml, jinja2, rich, pymavlink) are imported inside the commands that need
them, so that `ttctl validate` starts fast.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import Annotated

import typer

from . import __version__

app = typer.Typer(
    name="ttctl",
    help="Toolchain for custom MAVLink 2 links over DJI Data Transparent Transmission.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
    context_settings={"help_option_names": ["-h", "--help"]},
)
bench_app = typer.Typer(help="Benchmarks that print ratios against a named peer, measured in one run.",
                        no_args_is_help=True)
app.add_typer(bench_app, name="bench")


# Commands that leave nothing to clean up set this: main() then skips interpreter teardown
# (freeing tens of thousands of objects), which is a tenth of `ttctl validate`'s run time.
_fast_exit = False


class Fail(Exception):
    """A clear one-line failure: printed as `ttctl: error: ...`, exits with `code`."""

    def __init__(self, message: str, code: int = 2) -> None:
        super().__init__(message)
        self.code = code


def _version(value: bool) -> None:
    if value:
        print(f"ttctl {__version__}")
        raise typer.Exit()


@app.callback()
def _root(
    version: Annotated[
        bool | None, typer.Option("--version", callback=_version, is_eager=True, help="Print the version.")
    ] = None,
) -> None:
    pass


IncludeOpt = Annotated[
    list[Path] | None,
    typer.Option("-I", "--include-dir", help="Extra directory to search for <include> files (repeatable)."),
]


@app.command()
def validate(
    dialect: Annotated[Path, typer.Argument(help="Dialect XML file.", show_default=False)],
    include: IncludeOpt = None,
    mtu: Annotated[int, typer.Option(help="Packet size budget in bytes; warn for messages of this dialect whose "
                                          "largest frame does not fit one packet (0: off).", min=0, max=65535)] = 100,
    signed: Annotated[bool, typer.Option("--signed", help="Budget for signed frames (+13 bytes).")] = False,
    fmt: Annotated[str, typer.Option("--format", help="text or json.")] = "text",
    all_warnings: Annotated[bool, typer.Option("--all-warnings",
                                               help="Also show warnings inside pymavlink's own dialects.")] = False,
) -> None:
    """Validate a MAVLink 2 dialect: XSD and semantic checks, all problems in one run.

    Exit status: 0 no errors (warnings allowed), 1 errors, 2 unreadable input or bad options.
    """
    if fmt not in ("text", "json"):
        raise Fail(f"--format must be 'text' or 'json', not '{fmt}'")
    from .validate import run_validate

    global _fast_exit
    _fast_exit = True
    code = run_validate(str(dialect), [str(p) for p in include or []], mtu=mtu, signed=signed, fmt=fmt,
                        all_warnings=all_warnings)
    raise typer.Exit(code)


@app.command()
def gen(
    dialect: Annotated[Path | None, typer.Argument(help="Dialect XML file (default: dialects/ttapi.xml).",
                                                     show_default=False)] = None,
    lang: Annotated[str, typer.Option("--lang", help="Comma-separated: python,cpp,java.")] = "python,cpp,java",
    out: Annotated[Path, typer.Option("-o", "--out", help="Output directory.")] = Path("generated"),
    check: Annotated[bool, typer.Option("--check", help="Write nothing; list files that differ; exit 1 if any.")]
    = False,
    force_skeletons: Annotated[bool, typer.Option("--force-skeletons",
                                                  help="Overwrite skeletons (code you edit) too.")] = False,
    include: IncludeOpt = None,
    templates: Annotated[Path | None, typer.Option("--templates",
                                                      help="Folder of templates overriding ttctl's, by name.")] = None,
) -> None:
    """Generate Python, C++ and Java bindings, skeletons and conformance programs.

    Bindings are rewritten when they change; skeletons (handler and command stubs you fill in)
    are written once. Refuses a dialect with validation errors.
    """
    from .gen import GenError, run_gen

    try:
        code = run_gen(str(dialect) if dialect else None, lang, str(out), check, force_skeletons,
                       [str(p) for p in include or []], str(templates) if templates else None)
    except GenError as e:
        raise Fail(str(e), e.code) from None
    raise typer.Exit(code)


@bench_app.command("validate")
def bench_validate(
    dialect: Annotated[Path | None, typer.Argument(help="Dialect XML (default: pymavlink's all.xml).")] = None,
    runs: Annotated[int, typer.Option(help="Runs of each command.", min=1, max=200)] = 15,
    json_out: Annotated[bool, typer.Option("--json", help="Print the result as JSON.")] = False,
) -> None:
    """Whole-process time of `ttctl validate` against `mavgen.py --lang Python3 --wire-protocol 2.0`."""
    from .bench.validate import run

    run(str(dialect) if dialect else None, runs, json_out)


@bench_app.command("gen")
def bench_gen(
    dialect: Annotated[Path | None, typer.Argument(help="Dialect XML (default: pymavlink's all.xml).")] = None,
    runs: Annotated[int, typer.Option(help="Runs of each command.", min=1, max=50)] = 5,
    json_out: Annotated[bool, typer.Option("--json", help="Print the result as JSON.")] = False,
) -> None:
    """Whole-process time of `ttctl gen` (three languages) against mavgen's Python3 + C++11 + Java."""
    from .bench.gen import run

    run(str(dialect) if dialect else None, runs, json_out)


@bench_app.command("codec")
def bench_codec(
    seconds: Annotated[float, typer.Option(help="Approximate time budget per measurement.", min=0.05)] = 0.5,
    rounds: Annotated[int, typer.Option(help="Interleaved rounds; medians are reported.", min=1, max=50)] = 5,
    cpp: Annotated[bool, typer.Option("--cpp/--no-cpp", help="Also build and compare the C++ decoder with "
                                                             "mavgen's C library (needs g++).")] = True,
    json_out: Annotated[bool, typer.Option("--json", help="Print the result as JSON.")] = False,
) -> None:
    """Generated Python decode/encode against pymavlink, and generated C++ decode against mavgen's C."""
    from .bench.codec import run

    run(seconds, rounds, cpp, json_out)


def main() -> None:
    """Console entry point: clean one-line errors instead of tracebacks."""
    try:  # typer >= 0.26 vendors click
        from typer._click.exceptions import ClickException
    except ImportError:
        from click.exceptions import ClickException

    try:
        code = app(standalone_mode=False)
    except ClickException as e:
        # usage errors as one line, not a box
        ctx = getattr(e, "ctx", None)
        where = ctx.command_path if ctx is not None else "ttctl"
        msg = e.format_message()
        hint = " Did you mean"
        if msg.count(hint) > 1:  # typer and click both add the suggestion
            msg = msg[: msg.rindex(hint)]
        print(f"{where}: error: {msg} (see '{where} --help')", file=sys.stderr)
        sys.exit(e.exit_code)
    except typer.Abort:
        print("ttctl: aborted", file=sys.stderr)
        sys.exit(1)
    except Fail as e:
        print(f"ttctl: error: {e}", file=sys.stderr)
        sys.exit(e.code)
    except KeyboardInterrupt:
        print("ttctl: interrupted", file=sys.stderr)
        sys.exit(130)
    except BrokenPipeError:
        sys.stderr.close()
        sys.exit(1)
    except Exception as e:
        if os.environ.get("TTCTL_DEBUG"):
            raise
        print(f"ttctl: internal error: {type(e).__name__}: {e} (set TTCTL_DEBUG=1 for a traceback)",
              file=sys.stderr)
        sys.exit(3)
    code = code if isinstance(code, int) else 0
    if _fast_exit:
        try:
            sys.stdout.flush()
            sys.stderr.flush()
        except BrokenPipeError:
            code = code or 1
        os._exit(code)
    sys.exit(code)
