"""ttctl's plugin system: handlers bound to messages, several per msgid.

A plugin is a class deriving from Plugin whose methods are marked with @handles(...): message
classes of the generated bindings (`@handles(m.KrMotorControl)`), or MAVLink names
(`@handles("KR_MOTOR_CONTROL")`). `ttctl gen` writes a skeleton of one
(python/handlers/<dialect>_onboard.py). An end (onboard or tablet) loads plugin modules,
instantiates their Plugin classes, checks every handled message against the dialect it speaks
(a message it does not know, or knows with another definition, is refused before anything
starts: such a handler could never fire), and dispatches every received message to every
handler bound to its msgid, in registration order. A handler that raises is reported and does
not stop the others.
"""

from __future__ import annotations

import importlib.util
import inspect
import os
import stat
import sys
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any, TypeVar

from ..wire.bindings import Bindings

Handler = Callable[[Any, "Context"], None]


class Context:
    """What a handler gets besides the message: a way to send any message of the dialect to the
    other end of the link (`send`: the onboard end answers the tablet, the tablet's plugins talk to
    the vehicle) and to tell the ground stations (`send_gcs`, onboard), to log, to run something
    every so often (`every(seconds, fn)`), the dialect itself (`dialect`: its message classes and
    enums, `ctx.dialect.MyPong(...)`), the vehicle (`vehicle.snapshot()` for its state) when the
    end has one, and `shared`, a dict plugins read each other's results from (the orbit camera
    puts its latest `Camera` under "orbit_camera").

    In a handler, `reply(msg)` answers whoever sent the message being handled (`request`): the
    tablet, or the ground station it came from, on the link it came in on (directly, or back
    through the tablet's bridge), with `target_system`/`target_component` set to the request's
    source if the message has them. `send_gcs(msg)` publishes to every ground station;
    `send_gcs(msg, to=(sysid, compid))` (or `to=sysid`) to one. On the onboard end the user's
    plugins hear ground stations' messages as well as the tablet's: `source` says which
    ("tablet" or "gcs")."""

    def __init__(self, send: Callable[..., None] | None = None, log: Callable[[str], None] | None = None,
                 sysid: int = 1, compid: int = 240, vehicle: Any = None,
                 every: Callable[[float, Callable[[], None]], None] | None = None,
                 send_gcs: Callable[[Any], None] | None = None, dialect: Bindings | None = None) -> None:
        self.dialect: Any = dialect
        self._send = send
        self._send_gcs = send_gcs
        self._log = log
        self._every = every
        self.shared: dict[str, Any] = {}
        self.sysid = sysid
        self.compid = compid
        self.vehicle = vehicle
        self.logged: list[str] = []
        self.request: Any = None  # the message being handled (set by Dispatcher.dispatch)
        self.source: str | None = None  # where it came from: "tablet" or "gcs" (None: outside a handler)
        self._reply: Callable[[Any, bool], None] | None = None
        self._send_to: Callable[[Any, tuple[int, int]], None] | None = None

    def every(self, seconds: float, fn: Callable[[], None]) -> None:
        """Call fn every `seconds` (of the end's clock) from now on; an fn that raises is logged."""
        if self._every is None:
            raise RuntimeError("this context cannot schedule")
        if not seconds > 0:
            raise ValueError("every() wants a positive number of seconds")
        self._every(seconds, fn)

    def send(self, msg: Any, urgent: bool = False) -> None:
        """Queue `msg` for the other end of the link: with telemetry (ahead of file data), or
        with `urgent` ahead of telemetry too, as commands and acks go. ValueError for a message
        the link's dialect lacks."""
        if self._send is None:
            raise RuntimeError("this context cannot send")
        self._check(msg)
        self._send(msg, urgent)

    def send_gcs(self, msg: Any, to: int | tuple[int, int] | None = None) -> None:
        """Send to every ground station (as the autopilot component), or with `to` (a system id,
        or (sysid, compid)) to the one station heard with those ids, on the link it was heard on."""
        if self._send_gcs is None:
            raise RuntimeError("this context has no ground-station link")
        self._check(msg)
        if to is None:
            self._send_gcs(msg)
            return
        if self._send_to is None:
            raise RuntimeError("this context cannot address one ground station")
        peer = (to, 0) if isinstance(to, int) else (int(to[0]), int(to[1]))
        _address(msg, peer)
        self._send_to(msg, peer)

    def reply(self, msg: Any, urgent: bool = False) -> None:
        """Answer the message being handled: to the tablet (as `send`) or to the ground station
        that sent it, on its link; target_system/target_component (if `msg` has them) are set to
        the request's source. RuntimeError outside a handler, ValueError for a message the
        link's dialect lacks."""
        if self._reply is None or self.request is None:
            raise RuntimeError("reply() answers the message being handled: call it from a handler")
        self._check(msg)
        _address(msg, (self.request.get_srcSystem(), self.request.get_srcComponent()))
        self._reply(msg, urgent)

    def _check(self, msg: Any) -> None:
        """A message the link's dialect lacks (or defines otherwise) would be refused by every
        peer that speaks it: say so to the plugin now (ValueError), not by silence later."""
        if self.dialect is None:
            return
        problem = mismatch(self.dialect, type(msg))
        if problem:
            raise ValueError(problem)

    def log(self, text: str) -> None:
        self.logged.append(text)
        if self._log is not None:
            self._log(text)


