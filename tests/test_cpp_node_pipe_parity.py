"""The C++ node's MOP pipeline path (node_pipe.hpp) against ttctl's Python Endpoint
(proto/pipeline.py), sans-IO in virtual time (tests/cpp/node/node_driver.cpp): a Python tablet
fetches a file over a lossy packet channel while a pipeline beside it opens, closes mid-transfer
and opens again; in both worlds the onboard end sends the same packets and the same pipeline
frames byte for byte at every 5 ms step (file data on the pipeline in wide frames at its pace,
statuses and offers in the packets, narrow frames from the next offsets while it is closed).
Compared unsigned (a pipeline's signing, link id ^ 0x80, starts from the wall clock on both
sides); signed, a Python tablet accepts the node's pipeline frames."""

from __future__ import annotations

import random
from pathlib import Path

import pytest

from cpp_node_lib import ServingOnboards, needs_gxx, write
from test_cpp_node_parity import TABLET, shipped_bindings

pytestmark = needs_gxx

LATENCY = 0.05  # s a pipeline frame takes to the tablet; a close drops those on their way


@pytest.mark.parametrize("seed,loss,mtu", [(21, 0.05, 128), (22, 0.1, 100)])
def test_the_node_uses_the_pipeline_as_pythons_endpoint_does(cpp_node_bins: dict[str, Path], tmp_path: Path,
                                                             seed: int, loss: float, mtu: int) -> None:
    from ttctl.proto.endpoint import Endpoint
    from ttctl.proto.storage import ReceiveDir

    b = shipped_bindings()
    serve = write(tmp_path / "serve" / "s.bin", 120_000, seed).parent
    onboard = ServingOnboards(cpp_node_bins["driver"], tmp_path, serve, b, seed + 100, mtu)
    events = {1.0: True, 3.0: False, 4.5: True}  # the pipeline opens, closes mid-file, opens again
    worlds = []
    for name in ("python", "cpp"):
        done: list[bool] = []
        tab = Endpoint(b, *TABLET, mtu=mtu, rate_Bps=500.0, receive_dir=ReceiveDir(tmp_path / f"tablet_{name}"),
                       unsolicited=False, accept_commands=False, rng=random.Random(seed),
                       on_event=lambda what, obj, done=done: done.append(True) if what == "file-complete" else None)
        tab.request_file("s.bin", (1, 240))
        worlds.append((name, tab, random.Random(seed), done, []))  # [(due, frame)] on the pipeline
    now = 0.0
    frames = {"python": 0, "cpp": 0}
    packets_while_open = 0
    is_open = False
    try:
        while not all(w[3] for w in worlds) and now < 120:
            if now in events:
                is_open = events[now]
                for name, tab, _, _, flying in worlds:
                    onboard.set_pipe(name, now, is_open)
                    if not is_open:
                        flying.clear()  # in flight at the close: lost (the status names them)
                        tab.forget_source("pipe")
            outs, pipes = {}, {}
            for name, tab, lose, _, flying in worlds:
                while (pkt := tab.poll(now)) is not None:
                    if lose.random() >= loss:
                        onboard.receive(name, now, pkt)
                out = outs[name] = onboard.poll(name, now)
                pipe = pipes[name] = onboard.poll_pipe(name, now)
                flying.extend((now + LATENCY, f) for f in pipe)
                while flying and flying[0][0] <= now:
                    tab.receive_stream(now, flying.pop(0)[1], "pipe")
                for pkt in out:
                    if lose.random() >= loss:
                        tab.receive(now, pkt)
                frames[name] += len(pipe)
            assert outs["cpp"] == outs["python"], (now, [p.hex() for p in outs["cpp"]],
                                                   [p.hex() for p in outs["python"]])
            assert pipes["cpp"] == pipes["python"], (now, [p.hex() for p in pipes["cpp"]],
                                                     [p.hex() for p in pipes["python"]])
            if is_open:
                packets_while_open += sum(p.count(bytes.fromhex("59c300")) + p.count(bytes.fromhex("5ec300"))
                                          + p.count(bytes.fromhex("52c300")) for p in outs["python"])
            now = round(now + 0.005, 6)
    finally:
        onboard.close()
    assert all(w[3] for w in worlds), "a fetch did not complete"
    for name in ("python", "cpp"):
        assert (tmp_path / f"tablet_{name}" / "s.bin").read_bytes() == (serve / "s.bin").read_bytes()
    assert frames["python"] > 50, frames  # the pipeline carried file data
    assert packets_while_open == 0  # no data frame in the packets while the pipeline was open


def test_signed_pipeline_frames_carry_their_own_link_id(cpp_node_bins: dict[str, Path], tmp_path: Path) -> None:
    """Signed, the node's pipeline frames are signed with link id 0x80 (link id ^ PIPE_LINK_BIT,
    as ttctl's Python signs them) and a signed Python tablet accepts them: a fetch with the
    pipeline open throughout completes, its data all on the pipeline."""
    from ttctl.proto.endpoint import Endpoint
    from ttctl.proto.storage import ReceiveDir

    b = shipped_bindings()
    seed = 31
    serve = write(tmp_path / "serve" / "s.bin", 60_000, seed).parent
    key = random.Random(seed).randbytes(32)
    start = b.mavlink.Signing.now()  # the wall clock: a pipeline's signing starts from it on both ends
    onboard = ServingOnboards(cpp_node_bins["driver"], tmp_path, serve, b, seed + 100, 128, key, start)
    done: list[bool] = []
    tab = Endpoint(b, *TABLET, mtu=128, rate_Bps=500.0, receive_dir=ReceiveDir(tmp_path / "tablet"),
                   signing=b.mavlink.Signing(key, 0, False, start), unsolicited=False, accept_commands=False,
                   rng=random.Random(seed),
                   on_event=lambda what, obj: done.append(True) if what == "file-complete" else None)
    tab.request_file("s.bin", (1, 240))
    onboard.set_pipe("cpp", 0.0, True)
    now = 0.0
    links: set[int] = set()
    frames = 0
    try:
        while not done and now < 60:
            while (pkt := tab.poll(now)) is not None:
                onboard.receive("cpp", now, pkt)
            for pkt in onboard.poll("cpp", now):
                tab.receive(now, pkt)
            for frame in onboard.poll_pipe("cpp", now):
                assert frame[2] & 1, frame.hex()  # signed
                links.add(frame[-13])
                frames += 1
                tab.receive_stream(now, frame, "pipe")
            now = round(now + 0.005, 6)
    finally:
        onboard.close()
    assert done, "the fetch did not complete"
    assert (tmp_path / "tablet" / "s.bin").read_bytes() == (serve / "s.bin").read_bytes()
    assert links == {0x80} and frames >= 60_000 // 247, (links, frames)
