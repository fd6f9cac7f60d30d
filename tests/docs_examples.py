"""Running the manual's ```console examples and checking what they print, and finding the
messages the manual quotes in ttctl's code.

A console block is a list of `$ ` commands, each followed by what it prints (stdout and stderr
as a terminal shows them; `...` stands for any number of lines). `run_block` runs one in a
fresh folder holding a link to the repository's `dialects/`:

- a command ending in `&` starts in the background; the lines shown under it are the first it
  prints (waited for);
- `$ # ...` (a comment) shows lines that background commands print meanwhile: each must come;
- a command whose output starts `^C` gets Ctrl-C (SIGINT) a moment after it starts;
- any other command runs to its end, and prints exactly what is shown (`...` inside a line
  stands for any text: a path the manual leaves out).

Figures that vary by design are compared by their shape (`normalize`): the ports the block
names are replaced by free ones, a client's port by `PORT`, the folder the block runs in by the
`/tmp/demo` the manual shows, and seconds, rates and byte counts of a transfer by `N`.

A block whose `ttctl:` lines cannot be run in a test (a peer on a real aircraft, a long outage,
Ctrl-C) is preceded by `<!-- not run: why -->`; `quoted_by_code` then finds each of its lines
among the messages of cli/ttctl (every string literal and f-string, its fields standing for any
text).
"""

from __future__ import annotations

import ast
import functools
import os
import re
import signal
import socket
import subprocess
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

from conftest import ROOT
from machine import scaled

SHOWN_DIR = "/tmp/demo"
MIN_LITERAL = 12  # characters of a message's own words, so that `f"{a}: {b}"` matches nothing on its own


@dataclass
class Block:
    page: str
    line: int  # of the ```console line, 1-based
    not_run: str | None  # the reason, from `<!-- not run: ... -->` just above
    steps: list[tuple[str, list[str]]] = field(default_factory=list)

    @property
    def where(self) -> str:
        return f"{self.page}:{self.line}"


def blocks(page: Path) -> list[Block]:
    text = page.read_text()
    out = []
    for m in re.finditer(r"(?:<!-- not run: (.+?) -->\n)?```console\n(.*?)```", text, re.S):
        block = Block(str(page.relative_to(ROOT / "docs")), text[:m.start(2)].count("\n"), m.group(1))
        for chunk in re.split(r"^\$ ", m.group(2), flags=re.M)[1:]:
            cmd, _, rest = chunk.partition("\n")
            shown = [line.rstrip() for line in rest.rstrip("\n").split("\n") if line.strip()]
            block.steps.append((cmd.rstrip(), shown))
        out.append(block)
    return out


def matches(expected: list[str], got: list[str]) -> bool:
    if not expected:
        return not got
    if expected[0].strip() == "...":
        return any(matches(expected[1:], got[i:]) for i in range(len(got) + 1))
    return bool(got) and _line_matches(expected[0], got[0]) and matches(expected[1:], got[1:])


def _line_matches(expected: str, got: str) -> bool:
    """Equal, or equal but for each `...` inside the expected line (a path left out, say)."""
    if expected == got:
        return True
    return "..." in expected and re.fullmatch(".*?".join(map(re.escape, expected.split("..."))), got) is not None


def normalize(line: str, ports: dict[str, str], folder: Path) -> str:
    """A line with its figures that vary by design replaced by their shape."""
    for shown, real in ports.items():
        line = re.sub(rf"(?<=:){real}\b", shown, line)
    line = line.replace(str(folder), SHOWN_DIR)
    line = re.sub(r"(\b127\.0\.0\.1:)(?!145\d\d\b)\d{4,5}\b", r"\1PORT", line)  # a client's own port
    line = re.sub(r"\b\d+(\.\d+)? (s|B/s|bytes retransmitted)\b", r"N \2", line)
    return line


def _free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as u, socket.socket() as t:
        u.bind(("127.0.0.1", 0))
        port = u.getsockname()[1]
        try:
            t.bind(("127.0.0.1", port))
        except OSError:
            return _free_port()
        return int(port)


def _env() -> dict[str, str]:
    return {**os.environ, "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}",
            "PYTHONUNBUFFERED": "1", "COLUMNS": "200", "TERM": "dumb"}


