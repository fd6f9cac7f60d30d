"""Java: bindings for Android (API 24+, Java 8 syntax, builds with --release 8 and 11), a
conformance program, and tablet command skeletons (command pattern, one command queue).

Layout under the output root, for a dialect whose identifier is `ttapi`:

  java/ttctl/ttapi/Ttapi.java        registry: msgid -> MessageInfo, payload -> message object
  java/ttctl/ttapi/runtime/          framing, CRC, stream parser, dispatcher, links, commands
  java/ttctl/ttapi/msg/              one class per message
  java/ttctl/ttapi/enums/            one class of int/long constants per enum
  java/ttctl/ttapi/commands/         skeletons: Send<Msg> per message the tablet sends,
                                     Receive<Msg> per message it receives (yours to edit)
  java/Conformance.java              the `D <hex>` / `E <json>` conformance program

Java types of fields (documented in every message class, see TYPE_MAPPING):
  int8_t -> byte, uint8_t -> int, int16_t -> short, uint16_t -> int, int32_t -> int,
  uint32_t -> long, int64_t -> long, uint64_t -> long (two's complement bits; Unsigned helps),
  float -> float, double -> double, char[N] -> byte[] (exact bytes; String helpers),
  uint8_t[N] and int8_t[N] -> byte[], other arrays -> arrays of the scalar mapping.
"""

from __future__ import annotations

import re
from typing import Any

from ..dialect.model import INTEGER_RANGES, Dialect, Enum, Field, Message
from ..dialect.names import JAVA_KEYWORDS, JAVA_RESERVED_TYPES, camel
from .engine import Output, dialect_ident, receives, sends
from .text import wrap

name = "java"

# base type -> Java type of a scalar field
_SCALAR = {
    "int8_t": "byte",
    "uint8_t": "int",
    "int16_t": "short",
    "uint16_t": "int",
    "int32_t": "int",
    "uint32_t": "long",
    "int64_t": "long",
    "uint64_t": "long",
    "float": "float",
    "double": "double",
    "char": "byte",
}
# base type -> element type of an array field: the same, but uint8_t arrays stay raw bytes
_ARRAY = {**_SCALAR, "uint8_t": "byte"}
# Wire put/get method suffix per base type (scalars; arrays use the same per element, except
# byte arrays which are copied whole).
_WIRE = {
    "int8_t": "I8",
    "uint8_t": "U8",
    "int16_t": "I16",
    "uint16_t": "U16",
    "int32_t": "I32",
    "uint32_t": "U32",
    "int64_t": "I64",
    "uint64_t": "I64",
    "float": "F32",
    "double": "F64",
    "char": "I8",
}
# unsigned types that live in wider Java types: packing checks their range
_RANGES = {"uint8_t", "uint16_t", "uint32_t"}

TYPE_MAPPING = [
    ("int8_t", "byte"),
    ("uint8_t", "int (0..255)"),
    ("int16_t", "short"),
    ("uint16_t", "int (0..65535)"),
    ("int32_t", "int"),
    ("uint32_t", "long (0..4294967295)"),
    ("int64_t", "long"),
    ("uint64_t", "long holding the two's complement bits (see Unsigned)"),
    ("float / double", "float / double (bit-exact, NaN payloads kept)"),
    ("char[N]", "byte[] of at most N bytes, the exact bytes (String helpers use UTF-8)"),
    ("uint8_t[N] / int8_t[N]", "byte[] (uint8_t: read with &amp; 0xFF; at most N bytes for uint8_t)"),
    ("other T[N]", "an array of N elements of T's mapping (uint16_t[] int[], uint32_t[] long[]...)"),
]

