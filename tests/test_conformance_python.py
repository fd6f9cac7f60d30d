"""Python bindings against pymavlink, through the generated conformance program (a real
process), for every message of ttapi.xml (which includes all of common.xml) and of common.xml."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from conformance_lib import (
    Conformance,
    assert_fields_match,
    generate,
    json_fields,
    load_model,
    message_values,
    pymavlink_frame,
    pymavlink_module,
    python_cmd,
)

TTAPI_MODEL = load_model("ttapi")


@pytest.fixture(scope="module")
def world(tmp_path_factory: pytest.TempPathFactory) -> Iterator[dict[str, object]]:
    tmp = tmp_path_factory.mktemp("conf_py")
    out = generate("ttapi", tmp / "out", "python")
    proc = Conformance(python_cmd(out))
    yield {"proc": proc, "pm": pymavlink_module("ttapi", tmp)}
    assert proc.close() == 0


def roundtrip(world: dict[str, object], m, values, seq: int, sysid: int, compid: int) -> None:  # type: ignore[no-untyped-def]
    proc, pm = world["proc"], world["pm"]
    frame = pymavlink_frame(pm, m, values, seq, sysid, compid)
    doc = proc.decode(frame)  # type: ignore[attr-defined]
    assert "error" not in doc, (m.name, doc, frame.hex())
    assert (doc["msgid"], doc["name"], doc["sysid"], doc["compid"], doc["seq"]) == (m.id, m.name, sysid, compid, seq)
    assert_fields_match(m, doc["fields"], json_fields(m, values))
    again = proc.encode(doc)  # type: ignore[attr-defined]
    assert again == frame, (m.name, frame.hex(), again)
    parsed = pm.MAVLink(None).parse_buffer(again)  # type: ignore[attr-defined]
    assert parsed and parsed[0].get_msgId() == m.id


@pytest.mark.parametrize("m", sorted(TTAPI_MODEL.messages, key=lambda m: m.id), ids=lambda m: m.name)
def test_every_message_roundtrips(world: dict[str, object], m) -> None:  # type: ignore[no-untyped-def]
    @settings(max_examples=8, deadline=None, suppress_health_check=list(HealthCheck), database=None)
    @given(values=message_values(m), seq=st.integers(0, 255), sysid=st.integers(1, 255), compid=st.integers(0, 255))
    def check(values, seq, sysid, compid) -> None:  # type: ignore[no-untyped-def]
        roundtrip(world, m, values, seq, sysid, compid)

    check()
