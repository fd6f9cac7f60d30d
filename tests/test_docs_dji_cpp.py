"""docs/dji/onboard-cpp.md's C++ programs, as they stand there: every ```cpp block is compiled
with g++ -std=c++17 -Wall -Wextra -Wpedantic -Werror against DJI's real headers (vendored in
tests/vendor/dji/, as system headers): the Onboard SDK program against OSDK 3.9's and 4.1's,
the Payload SDK program against Payload SDK 3.13.1's. Linked with the stand-ins for the SDK
functions they call (tests/cpp/osdk_standin/, built for 3.9 or 4.1; tests/cpp/fake_psdk/), the
programs run against ttctl's Python ends through `ttctl link relay`:

- the OSDK 3.9 build (the M100's SDK, whose recvInfo.len counts two bytes more than 4.1's) takes
  a 4 KB file in full 100-byte packets, and serves one; the 4.1 build the same; a program that
  subtracts only PackageMin stalls on 3.9;
- the Payload SDK build takes a file and serves one in 128-byte packets (--profile psdk);
- the MOP build (the Payload SDK's low-speed channel and a MOP pipeline, with the stand-in of
  dji_mop_channel.h) takes a file from `send-file --profile mop --pipeline tcpout:`, its data over
  the pipeline, and says on stderr that the pipeline opened and closed (DJI's words).
"""

from __future__ import annotations

import hashlib
import os
import random
import re
import shutil
import signal
import socket
import subprocess
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

from conftest import ROOT, run_ttctl
from e2e_lib import LOCAL, Start, free_port, relay, send
from machine import scaled

pytestmark = pytest.mark.skipif(shutil.which("g++") is None, reason="needs g++")

WARN = ["-std=c++17", "-Wall", "-Wextra", "-Wpedantic", "-Werror"]
DOC = ROOT / "docs" / "dji" / "onboard-cpp.md"
VENDOR = ROOT / "tests" / "vendor" / "dji"
OSDK_STANDIN = ROOT / "tests" / "cpp" / "osdk_standin" / "fake_osdk.cpp"
FAKE_PSDK = ROOT / "tests" / "cpp" / "fake_psdk"
OSDK = {"3.9": VENDOR / "osdk-3.9.0", "4.1": VENDOR / "osdk-4.1.0"}
PSDK = VENDOR / "psdk-3.13.1"


def blocks() -> dict[str, str]:
    """The doc's cpp blocks, by the file their first line names."""
    out = {}
    for code in re.findall(r"```cpp\n(.+?)```", DOC.read_text(), re.S):
        m = re.match(r"// ([\w.]+):", code)
        assert m, code.split("\n", 1)[0]
        out[m.group(1)] = code
    return out


def system_includes(root: Path) -> list[str]:
    """-isystem for every folder of vendored headers (as DJI's build puts them on the path)."""
    dirs = sorted({p.parent for p in root.rglob("*.h*")})
    return [arg for d in dirs for arg in ("-isystem", str(d))]


def gxx(*args: str) -> None:
    proc = subprocess.run(["g++", *args], capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-5000:]


