"""`ttctl validate` as a real process: exit status, formats, options, and bad input that must
end in one clear line, never a traceback, never network or file access beyond the dialect."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from conftest import TTAPI, assert_no_traceback, run_ttctl

MINIMAL_OK = """<?xml version="1.0"?>
<mavlink>
  <messages>
    <message id="60000" name="HELLO">
      <description>x</description>
      <field type="uint8_t" name="a">a</field>
    </message>
  </messages>
</mavlink>
"""


def one_line_error(proc, code: int) -> str:  # type: ignore[no-untyped-def]
    assert proc.returncode == code, (proc.returncode, proc.stdout, proc.stderr)
    assert_no_traceback(proc)
    out = (proc.stdout + proc.stderr).strip().splitlines()
    assert len(out) == 1, out
    return out[0]


def test_ttapi_validates_clean() -> None:
    proc = run_ttctl("validate", str(TTAPI))
    assert proc.returncode == 0, proc.stdout
    assert "0 errors, 0 warnings" in proc.stdout


def test_json_document(tmp_path: Path) -> None:
    proc = run_ttctl("validate", str(TTAPI), "--format", "json")
    doc = json.loads(proc.stdout)
    assert doc["ok"] is True and doc["errors"] == 0 and doc["own_messages"] == 16
    assert any(f.endswith("common.xml") for f in doc["files"])


@pytest.mark.parametrize(
    ("content", "code", "needle"),
    [
        (b'<?xml version="1.0"?>\n<mavlink>\n <messages>\n  <message id="1" name="A">\n</mavlink>\n',
         "XML-SYNTAX", "5:"),
        (b'<?xml version="1.0"?>\n<mavlink><messages><message id="60000" name="A"><description>caf\xe9'
         b'</description><field type="uint8_t" name="a">x</field></message></messages></mavlink>\n',
         "ENCODING", "2:"),
        (b"", "XML-SYNTAX", "empty"),
    ],
    ids=["malformed", "not-utf8", "empty"],
)
def test_unreadable_xml_is_one_line_exit_2(tmp_path: Path, content: bytes, code: str, needle: str) -> None:
    f = tmp_path / "bad.xml"
    f.write_bytes(content)
    line = one_line_error(run_ttctl("validate", str(f)), 2)
    assert f"[{code}]" in line and needle in line


def test_billion_laughs_is_refused_without_expansion(tmp_path: Path) -> None:
    lol = "".join(f'<!ENTITY lol{i} "{f"&lol{i - 1};" * 10}">' for i in range(1, 10))
    doc = f'<?xml version="1.0"?>\n<!DOCTYPE x [<!ENTITY lol0 "lol">{lol}]>\n<mavlink>&lol9;</mavlink>\n'
    f = tmp_path / "laughs.xml"
    f.write_text(doc)
    line = one_line_error(run_ttctl("validate", str(f), timeout=20), 2)
    assert "[DTD]" in line and ":2:1:" in line


def test_external_entity_is_refused_and_not_read(tmp_path: Path) -> None:
    secret = tmp_path / "secret.txt"
    secret.write_text("TOP-SECRET-CONTENT")
    doc = (f'<?xml version="1.0"?>\n<!DOCTYPE m [<!ENTITY x SYSTEM "file://{secret}">]>\n'
           '<mavlink><messages><message id="1" name="A"><description>&x;</description>'
           '<field type="uint8_t" name="a">a</field></message></messages></mavlink>\n')
    f = tmp_path / "xxe.xml"
    f.write_text(doc)
    proc = run_ttctl("validate", str(f), "--format", "json")
    assert proc.returncode == 2
    assert "TOP-SECRET" not in proc.stdout + proc.stderr
    assert json.loads(proc.stdout)["diagnostics"][0]["code"] == "DTD"


def test_network_entity_in_include_is_not_fetched(tmp_path: Path) -> None:
    (tmp_path / "root.xml").write_text(MINIMAL_OK.replace("<mavlink>", "<mavlink>\n  <include>http://127.0.0.1:9/x.xml</include>"))
    proc = run_ttctl("validate", str(tmp_path / "root.xml"), timeout=20)
    assert proc.returncode == 1 and "[INCLUDE-MISSING]" in proc.stdout


def test_directory_and_missing_file(tmp_path: Path) -> None:
    assert "is a directory" in one_line_error(run_ttctl("validate", str(tmp_path)), 2)
    assert "no such file" in one_line_error(run_ttctl("validate", str(tmp_path / "nope.xml")), 2)


def test_fifty_megabyte_file_is_refused_quickly(tmp_path: Path) -> None:
    f = tmp_path / "huge.xml"
    with open(f, "wb") as fh:
        fh.write(b'<?xml version="1.0"?>\n<mavlink>')
        fh.truncate(50 * 1000 * 1000)
    line = one_line_error(run_ttctl("validate", str(f), timeout=20), 2)
    assert "[TOO-LARGE]" in line and "50.0 MB" in line


def test_bad_include_file_is_an_error_in_context(tmp_path: Path) -> None:
    (tmp_path / "broken.xml").write_text("<mavlink><messages>")
    (tmp_path / "root.xml").write_text(MINIMAL_OK.replace("<mavlink>", "<mavlink>\n  <include>broken.xml</include>"))
    proc = run_ttctl("validate", "root.xml", cwd=tmp_path)
    assert proc.returncode == 1
    assert_no_traceback(proc)
    assert proc.stdout.startswith("broken.xml:1:")
    assert "[XML-SYNTAX]" in proc.stdout


@pytest.mark.parametrize("args", [["validate"], ["validate", "x.xml", "--format", "yaml"],
                                  ["validate", "x.xml", "--mtu", "-3"], ["validat", "x.xml"], ["nope"]])
def test_bad_options_exit_2_with_one_line(args: list[str]) -> None:
    line = one_line_error(run_ttctl(*args), 2)
    assert "error" in line


def test_include_dirs_are_searched_after_the_includer(tmp_path: Path) -> None:
    lib = tmp_path / "lib"
    lib.mkdir()
    (lib / "extra.xml").write_text(MINIMAL_OK)
    root = tmp_path / "root.xml"
    root.write_text(MINIMAL_OK.replace("<mavlink>", "<mavlink>\n  <include>extra.xml</include>")
                    .replace("60000", "60001").replace("HELLO", "WORLD"))
    assert run_ttctl("validate", str(root)).returncode == 1
    proc = run_ttctl("validate", str(root), "-I", str(lib))
    assert proc.returncode == 0, proc.stdout
    assert "2 messages" in proc.stdout


def test_mtu_and_signed_budget(tmp_path: Path) -> None:
    f = tmp_path / "m.xml"
    f.write_text(MINIMAL_OK.replace('type="uint8_t" name="a"', 'type="uint8_t[80]" name="a"'))
    assert "[MTU]" not in run_ttctl("validate", str(f)).stdout  # 92-byte frame
    signed = run_ttctl("validate", str(f), "--signed")  # 105-byte frame
    assert signed.returncode == 0 and "[MTU]" in signed.stdout and "105 bytes" in signed.stdout
    assert "[MTU]" in run_ttctl("validate", str(f), "--mtu", "90").stdout
    assert "[MTU]" not in run_ttctl("validate", str(f), "--mtu", "0", "--signed").stdout


def test_hidden_pymavlink_warnings_can_be_shown() -> None:
    quiet = run_ttctl("validate", str(TTAPI))
    loud = run_ttctl("validate", str(TTAPI), "--all-warnings")
    assert "hidden (--all-warnings)" in quiet.stdout
    assert "[ENUM-VALUE-RANGE]" in loud.stdout and "[ENUM-VALUE-RANGE]" not in quiet.stdout


def test_unwritable_stdout_does_not_traceback(tmp_path: Path) -> None:
    import subprocess

    from conftest import ttctl_cmd

    r, w = os.pipe()
    os.close(r)  # a closed pipe: writes fail with EPIPE
    proc = subprocess.run(ttctl_cmd() + ["validate", str(TTAPI)], stdout=w, stderr=subprocess.PIPE,
                          text=True, timeout=60)
    os.close(w)
    assert "Traceback" not in proc.stderr
