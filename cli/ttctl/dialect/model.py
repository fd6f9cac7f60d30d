"""The dialect model: what the XML says, plus what MAVLink 2 derives from it.

Wire order, payload lengths and CRC_EXTRA follow pymavlink's mavparse exactly; the test
suite checks them against pymavlink's generated modules for every shipped dialect.
"""

from __future__ import annotations

import re
from typing import Any, Literal, NamedTuple

from .diagnostics import Loc, SourceText

# type -> (size in bytes, struct format character)
BASE_TYPES: dict[str, tuple[int, str]] = {
    "float": (4, "f"),
    "double": (8, "d"),
    "char": (1, "c"),
    "int8_t": (1, "b"),
    "uint8_t": (1, "B"),
    "int16_t": (2, "h"),
    "uint16_t": (2, "H"),
    "int32_t": (4, "i"),
    "uint32_t": (4, "I"),
    "int64_t": (8, "q"),
    "uint64_t": (8, "Q"),
}

INTEGER_RANGES: dict[str, tuple[int, int]] = {
    "char": (0, 0xFF),
    "int8_t": (-(2**7), 2**7 - 1),
    "uint8_t": (0, 2**8 - 1),
    "int16_t": (-(2**15), 2**15 - 1),
    "uint16_t": (0, 2**16 - 1),
    "int32_t": (-(2**31), 2**31 - 1),
    "uint32_t": (0, 2**32 - 1),
    "int64_t": (-(2**63), 2**63 - 1),
    "uint64_t": (0, 2**64 - 1),
}

MAVLINK2_HEADER = 10  # magic, len, incompat, compat, seq, sysid, compid, msgid[3]
MAVLINK2_CRC = 2
MAVLINK2_SIGNATURE = 13
MAX_PAYLOAD = 255
MAX_MSG_ID = 0xFFFFFF
MAX_FIELDS = 64

Sender = Literal["tablet", "onboard", "any"]
SENDER_RE = re.compile(r"\[sender:\s*([A-Za-z]+)\s*\]")
SENDERS: tuple[str, ...] = ("tablet", "onboard", "any")
SPANS_TAG = "[spans-packets]"  # in a description: this message is meant to span packets
RUNTIME_TAG = "[runtime]"  # in a description: ttctl's runtimes handle it themselves (no skeleton for it)


def frame_length(payload: int, signed: bool = False) -> int:
    return MAVLINK2_HEADER + payload + MAVLINK2_CRC + (MAVLINK2_SIGNATURE if signed else 0)


class Deprecation(NamedTuple):
    kind: str  # deprecated | superseded
    since: str
    replaced_by: str
    text: str = ""


class Field:
    """One field of a message. `type` is the base type (uint8_t, float, char...);
    `array_length` is 0 for a scalar. What only the generators need (description, units,
    display...) is read from the XML element on first use, as is the location."""

    __slots__ = (
        "_details",
        "_el",
        "_line",
        "_src",
        "array_length",
        "enum",
        "extension",
        "mavlink_version",
        "name",
        "type",
        "wire_offset",
    )

    def __init__(self, name: str, type: str, array_length: int, loc: Loc | None = None, enum: str | None = None,
                 extension: bool = False, mavlink_version: bool = False, element: Any = None,
                 **details: Any) -> None:
        self.name = name
        self.type = type
        self.array_length = array_length
        self.enum = enum
        self.extension = extension
        self.mavlink_version = mavlink_version  # declared as uint8_t_mavlink_version
        self.wire_offset = 0
        self._src: SourceText | None = loc.source if loc is not None else None
        self._line = loc.line if loc is not None else 0
        self._el = element
        self._details: dict[str, Any] | None = details if element is None else None

    @classmethod
    def at(cls, src: Any, line: int, name: str, type: str, array_length: int, enum: str | None,
           extension: bool, mavlink_version: bool, element: Any) -> Field:
        f = cls(name, type, array_length, None, enum, extension, mavlink_version, element)
        f._src, f._line = src, line
        return f

    def __repr__(self) -> str:
        return f"Field({self.name} {self.declared_type})"

    @property
    def loc(self) -> Loc:
        src = self._src if self._src is not None else SourceText("<built>", None)
        return Loc(src, self._line, "field", "name")

    def _detail(self, key: str) -> Any:
        if self._details is None:
            from .loader import field_details

            self._details = field_details(self._el)
            self._el = None
        return self._details.get(key)

    @property
    def description(self) -> str:
        return self._detail("description") or ""

    @property
    def display(self) -> str | None:
        return self._detail("display")

    @property
    def units(self) -> str | None:
        return self._detail("units")

    @property
    def multiplier(self) -> str | None:
        return self._detail("multiplier")

    @property
    def print_format(self) -> str | None:
        return self._detail("print_format")

    @property
    def invalid(self) -> str | None:
        return self._detail("invalid")

    @property
    def instance(self) -> bool:
        return bool(self._detail("instance"))

    @property
    def type_size(self) -> int:
        return BASE_TYPES[self.type][0]

    @property
    def wire_length(self) -> int:
        return BASE_TYPES[self.type][0] * (self.array_length or 1)

    @property
    def is_array(self) -> bool:
        return self.array_length > 0

    @property
    def is_string(self) -> bool:
        return self.type == "char" and self.array_length > 0

    @property
    def is_float(self) -> bool:
        return self.type in ("float", "double")

    @property
    def declared_type(self) -> str:
        t = "uint8_t_mavlink_version" if self.mavlink_version else self.type
        return f"{t}[{self.array_length}]" if self.array_length else t


