"""The identifiers the generators emit for a dialect's messages, enums and enum entries, where
a name cannot be emitted as it is spelled (mangling, as mavgen-compatible tools do).

The wire never carries these names: mangling changes how the generated code spells a type or
an entry, never a message id, a field or CRC_EXTRA. Everything is decided here once, so that
the validator (which tells the user, as notes) and the generators agree.

- A message and an enum with the same name (DroneLeaf's LEAF_MODE): both would become one
  CamelCase type in the Python package and the C++ namespace. The message keeps the name, the
  enum gets `Enum` appended (LeafModeEnum).
- A type whose CamelCase name is one the generated Python modules import (ANY -> Any,
  CLASS_VAR -> ClassVar, INT_ENUM -> IntEnum...) gets `Message` or `Enum` appended.
- Java writes one file per type; two types of one package whose names differ only in case
  (ardupilotmega's SIM_STATE -> SimState and SIMSTATE -> Simstate) would overwrite each other
  on case-insensitive file systems: in Java the later one (by message id, by enum name) gets
  `Message` or `Enum` appended.
- Python enum entries named like an attribute of int or IntEnum/IntFlag (mro, imag,
  bit_length...) or like Enum's reserved _sunder_ names get `_` appended in Python only.
"""

from __future__ import annotations

import re
import weakref
from dataclasses import dataclass, field

from .model import Dialect, Enum
from .names import JAVA_RESERVED_TYPES, RUNTIME_TYPE_NAMES, camel

# Names the generated Python modules (messages.py, enums.py, __init__.py) import or define at
# module level in CamelCase: a message or enum class of that name would replace them.
PYTHON_MODULE_TYPES = frozenset(["Any", "ClassVar", "Sequence", "IntEnum", "IntFlag", "Self", "Callable", "Iterable"])

# Attributes of Python's int and of IntEnum/IntFlag that an enum member cannot replace: the
# class does not import (mro), or mypy --strict refuses it (imag, bit_length...).
PYTHON_ENUM_ATTRIBUTES = frozenset([
    "as_integer_ratio", "bit_count", "bit_length", "conjugate", "denominator", "from_bytes", "imag", "numerator",
    "real", "to_bytes", "mro", "name", "value",
])
_SUNDER = re.compile(r"_[^_].*[^_]_\Z|_[^_]_\Z")

MESSAGE_SUFFIX = "Message"
ENUM_SUFFIX = "Enum"


@dataclass
class TypeNames:
    """Generated type names of one dialect: `messages` and `enums` by XML name; `java_*` the
    same for Java's files; `renamed` what differs from plain camel-casing, as the validator's
    notes say it."""

    messages: dict[str, str] = field(default_factory=dict)
    enums: dict[str, str] = field(default_factory=dict)
    java_messages: dict[str, str] = field(default_factory=dict)
    java_enums: dict[str, str] = field(default_factory=dict)
    # (kind, XML name, the XML name it yielded to, code, message)
    renamed: list[tuple[str, str, str | None, str, str]] = field(default_factory=list)


_Item = tuple[str, str]  # (kind, XML name)


def _assign(items: list[_Item], reserved: frozenset[str],
            fold: bool) -> tuple[dict[_Item, str], dict[_Item, tuple[str, str | None]]]:
    """Names for (kind, XML name) items in priority order: their CamelCase name where it is free
    (and not `reserved`), else with the kind's suffix (and a number if still taken). Returns
    (names, why) where `why` says, for a renamed item, why and whose name it yielded to."""
    def key(s: str) -> str:
        return s.casefold() if fold else s

    reserved_keys = {key(r) for r in reserved}
    owner: dict[str, tuple[str, str]] = {}
    names: dict[tuple[str, str], str] = {}
    why: dict[tuple[str, str], tuple[str, str | None]] = {}
    for item in items:
        c = camel(item[1])
        if key(c) in reserved_keys or key(c) in owner:
            continue
        owner[key(c)] = item
        names[item] = c
    for item in items:
        if item in names:
            continue
        kind, xml = item
        c = camel(xml)
        prev = owner.get(key(c))
        why[item] = ((f"{prev[0]} {prev[1]} is {camel(prev[1])}", prev[1]) if prev is not None
                     else (f"the generated Python code imports {c}", None))
        base = c + (MESSAGE_SUFFIX if kind == "message" else ENUM_SUFFIX)
        cand, n = base, 2
        while key(cand) in reserved_keys or key(cand) in owner:
            cand, n = f"{base}{n}", n + 1
        owner[key(cand)] = item
        names[item] = cand
    return names, why


