"""The README's quick start stays true (CI runs its test command verbatim), and the manual (README.md and
the docs site's pages: conftest.manual()) says what the commands do and print."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import ROOT, manual


def quick_start_commands() -> list[str]:
    text = (ROOT / "README.md").read_text()
    section = text.split("## Quick start", 1)[1].split("\n## ", 1)[0]
    return re.findall(r"```sh\n(.+?)\n```", section, re.S)


def test_quick_start_has_two_commands() -> None:
    cmds = quick_start_commands()
    assert len(cmds) == 2, cmds
    assert "pip install ." in cmds[0] and "ttctl" in cmds[0]
    assert "pytest" in cmds[1]


def test_ci_runs_the_readme_test_command() -> None:
    ci = (ROOT / ".ci" / "run").read_text()
    assert quick_start_commands()[1] in ci.splitlines()


def test_readme_tours_every_subcommand() -> None:
    from typer.main import get_command

    from ttctl.app import app

    text = manual()
    group = get_command(app)
    names: list[str] = []
    for name, cmd in group.commands.items():  # type: ignore[attr-defined]
        sub = getattr(cmd, "commands", None)
        names += [f"ttctl {name} {s}" for s in sub] if sub else [f"ttctl {name}"]
    for name in names:
        assert f"### `{name}" in text, f"the manual has no tour section for {name}"


def console_examples(heading: str) -> list[tuple[str, list[str]]]:
    """(command, expected output lines) of every `$ ttctl ...` in the console blocks of the tour
    section whose heading starts with `heading`; `...` in the expected output stands for any
    number of lines."""
    text = manual()
    section = text.split(f"### `{heading}", 1)[1].split("\n### ", 1)[0]
    out: list[tuple[str, list[str]]] = []
    for block in re.findall(r"```console\n(.+?)```", section, re.S):
        for chunk in re.split(r"^\$ ", block, flags=re.M)[1:]:
            cmd, _, rest = chunk.partition("\n")
            out.append((cmd, [line for line in rest.rstrip("\n").split("\n") if line != ""]))
    return out


def matches(expected: list[str], got: list[str]) -> bool:
    if not expected:
        return not got
    if expected[0].strip() == "...":
        return any(matches(expected[1:], got[i:]) for i in range(len(got) + 1))
    return bool(got) and got[0] == expected[0] and matches(expected[1:], got[1:])


@pytest.mark.parametrize(("heading", "columns", "least"),
                         [("ttctl validate", 200, 3), ("ttctl gen", 200, 3), ("ttctl bench link", 80, 1)])
def test_readme_examples_are_what_the_commands_print(heading: str, columns: int, least: int, tmp_path: Path) -> None:
    """Each example runs as shown (from a folder where `dialects/` and `tests/` are the
    repository's, and `docs/` takes plots) and prints what the manual says it prints: the
    tours of validate and gen, and bench link's (virtual time: the same every run), as a
    terminal `columns` wide shows it."""
    if heading == "ttctl bench link":
        pytest.importorskip("matplotlib")
    (tmp_path / "dialects").symlink_to(ROOT / "dialects")
    (tmp_path / "tests").symlink_to(ROOT / "tests")
    (tmp_path / "docs").mkdir()
    examples = [(c, e) for c, e in console_examples(heading) if "ttctl " in c and "conformance" not in c]
    assert len(examples) >= least, examples
    env = {**os.environ, "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}",
           "COLUMNS": str(columns)}
    for cmd, expected in examples:
        proc = subprocess.run(cmd, shell=True, cwd=tmp_path, capture_output=True, text=True, env=env, timeout=300)
        got = [line.rstrip() for line in (proc.stdout + proc.stderr).rstrip("\n").split("\n") if line.strip()]
        assert matches(expected, got), f"$ {cmd}\nthe manual:\n" + "\n".join(expected) + "\nprints:\n" + "\n".join(got)


def _options(cmd: object) -> dict[str, str]:
    """Every spelling of every option of a click command -> the option's name."""
    out = {}
    for p in getattr(cmd, "params", []):
        if getattr(p, "param_type_name", "") == "option":
            for o in [*p.opts, *p.secondary_opts]:
                out[o] = p.name
    return out


# tours whose heading is the command's full synopsis: every option it has, in brackets
FULL_SYNOPSIS = ["ttctl validate", "ttctl gen", "ttctl bench validate", "ttctl bench gen", "ttctl bench transfer",
                 "ttctl bench link", "ttctl send-file", "ttctl recv-file", "ttctl link relay", "ttctl emulate onboard",
                 "ttctl emulate tablet", "ttctl hmd dump", "ttctl bench latency"]


def test_synopses_are_the_commands_options() -> None:
    """A heading names only options the command has; the full synopses name all of them."""
    from typer.main import get_command

    from ttctl.app import app

    text = manual()
    group = get_command(app)
    checked = []
    for name, cmd in group.commands.items():  # type: ignore[attr-defined]
        subs = getattr(cmd, "commands", None)
        for full, c in ([(f"ttctl {name} {s}", sc) for s, sc in subs.items()] if subs else [(f"ttctl {name}", cmd)]):
            m = re.search(r"^### `" + re.escape(full) + r"(?: ([^`]*))?`", text, re.M)
            if m is None:
                continue  # test_readme_tours_every_subcommand says so
            listed = set(re.findall(r"(?<![\w-])(--?[A-Za-z][\w-]*)", m.group(1) or ""))
            real = _options(c)
            assert listed <= set(real), f"{full}: the manual names {sorted(listed - set(real))}, which it lacks"
            if full in FULL_SYNOPSIS:
                missing = {n for o, n in real.items() if n != "help"} - {real[o] for o in listed}
                assert not missing, f"{full}: the manual's synopsis lacks {sorted(missing)}"
                checked.append(full)
    assert sorted(checked) == sorted(FULL_SYNOPSIS)


def test_calibration_table_is_what_bench_link_computes() -> None:
    """The manual's m100-against-the-thesis table quotes `ttctl bench link`'s own numbers."""
    from ttctl.bench import linkbench
    from ttctl.link.model import load_profile

    text = manual()
    table = text[text.index("**Calibration: the m100 model against the thesis.**"):]
    table = table[:table.index("\n\n", table.index("|---|"))]
    rep = linkbench.measure(load_profile("m100"))
    facts = {f["fact"]: f["value"] for f in rep["facts"]}
    facts |= {f["fact"].split(" (")[0]: f["value"] for f in rep["facts"] if f["fact"].split(" (")[0]
              not in {g["fact"].split(" (")[0] for g in rep["facts"] if g is not f}}  # the unambiguous short names
    up = {(r["distance_m"], r["size"]): r for r in rep["uplink"]["rows"]}
    near, far = up[(10.0, 100)]["throughput_Bps"], up[(200.0, 100)]["throughput_Bps"]
    expected = [
        f"{max(r['throughput_Bps'] for r in rep['uplink']['rows']):.0f} B/s, "
        f"{facts['uplink: at best about half the advertised rate']:.2f} of it",
        f"{near:.0f} to {far:.0f} B/s ({near / far:.1f}x)",
        f"{facts['uplink: very few of 100 lost up to 150 m']['mean']} of 100 on average, at most "
        f"{facts['uplink: very few of 100 lost up to 150 m']['max']}",
        f"{facts['uplink: reliability plummets at 200 m']} of 100 on average",
        f"{facts['downlink: about a third lost at 100 Hz with 100-byte packets (10 m)']} of 100 at 10 m, "
        f"{facts['downlink: about a third lost at 100 Hz with 100-byte packets (200 m)']} at 200 m",
        f"within {facts['downlink: distance hardly matters']['throughput_rel_diff_max'] * 100:.1f} %, loss within "
        f"{facts['downlink: distance hardly matters']['lost_diff_max']} packets",
    ]
    for e in expected:
        assert e in table, (e, table)
    assert all(f["ok"] for f in rep["facts"])


# -- drift between the manual (README.md and docs/), the help and the code (issue 20) ---------------------------------

README = ROOT / "README.md"


def _console_blocks() -> list[str]:
    return re.findall(r"```console\n(.+?)```", manual(), re.S)


def test_runtime_dependencies_are_pyprojects() -> None:
    import tomllib

    deps = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["dependencies"]
    names = {re.split(r"[<>=!~ ;\[]", d, maxsplit=1)[0].lower() for d in deps}
    m = re.search(r"Runtime dependencies: ([^.]+)\.", README.read_text())
    assert m, "the README names its runtime dependencies"
    assert {n.strip().lower() for n in m.group(1).split(",")} == names


def test_example_files_the_readme_shows_or_runs_are_in_the_repository() -> None:
    """A ```python block that starts `# PATH` is the file PATH, byte for byte; every `python
    PATH.py` a console block runs exists (outputs of `ttctl gen -o out` aside)."""
    text = manual()
    shown = re.findall(r"```python\n# ([\w./-]+\.py)\n(.*?)```", text, re.S)
    assert shown, "the manual shows example files by path"
    for path, body in shown:
        assert (ROOT / path).is_file(), f"the manual shows {path}, which is not in the repository"
        assert (ROOT / path).read_text() == f"# {path}\n{body}", f"{path} differs from the manual's copy"
    for block in _console_blocks():
        for path in re.findall(r"^\$ python3? ([\w./-]+\.py)", block, re.M):
            if not path.startswith(("out/", "OUT/")):
                assert (ROOT / path).is_file(), f"the manual runs {path}, which is not in the repository"


def test_programs_the_readme_runs_are_built_under_that_name() -> None:
    text = manual()
    for prog in set(re.findall(r"\| \./([\w-]+)", text)):
        assert re.search(rf"(?:g\+\+|javac)[^`\n]*-o {re.escape(prog)}\b", text), \
            f"the manual runs ./{prog} but no compile command it shows writes it (-o {prog})"


def _endpoint_parses() -> list[tuple[str, str, str]]:
    """(file, option variable, what a bare udp: means) of every endpoint the commands parse."""
    out = []
    for path in (ROOT / "cli" / "ttctl").rglob("*.py"):
        for var, udp in re.findall(r"parse_(?:endpoint|spec)\((?:\w+\.)?(\w+)(?: or \"\")?,\s*(?:udp=)?\"(udp\w+)\"",
                                   path.read_text()):
            out.append((path.name, var, udp))
    return out


def test_udp_means_what_the_readme_says_it_means() -> None:
    """The manual's rule (`--listen` listens, `--to`/`--from`/`--gcs` send) is what each command
    does with a bare `udp:`, and what its --help says."""
    text = manual()
    assert "`--listen` listens (`udpin`" in text and "`--to`, `--from` and `--gcs` send\n(`udpout`)" in text
    assert "mavutil and MAVProxy read `udp:HOST:PORT`\nas *listen*" in text
    parses = _endpoint_parses()
    assert len(parses) >= 8, parses
    for file, var, udp in parses:
        assert udp == ("udpin" if var == "listen" else "udpout"), (file, var, udp)
    for path, cmd in _all_commands():
        for p in getattr(cmd, "params", []):
            said = re.search(r"udp: means (udp\w+)", getattr(p, "help", None) or "")
            if said:
                assert said.group(1) == ("udpin" if "--listen" in p.opts else "udpout"), (path, p.opts)


def _all_commands() -> list[tuple[str, object]]:
    from typer.main import get_command

    from ttctl.app import app

    out = []
    for name, cmd in get_command(app).commands.items():  # type: ignore[attr-defined]
        subs = getattr(cmd, "commands", None)
        out += [(f"ttctl {name} {s}", c) for s, c in subs.items()] if subs else [(f"ttctl {name}", cmd)]
    return out


def test_example_outputs_show_the_defaults_the_commands_have() -> None:
    """An example that leaves out --to prints the default endpoint, not another port."""
    default = next(p.default for path, c in _all_commands() if path == "ttctl emulate tablet"
                   for p in c.params if "--to" in p.opts)  # type: ignore[attr-defined]
    seen = 0
    for block in _console_blocks():
        for chunk in re.split(r"^\$ ", block, flags=re.M)[1:]:
            cmd, _, out = chunk.partition("\n")
            if cmd.startswith("ttctl emulate tablet") and "--to" not in cmd:
                for port in re.findall(r"connected to \S+ at (udpout:\S+)", out):
                    assert port == default, f"$ {cmd} prints {port}; its default is {default}"
                    seen += 1
    assert seen, "the manual shows `ttctl emulate tablet` with its default endpoint"


def _help(full: str) -> str:
    cmd = dict(_all_commands())[full]
    return " ".join(" ".join(filter(None, [getattr(cmd, "help", "") or ""] + [getattr(p, "help", "") or ""
                                                                             for p in cmd.params])).split())


def _section(full: str) -> str:
    text = manual()
    return " ".join(text.split(f"### `{full}", 1)[1].split("\n### ", 1)[0].split())


# claims the manual and --help both make, in words each must carry (and words neither may)
CLAIMS = [
    ("ttctl link relay", "where downlink packets go", ["valid", "frame", "lately"], ["address last heard"]),
    ("ttctl link relay", "what a burst is counted in", ["slot", "full packet"], ["burst-mean` packets"]),
    ("ttctl send-file", "what --timeout counts", ["without progress"], ["without a word"]),
    ("ttctl bench integrity", "what --seed reproduces", ["plan"], ["the same seed, the same plan)"]),
]


@pytest.mark.parametrize(("full", "what", "must", "never"), CLAIMS, ids=[c[1] for c in CLAIMS])
def test_readme_and_help_say_the_same(full: str, what: str, must: list[str], never: list[str]) -> None:
    for where, text in (("--help", _help(full)), ("the manual", _section(full))):
        for w in must:
            assert w in text, f"{full} {where} does not say {w!r} ({what})"
        for w in never:
            assert w not in text, f"{full} {where} still says {w!r} ({what})"
