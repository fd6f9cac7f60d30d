"""The tablet's end of the link, scriptable: what the Android app does, as an asyncio session over
the shared Runner and a proto Endpoint (255/190): commands with acks, setpoints, files both ways,
and the vehicle's state as its telemetry tells it.
"""

from __future__ import annotations

import asyncio
import contextlib
import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ...link.transport import Spec, make_transport
from ...proto.endpoint import CONTROL, TELEMETRY, Endpoint
from ...proto.storage import ReceiveDir
from ...proto.transfer import TransferConfig
from ...wire.bindings import Bindings
from ...wire.contract import RUNTIME_MESSAGES, TtAction
from ..plugins import Context, Dispatcher, Plugin
from ..runtime import Runner, unknown_note
from .gcs_bridge import GcsBridge

TABLET = (255, 190)
LINK_TIMEOUT = 3.5  # s without a frame from the vehicle: the link is lost (QGroundControl's figure, for heartbeats)
STATES = {  # PX4 (main, sub) modes the onboard end reports, as the vehicle's states
    (4, 1): "landed", (4, 3): "hovering", (4, 2): "taking off", (4, 4): "flying trajectory", (4, 6): "landing",
    (4, 5): "returning", (6, 0): "moving", (3, 0): "manual control",
}


@dataclass
class VehicleView:
    """What the tablet knows of the vehicle, from its telemetry."""

    heard: float | None = None  # when anything last came from the vehicle (loop time)
    state: str = "unknown"
    armed: bool = False
    n: float = 0.0
    e: float = 0.0
    altitude: float = 0.0  # above home, m
    speed: float = 0.0  # horizontal, m/s
    lat: float = 0.0
    lon: float = 0.0
    battery: float = 100.0
    log: list[str] = field(default_factory=list)
    log_levels: list[int] = field(default_factory=list)  # each line's MAV_SEVERITY

    def fields(self) -> dict[str, Any]:
        return {"state": self.state, "armed": self.armed, "n": self.n, "e": self.e, "altitude": self.altitude,
                "speed": self.speed, "lat": self.lat, "lon": self.lon}


@dataclass
class LinkView:
    frames: int = 0
    rtt_ms: float | None = None  # of the last command
    started: float = 0.0
    lost_at: float | None = None  # when the vehicle went silent (loop time), while it is


