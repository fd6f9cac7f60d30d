"""The Python side of tests/test_java_packets.py: reads the cases PacketsDriver.java reads and
prints the lines it should print, from ttctl's Python Packetizer and PacketReceiver. Run with
the freshly generated Python bindings first on PYTHONPATH."""

from __future__ import annotations

import sys
from typing import Any

import ttapi  # the freshly generated one, first on PYTHONPATH
from ttctl.wire.bindings import Bindings
from ttctl.wire.packets import Packetizer, PacketReceiver


def packetize(t: list[str]) -> str:
    got: list[bytes] = []
    p = Packetizer(got.append, int(t[1]))
    toks = []
    for h in t[2:]:
        p.add(bytes.fromhex(h))
        toks.append(",".join(x.hex() for x in got) + f"/{p.pending}")
        got.clear()
    p.flush()
    toks.append(",".join(x.hex() for x in got) + f"/{p.pending}")
    return " ".join(["P", *toks])


def messages(ms: list[Any]) -> str:
    return ",".join(("S" if m.get_signed() else "U")
                    + m.pack(m.get_seq(), m.get_srcSystem(), m.get_srcComponent()).hex() for m in ms)


def receive(t: list[str]) -> str:
    rx = PacketReceiver(Bindings(ttapi))
    toks = []
    for h in t[1:]:
        got = rx.feed(b"" if h == "-" else bytes.fromhex(h))
        toks.append(messages(got) + f"/{rx.pending}")
    toks.append(messages(rx.flush()) + f"/{rx.pending}")
    s = rx.stats
    toks.append(f"{s.packets}:{s.frames}:{s.bad_frames}:{s.carries_dropped}:{s.rescans}:{s.unknown}")
    return " ".join(["R", *toks])


def main() -> None:
    out = []
    for line in sys.stdin:
        t = line.split()
        if not t:
            continue
        out.append(packetize(t) if t[0] == "P" else receive(t))
    out.append("DONE")
    sys.stdout.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