def _address(msg: Any, peer: tuple[int, int]) -> None:
    """Address `msg` to `peer` where it has the fields for it (a compid 0 leaves it as it is)."""
    if hasattr(msg, "target_system"):
        msg.target_system = peer[0]
    if hasattr(msg, "target_component") and peer[1]:
        msg.target_component = peer[1]


F = TypeVar("F", bound=Callable[..., None])


class PluginError(Exception):
    pass


def handles(*messages: type | str) -> Callable[[F], F]:
    """Mark a plugin method as the handler of these messages: generated message classes, or
    MAVLink message names ("KR_MOTOR_CONTROL")."""
    if not messages:
        raise TypeError("@handles needs at least one message class or name")
    for m in messages:
        if not isinstance(m, str) and not isinstance(getattr(m, "MSG_ID", None), int):
            raise TypeError(f"@handles takes message classes or names, not {m!r}")

    def mark(fn: F) -> F:
        fn.__ttctl_handles__ = tuple(messages)  # type: ignore[attr-defined]
        return fn

    return mark


def mismatch(dialect: Bindings, cls: Any) -> str | None:
    """Why messages of class `cls` cannot travel on a link of `dialect`, or None."""
    name = getattr(cls, "NAME", getattr(cls, "__name__", repr(cls)))
    info = dialect.registry.get(getattr(cls, "MSG_ID", -1))
    if info is None:
        return (f"{name} (id {getattr(cls, 'MSG_ID', '?')}) is not in the dialect this end speaks "
                f"({dialect.name}): start it with --dialect naming the dialect that defines it")
    if info.crc_extra != getattr(cls, "CRC_EXTRA", None) or name != info.cls.NAME:
        return (f"{name} (id {cls.MSG_ID}, CRC_EXTRA {getattr(cls, 'CRC_EXTRA', '?')}) is defined otherwise in "
                f"the dialect this end speaks ({dialect.name}: {info.cls.NAME}, CRC_EXTRA {info.crc_extra}): "
                "regenerate the bindings the plugin imports, or start the end with the plugin's dialect")
    return None


class Plugin:
    """Base of handler plugins. Override `start`/`stop` for set-up and tear-down."""

    def start(self, ctx: Context) -> None:
        pass

    def stop(self) -> None:
        pass

    def handlers(self, dialect: Bindings | None = None) -> list[tuple[int, Handler]]:
        """(msgid, bound method) per handled message. With `dialect`, names are looked up in it
        and every message is checked against it (PluginError if one could never arrive)."""
        out: list[tuple[int, Handler]] = []
        for _, method in inspect.getmembers(self, predicate=inspect.ismethod):
            for m in getattr(method, "__ttctl_handles__", ()):
                where = owner(method)
                if isinstance(m, str):
                    if dialect is None:
                        raise PluginError(f"{where} handles {m} by name: it needs the end's dialect")
                    try:
                        cls: Any = dialect.message(m)
                    except KeyError as e:
                        raise PluginError(f"{where}: {e.args[0]}") from None
                else:
                    cls = m
                    if dialect is not None:
                        problem = mismatch(dialect, cls)
                        if problem:
                            raise PluginError(f"{where} handles {problem}")
                out.append((cls.MSG_ID, method))
        return out


def owner(handler: Handler) -> str:
    """'Plugin.method' of a bound handler, for messages about it."""
    obj = getattr(handler, "__self__", None)
    name = getattr(handler, "__name__", repr(handler))
    return f"{type(obj).__name__}.{name}" if obj is not None else name


