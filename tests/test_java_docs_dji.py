"""docs/dji/tablet-java.md cannot drift from the API: every ```java block compiles with javac
--release 11 -Xlint:all -Werror against the generated runtime, each wiring pasted into a method
(as tests/test_java_session.py does for the README), with stand-ins for the DJI classes it
names: Mobile SDK v4's (tests/java/readme, the default package) and Mobile SDK v5's
(tests/java/msdk5, DJI's packages and signatures). A block of imports only is the imports of the
blocks that use Mobile SDK v5, exactly as the page gives them.
"""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest

from conformance_lib import build_java
from conftest import ROOT

pytestmark = pytest.mark.skipif(shutil.which("javac") is None or shutil.which("java") is None,
                                reason="needs a JDK (javac, java)")

DOC = ROOT / "docs" / "dji" / "tablet-java.md"
RUNTIME_IMPORTS = """import java.io.File;
import java.util.concurrent.TimeUnit;

import ttctl.ttapi.Ttapi;
import ttctl.ttapi.commands.*;
import ttctl.ttapi.enums.*;
import ttctl.ttapi.msg.*;
import ttctl.ttapi.runtime.*;
import ttctl.ttapi.transfer.*;
"""
V5_NAMES = ("PayloadCenter", "IPayloadManager", "IDJIError", "PayloadIndexType", "PipelineManager")


@pytest.fixture(scope="module")
def classes(tmp_path_factory: pytest.TempPathFactory) -> Path:
    stand_ins = sorted((ROOT / "tests/java/readme").glob("*.java"))
    stand_ins += sorted((ROOT / "tests/java/msdk5").rglob("*.java"))
    cls, _ = build_java(tmp_path_factory.mktemp("java_docs_dji"), stand_ins)
    return cls


def test_every_java_block_of_the_tablet_page_compiles(classes: Path, tmp_path: Path) -> None:
    blocks = re.findall(r"```java\n(.+?)```", DOC.read_text(), re.S)
    imports = [b for b in blocks if all(ln.startswith("import ") for ln in b.splitlines() if ln.strip())]
    wirings = [b for b in blocks if b not in imports]
    assert len(imports) == 1 and len(wirings) >= 2, blocks
    assert any("new DjiLink(" in b and "sendDataToOnboardSDKDevice" in b for b in wirings)
    assert any("new PayloadLink(" in b and "sendDataToPayload" in b and "addPayloadDataListener" in b for b in wirings)
    assert any("new PipelineLink(" in b and "connectPipeline" in b and "options.pipeline" in b for b in wirings)
    sources = []
    for i, block in enumerate(wirings):
        v5 = any(n in block for n in V5_NAMES)
        head = RUNTIME_IMPORTS + (imports[0] if v5 else "")
        body = "\n".join("        " + line for line in block.splitlines())
        src = tmp_path / f"Doc{i}.java"
        src.write_text(f"{head}\npublic final class Doc{i} extends ReadmeContext {{\n    @Override\n"
                       f"    public void run() throws Exception {{\n{body}\n    }}\n}}\n")
        sources.append(src)
    out = tmp_path / "classes"
    out.mkdir()
    javac = subprocess.run(["javac", "--release", "11", "-Xlint:all", "-Werror", "-encoding", "UTF-8", "-cp",
                            str(classes), "-d", str(out), *map(str, sources)], capture_output=True, text=True,
                           timeout=300)
    assert javac.returncode == 0, javac.stderr[-4000:]