# The runtime package, one class per file. Generated code in other packages refers to these by
# simple name (imported) unless a message or skeleton class has the same simple name.
RUNTIME_FILES = [
    "Crc", "Wire", "Unsigned", "MavlinkMessage", "MessageInfo", "MavlinkDialect",
    "DecodeException", "Frame", "Parser", "Dispatcher", "Link", "UdpLink", "CommandContext",
    "CommandException", "Command", "MessageMatcher", "SendCommand", "ReceiveCommand", "CommandQueue",
    "LinkScheduler", "DjiLink",
    "Packetizer", "PacketReceiver", "Signing", "UdpForward", "Callbacks", "Session",
]
RUNTIME_CLASSES = frozenset(RUNTIME_FILES + ["SendSetpoint"])
# File transfer (package <root>.transfer), for dialects that have ttctl's file messages.
TRANSFER_FILES = ["RangeSet", "Names", "TransferConfig", "TransferResult", "Transfer", "LossEstimate", "FileSender",
                  "ReceiveDir", "Partial", "FileReceiver", "FileFetch", "FileTransfers"]
TRANSFER_MESSAGES = {"TT_FILE_OFFER", "TT_FILE_STATUS", "TT_FILE_REASON", "TT_FILE_DATA", "TT_FILE_DATA_WIDE",
                     "TT_FILE_REQUEST"}


def package(d: Dialect, override: str | None = None) -> str:
    """The Java root package of a dialect: `override` (--java-package), else ttctl.<ident>
    (ident_ if it is a Java keyword)."""
    if override:
        return override
    ident = dialect_ident(d)
    return f"ttctl.{ident}_" if ident in JAVA_KEYWORDS else f"ttctl.{ident}"


def registry_class(d: Dialect) -> str:
    """The registry class: the dialect's name in CamelCase, + "Dialect" if that would shadow a
    java.lang or runtime class."""
    n = camel(dialect_ident(d))
    return f"{n}Dialect" if n in JAVA_RESERVED_TYPES or n in RUNTIME_CLASSES or n == "Conformance" else n


def class_name(m: Message) -> str:
    return camel(m.name)


def java_type(f: Field) -> str:
    if f.array_length:
        return _ARRAY[f.type] + "[]"
    return _SCALAR[f.type]


def is_text(f: Field) -> bool:
    return f.type == "char" and f.array_length > 0


def is_bytes(f: Field) -> bool:
    """byte[] fields: char[N], uint8_t[N], int8_t[N]."""
    return f.array_length > 0 and f.type in ("char", "uint8_t", "int8_t")


def default_value(f: Field, d: Dialect) -> str | None:
    """Field initializer, or None for Java's zero default."""
    if f.mavlink_version:
        return str(d.version)
    if f.array_length:
        return f"new {_ARRAY[f.type]}[{f.array_length}]"
    return None


def _where(m: Message, f: Field) -> str:
    return f'"{m.name}.{f.name}"'


def pack_lines(m: Message, f: Field) -> list[str]:
    """Statements writing field f of `this` into byte[] out (payload offset 0)."""
    off = f.wire_offset
    ref = f"this.{f.name}"
    n = f.array_length
    if n == 0:
        suffix = _WIRE[f.type]
        if f.type in _RANGES:
            return [f"Wire.put{suffix}(out, {off}, {ref}, {_where(m, f)});"]
        return [f"Wire.put{suffix}(out, {off}, {ref});"]
    if is_bytes(f):
        exact = "false" if f.type in ("char", "uint8_t") else "true"
        return [f"Wire.putBytes(out, {off}, {ref}, {n}, {exact}, {_where(m, f)});"]
    size = f.type_size
    suffix = _WIRE[f.type]
    lines = [f"Wire.checkLength({ref} == null ? -1 : {ref}.length, {n}, {_where(m, f)});",
             f"for (int i = 0; i < {n}; i++) {{"]
    if f.type in _RANGES:
        lines.append(f"    Wire.put{suffix}(out, {off} + {size} * i, {ref}[i], {_where(m, f)});")
    else:
        lines.append(f"    Wire.put{suffix}(out, {off} + {size} * i, {ref}[i]);")
    lines.append("}")
    return lines


def unpack_lines(m: Message, f: Field) -> list[str]:
    """Statements reading field f into message `m` from byte[] b at offset o."""
    off = f.wire_offset
    n = f.array_length
    suffix = _WIRE[f.type]
    if n == 0:
        return [f"m.{f.name} = Wire.get{suffix}(b, o + {off});"]
    if is_bytes(f):
        return [f"m.{f.name} = Wire.getBytes(b, o + {off}, {n});"]
    size = f.type_size
    return [f"m.{f.name} = new {_ARRAY[f.type]}[{n}];",
            f"for (int i = 0; i < {n}; i++) {{",
            f"    m.{f.name}[i] = Wire.get{suffix}(b, o + {off} + {size} * i);",
            "}"]


