"""`ttctl hmd dump` and `ttctl hmd pulse`: the VR pose streams out of the headset (or a synthetic
or recorded one), converted to the chosen frame, recorded and/or streamed over the link.

The main thread takes samples from the source (pacing the ones that are not paced by a device:
synthetic and replay, at `--speed`), converts them (REP-103 by default, sign-continuous unit
quaternions), writes them, and offers them to the link. The link, when `--to` is given, is the
shared asyncio Runner over a proto Endpoint in a thread of its own, with a newest-wins
PoseStream as one of the scheduler's sources (ttctl.hmd.stream). Ctrl-C (or SIGTERM) stops
taking samples, finishes the file under its final name and exits 0.
"""

from __future__ import annotations

import asyncio
import contextlib
import math
import os
import signal
import sys
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .. import interrupts
from ..errors import Fail
from .common import TABLET, err, link_choice, parse_endpoint

SOURCES = ("synthetic", "openvr", "replay")
HEADROOM = 0.85  # of the profile's capacity, for streaming poses
CONFIRM_WAIT = 10.0  # s, at the end: the wait for the last button changes' confirmations stops after this long
# without one (a backlog of changes confirmed one by one on a lossy link keeps it going) ...
CONFIRM_MAX = 60.0  # s ... or after this long in all


@dataclass
class DumpOptions:
    source: str = "synthetic"
    replay_file: str | None = None
    rate_hmd: float = 90.0
    rate_controllers: float = 250.0
    duration: float | None = None
    fmt: str | None = None
    output: str | None = None
    frame: str = "ros"
    parent_frame: str = "vr_world"
    seed: int = 0
    speed: float = 1.0
    to: str | None = None
    rate: float | None = None
    profile: str | None = None
    distance: float = 10.0
    stream_hz: float = 30.0
    quiet: bool = False
    extra: dict[str, Any] = field(default_factory=dict)
    profile_file: Path | None = None
    dialect: Path | None = None  # of the link (--to)
    include_dirs: list[Path] = field(default_factory=list)
    salvage: bool = False  # replay what can be read of a damaged or cut-short recording
    force: bool = False  # -o may replace an existing file


def _check(o: DumpOptions) -> None:
    """Everything that can be refused, before anything is opened or made."""
    from ..hmd.model import FRAMES

    if o.source not in SOURCES:
        raise Fail(f"unknown source {o.source!r}: use one of {', '.join(SOURCES)}")
    if o.source == "replay" and not o.replay_file:
        raise Fail("--source replay needs the recording: ttctl hmd dump --source replay FILE")
    if o.source != "replay" and o.replay_file:
        raise Fail(f"{o.replay_file!r}: a FILE is only read with --source replay")
    if o.salvage and o.source != "replay":
        raise Fail("--salvage applies to --source replay FILE")
    if o.frame not in FRAMES:
        raise Fail(f"unknown frame {o.frame!r}: use ros or openvr")
    for name, v in (("--rate-hmd", o.rate_hmd), ("--rate-controllers", o.rate_controllers)):
        if not (math.isfinite(v) and 0 < v <= 1000):
            raise Fail(f"{name} must be in (0, 1000] Hz, not {v:g}")
    if o.duration is not None and not (math.isfinite(o.duration) and o.duration > 0):
        raise Fail(f"--duration must be a positive number of seconds, not {o.duration:g}")
    if not (math.isfinite(o.speed) and o.speed >= 0):
        raise Fail(f"--speed must be 0 (as fast as possible) or positive, not {o.speed:g}")
    if o.source == "openvr" and o.speed != 1.0:
        raise Fail("--speed applies to synthetic and replay sources; a headset runs in real time")
    if not o.parent_frame or not all(c.isalnum() or c in "_/" for c in o.parent_frame):
        raise Fail(f"--parent-frame {o.parent_frame!r}: letters, digits, _ and / only")
    if not (math.isfinite(o.stream_hz) and o.stream_hz > 0):
        raise Fail("--stream-hz must be positive")
    if o.rate is not None and not o.rate > 0:  # checked with or without --to: a bad value is never silently unused
        raise Fail(f"--rate must be a positive number of bytes per second, not {o.rate:g}")
    if o.distance < 0:  # with or without --to, as --rate
        raise Fail("--distance must not be negative")
    if o.to is None and (o.rate is not None or o.profile is not None or o.profile_file is not None):
        raise Fail("--rate, --profile and --profile-file pace the link: they apply with --to")


