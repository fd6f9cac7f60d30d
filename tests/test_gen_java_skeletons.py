"""The tablet's command skeletons (SendX): a field typed by an enum takes the enum's constants
as they are (an int8_t field is a Java byte, the constants are ints), range-checked; array
arguments are copied, not shared; the retry settings say what they are. Built with javac
-Xlint:all -Werror together with a driver that calls them as a user would."""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest

from conftest import run_ttctl

pytestmark = pytest.mark.skipif(shutil.which("javac") is None or shutil.which("java") is None,
                                reason="needs a JDK (javac, java)")

DIALECT = """<?xml version="1.0"?>
<mavlink>
  <enums>
    <enum name="KR_VEHICLE_DIR">
      <description>Direction.</description>
      <entry value="0" name="VEHICLE_STOP"/>
      <entry value="1" name="VEHICLE_FORWARD"/>
      <entry value="2" name="VEHICLE_BACKWARD"/>
    </enum>
    <enum name="KR_GEAR">
      <description>Gear, on a 16-bit field.</description>
      <entry value="300" name="KR_GEAR_HIGH"/>
    </enum>
    <enum name="KR_FLAGS" bitmask="true">
      <description>Flags past int, on an int32_t field.</description>
      <entry value="1" name="KR_FLAGS_A"/>
      <entry value="0x100000000" name="KR_FLAGS_FAR"/>
    </enum>
  </enums>
  <messages>
    <message id="60000" name="KR_MOTOR_CONTROL">
      <description>Drive. [sender: tablet]</description>
      <field type="int8_t" name="direction" enum="KR_VEHICLE_DIR">direction</field>
      <field type="uint8_t" name="speed">speed</field>
      <field type="int16_t" name="gear" enum="KR_GEAR">gear</field>
      <field type="uint8_t" name="udir" enum="KR_VEHICLE_DIR">as uint8_t, already an int</field>
      <field type="int32_t" name="flags" enum="KR_FLAGS">flags</field>
      <field type="float[4]" name="q">attitude</field>
      <field type="char[8]" name="tag">tag</field>
    </message>
    <message id="60001" name="KR_PING">
      <description>Answered by KR_PONG with the same seq. [sender: tablet]</description>
      <field type="uint8_t" name="seq">seq</field>
    </message>
    <message id="60002" name="KR_PONG">
      <description>[sender: onboard]</description>
      <field type="uint8_t" name="seq">seq</field>
    </message>
  </messages>
</mavlink>
"""

DRIVER = """package ttctl.kr.commands;

import ttctl.kr.enums.KrFlags;
import ttctl.kr.enums.KrGear;
import ttctl.kr.enums.KrVehicleDir;
import ttctl.kr.msg.KrMotorControl;

public final class SkeletonCheck {
    private SkeletonCheck() {
    }

    static void check(boolean ok, String what) {
        if (!ok) {
            throw new AssertionError(what);
        }
    }

    public static void main(String[] args) {
        float[] q = {1f, 2f, 3f, 4f};
        byte[] tag = {'a', 'b'};
        // the call the user wrote, no casts
        SendKrMotorControl c = new SendKrMotorControl(KrVehicleDir.VEHICLE_FORWARD, 10, KrGear.KR_GEAR_HIGH,
                KrVehicleDir.VEHICLE_BACKWARD, KrFlags.KR_FLAGS_A, q, tag);
        check(c.direction == 1 && c.gear == 300 && c.udir == 2 && c.flags == 1, "values");
        q[0] = 9f;
        tag[0] = 'z';
        check(c.q[0] == 1f && c.tag[0] == 'a', "the command copies the caller's arrays");
        KrMotorControl m = (KrMotorControl) c.createMessage(null, 0);
        check(m.direction == 1 && m.q[3] == 4f && m.tag[1] == 'b', "message values");
        m.q[3] = 7f;
        m.tag[1] = 'y';
        KrMotorControl again = (KrMotorControl) c.createMessage(null, 1);
        check(again.q[3] == 4f && again.tag[1] == 'b', "a retry packs the command's values, not a changed message's");
        check(again.q != m.q && c.q != m.q, "each message has its own arrays");
        new SendKrMotorControl(-128, 0, -32768, 0, -2147483648, null, null);
        for (long[] bad : new long[][] {{128, 0, 0}, {0, 32768, 0}, {0, 0, KrFlags.KR_FLAGS_FAR}}) {
            try {
                new SendKrMotorControl((int) bad[0], 0, (int) bad[1], 0, bad[2], q, tag);
                throw new AssertionError("accepted " + java.util.Arrays.toString(bad));
            } catch (IllegalArgumentException e) {
                check(e.getMessage().startsWith("KR_MOTOR_CONTROL."), e.getMessage());
                System.out.println("refused: " + e.getMessage());
            }
        }
        System.out.println("DONE");
    }
}
"""


@pytest.fixture(scope="module")
def built(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path]:
    base = tmp_path_factory.mktemp("skel")
    xml = base / "kr.xml"
    xml.write_text(DIALECT)
    out = base / "out"
    proc = run_ttctl("gen", str(xml), "--lang", "java", "-o", str(out))
    assert proc.returncode == 0, proc.stdout + proc.stderr
    driver = base / "SkeletonCheck.java"
    driver.write_text(DRIVER)
    classes = base / "classes"
    javac = subprocess.run(["javac", "--release", "11", "-Xlint:all", "-Werror", "-d", str(classes),
                            *map(str, sorted((out / "java").rglob("*.java"))), str(driver)],
                           capture_output=True, text=True, timeout=600)
    assert javac.returncode == 0, javac.stderr[-5000:]
    return out, classes


def test_enum_constants_need_no_cast_and_arrays_are_copied(built: tuple[Path, Path]) -> None:
    _, classes = built
    run = subprocess.run(["java", "-cp", str(classes), "ttctl.kr.commands.SkeletonCheck"], capture_output=True,
                         text=True, timeout=60)
    assert run.returncode == 0 and "DONE" in run.stdout, run.stdout + run.stderr
    assert "refused: KR_MOTOR_CONTROL.direction: 128 does not fit int8_t (-128..127)" in run.stdout, run.stdout
    assert "refused: KR_MOTOR_CONTROL.gear: 32768 does not fit int16_t (-32768..32767)" in run.stdout, run.stdout
    assert "refused: KR_MOTOR_CONTROL.flags: 4294967296 does not fit int32_t" in run.stdout, run.stdout


def test_retry_settings_are_named(built: tuple[Path, Path]) -> None:
    out, _ = built
    commands = out / "java" / "ttctl" / "kr" / "commands"
    for name in ("SendKrMotorControl", "SendKrPing"):
        text = (commands / f"{name}.java").read_text()
        call = re.search(r"super\((.*?)\);", text, re.S)
        assert call, name
        args = call.group(1).split("\n")
        assert len(args) == 4 and all("//" in a for a in args[:-1]) and "//" in text[call.end():].split("\n")[0], (
            name, call.group(0))
