"""The tablet's `msg` steps against a user's dialect with enum arrays and bitmasks, as real
processes on loopback (`ttctl emulate tablet --script` and `ttctl emulate onboard` with a plugin
that logs what it decoded): an enum array given by entry names arrives as their numbers; text is
never taken for an enum array's bytes; `|` only on bitmasks; numbers outside an enum and bits
outside a bitmask refused; `msg` without `until` sends once; and the tablet names, once, the
messages of the vehicle it cannot decode. Each refusal is one line naming the script's line, the
field and the allowed entries, exit 2, and nothing sent (the onboard end's plugin never hears
the script's first, valid step)."""

from __future__ import annotations

import re
import shutil
import subprocess
import time
from pathlib import Path
from typing import Any

import pytest

from conftest import ROOT, assert_no_traceback, run_ttctl
from e2e_lib import LOCAL, Proc, free_port

SURVEY = """<?xml version="1.0"?>
<mavlink>
  <include>ttapi.xml</include>
  <version>3</version>
  <dialect>0</dialect>
  <enums>
    <enum name="SV_SCHEDULE">
      <entry value="1" name="SV_SCHEDULE_SINGLE"/>
      <entry value="2" name="SV_SCHEDULE_BURST"/>
      <entry value="3" name="SV_SCHEDULE_CONTINUOUS"/>
    </enum>
    <enum name="SV_SENSORS" bitmask="true">
      <entry value="1" name="SV_SENSORS_CAMERA"/>
      <entry value="2" name="SV_SENSORS_LIDAR"/>
      <entry value="4" name="SV_SENSORS_THERMAL"/>
    </enum>
    <enum name="SV_BAND">
""" + "".join(f'      <entry value="{10 + k}" name="SV_BAND_B{k}"/>\n' for k in range(11)) + """    </enum>
  </enums>
  <messages>
    <message id="52000" name="SV_PLAN">
      <description>[sender: tablet] A survey plan.</description>
      <field type="uint8_t" name="target_system">System id of the vehicle.</field>
      <field type="uint16_t" name="seq">Sender's number.</field>
      <field type="uint8_t[3]" name="schedule" enum="SV_SCHEDULE">One per leg.</field>
      <field type="uint8_t" name="sensors" enum="SV_SENSORS">Sensors on.</field>
      <field type="uint8_t" name="band" enum="SV_BAND">Radio band.</field>
      <field type="uint8_t[4]" name="tag">Bytes of the user's.</field>
    </message>
    <message id="52001" name="SV_BEACON">
      <description>[sender: onboard] The vehicle is surveying.</description>
      <field type="uint16_t" name="count">Beacons sent.</field>
    </message>
  </messages>
</mavlink>
"""

PLUGIN = """
from ttctl.ends.plugins import Context, Plugin, handles


class Survey(Plugin):
    def start(self, ctx: Context) -> None:
        self.count = 0
        if ctx.dialect.name == "survey":
            def beacon() -> None:
                self.count += 1
                ctx.send(ctx.dialect.SvBeacon(count=self.count))
            ctx.every(0.2, beacon)

    @handles("SV_PLAN")
    def on_plan(self, msg, ctx: Context) -> None:
        ctx.log(f"plan seq={msg.seq} schedule={list(msg.schedule)} sensors={msg.sensors} band={msg.band} "
                f"tag={list(msg.tag)}")
"""


