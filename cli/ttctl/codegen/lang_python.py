"""Python: a package per dialect (enums, messages, framing), a conformance program, and a
handler module skeleton for ttctl's plugin system."""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Any

from ..dialect.model import BASE_TYPES, Dialect, Enum, Field, Message
from ..dialect.names import camel
from ..dialect.symbols import python_entry, type_names
from .engine import Output, dialect_ident
from .text import wrap as wrap_words

name = "python"

_PY_TYPES = {
    "float": "float",
    "double": "float",
    "char": "str",
    "int8_t": "int",
    "uint8_t": "int",
    "int16_t": "int",
    "uint16_t": "int",
    "int32_t": "int",
    "uint32_t": "int",
    "int64_t": "int",
    "uint64_t": "int",
}


def package(d: Dialect, override: str | None = None) -> str:
    """The Python package name of a dialect: `override` (--python-package) or its identifier."""
    return override or dialect_ident(d)


def is_bytes(f: Field) -> bool:
    """uint8_t arrays are `bytes` in Python (file data, raw buffers)."""
    return f.type == "uint8_t" and f.array_length > 0


def is_text(f: Field) -> bool:
    """char fields (arrays and the rare scalar) are `str`."""
    return f.type == "char"


def is_seq(f: Field) -> bool:
    return f.array_length > 0 and not is_bytes(f) and not is_text(f)


def struct_format(m: Message) -> str:
    parts = ["<"]
    for f in m.wire_fields:
        code = BASE_TYPES[f.type][1]
        if is_text(f) or is_bytes(f):
            parts.append(f"{max(f.array_length, 1)}s")
        elif f.array_length:
            parts.append(code * f.array_length)
        else:
            parts.append(code)
    return "".join(parts)


def py_type(f: Field) -> str:
    """Annotation of the attribute (what decoding produces)."""
    if is_bytes(f):
        return "bytes"
    if is_text(f):
        return "str"
    base = _PY_TYPES[f.type]
    return f"Sequence[{base}]" if f.array_length else base


def init_type(f: Field) -> str:
    """Annotation of the constructor parameter: what the attribute holds, and for uint8_t
    arrays also what pymavlink takes (a bytearray, a sequence of ints), converted to bytes."""
    return "bytes | bytearray | Sequence[int]" if is_bytes(f) else py_type(f)


def init_value(m: Message, f: Field) -> str:
    """The constructor's expression assigning parameter `f` to its attribute."""
    if is_bytes(f):  # the length is checked when packed, as for bytes
        return f'_ubytes({f.name}, {f.array_length}, "{m.name}.{f.name}", False)'
    return f.name


# Names pycodestyle finds ambiguous (E741: l, O, I look like 1 and 0). A field keeps its XML
# name (users and pymavlink spell it so), so the lines binding it as a name silence E741; and
# RUF100 too, which ruff's newer default rule set (without E741) would raise on that noqa.
_AMBIGUOUS = frozenset({"l", "O", "I"})


def noqa(f: Field) -> str:
    """A targeted noqa for a line that binds field `f` as a name, if it needs one."""
    return "  # noqa: E741, RUF100" if f.name in _AMBIGUOUS else ""


def message_imports(messages: list[Message]) -> dict[str, bool]:
    """Which helpers the messages module needs (unused imports fail ruff's F401)."""
    fields = [f for m in messages for f in m.fields]
    return {
        "Sequence": any(is_seq(f) or is_bytes(f) for f in fields),
        "_array": any(is_seq(f) for f in fields),
        "_cbytes": any(is_text(f) for f in fields),
        "_cstr": any(is_text(f) for f in fields),
        "_ubytes": any(is_bytes(f) for f in fields),
    }


def enum_imports(enums: list[Enum]) -> list[str]:
    """The enum base classes the enums module uses."""
    return sorted({enum_base(e) for e in enums})


def default(f: Field, d: Dialect) -> str:
    if f.mavlink_version:
        return str(d.version)
    if is_bytes(f):
        return f"bytes({f.array_length})"
    if is_text(f):
        return '""'
    zero = "0.0" if f.is_float else "0"
    return f"({', '.join([zero] * f.array_length)},)" if f.array_length else zero