def to_string_expr(f: Field) -> str:
    ref = f"this.{f.name}"
    if is_text(f):
        return f"Wire.quote({ref})"
    if f.array_length:
        if f.type == "uint8_t":
            return f"Wire.unsignedBytes({ref})"
        if f.type == "uint64_t":
            return f"Unsigned.toString({ref})"
        return f"java.util.Arrays.toString({ref})"
    if f.type == "uint64_t":
        return f"Unsigned.toString({ref})"
    return ref


# --- Javadoc ------------------------------------------------------------------------------

_DOC_ESCAPES = {"&": "&amp;", "<": "&lt;", ">": "&gt;", "@": "&#64;", "\\": "&#92;", "\t": " ", "\r": " ",
                "\n": " "}
_DOC_PLAIN = re.compile(r"[ -~]*\Z")
_DOC_SPECIAL = re.compile(r"[&<>@\\]|[^ -~]")


def _escape_doc(text: str) -> str:
    """Text for Javadoc: HTML-escaped, ASCII only (&#N; for the rest), no comment end."""
    if _DOC_PLAIN.match(text) and not any(c in text for c in "&<>@\\"):
        return text.replace("*/", "*&#47;")

    def sub(m: re.Match[str]) -> str:
        ch = m.group(0)
        return _DOC_ESCAPES.get(ch) or f"&#{ord(ch)};"

    return _DOC_SPECIAL.sub(sub, text).replace("*/", "*&#47;")


def javadoc(text: str | list[str], indent: int = 0, width: int = 100) -> str:
    """A Javadoc block (no trailing newline); each string of a list is a paragraph. Text is
    escaped for Javadoc and Java comments; a paragraph starting with "RAW:" is Javadoc already."""
    paras = [text] if isinstance(text, str) else list(text)
    pad = " " * indent
    lines: list[str] = []
    for p in paras:
        raw = p.startswith("RAW:")
        p = " ".join((p[4:] if raw else p or "").split())
        if not p:
            continue
        if lines:
            lines.append("<p>")
        lines.extend(wrap(p if raw else _escape_doc(p), max(40, width - indent - 3)))
    if not lines:
        lines = ["(no description)"]
    if len(lines) == 1 and len(lines[0]) + indent + 7 <= width:
        return f"{pad}/** {lines[0]} */"
    body = "\n".join(f"{pad} * {x}".rstrip() for x in lines)
    return f"{pad}/**\n{body}\n{pad} */"


def reply_conditions(m: Message, d: Dialect) -> list[str]:
    """Java conditions on `reply` (the expected reply message) for a Send skeleton."""
    r = expected_reply(m, d)
    if r is None:
        return []
    reply, fields = r
    stamped = stamped_fields(m)
    conds = [f"reply.{f} == this.{f}" if f not in stamped else f"reply.{f} == (this.{f} != 0 ? this.{f} : {stamped[f]})"
             for f in fields]
    if scalar_target(reply):
        conds.append("(reply.target_system == 0 || reply.target_system == ctx.sysId())")
    return conds


def field_doc(f: Field, d: Dialect | None = None, root: str | None = None) -> str:
    """Javadoc paragraph (RAW) of a field: description, units, MAVLink type, enum (linked when the
    dialect has it), extension."""
    text = f.description or f.name
    if f.units:
        text += f" [{f.units}]"
    notes = [f.declared_type]
    if f.enum:
        if d is not None and f.enum in d.enums_by_name:
            notes.append(f"enum {{@link {root or package(d)}.enums.{camel(f.enum)}}}")
        else:
            notes.append(f"enum {_escape_doc(camel(f.enum))}")
    if f.extension:
        notes.append("extension")
    return f"RAW:{_escape_doc(' '.join(text.split()))} ({'; '.join(notes)})"


