"""The user's dialect in the link layer, without processes: the runtime's contract, the bindings
cache, plugins checked against the end's dialect, the tablet's messages built from text, and
frames of messages a dialect lacks."""

from __future__ import annotations

import ast
import json
import multiprocessing
import os
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from conftest import ROOT, shipped

OWN = ROOT / "dialects" / "examples" / "robolab.xml"
LINK_LAYER = ("wire", "proto", "ends")


# -- the contract ---------------------------------------------------------------------------------

def test_contract_tables_are_the_shipped_dialects() -> None:
    """RUNTIME_MESSAGES and the protocol enums say exactly what dialects/ttapi.xml says."""
    import ttapi
    from ttctl.ends.onboard import params
    from ttctl.wire import contract

    for name, (msgid, crc) in contract.RUNTIME_MESSAGES.items():
        cls = ttapi.BY_NAME[name]
        assert (msgid, crc) == (cls.MSG_ID, cls.CRC_EXTRA), name
    for enum in ("TtFileResult", "TtFileFlags", "TtResult", "TtAction", "TtVrDevice", "TtVrRole", "TtVrButtons",
                 "TtVrPoseFlags"):
        mine, theirs = getattr(contract, enum), getattr(ttapi, enum)
        assert {m.name: int(m.value) for m in mine} == {m.name: int(m.value) for m in theirs}, enum
    assert params.INT32 == ttapi.MavParamType.MAV_PARAM_TYPE_INT32
    assert params.REAL32 == ttapi.MavParamType.MAV_PARAM_TYPE_REAL32


def _used_message_classes() -> set[str]:
    """Class names the link layer takes from its bindings (`b.X`, `self.b.X`, `bindings().X`)."""
    import ttapi

    used: set[str] = set()
    for py in (ROOT / "cli" / "ttctl").rglob("*.py"):
        for node in ast.walk(ast.parse(py.read_text())):
            if isinstance(node, ast.Attribute) and node.attr[:1].isupper():
                base = node.value
                holder = base.attr if isinstance(base, ast.Attribute) else getattr(base, "id", None)
                if isinstance(base, ast.Call):
                    holder = getattr(base.func, "id", None)
                if holder in ("b", "dialect", "bindings"):
                    cls = getattr(ttapi, node.attr, None)
                    if isinstance(cls, type) and issubclass(cls, ttapi.Message):
                        used.add(cls.NAME)
    return used


def test_every_message_the_runtime_makes_is_in_the_contract() -> None:
    """A message the ends build from their bindings but the contract does not require would fail
    at run time on a dialect that lacks it: the table must cover them all."""
    from ttctl.wire.contract import RUNTIME_MESSAGES

    used = _used_message_classes()
    assert len(used) > 20  # the scan finds them
    assert used - set(RUNTIME_MESSAGES) == set()


def test_the_link_layer_imports_no_generated_package() -> None:
    for layer in LINK_LAYER:
        for py in (ROOT / "cli" / "ttctl" / layer).rglob("*.py"):
            for node in ast.walk(ast.parse(py.read_text())):
                names = [a.name for a in node.names] if isinstance(node, ast.Import) else \
                    [node.module or ""] if isinstance(node, ast.ImportFrom) else []
                assert not any(n == "ttapi" or n.startswith("ttapi.") for n in names), py


def test_contract_refusals_say_what_to_include() -> None:
    from ttctl.wire.contract import RUNTIME_MESSAGES, problem

    assert problem(dict(RUNTIME_MESSAGES), "d.xml") is None
    missing = {k: v for k, v in RUNTIME_MESSAGES.items() if not k.startswith("TT_FILE")}
    why = problem(missing, "d.xml")
    assert why is not None and why.startswith("d.xml lacks the runtime's messages (TT_FILE_OFFER")
    assert "<include>ttapi.xml</include>" in why
    changed = {**RUNTIME_MESSAGES, "TT_LOG": (50008, 1)}
    why = problem(changed, "d.xml")
    assert why is not None and "TT_LOG otherwise" in why and "CRC_EXTRA 1" in why


