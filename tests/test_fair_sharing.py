"""Several senders, one receiver: five `ttctl send-file` processes at once through `ttctl link
relay --profile m100 --loss 0.1` (random and burst) to `ttctl recv-file --profile m100`, which
grants each transfer a share of its uplink in every status (TT_FILE_STATUS.rate_grant). Before
grants each sender paced to the whole link, the relay's two-packet buffer overflowed, and each
sent its file about twice over (`ttctl bench transfer`'s sharing rows: resent 1.04 to 1.58 of
the file bytes without grants). Then one sender alone on the same relay, for the ratio.
"""

from __future__ import annotations

import hashlib
import json
import random
import subprocess
from pathlib import Path

import pytest

from conftest import ROOT, ttctl_cmd
from e2e_lib import LOCAL, Start, free_port, receiver, relay

SIZE = 3000  # B: five of them take about 45 s on the 500 B/s uplink at 10 % loss


def senders(files: list[Path], port: int, timeout: float = 150) -> list[tuple[int, dict, str]]:
    """`send-file` of each file at once (the same moment, as five terminals would), each to the relay."""
    procs = [subprocess.Popen([*ttctl_cmd(), "send-file", str(f), "--to", f"udp:{LOCAL}:{port}", "--profile", "m100",
                               "--timeout", "60", "--json", "--no-compress"],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT)
             for f in files]
    out = []
    for p in procs:
        try:
            stdout, stderr = p.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            for q in procs:
                q.kill()
            raise AssertionError("a sender hung") from None
        assert "Traceback" not in stderr, stderr
        out.append((p.returncode, json.loads(stdout) if stdout.strip() else {}, stderr))
    return out


@pytest.mark.parametrize("model,seed", [("random", 11), ("burst", 12)])
def test_five_senders_share_the_uplink(tmp_path: Path, start: Start, model: str, seed: int) -> None:
    a, b = free_port(), free_port()
    receiver(start, tmp_path, f"udpin:{LOCAL}:{b}", "--profile", "m100")
    relay(start, a, b, "--profile", "m100", "--loss", "0.1", "--loss-model", model, "--seed", str(seed),
          "--stats-interval", "0")
    files = []
    for i in range(6):
        f = tmp_path / f"f{i}.bin"
        f.write_bytes(random.Random(seed * 10 + i).randbytes(SIZE))
        files.append(f)
    results = senders(files[:5], a)
    for code, r, err in results:
        assert code == 0 and r.get("ok"), err
    for f in files[:5]:
        assert hashlib.sha256((tmp_path / "inbox" / f.name).read_bytes()).digest() == \
            hashlib.sha256(f.read_bytes()).digest()
    [(code, alone, err)] = senders(files[5:], a)
    assert code == 0 and alone["ok"], err
    secs = [r["seconds"] for _, r, _ in results]
    resent = sum(r["retransmitted_bytes"] for _, r, _ in results) / (5 * SIZE)
    capacity = alone["capacity_Bps"]
    aggregate = 5 * SIZE / max(secs) / capacity
    report = {"model": model, "seconds": secs, "slowest_over_fastest": round(max(secs) / min(secs), 3),
              "resent_share": round(resent, 3), "aggregate_efficiency": round(aggregate, 4),
              "alone_efficiency": alone["efficiency"], "ratio": round(aggregate / alone["efficiency"], 3)}
    print("MEASURED", json.dumps(report))
    assert max(secs) <= 1.5 * min(secs), report
    assert resent < 0.3, report  # 1.04 to 1.58 without grants (bench transfer's sharing rows)
    # the 0.9 of one sender is judged in `bench transfer` (the model: 0.99 random, 0.90 burst);
    # live, five processes and a relay on two shared cores add their own jitter
    assert aggregate >= 0.8 * alone["efficiency"], report
