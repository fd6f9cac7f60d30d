"""`ttctl gen` as a real process: what it writes, what it keeps, --check, errors; and the
generated Python package: type-checked, linted, loadable as a plugin."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import ROOT, TTAPI, assert_no_traceback, pymavlink_dialects, run_ttctl


def gen(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    return run_ttctl("gen", *args, cwd=cwd, timeout=600)


@pytest.fixture(scope="module")
def py_out(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("gen_py")
    proc = gen(str(TTAPI), "--lang", "python", "-o", str(out))
    assert proc.returncode == 0, proc.stderr
    return out


def test_check_then_write_then_clean(tmp_path: Path) -> None:
    out = tmp_path / "out"
    first = gen(str(TTAPI), "--lang", "python", "-o", str(out), "--check")
    assert first.returncode == 1 and not out.exists()
    assert "out of date" in first.stdout
    assert gen(str(TTAPI), "--lang", "python", "-o", str(out)).returncode == 0
    again = gen(str(TTAPI), "--lang", "python", "-o", str(out), "--check")
    assert again.returncode == 0, again.stdout
    assert "up to date" in again.stdout


def test_only_changed_files_are_written(tmp_path: Path) -> None:
    out = tmp_path / "out"
    assert gen(str(TTAPI), "--lang", "python", "-o", str(out)).returncode == 0
    enums = out / "python" / "ttapi" / "enums.py"
    messages = out / "python" / "ttapi" / "messages.py"
    os.utime(messages, (1, 1))
    enums.write_text(enums.read_text() + "# tampered\n")
    proc = gen(str(TTAPI), "--lang", "python", "-o", str(out))
    assert "1 written" in proc.stdout
    assert messages.stat().st_mtime == 1  # untouched
    assert "tampered" not in enums.read_text()


def test_skeletons_are_kept_unless_forced(tmp_path: Path) -> None:
    out = tmp_path / "out"
    assert gen(str(TTAPI), "--lang", "python", "-o", str(out)).returncode == 0
    skel = out / "python" / "handlers" / "ttapi_onboard.py"
    skel.write_text(skel.read_text() + "# my code\n")
    proc = gen(str(TTAPI), "--lang", "python", "-o", str(out))
    assert "skeletons kept" in proc.stdout and skel.read_text().endswith("# my code\n")
    assert gen(str(TTAPI), "--lang", "python", "-o", str(out), "--check").returncode == 0
    skel.unlink()
    assert gen(str(TTAPI), "--lang", "python", "-o", str(out), "--check").returncode == 1
    assert gen(str(TTAPI), "--lang", "python", "-o", str(out)).returncode == 0 and skel.exists()
    skel.write_text("# my code\n")
    assert gen(str(TTAPI), "--lang", "python", "-o", str(out), "--force-skeletons").returncode == 0
    assert "class TtapiOnboard" in skel.read_text()


def test_stale_generated_files_are_flagged_and_removed(tmp_path: Path) -> None:
    out = tmp_path / "out"
    assert gen(str(TTAPI), "--lang", "python", "-o", str(out)).returncode == 0
    stale = out / "python" / "ttapi" / "old_module.py"
    stale.write_text("x = 1\n")
    check = gen(str(TTAPI), "--lang", "python", "-o", str(out), "--check")
    assert check.returncode == 1 and "old_module.py" in check.stdout
    assert gen(str(TTAPI), "--lang", "python", "-o", str(out)).returncode == 0
    assert not stale.exists()


def test_invalid_dialect_prints_diagnostics_and_writes_nothing(tmp_path: Path) -> None:
    out = tmp_path / "out"
    proc = gen(str(ROOT / "tests" / "dialects" / "broken" / "duplicates.xml"), "-o", str(out))
    assert proc.returncode == 1
    assert_no_traceback(proc)
    assert "[DUP-MSG-ID]" in proc.stderr and "nothing generated" in proc.stderr
    assert not any(out.rglob("*.py"))


@pytest.mark.parametrize("kind", ["file", "unwritable", "lang", "templates"])
def test_bad_options_exit_2_with_one_line(tmp_path: Path, kind: str) -> None:
    if kind == "file":
        target = tmp_path / "afile"
        target.write_text("x")
        args = ["-o", str(target)]
    elif kind == "unwritable":
        args = ["-o", "/proc/ttctl-cannot-exist/out"]
    elif kind == "lang":
        args = ["--lang", "python,rust", "-o", str(tmp_path)]
    else:
        args = ["--templates", str(tmp_path / "missing"), "-o", str(tmp_path)]
    proc = gen(str(TTAPI), *args)
    assert proc.returncode == 2
    assert_no_traceback(proc)
    lines = (proc.stdout + proc.stderr).strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("ttctl: error:"), lines


def test_user_templates_override_by_name(tmp_path: Path) -> None:
    mine = tmp_path / "tpl" / "python"
    mine.mkdir(parents=True)
    original = (ROOT / "templates" / "python" / "enums.py.j2").read_text()
    (mine / "enums.py.j2").write_text("# custom enums template\n" + original)
    out = tmp_path / "out"
    proc = gen(str(TTAPI), "--lang", "python", "-o", str(out), "--templates", str(tmp_path / "tpl"))
    assert proc.returncode == 0, proc.stderr
    assert (out / "python" / "ttapi" / "enums.py").read_text().startswith("# custom enums template")
    assert not (out / "python" / "ttapi" / "messages.py").read_text().startswith("# custom")


def test_compiled_template_cache_follows_the_source(tmp_path: Path) -> None:
    """Compiled templates are cached between runs; editing a template (same name, same path)
    takes effect at once, and an unusable cache folder costs only time."""
    mine = tmp_path / "tpl" / "python"
    mine.mkdir(parents=True)
    original = (ROOT / "templates" / "python" / "enums.py.j2").read_text()
    cache = tmp_path / "cache"
    out = tmp_path / "out"
    enums = out / "python" / "ttapi" / "enums.py"
    for marker in ("# first\n", "# second\n"):
        (mine / "enums.py.j2").write_text(marker + original)
        proc = run_ttctl("gen", str(TTAPI), "--lang", "python", "-o", str(out), "--templates", str(tmp_path / "tpl"),
                         env={"XDG_CACHE_HOME": str(cache)})
        assert proc.returncode == 0, proc.stderr
        assert enums.read_text().startswith(marker)
    assert list((cache / "ttctl" / "templates").glob("*.cache"))
    not_a_folder = tmp_path / "file"
    not_a_folder.write_text("x")
    proc = run_ttctl("gen", str(TTAPI), "--lang", "python", "-o", str(tmp_path / "out2"),
                     env={"XDG_CACHE_HOME": str(not_a_folder)})
    assert proc.returncode == 0, proc.stderr
    assert (tmp_path / "out2" / "python" / "ttapi" / "enums.py").read_text() == (
        ROOT / "generated" / "python" / "ttapi" / "enums.py").read_text()


def test_broken_user_template_is_one_line_error(tmp_path: Path) -> None:
    mine = tmp_path / "tpl" / "python"
    mine.mkdir(parents=True)
    (mine / "enums.py.j2").write_text("{{ no_such_variable }}\n")
    proc = gen(str(TTAPI), "--lang", "python", "-o", str(tmp_path / "out"), "--templates", str(tmp_path / "tpl"))
    assert proc.returncode == 2 and "no_such_variable" in proc.stderr
    assert_no_traceback(proc)


def test_default_arguments_work_from_the_repository_root() -> None:
    proc = gen("--check", cwd=ROOT)
    assert proc.returncode == 0, proc.stdout


def test_golden_generated_tree_is_current(tmp_path: Path) -> None:
    """generated/ is exactly what the templates make of dialects/ttapi.xml."""
    out = tmp_path / "golden"
    assert gen(str(TTAPI), "-o", str(out)).returncode == 0
    want = {p.relative_to(out).as_posix(): p.read_bytes() for p in out.rglob("*") if p.is_file()}
    repo = ROOT / "generated"
    have = {p.relative_to(repo).as_posix(): p.read_bytes() for p in repo.rglob("*")
            if p.is_file() and "__pycache__" not in p.parts}
    assert sorted(have) == sorted(want)
    differ = [k for k in want if have[k] != want[k]]
    assert differ == []


@pytest.mark.parametrize("dialect", ["ttapi", "common"])
def test_generated_python_passes_mypy_strict_and_ruff(tmp_path: Path, dialect: str) -> None:
    xml = TTAPI if dialect == "ttapi" else pymavlink_dialects() / "common.xml"
    out = tmp_path / "out"
    assert gen(str(xml), "--lang", "python", "-o", str(out)).returncode == 0
    pkg = out / "python"
    bindir = Path(sys.executable).parent
    for rules in ([], ["--select", "E4,E7,E9,F"]):
        ruff = subprocess.run([str(bindir / "ruff"), "check", "--no-cache", "--isolated", *rules, "."], cwd=pkg,
                              capture_output=True, text=True, timeout=300)
        assert ruff.returncode == 0, ruff.stdout[-3000:]
    mypy = subprocess.run([str(bindir / "mypy"), "--strict", "--no-incremental", dialect, "conformance.py",
                           f"handlers/{dialect}_onboard.py"], cwd=pkg, capture_output=True, text=True, timeout=600)
    assert mypy.returncode == 0, mypy.stdout[-3000:]


def test_handler_skeleton_loads_into_the_plugin_system(py_out: Path) -> None:
    from ttctl.ends.plugins import Context, Dispatcher, load_plugins

    plugins = load_plugins([py_out / "python" / "handlers" / "ttapi_onboard.py"])
    assert [type(p).__name__ for p in plugins] == ["TtapiOnboard"]
    disp = Dispatcher()
    disp.add(plugins[0])
    import importlib

    ttapi = importlib.import_module("ttapi")
    bound = {mid for mid in (m.MSG_ID for m in ttapi.ALL) if disp.handlers_for(mid)}
    # the file-transfer messages are tagged [runtime]: ttctl handles them, so no stubs for them
    assert bound == {ttapi.TtActionCommand.MSG_ID, ttapi.DjiPoseStamped.MSG_ID, ttapi.TtLog.MSG_ID,
                     ttapi.TtVrPose.MSG_ID, ttapi.TtVrController.MSG_ID}
    ctx = Context()
    assert disp.dispatch(ttapi.TtActionCommand(action=ttapi.TtAction.TT_ACTION_LAND), ctx) == 1
    assert "TT_ACTION_COMMAND" in ctx.logged[0] and "not handled yet" in ctx.logged[0]


def test_plugin_loader_errors_are_one_line(tmp_path: Path) -> None:
    from ttctl.ends.plugins import PluginError, load_plugins

    bad = tmp_path / "bad.py"
    bad.write_text("import no_such_module_anywhere\n")
    with pytest.raises(PluginError, match="ModuleNotFoundError"):
        load_plugins([bad])
    with pytest.raises(PluginError, match="no such plugin file"):
        load_plugins([tmp_path / "missing.py"])
    empty = tmp_path / "empty.py"
    empty.write_text("x = 1\n")
    with pytest.raises(PluginError, match="no Plugin subclass"):
        load_plugins([empty])


def test_dispatcher_runs_every_handler_even_if_one_raises() -> None:
    from ttctl.ends.plugins import Context, Dispatcher

    seen: list[str] = []

    class Msg:
        MSG_ID = 7

    def bad(msg: object, ctx: Context) -> None:
        raise RuntimeError("boom")

    errors: list[BaseException] = []
    disp = Dispatcher(on_error=lambda m, e, where: errors.append(e))
    disp.bind(7, lambda m, c: seen.append("a"))
    disp.bind(7, bad)
    disp.bind(7, lambda m, c: seen.append("b"))
    assert disp.dispatch(Msg(), Context()) == 3
    assert seen == ["a", "b"] and len(errors) == 1 and disp.errors == 1


def test_wheel_ships_templates_dialects_and_the_generated_package(tmp_path: Path) -> None:
    proc = subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-deps", "--no-build-isolation", "-q", "-w",
                           str(tmp_path), str(ROOT)], capture_output=True, text=True, timeout=600)
    if proc.returncode != 0 and "No module named 'hatchling'" in proc.stderr:
        proc = subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-deps", "-q", "-w", str(tmp_path),
                               str(ROOT)], capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-2000:]
    import zipfile

    wheel = next(tmp_path.glob("ttctl-*.whl"))
    names = set(zipfile.ZipFile(wheel).namelist())
    assert "ttctl/_data/dialects/ttapi.xml" in names
    assert "ttctl/_data/templates/python/messages.py.j2" in names
    assert "ttapi/messages.py" in names and "ttapi/py.typed" in names
    shutil.rmtree(tmp_path)