# -- the bindings cache -----------------------------------------------------------------------------

def _dialect(folder: Path, extra: str = "", name: str = "robolab.xml") -> Path:
    text = OWN.read_text()
    if extra:
        text = text.replace("  </messages>", extra + "\n  </messages>")
    path = folder / name
    path.write_text(text)
    return path


def _index(cache: Path) -> list[Path]:
    return sorted((cache / "bindings" / "index").glob("*.json")) if (cache / "bindings" / "index").is_dir() else []


def _entries(cache: Path) -> list[Path]:
    root = cache / "bindings"
    return sorted(p for p in root.iterdir() if p.is_dir() and p.name != "index") if root.is_dir() else []


def test_cache_cold_then_warm_then_rebuilt_when_anything_changes(tmp_path: Path) -> None:
    from ttctl.codegen.cache import python_bindings

    root = tmp_path / "cache" / "bindings"
    d = _dialect(tmp_path)
    first = python_bindings(str(d), [], root=root)
    assert first.built and first.package == "robolab"
    assert (first.folder / "robolab" / "__pycache__").is_dir()  # compiled now: a warm start does not compile
    again = python_bindings(str(d), [], root=root)
    assert not again.built and again.entry == first.entry
    # an edit of the dialect itself
    _dialect(tmp_path, '    <message id="51002" name="KR_PING"><description>x</description>'
                       '<field type="uint8_t" name="n">n</field></message>')
    edited = python_bindings(str(d), [], root=root)
    assert edited.built and edited.entry != first.entry
    assert "class KrPing" in (edited.folder / "robolab" / "messages.py").read_text()
    # a file appearing beside it that the bare <include>ttapi.xml</include> now finds first
    shutil.copy(ROOT / "dialects" / "ttapi.xml", tmp_path / "ttapi.xml")
    text = (tmp_path / "ttapi.xml").read_text().replace("<dialect>0</dialect>", "<dialect>0</dialect>\n  <!-- x -->")
    (tmp_path / "ttapi.xml").write_text(text)
    moved = python_bindings(str(d), [], root=root)
    assert moved.built and moved.entry != edited.entry
    assert not any(p.name.startswith(".build-") for p in root.iterdir())


def test_cache_refuses_a_broken_dialect_and_writes_nothing(tmp_path: Path) -> None:
    from ttctl.codegen.cache import DialectRefused, python_bindings

    root = tmp_path / "cache" / "bindings"
    bad = _dialect(tmp_path, '    <message id="51002" name="KR_BAD"><description>x</description>'
                             '<field type="uint8_t" name="n" enum="NOPE">n</field></message>')
    with pytest.raises(DialectRefused) as e:
        python_bindings(str(bad), [], root=root)
    assert "1 error(s)" in e.value.message and any("[UNDEFINED-ENUM]" in line for line in e.value.lines)
    assert not root.exists() or not any(root.iterdir())


def _build_in_process(args: tuple[str, str]) -> str:
    from ttctl.codegen.cache import python_bindings

    return str(python_bindings(args[0], [], root=Path(args[1])).entry)


def test_cache_builds_at_once_in_many_processes_agree(tmp_path: Path) -> None:
    """Four processes meeting a cold cache at once: every one gets a whole entry, the same one,
    and no temporary folder is left behind."""
    d = _dialect(tmp_path)
    root = tmp_path / "cache" / "bindings"
    with multiprocessing.get_context("spawn").Pool(4) as pool:
        entries = pool.map(_build_in_process, [(str(d), str(root))] * 4)
    assert len(set(entries)) == 1
    assert (Path(entries[0]) / "robolab" / "__init__.py").is_file()
    assert [p.name for p in root.iterdir() if p.name.startswith(".")] == []


