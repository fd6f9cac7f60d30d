"""The three conformance programs (Python, C++, Java) refuse bad requests in the same words,
byte for byte, as the README says they agree (issue 20: their error texts differed), field values
of every kind included. Built from the checked-in generated/ tree (g++ at -O0 and javac: quick)."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from conformance_lib import Conformance
from conftest import ROOT, manual

OUT = ROOT / "generated"
BAD = [
    "D fd0300",  # too short
    "D 000000000000000000000000000000",  # no magic
    "D zz", "D abc",  # not hex, odd digits
    "D fd0700000701f05ac3002a00ffbe01026407e8",  # bad CRC
    'E {"name":"NOPE"}', 'E {"msgid":99999}', "E {}", "E [1]", "X",
    'E {"name":"TT_COMMAND_ACK","fields":{"nope":1}}',
    "E {nope", 'E {"name": "TT_COMMAND_ACK", "fields": {"result": }}',
    # not JSON, though Python's reader takes the constants, and where a malformed number is refused
    'E {"name":"PARAM_VALUE","fields":{"param_value":NaN}}',
    'E {"name":"PARAM_VALUE","fields":{"param_value":-Infinity}}',
    'E {"name":"PARAM_VALUE","fields":{"param_value":"NaN\\"","x":Infinity}}',
    'E {"name":"TT_COMMAND_ACK","fields":{"result":1.}}', 'E {"name":"TT_COMMAND_ACK","fields":{"result":1.5e}}',
    'E {"name":"TT_COMMAND_ACK","fields":{"result":1e+}}', 'E {"name":"TT_COMMAND_ACK","fields":{"result":-}}',
    "E [1.]", "E -", "E 1e",
    # names quoted alike
    'E {"name":"it\'s"}', 'E {"name":"TT_COMMAND_ACK\\u0000"}', 'E {"name":"TT_COMMAND_ACK","fields":{"it\'s":1}}',
]


def e(name: str, **fields: str) -> str:
    """An E line: `fields` as JSON text (so that numbers stay as written)."""
    inner = ",".join(f'"{k}":{v}' for k, v in fields.items())
    return f'E {{"name":"{name}","fields":{{{inner}}}}}'


# Every kind of field value refused: integers out of range for each width (uint64 and int64
# limits too), negative for unsigned, a float, a string, null, a boolean, a list, an object for an
# integer; strings, booleans, null, lists and objects for a float, numbers too large for a float or a
# double; numbers, null, too long and non-Latin-1 strings for a char array; not a list, too long,
# too short, an element out of range or of the wrong type for the other arrays; and the request's
# own members (name, msgid, seq, sysid, compid, fields).
FIELD_VALUES = [
    e("TT_COMMAND_ACK", result="300"), e("TT_COMMAND_ACK", result="-1"), e("TT_COMMAND_ACK", result="1.5"),
    e("TT_COMMAND_ACK", result="2.0"), e("TT_COMMAND_ACK", result="1E2"), e("TT_COMMAND_ACK", result='"7"'),
    e("TT_COMMAND_ACK", result='"NaN"'), e("TT_COMMAND_ACK", result="null"), e("TT_COMMAND_ACK", result="true"),
    e("TT_COMMAND_ACK", result="{}"), e("TT_COMMAND_ACK", result="[1]"), e("TT_COMMAND_ACK", result="1e400"),
    e("TT_COMMAND_ACK", result="1" * 40), e("TT_COMMAND_ACK", result="1", progress="256"),
    e("SYS_STATUS", battery_remaining="128"), e("SYS_STATUS", battery_remaining="-129"),
    e("SYS_STATUS", load="65536"), e("SYS_STATUS", load="-1"),
    e("SYS_STATUS", current_battery="32768"), e("SYS_STATUS", current_battery="-32769"),
    e("HEARTBEAT", custom_mode="4294967296"), e("HEARTBEAT", custom_mode="-1"),
    e("GPS_RAW_INT", lat="2147483648"), e("GPS_RAW_INT", lat="-2147483649"),
    e("SYSTEM_TIME", time_unix_usec="18446744073709551616"), e("SYSTEM_TIME", time_unix_usec="-1"),
    e("SYSTEM_TIME", time_unix_usec="1.8e19"),
    e("TIMESYNC", tc1="9223372036854775808"), e("TIMESYNC", tc1="-9223372036854775809"), e("TIMESYNC", tc1="1e30"),
    e("TIMESYNC", tc1='"0"'),
    e("PARAM_VALUE", param_value='"x"'), e("PARAM_VALUE", param_value='"nan"'), e("PARAM_VALUE", param_value="true"),
    e("PARAM_VALUE", param_value="null"), e("PARAM_VALUE", param_value="[1]"), e("PARAM_VALUE", param_value="{}"),
    e("PARAM_VALUE", param_value="1e300"), e("PARAM_VALUE", param_value="-1e39"),
    e("PARAM_VALUE", param_value="1e400"), e("PARAM_VALUE", param_value="3.4028235677973366e38"),
    e("DJI_POSE_STAMPED", position="[1,2,1e309]"), e("DJI_POSE_STAMPED", position='[1,"Infinity",-1e309]'),
    e("DJI_POSE_STAMPED", position='["NaN",null,3]'), e("DJI_POSE_STAMPED", position="[1,2,true]"),
    e("DJI_POSE_STAMPED", position="[1,2,[3]]"), e("DJI_POSE_STAMPED", position="[1,2,3,4]"),
    e("DJI_POSE_STAMPED", position="[1,2]"), e("DJI_POSE_STAMPED", position="[]"), e("DJI_POSE_STAMPED", position="5"),
    e("PARAM_REQUEST_READ", param_id="7"), e("PARAM_REQUEST_READ", param_id="null"),
    e("PARAM_REQUEST_READ", param_id="false"), e("PARAM_REQUEST_READ", param_id='["a"]'),
    e("PARAM_REQUEST_READ", param_id='{"a":1}'), e("PARAM_REQUEST_READ", param_id='"abcdefghijklmnopq"'),
    e("PARAM_REQUEST_READ", param_id='"\\u0100"'), e("PARAM_REQUEST_READ", param_id='"\\ud83d\\ude00"'),
    e("PARAM_REQUEST_READ", param_id='"abc\u00e9\u20ac"'),
    e("TT_FILE_DATA", data="[256]"), e("TT_FILE_DATA", data="[-1]"), e("TT_FILE_DATA", data="[1.5]"),
    e("TT_FILE_DATA", data="[null]"), e("TT_FILE_DATA", data='"ab"'), e("TT_FILE_DATA", data="5"),
    e("TT_FILE_DATA", data="[" + ",".join(["7"] * 81) + "]"),
    e("TT_FILE_STATUS", ranges="[" + ",".join(["0"] * 15) + "]"), e("TT_FILE_STATUS", ranges="[1,2]"),
    e("TT_FILE_STATUS", ranges="[" + ",".join(["0"] * 13) + ",4294967296]"),
    e("TT_FILE_STATUS", ranges="[" + ",".join(["0"] * 13) + ',"a"]'),
    e("MEMORY_VECT", value="[" + ",".join(["0"] * 31) + ",128]"),
    e("BATTERY_STATUS", voltages="[" + ",".join(["0"] * 9) + ",65536]"),
    e("TERRAIN_DATA", data="[" + ",".join(["0"] * 15) + ",-32769]"),
    'E {"name":"TT_COMMAND_ACK","fields":[]}', 'E {"name":"TT_COMMAND_ACK","fields":"x"}',
    'E {"name":"TT_COMMAND_ACK","seq":256}', 'E {"name":"TT_COMMAND_ACK","sysid":-1}',
    'E {"name":"TT_COMMAND_ACK","sysid":1.0}', 'E {"name":"TT_COMMAND_ACK","compid":"x"}',
    'E {"name":"TT_COMMAND_ACK","compid":null}', 'E {"name":7}', 'E {"name":null}', 'E {"name":["TT_COMMAND_ACK"]}',
    'E {"msgid":"x"}', 'E {"msgid":-1}', 'E {"msgid":16777216}', 'E {"msgid":1e3}',
    'E {"name":"TT_COMMAND_ACK","fields":{"result":1,"progress":7,"result":300}}',  # the last of a key counts
]

# The values at the edges of what is allowed: accepted alike, the same frame from each.
EDGES = [
    e("SYSTEM_TIME", time_unix_usec="18446744073709551615"), e("SYSTEM_TIME", time_unix_usec="-0"),
    e("TIMESYNC", tc1="-9223372036854775808"), e("TIMESYNC", tc1="9223372036854775807"),
    e("SYS_STATUS", battery_remaining="-128", current_battery="32767", load="65535"),
    e("PARAM_VALUE", param_value="3.4028235e38"), e("PARAM_VALUE", param_value="-3.4028235e38"),
    e("PARAM_VALUE", param_value="1e-50"), e("PARAM_VALUE", param_value='"-Infinity"'),
    e("DJI_POSE_STAMPED", position='[1.7976931348623157e308,"NaN",-0.0]'),
    e("PARAM_REQUEST_READ", param_id='"abcdefghijklmnop"'), e("PARAM_REQUEST_READ", param_id='"\\u00ff\\u00e9"'),
    e("PARAM_REQUEST_READ", param_id='""'), e("TT_FILE_DATA", data="[]"),
    'E {"name":"TT_COMMAND_ACK","seq":255,"sysid":0,"compid":255,"fields":null}', 'E {"msgid":77}',
    'E {"name":"TT_COMMAND_ACK","fields":{"result":300,"progress":7,"result":1}}',
]

# The words, pinned: where, what is allowed, what came.
WORDS = {
    e("TT_COMMAND_ACK", result="300"): "TT_COMMAND_ACK.result: expected an integer in 0..255, got 300",
    e("SYSTEM_TIME", time_unix_usec="-1"):
        "SYSTEM_TIME.time_unix_usec: expected an integer in 0..18446744073709551615, got -1",
    e("TIMESYNC", tc1="1e30"):
        "TIMESYNC.tc1: expected an integer in -9223372036854775808..9223372036854775807, got 1e30",
    e("PARAM_VALUE", param_value="1e300"): 'PARAM_VALUE.param_value: expected a number in -3.4028235e38..'
                                           '3.4028235e38, "NaN", "Infinity" or "-Infinity", got 1e300',
    e("PARAM_REQUEST_READ", param_id='"abcdefghijklmnopq"'):
        "PARAM_REQUEST_READ.param_id: expected a string of at most 16 Latin-1 characters, got a string of 17 "
        "characters",
    e("TT_FILE_STATUS", ranges="[1,2]"): "TT_FILE_STATUS.ranges: expected a list of 14 values, got a list of 2 values",
    e("MEMORY_VECT", value="[" + ",".join(["0"] * 31) + ",128]"):
        "MEMORY_VECT.value[31]: expected an integer in -128..127, got 128",
    e("TT_FILE_DATA", data='"ab"'): "TT_FILE_DATA.data: expected a list of at most 80 values, got a string",
    'E {"name":"TT_COMMAND_ACK","seq":256}': "seq: expected an integer in 0..255, got 256",
}


@pytest.fixture(scope="module")
def programs(tmp_path_factory: pytest.TempPathFactory) -> list[list[str]]:
    build = tmp_path_factory.mktemp("conformance-errors")
    exe = build / "conformance"
    cpp = subprocess.run(["g++", "-std=c++17", "-O0", "-Wall", "-Wextra", "-Werror", "-I", str(OUT / "cpp"),
                          str(OUT / "cpp" / "conformance.cpp"), "-o", str(exe)], capture_output=True, text=True,
                         timeout=600)
    assert cpp.returncode == 0, cpp.stderr[-3000:]
    classes = build / "classes"
    java = subprocess.run(["javac", "--release", "11", "-d", str(classes),
                           *sorted(str(p) for p in (OUT / "java").rglob("*.java"))], capture_output=True, text=True,
                          timeout=600)
    assert java.returncode == 0, java.stderr[-3000:]
    return [[sys.executable, str(OUT / "python" / "conformance.py")], [str(exe)],
            ["java", "-cp", str(classes), "Conformance"]]


def test_the_three_refuse_in_the_same_words(programs: list[list[str]]) -> None:
    procs = [Conformance(cmd) for cmd in programs]
    try:
        for line in BAD:
            answers = [p.ask(line) for p in procs]
            assert answers[0].startswith('{"error":"'), (line, answers[0])
            assert answers[0] == answers[1] == answers[2], (line, answers)
    finally:
        for p in procs:
            p.close()


def test_field_values_are_refused_in_the_same_words(programs: list[list[str]]) -> None:
    procs = [Conformance(cmd) for cmd in programs]
    try:
        for line in FIELD_VALUES:
            answers = [p.ask(line) for p in procs]
            assert answers[0].startswith('{"error":"'), (line, answers[0])
            assert "Error" not in answers[0] and "Exception" not in answers[0], (line, answers[0])
            assert answers[0] == answers[1] == answers[2], (line, answers)
        for line in EDGES:
            answers = [p.ask(line) for p in procs]
            assert not answers[0].startswith("{"), (line, answers[0])
            assert answers[0] == answers[1] == answers[2], (line, answers)
        for line, words in WORDS.items():
            assert json.loads(procs[2].ask(line)) == {"error": words}
    finally:
        for p in procs:
            p.close()


def test_the_readme_shows_what_they_say() -> None:
    """The manual (README.md and docs/, conftest.manual()) shows the errors the programs print."""
    text = manual()
    shown = "$ echo 'D fd0300' | ./conformance\n" + '{"error":"not a MAVLink 2 frame (magic 0xFD, at least 12 bytes)"}'
    assert shown in text
    line = e("TT_COMMAND_ACK", result="300")
    shown = f"$ echo '{line}' | ./conformance\n" + json.dumps({"error": WORDS[line]}, separators=(",", ":"))
    assert shown in text
