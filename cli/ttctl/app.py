"""The `ttctl` command line: parses options, calls the library, prints.

Heavy modules (lxml, jinja2, rich, pymavlink) are imported inside the commands that need
them, so that `ttctl validate` starts fast.
"""

from __future__ import annotations

import contextlib
import os
import sys
from pathlib import Path
from typing import Annotated, Any

import typer

try:  # typer >= 0.26 vendors click
    from typer._click.exceptions import ClickException
except ImportError:
    from click.exceptions import ClickException

from . import __version__
from .commands.bench_cli import bench_app
from .commands.emulate_cli import emulate_app
from .commands.hmd_cli import hmd_app
from .commands.link_cli import link_app
from .commands.options import (
    AcceptUnsignedOpt,
    DialectIncludeOpt,
    DialectOpt,
    DistanceOpt,
    JsonOpt,
    KeyOpt,
    PipelineOpt,
    PipeRateOpt,
    ProfileFileOpt,
    ProfileOpt,
    RateOpt,
)
from .commands.panels import CHECKS, CODE, DIALECT, FILES, IDS, LINK, OUTPUT, RUN
from .errors import Fail

app = typer.Typer(
    name="ttctl",
    help="Toolchain for custom MAVLink 2 links over DJI Data Transparent Transmission.\n\n"
         "Start with your dialect: ttctl validate dialects/ttapi.xml, then ttctl gen.\n"
         "Every command's --help groups its options, shows an example and says what\n"
         "its exit statuses mean.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
    context_settings={"help_option_names": ["-h", "--help"]},
)
app.add_typer(bench_app, name="bench")


# Commands that leave nothing to clean up set this: main() then skips interpreter teardown
# (freeing tens of thousands of objects), which is a tenth of `ttctl validate`'s run time.
_fast_exit = False


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
    typer.Option("-I", "--include-dir", help="Extra directory to search for <include> files (repeatable).",
                 rich_help_panel=DIALECT),
]


@app.command()
def validate(
    dialect: Annotated[Path, typer.Argument(help="Dialect XML file.", show_default=False)],
    include: IncludeOpt = None,
    mtu: Annotated[int, typer.Option(help="Packet size budget in bytes; warn for messages of this dialect whose "
                                          "largest frame does not fit one packet (0: off).", min=0, max=65535,
                                     rich_help_panel=CHECKS)] = 100,
    signed: Annotated[bool, typer.Option("--signed", help="Budget for signed frames (+13 bytes).",
                                         rich_help_panel=CHECKS)] = False,
    fmt: Annotated[str, typer.Option("--format", help="text or json.", rich_help_panel=OUTPUT)] = "text",
    all_warnings: Annotated[bool, typer.Option("--all-warnings",
                                               help="Also show warnings inside pymavlink's own dialects.",
                                               rich_help_panel=CHECKS)] = False,
) -> None:
    """Validate a MAVLink 2 dialect: XSD and semantic checks, all problems in one run.

    Exit status:
      0    no errors (warnings allowed)
      1    errors in the dialect (each one printed)
      2    unreadable input or bad options
      3    internal error (a bug; TTCTL_DEBUG=1 shows the traceback)
      130  interrupted (Ctrl-C)

    Example:
      ttctl validate dialects/ttapi.xml
    """
    if fmt not in ("text", "json"):
        raise Fail(f"--format must be 'text' or 'json', not '{fmt}'")
    from .validate import include_dir_problem, run_validate

    for d in include or []:
        problem = include_dir_problem(str(d))
        if problem:
            raise Fail(problem)

    global _fast_exit
    _fast_exit = True
    code = run_validate(str(dialect), [str(p) for p in include or []], mtu=mtu, signed=signed, fmt=fmt,
                        all_warnings=all_warnings)
    raise typer.Exit(code)