def pack_arg(m: Message, f: Field) -> str:
    """Expression for this field in the struct.pack call (wire order)."""
    size = max(f.array_length, 1)
    where = f'"{m.name}.{f.name}"'
    if is_text(f):
        return f"_cbytes(self.{f.name}, {size}, {where})"
    if is_bytes(f):
        return f"_ubytes(self.{f.name}, {size}, {where})"
    if f.array_length:
        return f"*_array(self.{f.name}, {f.array_length}, {where})"
    return f"self.{f.name}"


def unpack_plan(m: Message) -> tuple[bool, list[tuple[str, str]]]:
    """(simple, assignments). simple: every wire field is one struct item, so the fields can
    be assigned straight from the tuple; else (field, expression over tuple t)."""
    simple = all(not f.array_length or is_bytes(f) for f in m.wire_fields) and not any(
        is_text(f) for f in m.wire_fields
    )
    plan: list[tuple[str, str]] = []
    i = 0
    for f in m.wire_fields:
        if is_text(f):
            plan.append((f.name, f"_cstr(t[{i}])"))
            i += 1
        elif is_bytes(f) or not f.array_length:
            plan.append((f.name, f"t[{i}]"))
            i += 1
        else:
            plan.append((f.name, f"t[{i}:{i + f.array_length}]"))
            i += f.array_length
    return simple, plan


def doc(text: str, indent: int = 4) -> str:
    """A safe docstring body."""
    t = " ".join((text or "").split()).replace("\\", "\\\\").replace('"""', '\\"\\"\\"')
    if t.endswith('"'):
        t = t[:-1] + '\\"'
    return t or "(no description)"


def field_doc(f: Field, d: Dialect | None = None) -> str:
    extra = []
    if f.units:
        extra.append(f"[{f.units}]")
    if f.enum:
        extra.append(f"(enum {enum_class(f.enum, d)})")
    if f.extension:
        extra.append("(extension)")
    return doc(" ".join([f.description, *extra]))


# Names the class body of a generated message refers to (annotations, defaults), and how to
# reach them when one of the message's fields has that name (a field `bytes` or `Any` would
# otherwise be taken as the type in the class's own scope, which mypy refuses).
_SHADOWABLE: dict[str, tuple[str, str]] = {
    **{n: (f"_builtins.{n}", "import builtins as _builtins")
       for n in ("int", "float", "str", "bytes", "bytearray", "tuple", "dict")},
    "Any": ("_typing.Any", "import typing as _typing"),
    "ClassVar": ("_typing.ClassVar", "import typing as _typing"),
    "Sequence": ("_abc.Sequence", "import collections.abc as _abc"),
    "struct": ("_struct", "import struct as _struct"),
}
_IDENT = re.compile(r"\b[A-Za-z_][A-Za-z0-9_]*\b")


def shadowed_names(d: Dialect) -> frozenset[str]:
    """The names of _SHADOWABLE that a field of the dialect is called: spelled qualified in
    every message (so that a bare import is never left unused or redefined by a parameter)."""
    fields = {f.name for m in d.messages for f in m.fields}
    return frozenset(n for n in _SHADOWABLE if n in fields)


def qualifier(m: Message, own: str, shadowed: frozenset[str]) -> Callable[[str], str]:
    """A function spelling a type expression (or a default) for the class body of message `m`
    (class `own`): unchanged unless the dialect's fields shadow a name in it."""
    table = {n: _SHADOWABLE[n][0] for n in shadowed}
    if own in {f.name for f in m.fields}:  # a field named like its own class: the class is Self inside it
        table[own] = "_typing.Self"
    if not table:
        return lambda text: text

    def q(text: str) -> str:
        if "bytes" in table:  # a call in a default is flagged by ruff (B008) unless it is the builtin's
            text = re.sub(r"\bbytes\((\d+)\)", lambda x: f'b"\\x00" * {x.group(1)}', text)
        return _IDENT.sub(lambda x: table.get(x.group(0), x.group(0)), text)

    return q


