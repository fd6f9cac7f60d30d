"""The shipped dialect: the facts the rest of ttctl relies on, checked against pymavlink's
own generator as an independent oracle."""

from __future__ import annotations

import importlib.util
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import TTAPI, pymavlink_dialects
from ttctl.dialect.model import frame_length
from ttctl.validate import load_and_check


@pytest.fixture(scope="module")
def ttapi():  # type: ignore[no-untyped-def]
    dialect, rep, _ = load_and_check(str(TTAPI), [])
    assert rep.errors == 0
    return dialect


def test_pose_stamped_is_wire_compatible_with_the_thesis(ttapi) -> None:  # type: ignore[no-untyped-def]
    m = ttapi.messages_by_name["DJI_POSE_STAMPED"]
    assert m.id == 50004 and m.payload_length == 66 and m.crc_extra == 70
    assert [(f.name, f.type, f.array_length) for f in m.fields] == [
        ("target_system", "uint8_t", 0), ("sec", "uint32_t", 0), ("nsec", "uint32_t", 0),
        ("topic_name", "uint8_t", 0), ("position", "double", 3), ("orientation", "double", 4)]
    assert m.field("topic_name").enum == "DJI_TOPIC_NAME"


def test_ids_senders_and_the_one_packet_budget(ttapi) -> None:  # type: ignore[no-untyped-def]
    own = ttapi.root.messages
    assert len(own) >= 12
    for m in own:
        assert 50000 <= m.id <= 50099, m.name
        assert m.sender in ("tablet", "onboard", "any"), m.name
        if m.spans_packets:
            continue
        assert m.payload_length <= 88 and frame_length(m.payload_length) <= 100, m.name
    spanning = [m.name for m in own if m.spans_packets]
    assert spanning == ["TT_FILE_DATA_WIDE", "TT_FILE_DATA_FIT"]  # the latter sized to the packet by its sender


def test_required_messages_exist(ttapi) -> None:  # type: ignore[no-untyped-def]
    names = {m.name for m in ttapi.root.messages}
    assert {"TT_ACTION_COMMAND", "TT_COMMAND_ACK", "TT_NAV_SAT_FIX", "TT_ODOMETRY", "TT_LOG",
            "TT_FILE_OFFER", "TT_FILE_STATUS", "TT_FILE_DATA", "TT_FILE_REQUEST", "TT_VR_POSE",
            "TT_VR_CONTROLLER"} <= names
    actions = {e.name for e in ttapi.enums_by_name["TT_ACTION"].entries}
    for a in ("TAKE_OFF", "LAND", "HOVER", "FLY_TRAJECTORY", "SYNC_TIME", "RETURN_HOME"):
        assert f"TT_ACTION_{a}" in actions
    odo = ttapi.messages_by_name["TT_ODOMETRY"]
    assert "x, y, z, w" in odo.description and "x, y, z, w" in odo.field("orientation").description


def test_pymavlink_generates_the_same_crc_extras(ttapi, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    # mavgen only looks for includes beside the including file: stage ttapi.xml with the
    # definitions pymavlink ships
    for xml in pymavlink_dialects().glob("*.xml"):
        shutil.copy(xml, tmp_path)
    shutil.copy(TTAPI, tmp_path)
    out = tmp_path / "ttapi_pm.py"
    proc = subprocess.run([sys.executable, "-m", "pymavlink.tools.mavgen", "--lang", "Python3",
                           "--wire-protocol", "2.0", "-o", str(out), str(tmp_path / "ttapi.xml")],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    spec = importlib.util.spec_from_file_location("ttapi_pm", out)
    mod = importlib.util.module_from_spec(spec)  # type: ignore[arg-type]
    spec.loader.exec_module(mod)  # type: ignore[union-attr]
    for m in ttapi.messages:
        ref = mod.mavlink_map[m.id]
        assert (m.crc_extra, m.payload_length) == (ref.crc_extra, ref.unpacker.size), m.name
        assert [f.name for f in m.wire_fields] == list(ref.ordered_fieldnames), m.name