def _open_source(o: DumpOptions) -> tuple[Any, str]:
    """The source and the frame its samples are in."""
    if o.source == "synthetic":
        from ..hmd.sources.synthetic import SyntheticSource

        return SyntheticSource(seed=o.seed, rate_hmd=o.rate_hmd, rate_controllers=o.rate_controllers,
                               duration=o.duration), "openvr"
    if o.source == "openvr":
        from ..hmd.sources.openvr_source import OpenVRSource

        return OpenVRSource(rate_hmd=o.rate_hmd, rate_controllers=o.rate_controllers, duration=o.duration), "openvr"
    from ..hmd.formats import read_recording

    assert o.replay_file is not None
    rec = read_recording(o.replay_file)
    if rec.damage:
        if not o.salvage:
            rec_close = getattr(rec, "close", None)
            if rec_close is not None:
                rec_close()
            raise Fail(f"{o.replay_file}: {rec.damage}; --salvage replays what can be read", 1)
        err(f"warning: {o.replay_file}: {rec.damage}; salvaging what can be read (--salvage)")
    return _Replay(rec, o.duration), rec.frame


class _Replay:
    """A recording as a source: its samples, at their own times (the driver paces them)."""

    paced = False

    def __init__(self, rec: Any, duration: float | None) -> None:
        self.rec = rec
        self.duration = duration
        self.counts: dict[str, int] = {}

    def samples(self) -> Any:
        first = None
        for s in self.rec.samples:
            if first is None:
                first = s.t
            if self.duration is not None and s.t - first >= self.duration:
                return
            yield s

    def close(self) -> None:
        close = getattr(self.rec, "close", None)
        if close is not None:
            close()


