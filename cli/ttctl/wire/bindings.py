"""The dialect a link carries: the generated Python package of the user's dialect (which includes
ttapi.xml's runtime messages), handed to every layer that makes or reads frames.

Nothing under `wire/`, `proto/` or `ends/` imports a generated package: they take a `Bindings`
and find message classes, enums, the parser, the encoder and signing on it (`b.TtFileOffer`,
`b.TtResult`, `b.Parser`). The command line passes the shipped `ttapi` package unless the user
names a dialect of their own (`--dialect`), whose package `ttctl.codegen.cache` generates.

Every generated package carries the same MAVLink framing code (`<package>.mavlink`); what differs
is the set of messages, so encoding works for a message of any package, while parsing and signing
need the registry of the dialect on the link.
"""

from __future__ import annotations

import difflib
from types import ModuleType
from typing import Any


class Bindings:
    """A generated Python package seen as the dialect of a link.

    Attribute access falls through to the package: `b.Heartbeat`, `b.MavCmd`, `b.Parser`."""

    def __init__(self, package: ModuleType, source: str | None = None) -> None:
        self.package = package
        self.name: str = package.__name__
        self.source = source  # the dialect file it was generated from (None: shipped with ttctl)
        self.mavlink: ModuleType = package.mavlink
        self.registry: dict[int, Any] = self.mavlink.REGISTRY
        self.by_name: dict[str, type] = {info.cls.NAME: info.cls for info in self.registry.values()}

    def __getattr__(self, name: str) -> Any:
        try:
            return getattr(self.__dict__["package"], name)
        except (KeyError, AttributeError):
            raise AttributeError(f"dialect {self.__dict__.get('name', '?')} has no {name}") from None

    def __repr__(self) -> str:
        return f"Bindings({self.name}{', ' + self.source if self.source else ''})"

    # -- what the link layer asks of a dialect ------------------------------------------------
    def parser(self, signing: Any = None) -> Any:
        """A stream parser for this dialect's messages."""
        return self.mavlink.Parser(self.registry, signing)

    def encoder(self, sysid: int, compid: int, signing: Any = None) -> Any:
        return self.mavlink.Encoder(sysid, compid, signing)

    def signing(self, key: bytes, link_id: int = 0, allow_unsigned: bool = False) -> Any:
        """MAVLink 2 signing whose signatures cover this dialect's frames (it needs each
        message's CRC_EXTRA to re-seal a frame it signs)."""
        return self.mavlink.Signing(key, link_id, allow_unsigned)

    def sign(self, signing: Any) -> Any:
        """`signing.sign` bound to this dialect's registry (a Signing made by another package
        would look frames up in that package's registry)."""
        registry = self.registry
        return lambda frame: signing.sign(frame, registry)

    def message(self, name: str) -> type:
        """The class of the message called `name` (its MAVLink name, KR_MOTOR_CONTROL, or its
        class name, KrMotorControl); KeyError with a suggestion if there is none."""
        cls = self.by_name.get(name) or self.by_name.get(name.upper())
        if cls is None:
            found = getattr(self.package, name, None)
            if isinstance(found, type) and getattr(found, "MSG_ID", -1) in self.registry:
                cls = found
        if cls is None:
            close = difflib.get_close_matches(name.upper(), list(self.by_name), n=1)
            hint = f" (did you mean {close[0]}?)" if close else ""
            raise KeyError(f"dialect {self.name} has no message {name}{hint}")
        return cls

    def knows(self, msgid: int, crc_extra: int | None = None) -> bool:
        info = self.registry.get(msgid)
        return info is not None and (crc_extra is None or info.crc_extra == crc_extra)


__all__ = ["Bindings"]
