"""The runtimes' API reference is built from their code: docs/reference/cpp.md is what
tools/gen_cpp_reference.py writes from the generated C++ headers, and the Javadoc command that
docs/reference/api.md gives builds the Java runtime's reference."""

from __future__ import annotations

import importlib.util
import re
import shlex
import shutil
import subprocess
from pathlib import Path
from types import ModuleType

import pytest

from conftest import ROOT

SCRIPT = ROOT / "tools" / "gen_cpp_reference.py"
PAGE = ROOT / "docs" / "reference" / "cpp.md"
API = ROOT / "docs" / "reference" / "api.md"


def _script() -> ModuleType:
    spec = importlib.util.spec_from_file_location("gen_cpp_reference", SCRIPT)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_cpp_reference_is_what_the_headers_say() -> None:
    assert PAGE.read_text() == _script().render(), \
        "docs/reference/cpp.md is stale: run python tools/gen_cpp_reference.py"


def test_the_cpp_reference_covers_every_header_and_the_main_classes() -> None:
    text = PAGE.read_text()
    headers = sorted(p.name for p in (ROOT / "generated" / "cpp" / "ttapi").glob("*.hpp"))
    assert re.findall(r"^## (\S+\.hpp)$", text, re.M) == headers
    for name in ("Node", "FileSender", "NodeConfig", "BasicScheduler", "Parser"):
        assert re.search(rf"^#### (class|struct) `{name}`$", text, re.M), name
    assert text.count("\n| `") > 150  # documented members, not only class names


def test_check_fails_on_a_stale_page(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    script = _script()
    stale = tmp_path / "cpp.md"
    stale.write_text(PAGE.read_text().replace("#### class `FileSender`", "#### class `Sender`"))
    monkeypatch.setattr(script, "PAGE", stale)
    monkeypatch.setattr(script, "ROOT", tmp_path)
    assert script.main(["--check"]) == 1
    assert script.main([]) == 0 and script.main(["--check"]) == 0
    assert stale.read_text() == PAGE.read_text()


def test_the_javadoc_command_of_the_page_builds_the_java_reference(tmp_path: Path) -> None:
    if shutil.which("javadoc") is None:
        pytest.skip("javadoc (the JDK) is not installed")
    [line] = [x for x in re.findall(r"```sh\n(.*?)```", API.read_text(), re.S)[0].splitlines() if x.strip()]
    argv = shlex.split(line)
    assert argv[0] == "javadoc"
    out = tmp_path / "javadoc"
    argv[argv.index("-d") + 1] = str(out)  # the page's build/javadoc, here in a temporary folder
    proc = subprocess.run(argv, cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    assert (out / "index.html").is_file()
    for cls in ("runtime/Session", "runtime/DjiLink", "runtime/UdpLink", "runtime/Signing", "runtime/GcsBridge"):
        assert (out / "ttctl" / "ttapi" / f"{cls}.html").is_file(), cls
    for pkg in ("transfer", "commands", "msg", "enums"):
        assert (out / "ttctl" / "ttapi" / pkg / "package-summary.html").is_file(), pkg