def test_cache_that_cannot_be_written_serves_from_a_temporary_folder(tmp_path: Path) -> None:
    from ttctl.codegen.cache import python_bindings

    if os.geteuid() == 0:
        blocked = tmp_path / "file-not-folder"
        blocked.write_text("x")  # root ignores permissions: a file where the folder would be
        root = blocked / "bindings"
    else:
        ro = tmp_path / "ro"
        ro.mkdir(mode=0o500)
        root = ro / "bindings"
    got = python_bindings(str(_dialect(tmp_path)), [], root=root)
    assert got.built and got.notes and "cannot be written" in got.notes[0]
    assert (got.folder / "robolab" / "__init__.py").is_file()
    shutil.rmtree(got.folder)


def test_bindings_by_name_and_shadowing_names_refused(tmp_path: Path) -> None:
    from ttctl.codegen.cache import DialectRefused, python_bindings

    root = tmp_path / "cache" / "bindings"
    for name, words in (("json.xml", "standard library"), ("yaml.xml", "ttctl or its plugins already use"),
                        ("typer.xml", "already use")):
        with pytest.raises(DialectRefused) as e:
            python_bindings(str(_dialect(tmp_path, name=name)), [], root=root)
        assert words in e.value.message and "rename the dialect file" in e.value.message


# -- plugins against the end's dialect ------------------------------------------------------------

@pytest.fixture(scope="module")
def robolab(tmp_path_factory: pytest.TempPathFactory) -> Any:
    """The robolab bindings, imported (once: one process speaks one dialect) from a cache."""
    from ttctl.codegen.cache import python_bindings
    from ttctl.wire.bindings import Bindings

    got = python_bindings(str(OWN), [], root=tmp_path_factory.mktemp("cache") / "bindings")
    code = ("import sys, json; sys.path.insert(0, sys.argv[1]); import robolab; "
            "print(json.dumps([robolab.KrMotorControl.MSG_ID, robolab.KrMotorControl.TYPES]))")
    out = subprocess.run([sys.executable, "-c", code, str(got.folder)], capture_output=True, text=True, check=True)
    assert json.loads(out.stdout) == [51000, ["uint8_t", "uint16_t", "uint8_t", "uint8_t"]]
    if str(got.folder) not in sys.path:
        sys.path.insert(0, str(got.folder))
    import importlib

    package = importlib.import_module("robolab")
    package.__ttctl_cached__ = True
    return Bindings(package)


def test_plugins_are_checked_against_the_end_dialect(robolab: Any) -> None:
    from ttctl.ends.plugins import Dispatcher, Plugin, PluginError, handles

    b = robolab

    class ByClass(Plugin):
        @handles(b.KrMotorControl)
        def on(self, msg: Any, ctx: Any) -> None:
            pass

    class ByName(Plugin):
        @handles("KR_MOTOR_STATUS", "TT_LOG")
        def on(self, msg: Any, ctx: Any) -> None:
            pass

    d = Dispatcher(dialect=b)
    d.add(ByClass())
    d.add(ByName())
    assert len(d.handlers_for(51000)) == 1 and len(d.handlers_for(51001)) == 1 and len(d.handlers_for(50008)) == 1
    with pytest.raises(PluginError, match=r"KR_MOTOR_CONTROL \(id 51000\) is not in the dialect this end speaks "
                                          r"\(ttapi\): start it with --dialect"):
        Dispatcher(dialect=shipped()).add(ByClass())
    with pytest.raises(PluginError, match="no message KR_MOTOR_STATUS"):
        Dispatcher(dialect=shipped()).add(ByName())


def test_context_refuses_to_send_what_the_link_cannot_carry(robolab: Any) -> None:
    from ttctl.ends.plugins import Context

    b = robolab
    sent: list[Any] = []
    ctx = Context(send=lambda m, urgent=False: sent.append(m), dialect=shipped())
    with pytest.raises(ValueError, match=r"KR_MOTOR_STATUS .* is not in the dialect this end speaks"):
        ctx.send(b.KrMotorStatus(seq=1))
    ctx.send(b.TtLog(text="fine: every dialect on the link has it"))
    assert len(sent) == 1


