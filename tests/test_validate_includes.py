"""Where includes come from: next to the including file, then each -I folder; a bare file name
(no folder part) not found there is ttctl's shipped copy or pymavlink's, said in a note; any
other miss is an INCLUDE-MISSING error. A missing or substituted include does not flood other
files with errors."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from conftest import DIALECTS, pymavlink_dialects, run_ttctl
from ttctl.dialect.diagnostics import display_path

MSG = '<message id="{id}" name="{name}"><description>x</description><field type="uint8_t" name="a">a</field></message>'


def dialect(includes: list[str], body: str = "", msgid: int = 60000, name: str = "MINE") -> str:
    inc = "".join(f"  <include>{i}</include>\n" for i in includes)
    return (f'<?xml version="1.0"?>\n<mavlink>\n{inc}  <messages>\n    {MSG.format(id=msgid, name=name)}\n{body}'
            "  </messages>\n</mavlink>\n")


def validate(cwd: Path, *args: str) -> tuple[int, list[str]]:
    proc = run_ttctl("validate", *args, cwd=cwd)
    assert "Traceback" not in proc.stdout + proc.stderr
    return proc.returncode, proc.stdout.splitlines()


def shown(path: Path, cwd: Path) -> str:
    """How ttctl shows a path when run in `cwd`."""
    import os

    here = os.getcwd()
    os.chdir(cwd)
    try:
        return display_path(str(path))
    finally:
        os.chdir(here)


def test_a_path_that_does_not_exist_is_missing_not_silently_pymavlinks(tmp_path: Path) -> None:
    (tmp_path / "my.xml").write_text(dialect(["../../message_definitions/v1.0/common.xml"]))
    code, out = validate(tmp_path, "my.xml")
    assert code == 1
    assert out[0] == ("my.xml:3:3: error: [INCLUDE-MISSING] cannot find included file "
                      "'../../message_definitions/v1.0/common.xml' (looked in .; a path with a folder part is not "
                      "looked up among the shipped dialects)")


def test_a_bare_name_found_nowhere_says_where_it_looked(tmp_path: Path) -> None:
    lib = tmp_path / "lib"
    lib.mkdir()
    (tmp_path / "my.xml").write_text(dialect(["nowhere.xml"]))
    code, out = validate(tmp_path, "my.xml", "-I", "lib")
    assert code == 1
    assert out[0] == ("my.xml:3:3: error: [INCLUDE-MISSING] cannot find included file 'nowhere.xml' (looked in ., "
                      "lib, ttctl's shipped dialects, pymavlink's dialects)")


def test_bare_ttapi_is_ttctls_shipped_copy_from_anywhere(tmp_path: Path) -> None:
    """ttapi.xml is ttctl's own; its common.xml is pymavlink's; both said in notes, which are
    neither errors nor warnings."""
    (tmp_path / "my.xml").write_text(dialect(["ttapi.xml"]))
    code, out = validate(tmp_path, "my.xml")
    assert code == 0, out
    ttapi = DIALECTS / "ttapi.xml"
    common = pymavlink_dialects() / "common.xml"
    assert out[0] == ("my.xml:3:3: note: [INCLUDE-SHIPPED] 'ttapi.xml' is ttctl's shipped copy "
                      f"({shown(ttapi, tmp_path)})")
    assert out[1].startswith(f"{shown(ttapi, tmp_path)}:19:3: note: [INCLUDE-SHIPPED] 'common.xml' is pymavlink's copy "
                             f"({shown(common, tmp_path)})"), out[1]
    assert out[-1].startswith("my.xml: 0 errors, 0 warnings (227 messages, 1 in this file;"), out[-1]
    proc = run_ttctl("validate", "my.xml", "--format", "json", cwd=tmp_path)
    doc = json.loads(proc.stdout)
    assert (doc["ok"], doc["errors"], doc["warnings"], doc["notes"]) == (True, 0, 0, 2)
    assert [(d["severity"], d["code"], d["line"]) for d in doc["diagnostics"]] == [
        ("note", "INCLUDE-SHIPPED", 3), ("note", "INCLUDE-SHIPPED", 19)]


def test_bare_common_is_pymavlinks_copy_with_a_note(tmp_path: Path) -> None:
    (tmp_path / "my.xml").write_text(dialect(["common.xml"]))
    code, out = validate(tmp_path, "my.xml")
    assert code == 0
    common = pymavlink_dialects() / "common.xml"
    assert out[0] == f"my.xml:3:3: note: [INCLUDE-SHIPPED] 'common.xml' is pymavlink's copy ({shown(common, tmp_path)})"


def test_a_copy_next_to_the_file_wins_and_needs_no_note(tmp_path: Path) -> None:
    (tmp_path / "common.xml").write_text(dialect([], msgid=1, name="LOCAL_COMMON"))
    (tmp_path / "my.xml").write_text(dialect(["common.xml"]))
    code, out = validate(tmp_path, "my.xml")
    assert code == 0
    assert out == ["my.xml: 0 errors, 0 warnings (2 messages, 1 in this file; 0 enums; 2 files)"]


def test_an_include_folder_wins_over_the_shipped_copies(tmp_path: Path) -> None:
    lib = tmp_path / "lib"
    lib.mkdir()
    (lib / "ttapi.xml").write_text(dialect([], msgid=2, name="MY_TTAPI"))
    (tmp_path / "my.xml").write_text(dialect(["ttapi.xml"]))
    code, out = validate(tmp_path, "my.xml", "-I", "lib")
    assert code == 0
    assert out == ["my.xml: 0 errors, 0 warnings (2 messages, 1 in this file; 0 enums; 2 files)"]


def test_a_shipped_copy_brings_no_second_copy_of_a_file_already_loaded(tmp_path: Path) -> None:
    """A copy of upstream's ardupilotmega.xml without its loweheiser.xml: pymavlink's
    loweheiser.xml includes pymavlink's minimal.xml, a second minimal.xml beside the user's.
    It was hundreds of duplicate errors in pymavlink's minimal.xml, none naming the cause."""
    pm = pymavlink_dialects()
    for name in ("common.xml", "standard.xml", "minimal.xml"):
        shutil.copy(pm / name, tmp_path / name)
    (tmp_path / "apm.xml").write_text(dialect(["common.xml", "loweheiser.xml"]))
    code, out = validate(tmp_path, "apm.xml")
    assert code == 0, out[:5]
    notes = [line for line in out if ": note: " in line]
    assert notes[0] == (f"apm.xml:4:3: note: [INCLUDE-SHIPPED] 'loweheiser.xml' is pymavlink's copy "
                        f"({shown(pm / 'loweheiser.xml', tmp_path)})")
    assert notes[1].startswith(f"{shown(pm / 'loweheiser.xml', tmp_path)}:")
    assert notes[1].endswith(f"note: [INCLUDE-SHIPPED] 'minimal.xml' is already loaded from minimal.xml; that copy "
                             f"is used, not {shown(pm / 'minimal.xml', tmp_path)}")
    # and the warning of the copied common.xml (pymavlink's own is hidden), then the summary
    assert len(notes) == 2 and len(out) == 4 and "0 errors" in out[-1], out


