"""The generated Python package for dialects unlike ttapi.xml (no enums, no arrays, fields named
like digits, nothing the onboard end receives): it imports, passes ruff's defaults and mypy
--strict; and uint8_t[N] fields take what pymavlink takes, encoding the same bytes."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
from pymavlink.dialects.v20 import common as pm

import ttapi
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
    # names with numbers, which isort (ruff's I001) orders naturally: F2 before F13 (ardupilotmega's
    # ESC_TELEMETRY_1_TO_4... and matrixpilot's SERIAL_UDB_EXTRA_F2_A... were out of order)
    "numbered_names": dialect('<enum name="MODE_13"><description>m</description><entry value="1" name="M1"/></enum>\n'
                              '<enum name="MODE_2_B"><description>m</description><entry value="1" name="M2"/></enum>\n',
                              message(60000, "ESC_TELEMETRY_13_TO_16", FIELD_A)
                              + message(60001, "ESC_TELEMETRY_1_TO_4", FIELD_A)
                              + message(60002, "SERIAL_UDB_EXTRA_F2_A", FIELD_A)
                              + message(60003, "SERIAL_UDB_EXTRA_F13", FIELD_A)),
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
    count = "4" if name == "numbered_names" else "1"
    assert proc.returncode == 0 and proc.stdout.strip() == count, proc.stderr[-3000:]


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


# --- uint8_t[N]: bytes, bytearray or a sequence of ints, as pymavlink takes them ------------

def _pm_ftp(payload: object) -> bytes:
    mav = pm.MAVLink(None, srcSystem=1, srcComponent=1)
    return bytes(pm.MAVLink_file_transfer_protocol_message(0, 1, 2, payload).pack(mav))


@pytest.mark.parametrize("kind", ["bytes", "bytearray", "list", "tuple", "range"])
def test_uint8_array_takes_what_pymavlink_takes_and_encodes_the_same(kind: str) -> None:
    values = [(i * 37) % 256 for i in range(251)]
    given: object = {"bytes": bytes(values), "bytearray": bytearray(values), "list": values,
                     "tuple": tuple(values), "range": range(251)}[kind]
    if kind == "range":
        values = list(range(251))
    ours = ttapi.FileTransferProtocol(target_network=0, target_system=1, target_component=2,
                                      payload=given)  # type: ignore[arg-type]
    assert ours.pack(0, 1, 1) == _pm_ftp(values)
    assert ours.payload == bytes(values) and ttapi.decode(ours.pack()) == ours


def test_uint8_array_list_with_a_zero_tail_truncates_as_pymavlink() -> None:
    values = [1, 2, 3] + [0] * 248
    frame = ttapi.FileTransferProtocol(target_system=1, target_component=2, payload=values).pack(0, 1, 1)
    assert frame == _pm_ftp(values) and frame[1] == 6  # 3 header bytes + 3 payload bytes kept


@pytest.mark.parametrize(("given", "needle"), [
    ([1, 256], "FILE_TRANSFER_PROTOCOL.payload: uint8_t[251] takes bytes or integers 0..255, not 256"),
    ([-1], "not -1"),
    ([1.5], "not 1.5"),
    (["a"], "not 'a'"),
    ("text", "not a str"),
    (7, "not an int"),
])
def test_uint8_array_bad_values_are_clear_value_errors(given: object, needle: str) -> None:
    with pytest.raises(ValueError, match=re.escape(needle)):
        ttapi.FileTransferProtocol(payload=given).pack()  # type: ignore[arg-type]


def test_uint8_array_assigned_after_construction_is_checked_when_packed() -> None:
    msg = ttapi.TtFileData(transfer_id=1, offset=2)
    msg.data = [9] * 80  # type: ignore[assignment]
    assert msg.pack() == ttapi.TtFileData(transfer_id=1, offset=2, data=bytes([9] * 80)).pack()
    msg.data = [300]  # type: ignore[assignment]
    with pytest.raises(ValueError, match=re.escape("TT_FILE_DATA.data: uint8_t[80] takes bytes or integers 0..255, "
                                                   "not 300")):
        msg.pack()
    msg.data = [1] * 81  # type: ignore[assignment]
    with pytest.raises(ValueError, match=re.escape("TT_FILE_DATA.data: 81 bytes do not fit uint8_t[80]")):
        msg.pack()
