"""Python bindings against pymavlink, through the generated conformance program (a real
process), for every message of ttapi.xml (which includes all of common.xml) and of common.xml."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

import pytest

from conformance_lib import (
    Conformance,
    check_message,
    generate,
    load_model,
    pymavlink_module,
    python_cmd,
)
from ttctl.dialect.model import Message

TTAPI_MODEL = load_model("ttapi")


@pytest.fixture(scope="module")
def world(tmp_path_factory: pytest.TempPathFactory) -> Iterator[dict[str, Any]]:
    tmp = tmp_path_factory.mktemp("conf_py")
    out = generate("ttapi", tmp / "out", "python")
    proc = Conformance(python_cmd(out))
    yield {"proc": proc, "pm": pymavlink_module("ttapi", tmp)}
    assert proc.close() == 0


@pytest.mark.parametrize("m", sorted(TTAPI_MODEL.messages, key=lambda m: m.id), ids=lambda m: m.name)
def test_every_message_roundtrips(world: dict[str, Any], m: Message) -> None:
    check_message(world, m, 8)