class TabletSession:
    """`bindings`: the dialect on the link (the vehicle's messages arrive as its classes; the
    latest of each type is kept in `latest`). `plugins` get every message from the vehicle, as
    the onboard end's plugins get the tablet's, and may send any message of the dialect."""

    def __init__(self, bindings: Bindings, spec: Spec, target: tuple[int, int] = (1, 240),
                 rate_Bps: float | None = None, inbox: Path | None = None, timeout: float = 60.0, mtu: int = 100,
                 on_event: Callable[[str, dict[str, Any]], None] | None = None,
                 log: Callable[[str], None] | None = None, signing: Any = None,
                 plugins: list[Plugin] | None = None, gcs: list[Spec] | None = None,
                 gcs_share: float | None = None, pipe: Any = None, pipe_Bps: float | None = None) -> None:
        self.b = bindings
        self.spec = spec
        self.target = target
        self.vehicle = VehicleView()
        self.link = LinkView()
        self.on_event = on_event or (lambda what, fields: None)
        self.log = log or (lambda text: None)
        self.store = ReceiveDir(inbox) if inbox is not None else None
        self.transport = make_transport(spec, log=lambda text: self.log(f"{spec.kind}: {text}"),
                                        mtu=mtu if spec.udp else None)
        self.bridge: GcsBridge | None = None  # ground stations carried to the vehicle (--gcs)
        if gcs:
            self.bridge = GcsBridge(bindings, gcs, target[0], rate_Bps,
                                    **({"share": gcs_share} if gcs_share else {}), log=self.log)
        self.ep = Endpoint(bindings, *TABLET, mtu=self.transport.mtu, rate_Bps=rate_Bps, receive_dir=self.store,
                           config=TransferConfig(give_up_after=timeout), on_message=self._on_message,
                           on_event=self._on_file_event, accept_commands=False, unsolicited=False,
                           signing=signing, divert=self.bridge.divert if self.bridge else None)
        # its own heartbeats make it known (udpout); file data on the pipeline while one is open
        self.runner = Runner(self.ep, self.transport, pipe=pipe, pipe_rate_Bps=pipe_Bps)
        self._changed = asyncio.Event()
        self._file_events: dict[Any, str] = {}
        self.signs = signing is not None
        self.key_refused: str | None = None  # why frames came that --key refused ("unsigned frames", ...)
        self._log_parts: dict[int, dict[int, bytes]] = {}
        self.heartbeats = 0
        self._hb_task: asyncio.Task[None] | None = None
        self.latest: dict[str, Any] = {}  # the latest message of each type from the vehicle, by name
        self.latest_at: dict[str, float] = {}  # ... and when it came (loop time)
        self.plugins = list(plugins or [])
        self.dispatcher = Dispatcher(on_error=self._plugin_error, dialect=bindings)
        for p in self.plugins:
            self.dispatcher.add(p)  # PluginError for a message the dialect lacks, before anything starts
        self.ctx = Context(send=self.send_message, log=self.log, sysid=TABLET[0], compid=TABLET[1],
                           vehicle=self.vehicle, every=self._every, dialect=bindings)
        self._timers: list[list[asyncio.TimerHandle]] = []
        self._echoes: dict[tuple[int, int], float] = {}  # stamps of set-points the vehicle echoed: flown

    # -- life --------------------------------------------------------------------------------------
    async def start(self) -> None:
        await self.runner.start()
        if self.bridge is not None:
            await self.bridge.start(self.ep, self.runner.kick)
        if self.store is not None:
            self.store.prepare()
        self.link.started = asyncio.get_running_loop().time()
        self._hb_task = asyncio.get_running_loop().create_task(self._heartbeats())
        for p in self.plugins:
            try:
                p.start(self.ctx)
            except Exception as e:
                self.log(f"plugin {type(p).__name__} failed to start: {type(e).__name__}: {e}")

    async def _heartbeats(self) -> None:
        """A HEARTBEAT a second: the vehicle's link-loss watch hears the tablet by it. And the
        tablet's own watch: the vehicle silent LINK_TIMEOUT s is "link lost", said at once."""
        loop = asyncio.get_running_loop()
        due = 0.0
        while True:
            now = loop.time()
            if now >= due:
                self.runner.sync()
                b = self.b
                self.ep.send_message(b.Heartbeat(type=int(b.MavType.MAV_TYPE_GCS),
                                                 autopilot=int(b.MavAutopilot.MAV_AUTOPILOT_INVALID)), CONTROL)
                self.runner.kick()
                due = now + 1.0
            heard = self.vehicle.heard
            if heard is not None and self.link.lost_at is None and now - heard >= LINK_TIMEOUT:
                self.link.lost_at = heard
                self.on_event("link", {"state": "lost", "silent": round(now - heard, 1)})
                self._changed.set()
            await asyncio.sleep(0.25)

    def silence(self) -> float | None:
        """Seconds the vehicle has been silent, while the link is lost (None while it is not)."""
        if self.link.lost_at is None:
            return None
        return asyncio.get_running_loop().time() - self.link.lost_at

    def link_note(self) -> str:
        """What a failure should add while the link is lost."""
        quiet = self.silence()
        return "" if quiet is None else f" (link lost: nothing heard from the vehicle for {quiet:.1f} s)"

    async def close(self) -> None:
        for slot in self._timers:
            slot[0].cancel()
        for p in self.plugins:
            with contextlib.suppress(Exception):
                p.stop()
        if self._hb_task is not None:
            self._hb_task.cancel()
        if self.bridge is not None:
            self.bridge.close()
        self.ep.close()
        await self.runner.close()
        if self.store is not None:
            self.store.release(failed=False)

    # -- what the vehicle says ------------------------------------------------------------------
    def _on_message(self, now: float, msg: Any) -> None:
        v = self.vehicle
        if (msg.get_srcSystem(), msg.get_srcComponent()) != self.target:
            return
        v.heard = now
        if self.link.lost_at is not None:
            self.on_event("link", {"state": "back", "silent": round(now - self.link.lost_at, 1)})
            self.link.lost_at = None
            self.ep.commands.hurry(self.ep.now)  # what waits for an ack goes again now, not after its back-off
            self.runner.kick()
        self.link.frames += 1
        self.latest[msg.NAME] = msg
        self.latest_at[msg.NAME] = now
        b = self.b
        if isinstance(msg, b.Heartbeat):
            self.heartbeats += 1
            main, sub = (msg.custom_mode >> 16) & 0xFF, (msg.custom_mode >> 24) & 0xFF
            armed = bool(msg.base_mode & b.MavModeFlag.MAV_MODE_FLAG_SAFETY_ARMED)
            state = STATES.get((main, sub), f"mode {main}/{sub}")
            if (state, armed) != (v.state, v.armed):
                v.state, v.armed = state, armed
                self.on_event("state", {"state": state, "armed": armed})
        elif isinstance(msg, b.TtOdometry):
            v.n, v.e, v.altitude = float(msg.position[0]), float(msg.position[1]), 0.0 - float(msg.position[2])
            v.speed = math.hypot(float(msg.linear[0]), float(msg.linear[1]))
        elif isinstance(msg, b.DjiPoseStamped) and msg.topic_name == b.DjiTopicName.DJI_TOPIC_NAME_SETPOINT:
            self._echoes[(int(msg.sec), int(msg.nsec))] = now  # a set-point of ours, flown
            if len(self._echoes) > 64:
                self._echoes.pop(next(iter(self._echoes)))
        elif isinstance(msg, b.TtNavSatFix):
            v.lat, v.lon = msg.latitude / 1e7, msg.longitude / 1e7
        elif isinstance(msg, b.TtLog):
            text = self._log_line(msg)
            if text is not None:
                v.log.append(text)
                v.log_levels.append(int(msg.severity))
                self.on_event("log", {"text": text, "severity": msg.severity})
        if self.plugins:
            self.dispatcher.dispatch(msg, self.ctx)
        self._changed.set()

    def user_messages(self) -> list[str]:
        """Names of the messages heard from the vehicle that the tablet's own view does not show
        (the user's, and any the runtime does not use), in the order first heard."""
        return [name for name in self.latest if name not in RUNTIME_MESSAGES]

    # -- plugins ----------------------------------------------------------------------------------
    def _plugin_error(self, msg: Any, e: BaseException, where: str) -> None:
        self.log(f"plugin {where} failed on {msg.NAME}: {type(e).__name__}: {e} (the tablet keeps running)")

    def _every(self, seconds: float, fn: Callable[[], None]) -> None:
        loop = asyncio.get_running_loop()

        def tick() -> None:
            try:
                fn()
            except Exception as e:
                self.log(f"plugin timer {getattr(fn, '__qualname__', fn)} failed: {type(e).__name__}: {e}")
            slot[0] = loop.call_later(seconds, tick)

        slot = [loop.call_later(seconds, tick)]  # the timer's next call, replaced as it runs
        self._timers.append(slot)

    def _log_line(self, msg: Any) -> str | None:
        """A whole TT_LOG line, once its last chunk is in (chunks of one id, by chunk_seq)."""
        raw = msg.text.encode("utf-8", "surrogateescape")
        if msg.id == 0:
            return raw.decode("utf-8", "replace")
        parts = self._log_parts.setdefault(msg.id, {})
        parts[msg.chunk_seq] = raw
        last = max(parts)
        if len(parts[last]) == 80 or sorted(parts) != list(range(last + 1)):
            if len(self._log_parts) > 16:  # lines whose chunks were lost
                self._log_parts.pop(next(iter(self._log_parts)))
            return None
        del self._log_parts[msg.id]
        return b"".join(parts[k] for k in range(last + 1)).decode("utf-8", "replace")

    def _on_file_event(self, what: str, obj: Any) -> None:
        if what == "unknown-message":  # counted by the endpoint (ep.unknown); named once per msgid
            self.log(f"tablet: {unknown_note(self.b, obj)}")
            _, msgid, (sysid, compid) = obj
            self.on_event("unknown-message", {"msgid": msgid, "from": f"{sysid}/{compid}"})
            return
        if what == "link-refused":  # (source, reason): said by heard_note if no vehicle answers
            self.key_refused = obj[1]
            return
        self._file_events[obj] = what
        self._changed.set()

    async def fresh_state(self, timeout: float = 3.0) -> None:
        """Wait for the next HEARTBEAT: after a command, the state it reports is the one the
        command made (a `wait until state == ...` right after would otherwise see the old one)."""
        seen = self.heartbeats
        end = asyncio.get_running_loop().time() + timeout
        while self.heartbeats == seen and asyncio.get_running_loop().time() < end:
            await self.changed(0.1)

    async def changed(self, timeout: float) -> None:
        self._changed.clear()
        with contextlib.suppress(TimeoutError):
            await asyncio.wait_for(self._changed.wait(), timeout)

    # -- what the tablet asks ----------------------------------------------------------------------
    async def command(self, action: int, params: list[float] | None = None, argument: str = "",
                      retries: int = 4, timeout: float = 1.5) -> tuple[bool, str]:
        """Send a TT_ACTION_COMMAND and wait for its ack: (ok, words). A refusal carries the
        vehicle's own words: the TT_LOG line it sends just ahead of the refusing ack. If the
        link lost that line, the command is asked once more (the same id and issue time: the
        vehicle does not run it again, it repeats the recorded ack and its words)."""
        p = (list(params or []) + [0.0] * 4)[:4]
        msg = self.b.TtActionCommand(action=action, param=p, argument=argument.encode("utf-8")[:48].decode(
            "utf-8", "ignore"))
        name = TtAction(action).name.removeprefix("TT_ACTION_").lower()
        t0 = time.monotonic()
        cmd, said = await self._ask(msg, retries, timeout)
        self.link.rtt_ms = (time.monotonic() - t0) * 1000 if cmd.ok else self.link.rtt_ms
        if cmd.ok:
            return True, f"{name}: accepted"
        if cmd.ack is not None and said is None:  # refused, and its words lost on the way: ask again
            again, said = await self._ask(msg, 2, timeout)
            if again.ack is None:
                said = None
        return False, f"{name}: {cmd.error}" + (f" ({said})" if said else "") + (
            self.link_note() if cmd.ack is None else "")

    async def _ask(self, msg: Any, retries: int, timeout: float) -> tuple[Any, str | None]:
        """Submit `msg` (a repeat keeps its command id and issue time) and wait for it to end:
        (the Command, for a refusal the vehicle's last warning heard after it was sent and by
        its ack: the words sent ahead of the ack)."""
        done = asyncio.get_running_loop().create_future()
        heard = len(self.vehicle.log)
        at_ack = [heard]

        def finish(c: Any) -> None:
            at_ack[0] = len(self.vehicle.log)
            if not done.done():
                done.set_result(c)

        self.runner.sync()
        cmd = self.ep.command(msg, self.target, retries=retries, timeout=timeout, on_success=finish,
                              on_failure=finish)
        self.runner.kick()
        try:
            await done
        except asyncio.CancelledError:  # the user cancelled it (Ctrl-C at the prompt): sent no more
            self.ep.commands.pending.pop(cmd.id, None)
            raise
        if cmd.ack is None or cmd.ok:
            return cmd, None
        v = self.vehicle  # a refusal's words: a warning (or worse), the last one heard by the ack
        said = [v.log[i] for i in range(heard, at_ack[0]) if v.log_levels[i] <= 4]
        return cmd, said[-1] if said else None

    def send_message(self, msg: Any, urgent: bool = True) -> None:
        """Queue any message of the dialect for the vehicle (urgent: ahead of telemetry and files,
        as commands go; else behind telemetry). Sent once: the link may lose it, and nothing but
        an answer of the vehicle's says it arrived."""
        self.runner.sync()
        self.ep.send_message(msg, CONTROL if urgent else TELEMETRY)
        self.runner.kick()

    async def setpoint(self, n: float, e: float, alt: float, sends: int = 5,
                       every: float = 1.5) -> tuple[bool, str]:
        """A DJI_POSE_STAMPED set-point (position north, east, altitude above home), sent until
        the vehicle answers: its echo of the stamp (flown) or a warning "set-point refused: ..."
        (its own words); (ok, words). Not answered after `sends` sends `every` s apart: failed."""
        now = time.time()
        b = self.b
        stamp = (int(now), int((now % 1) * 1e9))
        msg = b.DjiPoseStamped(target_system=self.target[0], sec=stamp[0], nsec=stamp[1],
                               topic_name=int(b.DjiTopicName.DJI_TOPIC_NAME_SETPOINT),
                               position=[n, e, alt], orientation=[0.0, 0.0, 0.0, 1.0])
        what = f"set-point {n:.1f} N, {e:.1f} E, {alt:.1f} m"
        v, loop = self.vehicle, asyncio.get_running_loop()
        heard = len(v.log)
        t0 = loop.time()
        for _ in range(sends):
            self.runner.sync()
            self.ep.send_message(msg, CONTROL)  # the same stamp each time: the vehicle flies it once
            self.runner.kick()
            end = loop.time() + every
            while loop.time() < end:
                if stamp in self._echoes:
                    return True, f"{what}: accepted"
                said = [v.log[i] for i in range(heard, len(v.log))
                        if v.log_levels[i] <= 4 and v.log[i].startswith("set-point refused")]
                if said:
                    return False, f"{what}: refused ({said[-1]})"
                await self.changed(min(0.25, max(0.0, end - loop.time())))
        return False, (f"{what}: no answer after {sends} sends in {loop.time() - t0:.1f} s (the vehicle echoes a "
                       "set-point it flies and says why it refuses one)" + self.link_note())

    async def send_file(self, path: Path, name: str | None = None, overwrite: bool = True) -> tuple[bool, str]:
        from ...proto.storage import FileSource, StorageError

        try:
            src = FileSource(path)
        except StorageError as e:
            return False, str(e)
        try:
            self.runner.sync()
            s = self.ep.send_file(path, self.target, name=name or path.name, overwrite=overwrite, source=src)
            self.runner.kick()
            try:
                while not s.done:
                    await self.changed(0.25)
            except asyncio.CancelledError:  # Ctrl-C at the prompt: the transfer ends here too
                s.cancel(self.runner.sync())
                self.runner.kick()
                raise
            r = s.result
            assert r is not None
            return r.ok, r.message
        finally:
            src.close()

    async def fetch_file(self, name: str) -> tuple[bool, str]:
        if self.store is None:
            return False, "this tablet has no --dir for fetched files"
        self.runner.sync()
        req = self.ep.request_file(name, self.target)
        self.runner.kick()
        while True:
            if req.error is not None:
                return False, req.error
            for obj, what in list(self._file_events.items()):
                if getattr(obj, "request_id", None) == req.id and not obj.offered_again:
                    if what == "file-complete":
                        return True, f"{name}: {obj.file_size} bytes received -> {obj.final_path}"
                    if what in ("file-refused", "file-failed"):
                        return False, obj.reason
            await self.changed(0.25)