@pytest.fixture(scope="module")
def built(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    tmp = tmp_path_factory.mktemp("docs_dji_cpp")
    code = blocks()
    assert set(code) == {"osdk_main.cpp", "psdk_main.cpp", "mop_main.cpp"}, sorted(code)
    out = tmp / "out"
    proc = run_ttctl("gen", str(ROOT / "dialects" / "ttapi.xml"), "--lang", "cpp", "-o", str(out), timeout=300)
    assert proc.returncode == 0, proc.stderr
    for name, text in code.items():
        (tmp / name).write_text(text)
    inc = ["-I", str(out / "cpp")]
    exes = {"osdk-3.9": tmp / "osdk39", "osdk-4.1": tmp / "osdk41", "psdk": tmp / "psdk", "mop": tmp / "mop"}
    jobs = [(*WARN, "-O1", *inc, *system_includes(OSDK[v]), f"-DFAKE_OSDK_VERSION={v.replace('.', '')}",
             str(tmp / "osdk_main.cpp"), str(OSDK_STANDIN), "-pthread", "-o", str(exes[f"osdk-{v}"]), "-lz")
            for v in ("3.9", "4.1")]
    jobs.append((*WARN, "-O1", *inc, "-I", str(FAKE_PSDK), *system_includes(PSDK), str(tmp / "psdk_main.cpp"),
                 str(FAKE_PSDK / "fake_psdk.cpp"), str(FAKE_PSDK / "fake_application.cpp"), "-pthread", "-o",
                 str(exes["psdk"]), "-lz"))
    jobs.append((*WARN, "-O1", *inc, "-I", str(FAKE_PSDK), *system_includes(PSDK), str(tmp / "mop_main.cpp"),
                 str(FAKE_PSDK / "fake_psdk.cpp"), str(FAKE_PSDK / "fake_mop.cpp"),
                 str(FAKE_PSDK / "fake_application.cpp"), "-pthread", "-o", str(exes["mop"]), "-lz"))
    with ThreadPoolExecutor(max_workers=2) as pool:
        for job in [pool.submit(gxx, *args) for args in jobs]:
            job.result()
    return exes


def sha(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def run_program(exe: Path, folder: Path, env: dict[str, str], start: Start, profile: str, up: int,
                down: int) -> None:
    """The program in `folder` with the stand-in's radio on a free port, a relay of `profile` in
    front of it: send-file --to takes `up` bytes to it and --from fetches `down` bytes."""
    (folder / "outbox").mkdir(parents=True)
    served = folder / "outbox" / "log.bin"
    served.write_bytes(random.Random(down).randbytes(down))
    src = folder / "up.bin"
    src.write_bytes(random.Random(up).randbytes(up))
    b = free_port()
    key = "FAKE_OSDK_LISTEN" if "osdk" in exe.name else "FAKE_PSDK_LISTEN"
    with open(folder / "prog.out", "w") as out, open(folder / "prog.err", "w") as err:
        prog = subprocess.Popen([str(exe)], cwd=folder, env={**os.environ, key: f"{LOCAL}:{b}", **env}, stdout=out,
                                stderr=err)
    try:
        time.sleep(0.3)
        assert prog.poll() is None, (folder / "prog.err").read_text()
        a = free_port()
        relay(start, a, b, "--profile", profile, "--loss", "0.02", "--seed", "3", "--stats-interval", "0")
        to = f"udpout:{LOCAL}:{a}"
        proc, r = send(str(src), "--to", to, "--profile", profile, "--timeout", "30", timeout=150)
        assert proc.returncode == 0 and r["ok"], proc.stderr
        assert sha(folder / "inbox" / "up.bin") == sha(src)
        (folder / "got").mkdir()
        proc, f = send("log.bin", "--from", to, "--dir", str(folder / "got"), "--profile", profile, "--timeout", "30",
                       timeout=150)
        assert proc.returncode == 0 and f["ok"], proc.stderr
        assert sha(folder / "got" / "log.bin") == sha(served)
        assert prog.poll() is None
    finally:
        prog.send_signal(signal.SIGINT)
        code = prog.wait(20)
    assert code == 0 and (folder / "prog.err").read_text() == ""


@pytest.mark.parametrize("version", ["3.9", "4.1"])
def test_the_osdk_program_moves_files_on_both_sdks(built: dict[str, Path], tmp_path: Path, start: Start,
                                                  version: str) -> None:
    """The one OSDK program, built against 3.9's headers and against 4.1's, each with its SDK's
    recvInfo.len: a 4 KB upload (full 100-byte packets from the tablet, which 3.9 reports two
    bytes longer) and a fetch both complete, and the program says which SDK it was built for."""
    run_program(built[f"osdk-{version}"], tmp_path, {}, start, "m100", 4096, 3000)
    assert (tmp_path / "prog.out").read_text() == f"on OSDK {version[0]}\n"


def test_the_psdk_program_moves_files_in_128_byte_packets(built: dict[str, Path], tmp_path: Path,
                                                          start: Start) -> None:
    run_program(built["psdk"], tmp_path, {}, start, "psdk", 4096, 6000)


@pytest.mark.parametrize("sdk", ["osdk-3.9", "osdk-4.1", "psdk"])
def test_the_adapters_compile_strictly_against_djis_headers(built: dict[str, Path], tmp_path: Path, sdk: str) -> None:
    """osdk_link.hpp (against 3.9's and 4.1's headers, telling them apart: OSDK_4) and
    psdk_link.hpp on their own, with the stricter warnings the other generated headers meet."""
    cpp = built["psdk"].parent / "out" / "cpp"
    src = tmp_path / "only.cpp"
    if sdk == "psdk":
        src.write_text('#include "ttapi/psdk_link.hpp"\n\nint main()\n{\n    return 0;\n}\n')
        inc = system_includes(PSDK)
    else:
        version = sdk.split("-")[1]
        src.write_text('#include "ttapi/osdk_link.hpp"\n\n'
                       f"static_assert(ttapi::link::OSDK_4 == {'true' if version == '4.1' else 'false'});\n\n"
                       "int main()\n{\n    return 0;\n}\n")
        inc = system_includes(OSDK[version])
    gxx(*WARN, "-Wshadow", "-Wconversion", "-Wsign-conversion", "-fsyntax-only", "-I", str(cpp), *inc, str(src))


OLD_WIRING = """// the wiring that subtracts only PackageMin (right on OSDK 4.x, two bytes too many on 3.x)
#include <atomic>
#include <csignal>

#include "dji_linux_helpers.hpp"
#include "ttapi/node.hpp"

namespace {
std::atomic<bool> g_stop{false};
void on_signal(int) { g_stop = true; }
ttapi::link::DttLink* g_link = nullptr;
void from_mobile(DJI::OSDK::Vehicle*, DJI::OSDK::RecvContainer rc, DJI::OSDK::UserData)
{
    g_link->from_mobile(rc.recvData.raw_ack_array, rc.recvInfo.len - DJI::OSDK::OpenProtocol::PackageMin);
}
}  // namespace

int main(int argc, char** argv)
{
    std::signal(SIGINT, on_signal);
    LinuxSetup setup(argc, argv);
    DJI::OSDK::Vehicle* vehicle = setup.getVehicle();
    ttapi::link::NodeConfig cfg;
    cfg.inbox = "inbox";
    ttapi::link::Node node(cfg);
    ttapi::link::DttLink link(node, [vehicle](const std::uint8_t* p, std::size_t n) {
        std::uint8_t packet[100];
        std::copy(p, p + n, packet);
        vehicle->mobileDevice->sendDataToMSDK(packet, static_cast<std::uint8_t>(n));
    });
    g_link = &link;
    ttapi::link::Words why;
    if (!node.start(why)) {
        return 1;
    }
    vehicle->mobileDevice->setFromMSDKCallback(from_mobile, nullptr);
    link.run(&g_stop);
    return 0;
}
"""


def test_subtracting_only_packagemin_stalls_a_4kb_upload_on_osdk_39(built: dict[str, Path], tmp_path: Path,
                                                                     start: Start) -> None:
    """Why OsdkLink tells the SDKs apart: on the 3.9 stand-in, a program that subtracts only
    PackageMin (as OSDK 4 needs) reads every packet two bytes long, so full 100-byte packets from
    the tablet are dropped and a 4 KB upload makes no progress (the same program with OsdkLink's
    length moves it: test_the_osdk_program_moves_files_on_both_sdks)."""
    src = tmp_path / "old.cpp"
    src.write_text(OLD_WIRING)
    exe = tmp_path / "old"
    gxx(*WARN, "-O1", "-I", str(built["psdk"].parent / "out" / "cpp"), *system_includes(OSDK["3.9"]),
        "-DFAKE_OSDK_VERSION=39", str(src), str(OSDK_STANDIN), "-pthread", "-o", str(exe), "-lz")
    b = free_port()
    prog = subprocess.Popen([str(exe)], cwd=tmp_path, env={**os.environ, "FAKE_OSDK_LISTEN": f"{LOCAL}:{b}"},
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        a = free_port()
        relay(start, a, b, "--profile", "m100", "--stats-interval", "0")
        up = tmp_path / "up.bin"
        up.write_bytes(random.Random(4).randbytes(4096))
        proc, r = send(str(up), "--to", f"udpout:{LOCAL}:{a}", "--profile", "m100", "--timeout", "6", timeout=120)
        assert proc.returncode == 1 and r["code"] == "TIMEOUT", proc.stderr
        assert not (tmp_path / "inbox" / "up.bin").exists()
    finally:
        prog.kill()
        prog.wait(10)


def test_the_mop_program_takes_a_file_over_the_pipeline(built: dict[str, Path], tmp_path: Path) -> None:
    """The doc's MOP program with both stand-ins: `send-file --profile mop --pipeline tcpout:`
    delivers 300 kB whole, all of it written to the pipeline; the program's stderr says the
    pipeline opened, and closed in DJI's words when send-file went."""
    (tmp_path / "outbox").mkdir()
    src = tmp_path / "up.bin"
    src.write_bytes(random.Random(9).randbytes(300_000))
    b, p = free_port(), free_port(socket.SOCK_STREAM)
    with open(tmp_path / "prog.out", "w") as out, open(tmp_path / "prog.err", "w") as err:
        prog = subprocess.Popen([str(built["mop"])], cwd=tmp_path, stdout=out, stderr=err,
                                env={**os.environ, "FAKE_PSDK_LISTEN": f"{LOCAL}:{b}", "TTCTL_FAKE_MOP_PORT": str(p)})
    try:
        time.sleep(0.3)
        assert prog.poll() is None, (tmp_path / "prog.err").read_text()
        proc, r = send(str(src), "--to", f"udpout:{LOCAL}:{b}", "--profile", "mop", "--pipeline",
                       f"tcpout:{LOCAL}:{p}", "--timeout", "30", timeout=150)
        assert proc.returncode == 0 and r["ok"], proc.stderr
        assert r["pipeline_opens"] == 1 and r["pipeline_bytes_out"] >= 300_000, r
        assert sha(tmp_path / "inbox" / "up.bin") == sha(src)
        deadline = time.monotonic() + scaled(10)
        while "Connection of channel is closed" not in (tmp_path / "prog.err").read_text():
            assert time.monotonic() < deadline, (tmp_path / "prog.err").read_text()
            time.sleep(0.05)
    finally:
        prog.send_signal(signal.SIGINT)
        code = prog.wait(20)
    assert code == 0
    assert (tmp_path / "prog.err").read_text().splitlines() == [
        "pipeline open: file data goes on it",
        "pipeline: DjiMopChannel_RecvData: Connection of channel is closed. The peer channel do not work or "
        "abnormally be closed. Please confirm state of the peer channel and reaccept the connection request of "
        "MSDK/OSDK"]
