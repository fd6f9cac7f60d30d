"""Rate grants in the generated C++ onboard end (sharing.hpp; the protocol is proto/sharing.py's):
several transfers through `ttctl link relay --profile m100` (500 B/s uplink, 10 % loss), real
processes on loopback; and against Python's Endpoint in virtual time.

- The node receiving (NodeConfig::inbound_Bps, `--inbound 500`): four `ttctl send-file --profile
  m100` at once, each paced to the whole uplink, are granted a quarter of it each (of 0.97 of it,
  less twice the other traffic coming in). Every file is verified, they finish together, few bytes
  are sent twice and the relay's buffer hardly overflows. Without grants (`--inbound 0`, the same
  seed) the same run overflows the relay's buffer and resends most of what it sends: the check
  that fails without the change.
- The same decisions as Python's, byte for byte, in virtual time (node_driver): the grants of
  three or four overlapping uploads in the node's statuses (the other traffic measured, grants
  kept within a tenth, told a packet apart), and two fetches it serves paced to a tablet's
  grants (one-packet frames, each starting at the status that told it its grant).
- The node sending: its upload to `ttctl recv-file --profile m100` (which grants: it knows the
  uplink) alongside two `send-file` processes follows its grant: its data frames leave at about
  the grant, not at the node's own 500 B/s, and every file is verified.
- A dialect with a copy of ttapi.xml from before rate_grant still gets a node that builds.
"""

from __future__ import annotations

import json
import random
import re
import signal
import subprocess
from pathlib import Path
from typing import Any

import pytest

import ttapi
from conftest import TTAPI, run_ttctl, shipped
from cpp_node_lib import WARN, ServingOnboards, gxx, needs_gxx, sha, write
from e2e_lib import LOCAL, Proc, Start, free_port, receiver, relay

pytestmark = needs_gxx

UPLINK = 500  # B/s: the m100 profile's uplink at 10 m


def relay_stats(radio: Proc) -> dict[str, int]:
    """The uplink's counters from the relay's last stats line (SIGINT: it prints one and exits)."""
    radio.signal(signal.SIGINT)
    radio.wait(10)
    line = [x for x in radio.stderr.splitlines() if x.startswith("relay ") and " s: up " in x][-1]
    up = line.split(" | ")[0]
    counts = {k: int(m.group(1)) if (m := re.search(rf"(\d+) {k}\b", up)) else 0 for k in ("in", "out", "lost")}
    m = re.search(r"overflow (\d+)", up)
    counts["overflow"] = int(m.group(1)) if m else 0
    return counts


def uploads(start: Start, tmp: Path, cpp_node_bins: dict[str, Path], cpp_nodes: Any, inbound: int,
            n: int = 4, size: int = 2000) -> tuple[list[dict[str, Any]], dict[str, int]]:
    """`n` send-file --profile m100 of `size` bytes each at once to the node (--inbound), through
    the m100 relay at 10 % loss (seed 3); their reports and the relay's uplink counters."""
    folder = tmp / f"inbound{inbound}"
    folder.mkdir()
    inbox = folder / "inbox"
    b = free_port()
    node = cpp_nodes(cpp_node_bins["plain"], folder, "node", "--listen", f"udpin:{LOCAL}:{b}", "--inbox", str(inbox),
                     "--inbound", str(inbound))
    a = free_port()
    radio = relay(start, a, b, "--profile", "m100", "--loss", "0.1", "--seed", "3", "--stats-interval", "0")
    srcs = [write(folder / f"f{i}.bin", size, 40 + i) for i in range(n)]
    procs = [start(f"send{inbound}_{i}", "send-file", str(s), "--to", f"udpout:{LOCAL}:{a}", "--profile", "m100",
                   "--timeout", "60", "--json") for i, s in enumerate(srcs)]
    reports = []
    for p, s in zip(procs, srcs, strict=True):
        assert p.wait(120) == 0, p.stderr
        r = json.loads(p.stdout)
        assert r["ok"] and r["code"] == "COMPLETE", r
        assert sha(inbox / s.name) == sha(s)
        reports.append(r)
    stats = relay_stats(radio)
    node.stop()
    return reports, stats


