"""`ttctl gen`: validate, render, write (or check) the output tree."""

from __future__ import annotations

import contextlib
import os
import shutil
import sys
from collections.abc import Callable
from pathlib import Path

from .codegen.engine import LANGUAGES, Names, Output, language, render, write_tree
from .dialect.names import C_RESERVED, CPP_KEYWORDS, IDENTIFIER_RE, JAVA_CONTEXTUAL, JAVA_KEYWORDS, PYTHON_KEYWORDS
from .validate import include_dir_problem, load_and_check, user_warnings

DEFAULT_DIALECT = "dialects/ttapi.xml"
DEFAULT_OUT = "generated"
XML = "xml"  # not a language: the dialect as one XML file, its includes resolved (codegen/xml_export.py)


class GenError(Exception):
    def __init__(self, message: str, code: int) -> None:
        super().__init__(message)
        self.code = code


def parse_langs(spec: str) -> list[str]:
    langs = [s.strip().lower() for s in spec.split(",") if s.strip()]
    aliases = {"py": "python", "c++": "cpp", "cxx": "cpp"}
    langs = [aliases.get(x, x) for x in langs]
    bad = [x for x in langs if x not in LANGUAGES and x != XML]
    if bad or not langs:
        raise GenError(f"--lang: unknown language {', '.join(bad) or '(none)'}; choose from "
                       f"{', '.join(LANGUAGES)}, or {XML} (the dialect as one file, includes resolved)", 2)
    return list(dict.fromkeys(langs))


# What the generated Python code imports (besides the standard library), and the names beside
# the package in python/: a package of one of these names would shadow it.
_PY_TAKEN = frozenset({"ttctl", "fastcrc", "handlers", "conformance"})
# Object-like macros of glibc and of g++ in its GNU modes (-std=gnu++17, the default).
_CPP_MACROS = frozenset({"linux", "unix", "errno", "math_errhandling", "sched_priority"})
# Namespaces of the runtime and the standard library; `mav` (the conformance program's alias
# for the namespace) and `main` are global names of cpp/conformance.cpp.
_CPP_TAKEN = frozenset({"std", "detail", "onboard"})
_CPP_TOP_TAKEN = frozenset({"mav", "main"})
# Variables in scope where the generated Registry and Conformance name the package in full: a
# first package segment of one of these names would be read as the variable.
_JAVA_LOCALS = frozenset({"all", "doc", "fields", "frame", "hex", "id", "info", "len", "m", "messageName",
                          "msgId", "n", "obj", "off", "payload", "sb", "text"})


def python_package_problem(name: str) -> str | None:
    """Why `name` cannot be the generated Python package, or None."""
    if not IDENTIFIER_RE.match(name):
        return "not a Python identifier (ASCII letters, digits, _; no dots)"
    if name in PYTHON_KEYWORDS:
        return f"'{name}' is a Python keyword"
    if name in _PY_TAKEN:
        return f"'{name}' would shadow the module or folder of that name that generated code uses"
    if name in sys.stdlib_module_names:
        return f"'{name}' is a module of Python's standard library, which the package would shadow"
    return None


def cpp_namespace_problem(name: str) -> str | None:
    """Why `name` (a or a::b::c) cannot be the generated C++ namespace, or None."""
    parts = name.split("::")
    for i, seg in enumerate(parts):
        if not IDENTIFIER_RE.match(seg):
            return f"'{seg}' is not a C++ identifier" if seg else "not a C++ namespace (a or a::b)"
        if seg in CPP_KEYWORDS:
            return f"'{seg}' is a C++ keyword"
        if (seg.startswith("_") and (i == 0 or seg[1:2].isupper())) or "__" in seg:
            return f"'{seg}' is reserved to the implementation (a leading _ at the top or before a capital, or __)"
        if seg in C_RESERVED or seg in _CPP_MACROS:
            return f"'{seg}' is a macro of the C library or the compiler"
        if seg in _CPP_TAKEN or (i == 0 and seg in _CPP_TOP_TAKEN):
            return f"'{seg}' is a name the generated code uses itself"
    return None


def java_package_problem(name: str) -> str | None:
    """Why `name` (dotted) cannot be the generated Java package, or None."""
    parts = name.split(".")
    for seg in parts:
        if not IDENTIFIER_RE.match(seg):
            return f"'{seg}' is not a Java identifier" if seg else "not a Java package (a or a.b.c)"
        if seg in JAVA_KEYWORDS and seg not in JAVA_CONTEXTUAL:
            return f"'{seg}' is a Java keyword or literal"
    first = parts[0]
    if first == "java":
        return "packages java.* are the JDK's: a class loader refuses classes in them"
    if not first[:1].islower():
        return f"'{first}' does not start with a lower-case letter: the generated code would read it as a class"
    if first in _JAVA_LOCALS:
        return f"'{first}' is a variable of the generated code, which would hide the package"
    return None


def check_names(names: Names) -> None:
    """GenError (exit 2) for the first name the user gives that cannot be used."""
    for option, value, problem in (("--python-package", names.python_package, python_package_problem),
                                   ("--cpp-namespace", names.cpp_namespace, cpp_namespace_problem),
                                   ("--java-package", names.java_package, java_package_problem)):
        if value is not None:
            why = problem(value)
            if why:
                raise GenError(f"{option} {value}: {why}", 2)