class _Link:
    """The link to the onboard end, in a thread of its own: a Runner over an Endpoint whose
    scheduler pulls the newest poses from a PoseStream."""

    def __init__(self, o: DumpOptions) -> None:
        from ..hmd.stream import PoseStream
        from .dialect import load_bindings

        self.spec = parse_endpoint(o.to or "", "udpout")
        self.b = load_bindings(o.dialect, o.include_dirs)
        default = "m100" if o.rate is None and o.profile_file is None else None
        choice = link_choice(o.rate, o.profile if o.profile is not None else default,
                             o.distance, TABLET[0], o.profile_file)
        # Poses are newest-wins: a queue in the radio's buffer would only make them stale. Paced
        # a little below the profile's capacity the buffer stays empty (at exactly the capacity
        # it holds its two packets, 0.3 s on the M100 uplink); --rate is taken as given.
        self.pace = choice.pace_Bps * HEADROOM if choice.pace_Bps and o.rate is None else choice.pace_Bps
        self.quiet = choice.quiet
        self.mtu = choice.mtu
        self.stream = PoseStream(self.b, max_hz=o.stream_hz)
        self.loop = asyncio.new_event_loop()
        self.ready = threading.Event()
        self.error: str | None = None
        self.done = asyncio.Event()
        self.runner: Any = None
        self.ep: Any = None
        self.heard = False  # the onboard end answered (anything, from anyone on the link)
        self.hurry = threading.Event()  # stop waiting for the last confirmations (a second Ctrl-C)
        self.thread = threading.Thread(target=self._main, name="ttctl-link", daemon=True)

    def start(self) -> None:
        self.thread.start()
        self.ready.wait(10)
        if self.error:
            raise Fail(self.error)

    def _main(self) -> None:
        asyncio.set_event_loop(self.loop)
        self.loop.run_until_complete(self._run())

    async def _run(self) -> None:
        from ..ends.runtime import Runner, hello
        from ..link.transport import TransportError, make_transport
        from ..proto.endpoint import Endpoint

        try:
            transport = make_transport(self.spec, mtu=self.mtu if self.spec.udp else None)
            ep = Endpoint(self.b, *TABLET, mtu=transport.mtu, rate_Bps=self.pace, accept_commands=False,
                          unsolicited=False, on_message=self._on_message)
            self.ep = ep
            ep.add_stream(self.stream)
            self.runner = Runner(ep, transport, quiet=self.quiet, hello=hello(TABLET[0], self.spec, self.b))
            await self.runner.start()
        except (TransportError, OSError) as e:
            self.error = f"cannot open {self.spec}: {e}"
            self.ready.set()
            return
        self.ready.set()
        await self.done.wait()
        now = self.loop.time()
        progress, confirmed = now, self.stream.stats.confirmed
        while self.stream.unconfirmed() and not self.hurry.is_set() and \
                self.loop.time() < min(progress + CONFIRM_WAIT, now + CONFIRM_MAX) and \
                (self.heard or self.loop.time() < now + 1.0):  # the last button changes, confirmed
            if self.stream.stats.confirmed != confirmed:  # still confirming a backlog: keep waiting
                progress, confirmed = self.loop.time(), self.stream.stats.confirmed
            self.runner.kick()
            await asyncio.sleep(0.05)
        await self.runner.drain(1.0)
        await self.runner.close()

    def _on_message(self, now: float, msg: Any) -> None:
        from ..hmd.stream import ACK_PREFIX

        self.heard = True
        if type(msg).__name__ != "NamedValueInt":
            return
        name = msg.name.decode("ascii", "replace") if isinstance(msg.name, bytes) else str(msg.name)
        name = name.rstrip("\x00")
        if name.startswith(ACK_PREFIX) and name[len(ACK_PREFIX):].isdigit():
            self.stream.now = now
            if self.stream.on_ack(int(name[len(ACK_PREFIX):]), int(msg.value) & 0xFFFFFFFF):
                self.runner.kick()

    def offer(self, s: Any) -> None:
        self.loop.call_soon_threadsafe(self._offer, s)

    def _offer(self, s: Any) -> None:
        self.stream.offer(s)
        if self.runner is not None:
            self.runner.kick()

    def close(self) -> None:
        if self.thread.is_alive():
            self.loop.call_soon_threadsafe(self.done.set)
            self.thread.join(CONFIRM_MAX + 5)