def test_the_node_shares_its_uplink_among_four_uploads(cpp_node_bins: dict[str, Path], tmp_path: Path,
                                                         start: Start, cpp_nodes: Any) -> None:
    """Four equal uploads at once, each sender paced to the whole 500 B/s uplink: with
    --inbound 500 each is granted at most 121 B/s (0.97 x 500 / 4, less twice the offers and
    polls coming in); all verified, the slowest within 1.5x of the fastest,
    retransmitted bytes under 0.3 of the file bytes, the relay's buffer overflowing rarely (a
    fifth of the packets at most: until their grants arrive they start at full rate). The same
    run without grants overflows it several times as often and resends far more."""
    reports, stats = uploads(start, tmp_path, cpp_node_bins, cpp_nodes, UPLINK)
    seconds = [r["seconds"] for r in reports]
    resent = sum(r["retransmitted_bytes"] for r in reports) / sum(r["bytes"] for r in reports)
    assert max(seconds) <= 1.5 * min(seconds), seconds
    assert resent < 0.3, (resent, reports)
    assert stats["overflow"] <= 0.2 * stats["in"], stats

    bare, bare_stats = uploads(start, tmp_path, cpp_node_bins, cpp_nodes, 0)
    bare_resent = sum(r["retransmitted_bytes"] for r in bare) / sum(r["bytes"] for r in bare)
    print(f"MEASURED granted: {sorted(seconds)} s, resent {resent:.2f}, overflow {stats['overflow']} of "
          f"{stats['in']}; bare: {sorted(r['seconds'] for r in bare)} s, resent {bare_resent:.2f}, overflow "
          f"{bare_stats['overflow']} of {bare_stats['in']}")
    assert bare_stats["overflow"] > 2 * max(1, stats["overflow"]), (stats, bare_stats)  # seen: 4x to 24x
    assert bare_resent > 1.5 * resent, (resent, bare_resent)  # seen: 3x to 13x


def test_the_node_s_upload_follows_its_grant(cpp_node_bins: dict[str, Path], tmp_path: Path, start: Start,
                                             cpp_nodes: Any) -> None:
    """`ttctl recv-file --profile m100` (1/240, which grants: it knows the 500 B/s uplink)
    receives two send-file uploads and, a moment later, one from the node (2/240, paced at the
    whole uplink itself): three share, at most 161 B/s each (0.97 x 500 / 3, less twice the other
    traffic coming in). The node's data frames leave at about its grant, a third of its own pace;
    every file is verified."""
    b = free_port()
    rx = receiver(start, tmp_path, f"udpin:{LOCAL}:{b}", "--profile", "m100", "--json")
    a = free_port()
    relay(start, a, b, "--profile", "m100", "--loss", "0.1", "--seed", "5", "--stats-interval", "0")
    srcs = [write(tmp_path / f"p{i}.bin", 3200, 50 + i) for i in range(2)]
    procs = [start(f"send{i}", "send-file", str(s), "--to", f"udpout:{LOCAL}:{a}", "--profile", "m100", "--timeout",
                   "60", "--json") for i, s in enumerate(srcs)]
    for s in srcs:  # both accepted: the node's transfer joins two that share
        rx.wait_for(f'"event": "accepted", "name": "{s.name}"', 30, where="stdout")
    mine = write(tmp_path / "n.bin", 1600, 59)  # done while all three share
    node = cpp_nodes(cpp_node_bins["plain"], tmp_path, "node", "--to", f"udpout:{LOCAL}:{a}", "--sysid", "2",
                     "--rate", str(UPLINK), "--send", str(mine), "--send-to", "1/240")
    sent = node.wait_event("sent", 90)
    assert sent["ok"] and sent["code"] == "COMPLETE", sent
    for p in procs:
        assert p.wait(120) == 0, p.stderr
        assert json.loads(p.stdout)["ok"]
    for s in [*srcs, mine]:
        assert sha(tmp_path / "inbox" / s.name) == sha(s)
    grant = sent["grant_max"]
    assert 0 < grant <= int(UPLINK * 0.97 / 2), sent  # at least two shared while it sent
    rate = sent["wire_bytes"] / sent["data_seconds"]
    print(f"MEASURED the node's upload: {rate:.0f} B/s under a grant of {grant} B/s")
    assert 0.5 * grant <= rate <= 1.25 * grant, (rate, sent)
    node.stop()


# -- the same grants as Python's, byte for byte, in virtual time --------------------------------------

Pause = tuple[int, float, float]  # a tablet that sends nothing from one moment to another


