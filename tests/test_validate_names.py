"""Reserved words are judged as the generators spell each name: message and enum names as
CamelCase types, fields and entries as written. Real compilers decide: names the validator
accepts build in Python, C++ (both -std=c++17 and g++'s default GNU mode) and Java; names it
refuses really break the code the generators would write for them."""

from __future__ import annotations

import shutil
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

from conftest import run_ttctl
from ttctl.codegen.engine import render
from ttctl.validate import load_and_check

WARN = ["-Wall", "-Wextra", "-Wpedantic", "-Werror"]
needs_compilers = pytest.mark.skipif(shutil.which("g++") is None or shutil.which("javac") is None,
                                     reason="needs g++ and a JDK")


def enum(name: str, entries: list[tuple[str, int]], bitmask: bool = False) -> str:
    body = "".join(f'<entry value="{v}" name="{n}"><description>x</description></entry>\n' for n, v in entries)
    flag = ' bitmask="true"' if bitmask else ""
    return f'<enum name="{name}"{flag}>\n<description>x</description>\n{body}</enum>\n'


def message(msgid: int, name: str, fields: list[str], enum_of: dict[str, str] | None = None) -> str:
    body = "".join(f'<field type="uint8_t" name="{f}"{_enum_attr(f, enum_of)}>x</field>\n' for f in fields)
    return f'<message id="{msgid}" name="{name}">\n<description>x</description>\n{body}</message>\n'


def _enum_attr(field: str, enum_of: dict[str, str] | None) -> str:
    return f' enum="{enum_of[field]}"' if enum_of and field in enum_of else ""


def dialect(enums: list[str], messages: list[str]) -> str:
    return (f'<?xml version="1.0"?>\n<mavlink>\n<enums>\n{"".join(enums)}</enums>\n'
            f'<messages>\n{"".join(messages)}</messages>\n</mavlink>\n')


# Upper-case words whose lower case is a keyword somewhere, and words that are keywords only
# in a language no generator writes (C's restrict) or only where no generator puts them (Java's
# contextual var, record, sealed, permits; Python's soft match and type): all fine as spelled.
ACCEPTED = dialect(
    [enum("BOOL", [("BOOL_FALSE", 0), ("BOOL_TRUE", 1)], bitmask=True),  # standard.xml, 2025-03..07
     enum("INT", [("var", 1), ("permits", 2), ("record", 3), ("restrict", 4), ("match", 5), ("sealed", 6)]),
     enum("DELETE", [("DELETE_OK", 0)]), enum("REGISTER", [("REGISTER_A", 1)]),
     enum("TEMPLATE", [("TEMPLATE_A", 1)]), enum("NULLPTR", [("NULLPTR_A", 1)])],
    [message(60000, "STRUCT", ["restrict", "var", "record", "sealed", "permits", "match", "type", "module",
                               "assert_"], {"var": "INT", "sealed": "BOOL"}),
     message(60001, "VOLATILE", ["x"]), message(60002, "NAMESPACE", ["x"]), message(60003, "TYPEOF", ["x"]),
     message(60004, "OPERATOR", ["x"]), message(60005, "BOOL_STATE", ["x"])],
)


def test_accepted_names_raise_no_name_diagnostics(tmp_path: Path) -> None:
    xml = tmp_path / "names.xml"
    xml.write_text(ACCEPTED)
    proc = run_ttctl("validate", str(xml))
    assert proc.returncode == 0, proc.stdout
    assert "[KEYWORD]" not in proc.stdout and "[RESERVED-NAME]" not in proc.stdout, proc.stdout