def shadow_imports(messages: list[Message], own: Callable[[Message], str], shadowed: frozenset[str]) -> list[str]:
    """The module's plain imports: struct, and those the qualified spellings of qualifier() need
    (in isort's order)."""
    lines = {"import struct", *(_SHADOWABLE[n][1] for n in shadowed)}
    if any(own(m) in {f.name for f in m.fields} for m in messages):
        lines.add("import typing as _typing")
    return sorted(lines, key=lambda line: (line.split()[1], line))


def enum_class(name: str, d: Dialect | None) -> str:
    """The generated type of the enum called `name` (CamelCase when the dialect lacks it)."""
    got = type_names(d).enums.get(name) if d is not None else None
    return got or camel(name)


def wrap(text: str, width: int = 96, prefix: str = "    ") -> str:
    return "\n".join(prefix + line for line in wrap_words(text, width - len(prefix))) or prefix


def _natural(s: str) -> list[Any]:
    return [int(part) if part.isdigit() else part for part in re.split(r"(\d+)", s)]


def isort_sorted(names: list[str]) -> list[str]:
    """The order ruff's RUF022 wants for __all__: SCREAMING_CASE, then CamelCase, then the
    rest, each in natural order. A single capital (an enum named F) counts as CamelCase."""

    def key(n: str) -> tuple[int, list[Any]]:
        if len(n) > 1 and n.upper() == n and any(c.isalpha() for c in n):
            group = 0
        elif n[:1].isupper():
            group = 1
        else:
            group = 2
        return group, _natural(n)

    return sorted(names, key=key)


def import_sorted(names: list[str]) -> list[str]:
    """isort's order of names in `from x import (...)`: CONSTANTS (two characters or more),
    Classes, functions, each case-insensitively in natural order (F2A before F13)."""

    def key(n: str) -> tuple[int, list[Any], list[Any]]:
        group = 0 if len(n) > 1 and n.upper() == n else (1 if n[:1].isupper() else 2)
        return group, _natural(n.lower()), _natural(n)  # FooBar before Foobar, as isort has them

    return sorted(names, key=key)


def natural_sorted(names: list[str]) -> list[str]:
    return sorted(names, key=_natural)


def enum_base(e: Enum) -> str:
    return "IntFlag" if e.bitmask else "IntEnum"


class _Python:
    name = "python"

    def __init__(self, override: str | None = None) -> None:
        self.override = override  # --python-package; None: the dialect's identifier

    def outputs(self, d: Dialect) -> list[Output]:
        pkg = package(d, self.override)
        return [
            Output(f"python/{pkg}/__init__.py", "python/__init__.py.j2"),
            Output(f"python/{pkg}/mavlink.py", "python/mavlink.py.j2"),
            Output(f"python/{pkg}/enums.py", "python/enums.py.j2"),
            Output(f"python/{pkg}/messages.py", "python/messages.py.j2"),
            Output(f"python/{pkg}/py.typed", "python/py.typed.j2"),
            Output("python/conformance.py", "python/conformance.py.j2"),
            Output(f"python/handlers/{pkg}_onboard.py", "python/handlers.py.j2", skeleton=True),
        ]

    def owned_dirs(self, d: Dialect) -> list[str]:
        return [f"python/{package(d, self.override)}"]

    def globals(self, d: Dialect) -> dict[str, Any]:
        shadowed = shadowed_names(d)
        return {
            "pkg": package(d, self.override),
            "py_type": py_type,
            "default": lambda f: default(f, d),
            "struct_format": struct_format,
            "pack_arg": pack_arg,
            "unpack_plan": unpack_plan,
            "doc": doc,
            "field_doc": lambda f: field_doc(f, d),
            "py_entry": python_entry,
            "qualifier": lambda m: qualifier(m, type_names(d).messages[m.name], shadowed),
            "shadow_imports": lambda ms: shadow_imports(ms, lambda m: type_names(d).messages[m.name], shadowed),
            "shadowed": shadowed,
            "wrap": wrap,
            "enum_base": enum_base,
            "isort_sorted": isort_sorted,
            "natural_sorted": natural_sorted,
            "import_sorted": import_sorted,
            "is_text": is_text,
            "is_bytes": is_bytes,
            "is_seq": is_seq,
            "init_type": init_type,
            "init_value": init_value,
            "noqa": noqa,
            "message_imports": message_imports,
            "enum_imports": enum_imports,
        }


LANG = _Python()
