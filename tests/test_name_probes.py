"""Names that validate must build in every generator (issue 28): tests/dialects/probes/name_probes.xml
gathers the names found to break generated code while validating cleanly (a message and an enum
of one name as in DroneLeaf's dialect, Python's imported names as types, fields shadowing what a
Python message class refers to, enum entries IntEnum cannot have, types whose Java files collide
on case-insensitive file systems). Validation passes with a note for each rename; `ttctl gen`'s
three languages build strictly (Python: import, ruff's defaults and E4/E7/E9/F, mypy --strict;
C++: g++ -std=c++17 -Wall -Wextra -Wpedantic -Werror of the conformance program with the handler
skeleton and of a program using the renamed types; Java: javac --release 11 -Xlint:all -Werror);
and the wire is unchanged: pymavlink's mavgen on the same XML is the oracle (msgid, CRC_EXTRA,
frames round-tripped byte for byte by each language).

The names that cannot be generated are refused by validate with a precise error, and so is gen;
includes deeper than mavgen follows get a warning naming the chain."""

from __future__ import annotations

import importlib.util
import json
import os
import shutil
import subprocess
import sys
from collections.abc import Iterator
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest

from conformance_lib import Conformance, check_message
from conftest import ROOT, run_ttctl
from ttctl.validate import load_and_check

PROBES = ROOT / "tests" / "dialects" / "probes" / "name_probes.xml"
BIN = Path(sys.executable).parent
CXX = ["g++", "-std=c++17", "-Wall", "-Wextra", "-Wpedantic", "-Werror", "-O0"]
LANGS = ("python", "cpp", "java")

needs_builds = pytest.mark.skipif(shutil.which("g++") is None or shutil.which("javac") is None,
                                  reason="needs g++ and a JDK")

# what validate says about each rename: (line, code, start of the message)
NOTES = [
    (8, "TYPE-RENAMED", "enum INT_ENUM is generated as IntEnumEnum in Python, C++ and Java"),
    (13, "TYPE-RENAMED", "enum INT_FLAG is generated as IntFlagEnum"),
    (21, "ENTRY-RENAMED", "PROBE_ENTRIES.mro is generated as ProbeEntries.mro__ in Python"),
    (22, "ENTRY-RENAMED", "PROBE_ENTRIES.imag is generated as ProbeEntries.imag_ in Python"),
    (23, "ENTRY-RENAMED", "PROBE_ENTRIES.bit_length is generated as ProbeEntries.bit_length_"),
    (24, "ENTRY-RENAMED", "PROBE_ENTRIES.to_bytes is generated as ProbeEntries.to_bytes_"),
    (25, "ENTRY-RENAMED", "PROBE_ENTRIES.from_bytes is generated as ProbeEntries.from_bytes_"),
    (26, "ENTRY-RENAMED", "PROBE_ENTRIES._missing_ is generated as ProbeEntries._missing__"),
    (27, "ENTRY-RENAMED", "PROBE_ENTRIES._generate_next_value_ is generated as ProbeEntries._generate_next_value__"),
    (33, "TYPE-RENAMED", "enum LEAF_MODE is generated as LeafModeEnum in Python, C++ and Java, as message LEAF_MODE "
                         "is LeafMode"),
    (38, "TYPE-RENAMED", "enum LEAF_STATUS is generated as LeafStatusEnum"),
    (43, "CASE-COLLISION", "enum FOO_BAR is generated as Java class FooBarEnum, as enum FOOBAR is Foobar"),
    (79, "TYPE-RENAMED", "message CLASS_VAR is generated as ClassVarMessage"),
    (83, "TYPE-RENAMED", "message ANY is generated as AnyMessage"),
    (100, "CASE-COLLISION", "message SIMSTATE is generated as Java class SimstateMessage, as message SIM_STATE is "
                           "SimState"),
]


def test_probes_validate_with_a_note_per_rename() -> None:
    proc = run_ttctl("validate", str(PROBES), "--format", "json")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    diags = json.loads(proc.stdout)["diagnostics"]
    assert [d for d in diags if d["severity"] != "note"] == []
    got = [(d["line"], d["code"], d["message"]) for d in diags]
    assert len(got) == len(NOTES), got
    for (line, code, text), (gline, gcode, gtext) in zip(NOTES, got, strict=True):
        assert (gline, gcode) == (line, code) and gtext.startswith(text), (gline, gcode, gtext)


# --- generated once, built strictly ------------------------------------------------------------

