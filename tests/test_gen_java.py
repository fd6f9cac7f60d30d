"""`ttctl gen --lang java`: the generated tree, builds with javac --release 11 and --release 8
under -Xlint:all -Werror, no API that Android API 24 lacks, skeleton handling; and Java test
drivers (tests/java) compiled with the generated sources: Parser resync and Dispatcher, and the
CommandQueue end to end over real loopback UDP against a Python responder that uses the
generated Python bindings."""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import pytest

from conftest import ROOT, TTAPI, run_ttctl

pytestmark = pytest.mark.skipif(shutil.which("javac") is None or shutil.which("java") is None,
                                reason="needs a JDK (javac, java)")

DRIVERS = ROOT / "tests" / "java"
PKG = Path("java/ttctl/ttapi")


def gen(*args: str) -> subprocess.CompletedProcess[str]:
    return run_ttctl("gen", *args, timeout=600)


def java_sources(out: Path) -> list[str]:
    return sorted(str(p) for p in (out / "java").rglob("*.java"))


def javac(release: str, classes: Path, sources: list[str], classpath: Path | None = None) -> None:
    classes.mkdir(parents=True, exist_ok=True)
    cp = ["-cp", str(classpath)] if classpath else []
    proc = subprocess.run(["javac", "--release", release, "-Xlint:all", "-Werror", "-encoding", "UTF-8", *cp,
                           "-d", str(classes), *sources], capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-6000:]
    assert "warning" not in proc.stderr, proc.stderr[-6000:]


@pytest.fixture(scope="module")
def out(tmp_path_factory: pytest.TempPathFactory) -> Path:
    o = tmp_path_factory.mktemp("gen_java") / "out"
    proc = gen(str(TTAPI), "--lang", "python,java", "-o", str(o))
    assert proc.returncode == 0, proc.stdout + proc.stderr
    return o


@pytest.fixture(scope="module")
def classes(out: Path) -> Path:
    """The generated sources and the test drivers, built once with --release 11."""
    c = out.parent / "classes11"
    javac("11", c, java_sources(out) + sorted(str(p) for p in DRIVERS.glob("*.java")))
    return c


def run_java(classes: Path, main: str, *args: str, timeout: float = 120) -> str:
    proc = subprocess.run(["java", "-cp", str(classes), main, *args], capture_output=True, text=True,
                          timeout=timeout)
    failed = re.search(r"^FAIL ", proc.stdout, re.M)
    assert proc.returncode == 0 and not failed, proc.stdout[-4000:] + proc.stderr[-4000:]
    assert "DONE" in proc.stdout, proc.stdout
    return proc.stdout


# --- the tree -----------------------------------------------------------------------------

def test_tree(out: Path) -> None:
    from ttctl.dialect.names import camel

    root = out / PKG
    assert (root / "Ttapi.java").is_file() and (out / "java" / "Conformance.java").is_file()
    for name in ("Crc", "MavlinkMessage", "Frame", "Parser", "Dispatcher", "Link", "UdpLink", "Command",
                 "SendCommand", "ReceiveCommand", "CommandQueue"):
        assert (root / "runtime" / f"{name}.java").is_file(), name
    model = _model()
    msgs = [m for m in model.messages if m.complete]
    assert {p.stem for p in (root / "msg").glob("*.java")} == {camel(m.name) for m in msgs}
    assert {p.stem for p in (root / "enums").glob("*.java")} == {camel(e.name) for e in model.enums}
    from ttctl.codegen.engine import receives, sends

    cmds = {p.stem for p in (root / "commands").glob("*.java")}
    assert cmds == {f"Send{camel(m.name)}" for m in sends(model, "tablet")} | {
        f"Receive{camel(m.name)}" for m in receives(model, "tablet")}
    assert {"SendTtActionCommand", "ReceiveTtCommandAck"} <= cmds
    assert "SendTtCommandAck" not in cmds and "ReceiveTtActionCommand" not in cmds  # sender tags
    skel = (root / "commands" / "SendTtActionCommand.java").read_text()
    assert "TtCommandAck.MSG_ID" in skel
    assert "reply.command_id == (this.command_id != 0 ? this.command_id : ctx.commandId())" in skel
    assert "msg.time_usec = this.time_usec != 0 ? this.time_usec : ctx.issuedUsec();" in skel
    cls = (root / "msg" / "TtActionCommand.java").read_text()
    assert "public static final int MSG_ID = 50005;" in cls
    assert "public long time_usec;" in cls and "public byte[] argument = new byte[48];" in cls
    assert "public float[] param = new float[4];" in cls


