"""The broken-dialect corpus: each offending line carries `<!-- expect: error|warning|note CODE -->`,
and validation must report exactly those diagnostics (code, severity, file, line)."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from conftest import ROOT, run_ttctl
from ttctl.validate import load_and_check

CORPUS = ROOT / "tests" / "dialects" / "broken"
EXPECT_RE = re.compile(r"<!--\s*expect:\s*(error|warning|note)\s+([A-Z0-9-]+)\s*-->")


def cases() -> list[Path]:
    singles = sorted(CORPUS.glob("*.xml"))
    dirs = sorted(p / "a.xml" for p in CORPUS.iterdir() if p.is_dir())
    return singles + dirs


def expected(case: Path) -> set[tuple[str, int, str, str]]:
    files = [case] if case.parent == CORPUS else sorted(case.parent.glob("*.xml"))
    out = set()
    for f in files:
        for lineno, line in enumerate(f.read_text().splitlines(), 1):
            for m in EXPECT_RE.finditer(line):
                out.add((f.name, lineno, m.group(1), m.group(2)))
    return out


def in_case(case: Path, path: str) -> bool:
    base = CORPUS if case.parent == CORPUS else case.parent
    return Path(path).resolve().parent == base.resolve()


@pytest.mark.parametrize("case", cases(), ids=lambda p: str(p.relative_to(CORPUS)))
def test_library_reports_exactly_the_expected_diagnostics(case: Path) -> None:
    want = expected(case)
    assert want, f"{case} has no expect markers"
    _, rep, _ = load_and_check(str(case), [])
    got = {(Path(d.path).name, d.line, d.severity, d.code) for d in rep.items if in_case(case, d.path)}
    assert got == want


@pytest.mark.parametrize("case", cases(), ids=lambda p: str(p.relative_to(CORPUS)))
def test_cli_json_matches_and_exit_status(case: Path) -> None:
    want = expected(case)
    proc = run_ttctl("validate", str(case), "--format", "json", cwd=case.parent)
    doc = json.loads(proc.stdout)
    got = {(Path(d["path"]).name, d["line"], d["severity"], d["code"]) for d in doc["diagnostics"]
           if in_case(case, str(case.parent / d["path"]))}
    assert got == want
    has_errors = any(sev == "error" for _, _, sev, _ in want)
    assert proc.returncode == (1 if has_errors else 0)
    assert doc["errors"] == sum(1 for d in doc["diagnostics"] if d["severity"] == "error")
    for d in doc["diagnostics"]:
        assert d["col"] >= 1 and d["message"] and d["code"]


def test_text_format_is_path_line_col_severity_code() -> None:
    case = CORPUS / "duplicates.xml"
    proc = run_ttctl("validate", "duplicates.xml", cwd=CORPUS)
    lines = proc.stdout.splitlines()
    diag_re = re.compile(r"^duplicates\.xml:(\d+):(\d+): (error|warning): \[([A-Z0-9-]+)\] .+")
    parsed = [diag_re.match(line) for line in lines[:-1]]
    assert all(parsed), lines
    assert {(int(m.group(1)), m.group(3), m.group(4)) for m in parsed if m} == {
        (line, sev, code) for _, line, sev, code in expected(case)
    }
    assert lines[-1].startswith("duplicates.xml: 5 errors, 0 warnings")


def test_duplicates_name_both_places() -> None:
    proc = run_ttctl("validate", "duplicates.xml", cwd=CORPUS)
    dup_id = next(line for line in proc.stdout.splitlines() if "[DUP-MSG-ID]" in line)
    assert "SECOND" in dup_id and "FIRST at duplicates.xml:13:" in dup_id


def test_duplicates_across_includes_point_into_the_include() -> None:
    proc = run_ttctl("validate", "a.xml", cwd=CORPUS / "include_dups")
    dup = next(line for line in proc.stdout.splitlines() if "[DUP-MSG-ID]" in line)
    assert dup.startswith("a.xml:11:") and "HEARTBEAT at " in dup and "minimal.xml:" in dup


def test_include_cycle_names_the_chain() -> None:
    proc = run_ttctl("validate", "a.xml", cwd=CORPUS / "include_cycle")
    assert "include cycle: a.xml -> b.xml -> a.xml" in proc.stdout
    assert proc.returncode == 1


def test_columns_point_at_the_offending_attribute() -> None:
    proc = run_ttctl("validate", "array_length.xml", cwd=CORPUS)
    first = proc.stdout.splitlines()[0]
    line_text = (CORPUS / "array_length.xml").read_text().splitlines()[5]
    col = int(first.split(":")[2])
    assert line_text[col - 1:].startswith('type="uint8_t[0]"')