CPP_USE = """// the renamed types, as a user's program names them
#include "name_probes/name_probes.hpp"
int main() {
    name_probes::LeafMode msg;
    msg.mode = static_cast<std::uint8_t>(name_probes::LeafModeEnum::LEAF_MODE_FLY);
    name_probes::AnyMessage any;
    name_probes::ClassVarMessage cv;
    const auto e = name_probes::ProbeEntries::mro;
    const auto f = name_probes::IntFlagEnum::IF_B;
    return (msg.mode == 1 && any.MSG_ID == 42002 && cv.MSG_ID == 42001 && static_cast<int>(e) == 1
            && static_cast<int>(f) == 2 && name_probes::Simstate::MSG_ID == 42006) ? 0 : 1;
}
"""

JAVA_USE = """// the renamed classes, as a tablet app names them
public final class UseProbes {
    public static void main(String[] args) {
        ttctl.name_probes.msg.LeafMode m = new ttctl.name_probes.msg.LeafMode();
        m.mode = (byte) ttctl.name_probes.enums.LeafModeEnum.LEAF_MODE_FLY;
        ttctl.name_probes.msg.SimstateMessage s = new ttctl.name_probes.msg.SimstateMessage();
        ttctl.name_probes.msg.SimState t = new ttctl.name_probes.msg.SimState();
        ttctl.name_probes.msg.ProbeFields p = new ttctl.name_probes.msg.ProbeFields();
        p.Wire = 200;
        p.big = -1L;
        p.flags = ttctl.name_probes.enums.JavaTables.ENTRY_NAMES | ttctl.name_probes.enums.JavaTables.String;
        boolean ok = m.mode == 1 && ttctl.name_probes.enums.FooBarEnum.FOO_BAR_A == 0
            && "ENTRY_NAMES|String".equals(ttctl.name_probes.enums.JavaTables.flags(p.flags))
            && p.toString().contains("big=18446744073709551615")
            && ttctl.name_probes.enums.Foobar.FOOBAR_A == 0 && s.msgId() != t.msgId();
        System.exit(ok ? 0 : 1);
    }
}
"""


def _run(cmd: list[str], cwd: Path | None = None, env: dict[str, str] | None = None) -> tuple[bool, str]:
    proc = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=600,
                          env={**os.environ, **env} if env else None)
    return proc.returncode == 0 and "warning" not in proc.stderr.lower(), (proc.stdout + proc.stderr)[-6000:]


def _python(out: Path) -> tuple[bool, str]:
    py = out / "python"
    env = {"PYTHONPATH": str(py), "PYTHONDONTWRITEBYTECODE": "1"}
    use = ("import name_probes as p\n"
           "assert p.LeafMode.MSG_ID == 42003 and p.LeafModeEnum.LEAF_MODE_FLY == 1\n"
           "assert p.AnyMessage.NAME == 'ANY' and p.ClassVarMessage.NAME == 'CLASS_VAR'\n"
           "assert p.IntEnumEnum.IE_B == 1 and p.IntFlagEnum.IF_B == 2 and p.ZzAfter.ZZ_A == 0\n"
           "e = p.ProbeEntries\n"
           "assert (e.mro_, e.mro__, e.imag_, e.bit_length_, e.to_bytes_, e.from_bytes_, e._missing__,\n"
           "        e._generate_next_value__) == tuple(range(8))\n"
           "m = p.ProbeFields(bytes=7, Any=-1, str='ab', Sequence=[1, 2, 3, 4], dict=(3, -4))\n"
           "assert p.ProbeFields.unpack_payload(m.pack_payload()) == m\n")
    for cmd in ([sys.executable, "-c", use],
                [str(BIN / "ruff"), "check", "--no-cache", "--isolated", "--output-format", "concise", "."],
                [str(BIN / "ruff"), "check", "--no-cache", "--isolated", "--output-format", "concise", "--select",
                 "E4,E7,E9,F", "."],
                [str(BIN / "mypy"), "--strict", "--no-incremental", "--cache-dir", os.devnull, "name_probes",
                 "conformance.py", "handlers/name_probes_onboard.py"]):
        ok, log = _run(cmd, cwd=py, env=env)
        if not ok:
            return False, f"{cmd[0:3]}:\n{log}"
    return True, ""


def _cpp(out: Path) -> tuple[bool, str]:
    cpp = out / "cpp"
    (out / "use.cpp").write_text(CPP_USE)
    ok, log = _run([*CXX, "-I", str(cpp), "-include", str(cpp / "onboard" / "name_probes_plugin.hpp"),
                    str(cpp / "conformance.cpp"), "-o", str(out / "conformance_cpp")])
    if not ok:
        return False, log
    ok, log = _run([*CXX, "-I", str(cpp), str(out / "use.cpp"), "-o", str(out / "use_cpp")])
    return (_run([str(out / "use_cpp")]) if ok else (False, log))