def _model() -> Any:
    from ttctl.validate import load_and_check

    d, rep, _ = load_and_check(str(TTAPI), [])
    assert rep.errors == 0
    return d


def test_skeletons_kept_and_stale_bindings_removed(tmp_path: Path) -> None:
    o = tmp_path / "out"
    assert gen(str(TTAPI), "--lang", "java", "-o", str(o)).returncode == 0
    skel = o / PKG / "commands" / "SendTtActionCommand.java"
    skel.write_text(skel.read_text() + "// my code\n")
    stale_msg = o / PKG / "msg" / "Gone.java"
    stale_msg.write_text("class Gone {}\n")
    mine = o / PKG / "commands" / "MyCommand.java"
    mine.write_text("// mine\n")
    proc = gen(str(TTAPI), "--lang", "java", "-o", str(o))
    assert proc.returncode == 0 and "skeletons kept" in proc.stdout and "1 stale removed" in proc.stdout, proc.stdout
    assert skel.read_text().endswith("// my code\n") and not stale_msg.exists() and mine.exists()
    assert gen(str(TTAPI), "--lang", "java", "-o", str(o), "--check").returncode == 0
    forced = gen(str(TTAPI), "--lang", "java", "-o", str(o), "--force-skeletons")
    assert forced.returncode == 0 and "// my code" not in skel.read_text()


# --- builds -------------------------------------------------------------------------------

def test_release_11_build_with_drivers(classes: Path) -> None:
    assert (classes / "Conformance.class").is_file()
    assert (classes / "ttctl" / "ttapi" / "runtime" / "CommandQueue.class").is_file()


def test_release_8_build(out: Path) -> None:
    """Java 8's API is a close approximation of what Android API 24 offers."""
    javac("8", out.parent / "classes8", java_sources(out) + sorted(str(p) for p in DRIVERS.glob("*.java")))


# Java 8 (or later) APIs that Android API 24 does not have, and newer-Java APIs that --release 8
# would catch too, as patterns over the generated sources.
DENYLIST = {
    r"\bjava\.time\b": "java.time (API 26)",
    r"\bjava\.nio\.file\b": "java.nio.file (API 26)",
    r"\bjava\.util\.Base64\b": "java.util.Base64 (API 26)",
    r"\bString\.join\(": "String.join (API 26)",
    r"\b(?:List|Set|Map)\.(?:of|copyOf|ofEntries|entry)\(": "immutable collection factories (Java 9)",
    r"\.(?:isBlank|strip|stripLeading|stripTrailing|lines|repeat|indent|formatted)\(": "Java 11+ String methods",
    r"\bOptional\b": "java.util.Optional (orElseThrow()/isEmpty() are Java 10/11; keep it out)",
    r"\b(?:to|parse)Unsigned(?:String|Long|Int)\b|\b(?:compare|divide|remainder)Unsigned\b":
        "unsigned Integer/Long helpers (API 26)",
    r"\btoUnsigned(?:Int|Long)\(": "Byte/Short/Integer.toUnsigned* (API 26)",
    r"\bvar\s+\w+\s*=": "var (Java 10)",
    r"\brecord\s+\w+\s*\(": "records (Java 16)",
    r"\.(?:readAllBytes|readNBytes|transferTo)\(": "InputStream Java 9+ methods",
    r"\b(?:orTimeout|completeOnTimeout|failedFuture|completedStage|failedStage|delayedExecutor|minimalCompletionStage)\(":
        "CompletableFuture Java 9+ methods",
    r"\bThread\.onSpinWait\b|\bProcessHandle\b|\bStackWalker\b|\bVarHandle\b": "Java 9+ runtime APIs",
    r"\bjava\.lang\.invoke\b": "java.lang.invoke (limited before API 26)",
    r"\bjava\.util\.concurrent\.Flow\b": "Flow (API 30)",
    r"\.toList\(\)": "Stream.toList (Java 16)",
    r"\bCollectors\.toUnmodifiable": "Collectors.toUnmodifiable* (Java 10)",
    r"\bObjects\.(?:requireNonNullElse|requireNonNullElseGet|checkIndex|checkFromToIndex|checkFromIndexSize)\(":
        "Objects Java 9+ methods",
    r"\bMath\.(?:fma|floorMod\(\s*\w+\s*,\s*\d+\s*\)|multiplyHigh)": "Java 9+ Math methods",
    r"\bString\.valueOf\(\s*\w+\s*\)\.chars\(": "odd stream use",
    r"\bHttpClient\b|\bjava\.net\.http\b": "java.net.http (Java 11)",
}


