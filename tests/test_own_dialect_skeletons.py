"""The README's Java and C++ examples against the skeletons of a user's dialect
(dialects/examples/robolab.xml, which includes ttapi.xml): the Java tablet's take-off
(`SendTtActionCommand`) and set-point (`SendSetpoint`) compile with javac -Xlint:all -Werror
against the generated robolab tree, and the C++ skeleton's set-point handler, filled in with the
README's methods, is registered: the node built from it flies the emulated tablet's goto and
refuses one more than 1000 m from home in the README's words."""

from __future__ import annotations

import json
import re
import shutil
import signal
import subprocess
from pathlib import Path

import pytest

from conftest import ROOT, run_ttctl
from e2e_lib import LOCAL, free_port
from test_java_session import readme_java_blocks
from test_readme_cpp import blocks, fill_skeleton

ROBOLAB = ROOT / "dialects" / "examples" / "robolab.xml"


@pytest.fixture(scope="module")
def gen(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("robolab_skeletons")
    proc = run_ttctl("gen", str(ROBOLAB), "--lang", "java,cpp", "-o", str(out), timeout=300)
    assert proc.returncode == 0, proc.stderr
    return out


@pytest.mark.skipif(shutil.which("javac") is None, reason="needs a JDK (javac)")
def test_the_readmes_java_commands_compile_against_a_user_dialects_skeletons(gen: Path, tmp_path: Path) -> None:
    used = [b for b in readme_java_blocks("### Java on the tablet", "### C++ onboard")
            if "new SendTtActionCommand(" in b or "new SendSetpoint(" in b]
    assert len(used) >= 2, used
    robolab = lambda text: text.replace("ttctl.ttapi", "ttctl.robolab").replace("Ttapi", "Robolab")  # noqa: E731
    sources = sorted(str(p) for p in (gen / "java" / "ttctl" / "robolab").rglob("*.java"))
    for p in sorted((ROOT / "tests" / "java" / "readme").glob("*.java")):
        (tmp_path / p.name).write_text(robolab(p.read_text()))
        sources.append(str(tmp_path / p.name))
    imports = ("import java.util.concurrent.TimeUnit;\n\nimport ttctl.robolab.commands.*;\n"
               "import ttctl.robolab.enums.*;\nimport ttctl.robolab.msg.*;\nimport ttctl.robolab.runtime.*;\n")
    for i, block in enumerate(used):
        body = "\n".join("        " + line for line in block.splitlines())
        src = tmp_path / f"Readme{i}.java"
        src.write_text(f"{imports}\npublic final class Readme{i} extends ReadmeContext {{\n    @Override\n"
                       f"    public void run() throws Exception {{\n{body}\n    }}\n}}\n")
        sources.append(str(src))
    (tmp_path / "classes").mkdir()
    javac = subprocess.run(["javac", "--release", "11", "-Xlint:all", "-Werror", "-encoding", "UTF-8", "-d",
                            str(tmp_path / "classes"), *sources], capture_output=True, text=True, timeout=300)
    assert javac.returncode == 0, javac.stderr[-4000:]


@pytest.mark.skipif(shutil.which("g++") is None, reason="needs g++")
def test_the_readmes_setpoint_handler_fills_a_user_dialects_cpp_skeleton(gen: Path, tmp_path: Path) -> None:
    code = blocks()
    skeleton = gen / "cpp" / "onboard" / "robolab_plugin.hpp"
    text = skeleton.read_text()
    assert "void on_dji_pose_stamped(" in text and "node.on<DjiPoseStamped>" in text
    skeleton.write_text(fill_skeleton(text, code["onboard/ttapi_plugin.hpp"]))
    port = free_port()
    laptop = (code["laptop.cpp"].replace("TtapiPlugin", "RobolabPlugin").replace("ttapi", "robolab")
              .replace("127.0.0.1:14560", f"{LOCAL}:{port}"))
    (tmp_path / "laptop.cpp").write_text(laptop)
    exe = tmp_path / "laptop"
    gxx = subprocess.run(["g++", "-std=c++17", "-Wall", "-Wextra", "-Wpedantic", "-Werror", "-O0", "-I",
                          str(gen / "cpp"), str(tmp_path / "laptop.cpp"), "-o", str(exe), "-lz"],
                         capture_output=True, text=True, timeout=600)
    assert gxx.returncode == 0, gxx.stderr[-5000:]
    with open(tmp_path / "node.err", "w") as err:
        prog = subprocess.Popen([str(exe)], cwd=tmp_path, stdout=subprocess.DEVNULL, stderr=err)
    try:
        script = tmp_path / "script.yaml"
        script.write_text("- takeoff: 3\n- goto: [3, 4, 5]\n- goto: [2000, 0, 5]\n")
        proc = run_ttctl("emulate", "tablet", "--dialect", str(ROBOLAB), "--to", f"udpout:{LOCAL}:{port}", "--json",
                         "--script", str(script), cwd=tmp_path, timeout=120)
        steps = [json.loads(line) for line in proc.stdout.splitlines() if line.startswith("{")]
        oks = [s["ok"] for s in steps if s.get("event") == "step"]
        assert oks == [True, True, False], proc.stdout + proc.stderr
        assert re.search(r"more than 1000 m from home", proc.stdout + proc.stderr), proc.stdout + proc.stderr
        assert prog.poll() is None
    finally:
        prog.send_signal(signal.SIGINT)
        prog.wait(20)
