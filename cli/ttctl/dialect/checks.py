"""Semantic checks on a loaded dialect: everything mavgen lets through, and then some."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import NamedTuple, Protocol

from .diagnostics import Loc, Reporter
from .model import (
    INTEGER_RANGES,
    MAX_FIELDS,
    MAX_PAYLOAD,
    SENDER_RE,
    SENDERS,
    Dialect,
    Enum,
    EnumEntry,
    Field,
    Message,
    frame_length,
)
from .names import (
    C_MACROS,
    GENERATED_MESSAGE_MEMBERS,
    IDENTIFIER_RE,
    JAVA_QUALIFIERS_IN_ENUMS,
    JAVA_QUALIFIERS_IN_MESSAGES,
    JAVA_RESERVED_TYPES,
    RESERVED_WORDS,
    RUNTIME_TYPE_NAMES,
    camel,
    keyword_hits,
    lower_camel,
    reserved_identifier,
    spelled,
)
from .symbols import python_entry, python_entry_clash, type_names


class CheckOptions(NamedTuple):
    mtu: int = 100  # 0 disables the MTU budget
    signed: bool = False


def check_dialect(d: Dialect, rep: Reporter, opts: CheckOptions | None = None) -> None:
    opts = opts or CheckOptions()
    _duplicates(d, rep)
    _names(d, rep)
    own = {id(m) for m in d.root.messages}  # a set: a list test per message made validation quadratic
    misfits: dict[tuple[str, str], list[EnumEntry]] = {}  # per (enum, field type): once, not once per field
    # with an include missing, references to undefined enums are one error, not a flood
    undefined: list[tuple[Message, Field]] | None = [] if d.incomplete else None
    for m in d.messages:
        _message(d, m, rep, opts, own=id(m) in own, misfits=misfits, undefined=undefined)
    if undefined:
        m, f = undefined[0]
        more = sorted({g.enum or "" for _, g in undefined})
        shown = ", ".join(more[:5]) + (" ..." if len(more) > 5 else "")
        rep.error(f.loc.at("enum"), "UNDEFINED-ENUM",
                  f"{m.name}.{f.name} refers to enum {f.enum}, which is not defined here or in any include; so do "
                  f"{len(undefined) - 1} more fields (enums {shown}), perhaps defined in the missing include(s)",
                  f.enum)
    for e in d.enums:
        _enum(e, rep)


def _duplicates(d: Dialect, rep: Reporter) -> None:
    by_id: dict[int, Message] = {}
    by_name: dict[str, Message] = {}
    for m in d.messages:
        prev = by_id.get(m.id) if m.id >= 0 else None
        if prev is not None:
            rep.error(m.loc.at("id"), "DUP-MSG-ID",
                      f"message id {m.id} of {m.name} is already used by {prev.name} at {prev.loc.short()}", m.name)
        else:
            by_id[m.id] = m
        prev = by_name.get(m.name)
        if prev is not None:
            rep.error(m.loc, "DUP-MSG-NAME",
                      f"message {m.name} (id {m.id}) is already defined (id {prev.id}) at {prev.loc.short()}", m.name)
        else:
            by_name[m.name] = m
        seen: dict[str, Loc] = {}
        for f in m.fields:
            if f.name in seen:
                rep.error(f.loc, "DUP-FIELD",
                          f"{m.name}: field {f.name} is already defined at {seen[f.name].short()}", f.name)
            else:
                seen[f.name] = f.loc
    # enum entries, in declaration order across files (merged enums share entries)
    names: dict[tuple[str, str], Loc] = {}
    values: dict[tuple[str, int], tuple[str, Loc]] = {}
    for df in d.files:
        for e in df.enums:
            for entry in e.entries:
                key = (e.name, entry.name)
                if key in names:
                    rep.error(entry.loc, "DUP-ENUM-ENTRY",
                              f"{e.name}: entry {entry.name} is already defined at {names[key].short()}", entry.name)
                    continue
                names[key] = entry.loc
                vkey = (e.name, entry.value)
                if vkey in values:
                    other, oloc = values[vkey]
                    rep.error(entry.loc, "DUP-ENUM-VALUE",
                              f"{e.name}: {entry.name} = {entry.value} has the same value as {other} "
                              f"at {oloc.short()}", entry.name)
                else:
                    values[vkey] = (entry.name, entry.loc)


def _plainly_fine(name: str) -> bool:
    """Fast pre-check for a field or entry name (spelled as written); names failing it get
    the full treatment."""
    return (IDENTIFIER_RE.match(name) is not None and name not in RESERVED_WORDS
            and reserved_identifier(name) is None)


def _identifier(loc: Loc, kind: str, name: str, rep: Reporter, fold_case: bool) -> bool:
    """Valid identifier, not a keyword, not reserved, as the generators spell it (`fold_case`:
    a message or enum name, which they CamelCase). Returns False if the name is unusable."""
    if not IDENTIFIER_RE.match(name):
        rep.error(loc, "NAME-INVALID",
                  f"{kind} name '{name}' is not a valid identifier in C, C++, Java and Python "
                  "(ASCII letters, digits and '_', not starting with a digit)", name)
        return False
    ident = spelled(name, fold_case)
    hits = keyword_hits(ident)
    if hits:
        where = f" (as '{ident}')" if ident != name else ""
        rep.error(loc, "KEYWORD",
                  f"{kind} name '{name}'{where} is a reserved word in {', '.join(hits)}; generated code "
                  "would not compile", name)
        return False
    macro = C_MACROS.get(ident)
    if macro:
        rep.error(loc, "RESERVED-NAME",
                  f"{kind} name '{name}' is {macro}, so it cannot name anything in C++ (the macro replaces it)",
                  name)
        return False
    why = reserved_identifier(name)
    if why:
        rep.error(loc, "RESERVED-NAME", f"{kind} name '{name}': {why}", name)
        return False
    if fold_case and camel(name) in RUNTIME_TYPE_NAMES:
        rep.error(loc, "RESERVED-NAME",
                  f"{kind} name '{name}' becomes {camel(name)}, a type the generated runtime defines", name)
        return False
    if fold_case and camel(name) in JAVA_RESERVED_TYPES:
        rep.error(loc, "RESERVED-NAME",
                  f"{kind} name '{name}' becomes class {camel(name)}, which would shadow java.lang.{camel(name)} "
                  "in the generated Java package", name)
        return False
    return True


class _Named(Protocol):
    name: str

    @property
    def loc(self) -> Loc: ...


def _collisions(items: Sequence[_Named], kind: str, camelfn: Callable[[str], str] | None,
                rep: Reporter) -> None:
    """Error when two names give the same name after case folding, or (with `camelfn`) the
    same identifier after camel-casing. (Types whose names differ only in case once
    camel-cased, and a message and an enum of the same name, are renamed in the generated code:
    see _renamed.)"""
    folded: dict[str, tuple[str, _Named]] = {}
    camels: dict[str, tuple[str, _Named]] = {}
    for item in items:
        name = item.name
        key = name.casefold()
        prev = folded.get(key)
        if prev is None:
            folded[key] = (name, item)
        else:
            if prev[0] != name:
                rep.error(item.loc, "NAME-COLLISION",
                          f"{kind} {name} collides with {prev[0]} at {prev[1].loc.short()} after case folding "
                          "(one generated identifier or file would overwrite the other)", name)
            continue
        if camelfn is None:
            continue
        c = camelfn(name)
        prev = camels.get(c)
        if prev is not None:
            rep.error(item.loc, "NAME-COLLISION",
                      f"{kind} {name} collides with {prev[0]} at {prev[1].loc.short()} after camel-casing "
                      "(one generated identifier or file would overwrite the other)", name)
            continue
        camels[c] = (name, item)


def _names(d: Dialect, rep: Reporter) -> None:
    field_names = {f.name for m in d.messages for f in m.fields}
    bad_fields = {n for n in field_names if not _plainly_fine(n) or n in GENERATED_MESSAGE_MEMBERS}
    for m in d.messages:
        _identifier(m.loc, "message", m.name, rep, fold_case=True)
        for f in m.fields:
            if f.name in bad_fields and _identifier(f.loc, "field", f.name, rep, fold_case=False) \
                    and f.name in GENERATED_MESSAGE_MEMBERS:
                rep.error(f.loc, "RESERVED-NAME",
                          f"{m.name}.{f.name}: '{f.name}' is a member every generated message class defines",
                          f.name)
        _collisions(m.fields, f"{m.name} field", lower_camel, rep)
    entry_names = {x.name for e in d.enums for x in e.entries}
    bad_entries = {n for n in entry_names if not _plainly_fine(n)}
    for e in d.enums:
        for part in e.parts:
            _identifier(part, "enum", e.name, rep, fold_case=True)
        for entry in e.entries:
            if entry.name in bad_entries:
                _identifier(entry.loc, "enum entry", entry.name, rep, fold_case=False)
        _collisions(e.entries, f"{e.name} entry", None, rep)
    # messages and enums share one namespace in every generated language
    rank = {f.path: i for i, f in enumerate(d.files)}
    types: list[Message | Enum] = [*d.messages, *d.enums]
    types.sort(key=lambda t: (rank.get(t.loc.path, -1), t.loc.line))  # report the later definition
    _collisions(types, "type", camel, rep)
    _renamed(d, rep)
    stems: dict[str, str] = {}
    for df in d.files:
        key = df.stem.casefold()
        if key in stems and stems[key] != df.path:
            rep.error(df.loc, "NAME-COLLISION",
                      f"dialect file {df.path} has the same name as {stems[key]} after case folding "
                      "(their generated modules would overwrite each other)", df.stem)
        stems[key] = df.path


def _renamed(d: Dialect, rep: Reporter) -> None:
    """A note for every type the generators rename (dialect.symbols), at its definition, and an
    error for a field that C++ cannot have: one spelled like its own message's type."""
    tn = type_names(d)
    by_name: dict[tuple[str, str], Loc] = {}
    for m in d.messages:
        by_name.setdefault(("message", m.name), m.loc)
    for e in d.enums:
        by_name.setdefault(("enum", e.name), e.parts[-1] if e.parts else e.loc)
    for kind, xml, other, code, text in tn.renamed:
        if code == "TYPE-RENAMED" and other is not None and other != xml:
            continue  # two names that camel-case alike: a NAME-COLLISION error already
        rep.note(by_name[(kind, xml)], code, text, xml)
    entry_names = {x.name for e in d.enums for x in e.entries}
    for e in d.enums if entry_names & JAVA_QUALIFIERS_IN_ENUMS.keys() else []:
        for x in e.entries:
            if x.name in JAVA_QUALIFIERS_IN_ENUMS:
                rep.error(x.loc, "RESERVED-NAME", f"{e.name}.{x.name}: {JAVA_QUALIFIERS_IN_ENUMS[x.name]}; rename the "
                          "entry", x.name)
    field_names = {f.name for m in d.messages for f in m.fields}
    for m in d.messages if field_names & JAVA_QUALIFIERS_IN_MESSAGES.keys() else []:
        for f in m.fields:
            if f.name in JAVA_QUALIFIERS_IN_MESSAGES:
                rep.error(f.loc, "RESERVED-NAME", f"{m.name}.{f.name}: {JAVA_QUALIFIERS_IN_MESSAGES[f.name]}; rename "
                          "the field", f.name)
    if any(python_entry_clash(n) for n in entry_names):
        for e in d.enums:
            for x in e.entries:
                py = python_entry(e, x.name)
                if py != x.name:
                    rep.note(x.loc, "ENTRY-RENAMED",
                             f"{e.name}.{x.name} is generated as {type_names(d).enums[e.name]}.{py} in Python, whose "
                             f"IntEnum and IntFlag reserve '{x.name}' (C++ and Java keep {x.name}; the wire is "
                             "unchanged)", x.name)
    for m in d.messages:
        own = tn.messages.get(m.name)
        for f in m.fields:
            if f.name == own:
                rep.error(f.loc, "RESERVED-NAME",
                          f"{m.name}.{f.name}: a field cannot be spelled like its message's generated type {own} "
                          "(C++ refuses a member named like its class); rename the field", f.name)


