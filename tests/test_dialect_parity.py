"""pymavlink is the oracle: every dialect it ships validates cleanly, and for every message
our model's payload length, wire order and CRC_EXTRA equal its generated module's."""

from __future__ import annotations

import importlib
from pathlib import Path

import pytest

from conftest import pymavlink_dialects
from ttctl.validate import load_and_check

SHIPPED = sorted(pymavlink_dialects().glob("*.xml"))


def test_pymavlink_ships_the_dialects_we_expect() -> None:
    names = {p.stem for p in SHIPPED}
    assert {"common", "all", "ardupilotmega", "minimal", "standard"} <= names
    assert len(SHIPPED) >= 19


@pytest.mark.parametrize("xml", SHIPPED, ids=lambda p: p.stem)
def test_shipped_dialect_has_no_errors(xml: Path) -> None:
    _, rep, _ = load_and_check(str(xml), [])
    errors = [d.text() for d in rep.items if d.severity == "error"]
    assert errors == []


@pytest.mark.parametrize("xml", SHIPPED, ids=lambda p: p.stem)
def test_model_matches_pymavlink_generated_module(xml: Path) -> None:
    dialect, _, _ = load_and_check(str(xml), [])
    mod = importlib.import_module(f"pymavlink.dialects.v20.{xml.stem}")
    assert {m.id for m in dialect.messages} == set(mod.mavlink_map)
    for m in dialect.messages:
        ref = mod.mavlink_map[m.id]
        assert m.name == ref.msgname
        assert [f.name for f in m.wire_fields] == list(ref.ordered_fieldnames), m.name
        assert m.payload_length == ref.unpacker.size, m.name
        assert m.crc_extra == ref.crc_extra, m.name
        by_name = {f.name: f for f in m.fields}
        for name, typ in zip(ref.fieldnames, ref.fieldtypes, strict=True):
            assert by_name[name].type == typ, (m.name, name)
        for name, alen in zip(ref.ordered_fieldnames, ref.array_lengths, strict=True):
            f = by_name[name]
            # pymavlink packs char and 8-bit integer arrays as byte strings (array length 0)
            assert f.array_length == alen or (alen == 0 and f.type_size == 1), (m.name, name)
    for e in dialect.enums:
        ref_entries = {v: entry.name for v, entry in mod.enums[e.name].items()
                       if not entry.name.endswith("_ENUM_END")}
        assert {x.value: x.name for x in e.entries} == ref_entries, e.name


def test_enum_entry_details_are_read_on_demand(pm_dialects: Path) -> None:
    dialect, _, _ = load_and_check(str(pm_dialects / "common.xml"), [])
    wp = dialect.enums_by_name["MAV_CMD"].entry("MAV_CMD_NAV_WAYPOINT")
    assert wp is not None and wp.value == 16
    assert wp.description.startswith("Navigate to waypoint")
    assert [p.index for p in wp.params] == [1, 2, 3, 4, 5, 6, 7]
    att = dialect.messages_by_name["ATTITUDE"].field("roll")
    assert att is not None and att.units == "rad" and att.description == "Roll angle (-pi..+pi)"