@app.command()
def gen(
    dialect: Annotated[Path | None, typer.Argument(help="Dialect XML file (default: dialects/ttapi.xml).",
                                                     show_default=False)] = None,
    lang: Annotated[str, typer.Option("--lang", help="Comma-separated: python,cpp,java; xml writes the dialect as one "
                                                  "file, includes resolved (MAVSDK's load_custom_xml, libmav).",
                                      rich_help_panel=CODE)] = "python,cpp,java",
    out: Annotated[Path, typer.Option("-o", "--out", help="Output directory.",
                                      rich_help_panel=OUTPUT)] = Path("generated"),
    check: Annotated[bool, typer.Option("--check", help="Write nothing; list files that differ; exit 1 if any.",
                                        rich_help_panel=OUTPUT)]
    = False,
    force_skeletons: Annotated[bool, typer.Option("--force-skeletons",
                                                  help="Overwrite skeletons (code you edit) too.",
                                                  rich_help_panel=OUTPUT)] = False,
    include: IncludeOpt = None,
    templates: Annotated[Path | None, typer.Option("--templates",
                                                      help="Folder of templates overriding ttctl's, by name.",
                                                   rich_help_panel=CODE)] = None,
    python_package: Annotated[str | None, typer.Option(
        "--python-package", metavar="NAME", show_default=False,
        help="Python package of the bindings (default: the dialect's name).", rich_help_panel=CODE)] = None,
    cpp_namespace: Annotated[str | None, typer.Option(
        "--cpp-namespace", metavar="NAME", show_default=False,
        help="C++ namespace, a or a::b (default: the dialect's name); headers in cpp/a/b/.",
        rich_help_panel=CODE)] = None,
    java_package: Annotated[str | None, typer.Option(
        "--java-package", metavar="NAME", show_default=False,
        help="Java package, a.b.c (default: ttctl.<dialect>).", rich_help_panel=CODE)] = None,
) -> None:
    """Generate Python, C++ and Java bindings, skeletons and conformance programs.

    Bindings are rewritten when they change; skeletons (handler and command stubs
    you fill in) are written once. Refuses a dialect with validation errors.

    Exit status:
      0    written (with --check: nothing differs)
      1    the dialect has errors, nothing written (--check: files differ)
      2    unreadable dialect, bad options or an unusable output folder
      3    internal error (a bug; TTCTL_DEBUG=1 shows the traceback)
      130  interrupted (Ctrl-C): what this run created is taken back

    Example:
      ttctl gen dialects/ttapi.xml -o out --lang python
    """
    from .codegen.engine import Names
    from .gen import GenError, run_gen

    global _fast_exit
    _fast_exit = True  # every file is written and closed before run_gen returns
    try:
        code = run_gen(str(dialect) if dialect else None, lang, str(out), check, force_skeletons,
                       [str(p) for p in include or []], str(templates) if templates else None,
                       names=Names(python_package, cpp_namespace, java_package), when_written=_ignore_ctrl_c)
    except GenError as e:
        raise Fail(str(e), e.code) from None
    raise typer.Exit(code)


app.add_typer(link_app, name="link")
app.add_typer(emulate_app, name="emulate")
app.add_typer(hmd_app, name="hmd")


@app.command("recv-file")
def recv_file_cmd(
    listen: Annotated[str, typer.Option("--listen", help="Endpoint: udpin:HOST:PORT (udp: means udpin), "
                                                         "tcpin:HOST:PORT, or udpout:/tcp: to reach out.",
                                        show_default=False, rich_help_panel=LINK)],
    folder: Annotated[Path, typer.Option("--dir", help="Where received files go (created if missing).",
                                         show_default=False, rich_help_panel=FILES)],
    overwrite: Annotated[bool, typer.Option("--overwrite", help="Allow replacing files, when the sender asks "
                                                                "for it too.", rich_help_panel=FILES)] = False,
    max_file: Annotated[int | None, typer.Option("--max-file", help="Largest file accepted, bytes "
                                                                    "(default 1 GiB).", show_default=False,
                                                 rich_help_panel=FILES)] = None,
    max_dir: Annotated[int | None, typer.Option("--max-dir", help="Quota for everything in --dir, partial files "
                                                                  "included, bytes (default 8 GiB).",
                                                show_default=False, rich_help_panel=FILES)] = None,
    serve: Annotated[Path | None, typer.Option("--serve", help="Offer the files in this folder for download "
                                                               "(send-file --from).", show_default=False,
                                               rich_help_panel=FILES)] = None,
    count: Annotated[int | None, typer.Option("--count", help="Exit 0 after this many files completed.",
                                              show_default=False, rich_help_panel=RUN)] = None,
    sysid: Annotated[int, typer.Option("--sysid", help="This end's MAVLink system id.", rich_help_panel=IDS)] = 1,
    compid: Annotated[int, typer.Option("--compid", help="This end's MAVLink component id.",
                                        rich_help_panel=IDS)] = 240,
    rate: RateOpt = None,
    profile: ProfileOpt = None,
    profile_file: ProfileFileOpt = None,
    distance: DistanceOpt = 10.0,
    json_out: JsonOpt = False,
    key: KeyOpt = None,
    accept_unsigned: AcceptUnsignedOpt = False,
    dialect: DialectOpt = None,
    include: DialectIncludeOpt = None,
    pipeline: PipelineOpt = None,
    pipe_rate: PipeRateOpt = None,
) -> None:
    """Receive files (the onboard end, 1/240, by default) until interrupted or --count files are in.

    Prints a line per file accepted, refused (with the reason), completed or
    failed (--json: JSON lines). Files land in DIR/.ttctl-partial first and are
    renamed into place once their SHA-256 matches. On SIGINT/SIGTERM or a crash,
    what arrived stays there: offering the file again resumes it.

    Exit status:
      0    stopped by Ctrl-C or SIGTERM, or --count files are in
      2    bad options, an unusable --dir or endpoint
      3    internal error (a bug; TTCTL_DEBUG=1 shows the traceback)
      130  interrupted while starting (Ctrl-C)

    Example:
      ttctl recv-file --listen udpin:0.0.0.0:14560 --dir inbox --profile m100
    """
    from .commands.recv_file import RecvOptions, recv_file

    code = recv_file(RecvOptions(listen, folder, overwrite, max_file, max_dir, serve, count, sysid, compid, rate,
                                 profile, distance, json_out, key, accept_unsigned, profile_file, dialect,
                                 include or [], pipeline, pipe_rate))
    raise typer.Exit(code)


