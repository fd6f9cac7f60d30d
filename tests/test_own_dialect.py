"""The user's own dialect end to end, as real processes on loopback: a dialect that includes
ttapi.xml and adds two messages (dialects/examples/robolab.xml), its generated skeleton and a
filled-in handler loaded into `ttctl emulate onboard --dialect`, `ttctl emulate tablet --dialect`
sending the user's message through `ttctl link relay --profile m100` at 10 % loss and waiting for
the answer, files between ends of that dialect, a Java tablet built from the generated Java, and
every refusal: one line, exit 2, nothing started, nothing written."""

from __future__ import annotations

import re
import shutil
import subprocess
import time
from pathlib import Path
from typing import Any

import pytest

from conftest import ROOT, assert_no_traceback, manual, run_ttctl
from e2e_lib import LOCAL, Proc, free_port, relay

OWN = ROOT / "dialects" / "examples"


@pytest.fixture(scope="session")
def bindings_cache(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("ttctl-cache")


@pytest.fixture
def own(tmp_path: Path, bindings_cache: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """tmp_path with the robolab dialect and the motors plugin in it; the processes share one
    bindings cache (TTCTL_CACHE_DIR), as a user's runs do."""
    monkeypatch.setenv("TTCTL_CACHE_DIR", str(bindings_cache))
    monkeypatch.delenv("TTCTL_DIALECT", raising=False)
    shutil.copy(OWN / "robolab.xml", tmp_path)
    shutil.copy(OWN / "motors.py", tmp_path)
    return tmp_path


def onboard(start: Any, port: int, *extra: str, name: str = "onboard") -> Proc:
    p = start(name, "emulate", "onboard", "--listen", f"udpin:{LOCAL}:{port}", "--no-gcs", *extra)
    p.wait_for(f"onboard 1: tablet link udpin:{LOCAL}:{port}", timeout=30)
    return p


def tablet(folder: Path, to: int, script: str, *extra: str, timeout: float = 120) -> subprocess.CompletedProcess[str]:
    (folder / "script.yaml").write_text(script)
    proc = run_ttctl("emulate", "tablet", "--to", f"udpout:{LOCAL}:{to}", "--script", str(folder / "script.yaml"),
                     *extra, timeout=timeout, cwd=folder)
    assert_no_traceback(proc)
    return proc


def test_the_generated_skeleton_loads_unchanged_and_its_handler_fires(own: Path, start: Any) -> None:
    gen = run_ttctl("gen", "robolab.xml", "--lang", "python", "-o", "gen", cwd=own)
    assert gen.returncode == 0, gen.stderr
    skeleton = own / "gen" / "python" / "handlers" / "robolab_onboard.py"
    assert "--dialect path/to/robolab.xml --plugin python/handlers/robolab_onboard.py" in skeleton.read_text()
    port = free_port()
    node = onboard(start, port, "--dialect", "robolab.xml", "--plugin", str(skeleton))
    assert "dialect robolab; plugins RobolabOnboard" in node.stderr
    t = tablet(own, port, "- msg: KR_MOTOR_CONTROL seq=5 dir=FORWARD speed=10\n- wait: 1\n", "--dialect", "robolab.xml")
    assert t.returncode == 0, t.stderr
    assert "step 1 msg KR_MOTOR_CONTROL seq=5 dir=FORWARD speed=10: sent KR_MOTOR_CONTROL target_system=1 seq=5 " \
           "dir=KR_VEHICLE_DIR_FORWARD speed=10" in t.stdout
    node.wait_for("KR_MOTOR_CONTROL from 255/190 not handled yet: KrMotorControl(target_system=1, seq=5, dir=1, "
                  "speed=10)")


@pytest.mark.parametrize("loss_model", ["random", "burst"])
def test_a_user_message_crosses_a_lossy_m100_relay_and_its_answer_comes_back(own: Path, start: Any,
                                                                               loss_model: str) -> None:
    port, front = free_port(), free_port()
    node = onboard(start, port, "--dialect", "robolab.xml", "--plugin", "motors.py", "--profile", "m100")
    relay(start, front, port, "--profile", "m100", "--loss", "0.1", "--loss-model", loss_model, "--seed", "3",
          "--dialect", "robolab.xml")
    steps = "".join(f"- msg: {{send: KR_MOTOR_CONTROL seq={k} dir={d} speed={10 * k}, until: KR_MOTOR_STATUS.seq == "
                    f"{k} and KR_MOTOR_STATUS.speed == {10 * k}, every: 1, timeout: 40}}\n"
                    for k, d in ((1, "FORWARD"), (2, "BACKWARD"), (3, "STOP")))
    steps += "- wait: {until: KR_MOTOR_STATUS.note == ok and KR_MOTOR_STATUS.dir == STOP, timeout: 5}\n"
    t = tablet(own, front, steps, "--dialect", "robolab.xml", "--profile", "m100", "--json")
    assert t.returncode == 0, t.stdout + t.stderr
    for k, d in ((1, "FORWARD"), (2, "BACKWARD"), (3, "STOP")):
        assert f"seq {k}: KR_VEHICLE_DIR_{d} at {10 * k} %" in node.stderr
    assert "msgid" not in node.stderr  # both ends knew every frame


def test_files_move_between_ends_of_the_users_dialect(own: Path, start: Any) -> None:
    port = free_port()
    data = bytes(range(256)) * 40
    (own / "mission.bin").write_bytes(data)
    node = onboard(start, port, "--dialect", "robolab.xml", "--inbox", str(own / "inbox"))
    proc = run_ttctl("send-file", "mission.bin", "--to", f"udpout:{LOCAL}:{port}", "--dialect", "robolab.xml",
                     "--rate", "8000", "--timeout", "30", cwd=own, timeout=60)
    assert proc.returncode == 0, proc.stderr
    assert (own / "inbox" / "mission.bin").read_bytes() == data
    node.wait_for("received mission.bin (10240 bytes)")


def test_a_java_tablet_from_the_generated_skeleton_talks_to_the_onboard_end(own: Path, start: Any) -> None:
    gen = run_ttctl("gen", "robolab.xml", "--lang", "java", "-o", "gen", cwd=own, timeout=300)
    assert gen.returncode == 0, gen.stderr
    sources = sorted(str(p) for p in (own / "gen" / "java").rglob("*.java"))
    sources.append(str(ROOT / "tests" / "java" / "own" / "RobolabTablet.java"))
    # the README's few lines of the same app compile too (pasted into a method)
    readme = manual().split("## Your own messages", 1)[1].split("\n## ", 1)[0]
    (block,) = re.findall(r"```java\n(.+?)```", readme, re.S)
    snippet = own / "ReadmeRobolab.java"
    snippet.write_text("import java.util.concurrent.TimeUnit;\nimport ttctl.robolab.Robolab;\n"
                       "import ttctl.robolab.commands.SendKrMotorControl;\nimport ttctl.robolab.enums.KrVehicleDir;\n"
                       "import ttctl.robolab.msg.KrMotorStatus;\nimport ttctl.robolab.runtime.*;\n"
                       "final class ReadmeRobolab {\n    static Object run() throws Exception {\n" + block
                       + "        return st;\n    }\n}\n")
    sources.append(str(snippet))
    classes = own / "classes"
    javac = subprocess.run(["javac", "--release", "11", "-Xlint:all", "-Werror", "-encoding", "UTF-8", "-d",
                            str(classes), *sources], capture_output=True, text=True, timeout=600)
    assert javac.returncode == 0, javac.stderr[-4000:]
    port = free_port()
    node = onboard(start, port, "--dialect", "robolab.xml", "--plugin", "motors.py")
    java = subprocess.run(["java", "-cp", str(classes), "RobolabTablet", str(port), "42"], capture_output=True,
                          text=True, timeout=60)
    assert java.stdout.strip() == "RESULT 42 1 30 375.0 ok", java.stdout + java.stderr
    node.wait_for("motors: seq 42: KR_VEHICLE_DIR_FORWARD at 30 %")


def test_ends_of_two_dialects_say_so_once_and_keep_working(own: Path, start: Any) -> None:
    """A tablet speaking robolab, a vehicle speaking ttctl's own dialect: the vehicle counts and
    names the messages it does not know, once, and still obeys the commands both know."""
    port = free_port()
    node = onboard(start, port, "--speed", "4")
    script = ("- msg: KR_MOTOR_CONTROL seq=1\n- msg: KR_MOTOR_CONTROL seq=2\n- msg: KR_MOTOR_STATUS seq=3\n"
              "- takeoff: 3\n- wait: {until: altitude >= 2.5, timeout: 30}\n")
    t = tablet(own, port, script, "--dialect", "robolab.xml")
    assert t.returncode == 0, t.stdout + t.stderr
    notes = [line for line in node.stderr.splitlines() if "which dialect ttapi does not have" in line]
    assert len(notes) == 2, node.stderr  # once for 51000, once for 51001
    assert "255/190 at 127.0.0.1:" in notes[0] and "sends msgid 51000" in notes[0]
    assert "do both ends use the same --dialect?" in notes[0]
    assert node.p.poll() is None


def _refused(proc: subprocess.CompletedProcess[str], words: str) -> None:
    assert_no_traceback(proc)
    assert proc.returncode == 2, proc.stderr
    last = proc.stderr.strip().splitlines()[-1]
    assert last.startswith("ttctl: error: ") and words in last, proc.stderr


@pytest.mark.parametrize("case", ["no-runtime", "errors", "missing-include", "no-file"])
def test_a_dialect_that_cannot_carry_the_link_is_refused_before_anything_starts(own: Path, case: str,
                                                                                bindings_cache: Path) -> None:
    from ttctl.wire.contract import RUNTIME_MESSAGES

    files = {
        "no-runtime": ('<mavlink><messages><message id="51000" name="X"><description>x</description>'
                       '<field type="uint8_t" name="a">a</field></message></messages></mavlink>',
                       "lacks the runtime's messages (TT_FILE_OFFER, TT_FILE_STATUS, TT_FILE_DATA, TT_FILE_REQUEST "
                       f"and {len(RUNTIME_MESSAGES) - 4} more): add <include>ttapi.xml</include> to it"),
        "errors": ('<mavlink><include>ttapi.xml</include><messages><message id="51000" name="X"><description>x'
                   '</description><field type="uint8_t" name="a" enum="NOPE">a</field></message></messages></mavlink>',
                   "1 error(s) in the dialect; nothing started"),
        "missing-include": ('<mavlink><include>../message_definitions/v1.0/common.xml</include><include>ttapi.xml'
                            '</include><messages/></mavlink>', "1 error(s) in the dialect; nothing started"),
        "no-file": (None, "--dialect d.xml: no such file"),
    }
    text, words = files[case]
    if text is not None:
        (own / "d.xml").write_text(text + "\n")
    before = sorted(p.name for p in (bindings_cache / "bindings" / "index").glob("*")) \
        if (bindings_cache / "bindings" / "index").is_dir() else []
    port = free_port()
    commands = [
        ["emulate", "onboard", "--listen", f"udpin:{LOCAL}:{port}", "--no-gcs", "--inbox", "inbox"],
        ["emulate", "tablet", "--to", f"udpout:{LOCAL}:{port}"],
        ["send-file", "robolab.xml", "--to", f"udpout:{LOCAL}:{port}"],
        ["recv-file", "--listen", f"udpin:{LOCAL}:{port}", "--dir", "inbox"],
        ["link", "relay", "--listen", f"udp:{LOCAL}:{port}", "--to", f"udp:{LOCAL}:{free_port()}"],
        ["hmd", "dump", "--duration", "1", "--to", f"udpout:{LOCAL}:{port}", "-o", "poses.jsonl"],
        ["bench", "latency", "--to", f"udpout:{LOCAL}:{port}"],
    ]
    for args in commands:
        t0 = time.monotonic()
        proc = run_ttctl(*args, "--dialect", "d.xml", cwd=own, timeout=60)
        _refused(proc, words)
        assert time.monotonic() - t0 < 20, args  # refused, not tried
        if case == "missing-include":
            assert "[INCLUDE-MISSING] cannot find included file '../message_definitions/v1.0/common.xml'" \
                   in proc.stderr
        if case == "errors":
            assert "d.xml:1:" in proc.stderr and "[UNDEFINED-ENUM]" in proc.stderr
    assert not (own / "inbox").exists() and not (own / "poses.jsonl").exists()
    after = sorted(p.name for p in (bindings_cache / "bindings" / "index").glob("*")) \
        if (bindings_cache / "bindings" / "index").is_dir() else []
    assert after == before  # nothing cached for a refused dialect


def test_a_plugin_for_another_dialect_is_refused(own: Path) -> None:
    """The motors plugin on an end that speaks ttctl's shipped dialect: it cannot even import."""
    proc = run_ttctl("emulate", "onboard", "--listen", f"udpin:{LOCAL}:{free_port()}", "--no-gcs", "--plugin",
                     "motors.py", cwd=own, timeout=60)
    _refused(proc, "--plugin motors.py: ModuleNotFoundError: No module named 'robolab' (the bindings of a dialect? "
                   "start the end with --dialect FILE.xml)")


def test_a_plugin_whose_message_the_end_lacks_is_refused(own: Path) -> None:
    (own / "by_name.py").write_text(
        "from ttctl.ends.plugins import Plugin, handles\n\n\nclass P(Plugin):\n"
        "    @handles('KR_MOTOR_CONTROL')\n    def on(self, msg, ctx):\n        pass\n")
    proc = run_ttctl("emulate", "tablet", "--to", f"udpout:{LOCAL}:{free_port()}", "--plugin", "by_name.py",
                     cwd=own, timeout=60)
    _refused(proc, "--plugin P.on: dialect ttapi has no message KR_MOTOR_CONTROL")


def test_the_dialect_set_once_in_the_environment(own: Path, start: Any, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("TTCTL_DIALECT", str(own / "robolab.xml"))
    port = free_port()
    node = onboard(start, port, "--plugin", "motors.py")
    assert "dialect robolab" in node.stderr
    t = tablet(own, port, "- msg: {send: KR_MOTOR_CONTROL seq=9 speed=1, until: KR_MOTOR_STATUS.seq == 9, "
                          "timeout: 20}\n")
    assert t.returncode == 0, t.stderr
    bad = tablet(own, port, "- msg: KR_MOTOR_CONTROL spede=1\n")
    _refused(bad, "line 1: KR_MOTOR_CONTROL has no field 'spede' (did you mean speed?")