def test_no_api_android_24_lacks(out: Path) -> None:
    hits = []
    for path in (out / "java").rglob("*.java"):
        text = path.read_text(encoding="utf-8")
        code = re.sub(r"/\*.*?\*/|//[^\n]*", "", text, flags=re.S)  # comments may mention anything
        for pattern, why in DENYLIST.items():
            for m in re.finditer(pattern, code):
                hits.append(f"{path.relative_to(out)}: {m.group(0)!r}: {why}")
    assert not hits, "\n".join(hits[:50])


def test_denylist_catches_what_it_should() -> None:
    samples = ["java.time.Instant.now()", "List.of(1)", "s.isBlank()", "Long.toUnsignedString(x)", "var x = 1;",
               "Optional.empty()", "String.join(\",\", a)", "f.orTimeout(1, u)", "Integer.parseUnsignedInt(s)"]
    for s in samples:
        assert any(re.search(p, s) for p in DENYLIST), s


def test_sources_are_ascii(out: Path) -> None:
    """javac reads sources in the platform encoding unless told; keep them ASCII."""
    for path in (out / "java").rglob("*.java"):
        path.read_bytes().decode("ascii")


# --- drivers ------------------------------------------------------------------------------

def test_runtime_driver(classes: Path) -> None:
    """Parser resync on split, lost and corrupted chunks; Dispatcher with two handlers on one
    msgid; frame errors; helpers."""
    stdout = run_java(classes, "RuntimeCheck")
    assert "ok dispatcher" in stdout and "ok parser: a lost chunk" in stdout


RESPONDER = r'''
import json, socket, sys, threading
sys.path.insert(0, sys.argv[1])
import ttapi
from ttapi.mavlink import Encoder, Parser
from ttapi.messages import TtActionCommand, TtCommandAck, TtLog

DROP = {1: 2}  # command_id -> tries to drop before answering
log = []
tries = []
silent_count = [0]
lock = threading.Lock()
resp = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
resp.bind(("127.0.0.1", 0))
silent = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
silent.bind(("127.0.0.1", 0))


def serve():
    parser, enc, seen = Parser(), Encoder(sysid=1, compid=191), {}
    while True:
        data, addr = resp.recvfrom(65536)
        for msg in parser.feed(data):
            if not isinstance(msg, TtActionCommand):
                continue
            with lock:
                log.append(msg.command_id)
                tries.append([msg.command_id, msg.action, msg.time_usec])
            seen[msg.command_id] = n = seen.get(msg.command_id, 0) + 1
            if n <= DROP.get(msg.command_id, 0) or msg.action == 3 or (msg.action == 5 and n == 1):
                continue  # HOVER: never answered; RETURN_HOME: its first try dropped
            ack = TtCommandAck(target_system=msg.get_srcSystem(), target_component=msg.get_srcComponent(),
                               command_id=msg.command_id, action=msg.action, result=4 if msg.action == 4 else 0,
                               progress=100)
            if msg.action == 4 and n == 2:  # SYNC_TIME's refusal: its words as if the first were lost
                words = "refused: not now, " + "a test " * 20  # 158 bytes: two chunks, as log_chunks cuts
                raw = words.encode()
                for k in range(0, 2):
                    chunk = TtLog(id=77, severity=4, chunk_seq=k, text=raw[80 * k:80 * k + 80].decode())
                    resp.sendto(enc.encode(chunk), addr)
            resp.sendto(enc.encode(ack), addr)


def swallow():
    while True:
        silent.recvfrom(65536)
        with lock:
            silent_count[0] += 1


for f in (serve, swallow):
    threading.Thread(target=f, daemon=True).start()
print(json.dumps({"port": resp.getsockname()[1], "silent": silent.getsockname()[1], "module": ttapi.__file__}),
      flush=True)
sys.stdin.read()
with lock:
    print(json.dumps({"log": log, "tries": tries, "silent": silent_count[0]}), flush=True)
'''


