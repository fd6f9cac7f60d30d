"""The generated Python package for dialects unlike ttapi.xml (no enums, no arrays, fields named
like digits, nothing the onboard end receives): it imports, passes ruff's defaults and mypy
--strict."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import run_ttctl

BIN = Path(sys.executable).parent


def dialect(enums: str, messages: str) -> str:
    return (f'<?xml version="1.0"?>\n<mavlink>\n<enums>\n{enums}</enums>\n<messages>\n{messages}</messages>\n'
            "</mavlink>\n")


def message(msgid: int, name: str, fields: str, description: str = "x") -> str:
    return f'<message id="{msgid}" name="{name}">\n<description>{description}</description>\n{fields}</message>\n'


FIELD_A = '<field type="uint8_t" name="a">a</field>\n'
# Dialects that each leave out something ttapi.xml has, so that an import the generated code
# always wrote would go unused there (ruff F401) or not parse at all.
ODD_DIALECTS = {
    # no enums at all: `from .enums import (\n)` was a SyntaxError
    "no_enums": dialect("", message(60000, "PLAIN", FIELD_A)),
    # only a bitmask enum (IntEnum unused), only a plain enum (IntFlag unused)
    "only_flags": dialect('<enum name="F" bitmask="true"><description>f</description>'
                          '<entry value="1" name="F_A"/></enum>\n', message(60000, "PLAIN", FIELD_A)),
    "only_plain": dialect('<enum name="E"><description>e</description><entry value="1" name="E_A"/></enum>\n',
                          message(60000, "PLAIN", FIELD_A)),
    # no arrays of any kind (Sequence, _array, _cbytes, _cstr unused), and fields whose names
    # pycodestyle calls ambiguous (E741): they must keep their XML names
    "ambiguous_names": dialect("", message(60000, "PID", '<field type="float" name="P">p</field>\n'
                                           '<field type="float" name="I">i</field>\n'
                                           '<field type="float" name="l">l</field>\n'
                                           '<field type="float" name="O">o</field>\n')),
    # arrays of each kind, but nothing the onboard end receives (its skeleton handles nothing)
    "arrays_onboard_only": dialect("", message(60000, "ARRAYS", '<field type="uint8_t[4]" name="raw">r</field>\n'
                                              '<field type="char[8]" name="text">t</field>\n'
                                              '<field type="int16_t[3]" name="v">v</field>\n',
                                              "sent by the vehicle [sender: onboard]")),
}


@pytest.fixture(scope="module")
def odd_packages(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """All the odd dialects generated (Python) side by side in one python/ folder."""
    base = tmp_path_factory.mktemp("odd")
    out = base / "out"
    for name, text in ODD_DIALECTS.items():
        xml = base / f"{name}.xml"
        xml.write_text(text)
        proc = run_ttctl("gen", str(xml), "--lang", "python", "-o", str(out))
        assert proc.returncode == 0, proc.stdout + proc.stderr
    return out / "python"


@pytest.mark.parametrize("name", sorted(ODD_DIALECTS))
def test_odd_dialect_package_imports_and_round_trips(odd_packages: Path, name: str) -> None:
    code = ("import importlib, sys\n"
            "pkg = importlib.import_module(sys.argv[1])\n"
            "for cls in pkg.ALL:\n"
            "    assert pkg.decode(pkg.encode(cls())) == cls()\n"
            "print(len(pkg.ALL))\n")
    proc = subprocess.run([sys.executable, "-c", code, name], cwd=odd_packages, capture_output=True, text=True,
                          env={**os.environ, "PYTHONPATH": str(odd_packages)}, timeout=120)
    assert proc.returncode == 0 and proc.stdout.strip() == "1", proc.stderr[-3000:]


def test_odd_dialect_packages_pass_ruff_defaults_and_mypy_strict(odd_packages: Path) -> None:
    ruff = subprocess.run([str(BIN / "ruff"), "check", "--no-cache", "--isolated", "."], cwd=odd_packages,
                          capture_output=True, text=True, timeout=300)
    assert ruff.returncode == 0, ruff.stdout[-4000:]
    targets = [*sorted(ODD_DIALECTS), *(f"handlers/{n}_onboard.py" for n in sorted(ODD_DIALECTS))]
    mypy = subprocess.run([str(BIN / "mypy"), "--strict", "--no-incremental", *targets], cwd=odd_packages,
                          capture_output=True, text=True, timeout=600)
    assert mypy.returncode == 0, mypy.stdout[-4000:]


def test_ambiguous_field_names_stay_as_in_the_xml(odd_packages: Path) -> None:
    text = (odd_packages / "ambiguous_names" / "messages.py").read_text()
    assert "self.I = I" in text and "self.l = l" in text and "self.O = O" in text