def java_string(s: str) -> str:
    """A Java string literal (ASCII; other characters as \\u escapes)."""
    out = ['"']
    for ch in s:
        o = ord(ch)
        if ch in '"\\':
            out.append("\\" + ch)
        elif 32 <= o < 127:
            out.append(ch)
        elif o < 0x10000:
            out.append(f"\\u{o:04x}")
        else:
            o -= 0x10000
            out.append(f"\\u{0xD800 + (o >> 10):04x}\\u{0xDC00 + (o & 0x3FF):04x}")
    out.append('"')
    return "".join(out)


# --- enums --------------------------------------------------------------------------------

def enum_type(e: Enum) -> str:
    return "int" if all(-(2**31) <= x.value < 2**31 for x in e.entries) else "long"


def java_long(v: int) -> str:
    if -(2**31) <= v < 2**31:
        return str(v)
    if v == -(2**63):
        return "Long.MIN_VALUE"
    if v >= 2**63:  # not representable: keep the bits
        v -= 2**64
    return f"{v}L"


def enum_table(e: Enum) -> list[tuple[int, str]]:
    """(value, name) sorted by value, first name of each value."""
    seen: dict[int, str] = {}
    for x in e.entries:
        v = x.value - 2**64 if x.value >= 2**63 else x.value
        seen.setdefault(v, x.name)
    return sorted(seen.items())


# --- conformance --------------------------------------------------------------------------

def json_out(f: Field) -> str:
    """Statement appending the JSON value of m.<field> to StringBuilder sb."""
    ref = f"m.{f.name}"
    n = f.array_length
    t = f.type
    if t == "char":
        return f"Json.text(sb, {ref});" if n else f"Json.textChar(sb, {ref});"
    if n:
        fn = {
            "uint8_t": "u8s", "int8_t": "i8s", "int16_t": "shorts", "uint16_t": "ints", "int32_t": "ints",
            "uint32_t": "longs", "int64_t": "longs", "uint64_t": "ulongs", "float": "f32s", "double": "f64s",
        }[t]
        return f"Json.{fn}(sb, {ref});"
    if t == "uint64_t":
        return f"sb.append(Unsigned.toString({ref}));"
    if t == "float":
        return f"Json.f32(sb, {ref});"
    if t == "double":
        return f"Json.f64(sb, {ref});"
    return f"sb.append({ref});"


_INT_LIMITS = {
    "int8_t": ("-128", "127"),
    "uint8_t": ("0", "255"),
    "int16_t": ("-32768", "32767"),
    "uint16_t": ("0", "65535"),
    "int32_t": ("Integer.MIN_VALUE", "Integer.MAX_VALUE"),
    "uint32_t": ("0", "4294967295L"),
    "int64_t": ("Long.MIN_VALUE", "Long.MAX_VALUE"),
}


def json_in(f: Field) -> str:
    """Expression converting JSON value v to the field's Java type."""
    n = f.array_length
    t = f.type
    w = f'"{f.name}"'
    if t == "char":
        return f"Json.text(v, {n}, {w})" if n else f"Json.textChar(v, {w})"
    if n:
        if t == "uint8_t":
            return f"Json.u8s(v, {n}, {w})"
        if t == "int8_t":
            return f"Json.i8s(v, {n}, {w})"
        if t == "int16_t":
            return f"Json.shorts(v, {n}, {w})"
        if t in ("uint16_t", "int32_t"):
            lo, hi = _INT_LIMITS[t]
            return f"Json.ints(v, {n}, {lo}, {hi}, {w})"
        if t in ("uint32_t", "int64_t"):
            lo, hi = _INT_LIMITS[t]
            return f"Json.longs(v, {n}, {lo}, {hi}, {w})"
        if t == "uint64_t":
            return f"Json.ulongs(v, {n}, {w})"
        if t == "float":
            return f"Json.f32s(v, {n}, {w})"
        return f"Json.f64s(v, {n}, {w})"
    if t == "uint64_t":
        return f"Json.uint64(v, {w})"
    if t == "float":
        return f"Json.f32(v, {w})"
    if t == "double":
        return f"Json.f64(v, {w})"
    lo, hi = _INT_LIMITS[t]
    cast = {"int8_t": "(byte) ", "int16_t": "(short) ", "uint8_t": "(int) ", "uint16_t": "(int) ",
            "int32_t": "(int) "}.get(t, "")
    return f"{cast}Json.integer(v, {lo}, {hi}, {w})"


