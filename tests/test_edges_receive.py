"""recv-file's promises at the edges (issue 20): --count counts distinct files, a receive
leaves no empty `.ttctl-partial/`, --json answers refusals in JSON too (real processes)."""

from __future__ import annotations

import json
import os
from pathlib import Path

from conftest import assert_no_traceback, run_ttctl
from e2e_lib import LOCAL, Start, data_file, free_port, receiver, send


def test_count_counts_distinct_files_and_no_empty_partial_folder(tmp_path: Path, start: Start) -> None:
    a = data_file(tmp_path, "a.bin", size=4096)
    b = data_file(tmp_path, "b.bin", size=4096, seed=2)
    port = free_port()
    recv = receiver(start, tmp_path, f"udpin:{LOCAL}:{port}", "--count", "2", "--json")
    for _ in range(2):  # the same file twice (as a sender that never heard COMPLETE would): one file
        proc, r = send(str(a), "--to", f"udpout:{LOCAL}:{port}")
        assert proc.returncode == 0 and r["ok"], proc.stderr
    recv.wait_for('"complete-again"', where="stdout")
    assert recv.p.poll() is None, "one file sent twice was counted as two"
    proc, r = send(str(b), "--to", f"udpout:{LOCAL}:{port}")
    assert proc.returncode == 0 and r["ok"], proc.stderr
    assert recv.wait() == 0
    events = [json.loads(line)["event"] for line in recv.stdout.splitlines()]
    assert events.count("complete") == 2 and events.count("complete-again") == 1, events
    assert sorted(os.listdir(tmp_path / "inbox")) == ["a.bin", "b.bin"]  # no empty .ttctl-partial/


def test_json_refusals_are_json(tmp_path: Path) -> None:
    (tmp_path / "here.bin").write_bytes(b"x")
    cases = [
        (["send-file", "nope", "--to", "udpout:127.0.0.1:9", "--json"], 2, "BAD_INPUT", "nope"),
        (["send-file", "here.bin", "--from", "udpout:127.0.0.1:9", "--json"], 1, "REFUSED", "exists here"),
    ]
    for args, code, what, text in cases:
        proc = run_ttctl(*args, cwd=tmp_path)
        assert_no_traceback(proc)
        assert proc.returncode == code, proc.stderr
        r = json.loads(proc.stdout)
        assert r["ok"] is False and r["code"] == what and text in r["message"] and r["exit"] == code
        assert proc.stderr.strip().count("\n") == 0 and proc.stderr.startswith("ttctl: error: ")
    proc = run_ttctl("recv-file", "--listen", "udpin:127.0.0.1:0", "--dir", "here.bin", "--json", cwd=tmp_path)
    assert proc.returncode == 2
    r = json.loads(proc.stdout)
    assert r["event"] == "error" and "not a directory" in r["message"] and r["exit"] == 2
    assert sorted(os.listdir(tmp_path)) == ["here.bin"]


def test_every_json_command_answers_a_refusal_in_json(tmp_path: Path) -> None:
    """Commands without JSON of their own for refusals: the one line on stderr, and on stdout
    `{"ok": false, "error": ..., "exit": ...}` (app-wide, for any --json)."""
    for args, text in ((["link", "fit", "nope.json", "-o", "x.toml", "--json"], "nope.json: No such file"),
                       (["bench", "transfer", "--profile", "nope", "--json"], "unknown link profile 'nope'"),
                       (["bench", "latency", "--profile-file", "nope.toml", "--json"], "nope.toml")):
        proc = run_ttctl(*args, cwd=tmp_path)
        assert proc.returncode == 2, proc.stderr
        r = json.loads(proc.stdout)
        assert r["ok"] is False and text in r["error"] and r["exit"] == 2, r
        assert proc.stderr.startswith("ttctl: error: ") and proc.stderr.count("\n") == 1
    assert os.listdir(tmp_path) == []