@app.command("send-file")
def send_file_cmd(
    file: Annotated[str, typer.Argument(help="The file to send (with --to), or the name to fetch (with --from).",
                                        show_default=False)],
    to: Annotated[str | None, typer.Option("--to", help="Send FILE to this endpoint: udpout:HOST:PORT (udp: "
                                                        "means udpout), tcp:HOST:PORT, udpin:/tcpin: to wait "
                                                        "for the peer.", show_default=False,
                                           rich_help_panel=LINK)] = None,
    from_: Annotated[str | None, typer.Option("--from", help="Fetch FILE from a receiver started with --serve "
                                                             "at this endpoint.", show_default=False,
                                              rich_help_panel=LINK)] = None,
    name: Annotated[str | None, typer.Option("--name", help="Name at the receiver (default: FILE's base name); "
                                                            "a relative path.", show_default=False,
                                             rich_help_panel=FILES)] = None,
    overwrite: Annotated[bool, typer.Option("--overwrite", help="Ask the receiver to replace an existing "
                                                                "file.", rich_help_panel=FILES)] = False,
    folder: Annotated[Path | None, typer.Option("--dir", help="With --from: where the file goes (default: .).",
                                                show_default=False, rich_help_panel=FILES)] = None,
    json_out: JsonOpt = False,
    rate: RateOpt = None,
    profile: ProfileOpt = None,
    profile_file: ProfileFileOpt = None,
    distance: DistanceOpt = 10.0,
    sysid: Annotated[int, typer.Option("--sysid", help="This end's MAVLink system id.", rich_help_panel=IDS)] = 255,
    compid: Annotated[int, typer.Option("--compid", help="This end's MAVLink component id.",
                                        rich_help_panel=IDS)] = 190,
    target_sysid: Annotated[int, typer.Option("--target-sysid", help="The receiver's system id.",
                                              rich_help_panel=IDS)] = 1,
    target_compid: Annotated[int, typer.Option("--target-compid", help="The receiver's component id.",
                                               rich_help_panel=IDS)] = 240,
    timeout: Annotated[float, typer.Option("--timeout", help="Give up after this many seconds without progress "
                                                             "(no new bytes acknowledged: a receiver that only "
                                                             "says busy does not count).", rich_help_panel=RUN)] = 60.0,
    key: KeyOpt = None,
    accept_unsigned: AcceptUnsignedOpt = False,
    dialect: DialectOpt = None,
    include: DialectIncludeOpt = None,
    no_compress: Annotated[bool, typer.Option("--no-compress", help="Send the file as it is, never as its zlib "
                                                                    "stream (by default a file that deflates "
                                                                    "well goes deflated).",
                                              rich_help_panel=FILES)] = False,
    pipeline: PipelineOpt = None,
    pipe_rate: PipeRateOpt = None,
) -> None:
    """Send a file to a receiver (ttctl recv-file, or the onboard end), or fetch one with --from.

    A progress bar on stderr when it is a terminal; at the end a summary: bytes,
    seconds, goodput, efficiency against the link capacity (known from --rate or
    --profile), retransmitted bytes, and the compression when the file went
    deflated (text usually does; JPEG and archives never). --json prints one
    JSON object instead: ok, code, message, name, bytes, seconds, goodput_Bps,
    capacity_Bps, efficiency, retransmitted_bytes, frames_sent, bytes_sent,
    resumed_bytes, deflated_bytes (the zlib stream's size, null when sent as it
    is), deflate_fallback. Sending a file again after an interruption resumes
    where the receiver got to.

    Exit status:
      0    delivered and verified
      1    refused (with the receiver's reason), failed or timed out
      2    bad options, a missing file or an unusable endpoint
      3    internal error (a bug; TTCTL_DEBUG=1 shows the traceback)
      130  interrupted (Ctrl-C); sending again resumes

    Example:
      ttctl send-file photo.jpg --to udpout:192.168.1.20:14560 --profile m100
    """
    from .commands.send_file import SendOptions, send_file

    code = send_file(SendOptions(file, to, from_, name, overwrite, json_out, rate, profile, distance, sysid, compid,
                                 target_sysid, target_compid, timeout, folder, key, accept_unsigned, profile_file,
                                 dialect, include or [], compress=not no_compress, pipeline=pipeline,
                                 pipe_rate=pipe_rate))
    raise typer.Exit(code)


