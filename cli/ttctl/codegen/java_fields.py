"""Java: how each MAVLink field is typed, packed, unpacked, printed and documented in the
generated Java (message classes, enums, the conformance program's JSON), for lang_java.

Java types of fields (documented in every message class, see TYPE_MAPPING):
  int8_t -> byte, uint8_t -> int, int16_t -> short, uint16_t -> int, int32_t -> int,
  uint32_t -> long, int64_t -> long, uint64_t -> long (two's complement bits; Unsigned helps),
  float -> float, double -> double, char[N] -> byte[] (exact bytes; String helpers),
  uint8_t[N] and int8_t[N] -> byte[], other arrays -> arrays of the scalar mapping.
"""

from __future__ import annotations

import re

from ..dialect.model import Dialect, Enum, Field, Message
from ..dialect.names import camel
from ..dialect.symbols import type_names
from .text import wrap

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



def class_name(m: Message, d: Dialect) -> str:
    """The Java class of message `m` of dialect `d` (see dialect.symbols: mangled where two
    files would collide on a case-insensitive file system)."""
    return type_names(d).java_messages[m.name]


def enum_class(name: str, d: Dialect | None) -> str:
    """The Java class of the enum called `name` (CamelCase when the dialect lacks it)."""
    got = type_names(d).java_enums.get(name) if d is not None else None
    return got or camel(name)


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


def field_doc(f: Field, d: Dialect | None = None, root: str | None = None) -> str:
    """Javadoc paragraph (RAW) of a field: description, units, MAVLink type, enum (linked when the
    dialect has it), extension."""
    text = f.description or f.name
    if f.units:
        text += f" [{f.units}]"
    notes = [f.declared_type]
    if f.enum:
        if d is not None and root is not None and f.enum in d.enums_by_name:
            notes.append(f"enum {{@link {root}.enums.{enum_class(f.enum, d)}}}")
        else:
            notes.append(f"enum {_escape_doc(enum_class(f.enum, d))}")
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
        return f"ConformanceJson.text(sb, {ref});" if n else f"ConformanceJson.textChar(sb, {ref});"
    if n:
        fn = {
            "uint8_t": "u8s", "int8_t": "i8s", "int16_t": "shorts", "uint16_t": "ints", "int32_t": "ints",
            "uint32_t": "longs", "int64_t": "longs", "uint64_t": "ulongs", "float": "f32s", "double": "f64s",
        }[t]
        return f"ConformanceJson.{fn}(sb, {ref});"
    if t == "uint64_t":
        return f"sb.append(Unsigned.toString({ref}));"
    if t == "float":
        return f"ConformanceJson.f32(sb, {ref});"
    if t == "double":
        return f"ConformanceJson.f64(sb, {ref});"
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


def json_in(f: Field, message: str = "") -> str:
    """Expression converting JSON value v to the field's Java type (a refusal names the field as
    MESSAGE.field)."""
    n = f.array_length
    t = f.type
    w = f'"{message}.{f.name}"' if message else f'"{f.name}"'
    if t == "char":
        return f"ConformanceJson.text(v, {n}, {w})" if n else f"ConformanceJson.textChar(v, {w})"
    if n:
        if t == "uint8_t":
            return f"ConformanceJson.u8s(v, {n}, {w})"
        if t == "int8_t":
            return f"ConformanceJson.i8s(v, {n}, {w})"
        if t == "int16_t":
            return f"ConformanceJson.shorts(v, {n}, {w})"
        if t in ("uint16_t", "int32_t"):
            lo, hi = _INT_LIMITS[t]
            return f"ConformanceJson.ints(v, {n}, {lo}, {hi}, {w})"
        if t in ("uint32_t", "int64_t"):
            lo, hi = _INT_LIMITS[t]
            return f"ConformanceJson.longs(v, {n}, {lo}, {hi}, {w})"
        if t == "uint64_t":
            return f"ConformanceJson.ulongs(v, {n}, {w})"
        if t == "float":
            return f"ConformanceJson.f32s(v, {n}, {w})"
        return f"ConformanceJson.f64s(v, {n}, {w})"
    if t == "uint64_t":
        return f"ConformanceJson.uint64(v, {w})"
    if t == "float":
        return f"ConformanceJson.f32(v, {w})"
    if t == "double":
        return f"ConformanceJson.f64(v, {w})"
    lo, hi = _INT_LIMITS[t]
    cast = {"int8_t": "(byte) ", "int16_t": "(short) ", "uint8_t": "(int) ", "uint16_t": "(int) ",
            "int32_t": "(int) "}.get(t, "")
    return f"{cast}ConformanceJson.integer(v, {lo}, {hi}, {w})"


# --- skeletons ----------------------------------------------------------------------------
