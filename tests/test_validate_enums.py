"""Enum values as upstream dialects write them: a negative value is refused for what it is (the
schema allows none), and a bitmask's 0 entry (MAV_BOOL_FALSE = 0, "no flags") is no warning."""

from __future__ import annotations

from pathlib import Path

import pytest

from ttctl.validate import load_and_check


def check(tmp_path: Path, entries: str, bitmask: bool = False) -> list[tuple[str, str, str]]:
    flag = ' bitmask="true"' if bitmask else ""
    xml = tmp_path / "e.xml"
    xml.write_text(f'<?xml version="1.0"?>\n<mavlink>\n<enums>\n<enum name="E"{flag}>\n<description>x</description>\n'
                   f'{entries}</enum>\n</enums>\n<messages>\n<message id="60000" name="M">\n<description>x'
                   '</description>\n<field type="uint8_t" name="a">a</field>\n</message>\n</messages>\n</mavlink>\n')
    _, rep, _ = load_and_check(str(xml), [])
    return [(d.severity, d.code, d.message) for d in rep.items]


@pytest.mark.parametrize("value", ["-1", "-0x10", " -7 ", "-2**3"])
def test_a_negative_value_is_refused_as_negative(tmp_path: Path, value: str) -> None:
    got = check(tmp_path, f'<entry value="{value}" name="E_NEG"/>\n')
    assert got == [("error", "ENUM-VALUE", f"enum entry E_NEG: value '{value}' is negative; the schema "
                    "(mavschema.xsd) allows enum values from 0 up")]


@pytest.mark.parametrize("value", ["abc", "1.5", "--1", "-", "0x"])
def test_a_value_that_is_no_integer_is_still_said_so(tmp_path: Path, value: str) -> None:
    got = check(tmp_path, f'<entry value="{value}" name="E_BAD"/>\n')
    assert [(s, c) for s, c, _ in got] == [("error", "ENUM-VALUE")]
    assert f"value '{value}' is not an integer" in got[0][2]


def test_a_bitmask_zero_entry_is_no_warning(tmp_path: Path) -> None:
    entries = ('<entry value="0" name="E_NONE"/>\n<entry value="1" name="E_A"/>\n<entry value="2" name="E_B"/>\n'
               '<entry value="0x80000000" name="E_HIGH"/>\n')
    assert check(tmp_path, entries, bitmask=True) == []


def test_a_bitmask_entry_of_several_bits_is_still_a_warning(tmp_path: Path) -> None:
    got = check(tmp_path, '<entry value="0" name="E_NONE"/>\n<entry value="3" name="E_AB"/>\n', bitmask=True)
    assert got == [("warning", "BITMASK-VALUE", "E is a bitmask but E_AB = 3 is not a power of two")]
