"""The three conformance programs (Python, C++, Java) refuse bad requests in the same words,
byte for byte, as the README says they agree (issue 20: their error texts differed). Built
from the checked-in generated/ tree (g++ at -O0 and javac: quick)."""

from __future__ import annotations

import subprocess
import sys

import pytest

from conformance_lib import Conformance
from conftest import ROOT

OUT = ROOT / "generated"
BAD = [
    "D fd0300",  # too short
    "D 000000000000000000000000000000",  # no magic
    "D zz", "D abc",  # not hex, odd digits
    "D fd0700000701f05ac3002a00ffbe01026407e8",  # bad CRC
    'E {"name":"NOPE"}', 'E {"msgid":99999}', "E {}", "E [1]", "X",
    'E {"name":"TT_COMMAND_ACK","fields":{"nope":1}}',
    "E {nope", 'E {"name": "TT_COMMAND_ACK", "fields": {"result": }}',
]


@pytest.fixture(scope="module")
def programs(tmp_path_factory: pytest.TempPathFactory) -> list[list[str]]:
    build = tmp_path_factory.mktemp("conformance-errors")
    exe = build / "conformance"
    cpp = subprocess.run(["g++", "-std=c++17", "-O0", "-Wall", "-Wextra", "-Werror", "-I", str(OUT / "cpp"),
                          str(OUT / "cpp" / "conformance.cpp"), "-o", str(exe)], capture_output=True, text=True,
                         timeout=600)
    assert cpp.returncode == 0, cpp.stderr[-3000:]
    classes = build / "classes"
    java = subprocess.run(["javac", "--release", "11", "-d", str(classes),
                           *sorted(str(p) for p in (OUT / "java").rglob("*.java"))], capture_output=True, text=True,
                          timeout=600)
    assert java.returncode == 0, java.stderr[-3000:]
    return [[sys.executable, str(OUT / "python" / "conformance.py")], [str(exe)],
            ["java", "-cp", str(classes), "Conformance"]]


def test_the_three_refuse_in_the_same_words(programs: list[list[str]]) -> None:
    procs = [Conformance(cmd) for cmd in programs]
    try:
        for line in BAD:
            answers = [p.ask(line) for p in procs]
            assert answers[0].startswith('{"error":"'), (line, answers[0])
            assert answers[0] == answers[1] == answers[2], (line, answers)
    finally:
        for p in procs:
            p.close()


def test_the_readme_shows_what_they_say() -> None:
    text = (ROOT / "README.md").read_text()
    shown = "$ echo 'D fd0300' | ./conformance\n" + '{"error":"not a MAVLink 2 frame (magic 0xFD, at least 12 bytes)"}'
    assert shown in text