def check_out_dir(out: Path, check: bool) -> None:
    """GenError unless `out` is a writable directory or can be made one. Creates nothing: the
    tree is only made once there is something to write."""
    try:
        _check_out_dir(out, check)
    except OSError as e:  # a name too long, a loop of symlinks...
        raise GenError(f"output path {out}: {e.strerror or e}", 2) from None


def _check_out_dir(out: Path, check: bool) -> None:
    if out.exists() and not out.is_dir():
        raise GenError(f"output path {out} exists and is not a directory", 2)
    if check:
        return
    if out.exists():
        if not os.access(out, os.W_OK | os.X_OK):
            raise GenError(f"output path {out} is not writable", 2)
        return
    parent = out.absolute().parent
    while not parent.exists():
        parent = parent.parent
    if not parent.is_dir() or not os.access(parent, os.W_OK | os.X_OK):
        raise GenError(f"output path {out} cannot be created: {parent} is not a writable directory", 2)


def check_include_dirs(include_dirs: list[str]) -> None:
    for d in include_dirs:
        problem = include_dir_problem(d)
        if problem:
            raise GenError(problem, 2)


def _take_back(created: list[Path]) -> None:
    """Remove what a failed run made (newest first), deaf to a second Ctrl-C meanwhile."""
    import signal

    try:
        previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    except ValueError:  # not the main thread
        previous = None
    try:
        for p in reversed(created):
            if os.path.isdir(p) and not os.path.islink(p):
                shutil.rmtree(p, ignore_errors=True)
            else:
                with contextlib.suppress(OSError):  # not made after all (missing, a name too long)
                    os.unlink(p)
    finally:
        if previous is not None:
            signal.signal(signal.SIGINT, previous)


def run_gen(dialect_path: str | None, langs_spec: str, out_dir: str, check: bool, force_skeletons: bool,
            include_dirs: list[str], user_templates: str | None, quiet: bool = False,
            names: Names | None = None, when_written: Callable[[], None] | None = None) -> int:
    """`names`: --python-package, --cpp-namespace, --java-package (see check_names).
    `when_written` is called once the whole tree is in place (the CLI stops listening to Ctrl-C
    there: exit 130 must mean nothing was left behind)."""
    from .dialect import LoadError

    if dialect_path is None:
        if not os.path.isfile(DEFAULT_DIALECT):
            raise GenError(f"no dialect given and {DEFAULT_DIALECT} is not here", 2)
        dialect_path = DEFAULT_DIALECT
    langs = parse_langs(langs_spec)
    if names is not None:
        check_names(names)
    if user_templates is not None and not os.path.isdir(user_templates):
        raise GenError(f"--templates {user_templates}: not a directory", 2)
    out = Path(out_dir)
    check_out_dir(out, check)
    check_include_dirs(include_dirs)
    try:
        dialect, rep, order = load_and_check(dialect_path, include_dirs)
    except LoadError as e:
        print(f"{e.path}:{e.line}:{e.col}: error: [{e.code}] {e.message}", file=sys.stderr)
        return 2
    if rep.errors:
        for d in rep.sorted(order):
            if d.severity == "error":
                print(d.text(), file=sys.stderr)
        print(f"{dialect_path}: {rep.errors} error(s); nothing generated", file=sys.stderr)
        return 1
    try:
        rendered = render(dialect, [x for x in langs if x != XML], user_templates, names=names)
        if XML in langs:
            from .codegen.xml_export import export_path, flatten

            rendered.append((Output(export_path(dialect), ""), flatten(dialect)))
    except Exception as e:  # jinja2 template errors (user templates), undefined names
        import jinja2

        if isinstance(e, jinja2.TemplateError):
            where = f"{e.filename}:{e.lineno}: " if isinstance(e, jinja2.TemplateSyntaxError) else ""
            raise GenError(f"template error: {where}{e}", 2) from None
        raise
    owned = [p for lang in langs if lang != XML for p in language(lang, names).owned_dirs(dialect)]
    created: list[Path] = []
    try:
        report = write_tree(out, rendered, owned, check, force_skeletons, created)
        if not check and when_written is not None:
            when_written()  # still inside: an interrupt before it has returned takes the tree back
    except BaseException as e:  # a full disk, a permission, Ctrl-C
        _take_back(created)  # leave no file or folder this run made
        if isinstance(e, OSError):
            raise GenError(f"cannot write {e.filename or out}: {e.strerror or e}", 2) from None
        raise
    if check:
        for p in report.differ:
            print(f"{out / p}: out of date", file=sys.stdout)
        if report.differ:
            print(f"{len(report.differ)} file(s) differ from what `ttctl gen` would write; run it", file=sys.stdout)
            return 1
        if not quiet:
            print(f"{out}: up to date ({len(report.unchanged) + len(report.kept)} files)")
        return 0
    if not quiet:
        parts = [f"{len(report.written)} written", f"{len(report.unchanged)} unchanged"]
        if report.kept:
            parts.append(f"{len(report.kept)} skeletons kept (--force-skeletons overwrites)")
        if report.removed:
            parts.append(f"{len(report.removed)} stale removed")
        print(f"{out}: {', '.join(parts)} [{', '.join(langs)}; {len(dialect.messages)} messages]")
        warnings = user_warnings(rep, dialect_path)
        if warnings:
            print(f"({warnings} validation warning(s); `ttctl validate {dialect_path}` shows them)")
    return 0