# --- skeletons ----------------------------------------------------------------------------

_ANSWERED_RE = re.compile(r"\b(?:answered|acknowledged|replied to) by ([A-Z][A-Z0-9_]*)", re.IGNORECASE)
_SAME_RE = re.compile(r"\bsame ([a-z][a-z0-9_]*)")


def expected_reply(m: Message, d: Dialect) -> tuple[Message, list[str]] | None:
    """The reply a sent message waits for, from its description ("Answered by X with the same
    f"): X and the fields that must match (scalar integer fields both messages have)."""
    hit = _ANSWERED_RE.search(m.description or "")
    if not hit:
        return None
    reply = d.messages_by_name.get(hit.group(1).upper())
    if reply is None or reply is m:
        return None
    fields = []
    for name_ in _SAME_RE.findall(m.description or ""):
        a, b = m.field(name_), reply.field(name_)
        if a and b and not a.array_length and not b.array_length and not a.is_float and not b.is_float \
                and a.type != "char" and b.type != "char" and name_ not in fields:
            fields.append(name_)
    return reply, fields


# Java types narrower than an enum's constants (int, or long past int): a field of such a type
# typed by an enum takes the constants' type in a Send skeleton, range-checked into the field.
_WIDTH = {"byte": 1, "short": 2, "int": 4, "long": 8}


def ctor_type(f: Field, d: Dialect) -> str:
    """The type of a Send skeleton's constructor parameter for field f: the field's Java type,
    or for a scalar typed by an enum whose constants are wider (a byte field, int constants)
    the constants' type, so that `new SendX(SomeEnum.ENTRY)` compiles without a cast."""
    e = d.enums_by_name.get(f.enum) if f.enum and not f.array_length else None
    own = java_type(f)
    if e is None or own not in _WIDTH:
        return own
    wider = enum_type(e)
    return wider if _WIDTH[wider] > _WIDTH[own] else own


def ctor_assign(m: Message, f: Field, d: Dialect) -> str:
    """The expression a Send skeleton's constructor assigns to field f: the argument, range
    checked and narrowed when ctor_type widened it; a copy of an array (a retry must pack the
    values given, whatever the caller does with its array afterwards)."""
    if f.array_length:
        return f"{f.name} == null ? null : {f.name}.clone()"
    own = java_type(f)
    if ctor_type(f, d) == own:
        return f.name
    lo, hi = (str(v) + ("L" if abs(v) >= 2**31 else "") for v in INTEGER_RANGES[f.type])
    return f'({own}) Wire.checkRange({f.name}, {lo}, {hi}, "{m.name}.{f.name}", "{f.type}")'


def ctor_doc(m: Message, d: Dialect) -> str:
    """The Javadoc of a Send skeleton's constructor."""
    text = "The values to send, packed anew on every try."
    narrowed = [f for f in m.fields if ctor_type(f, d) != java_type(f)]
    if narrowed:
        one = len(narrowed) == 1
        names = ", ".join(f"{f.name} ({f.declared_type})" for f in narrowed)
        text += (f" {names} take{'s' * one} the constants of {'its enum' if one else 'their enums'} as they are and "
                 f"{'is' if one else 'are'} range-checked into the field{'' if one else 's'}.")
    if any(f.array_length for f in m.fields):
        text += " Arrays are copied: changing yours afterwards changes nothing sent."
    return text


# Fields of a contract message the runtime itself reads or fills (dialects/ttapi.xml): the runtime
# uses the message only if the dialect has it with these fields (the generated runtime of a
# dialect without ttapi.xml, such as common.xml, still compiles).
CONTRACT_FIELDS = {
    "TT_ACTION_COMMAND": ("command_id", "time_usec"),
    "TT_COMMAND_ACK": ("command_id", "result"),
    "TT_LOG": ("id", "severity", "chunk_seq"),  # and its text, a char array (checked below)
    "HEARTBEAT": ("type", "autopilot"),  # the Session's own, a second (MAV_TYPE_GCS, MAV_AUTOPILOT_INVALID)
}