class Message:
    """A message: fields in declared order, plus what finalize() derives (wire order,
    lengths, CRC_EXTRA)."""

    __slots__ = (
        "complete",
        "crc_extra",
        "deprecated",
        "description",
        "fields",
        "id",
        "loc",
        "min_length",
        "name",
        "payload_length",
        "wip",
        "wire_fields",
    )

    def __init__(self, id: int, name: str, loc: Loc, description: str = "") -> None:
        self.id = id
        self.name = name
        self.loc = loc
        self.description = description
        self.fields: list[Field] = []
        self.deprecated: Deprecation | None = None
        self.wip = False
        self.complete = True  # False when a field or the id could not be read (already reported)
        self.wire_fields: list[Field] = []
        self.payload_length = 0
        self.min_length = 0
        self.crc_extra = 0

    def __repr__(self) -> str:
        return f"Message({self.id} {self.name})"

    @property
    def base_fields(self) -> list[Field]:
        return [f for f in self.wire_fields if not f.extension]

    @property
    def extension_fields(self) -> list[Field]:
        return [f for f in self.wire_fields if f.extension]

    @property
    def sender(self) -> str | None:
        """Which end sends this message, from a `[sender: tablet|onboard|any]` tag in the
        description (ttctl's convention; other tools see plain description text)."""
        m = SENDER_RE.search(self.description)
        return m.group(1).lower() if m else None

    @property
    def spans_packets(self) -> bool:
        return SPANS_TAG in self.description

    @property
    def runtime(self) -> bool:
        """Handled by ttctl's runtimes (the file transfer, say): skeletons leave it out."""
        return RUNTIME_TAG in self.description

    def field(self, name: str) -> Field | None:
        for f in self.fields:
            if f.name == name:
                return f
        return None

    def finalize(self) -> None:
        """Wire order (base fields stable-sorted by type size, largest first; extensions
        after, unsorted), offsets, lengths and CRC_EXTRA."""
        base = [f for f in self.fields if not f.extension]
        ext = [f for f in self.fields if f.extension]
        self.wire_fields = sorted(base, key=lambda f: -BASE_TYPES[f.type][0]) + ext
        offset = 0
        for f in self.wire_fields:
            f.wire_offset = offset
            offset += f.wire_length
            if not f.extension:
                self.min_length = offset
        self.payload_length = offset
        self.crc_extra = crc_extra(self.name, self.wire_fields)


def crc_extra(name: str, wire_fields: list[Field]) -> int:
    """CRC-16/MCRF4XX over "NAME " and "type name " (+ array length byte) of each base field
    in wire order, folded to one byte."""
    from fastcrc import crc16

    buf = bytearray(name.encode("ascii", "replace") + b" ")
    for f in wire_fields:
        if f.extension:
            continue
        buf += f.type.encode() + b" " + f.name.encode("ascii", "replace") + b" "
        if f.array_length:
            buf.append(f.array_length & 0xFF)
    crc = crc16.mcrf4xx(bytes(buf))
    return (crc & 0xFF) ^ (crc >> 8)


