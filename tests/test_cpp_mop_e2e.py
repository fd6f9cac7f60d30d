"""The generated node's MOP pipeline against ttctl's own Python end: `ttctl send-file --profile
mop --pipeline tcpout:` to and from tests/cpp/psdk/mop_node.cpp (PsdkLink on the low-speed
channel's stand-in, UDP; MopLink on the MOP channel's stand-in, TCP; built against DJI's vendored
headers, tests/mop_lib.py):

- a 2 MB upload: the data over the pipeline (what ttctl wrote there is what the stand-in read),
  SHA-256 equal;
- the same with the stand-in closing the pipeline twice under the node mid-transfer: ttctl
  carries on over the low-speed channel and back, the file arrives whole;
- a fetch the node serves over the pipeline through an SDK that takes at most 7 bytes a send;
- a send that never returns: a timeout after 2 s, the connection closed under it, accepted again.
"""

from __future__ import annotations

import random
import shutil
from pathlib import Path
from typing import Any

import pytest

from e2e_lib import LOCAL, send
from mop_lib import MopNode, build_mop_node, sha

pytestmark = pytest.mark.skipif(shutil.which("g++") is None, reason="needs g++")

MB2 = 2 * 1024 * 1024


@pytest.fixture(scope="module")
def mop_node(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return build_mop_node(tmp_path_factory.mktemp("mop_e2e"))


@pytest.fixture
def nodes() -> Any:
    started: list[MopNode] = []

    def start(*args: Any, **kw: Any) -> MopNode:
        n = MopNode(*args, **kw)
        started.append(n)
        return n

    yield start
    for n in started:
        n.kill()


def paths(node: MopNode) -> list[str]:
    return ["--profile", "mop", "--pipeline", f"tcpout:{LOCAL}:{node.pipe_port}", "--timeout", "60"]


def test_send_file_2mb_over_the_pipeline(mop_node: Path, tmp_path: Path, nodes: Any) -> None:
    node = nodes(mop_node, tmp_path, {})
    node.wait_ready()
    src = tmp_path / "big.bin"
    src.write_bytes(random.Random(1).randbytes(MB2))
    proc, r = send(str(src), "--to", f"udpout:{LOCAL}:{node.port}", *paths(node), timeout=180)
    assert proc.returncode == 0 and r["ok"], proc.stderr
    assert sha(node.inbox / "big.bin") == sha(src)
    assert r["pipeline_opens"] == 1 and r["pipeline_closes"] == 0 and r["pipeline_bytes_out"] >= MB2, r
    stats = node.stop()
    # every byte ttctl wrote there (and its hello, a HEARTBEAT, which it does not count)
    assert 0 <= stats["sdk_bytes_in"] - r["pipeline_bytes_out"] <= 64, (stats, r)
    assert stats["pipe_frames_in"] >= MB2 // 247 and stats["bad_bytes"] == 0, stats


def test_send_file_with_the_pipeline_closed_twice(mop_node: Path, tmp_path: Path, nodes: Any) -> None:
    node = nodes(mop_node, tmp_path, {"TTCTL_FAKE_MOP_CLOSE_AFTER": "500000,1300000"})
    node.wait_ready()
    src = tmp_path / "big.bin"
    src.write_bytes(random.Random(2).randbytes(MB2))
    proc, r = send(str(src), "--to", f"udpout:{LOCAL}:{node.port}", *paths(node), timeout=240)
    assert proc.returncode == 0 and r["ok"], proc.stderr
    assert sha(node.inbox / "big.bin") == sha(src)
    assert r["pipeline_closes"] >= 2 and r["pipeline_opens"] >= 3, r
    stats = node.stop()
    assert stats["sdk_forced_closes"] == 2 and stats["connections"] >= 3, stats
    closed = node.pipe_events("closed")
    assert len(closed) >= 2 and closed[0]["call"] == "DjiMopChannel_RecvData", closed


def test_a_fetch_served_over_the_pipeline_in_short_writes(mop_node: Path, tmp_path: Path, nodes: Any) -> None:
    node = nodes(mop_node, tmp_path, {"TTCTL_FAKE_MOP_SHORT": "1"})
    served = node.serve / "log.bin"
    served.write_bytes(random.Random(3).randbytes(600_000))
    node.wait_ready()
    got = tmp_path / "got"
    got.mkdir()
    proc, r = send("log.bin", "--from", f"udpout:{LOCAL}:{node.port}", "--dir", str(got), *paths(node), timeout=180)
    assert proc.returncode == 0 and r["ok"], proc.stderr
    assert sha(got / "log.bin") == sha(served)
    assert r["pipeline_bytes_in"] >= 600_000, r
    stats = node.stop()
    assert stats["sdk_short_sends"] > 0 and stats["pipe_bytes_out"] >= r["pipeline_bytes_in"], (stats, r)


def test_a_send_that_never_returns_is_a_timeout(mop_node: Path, tmp_path: Path, nodes: Any) -> None:
    """The SDK's send hangs after 100 kB (until the connection is closed under it): after 2 s
    the node gives the connection up in one line, closes it so the call returns, and accepts
    the app again; the fetch completes whole."""
    node = nodes(mop_node, tmp_path, {"TTCTL_FAKE_MOP_STALL": "100000"})
    served = node.serve / "log.bin"
    served.write_bytes(random.Random(4).randbytes(300_000))
    node.wait_ready()
    got = tmp_path / "got"
    got.mkdir()
    proc, r = send("log.bin", "--from", f"udpout:{LOCAL}:{node.port}", "--dir", str(got), *paths(node), timeout=180)
    assert proc.returncode == 0 and r["ok"], proc.stderr
    assert sha(got / "log.bin") == sha(served)
    assert r["pipeline_opens"] >= 2, r
    stats = node.stop()
    assert stats["sdk_stalls"] == 1 and stats["timeouts"] == 1 and stats["connections"] >= 2, stats
    closed = node.pipe_events("closed")
    assert "did not return within 2 s" in closed[0]["words"], closed
    assert stats["sdk_live_handles"] == 0, stats