# -- the tablet's messages from text --------------------------------------------------------------

def test_messages_from_text_every_field_checked(robolab: Any) -> None:
    from ttctl.ends.tablet.usermsg import MessageError, build

    b = robolab
    m = build(b, "KR_MOTOR_CONTROL seq=0x10 dir=FORWARD speed=40", (1, 240))
    assert (m.target_system, m.seq, m.dir, m.speed) == (1, 16, 1, 40)
    assert build(b, "KrMotorControl dir=KR_VEHICLE_DIR_BACKWARD", (7, 240)).dir == 2
    s = build(b, "KR_MOTOR_STATUS rpm=nan note='two words'", (1, 240))
    assert s.note == "two words" and s.rpm != s.rpm
    a = build(b, "TT_ACTION_COMMAND param=[1,2.5,-3,4] argument=m.yaml action=HOVER", (1, 240))
    assert list(a.param) == [1.0, 2.5, -3.0, 4.0] and a.action == 3 and a.argument == "m.yaml"
    f = build(b, 'TT_FILE_REQUEST name="abc" name_length=3', (1, 240))
    assert f.name[:4] == b"abc\0"
    bad = {
        "KR_MOTOR_CONTROL speed=256": "KR_MOTOR_CONTROL.speed: 256 is outside uint8_t's 0..255",
        "KR_MOTOR_CONTROL speed=-1": "outside uint8_t's 0..255",
        "KR_MOTOR_CONTROL speed=1.5": "'1.5' is not an integer (uint8_t)",
        "KR_MOTOR_CONTROL dir=LEFT": "'LEFT' is not an entry of KR_VEHICLE_DIR (STOP, FORWARD, BACKWARD)",
        "KR_MOTOR_CONTROL sped=3": "has no field 'sped' (did you mean speed?",
        "KR_MOTOR_CONTROL speed=3 speed=4": "given twice",
        "KR_MOTOR_CONTROL speed": "'speed' is not field=value",
        "KR_MOTOR_STATUS note=seventeen_bytes!!": "17 bytes do not fit char[16]",
        "KR_MOTOR_STATUS rpm=1e39": "does not fit a float",
        "TT_ACTION_COMMAND param=[1,2,3]": "wants 4 values (float[4]), got 3",
        "KR_MOTOR_CONTROLL": "no message KR_MOTOR_CONTROLL (did you mean KR_MOTOR_CONTROL?)",
        "KR_MOTOR_CONTROL seq='7": "cannot read",
    }
    for text, words in bad.items():
        with pytest.raises(MessageError) as e:
            build(b, text, (1, 240))
        assert words in str(e.value), (text, str(e.value))