class Dispatcher:
    """msgid -> handlers, in registration order. With `dialect`, plugins are checked against it
    as they are added (Plugin.handlers)."""

    def __init__(self, on_error: Callable[[Any, BaseException, str], None] | None = None,
                 dialect: Bindings | None = None) -> None:
        self.dialect = dialect
        self._table: dict[int, list[Handler]] = {}
        self.on_error = on_error
        self.errors = 0

    def bind(self, msgid: int, handler: Handler) -> None:
        self._table.setdefault(msgid, []).append(handler)

    def add(self, plugin: Plugin) -> None:
        for msgid, handler in plugin.handlers(self.dialect):
            self.bind(msgid, handler)

    def handlers_for(self, msgid: int) -> list[Handler]:
        return list(self._table.get(msgid, ()))

    def dispatch(self, msg: Any, ctx: Context, reply: Callable[[Any, bool], None] | None = None,
                 source: str = "tablet") -> int:
        """Run every handler of msg's id, `ctx.reply` answering through `reply` (None: through
        `ctx.send`); returns how many ran."""
        handlers = self._table.get(msg.MSG_ID, ())
        if not handlers:
            return 0
        saved = ctx.request, ctx.source, ctx._reply
        ctx.request, ctx.source = msg, source
        ctx._reply = reply if reply is not None else (lambda m, urgent: ctx.send(m, urgent))
        try:
            for h in handlers:
                try:
                    h(msg, ctx)
                except Exception as e:
                    self.errors += 1
                    if self.on_error is not None:
                        self.on_error(msg, e, owner(h))
        finally:
            ctx.request, ctx.source, ctx._reply = saved
        return len(handlers)


MAX_PLUGIN_BYTES = 16 << 20


def load_plugins(paths: Iterable[str | Path]) -> list[Plugin]:
    """Import each module file and instantiate every Plugin subclass it defines. The file's
    parent folder goes on sys.path so that generated packages beside it import."""
    plugins: list[Plugin] = []
    for raw in paths:
        try:
            st = os.stat(raw)
        except FileNotFoundError:
            raise PluginError(f"{raw}: no such plugin file") from None
        except OSError as e:  # a symlink loop, a folder it may not enter...
            raise PluginError(f"{raw}: {e.strerror or e}") from None
        if not stat.S_ISREG(st.st_mode):
            raise PluginError(f"{raw}: no such plugin file (not a regular file)")
        if st.st_size > MAX_PLUGIN_BYTES:  # the import reads it whole
            raise PluginError(f"{raw}: {st.st_size} bytes; a plugin file over {MAX_PLUGIN_BYTES >> 20} MiB is refused")
        path = Path(raw).resolve()
        for folder in (str(path.parent.parent), str(path.parent)):
            if folder not in sys.path:
                sys.path.append(folder)
        spec = importlib.util.spec_from_file_location(f"ttctl_plugin_{path.stem}", path)
        if spec is None or spec.loader is None:
            raise PluginError(f"{raw}: not a Python module")
        module = importlib.util.module_from_spec(spec)
        try:
            spec.loader.exec_module(module)
        except ModuleNotFoundError as e:
            raise PluginError(f"{raw}: {type(e).__name__}: {e} (the bindings of a dialect? start the end with "
                              "--dialect FILE.xml)") from None
        except Exception as e:
            raise PluginError(f"{raw}: {type(e).__name__}: {e}") from None
        found = [obj for obj in vars(module).values()
                 if inspect.isclass(obj) and issubclass(obj, Plugin) and obj is not Plugin
                 and obj.__module__ == module.__name__]
        if not found:
            raise PluginError(f"{raw}: defines no Plugin subclass")
        plugins.extend(cls() for cls in found)
    return plugins


ENTRY_POINT_GROUP = "ttctl.plugins"


def _instances(obj: Any, where: str) -> list[Plugin]:
    if inspect.isclass(obj) and issubclass(obj, Plugin):
        return [obj()]
    if isinstance(obj, Plugin):
        return [obj]
    if callable(obj):
        made = obj()
        if isinstance(made, Plugin):
            return [made]
    raise PluginError(f"{where}: not a Plugin class, instance or factory")


def load_plugin(spec: str) -> list[Plugin]:
    """`path/to/file.py` (every Plugin class in it) or `module:attr` (a Plugin class, instance
    or factory)."""
    if spec.endswith(".py") or "/" in spec:
        return load_plugins([spec])
    module_name, sep, attr = spec.partition(":")
    if not sep or not module_name or not attr:
        raise PluginError(f"{spec}: give a file (path/to/plugin.py) or module:attr")
    try:
        module = importlib.import_module(module_name)
    except Exception as e:
        raise PluginError(f"{spec}: cannot import {module_name}: {type(e).__name__}: {e}") from None
    obj = getattr(module, attr, None)
    if obj is None:
        raise PluginError(f"{spec}: {module_name} has no {attr}")
    return _instances(obj, spec)


def entry_point_plugins() -> list[Plugin]:
    """Every plugin installed packages declare in the `ttctl.plugins` entry-point group."""
    from importlib.metadata import entry_points

    out: list[Plugin] = []
    for ep in entry_points(group=ENTRY_POINT_GROUP):
        try:
            out.extend(_instances(ep.load(), f"entry point {ep.name}"))
        except PluginError:
            raise
        except Exception as e:
            raise PluginError(f"entry point {ep.name} ({ep.value}): {type(e).__name__}: {e}") from None
    return out