def test_command_queue_over_udp(out: Path, classes: Path) -> None:
    responder = subprocess.Popen([sys.executable, "-c", RESPONDER, str(out / "python")], stdin=subprocess.PIPE,
                                 stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                 env={**os.environ, "PYTHONPATH": ""})
    try:
        assert responder.stdout is not None
        hello = json.loads(responder.stdout.readline() or "{}")
        assert hello, responder.stderr.read() if responder.stderr else ""
        assert Path(hello["module"]).resolve().is_relative_to((out / "python").resolve())
        stdout = run_java(classes, "QueueCheck", str(hello["port"]), str(hello["silent"]), timeout=120)
        summary, _ = responder.communicate("", timeout=30)
    finally:
        if responder.poll() is None:
            responder.kill()
            responder.wait()
    result = json.loads(summary.strip().splitlines()[-1])
    log = result["log"]
    assert log.count(1) == 3, log  # two tries dropped, the third answered
    assert [c for c in log if 10 <= c <= 14] == [11, 13, 12, 10, 14], log
    assert 30 not in log and 50 not in log  # unpackable, cancelled: never sent
    assert result["silent"] >= 3  # the never-answered command's three tries
    for check in ("retries", "no answer", "priorities", "receive: times out", "send failures", "shutdown",
                  "ids", "refused", "pre-emption", "every one of"):
        assert f"ok {check}" in stdout, stdout
    # the ids the queue chose: the RETURN_HOME's two tries, and the TAKE_OFF after it, carry the
    # same id and issue time on every try; the issue times are the wall clock's, increasing
    ids = [int(x) for x in re.search(r"^IDS (\d+) (\d+)$", stdout, re.M).groups()]  # type: ignore[union-attr]
    by_id = {i: [t for t in result["tries"] if t[0] == i] for i in ids}
    assert len(by_id[ids[0]]) == 2 and len({tuple(t) for t in by_id[ids[0]]}) == 1, by_id
    assert len(by_id[ids[1]]) == 1, by_id
    t1, t2 = by_id[ids[0]][0][2], by_id[ids[1]][0][2]
    assert 0 < t1 < t2 and abs(t2 / 1e6 - time.time()) < 120, (t1, t2)


