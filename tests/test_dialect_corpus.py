"""Real third-party dialects (tests/dialects/real/, sources and licences in its README.md), each
through everything ttctl does with a dialect: `ttctl validate` (no errors; warnings allowed),
`ttctl gen` of all three languages, strict builds (Python: ruff's defaults and the classic
E4/E7/E9/F set, mypy --strict; C++: g++ -std=c++17 -Wall -Wextra -Wpedantic -Werror of the
conformance program with the handler skeleton; Java: javac --release 11 -Xlint:all -Werror of
the whole tree, skeletons included), and byte conformance against pymavlink's own mavgen output
for the same XML: all of a dialect's own messages and a few of what it includes (common.xml
itself is tested elsewhere) round-trip pymavlink -> each language -> the same bytes -> pymavlink.

Budget: about 3 minutes on 2 cores. Everything is generated and built once, 2 jobs at a time
(Java in one JVM for all dialects, its JIT warmed once); the tests then read the results, each
named after its dialect."""

from __future__ import annotations

import importlib.util
import json
import os
import shutil
import subprocess
import sys
from collections.abc import Callable, Iterator
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest

from conformance_lib import Conformance, check_message
from conftest import ROOT, run_ttctl
from ttctl.dialect.model import Dialect, Message
from ttctl.validate import load_and_check

REAL = ROOT / "tests" / "dialects" / "real"
BIN = Path(sys.executable).parent
CXX = ["g++", "-std=c++17", "-Wall", "-Wextra", "-Wpedantic", "-Werror", "-O0"]
EXAMPLES = 3  # hypothesis examples per message and language
INCLUDED_SAMPLES = 3  # messages sampled from what a dialect includes

pytestmark = pytest.mark.skipif(shutil.which("g++") is None or shutil.which("java") is None,
                                reason="needs g++ and a JDK")


@dataclass(frozen=True)
class Case:
    """One dialect of the corpus: its root file, and for a dialect that legitimately fails
    validation (a real error upstream) the errors expected: (line, col, code, message)."""

    path: str  # relative to tests/dialects/real
    errors: tuple[tuple[int, int, str, str], ...] = ()
    warnings: tuple[tuple[int, int, str, str], ...] = ()  # warnings that must be among those reported

    @property
    def id(self) -> str:
        return Path(self.path).stem

    @property
    def xml(self) -> Path:
        return REAL / self.path


UP = "mavlink-2025-12/"
CASES = [
    Case(UP + "development.xml", warnings=(
        # upstream's defect: a MAV_CMD entry pasted into the MAV_BATTERY_STATUS_FLAGS bitmask
        (84, 27, "BITMASK-VALUE", "MAV_BATTERY_STATUS_FLAGS is a bitmask but MAV_CMD_NAV_FENCE_HOME_CIRCLE_INCLUSION "
                                  "= 5005 is not a power of two"),)),
    Case(UP + "ardupilotmega.xml"),
    Case(UP + "storm32.xml"),
    Case(UP + "csAirLink.xml"),
    Case(UP + "cubepilot.xml"),
    Case(UP + "marsh.xml"),
    Case(UP + "stemstudios.xml"),
    Case(UP + "AVSSUAS.xml"),
    Case(UP + "loweheiser.xml"),
    Case(UP + "ualberta.xml"),
    Case(UP + "matrixpilot.xml"),
    Case(UP + "paparazzi.xml"),
    Case(UP + "ASLUAV.xml"),
    Case("mavlink-2025-07/standard.xml"),  # the enum BOOL
    Case("asv-mavlink/asv_radio.xml"),
    Case("asv-mavlink/asv_chart.xml"),
    # includes only minimal.xml but uses common.xml's GPS_FIX_TYPE (pymavlink's mavgen stops on
    # it too)
    Case("asv-mavlink/asv_rsga.xml", errors=(
        (486, 51, "UNDEFINED-ENUM", "ASV_RSGA_RTT_GNSS.fix_type refers to enum GPS_FIX_TYPE, which is not defined "
                                    "here or in any include"),)),
]
VALID = [c for c in CASES if not c.errors]
LANGS = ("python", "cpp", "java")


# --- validation ---------------------------------------------------------------------------