@pytest.fixture(scope="module")
def cache(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("ttctl-cache")


@pytest.fixture
def survey(tmp_path: Path, cache: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.setenv("TTCTL_CACHE_DIR", str(cache))
    monkeypatch.delenv("TTCTL_DIALECT", raising=False)
    (tmp_path / "survey.xml").write_text(SURVEY)
    (tmp_path / "survey_plugin.py").write_text(PLUGIN)
    return tmp_path


def onboard(start: Any, folder: Path, *extra: str) -> tuple[Proc, int]:
    port = free_port()
    p = start("onboard", "emulate", "onboard", "--listen", f"udpin:{LOCAL}:{port}", "--no-gcs", "--plugin",
              str(folder / "survey_plugin.py"), *extra)
    p.wait_for(f"onboard 1: tablet link udpin:{LOCAL}:{port}", timeout=60)
    return p, port


def tablet(folder: Path, port: int, script: str, *extra: str) -> subprocess.CompletedProcess[str]:
    (folder / "script.yaml").write_text(script)
    proc = run_ttctl("emulate", "tablet", "--to", f"udpout:{LOCAL}:{port}", "--script", str(folder / "script.yaml"),
                     *extra, timeout=90, cwd=folder)
    assert_no_traceback(proc)
    return proc


def plans(node: Proc) -> list[str]:
    return [line.split("plan ", 1)[1] for line in node.stderr.splitlines() if "plan seq=" in line]


def test_an_enum_array_by_entry_names_arrives_as_their_numbers(survey: Path, start: Any) -> None:
    node, port = onboard(start, survey, "--dialect", "survey.xml")
    t = tablet(survey, port, "- msg: SV_PLAN seq=1 schedule=[SINGLE,BURST,CONTINUOUS] sensors=CAMERA|THERMAL "
                             "band=B10 tag=ab\n"
                             "- msg: {send: \"SV_PLAN seq=2 schedule=SV_SCHEDULE_CONTINUOUS,3,burst sensors=7 band=10 "
                             "tag=[1,2,3,4]\"}\n- wait: 1\n", "--dialect", "survey.xml")
    assert t.returncode == 0, t.stdout + t.stderr
    node.wait_for("plan seq=2")
    assert plans(node) == ["seq=1 schedule=[1, 2, 3] sensors=5 band=20 tag=[97, 98, 0, 0]",
                           "seq=2 schedule=[3, 3, 2] sensors=7 band=10 tag=[1, 2, 3, 4]"], node.stderr


def test_msg_without_until_sends_once(survey: Path, start: Any) -> None:
    node, port = onboard(start, survey, "--dialect", "survey.xml")
    t = tablet(survey, port, "- msg: {send: \"SV_PLAN seq=7 schedule=[1,1,1]\"}\n- wait: 2\n",
               "--dialect", "survey.xml")
    assert t.returncode == 0, t.stdout + t.stderr
    assert "step 1 msg SV_PLAN seq=7 schedule=[1,1,1]: sent SV_PLAN" in t.stdout, t.stdout
    node.wait_for("plan seq=7")
    time.sleep(1.0)  # a second send would have come a second after the first (until's default every)
    assert plans(node) == ["seq=7 schedule=[1, 1, 1] sensors=0 band=0 tag=[0, 0, 0, 0]"], node.stderr

REFUSED = [
    # (the step's field=value, words the one-line refusal holds)
    ("schedule=ABC", "SV_PLAN.schedule: 'ABC' is not an entry of SV_SCHEDULE (SINGLE, BURST, CONTINUOUS)"),
    ("schedule=[SINGLE,BURST,WALK]", "SV_PLAN.schedule: 'WALK' is not an entry of SV_SCHEDULE (SINGLE, BURST, "
                                     "CONTINUOUS)"),
    ("schedule=[1,2,9]", "SV_PLAN.schedule: 9 is not an entry of SV_SCHEDULE (SINGLE=1, BURST=2, CONTINUOUS=3)"),
    ("schedule=[SINGLE,BURST]", "SV_PLAN.schedule wants 3 entries of SV_SCHEDULE (SINGLE, BURST, CONTINUOUS), "
                                "got 2"),
    ("schedule=[SINGLE|BURST,1,1]", "SV_PLAN.schedule: 'SINGLE|BURST': SV_SCHEDULE is not a bitmask, give one "
                                    "entry (SINGLE, BURST, CONTINUOUS)"),
    ("band=B1|B2", "SV_PLAN.band: 'B1|B2': SV_BAND is not a bitmask, give one entry (B0, B1, B2, B3, B4, B5, B6, B7 "
                   "and 3 more)"),
    ("band=9", "SV_PLAN.band: 9 is not an entry of SV_BAND (B0=10, B1=11, B2=12, B3=13, B4=14, B5=15, B6=16, B7=17 "
               "and 3 more)"),
    ("sensors=8", "SV_PLAN.sensors: 8 has bits outside SV_SENSORS (0x8; its bits: CAMERA=1, LIDAR=2, THERMAL=4)"),
    ("sensors=CAMERA|SONAR", "SV_PLAN.sensors: 'SONAR' is not an entry of SV_SENSORS (CAMERA, LIDAR, THERMAL)"),
]


@pytest.mark.parametrize(("value", "words"), REFUSED, ids=[v for v, _ in REFUSED])
def test_a_bad_enum_value_refuses_the_script_before_anything_is_sent(survey: Path, start: Any, value: str,
                                                                     words: str) -> None:
    node, port = onboard(start, survey, "--dialect", "survey.xml")
    bad = tablet(survey, port, f"- msg: SV_PLAN seq=1 schedule=[1,1,1]\n- wait: 1\n- msg: SV_PLAN seq=2 {value}\n",
                 "--dialect", "survey.xml")
    assert bad.returncode == 2, bad.stdout + bad.stderr
    lines = bad.stderr.strip().splitlines()
    assert len(lines) == 1, bad.stderr
    assert lines[0].startswith("ttctl: error: --script ") and ": line 3: " in lines[0], lines[0]
    assert words in lines[0], lines[0]
    assert bad.stdout == ""
    # nothing was sent: the plugin hears the next run's plan, and never the refused script's first step
    good = tablet(survey, port, "- msg: SV_PLAN seq=3 schedule=[1,1,1]\n- wait: 0.5\n", "--dialect", "survey.xml")
    assert good.returncode == 0, good.stdout + good.stderr
    node.wait_for("plan seq=3")
    assert [p for p in plans(node) if not p.startswith("seq=3 ")] == [], node.stderr


def test_the_tablet_names_a_message_it_cannot_decode_once(survey: Path, start: Any) -> None:
    """The vehicle speaks survey (SV_BEACON 5 times a second), the tablet ttctl's own dialect."""
    node, port = onboard(start, survey, "--dialect", "survey.xml")
    t = tablet(survey, port, "- wait: 2\n- status\n")
    assert t.returncode == 0, t.stdout + t.stderr
    notes = [line for line in t.stderr.splitlines() if "msgid 52001" in line]
    assert len(notes) == 1, t.stderr
    assert notes[0].startswith("ttctl: tablet: 1/240 at 127.0.0.1:")
    assert "which dialect ttapi does not have: counted and ignored (do both ends use the same --dialect?)" in notes[0]
    (status,) = [line for line in t.stdout.splitlines() if line.startswith("step 2 status: ")]
    counted = re.search(r" frames \(and (\d+) of messages dialect ttapi lacks\)", status)
    assert counted is not None and int(counted.group(1)) >= 5, status  # 5 a second for 2 s, each counted
    assert node.p.poll() is None


@pytest.fixture(scope="module")
def java_classes(tmp_path_factory: pytest.TempPathFactory) -> Path:
    if shutil.which("javac") is None or shutil.which("java") is None:
        pytest.skip("needs a JDK (javac, java)")
    from conformance_lib import build_java

    cls, _ = build_java(tmp_path_factory.mktemp("java_unknown"), [ROOT / "tests" / "java" / "unknown" /
                                                                  "UnknownTablet.java"])
    return cls


def test_the_java_tablet_names_a_message_it_cannot_decode_once(survey: Path, start: Any, java_classes: Path) -> None:
    """The generated Java runtime (ttapi) against a vehicle speaking survey: its Session counts
    SV_BEACON's frames and tells onProblem, once, in the Python ends' words; the vehicle's frames
    of ttapi are still decoded."""
    node, port = onboard(start, survey, "--dialect", "survey.xml")
    java = subprocess.run(["java", "-cp", str(java_classes), "UnknownTablet", str(port), "2.5"], capture_output=True,
                          text=True, timeout=60)
    assert java.returncode == 0, java.stdout + java.stderr
    lines = java.stdout.splitlines()
    problems = [line for line in lines if line.startswith("PROBLEM ")]
    assert problems == ["PROBLEM 1/240 sends msgid 52001, which dialect ttapi does not have: counted and ignored "
                        "(do both ends use the same dialect?)"], java.stdout + java.stderr
    counts = {k: int(v) for k, v in (line.split() for line in lines if line.startswith(("UNKNOWN ", "HEARD ")))}
    assert counts["UNKNOWN"] >= 5, java.stdout  # 5 a second for 2.5 s, each counted
    assert counts["HEARD"] >= 2, java.stdout  # the vehicle's HEARTBEATs, at least
    assert "msgid" not in java.stderr
    assert node.p.poll() is None