def has_contract(d: Dialect, name: str) -> bool:
    """Whether the dialect has the contract message `name` (complete, with the fields the
    runtime uses, as scalars)."""
    m = d.messages_by_name.get(name)
    if m is None or not m.complete:
        return False
    if name == "TT_LOG" and ((t := m.field("text")) is None or t.type != "char" or not t.array_length):
        return False
    return all((f := m.field(n)) is not None and not f.array_length and not f.is_float and f.type != "char"
               for n in CONTRACT_FIELDS[name])


def has_setpoints(d: Dialect) -> bool:
    """Whether the dialect has answered set-points (SendSetpoint): ttapi.xml's DJI_POSE_STAMPED
    with its SETPOINT topic, and TT_LOG for the refusals."""
    m = d.messages_by_name.get("DJI_POSE_STAMPED")
    if m is None or not m.complete or not has_contract(d, "TT_LOG"):
        return False
    shape = {"target_system": ("uint8_t", 0), "sec": ("uint32_t", 0), "nsec": ("uint32_t", 0),
             "topic_name": ("uint8_t", 0), "position": ("double", 3), "orientation": ("double", 4)}
    for name, (t, n) in shape.items():
        f = m.field(name)
        if f is None or f.type != t or (f.array_length or 0) != n:
            return False
    topics = next((e for e in d.enums if e.name == "DJI_TOPIC_NAME"), None)
    return topics is not None and any(x.name == "DJI_TOPIC_NAME_SETPOINT" for x in topics.entries)


def stamped_fields(m: Message) -> dict[str, str]:
    """The fields of a sent message the command queue fills when the app leaves them 0: a scalar
    `command_id` (uint16_t or uint32_t) gets the queue's id for the submission, and then a
    `time_usec` (uint64_t) the time it was submitted (so an (id, time) pair is never reused,
    even by an app that restarts and numbers its commands afresh). Name -> what fills it."""
    cid = m.field("command_id")
    if cid is None or cid.array_length or cid.type not in ("uint16_t", "uint32_t"):
        return {}
    out = {"command_id": "ctx.commandId()"}
    t = m.field("time_usec")
    if t is not None and not t.array_length and t.type == "uint64_t":
        out["time_usec"] = "ctx.issuedUsec()"
    return out


def scalar_target(m: Message) -> bool:
    f = m.field("target_system")
    return bool(f and not f.array_length and f.type == "uint8_t")


class _Refs:
    """How generated code outside the runtime package names runtime and message classes:
    imported simple names unless two classes would share one."""

    def __init__(self, d: Dialect, root: str) -> None:
        self.root = root
        self.msg_names = {class_name(m) for m in d.messages if m.complete}
        self.clash = {n for n in RUNTIME_CLASSES if n in self.msg_names}

    def rt(self, simple: str, own_class: str = "") -> str:
        if simple in self.clash or simple == own_class:
            return f"{self.root}.runtime.{simple}"
        return simple

    def qualify(self, code: str) -> str:
        """Code naming runtime classes by simple name, with the clashing ones qualified."""
        for n in self.clash:
            code = re.sub(rf"\b{n}\.", f"{self.root}.runtime.{n}.", code)
        return code

    def rt_imports(self, names: list[str], own_class: str = "") -> list[str]:
        return [f"import {self.root}.runtime.{n};" for n in sorted(set(names))
                if n not in self.clash and n != own_class]

    def msg(self, m: Message, own_class: str = "") -> str:
        cn = class_name(m)
        if cn in RUNTIME_CLASSES or cn == own_class:
            return f"{self.root}.msg.{cn}"
        return cn

    def msg_imports(self, msgs: list[Message], own_class: str = "") -> list[str]:
        out = set()
        for m in msgs:
            cn = class_name(m)
            if cn not in RUNTIME_CLASSES and cn != own_class:
                out.add(f"import {self.root}.msg.{cn};")
        return sorted(out)


