"""`ttctl gen --python-package / --cpp-namespace / --java-package`: generated code placed in the
user's own package or namespace builds, runs and speaks the same bytes as the default; bad
names are refused in one line before anything is written."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import TTAPI, assert_no_traceback, run_ttctl
from ttctl.codegen.lang_cpp import NODE_HEADERS, RUNTIME_HEADERS, SDK_HEADERS, TRANSFER_HEADERS

WARN = ["-std=c++17", "-Wall", "-Wextra", "-Wpedantic", "-Werror"]
# TT_COMMAND_ACK as the README's conformance example encodes it (seq 7, from 1/240)
ACK_FIELDS = {"target_system": 255, "target_component": 190, "command_id": 42, "action": 1, "result": 2,
              "progress": 100}
ACK_JSON = ('{"name":"TT_COMMAND_ACK","sysid":1,"compid":240,"seq":7,"fields":{"target_system":255,'
            '"target_component":190,"command_id":42,"action":1,"result":2,"progress":100}}')
ACK_HEX = "fd0700000701f05ac3002a00ffbe01026407e7"


def gen(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    return run_ttctl("gen", *args, cwd=cwd, timeout=600)


def gen_ok(out: Path, *args: str) -> Path:
    proc = gen(str(TTAPI), "-o", str(out), *args)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    return out


def tree(root: Path) -> dict[str, bytes]:
    return {p.relative_to(root).as_posix(): p.read_bytes() for p in root.rglob("*")
            if p.is_file() and "__pycache__" not in p.parts}


# --- option checking ----------------------------------------------------------------------

BAD = [
    ("--java-package", "com.example.class"),  # keyword
    ("--java-package", "com.null.drone"),  # literal
    ("--java-package", "com._.drone"),  # `_` is a keyword since Java 9
    ("--java-package", "com..drone"),
    ("--java-package", "com.example."),
    ("--java-package", "com.2fast"),
    ("--java-package", "com-example"),
    ("--java-package", "java.drone"),  # the JDK's
    ("--java-package", "Com.example"),  # would read as a class
    ("--java-package", "m"),  # a variable of the generated Conformance
    ("--cpp-namespace", "class"),
    ("--cpp-namespace", "myco::int"),
    ("--cpp-namespace", "myco:drone"),
    ("--cpp-namespace", "myco::"),
    ("--cpp-namespace", "::myco"),
    ("--cpp-namespace", "my-co"),
    ("--cpp-namespace", "std"),
    ("--cpp-namespace", "myco::std"),  # would hide ::std inside the runtime
    ("--cpp-namespace", "linux"),  # g++ -std=gnu++17 defines it
    ("--cpp-namespace", "_Drone"),
    ("--cpp-namespace", "my__co"),
    ("--cpp-namespace", "mav"),  # the conformance program's alias
    ("--python-package", "class"),
    ("--python-package", "None"),
    ("--python-package", "my.drone"),
    ("--python-package", "2drone"),
    ("--python-package", "my-drone"),
    ("--python-package", "struct"),  # imported by the generated code
    ("--python-package", "json"),
    ("--python-package", "typing"),
    ("--python-package", "ttctl"),  # the handler skeleton imports ttctl.ends.plugins
    ("--python-package", "handlers"),  # the skeleton folder beside the package
    ("--python-package", ""),
]


@pytest.mark.parametrize(("option", "value"), BAD)
def test_bad_names_are_one_line_exit_2_nothing_written(tmp_path: Path, option: str, value: str) -> None:
    out = tmp_path / "out"
    for check in ([], ["--check"]):
        proc = gen(str(TTAPI), "-o", str(out), option, value, *check)
        assert proc.returncode == 2, proc.stdout + proc.stderr
        assert_no_traceback(proc)
        lines = (proc.stdout + proc.stderr).strip().splitlines()
        assert len(lines) == 1 and lines[0].startswith(f"ttctl: error: {option} {value}:"), lines
        assert not out.exists()


def test_bad_name_refused_even_for_a_language_not_generated(tmp_path: Path) -> None:
    proc = gen(str(TTAPI), "--lang", "python", "-o", str(tmp_path / "out"), "--java-package", "a.class")
    assert proc.returncode == 2 and "--java-package a.class" in proc.stderr
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize(("option", "value"), [
    ("--java-package", "drone"), ("--java-package", "com.example.drone"), ("--java-package", "io.my_co.v2"),
    ("--java-package", "org.example.record"), ("--java-package", "com.example.Drone"),
    ("--cpp-namespace", "drone"), ("--cpp-namespace", "myco::drone"), ("--cpp-namespace", "a::b::c_2"),
    ("--cpp-namespace", "Drone"),
    ("--python-package", "mydrone"), ("--python-package", "_drone"), ("--python-package", "Drone2"),
])
def test_good_names_are_accepted(option: str, value: str) -> None:
    from ttctl.gen import cpp_namespace_problem, java_package_problem, python_package_problem

    problem = {"--java-package": java_package_problem, "--cpp-namespace": cpp_namespace_problem,
               "--python-package": python_package_problem}[option]
    assert problem(value) is None


def test_defaults_are_the_dialect_names(tmp_path: Path) -> None:
    """Naming the defaults explicitly writes the very tree the defaults write (so `generated/`
    does not change), and --check agrees both ways."""
    plain = gen_ok(tmp_path / "plain")
    named = gen_ok(tmp_path / "named", "--python-package", "ttapi", "--cpp-namespace", "ttapi",
                   "--java-package", "ttctl.ttapi")
    assert tree(plain) == tree(named)
    proc = gen(str(TTAPI), "-o", str(plain), "--check", "--python-package", "ttapi", "--cpp-namespace", "ttapi",
               "--java-package", "ttctl.ttapi")
    assert proc.returncode == 0 and "up to date" in proc.stdout, proc.stdout + proc.stderr


def test_check_accepts_the_options(tmp_path: Path) -> None:
    opts = ["--python-package", "mydrone", "--cpp-namespace", "myco::drone", "--java-package", "com.example.drone"]
    out = tmp_path / "out"
    first = gen(str(TTAPI), "-o", str(out), "--check", *opts)
    assert first.returncode == 1 and not out.exists()
    assert f"{out}/python/mydrone/messages.py: out of date" in first.stdout
    gen_ok(out, *opts)
    again = gen(str(TTAPI), "-o", str(out), "--check", *opts)
    assert again.returncode == 0 and "up to date" in again.stdout, again.stdout
    default = gen(str(TTAPI), "-o", str(out), "--check")  # the default names: other files
    assert default.returncode == 1 and "python/ttapi/messages.py: out of date" in default.stdout


def test_named_folders_are_owned_and_nothing_beside_them(tmp_path: Path) -> None:
    """Stale files in the named package/namespace folders go, as in the default ones; the user's
    files beside them (the outer namespace's folder, the Java package itself) stay."""
    opts = ["--python-package", "mydrone", "--cpp-namespace", "myco::drone", "--java-package", "com.example.drone"]
    out = gen_ok(tmp_path / "out", *opts)
    stale = [out / "python/mydrone/old.py", out / "cpp/myco/drone/old.hpp", out / "java/com/example/drone/msg/Old.java"]
    mine = [out / "cpp/myco/mine.hpp", out / "java/com/example/drone/Mine.java", out / "python/mine.py"]
    for p in stale + mine:
        p.write_text("// x\n")
    check = gen(str(TTAPI), "-o", str(out), "--check", *opts)
    assert check.returncode == 1
    assert sorted(line.split(":")[0] for line in check.stdout.splitlines() if "out of date" in line) == sorted(
        map(str, stale))
    gen_ok(out, *opts)
    assert not any(p.exists() for p in stale) and all(p.exists() for p in mine)


# --- Java ---------------------------------------------------------------------------------

@pytest.mark.skipif(shutil.which("javac") is None or shutil.which("java") is None, reason="needs a JDK")
def test_java_package_builds_and_runs(tmp_path: Path) -> None:
    out = gen_ok(tmp_path / "out", "--lang", "java", "--java-package", "com.example.drone")
    java = out / "java"
    assert not (java / "ttctl").exists()
    root = java / "com" / "example" / "drone"
    assert (root / "Ttapi.java").is_file()
    for sub in ("runtime", "msg", "enums", "commands"):
        assert any((root / sub).glob("*.java")), sub
    sources = sorted(java.rglob("*.java"))
    for p in sources:
        rel = p.parent.relative_to(java).as_posix()
        declared = re.findall(r"^package ([\w.]+);", p.read_text(), re.M)
        if rel == ".":
            assert declared == [], p  # Conformance: the default package
        else:
            assert declared == [rel.replace("/", ".")], p
            assert rel == "com/example/drone" or rel.startswith("com/example/drone/"), p
    text = "\n".join(p.read_text() for p in sources)
    assert "ttctl.ttapi" not in text
    classes = tmp_path / "classes"
    proc = subprocess.run(["javac", "--release", "11", "-Xlint:all", "-Werror", "-encoding", "UTF-8",
                           "-d", str(classes), *map(str, sources)], capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0 and "warning" not in proc.stderr, proc.stderr[-6000:]
    assert (classes / "com" / "example" / "drone" / "runtime" / "Parser.class").is_file()
    run = subprocess.run(["java", "-cp", str(classes), "Conformance"], input=f"E {ACK_JSON}\nD {ACK_HEX}\n",
                         capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    lines = run.stdout.splitlines()
    assert lines[0] == ACK_HEX and '"command_id":42' in lines[1], lines


# --- C++ ----------------------------------------------------------------------------------

CPP_MAIN = r"""#include <cstdint>
#include <cstdio>

#include "myco/drone/ttapi.hpp"
#include "myco/drone/udp_forward.hpp"  // compiles in the namespace too
#include "myco/drone/udp_link.hpp"
#include "onboard/ttapi_plugin.hpp"

namespace {

namespace drone = myco::drone;

}  // namespace

int main()
{
    drone::TtCommandAck ack;
    ack.target_system = 255;
    ack.target_component = 190;
    ack.command_id = 42;
    ack.action = 1;
    ack.result = 2;
    ack.progress = 100;
    std::uint8_t buf[300];
    const std::size_t n = ack.encode(buf, sizeof buf, 7, 1, 240);
    for (std::size_t i = 0; i < n; ++i) {
        std::printf("%02x", static_cast<unsigned>(buf[i]));
    }
    std::printf("\n");
    drone::link::Node node(drone::link::NodeConfig{});
    drone::onboard::TtapiPlugin plugin;
    drone::link::NodePlugin& base = plugin;
    node.add(base);
    drone::Dispatcher dispatcher;
    int seen = 0;
    dispatcher.on<drone::TtCommandAck>([&seen](const drone::TtCommandAck& m, const drone::Frame&) {
        seen += m.command_id == 42 ? 1 : 0;
    });
    drone::Parser parser;
    parser.feed(buf, n, dispatcher);
    return seen == 1 ? 0 : 1;
}
"""


@pytest.mark.skipif(shutil.which("g++") is None, reason="needs g++")
def test_cpp_namespace_builds_and_runs(tmp_path: Path) -> None:
    out = gen_ok(tmp_path / "out", "--lang", "cpp", "--cpp-namespace", "myco::drone")
    cpp = out / "cpp"
    assert {p.relative_to(cpp).as_posix() for p in cpp.rglob("*") if p.is_file()} == {
        "myco/drone/enums.hpp", "myco/drone/messages.hpp", "myco/drone/ttapi.hpp", "myco/drone/signing.hpp",
        "myco/drone/packets.hpp", "myco/drone/udp_forward.hpp", "myco/drone/sha256.hpp", "myco/drone/scheduler.hpp",
        "myco/drone/commands.hpp", "myco/drone/udp_link.hpp", "myco/drone/pipe_link.hpp", "conformance.cpp",
        "conformance_json.hpp", "conformance_json_reader.hpp", "onboard/ttapi_plugin.hpp",
        *(f"myco/drone/{h}.hpp" for h in (*RUNTIME_HEADERS, *TRANSFER_HEADERS, *NODE_HEADERS, *SDK_HEADERS))}
    for names, ns in (((*RUNTIME_HEADERS, "enums", "messages"), "myco::drone"),
                      (("scheduler", "commands", *TRANSFER_HEADERS, *NODE_HEADERS, *SDK_HEADERS, "udp_link",
                        "pipe_link"),
                       "myco::drone::link")):
        for name in names:
            text = (cpp / "myco" / "drone" / f"{name}.hpp").read_text()
            assert f"#ifndef TTCTL_MYCO_DRONE_{name.upper()}_HPP" in text and "namespace ttapi" not in text
            # runtime.hpp and transfer.hpp only include their pieces
            assert f"namespace {ns} {{" in text or name in ("runtime", "transfer"), name
    assert "namespace myco::drone::onboard {" in (cpp / "onboard" / "ttapi_plugin.hpp").read_text()
    main = tmp_path / "main.cpp"
    main.write_text(CPP_MAIN)
    exe, conf = tmp_path / "main", tmp_path / "conformance"
    jobs = [subprocess.Popen(["g++", *WARN, "-O0", "-I", str(cpp), str(src), "-o", str(dst), "-lz"],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            for src, dst in ((main, exe), (cpp / "conformance.cpp", conf))]
    for job in jobs:
        _, err = job.communicate(timeout=600)
        assert job.returncode == 0, err[-4000:]
    run = subprocess.run([str(exe)], capture_output=True, text=True, timeout=30)
    assert run.returncode == 0 and run.stdout.strip() == ACK_HEX, run.stdout + run.stderr
    run = subprocess.run([str(conf)], input=f"E {ACK_JSON}\n", capture_output=True, text=True, timeout=30)
    assert run.stdout.strip() == ACK_HEX, run.stdout + run.stderr


# --- Python -------------------------------------------------------------------------------

PY_ROUND_TRIP = """
import hashlib, importlib, sys

pkg = importlib.import_module(sys.argv[1])
h = hashlib.sha256()
for i, cls in enumerate(pkg.ALL):
    frame = pkg.encode(cls(), i & 255, 1, 240)
    msg = pkg.decode(frame)
    assert type(msg) is cls and msg.to_dict() == cls().to_dict(), cls
    assert type(msg).__module__ == sys.argv[1] + ".messages"
    h.update(frame)
ack = pkg.BY_NAME["TT_COMMAND_ACK"](**ACK_FIELDS)
print(len(pkg.ALL), h.hexdigest(), pkg.encode(ack, 7, 1, 240).hex())
""".replace("ACK_FIELDS", repr(ACK_FIELDS))


def run_py(python_dir: Path, *args: str, stdin: str | None = None) -> str:
    env = {**os.environ, "PYTHONPATH": str(python_dir)}
    proc = subprocess.run([sys.executable, *args], cwd=python_dir.parent, env=env, input=stdin,
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    return proc.stdout


def test_python_package_imports_and_speaks_the_same_bytes(tmp_path: Path) -> None:
    mine = gen_ok(tmp_path / "mine", "--lang", "python", "--python-package", "mydrone") / "python"
    plain = gen_ok(tmp_path / "plain", "--lang", "python") / "python"
    assert sorted(p.relative_to(mine).as_posix() for p in mine.rglob("*") if p.is_file()) == [
        "conformance.py", "handlers/mydrone_onboard.py", "mydrone/__init__.py", "mydrone/enums.py",
        "mydrone/mavlink.py", "mydrone/messages.py", "mydrone/py.typed"]
    for p in (mine / "mydrone").glob("*.py"):
        assert not re.search(r"^\s*(from|import) ttapi\b", p.read_text(), re.M), p
    ours = run_py(mine, "-c", PY_ROUND_TRIP, "mydrone")
    assert ours == run_py(plain, "-c", PY_ROUND_TRIP, "ttapi")
    assert ours.split()[-1] == ACK_HEX
    assert run_py(mine, str(mine / "conformance.py"), stdin=f"E {ACK_JSON}\n").strip() == ACK_HEX
    load = ("from ttctl.ends.plugins import load_plugins\n"
            f"print(*[type(p).__name__ for p in load_plugins([{str(mine / 'handlers' / 'mydrone_onboard.py')!r}])])")
    assert run_py(mine, "-c", load).strip() == "TtapiOnboard"


def test_python_package_passes_mypy_strict_and_ruff(tmp_path: Path) -> None:
    pkg = gen_ok(tmp_path / "out", "--lang", "python", "--python-package", "mydrone") / "python"
    bindir = Path(sys.executable).parent
    ruff = subprocess.run([str(bindir / "ruff"), "check", "--no-cache", "--isolated", "."], cwd=pkg,
                          capture_output=True, text=True, timeout=300)
    assert ruff.returncode == 0, ruff.stdout[-3000:]
    mypy = subprocess.run([str(bindir / "mypy"), "--strict", "--no-incremental", "mydrone", "conformance.py",
                           "handlers/mydrone_onboard.py"], cwd=pkg, capture_output=True, text=True, timeout=600)
    assert mypy.returncode == 0, mypy.stdout[-3000:]