NASTY = """<?xml version="1.0"?>
<mavlink>
  <version>3</version>
  <dialect>0</dialect>
  <enums>
    <enum name="BIG_FLAGS" bitmask="true">
      <description>Values past int: 2^31, 2^32. Comment enders */ unicode escapes \\u0041 @param &lt;b&gt; caf&#233;.
      </description>
      <entry value="1" name="BIG_FLAGS_ONE"/>
      <entry value="2147483648" name="BIG_FLAGS_HIGH"/>
      <entry value="4294967296" name="BIG_FLAGS_HIGHER"/>
    </enum>
  </enums>
  <messages>
    <message id="1" name="CRC">
      <description>[sender: tablet] Named like a runtime class; answered by COMMAND with the same len.</description>
      <field type="uint8_t" name="len">len</field>
      <field type="uint8_t" name="m">m</field>
      <field type="int8_t" name="b">b</field>
      <field type="int16_t" name="o">o</field>
      <field type="uint16_t" name="i">i</field>
      <field type="uint32_t" name="out">out</field>
      <field type="int32_t" name="ctx">ctx</field>
      <field type="int64_t" name="msg">msg</field>
      <field type="uint64_t" name="reply">reply</field>
      <field type="float" name="sb">sb</field>
      <field type="double" name="e">e</field>
      <field type="char" name="v">a scalar char</field>
      <field type="uint8_t" name="target_system">t</field>
      <extensions/>
      <field type="uint64_t[3]" name="fields">x</field>
      <field type="int8_t[4]" name="signed_bytes">x</field>
      <field type="int16_t[2]" name="shorts">x</field>
      <field type="uint16_t[2]" name="ushorts">x</field>
      <field type="int32_t[2]" name="ints">x</field>
      <field type="uint32_t[2]" name="uints">x</field>
      <field type="int64_t[2]" name="longs">x</field>
      <field type="double[2]" name="doubles">x</field>
      <field type="char[5]" name="text">x</field>
    </message>
    <message id="2" name="COMMAND">
      <description>[sender: onboard] Skeletons SendCommand, ReceiveCommand: named like runtime classes.</description>
      <field type="uint8_t" name="target_system">t</field>
      <field type="uint8_t" name="len">len</field>
    </message>
    <message id="3" name="MAVLINK_MESSAGE">
      <description>[sender: any] Named like the base class.</description>
      <field type="uint8_t" name="name">a field called name</field>
    </message>
  </messages>
</mavlink>
"""


def test_names_that_clash_with_generated_code(tmp_path: Path) -> None:
    """Message classes named like runtime classes, skeletons named like runtime classes, fields
    named like locals of generated methods, every type (a scalar char, arrays of each), enum
    values past int, descriptions with comment enders and unicode escapes: still builds with
    --release 8 under -Xlint:all -Werror, and encodes and decodes."""
    xml = tmp_path / "nasty.xml"
    xml.write_text(NASTY)
    o = tmp_path / "out"
    proc = gen(str(xml), "--lang", "java", "-o", str(o))
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert (o / "java/ttctl/nasty/commands/ReceiveCommand.java").is_file()
    javac("8", tmp_path / "classes", java_sources(o))
    fields = {"len": 255, "m": 1, "b": -128, "o": -32768, "i": 65535, "out": 4294967295, "ctx": -2147483648,
              "msg": -9223372036854775808, "reply": 18446744073709551615, "sb": "NaN", "e": -1.5e300, "v": "\u00ff",
              "target_system": 3, "fields": [1, 18446744073709551615, 0], "signed_bytes": [-1, 2, -3, 4],
              "shorts": [-1, 1], "ushorts": [65535, 0], "ints": [-1, 1], "uints": [4294967295, 1], "longs": [-1, 1],
              "doubles": [5e-324, "-Infinity"], "text": "ab\u00e9"}
    lines = "E " + json.dumps({"name": "CRC", "fields": fields}) + "\n"
    run = subprocess.run(["java", "-cp", str(tmp_path / "classes"), "Conformance"], input=lines, capture_output=True,
                         text=True, timeout=60)
    frame = run.stdout.strip()
    assert run.returncode == 0 and not frame.startswith("{"), run.stdout + run.stderr
    run = subprocess.run(["java", "-cp", str(tmp_path / "classes"), "Conformance"], input=f"D {frame}\n",
                         capture_output=True, text=True, timeout=60)
    doc = json.loads(run.stdout)
    assert doc["fields"] == {**fields, "e": -1.5e300, "doubles": [5e-324, "-Infinity"]}