def test_conditions_on_the_latest_message(robolab: Any) -> None:
    from ttctl.ends.tablet.steps import StepError, check_condition, check_step, holds

    b = robolab
    parts = check_condition("KR_MOTOR_STATUS.seq == 7 and KR_MOTOR_STATUS.dir != STOP and altitude >= 0", b)
    fields = {"altitude": 1.0}
    assert not holds(parts, fields, {})  # nothing heard yet: false, not an error
    assert holds(parts, fields, {"KR_MOTOR_STATUS": b.KrMotorStatus(seq=7, dir=1)})
    assert not holds(parts, fields, {"KR_MOTOR_STATUS": b.KrMotorStatus(seq=7, dir=0)})
    assert holds(check_condition("KR_MOTOR_STATUS.note == ok", b), {}, {"KR_MOTOR_STATUS": b.KrMotorStatus(note="ok")})
    assert holds(check_condition("TT_ODOMETRY.position[2] < -1.5", b), {},
                 {"TT_ODOMETRY": b.TtOdometry(position=[0, 0, -2.0])})
    for text, words in (("KR_MOTOR_STATUS.sped == 1", "has no field 'sped'"),
                        ("KR_MOTOR_STATUZ.seq == 1", "no message KR_MOTOR_STATUZ"),
                        ("KR_MOTOR_STATUS.dir == LEFT", "not an entry of KR_VEHICLE_DIR"),
                        ("KR_MOTOR_STATUS.note > a", "compare it with == or !="),
                        ("TT_ODOMETRY.position == 1", "is an array"),
                        ("TT_ODOMETRY.position[3] == 1", "position[3]: position is float[3]")):
        with pytest.raises(StepError, match="cannot read condition") as e:
            check_condition(text, b)
        assert words in str(e.value), text
    with pytest.raises(StepError, match="no message KR_NOPE"):
        check_step("msg", "KR_NOPE seq=1", "", b)
    # without until: sent once, as the README says (it was refused)
    assert check_step("msg", {"send": "KR_MOTOR_CONTROL"}, "", b).describe() == "msg KR_MOTOR_CONTROL"
    with pytest.raises(StepError, match="timeout go with until"):
        check_step("msg", {"send": "KR_MOTOR_CONTROL", "timeout": 5}, "", b)
    with pytest.raises(StepError, match="msg wants"):
        check_step("msg", {"until": "KR_MOTOR_STATUS.seq == 3"}, "", b)
    step = check_step("msg", {"send": "KR_MOTOR_CONTROL seq=3", "until": "KR_MOTOR_STATUS.seq == 3", "every": 0.5},
                      "", b)
    assert step.describe() == "msg KR_MOTOR_CONTROL seq=3 until KR_MOTOR_STATUS.seq == 3"


def test_prompt_completion_knows_the_dialect(robolab: Any) -> None:
    from ttctl.commands.tablet import completions

    b = robolab
    assert "msg" in completions(b, "m", "m")
    assert completions(b, "msg KR_MOTOR_C", "KR_MOTOR_C") == ["KR_MOTOR_CONTROL"]
    assert completions(b, "msg KR_MOTOR_CONTROL sp", "sp") == ["speed="]
    assert completions(b, "wait until KR_MOTOR_STATUS.s", "KR_MOTOR_STATUS.s") == ["KR_MOTOR_STATUS.seq",
                                                                                     "KR_MOTOR_STATUS.speed"]
    assert "altitude" in completions(b, "wait until a", "a")


# -- frames of messages the dialect lacks -------------------------------------------------------------

def test_unknown_messages_are_counted_and_told_once_without_changing_decisions(robolab: Any) -> None:
    from ttctl.proto.endpoint import Endpoint
    from ttctl.wire.packets import PacketReceiver, packetize

    b = robolab
    enc = b.encoder(255, 190)
    frames = [enc.encode(b.KrMotorControl(target_system=1, seq=i, speed=5)) for i in range(3)]
    frames.insert(1, enc.encode(b.TtLog(text="known")))
    packets = packetize(frames)
    rx = PacketReceiver(shipped(), on_unknown=lambda *a: heard.append(a))
    heard: list[tuple[int, int, int]] = []
    got = [m for p in packets for m in rx.feed(p)]
    assert [m.NAME for m in got] == ["TT_LOG"]
    assert rx.stats.unknown == 3 and heard == [(51000, 255, 190)] * 3
    # the same packets through a receiver that knows them: nothing unknown
    rx2 = PacketReceiver(b)
    assert [m.NAME for p in packets for m in rx2.feed(p)] == ["KR_MOTOR_CONTROL", "TT_LOG", "KR_MOTOR_CONTROL",
                                                             "KR_MOTOR_CONTROL"]
    assert rx2.stats.unknown == 0
    events: list[tuple[str, Any]] = []
    ep = Endpoint(shipped(), 1, 240, on_event=lambda what, obj: events.append((what, obj)))
    for p in packets * 2:
        ep.receive(0.0, p, ("127.0.0.1", 5))
    assert ep.unknown == 6
    assert [e for e in events if e[0] == "unknown-message"] == [("unknown-message", (("127.0.0.1", 5), 51000,
                                                                                      (255, 190)))]