@pytest.mark.parametrize("case", CASES, ids=lambda c: c.id)
def test_validates(case: Case) -> None:
    proc = run_ttctl("validate", str(case.xml), "--format", "json", cwd=case.xml.parent)
    doc = json.loads(proc.stdout)
    diags = [(d["line"], d["col"], d["code"], d["message"]) for d in doc["diagnostics"]
             if Path(d["path"]).name == case.xml.name]
    errors = [(d["line"], d["col"], d["code"], d["message"]) for d in doc["diagnostics"] if d["severity"] == "error"]
    assert errors == list(case.errors), errors
    assert proc.returncode == (1 if case.errors else 0)
    for w in case.warnings:
        assert w in diags, diags


# --- generating and building, once -----------------------------------------------------------

@dataclass
class Built:
    case: Case
    out: Path
    model: Dialect
    pkg: str = ""
    results: dict[str, tuple[bool, str]] = field(default_factory=dict)  # language -> (ok, what went wrong)
    pymavlink: ModuleType | None = None


def _run(cmd: list[str], cwd: Path | None = None, timeout: float = 900) -> tuple[bool, str]:
    proc = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=timeout)
    return proc.returncode == 0 and "warning" not in proc.stderr.lower(), (proc.stdout + proc.stderr)[-6000:]


def _gen(case: Case, base: Path) -> Built:
    out = base / case.id
    proc = run_ttctl("gen", str(case.xml), "-o", str(out), timeout=600)
    assert proc.returncode == 0, f"{case.id}: ttctl gen failed:\n{proc.stdout}{proc.stderr}"
    model, rep, _ = load_and_check(str(case.xml), [])
    assert rep.errors == 0
    pkg = next(p.name for p in (out / "python").iterdir() if p.is_dir() and p.name != "handlers")
    return Built(case, out, model, pkg)


def _cpp(b: Built) -> None:
    cpp = b.out / "cpp"
    plugin = next((cpp / "onboard").glob("*_plugin.hpp"))
    b.results["cpp"] = _run([*CXX, "-I", str(cpp), "-include", str(plugin), str(cpp / "conformance.cpp"), "-o",
                             str(b.out / "conformance_cpp")])


def _java(built: list[Built]) -> None:
    """Every dialect's Java tree in one JVM (tests/java/corpus/BatchJavac.java)."""
    args = [str(x) for b in built for x in (b.out / "java", b.out / "classes")]
    proc = subprocess.run(["java", "-XX:+UseParallelGC", "-XX:TieredStopAtLevel=1",
                           str(ROOT / "tests" / "java" / "corpus" / "BatchJavac.java"), "1", *args],
                          capture_output=True, text=True, timeout=900)
    reports = proc.stdout.split("\nEND\n")
    for b in built:
        report = next((r.strip() for r in reports if r.strip().split("\n")[0].endswith(str(b.out / "java"))), None)
        b.results["java"] = (report is not None and report.startswith("OK "), report or proc.stderr[-6000:])


def _python(built: list[Built], base: Path) -> None:
    """All the Python packages side by side (their names differ), checked by one ruff and one
    mypy run; a problem is charged to the dialect whose file it is in."""
    merged = base / "python"
    (merged / "handlers").mkdir(parents=True)
    owner: dict[str, Built] = {}
    for b in built:
        shutil.copytree(b.out / "python" / b.pkg, merged / b.pkg)
        shutil.copy(b.out / "python" / "handlers" / f"{b.pkg}_onboard.py", merged / "handlers")
        shutil.copy(b.out / "python" / "conformance.py", merged / f"conformance_{b.pkg}.py")
        for name in (f"{b.pkg}/", f"handlers/{b.pkg}_onboard.py", f"conformance_{b.pkg}.py"):
            owner[name] = b
    checks = [[str(BIN / "ruff"), "check", "--no-cache", "--isolated", "--output-format", "concise", "."],
              [str(BIN / "ruff"), "check", "--no-cache", "--isolated", "--output-format", "concise", "--select",
               "E4,E7,E9,F", "."],
              [str(BIN / "mypy"), "--strict", "--no-incremental", "--no-error-summary", "--hide-error-context",
               *(b.pkg for b in built), *(f"conformance_{b.pkg}.py" for b in built), "handlers"]]
    problems: dict[str, list[str]] = {b.case.id: [] for b in built}
    for cmd in checks:
        proc = subprocess.run(cmd, cwd=merged, capture_output=True, text=True, timeout=900)
        for line in (proc.stdout + proc.stderr).splitlines():
            hit = next((o for name, o in owner.items() if line.startswith(name)), None)
            if hit is not None:
                problems[hit.case.id].append(line)
            elif proc.returncode != 0 and line.strip() and not line.startswith(("Found ", "[*]", "All checks")):
                for p in problems.values():
                    p.append(line)
    for b in built:
        b.results["python"] = (not problems[b.case.id], "\n".join(problems[b.case.id])[-6000:])


