"""Shared helpers: paths, and running the real `ttctl` console script."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parent.parent
DIALECTS = ROOT / "dialects"


def nav_pages() -> list[Path]:
    """The docs site's pages in the order of mkdocs.yml's nav (a title's page, or a section's pages)."""
    import yaml

    def walk(entries: Any) -> Iterator[str]:
        for entry in entries:
            value = next(iter(entry.values())) if isinstance(entry, dict) else entry
            if isinstance(value, list):
                yield from walk(value)
            else:
                yield value

    nav = yaml.safe_load((ROOT / "mkdocs.yml").read_text())["nav"]
    return [ROOT / "docs" / page for page in walk(nav)]


def manual() -> str:
    """The whole manual: README.md (the front door), then every page of the docs site in nav order.
    The pages keep the README's old heading levels, so a section runs to the next heading of its
    level whichever page it ends on."""
    return "\n\n".join(p.read_text() for p in [ROOT / "README.md", *nav_pages()])
TTAPI = DIALECTS / "ttapi.xml"


def shipped() -> Any:
    """ttctl's shipped dialect as the link layer takes it (a ttctl.wire.bindings.Bindings)."""
    import ttapi
    from ttctl.wire.bindings import Bindings

    return Bindings(ttapi)


def pymavlink_dialects() -> Path:
    import pymavlink

    return Path(pymavlink.__file__).parent / "dialects" / "v20"


def ttctl_cmd() -> list[str]:
    exe = Path(sys.executable).with_name("ttctl")
    if exe.exists():
        return [str(exe)]
    found = shutil.which("ttctl")
    return [found] if found else [sys.executable, "-m", "ttctl"]


def run_ttctl(*args: str, cwd: str | os.PathLike[str] | None = None, timeout: float = 120,
              input: bytes | None = None, env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    """Run the installed console script as a real process (`env`: variables to add); `timeout`
    is the idle machine's allowance, stretched on a busy one (machine.scaled)."""
    from machine import scaled

    return subprocess.run(ttctl_cmd() + list(args), cwd=cwd, capture_output=True, text=True, timeout=scaled(timeout),
                          input=input.decode() if input is not None else None,
                          env={**os.environ, **env} if env else None)


def assert_no_traceback(proc: subprocess.CompletedProcess[str]) -> None:
    assert "Traceback" not in proc.stderr and "Traceback" not in proc.stdout, proc.stderr


@pytest.fixture(scope="session")
def pm_dialects() -> Path:
    return pymavlink_dialects()


@pytest.fixture
def start(tmp_path: Path) -> Iterator[Any]:
    """Start a ttctl process (`start(name, *args)`, output in tmp_path/name.out|err); every one
    is killed when the test ends."""
    from e2e_lib import Proc

    procs: list[Proc] = []

    def go(name: str, *args: str) -> Proc:
        p = Proc(tmp_path, name, list(args))
        procs.append(p)
        return p

    try:
        yield go
    finally:
        for p in procs:
            p.close()


@pytest.fixture(scope="session")
def cpp_node_bins(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    """The C++ onboard end's test programs (tests/cpp_node_lib.py): onboard_node plain ("plain")
    and under the sanitizers ("asan"), scheduler_driver ("scheduler"), node_driver ("driver"),
    generated and built once a session for all the test_cpp_node_* files."""
    from cpp_node_lib import build

    return build(tmp_path_factory.mktemp("cpp_node"))


@pytest.fixture
def cpp_nodes() -> Iterator[Any]:
    """Start onboard_node processes (`cpp_nodes(exe, folder, name, *args)`: a cpp_node_lib.Node);
    those still running when the test ends are killed."""
    from cpp_node_lib import Node

    started: list[Node] = []

    def start(*args: Any, **kw: Any) -> Node:
        n = Node(*args, **kw)
        started.append(n)
        return n

    yield start
    for n in started:
        if n.p.poll() is None:
            n.kill()


# Under pytest-xdist (`--dist loadgroup`, the README's test command) each test file runs whole on
# one worker (its module fixtures, builds and peers built once), except the files that measure a
# live link against a bound: those share one group, so no two of them measure at the same time.
MEASURING = {"test_fair_sharing.py", "test_link_fit_live.py", "test_bench_live.py", "test_bench_latency.py",
             "test_java_transfer.py", "test_cpp_node_transfer.py", "test_udp_forward.py", "test_cpp_node_sharing.py",
             "test_gcs_bridge.py", "test_java_bridge_e2e.py",
             # (latency against idle, goodput against the rate: on one worker)
             "test_java_pipeline.py", "test_cpp_mop.py"}


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    for item in items:
        name = item.path.name
        item.add_marker(pytest.mark.xdist_group("measuring" if name in MEASURING else name))