def _java(out: Path) -> tuple[bool, str]:
    (out / "UseProbes.java").write_text(JAVA_USE)
    classes = out / "classes"
    classes.mkdir()
    sources = sorted(str(p) for p in (out / "java").rglob("*.java"))
    ok, log = _run(["javac", "--release", "11", "-Xlint:all", "-Werror", "-encoding", "UTF-8", "-d", str(classes),
                    *sources, str(out / "UseProbes.java")])
    return (_run(["java", "-cp", str(classes), "UseProbes"]) if ok else (False, log))


def _mavgen(out: Path) -> ModuleType:
    target = out / "pm_name_probes.py"
    proc = subprocess.run([sys.executable, "-m", "pymavlink.tools.mavgen", "--lang", "Python3", "--wire-protocol",
                           "2.0", "-o", str(target), str(PROBES)], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    spec = importlib.util.spec_from_file_location("pm_name_probes", target)
    assert spec and spec.loader
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.fixture(scope="module")
def built(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    out = tmp_path_factory.mktemp("name_probes")
    proc = run_ttctl("gen", str(PROBES), "-o", str(out), timeout=600)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    with ThreadPoolExecutor(max_workers=2) as pool:
        jobs = {"java": pool.submit(_java, out), "cpp": pool.submit(_cpp, out), "python": pool.submit(_python, out),
                "pm": pool.submit(_mavgen, out)}
        results = {k: v.result() for k, v in jobs.items()}
    return {"out": out, **results}


@needs_builds
@pytest.mark.parametrize("lang", LANGS)
def test_probes_build_strictly(built: dict[str, Any], lang: str) -> None:
    ok, log = built[lang]
    assert ok, f"{lang}:\n{log}"


@needs_builds
def test_renamed_java_files_do_not_collide_case_insensitively(built: dict[str, Any]) -> None:
    for folder in ("msg", "enums"):
        names = [p.name for p in (built["out"] / "java" / "ttctl" / "name_probes" / folder).iterdir()]
        assert len({n.casefold() for n in names}) == len(names), names


@pytest.fixture
def world(built: dict[str, Any], request: pytest.FixtureRequest) -> Iterator[dict[str, Any]]:
    lang = request.param
    ok, log = built[lang]
    if not ok:
        pytest.fail(f"{lang} did not build:\n{log}")
    out: Path = built["out"]
    if lang == "python":
        cmd, env = [sys.executable, str(out / "python" / "conformance.py")], {"PYTHONPATH": str(out / "python")}
    elif lang == "cpp":
        cmd, env = [str(out / "conformance_cpp")], {}
    else:
        cmd, env = ["java", "-XX:TieredStopAtLevel=1", "-cp", str(out / "classes"), "Conformance"], {}
    proc = Conformance(cmd, env={**env, "PYTHONDONTWRITEBYTECODE": "1"})
    model, rep, _ = load_and_check(str(PROBES), [])
    assert rep.errors == 0
    yield {"proc": proc, "pm": built["pm"], "model": model}
    assert proc.close() == 0


@needs_builds
@pytest.mark.parametrize("world", LANGS, indirect=True)
def test_the_wire_is_pymavlinks(world: dict[str, Any]) -> None:
    pm = world["pm"]
    for m in world["model"].messages:
        cls = pm.mavlink_map[m.id]
        assert (cls.msgname, cls.crc_extra) == (m.name, m.crc_extra)
        check_message(world, m, 3)


# --- what cannot be generated: refused, precisely ----------------------------------------------

def _dialect(tmp: Path, name: str, body: str) -> Path:
    p = tmp / f"{name}.xml"
    p.write_text(f'<?xml version="1.0"?>\n<mavlink>\n  <version>3</version>\n  <messages>\n{body}  </messages>\n'
                 "</mavlink>\n")
    return p


@pytest.mark.parametrize(("field", "why"), [
    ("TYPES", "PROBE.TYPES: 'TYPES' is a member every generated message class defines"),
    ("java", "PROBE.java: the generated Java message class calls java.util.Arrays, which a field named java hides; "
             "rename the field"),
    ("Probe", "PROBE.Probe: a field cannot be spelled like its message's generated type Probe (C++ refuses a member "
              "named like its class); rename the field"),
])
def test_a_field_no_generator_can_emit_is_refused_with_its_line(tmp_path: Path, field: str, why: str) -> None:
    xml = _dialect(tmp_path, "refused", '    <message id="42010" name="PROBE">\n      <description>x</description>\n'
                                        f'      <field type="uint8_t" name="{field}">x</field>\n    </message>\n')
    proc = run_ttctl("validate", str(xml), "--format", "json")
    assert proc.returncode == 1
    errors = [d for d in json.loads(proc.stdout)["diagnostics"] if d["severity"] == "error"]
    assert [(d["line"], d["code"], d["message"]) for d in errors] == [(7, "RESERVED-NAME", why)]
    gen = run_ttctl("gen", str(xml), "-o", str(tmp_path / "out"))
    assert gen.returncode == 1 and "nothing generated" in gen.stderr and not (tmp_path / "out").exists()


@pytest.mark.parametrize("entry", ["java", "Long"])
def test_an_entry_java_cannot_have_is_refused_with_its_line(tmp_path: Path, entry: str) -> None:
    xml = tmp_path / "refused.xml"
    xml.write_text('<?xml version="1.0"?>\n<mavlink>\n  <enums>\n    <enum name="FLAGS" bitmask="true">\n'
                   f'      <entry value="1" name="{entry}"/>\n    </enum>\n  </enums>\n  <messages/>\n</mavlink>\n')
    proc = run_ttctl("validate", str(xml), "--format", "json")
    assert proc.returncode == 1
    errors = [(d["line"], d["code"], d["message"]) for d in json.loads(proc.stdout)["diagnostics"]
              if d["severity"] == "error"]
    calls = "java.util.Arrays" if entry == "java" else "Long.toHexString"
    assert errors == [(5, "RESERVED-NAME", f"FLAGS.{entry}: the generated Java enum class calls {calls}, which an "
                                           f"entry named {entry} hides; rename the entry")]


def test_includes_deeper_than_mavgen_follows_are_named(tmp_path: Path) -> None:
    for i in range(8):
        inc = f"<include>d{i + 1}.xml</include>" if i < 7 else ""
        (tmp_path / f"d{i}.xml").write_text(
            f'<?xml version="1.0"?>\n<mavlink>\n  {inc}\n  <version>3</version>\n  <messages>\n'
            f'    <message id="{43000 + i}" name="DEEP_{i}">\n      <description>level {i}</description>\n'
            '      <field type="uint8_t" name="x">x</field>\n    </message>\n  </messages>\n</mavlink>\n')
    proc = run_ttctl("validate", "d0.xml", "--format", "json", cwd=tmp_path)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    warnings = [d for d in json.loads(proc.stdout)["diagnostics"] if d["severity"] == "warning"]
    chain = " -> ".join(f"d{i}.xml" for i in range(7))
    assert [(d["path"], d["line"], d["code"]) for d in warnings] == [("d5.xml", 3, "INCLUDE-DEPTH-MAVGEN")]
    assert f"includes nested 6 deep ({chain})" in warnings[0]["message"]
    assert "ERROR in includes tree, no base found!" in warnings[0]["message"]
    # pymavlink's mavgen refuses the same chain, as the warning says, and builds one level less
    mavgen = [sys.executable, "-m", "pymavlink.tools.mavgen", "--lang", "Python3", "--wire-protocol", "2.0", "-o"]
    pm = subprocess.run([*mavgen, str(tmp_path / "pm.py"), "d0.xml"], cwd=tmp_path, capture_output=True, text=True,
                        timeout=120)
    assert "ERROR in includes tree, no base found!" in pm.stdout + pm.stderr
    # mavgen reads includes breadth first: d6 included by the root too is 1 deep, and mavgen builds it
    d0 = tmp_path / "d0.xml"
    d0.write_text(d0.read_text().replace("<include>d1.xml</include>",
                                         "<include>d1.xml</include><include>d6.xml</include>"))
    for _ in range(2):
        proc = run_ttctl("validate", "d0.xml", "--format", "json", cwd=tmp_path)
        assert [d for d in json.loads(proc.stdout)["diagnostics"] if d["severity"] == "warning"] == []
        pm = subprocess.run([*mavgen, str(tmp_path / "pm.py"), "d0.xml"], cwd=tmp_path, capture_output=True,
                            text=True, timeout=120)
        assert pm.returncode == 0, pm.stdout + pm.stderr
        # and with 5 levels only
        d0.write_text(d0.read_text().replace("<include>d6.xml</include>", ""))
        d5 = tmp_path / "d5.xml"
        d5.write_text(d5.read_text().replace("<include>d6.xml</include>", ""))