class EnumParam:
    """A <param> of an enum entry (MAV_CMD's command parameters)."""

    __slots__ = ("default", "description", "enum", "increment", "index", "label", "max_value", "min_value",
                 "reserved", "units")

    def __init__(self, index: int, description: str = "", label: str | None = None, units: str | None = None,
                 enum: str | None = None, reserved: bool = False, default: str | None = None,
                 min_value: str | None = None, max_value: str | None = None, increment: str | None = None) -> None:
        self.index = index
        self.description = description
        self.label = label
        self.units = units
        self.enum = enum
        self.reserved = reserved
        self.default = default
        self.min_value = min_value
        self.max_value = max_value
        self.increment = increment

    def __repr__(self) -> str:
        return f"EnumParam({self.index}, {self.label!r})"


class EnumEntry:
    """An enum entry. Its description, params and deprecation are read from the XML element
    on first use: validation never needs them, and MAV_CMD alone has thousands of params."""

    __slots__ = ("_deprecated", "_description", "_el", "_params", "_wip", "autovalue", "loc", "name", "value")

    def __init__(self, name: str, value: int, loc: Loc, autovalue: bool = False, element: Any = None) -> None:
        self.name = name
        self.value = value
        self.loc = loc
        self.autovalue = autovalue
        self._el = element
        self._description = ""
        self._params: list[EnumParam] = []
        self._deprecated: Deprecation | None = None
        self._wip = False

    def __repr__(self) -> str:
        return f"EnumEntry({self.name} = {self.value})"

    def _details(self) -> None:
        if self._el is not None:
            from .loader import entry_details

            self._description, self._params, self._deprecated, self._wip = entry_details(self._el)
            self._el = None

    @property
    def description(self) -> str:
        self._details()
        return self._description

    @property
    def params(self) -> list[EnumParam]:
        self._details()
        return self._params

    @property
    def deprecated(self) -> Deprecation | None:
        self._details()
        return self._deprecated

    @property
    def wip(self) -> bool:
        self._details()
        return self._wip


class Enum:
    __slots__ = ("bitmask", "deprecated", "description", "entries", "loc", "name", "parts", "wip")

    def __init__(self, name: str, loc: Loc, description: str = "", bitmask: bool = False) -> None:
        self.name = name
        self.loc = loc
        self.description = description
        self.bitmask = bitmask
        self.entries: list[EnumEntry] = []
        self.deprecated: Deprecation | None = None
        self.wip = False
        self.parts: list[Loc] = []  # every <enum> element that contributed (merged across includes)

    def __repr__(self) -> str:
        return f"Enum({self.name}, {len(self.entries)} entries)"

    def entry(self, name: str) -> EnumEntry | None:
        for e in self.entries:
            if e.name == name:
                return e
        return None


class DialectFile:
    __slots__ = ("dialect", "enums", "includes", "loc", "messages", "path", "resolved", "version")

    def __init__(self, path: str, loc: Loc) -> None:
        self.path = path
        self.loc = loc
        self.includes: list[tuple[str, Loc]] = []  # raw text, where
        self.resolved: list[str] = []  # real paths of included files
        self.version: int | None = None
        self.dialect: int | None = None
        self.messages: list[Message] = []
        self.enums: list[Enum] = []  # as declared in this file (before merge)

    def __repr__(self) -> str:
        return f"DialectFile({self.path})"

    @property
    def stem(self) -> str:
        base = self.path.rsplit("/", 1)[-1]
        return base[:-4] if base.lower().endswith(".xml") else base


class Dialect:
    """A loaded dialect: its files (dependencies first, root last), every message, the
    enums merged across files."""

    def __init__(self, root: DialectFile, files: list[DialectFile], messages: list[Message],
                 enums: list[Enum]) -> None:
        self.root = root
        self.files = files
        self.messages = messages
        self.enums = enums
        self.enums_by_name = {e.name: e for e in enums}
        self.incomplete = False  # an include could not be found or read (see the loader)
        self.messages_by_id: dict[int, Message] = {}
        self.messages_by_name: dict[str, Message] = {}
        for m in messages:
            if m.complete:
                self.messages_by_id.setdefault(m.id, m)
                self.messages_by_name.setdefault(m.name, m)

    @property
    def name(self) -> str:
        return self.root.stem

    @property
    def version(self) -> int:
        for f in reversed(self.files):
            if f.version is not None:
                return f.version
        return 3

    @property
    def own_messages(self) -> list[Message]:
        """Messages defined in the root file itself."""
        return self.root.messages

    def message_file(self, msg: Message) -> DialectFile:
        for f in self.files:
            if msg in f.messages:
                return f
        raise KeyError(msg.name)