@needs_compilers
def test_accepted_names_build_in_every_language(tmp_path: Path) -> None:
    xml = tmp_path / "names.xml"
    xml.write_text(ACCEPTED)
    out = tmp_path / "out"
    proc = run_ttctl("gen", str(xml), "-o", str(out))
    assert proc.returncode == 0, proc.stdout + proc.stderr
    cpp = out / "cpp"
    jobs = [["g++", f"-std={std}", *WARN, "-O0", "-I", str(cpp), str(cpp / "conformance.cpp"), "-o",
             str(tmp_path / f"conf_{std}")] for std in ("c++17", "gnu++17")]
    jobs.append(["javac", "--release", "11", "-Xlint:all", "-Werror", "-d", str(tmp_path / "classes"),
                 *map(str, sorted((out / "java").rglob("*.java")))])
    jobs.append([sys.executable, "-c", "import names\nfor c in names.ALL:\n"
                 "    assert names.decode(names.encode(c())) == c()"])
    with ThreadPoolExecutor(max_workers=2) as pool:
        results = list(pool.map(lambda cmd: subprocess.run(cmd, capture_output=True, text=True, timeout=600,
                                                           cwd=out / "python"), jobs))
    for cmd, res in zip(jobs, results, strict=True):
        assert res.returncode == 0, f"{cmd[:2]}: {res.stderr[-3000:]}"


# (where the name goes, the name, the diagnostic, the language whose build it breaks)
REFUSED = [
    ("message", "NONE", "KEYWORD", "python"),  # class None
    ("enum", "TRUE", "KEYWORD", "python"),  # class True
    ("entry", "None", "KEYWORD", "python"),
    ("entry", "delete", "KEYWORD", "c++17"),
    ("field", "int", "KEYWORD", "java"),
    ("field", "_", "KEYWORD", "java"),
    ("field", "typeof", "KEYWORD", "gnu++17"),  # g++'s default mode only
    ("field", "errno", "RESERVED-NAME", "c++17"),  # a macro
    ("entry", "NULL", "RESERVED-NAME", "c++17"),
    ("field", "linux", "RESERVED-NAME", "gnu++17"),  # predefined by g++ in its GNU modes
]


def placed(where: str, name: str) -> str:
    if where == "message":
        return dialect([], [message(60000, name, ["a"])])
    if where == "enum":
        return dialect([enum(name, [("E_A", 1)])], [message(60000, "M", ["a"], {"a": name})])
    if where == "entry":
        return dialect([enum("E", [(name, 1)])], [message(60000, "M", ["a"], {"a": "E"})])
    return dialect([], [message(60000, "M", [name])])


@pytest.mark.parametrize(("where", "name", "code", "lang"), REFUSED, ids=[f"{w}-{n}" for w, n, _, _ in REFUSED])
def test_refused_names_are_reported_where_they_are(tmp_path: Path, where: str, name: str, code: str,
                                                    lang: str) -> None:
    xml = tmp_path / "d.xml"
    xml.write_text(placed(where, name))
    _, rep, _ = load_and_check(str(xml), [])
    got = [(d.code, d.name) for d in rep.items if d.severity == "error"]
    assert got == [(code, name)], got


@needs_compilers
@pytest.mark.parametrize(("where", "name", "code", "lang"), REFUSED, ids=[f"{w}-{n}" for w, n, _, _ in REFUSED])
def test_refused_names_really_break_the_generated_code(tmp_path: Path, where: str, name: str, code: str,
                                                       lang: str) -> None:
    """The generators, run past the validator, write code that `lang` refuses."""
    xml = tmp_path / "d.xml"
    xml.write_text(placed(where, name))
    d, _, _ = load_and_check(str(xml), [])
    target = {"python": "python", "java": "java"}.get(lang, "cpp")
    out = tmp_path / "out"
    for o, text in render(d, [target]):
        (out / o.path).parent.mkdir(parents=True, exist_ok=True)
        (out / o.path).write_text(text)
    if lang == "python":
        errors = []
        for p in (out / "python" / "d").glob("*.py"):
            try:
                compile(p.read_text(), str(p), "exec")
            except SyntaxError as e:
                errors.append(e)
        assert errors
        return
    if lang == "java":
        cmd = ["javac", "--release", "11", "-d", str(tmp_path / "classes"),
               *map(str, sorted((out / "java").rglob("*.java")))]
    else:
        main = tmp_path / "main.cpp"
        main.write_text('#include <cerrno>\n#include <cstdio>\n#include "d/d.hpp"\nint main() { return 0; }\n')
        cmd = ["g++", f"-std={lang}", "-fsyntax-only", "-I", str(out / "cpp"), str(main)]
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    assert proc.returncode != 0, f"{lang} accepted {where} {name!r}"
    assert name in proc.stderr or "expected" in proc.stderr, proc.stderr[-2000:]