def run_block(block: Block, folder: Path, files: tuple[str, ...] = ()) -> None:
    """Run the block's commands in `folder` (holding `dialects/` and a copy of each of the
    repository's `files`); assert that each prints what the manual shows."""
    (folder / "dialects").symlink_to(ROOT / "dialects")
    for name in files:
        (folder / Path(name).name).write_bytes((ROOT / name).read_bytes())
    text = "\n".join(c for c, _ in block.steps)
    ports = {p: str(_free_port()) for p in sorted(set(re.findall(r"127\.0\.0\.1:(145\d\d)\b", text)))}
    background: list[tuple[subprocess.Popen[str], Path]] = []

    def real(cmd: str) -> str:
        for shown, port in ports.items():
            cmd = re.sub(rf"(?<=:){shown}\b", port, cmd)
        return cmd

    def lines_of(path: Path) -> list[str]:
        text = path.read_text(errors="replace")
        return [normalize(x.rstrip(), ports, folder) for x in text.splitlines() if x.strip()]

    def wait_for(expected: list[str], paths: list[Path], what: str) -> None:
        deadline = time.monotonic() + scaled(20)
        while True:
            got = [x for p in paths for x in lines_of(p)]
            missing = [e for e in expected if e != "..." and not any(_line_matches(e, g) for g in got)]
            if not missing or time.monotonic() > deadline:
                break
            time.sleep(0.1)
        assert not missing, f"{block.where}: {what}\nthe manual:\n" + "\n".join(expected) + \
            "\nprints:\n" + "\n".join(got)

    try:
        for cmd, shown in block.steps:
            expected = [normalize(x, {}, folder) for x in shown]
            if cmd.startswith("#"):
                wait_for(expected, [log for _, log in background], f"$ {cmd} (the background commands' lines)")
                continue
            if cmd.endswith("&"):
                log = folder / f".bg{len(background)}.log"
                with log.open("w") as out:
                    proc = subprocess.Popen(["bash", "-c", real(cmd[:-1])], cwd=folder, stdout=out,
                                            stderr=subprocess.STDOUT, text=True, env=_env(), start_new_session=True)
                background.append((proc, log))
                wait_for(expected, [log], f"$ {cmd}")
                got = lines_of(log)[:len(expected)]
                assert matches(expected, got), f"{block.where}: $ {cmd}\nthe manual:\n" + "\n".join(expected) + \
                    "\nprints first:\n" + "\n".join(got)
                continue
            if expected and expected[0].startswith("^C"):  # Ctrl-C before it printed anything
                expected[0] = expected[0][2:]
                output = _interrupted(real(cmd), folder)
            else:
                output = subprocess.run(["bash", "-c", real(cmd)], cwd=folder, stdout=subprocess.PIPE,
                                        stderr=subprocess.STDOUT, text=True, env=_env(), timeout=scaled(120)).stdout
            got = [normalize(x.rstrip(), ports, folder) for x in output.splitlines() if x.strip()]
            assert "Traceback" not in output, output
            assert matches(expected, got), f"{block.where}: $ {cmd}\nthe manual:\n" + "\n".join(expected) + \
                "\nprints:\n" + "\n".join(got)
    finally:
        for proc, _ in background:
            if proc.poll() is None:
                os.killpg(proc.pid, signal.SIGTERM)
            try:
                proc.wait(timeout=scaled(10))
            except subprocess.TimeoutExpired:
                os.killpg(proc.pid, signal.SIGKILL)
                proc.wait()


def _interrupted(cmd: str, folder: Path) -> str:
    """What the command prints when Ctrl-C comes a moment after it started (it has printed
    nothing by then), as the terminal's SIGINT to its process group."""
    proc = subprocess.Popen(["bash", "-c", cmd], cwd=folder, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, env=_env(), start_new_session=True)
    try:
        out, _ = proc.communicate(timeout=scaled(2))  # ended on its own: not what the manual shows
        return out
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGINT)
    try:
        out, _ = proc.communicate(timeout=scaled(20))
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        out, _ = proc.communicate()
        return out + "\n(still running 20 s after Ctrl-C)"
    return out


@functools.cache
def messages() -> list[re.Pattern[str]]:
    """Every message cli/ttctl can print, as a pattern: its literal words, each field `(.+)`."""
    out: list[re.Pattern[str]] = []
    for path in sorted((ROOT / "cli" / "ttctl").rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.Constant) and isinstance(node.value, str):
                parts: list[str | None] = [node.value]
            elif isinstance(node, ast.JoinedStr):
                parts = [v.value if isinstance(v, ast.Constant) else None for v in node.values]
            else:
                continue
            literal = "".join(p for p in parts if p)
            if len(literal.strip()) < MIN_LITERAL:
                continue
            pattern = "".join("(.+)" if p is None else re.escape(p) for p in parts)
            # %-style and str.format fields of plain strings stand for any text too
            pattern = re.sub(r"%(?:\\\.)?\d*[sdfgr]|\\\{[^}]*\\\}", "(.+)", pattern)
            out.append(re.compile(pattern, re.S))
    return out


def quoted_by_code(line: str) -> bool:
    """Whether the line (less `^C` and ttctl's `ttctl: error: ` style prefix) is a message of
    cli/ttctl; its fields may be any text, but a field holding more than a word or two must be a
    message of cli/ttctl itself (a reason inside a refusal)."""
    line = line.removeprefix("^C")
    tails = [line]
    for prefix in ("ttctl: error: ", "ttctl: warning: ", "ttctl: "):
        if line.startswith(prefix):
            tails.append(line[len(prefix):])
    return any(_produced(t, 0) for t in tails)


def _produced(text: str, depth: int) -> bool:
    if depth > 3:
        return False
    for pattern in messages():
        m = pattern.fullmatch(text)
        if m and all(len(g.split()) <= 3 or _produced(g, depth + 1) or _composed(g, depth + 1) for g in m.groups()):
            return True
    return False


def _composed(text: str, depth: int) -> bool:
    """A field made of a message and a few words (a reason and its hint, say)."""
    for pattern in messages():
        m = pattern.match(text)
        if m and m.end() < len(text) and len(text[m.end():].split()) <= 3 and not m.groups():
            return True
    return False