def test_a_missing_include_does_not_flood_with_undefined_enums(tmp_path: Path) -> None:
    fields = "".join(f'\n<field type="uint8_t" name="f{i}" enum="PRIVATE_{i % 4}">f</field>' for i in range(30))
    body = f'    <message id="60001" name="USES"><description>x</description>{fields}</message>\n'
    (tmp_path / "my.xml").write_text(dialect(["private_enums.xml"], body))
    code, out = validate(tmp_path, "my.xml")
    assert code == 1
    errors = [line for line in out if ": error: " in line]
    assert len(errors) == 2, errors
    assert "[INCLUDE-MISSING] cannot find included file 'private_enums.xml'" in errors[0]
    assert errors[1].startswith("my.xml:7:33: error: ")
    assert errors[1].endswith("[UNDEFINED-ENUM] USES.f0 refers to enum PRIVATE_0, which is not defined here or in "
                              "any include; so do 29 more fields (enums PRIVATE_0, PRIVATE_1, PRIVATE_2, PRIVATE_3), "
                              "perhaps defined in the missing include(s)")


@pytest.mark.parametrize("fmt", ["text", "json"])
def test_notes_do_not_count_as_warnings_or_errors(tmp_path: Path, fmt: str) -> None:
    (tmp_path / "my.xml").write_text(dialect(["common.xml"]))
    proc = run_ttctl("validate", "my.xml", "--format", fmt, cwd=tmp_path)
    assert proc.returncode == 0
    if fmt == "json":
        doc = json.loads(proc.stdout)
        assert (doc["errors"], doc["warnings"], doc["notes"]) == (0, 0, 1)
    else:
        assert "0 errors, 0 warnings" in proc.stdout.splitlines()[-1]
    gen = run_ttctl("gen", "my.xml", "--lang", "python", "-o", "out", cwd=tmp_path)
    assert gen.returncode == 0 and "validation warning" not in gen.stdout, gen.stdout + gen.stderr