_CACHE: weakref.WeakKeyDictionary[Dialect, TypeNames] = weakref.WeakKeyDictionary()


def type_names(d: Dialect) -> TypeNames:
    """The generated type names of dialect `d` (computed once per dialect)."""
    got = _CACHE.get(d)
    if got is not None:
        return got
    msgs = [("message", m.name) for m in sorted(d.messages, key=lambda m: (m.id, m.name))]
    enums = [("enum", e.name) for e in sorted(d.enums, key=lambda e: e.name)]
    # Python and C++: one namespace for messages and enums; JAVA_RESERVED_TYPES and the runtime's
    # names are refused by the validator, so they are only kept free for the mangled names
    shared, why = _assign(_unique(msgs + enums), PYTHON_MODULE_TYPES | RUNTIME_TYPE_NAMES | JAVA_RESERVED_TYPES,
                          fold=False)
    tn = TypeNames()
    for (kind, xml), ident in shared.items():
        (tn.messages if kind == "message" else tn.enums)[xml] = ident
    for item, (reason, other) in why.items():
        if other is None and camel(item[1]) not in PYTHON_MODULE_TYPES:
            continue  # a runtime's or java.lang's type: the validator refuses the name
        tn.renamed.append((item[0], item[1], other, "TYPE-RENAMED",
                           f"{item[0]} {item[1]} is generated as {shared[item]} in Python, C++ and Java, as {reason} "
                           "(the wire is unchanged)"))
    # Java: a package per kind (msg, enums), a file per type: unique also after case folding
    for kind, items, src, dst in (("message", msgs, tn.messages, tn.java_messages),
                                  ("enum", enums, tn.enums, tn.java_enums)):
        folded: dict[str, str] = {}
        for _, xml in _unique(items):
            ident = src[xml]
            k = ident.casefold()
            prev = folded.get(k)
            if prev is None:
                folded[k] = xml
                dst[xml] = ident
                continue
            base = ident + (MESSAGE_SUFFIX if kind == "message" else ENUM_SUFFIX)
            cand, n = base, 2
            while cand.casefold() in folded:
                cand, n = f"{base}{n}", n + 1
            folded[cand.casefold()] = xml
            dst[xml] = cand
            tn.renamed.append((kind, xml, prev, "CASE-COLLISION",
                               f"{kind} {xml} is generated as Java class {cand}, as {kind} {prev} is {src[prev]} and "
                               f"{ident}.java and {src[prev]}.java would collide on case-insensitive file systems"))
    _CACHE[d] = tn
    return tn


def _unique(items: list[tuple[str, str]]) -> list[tuple[str, str]]:
    seen: set[tuple[str, str]] = set()
    out = []
    for it in items:
        if it not in seen:
            seen.add(it)
            out.append(it)
    return out


def python_entry(e: Enum, name: str) -> str:
    """The Python member name of entry `name` of enum `e`: as written, or with `_` appended
    (repeatedly, until unique in the enum) if Python's IntEnum/IntFlag cannot have it."""
    if name not in PYTHON_ENUM_ATTRIBUTES and not _SUNDER.match(name):
        return name
    others = {x.name for x in e.entries}
    cand = name + "_"
    while cand in others:
        cand += "_"
    return cand


def python_entry_clash(name: str) -> bool:
    return name in PYTHON_ENUM_ATTRIBUTES or _SUNDER.match(name) is not None
