"""The generated C++ onboard end confirms the tablet's VR controller input as ttctl's Python
onboard end does (ttctl.ends.onboard.vr_controller): every TT_VR_CONTROLLER answered with
NAMED_VALUE_INT "vrbtn<index>" = its packet_num (as int32), ahead of telemetry, before the
user's handler gets it.

- `ttctl hmd dump --to` through `ttctl link relay --profile m100 --loss 0.2` to the C++ node
  (real processes): exit 0, every button change confirmed, the handler saw each change once;
- on raw UDP: the confirmation's name and value at the edges (index 0, 200; packet_num 2^32 - 2);
- a dialect without TT_VR_CONTROLLER still gets a node that compiles (and confirms nothing).
"""

from __future__ import annotations

import re
import subprocess
from pathlib import Path
from typing import Any

import ttapi
from conftest import ROOT, TTAPI, ttctl_cmd
from cpp_node_lib import WARN, Raw, gxx, needs_gxx
from e2e_lib import LOCAL, Start, free_port, relay
from test_hmd_link_e2e import recorded_changes

pytestmark = needs_gxx


def test_hmd_dump_through_the_m100_relay_is_confirmed_by_the_cpp_node(cpp_node_bins: dict[str, Path],
                                                                       tmp_path: Path, start: Start,
                                                                       cpp_nodes: Any) -> None:
    port = free_port()
    node = cpp_nodes(cpp_node_bins["plain"], tmp_path, "node", "--listen", f"udpin:{LOCAL}:{port}")
    air = free_port()
    relay(start, air, port, "--profile", "m100", "--distance", "10", "--loss", "0.2", "--seed", "4",
          "--stats-interval", "0")
    rec = tmp_path / "rec.jsonl"
    dump = subprocess.run(ttctl_cmd() + ["hmd", "dump", "--duration", "8", "--seed", "2", "-o", str(rec),
                                         "--to", f"udpout:{LOCAL}:{air}"],
                          capture_output=True, text=True, timeout=90)
    stats = node.stop()
    want = recorded_changes(rec)
    assert dump.returncode == 0, dump.stderr
    assert len(want) >= 8
    m = re.search(r"button changes: (\d+) of (\d+) confirmed by the onboard end \((\d+) resent\)", dump.stderr)
    assert m is not None, dump.stderr
    assert int(m[1]) == int(m[2]) == len(want) and int(m[3]) > 0  # 20 % loss: some were resent
    assert "Traceback" not in dump.stderr
    # every TT_VR_CONTROLLER that arrived was confirmed, and the user's handler got it too; the
    # handler saw each button change once (the tablet holds the rest until a change is confirmed)
    assert stats["vr_confirmed"] == stats["plugin_vr_messages"] >= len(want), stats
    assert stats["plugin_vr_changes"] == len(want), stats


def confirmations(got: list[Any]) -> list[tuple[str, int]]:
    return [(m.name, m.value) for m in got if isinstance(m, ttapi.NamedValueInt)]


def test_the_confirmation_names_the_controller_and_its_packet(cpp_node_bins: dict[str, Path], tmp_path: Path,
                                                              cpp_nodes: Any) -> None:
    """Index in decimal without padding, packet_num >= 2^31 as packet_num - 2^32 (the tablet reads
    value & 0xFFFFFFFF); a copy (the confirmation was lost) is confirmed again."""
    node = cpp_nodes(cpp_node_bins["plain"], tmp_path, "node", "--listen", f"udpin:{LOCAL}:0", "--heartbeat", "0")
    raw = Raw(node.port)
    sent = [(0, 1), (7, 0xFFFFFFFE), (200, 5), (200, 5), (255, 0x80000000)]
    want = [("vrbtn0", 1), ("vrbtn7", -2), ("vrbtn200", 5), ("vrbtn200", 5), ("vrbtn255", -(1 << 31))]
    got: list[tuple[str, int]] = []
    try:
        for index, packet in sent:
            raw.frames(ttapi.TtVrController(time_usec=1, packet_num=packet, index=index, role=1, trigger=0.0,
                                            pad_x=0.0, pad_y=0.0, buttons=1))
            got += confirmations(raw.collect(2.0, until=lambda m: bool(confirmations(m))))
    finally:
        raw.close()
    assert got == want
    stats = node.stop()
    assert stats["vr_confirmed"] == stats["plugin_vr_messages"] == len(sent), stats


def test_a_dialect_without_vr_controllers_still_gets_a_node_that_compiles(tmp_path: Path) -> None:
    xml = tmp_path / "ttapi.xml"
    text = TTAPI.read_text()
    without = re.sub(r'\s*<message id="\d+" name="TT_VR_CONTROLLER">.*?</message>', "", text, flags=re.S)
    assert without != text
    xml.write_text(without)
    out = tmp_path / "out"
    proc = subprocess.run(ttctl_cmd() + ["gen", str(xml), "--lang", "cpp", "-o", str(out)], capture_output=True,
                          text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    receive = (out / "cpp" / "ttapi" / "node_receive.hpp").read_text()
    assert "vr_confirmation" not in receive and "TtVrController" not in receive
    assert "vr_confirmation" in (ROOT / "generated" / "cpp" / "ttapi" / "node_receive.hpp").read_text()
    (tmp_path / "main.cpp").write_text('#include "ttapi/node.hpp"\n\nint main()\n{\n'
                                       "    ttapi::link::Node node{ttapi::link::NodeConfig{}};\n"
                                       "    return static_cast<int>(node.stats().vr_confirmed);\n}\n")
    gxx(*WARN, "-fsyntax-only", "-I", str(out / "cpp"), str(tmp_path / "main.cpp"))