def _mavgen(b: Built) -> None:
    """pymavlink's own Python for the same XML: the oracle."""
    out = b.out / f"pm_{b.pkg}.py"
    ok, log = _run([sys.executable, "-m", "pymavlink.tools.mavgen", "--lang", "Python3", "--wire-protocol", "2.0",
                    "--no-validate", "-o", str(out), str(b.case.xml)])
    assert ok, f"{b.case.id}: mavgen failed: {log}"
    spec = importlib.util.spec_from_file_location(f"pm_{b.pkg}", out)
    assert spec and spec.loader
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    b.pymavlink = mod


@pytest.fixture(scope="module")
def corpus(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Built]:
    base = tmp_path_factory.mktemp("corpus")
    with ThreadPoolExecutor(max_workers=2) as pool:
        built = list(pool.map(lambda c: _gen(c, base), VALID))
        # the longest first: the Java batch, then the C++ builds, the Python checks and mavgen
        jobs: list[Callable[[], None]] = [lambda: _java(built), *(lambda b=b: _cpp(b) for b in built),
                                          lambda: _python(built, base), *(lambda b=b: _mavgen(b) for b in built)]
        for job in [pool.submit(j) for j in jobs]:
            job.result()
    return {b.case.id: b for b in built}


BUILD_IDS = [f"{c.id}-{lang}" for c in VALID for lang in LANGS]


@pytest.mark.parametrize(("case", "lang"), [(c, lang) for c in VALID for lang in LANGS], ids=BUILD_IDS)
def test_builds_strictly(corpus: dict[str, Built], case: Case, lang: str) -> None:
    ok, log = corpus[case.id].results[lang]
    assert ok, f"{case.id} ({lang}):\n{log}"


def test_a_dialect_that_fails_validation_is_not_generated(tmp_path: Path) -> None:
    for case in CASES:
        if case.errors:
            proc = run_ttctl("gen", str(case.xml), "-o", str(tmp_path / case.id))
            assert proc.returncode == 1 and "nothing generated" in proc.stderr, proc.stderr
            assert not (tmp_path / case.id).exists()


# --- byte conformance against pymavlink -------------------------------------------------------

def samples(d: Dialect) -> list[Message]:
    """All the dialect's own messages and a few of what it includes, spread over the ids
    (deterministic)."""
    own = sorted((m for m in d.root.messages if m.complete), key=lambda m: m.id)
    ids = {m.id for m in own}
    rest = sorted((m for m in d.messages if m.complete and m.id not in ids), key=lambda m: m.id)
    step = max(1, len(rest) // INCLUDED_SAMPLES)
    return own + rest[::step][:INCLUDED_SAMPLES]


def command(b: Built, lang: str) -> tuple[list[str], dict[str, str]]:
    if lang == "python":
        return [sys.executable, str(b.out / "python" / "conformance.py")], {"PYTHONPATH": str(b.out / "python")}
    if lang == "cpp":
        return [str(b.out / "conformance_cpp")], {}
    return ["java", "-XX:TieredStopAtLevel=1", "-cp", str(b.out / "classes"), "Conformance"], {}


@pytest.fixture
def world(corpus: dict[str, Built], request: pytest.FixtureRequest) -> Iterator[dict[str, Any]]:
    case, lang = request.param
    b = corpus[case.id]
    ok, log = b.results[lang]
    if not ok:
        pytest.fail(f"{case.id} ({lang}) did not build:\n{log}")
    cmd, env = command(b, lang)
    proc = Conformance(cmd, env={**env, "PYTHONDONTWRITEBYTECODE": os.environ.get("PYTHONDONTWRITEBYTECODE", "1")})
    yield {"proc": proc, "pm": b.pymavlink, "model": b.model}
    assert proc.close() == 0


@pytest.mark.parametrize("world", [(c, lang) for c in VALID for lang in LANGS], ids=BUILD_IDS, indirect=True)
def test_sample_messages_round_trip_byte_for_byte(world: dict[str, Any]) -> None:
    sample = samples(world["model"])
    assert sample
    for m in sample:
        check_message(world, m, EXAMPLES)