class _Java:
    name = "java"

    def __init__(self, override: str | None = None) -> None:
        self.override = override  # --java-package; None: ttctl.<ident>

    def outputs(self, d: Dialect) -> list[Output]:
        root = "java/" + package(d, self.override).replace(".", "/")
        outs = [Output(f"{root}/{registry_class(d)}.java", "java/Registry.java.j2")]
        for n in RUNTIME_FILES:
            outs.append(Output(f"{root}/runtime/{n}.java", f"java/runtime/{n}.java.j2"))
        if has_setpoints(d):
            outs.append(Output(f"{root}/runtime/SendSetpoint.java", "java/runtime/SendSetpoint.java.j2"))
        if TRANSFER_MESSAGES.issubset(m.name for m in d.messages if m.complete):
            for n in TRANSFER_FILES:
                outs.append(Output(f"{root}/transfer/{n}.java", f"java/runtime/transfer/{n}.java.j2"))
        for m in sorted((m for m in d.messages if m.complete), key=lambda m: m.id):
            outs.append(Output(f"{root}/msg/{class_name(m)}.java", "java/Message.java.j2", context={"m": m}))
        for e in sorted(d.enums, key=lambda e: e.name):
            outs.append(Output(f"{root}/enums/{camel(e.name)}.java", "java/Enum.java.j2", context={"e": e}))
        outs.append(Output("java/Conformance.java", "java/Conformance.java.j2"))
        for m in sends(d, "tablet"):
            outs.append(Output(f"{root}/commands/Send{class_name(m)}.java", "java/SendSkeleton.java.j2",
                               skeleton=True, context={"m": m, "cls": f"Send{class_name(m)}"}))
        for m in receives(d, "tablet"):
            outs.append(Output(f"{root}/commands/Receive{class_name(m)}.java", "java/ReceiveSkeleton.java.j2",
                               skeleton=True, context={"m": m, "cls": f"Receive{class_name(m)}"}))
        return outs

    def owned_dirs(self, d: Dialect) -> list[str]:
        root = "java/" + package(d, self.override).replace(".", "/")
        return [f"{root}/runtime", f"{root}/transfer", f"{root}/msg", f"{root}/enums"]

    def globals(self, d: Dialect) -> dict[str, Any]:
        pkg = package(d, self.override)
        refs = _Refs(d, pkg)
        return {
            "pkg": pkg,
            "registry": registry_class(d),
            "class_name": class_name,
            "java_type": java_type,
            "is_text": is_text,
            "is_bytes": is_bytes,
            "default_value": lambda f: default_value(f, d),
            "pack_lines": lambda m, f: [refs.qualify(x) for x in pack_lines(m, f)],
            "unpack_lines": lambda m, f: [refs.qualify(x) for x in unpack_lines(m, f)],
            "to_string_expr": lambda f: refs.qualify(to_string_expr(f)),
            "javadoc": javadoc,
            "field_doc": lambda f: field_doc(f, d, pkg),
            "java_string": java_string,
            "enum_type": enum_type,
            "enum_table": enum_table,
            "java_long": java_long,
            "java_longs": lambda vs: ", ".join(java_long(v) for v in vs),
            "json_out": json_out,
            "json_in": json_in,
            "expected_reply": lambda m: expected_reply(m, d),
            "reply_conditions": lambda m: reply_conditions(m, d),
            "scalar_target": scalar_target,
            "stamped_fields": stamped_fields,
            "has_contract": lambda name: has_contract(d, name),
            "has_transfers": TRANSFER_MESSAGES.issubset(m.name for m in d.messages if m.complete),
            "ctor_type": lambda f: ctor_type(f, d),
            "narrowed": lambda m: [f.name for f in m.fields if ctor_type(f, d) != java_type(f)],
            "ctor_doc": lambda m: ctor_doc(m, d),
            "ctor_assign": lambda m, f: refs.qualify(ctor_assign(m, f, d)),
            "type_mapping": TYPE_MAPPING,
            "rt": refs.rt,
            "rt_imports": refs.rt_imports,
            "msg_ref": refs.msg,
            "msg_imports": refs.msg_imports,
        }


LANG = _Java()