def _ignore_ctrl_c() -> None:
    """The command's work is done and cannot be taken back: a Ctrl-C from here on is ignored
    (main keeps it so), so that `interrupted` and 130 always mean nothing was left half done."""
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)


def _interrupted(signum: int, frame: object) -> None:
    """Ctrl-C once the command is over (while reporting, or during interpreter teardown)."""
    try:
        sys.stderr.write("ttctl: interrupted\n")
        sys.stderr.flush()
    finally:
        os._exit(130)


class _WatchedStdout:
    """stdout, remembering whether anything was written to it (see `_run`)."""

    def __init__(self, inner: Any) -> None:
        self._inner = inner
        self.written = False

    def write(self, text: str) -> int:
        self.written = self.written or bool(text)
        return int(self._inner.write(text))

    def __getattr__(self, name: str) -> Any:
        return getattr(self._inner, name)


def _run() -> int:
    """Run the command line; returns the exit status, having printed any failure as one line.
    With --json, a failure before the command printed anything is also a JSON object on stdout
    (`{"ok": false, "error": ..., "exit": ...}`), so a script reading stdout always gets JSON."""
    if "--json" not in sys.argv[1:] or isinstance(sys.stdout, _WatchedStdout):
        return _run_command()
    real = sys.stdout
    sys.stdout = _WatchedStdout(real)  # type: ignore[assignment]
    try:
        return _run_command()
    finally:
        sys.stdout = real


def _json_refusal(error: str, code: int) -> None:
    """--json: a refusal (a usage error too) as JSON on stdout, unless the command printed already."""
    if isinstance(sys.stdout, _WatchedStdout) and not sys.stdout.written:
        import json

        print(json.dumps({"ok": False, "error": error, "exit": code}), flush=True)


def _run_command() -> int:
    from .commands.lazy import lazy_command

    try:
        code = lazy_command(app)(standalone_mode=False)
    except ClickException as e:
        # usage errors as one line, not a box; always `ttctl: error:` (click would start them
        # with the command path), the subcommand in the hint
        ctx = getattr(e, "ctx", None)
        where = ctx.command_path if ctx is not None else "ttctl"
        msg = e.format_message()
        hint = " Did you mean"
        if msg.count(hint) > 1:  # typer and click both add the suggestion
            msg = msg[: msg.rindex(hint)]
        if msg.strip():  # a group called without a command has printed its help already
            _json_refusal(f"{msg} (see '{where} --help')", e.exit_code)
            print(f"ttctl: error: {msg} (see '{where} --help')", file=sys.stderr)
        return e.exit_code
    except typer.Abort:  # click's word for a KeyboardInterrupt inside a command
        print("ttctl: interrupted", file=sys.stderr)
        return 130
    except Fail as e:
        _json_refusal(str(e), e.code)
        print(f"ttctl: error: {e}", file=sys.stderr)
        return e.code
    except KeyboardInterrupt:
        print("ttctl: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        sys.stderr.close()
        return 1
    except Exception as e:
        if os.environ.get("TTCTL_DEBUG"):
            raise
        print(f"ttctl: internal error: {type(e).__name__}: {e} (set TTCTL_DEBUG=1 for a traceback)",
              file=sys.stderr)
        return 3
    code = code if isinstance(code, int) else 0
    if code == 130:  # typer turns Ctrl-C into a quiet exit 130
        print("ttctl: interrupted", file=sys.stderr)
    return code


def main() -> None:
    """Console entry point: clean one-line errors instead of tracebacks, and Ctrl-C at any
    moment one quiet line and exit 130 (`ttctl.entry` covers the imports before this)."""
    import signal

    from .interrupts import install

    try:
        install()  # from here a Ctrl-C raises KeyboardInterrupt, remembered even where Python loses it
        code = _run()
    except KeyboardInterrupt:  # while the handler was being installed, or a failure was being reported
        with contextlib.suppress(Exception):
            print("ttctl: interrupted", file=sys.stderr)
        code = 130
    with contextlib.suppress(ValueError):  # the main thread, always, but do not fail over it
        if signal.getsignal(signal.SIGINT) is not signal.SIG_IGN:  # a command that finished its work keeps it ignored
            signal.signal(signal.SIGINT, _interrupted)
    if _fast_exit:
        try:
            sys.stdout.flush()
            sys.stderr.flush()
        except (BrokenPipeError, ValueError):
            code = code or 1
        os._exit(code)
    sys.exit(code)