def sharing_script(tmp: Path, seed: int, loss: float, inbound: float, sizes: list[int], starts: list[float],
                   pause: Pause | None) -> tuple[list[str], list[str], list[int]]:
    """Python tablets (Endpoints 255/190, 254/190..., each paced at 500 B/s) upload files of
    `sizes`, starting at `starts`, to a Python onboard Endpoint (1/240, paced at 6700 B/s, with
    `inbound` B/s to share) over a channel that loses `loss` of the packets either way, in
    virtual time (5 ms steps); `pause`: one of them goes quiet for a while. The sharing set grows
    and shrinks. Returns the onboard end's input as a node_driver script, what it sent at each
    poll, and the grants its statuses carried."""
    from ttctl.proto.endpoint import Endpoint
    from ttctl.proto.storage import BytesSource, ReceiveDir

    b = shipped()
    rng = random.Random(seed)
    n = len(sizes)
    rx = Endpoint(b, 1, 240, rate_Bps=6700.0, receive_dir=ReceiveDir(tmp / "python"), inbound_Bps=inbound)
    tablets = [Endpoint(b, 255 - i, 190, rate_Bps=float(UPLINK), rng=random.Random(seed * 10 + i)) for i in range(n)]
    data = [random.Random(seed + i).randbytes(size) for i, size in enumerate(sizes)]
    senders: list[Any] = [None] * n
    script: list[str] = []
    sent: list[str] = []
    grants: list[int] = []
    now = 0.0
    while (not all(s is not None and s.done for s in senders)) and now < 300:
        for i, tab in enumerate(tablets):
            if senders[i] is None and now >= starts[i]:
                senders[i] = tab.send_file(f"f{i}.bin", (1, 240), source=BytesSource(data[i], f"f{i}.bin"))
            if pause is not None and pause[0] == i and pause[1] <= now < pause[2]:
                continue  # quiet: what it would send waits
            while (pkt := tab.poll(now)) is not None:
                if rng.random() >= loss:
                    script.append(f"R {now!r} {pkt.hex()}")
                    rx.receive(now, pkt)
        out = []
        while (pkt := rx.poll(now)) is not None:
            out.append(pkt)
        script.append(f"P {now!r}")
        sent.append(" ".join(p.hex() for p in out) or "-")
        for pkt in out:
            grants += [m.rate_grant for m in ttapi.Parser().feed(pkt) if isinstance(m, ttapi.TtFileStatus)]
            if rng.random() >= loss:
                for tab in tablets:
                    tab.receive(now, pkt)
        now = round(now + 0.005, 6)
    for i, s in enumerate(senders):
        assert s.result is not None and s.result.ok, s.result
        assert (tmp / "python" / f"f{i}.bin").read_bytes() == data[i]
    return script, sent, grants


THREE = ([3000, 1200, 2000], [0.0, 3.0, 6.0])
FOUR = ([3000, 1200, 2000, 1600], [0.0, 1.0, 2.0, 3.0])