def dump(o: DumpOptions) -> int:
    from ..hmd.formats import await_reader, check_output, format_for, open_writer
    from ..hmd.frames import Continuity, convert

    _check(o)
    fmt = format_for(o.output, o.fmt)
    check_output(o.output, fmt)
    if o.output is not None and os.path.isfile(o.output) and not o.force:  # as `ros2 bag record` refuses
        raise Fail(f"{o.output} exists: --force replaces it")
    link = _Link(o) if o.to else None
    source, src_frame = _open_source(o)
    stop = threading.Event()

    def on_signal(*_: Any) -> None:  # the first stops taking samples, a second stops waiting for confirmations
        if stop.is_set() and link is not None:
            link.hurry.set()
        stop.set()

    previous = {sig: signal.signal(sig, on_signal) for sig in (signal.SIGINT, signal.SIGTERM)}
    if interrupts.seen():  # a Ctrl-C Python swallowed on the way here
        stop.set()
    writer = None
    taken = 0
    kinds: dict[str, int] = {}
    started = time.monotonic()
    try:
        if link is not None:
            link.start()
        if isinstance(source, _Replay):  # what the recording said of itself, kept
            meta: dict[str, Any] = {"source": "replay", "replay": o.replay_file, "recorded": source.rec.meta}
        else:
            meta = {"source": o.source, "rate_hmd": o.rate_hmd, "rate_controllers": o.rate_controllers,
                    **({"seed": o.seed} if o.source == "synthetic" else {})}
        reader = await_reader(o.output, stop.is_set)  # a FIFO: its reader first, Ctrl-C heard meanwhile
        try:
            writer = open_writer(o.output, fmt, o.frame, o.parent_frame, meta)
        finally:
            if reader is not None:
                os.close(reader)
        keep, keep_link = Continuity(), Continuity()
        first_t: float | None = None
        for s in source.samples():
            if stop.is_set():
                break
            if not source.paced and o.speed > 0:
                if first_t is None:
                    first_t = s.t
                wait = started + (s.t - first_t) / o.speed - time.monotonic()
                if wait > 0 and stop.wait(wait):
                    break
            out = keep(convert(s, src_frame, o.frame))
            writer.write(out)
            if link is not None:  # TT_VR_POSE is REP-103 whatever --frame the file is in
                link.offer(out if o.frame == "ros" else keep_link(convert(s, src_frame, "ros")))
            s = out
            taken += 1
            kinds[s.device.frame] = kinds.get(s.device.frame, 0) + 1
        writer.close()
    except BrokenPipeError:
        if writer is not None:
            writer.abort()
        with contextlib.suppress(Exception):
            sys.stderr.close()
        return 1
    except BaseException:
        if writer is not None:
            writer.abort()
        raise
    finally:
        source.close()
        if link is not None:
            link.close()
        for sig, h in previous.items():
            signal.signal(sig, h)
    elapsed = time.monotonic() - started
    if not o.quiet:
        _summary(o, fmt, taken, kinds, elapsed, writer, link, stop.is_set())
    return 0 if link is None else _link_verdict(o, link)


def _summary(o: DumpOptions, fmt: str, taken: int, kinds: dict[str, int], elapsed: float, writer: Any,
             link: _Link | None, interrupted: bool) -> None:
    where = o.output or "stdout"
    per = ", ".join(f"{k} {n}" for k, n in sorted(kinds.items()))
    err(f"{'interrupted: ' if interrupted else ''}{taken} samples in {elapsed:.1f} s ({per}) -> {where} "
        f"({fmt}, {o.frame} frame under {o.parent_frame})")
    if link is not None:
        st = link.stream.stats
        held = link.stream.held()
        err(f"streamed to {o.to}: {st.taken} taken = {st.sent} sent + {st.superseded} superseded"
            + (f" + {held} not sent by the end" if held else "")
            + (f", paced at {link.pace:.0f} B/s" if link.pace else ""))
        if st.buttons:
            err(f"button changes: {st.confirmed} of {st.buttons} confirmed by the onboard end"
                + (f" ({st.resent} resent)" if st.resent else ""))


def _link_verdict(o: DumpOptions, link: _Link) -> int:
    """1 when the onboard end never answered or a button change was not confirmed (said, even
    with --quiet)."""
    lost = link.stream.unconfirmed()
    if not link.heard:
        err(f"error: nothing heard from the onboard end at {o.to}: no pose or button change can be confirmed")
        return 1
    if lost and not link.stream.stats.confirmed:
        err(f"error: the onboard end at {o.to} confirmed none of {lost} button change{'s' if lost != 1 else ''}: it "
            "must answer each TT_VR_CONTROLLER with NAMED_VALUE_INT 'vrbtn<index>' = its packet_num "
            "(ttctl emulate onboard and the generated C++ node do)")
        return 1
    if lost:
        err(f"error: {lost} button change{'s' if lost != 1 else ''} not confirmed by the onboard end: none "
            f"confirmed in the last {CONFIRM_WAIT:g} s")
        return 1
    return 0


def pulse(device: str, us: int) -> int:
    from ..hmd.sources.openvr_source import pulse as do_pulse

    if device not in ("left", "right"):
        raise Fail(f"--device {device!r}: left or right")
    used, warning = do_pulse(device, us)
    if warning:
        err(f"warning: {warning}")
    print(f"pulsed the {device} controller for {used} us")
    return 0
