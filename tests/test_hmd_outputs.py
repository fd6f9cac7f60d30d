"""An existing output is not replaced by accident (real processes): `ttctl hmd dump -o FILE` and
`ttctl link fit -o FILE` refuse a file that exists, in one line, leaving it as it was, unless
`--force` (as `ros2 bag record` refuses an existing bag)."""

from __future__ import annotations

import json
from pathlib import Path

from conftest import assert_no_traceback, run_ttctl


def _refused(args: list[str], path: Path) -> None:
    before = path.read_bytes()
    proc = run_ttctl(*args, timeout=60)
    assert_no_traceback(proc)
    assert proc.returncode == 2, proc.stderr
    assert proc.stderr.strip() == f"ttctl: error: {path} exists: --force replaces it" or \
        proc.stderr.strip() == f"ttctl: error: -o {path} exists: --force replaces it", proc.stderr
    assert path.read_bytes() == before
    assert sorted(p.name for p in path.parent.iterdir() if p.name.startswith(".")) == []  # no temporary left


def test_hmd_dump_refuses_an_existing_recording_without_force(tmp_path: Path) -> None:
    for ext in ("jsonl", "mcap"):
        rec = tmp_path / f"session.{ext}"
        rec.write_bytes(b"precious\n")
        args = ["hmd", "dump", "--duration", "0.5", "--speed", "0", "-o", str(rec)]
        _refused(args, rec)
        proc = run_ttctl(*args, "--force", "-q", timeout=60)
        assert proc.returncode == 0, proc.stderr
        assert rec.read_bytes() != b"precious\n"
    assert run_ttctl("hmd", "dump", "--duration", "0.2", "--speed", "0", "-o", "/dev/null", "--format", "jsonl",
                     "-q", timeout=60).returncode == 0  # not a regular file: written into, not replaced


def test_link_fit_refuses_an_existing_profile_without_force(tmp_path: Path) -> None:
    from test_link_fit import field_day, known

    files = []
    for m in field_day(known("burst"), count=200):
        path = tmp_path / m.path
        path.write_text(json.dumps(m.report))
        files.append(str(path))
    out = tmp_path / "site.toml"
    out.write_text("# hand-edited\n[site]\n")
    _refused(["link", "fit", *files, "-o", str(out)], out)
    proc = run_ttctl("link", "fit", *files, "-o", str(out), "--force", timeout=60)
    assert proc.returncode == 0, proc.stderr
    assert out.read_text().startswith("# Link profile 'site'")


def test_help_names_the_vr_extra() -> None:
    """Rich reads "[vr]" as a style tag unless it is escaped: the help must show it."""
    for cmd in (["hmd", "dump", "--help"], ["hmd", "pulse", "--help"]):
        proc = run_ttctl(*cmd, timeout=60, env={"COLUMNS": "200"})
        assert proc.returncode == 0
        assert "ttctl[vr]" in proc.stdout, proc.stdout