@pytest.mark.parametrize("seed,loss,inbound,files,pause,seen", [
    # alone; two share 0.97 x 500 (242 each); three share less twice the offers and polls coming in
    (1, 0.1, UPLINK, THREE, None, {0, 242, 202, 152, 134}),
    (2, 0.25, UPLINK, THREE, None, {0, 242, 215, 161, 143}),
    # four share (87 to 121 B/s as the other traffic comes and goes); one goes quiet for 5 s (it
    # leaves the sharing set after 4 frames' time at its grant), three share, it is back
    (6, 0.1, UPLINK, FOUR, (0, 6.0, 11.0), {87, 121, 161, 242}),
    (7, 0.1, 200_000, THREE, None, {0, 64639, 65535}),  # what TT_FILE_STATUS.rate_grant holds at most
], ids=["three", "three-lossy", "four-one-quiet", "wide-link"])
def test_the_node_grants_what_pythons_endpoint_grants(cpp_node_bins: dict[str, Path], tmp_path: Path, seed: int,
                                                      loss: float, inbound: int, files: tuple[list[int], list[float]],
                                                      pause: Pause | None, seen: set[int]) -> None:
    """The C++ node and ttctl's Python Endpoint, each with `inbound` B/s to share, as the onboard
    end of overlapping uploads over a lossy channel in virtual time, given the same packets at
    the same moments, send the same packets byte for byte at the same moments: the same grants
    (none alone; for n, 0.97 x inbound less twice the other traffic measured coming in over 5 s,
    at least half of inbound, over n; at most 65535) in the same statuses, changed only when the
    sharing set changes (a transfer starts, ends, goes quiet or comes back) or the share moves by
    more than a tenth, told one packet's time apart in the order of the transfers' keys, with
    statuses kept coming while frames arrive at the granted pace; and store the same files."""
    script, want, grants = sharing_script(tmp_path, seed, loss, inbound, *files, pause)
    assert seen <= set(grants), sorted(set(grants))
    run = subprocess.run([str(cpp_node_bins["driver"]), str(tmp_path / "cpp"), "-", "6700", str(inbound)],
                         input="\n".join(script) + "\n", capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    got = run.stdout.splitlines()
    assert len(got) == len(want)
    polls = [line for line in script if line.startswith("P")]
    for i, (g, w) in enumerate(zip(got, want, strict=True)):
        assert g == w, (i, polls[i], g, w)
    for i in range(len(files[0])):
        assert (tmp_path / "cpp" / f"f{i}.bin").read_bytes() == (tmp_path / "python" / f"f{i}.bin").read_bytes()


@pytest.mark.parametrize("seed,loss,inbound,size,blackout", [
    (3, 0.05, 2000, 8000, None),
    (4, 0.2, 2000, 8000, None),
    # nothing from the tablet for 6 s while data flows at 290 B/s: the servers poll it three
    # frames' time at their grant (1 s) later than they would without a grant
    (5, 0.05, 600, 2400, (3.0, 9.0)),
], ids=["lossy", "lossier", "statuses-stop"])
def test_the_node_serves_at_its_grants_as_pythons_endpoint_does(cpp_node_bins: dict[str, Path], tmp_path: Path,
                                                                seed: int, loss: float, inbound: int, size: int,
                                                                blackout: tuple[float, float] | None) -> None:
    """Two worlds in virtual time, alike but for the onboard end: a Python tablet that can take
    `inbound` B/s fetches two files at once, so it grants each fetch about 0.97 x inbound / 2
    (less twice the other traffic it measures coming in), from ttctl's Python Endpoint in one
    world and from the C++ node (paced at 6700 B/s, drawing the same transfer ids) in the other;
    `blackout`: what the tablet sends is lost from one moment to another. At every 5 ms step both
    onboard ends send the same packets byte for byte: their data frames paced to the grants
    (one-packet frames only, each server starting its frames at the status that told it a new
    grant, polling a quiet tablet three frames' time at its grant later), not to their own
    6700 B/s; both fetches complete."""
    from ttctl.proto.endpoint import Endpoint
    from ttctl.proto.storage import ReceiveDir

    b = shipped()
    serve = tmp_path / "serve"
    files = [write(serve / f"s{i}.bin", size, seed + i) for i in range(2)]
    onboard = ServingOnboards(cpp_node_bins["driver"], tmp_path, serve, b, seed + 100)
    worlds = []
    for name in ("python", "cpp"):
        done: list[bool] = []
        tab = Endpoint(b, 255, 190, rate_Bps=500.0, receive_dir=ReceiveDir(tmp_path / f"tablet_{name}"),
                       unsolicited=False, accept_commands=False, rng=random.Random(seed), inbound_Bps=float(inbound),
                       on_event=lambda what, obj, done=done: done.append(True) if what == "file-complete" else None)
        for f in files:
            tab.request_file(f.name, (1, 240))
        worlds.append((name, tab, random.Random(seed), done))
    now = 0.0
    grants: set[int] = set()
    try:
        while not all(len(w[3]) == 2 for w in worlds) and now < 120:
            outs = {}
            for name, tab, lose, _ in worlds:
                while (pkt := tab.poll(now)) is not None:
                    if name == "python":
                        grants |= {m.rate_grant for m in ttapi.Parser().feed(pkt)
                                   if isinstance(m, ttapi.TtFileStatus)}
                    quiet = blackout is not None and blackout[0] <= now < blackout[1]
                    if lose.random() >= loss and not quiet:
                        onboard.receive(name, now, pkt)
                out = outs[name] = onboard.poll(name, now)
                for pkt in out:
                    if lose.random() >= loss:
                        tab.receive(now, pkt)
            assert outs["cpp"] == outs["python"], (now, [p.hex() for p in outs["cpp"]],
                                                   [p.hex() for p in outs["python"]])
            now = round(now + 0.005, 6)
    finally:
        onboard.close()
    assert all(len(w[3]) == 2 for w in worlds), "a fetch did not complete"
    for name in ("python", "cpp"):
        for f in files:
            assert (tmp_path / f"tablet_{name}" / f.name).read_bytes() == f.read_bytes()
    fair = int(0.97 * inbound / 2)
    assert any(0.9 * fair <= g <= fair for g in grants), grants  # seen: 943 of 970
    assert now > 2 * size / inbound, now  # at their grants (1.25 x the bytes on the wire), not at 6700 B/s


def test_a_dialect_with_an_older_ttapi_xml_builds_the_node_without_grants(tmp_path: Path) -> None:
    """A user's dialect with a copy of ttapi.xml from before rate_grant (TT_FILE_STATUS without
    the extension: the same CRC_EXTRA, so the node is generated for it) builds with g++ -Werror:
    its statuses carry no grant and its senders read none."""
    text = TTAPI.read_text()
    # (TT_FILE_STATUS's extension only: TT_FILE_MAP, later still, has its own rate_grant field)
    old = re.sub(r'\s*<field type="uint16_t" name="rate_grant".*?</field>', "", text, count=1, flags=re.S)
    assert old != text
    (tmp_path / "ttapi.xml").write_text(old)
    proc = run_ttctl("gen", str(tmp_path / "ttapi.xml"), "--lang", "cpp", "-o", str(tmp_path / "out"), timeout=300)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    messages = (tmp_path / "out" / "cpp" / "ttapi" / "messages.hpp").read_text()
    status = re.search(r"struct TtFileStatus \{.*?\n\};", messages, flags=re.S)
    assert status is not None and "rate_grant" not in status.group(0)
    (tmp_path / "t.cpp").write_text("""#include "ttapi/node.hpp"
static_assert(!ttapi::link::has_rate_grant<ttapi::TtFileStatus>::value, "no rate_grant in this dialect");
int main()
{
    ttapi::link::NodeConfig cfg;
    cfg.inbound_Bps = ttapi::link::NodeConfig::M100_UPLINK_BPS;
    ttapi::TtFileStatus s;
    ttapi::link::set_rate_grant(s, 158);
    ttapi::link::Node node(cfg);
    return ttapi::link::rate_grant_of(s);
}
""")
    gxx(*WARN, "-I", str(tmp_path / "out" / "cpp"), str(tmp_path / "t.cpp"), "-o", str(tmp_path / "t"))
    assert subprocess.run([str(tmp_path / "t")], timeout=30).returncode == 0


LOAD_PROGRAM = r"""#include <cstdio>
#include "ttapi/sharing.hpp"
int main()
{
    ttapi::link::InboundLoad load;
    char what;
    double now;
    long n;
    while (std::scanf(" %c %lf %ld", &what, &now, &n) == 3) {
        if (what == 'P') {
            load.packet(now, static_cast<std::size_t>(n));
        } else if (what == 'D') {
            load.data(now, static_cast<std::size_t>(n));
        } else {
            std::printf("%.17g\n", load.other_Bps(now));
        }
    }
    return 0;
}
"""


def test_the_node_measures_the_other_traffic_as_python_does(cpp_node_bins: dict[str, Path], tmp_path: Path) -> None:
    """InboundLoad (sharing.hpp) against proto/sharing.py's, the same packets at the same moments:
    commands, offers and polls count, data frames (100 or 267 bytes each, signed or not) do not,
    over the last 5 s. Packets at least 5 ms apart (the parity tests' steps): the same figure
    exactly. A packet every millisecond for 20 s, more moments than the C++ table holds: within
    one moment's bytes of Python's (a packet's bytes leave the window at most 4.9 ms early), not
    growing without end."""
    from ttctl.proto.sharing import InboundLoad

    (tmp_path / "load.cpp").write_text(LOAD_PROGRAM)
    gxx(*WARN, "-I", str(cpp_node_bins["plain"].parent / "out" / "cpp"), str(tmp_path / "load.cpp"), "-o",
        str(tmp_path / "load"))
    rng = random.Random(11)
    for step, seconds, tolerance in ((0.005, 30.0, 0.0), (0.001, 20.0, 6 * 2 * 40 / 5)):
        py = InboundLoad()
        lines, want = [], []
        now = 0.0
        while now < seconds:
            now = round(now + step * rng.choice([1, 1, 2, 7]), 6)
            for _ in range(rng.choice([1, 1, 2])):  # one or more packets at the same moment
                kind = rng.random()
                size = rng.choice([100, 113, 267, 280]) if kind < 0.6 else rng.randint(12, 40)
                py.packet(now, size)
                lines.append(f"P {now!r} {size}")
                if kind < 0.6:  # a data frame (signed: 13 bytes more on the wire)
                    frame = 100 if size in (100, 113) else 267
                    py.data(now, frame)
                    lines.append(f"D {now!r} {frame}")
            if rng.random() < 0.3:
                lines.append(f"Q {now!r} 0")
                want.append(py.other_Bps(now))
        run = subprocess.run([str(tmp_path / "load")], input="\n".join(lines) + "\n", capture_output=True, text=True,
                             timeout=60)
        assert run.returncode == 0, run.stderr
        got = [float(x) for x in run.stdout.split()]
        assert len(got) == len(want)
        worst = max(abs(g - w) for g, w in zip(got, want, strict=True))
        assert worst <= tolerance, (step, worst, max(want))
        assert max(got) < 2 * max(want) + 1