def _message(d: Dialect, m: Message, rep: Reporter, opts: CheckOptions, own: bool,
             misfits: dict[tuple[str, str], list[EnumEntry]], undefined: list[tuple[Message, Field]] | None) -> None:
    if m.complete and m.payload_length > MAX_PAYLOAD:
        ext = sum(f.wire_length for f in m.extension_fields)
        detail = f" ({m.min_length} B base + {ext} B extensions)" if ext else ""
        rep.error(m.loc, "PAYLOAD-TOO-LARGE",
                  f"message {m.name}: payload is {m.payload_length} bytes{detail}; MAVLink 2 allows at most "
                  f"{MAX_PAYLOAD}", m.name)
    if len(m.fields) > MAX_FIELDS:
        rep.error(m.loc, "TOO-MANY-FIELDS",
                  f"message {m.name} has {len(m.fields)} fields; mavgen and its peers allow at most {MAX_FIELDS}",
                  m.name)
    for f in m.fields:
        if not f.enum:
            continue
        e = d.enums_by_name.get(f.enum)
        if e is None:
            if undefined is not None:
                undefined.append((m, f))
                continue
            rep.error(f.loc.at("enum"), "UNDEFINED-ENUM",
                      f"{m.name}.{f.name} refers to enum {f.enum}, which is not defined here or in any include",
                      f.enum)
            continue
        if f.is_float:
            rep.error(f.loc.at("enum"), "ENUM-ON-FLOAT",
                      f"{m.name}.{f.name} is {f.type} but uses enum {f.enum}; enums need an integer field",
                      f.name)
            continue
        if f.type == "char":
            rep.error(f.loc.at("enum"), "ENUM-ON-CHAR",
                      f"{m.name}.{f.name} is {f.declared_type} but uses enum {f.enum}; enums need an integer field",
                      f.name)
            continue
        lo, hi = INTEGER_RANGES[f.type]
        bad = misfits.get((e.name, f.type))
        if bad is None:  # scanning the enum for every field that uses it was fields x entries
            bad = misfits[(e.name, f.type)] = [x for x in e.entries if not lo <= x.value <= hi]
        if bad:
            shown = ", ".join(f"{x.name} = {x.value}" for x in bad[:3]) + (" ..." if len(bad) > 3 else "")
            if e.bitmask:
                # a narrow field carrying the low flags of a wider bitmask is a common, deliberate
                # pattern (e.g. GIMBAL_DEVICE_INFORMATION.cap_flags); the high flags cannot be sent
                rep.warning(f.loc.at("enum"), "ENUM-VALUE-RANGE",
                            f"{m.name}.{f.name} is {f.type} ({lo}..{hi}); these flags of bitmask {f.enum} "
                            f"cannot be set in it: {shown}", f.name)
            else:
                rep.error(f.loc.at("enum"), "ENUM-VALUE-RANGE",
                          f"{m.name}.{f.name} is {f.type} ({lo}..{hi}) but enum {f.enum} has values that do "
                          f"not fit: {shown}", f.name)
    tag = SENDER_RE.search(m.description)
    if tag and tag.group(1).lower() not in SENDERS:
        rep.warning(m.loc, "SENDER",
                    f"message {m.name}: unknown sender '{tag.group(1)}' (expected one of {', '.join(SENDERS)})",
                    m.name)
    if own and m.complete and opts.mtu > 0 and m.payload_length <= MAX_PAYLOAD and not m.spans_packets:
        size = frame_length(m.payload_length, opts.signed)
        if size > opts.mtu:
            kind = "signed" if opts.signed else "unsigned"
            packets = -(-size // opts.mtu)
            rep.warning(m.loc, "MTU",
                        f"message {m.name}: largest {kind} frame is {size} bytes (payload {m.payload_length}), "
                        f"over the {opts.mtu}-byte packet; it spans {packets} packets", m.name)


def _enum(e: Enum, rep: Reporter) -> None:
    for x in e.entries:
        if x.value > INTEGER_RANGES["uint64_t"][1]:
            rep.error(x.loc, "ENUM-VALUE-RANGE",
                      f"{e.name}.{x.name} = {x.value} does not fit in 64 bits", x.name)
        elif e.bitmask and x.value & (x.value - 1):  # 0, "no flags", is fine (MAV_BOOL_FALSE...)
            rep.warning(x.loc, "BITMASK-VALUE",
                        f"{e.name} is a bitmask but {x.name} = {x.value} is not a power of two", x.name)
