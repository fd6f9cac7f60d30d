"""From dialect files to the model: includes, element walking, enum merging.

Includes are resolved relative to the including file, then each `-I` directory; a bare file
name (no folder part) found in neither is ttctl's shipped copy, else pymavlink's, with a note
saying which (a copy next to the including file wins, as with mavgen). A file name is loaded
once when one of its copies is shipped: pymavlink's loweheiser.xml including its minimal.xml
beside the user's own minimal.xml gets the user's. Enums split across files are merged as
mavgen merges them. Problems go to the Reporter; loading continues so that one run shows all
of them.
"""

from __future__ import annotations

import os
import re
from typing import Any, NamedTuple

from .diagnostics import Loc, Reporter, SourceText, display_path
from .model import (
    BASE_TYPES,
    MAX_MSG_ID,
    Deprecation,
    Dialect,
    DialectFile,
    Enum,
    EnumEntry,
    EnumParam,
    Field,
    Message,
)
from .source import (
    ParsedFile,
    Unreadable,
    is_shipped,
    parse_file,
    pymavlink_dialects_dir,
    schema_check,
    shipped_dirs,
    ttctl_dialects_dir,
)

MAX_INCLUDE_DEPTH = 32
# pymavlink's mavgen (generator/mavgen.py, MAXIMUM_INCLUDE_FILE_NESTING = 5) expands includes in
# 5 rounds: a file included 6 deep is never parsed, and mavgen stops with "ERROR in includes
# tree, no base found!" (checked with pymavlink 2.4.50). ttctl follows them, with a warning.
MAVGEN_INCLUDE_NESTING = 5
_TYPE_RE = re.compile(r"([A-Za-z_][A-Za-z0-9_]*)(?:\[(\d+)\])?\Z")
_VALUE_RE = re.compile(r"\s*(?:(0[xX][0-9a-fA-F]+)|(0[bB][01]+)|2\*\*(\d+)|(\d+))\s*\Z")


class LoadError(Exception):
    """The root dialect file itself could not be read or parsed."""

    def __init__(self, path: str, code: str, message: str, line: int = 1, col: int = 1) -> None:
        super().__init__(message)
        self.path, self.code, self.message, self.line, self.col = path, code, message, line, col


class LoadResult(NamedTuple):
    dialect: Dialect
    reporter: Reporter
    file_order: list[str]


def parse_enum_value(text: str) -> int | None:
    if text.isdigit():
        return int(text)
    m = _VALUE_RE.match(text)
    if not m:
        return None
    hexa, binary, power, dec = m.groups()
    if hexa:
        return int(hexa, 16)
    if binary:
        return int(binary, 2)
    if power:
        return 2 ** int(power)
    return int(dec)


def _text(el: Any) -> str:
    return (el.text or "").strip()


def _deprecation(el: Any) -> Deprecation:
    return Deprecation(str(el.tag), el.get("since", ""), el.get("replaced_by", ""), _text(el))


class _FileReader:
    """Builds the DialectFile of one parsed document."""

    def __init__(self, pf: ParsedFile, rep: Reporter) -> None:
        self.pf = pf
        self.src: SourceText = pf.source
        self.rep = rep
        # (line, attribute) pairs already explained, so the XSD check does not repeat them
        self.covered: set[tuple[int, str | None]] = set()

    def loc(self, el: Any, attr: str | None = None) -> Loc:
        return Loc(self.src, el.sourceline or 1, str(el.tag), attr)

    def error(self, el: Any, attr: str | None, code: str, msg: str, name: str | None = None) -> None:
        self.covered.add((el.sourceline or 1, attr))
        self.rep.error(self.loc(el, attr), code, msg, name)

    def read(self) -> DialectFile:
        root = self.pf.root
        df = DialectFile(self.pf.path, self.loc(root))
        if root.tag != "mavlink":
            self.error(root, None, "XSD", f"root element is <{root.tag}>, expected <mavlink>")
            self.covered.add((root.sourceline or 1, "*"))
            return df
        for child in root:
            tag = child.tag
            if not isinstance(tag, str):
                continue
            if tag == "include":
                df.includes.append((_text(child), self.loc(child)))
            elif tag == "version":
                df.version = self._int(child)
            elif tag == "dialect":
                df.dialect = self._int(child)
            elif tag == "enums":
                for el in child:
                    if el.tag == "enum":
                        e = self._enum(el)
                        if e is not None:
                            df.enums.append(e)
            elif tag == "messages":
                for el in child:
                    if el.tag == "message":
                        m = self._message(el)
                        if m is not None:
                            df.messages.append(m)
        return df

    def _int(self, el: Any) -> int | None:
        try:
            return int(_text(el))
        except ValueError:
            return None  # the XSD reports it

    def _enum(self, el: Any) -> Enum | None:
        name = el.get("name")
        if not name:
            return None
        e = Enum(name, self.loc(el, "name"), "", el.get("bitmask") == "true")
        e.parts.append(e.loc)
        highest = 0
        for child in el:
            tag = child.tag
            if tag == "description":
                e.description = _text(child)
            elif tag in ("deprecated", "superseded"):
                e.deprecated = _deprecation(child)
            elif tag == "wip":
                e.wip = True
            elif tag == "entry":
                a = dict(child.attrib)
                ename = a.get("name")
                if not ename:
                    continue
                raw = a.get("value")
                if raw is None:
                    value, auto = highest + 1, True
                else:
                    parsed = parse_enum_value(raw)
                    if parsed is None:
                        bare = raw.strip()
                        why = ("is negative; the schema (mavschema.xsd) allows enum values from 0 up"
                               if bare[:1] == "-" and parse_enum_value(bare[1:]) is not None else
                               "is not an integer (decimal, 0x hex, 0b binary or 2**N)")
                        self.error(child, "value", "ENUM-VALUE", f"enum entry {ename}: value '{raw}' {why}", ename)
                        continue
                    value, auto = parsed, False
                highest = max(highest, value)
                loc = Loc(self.src, child.sourceline or 1, "entry", "name")
                e.entries.append(EnumEntry(ename, value, loc, auto, child if len(child) else None))
        return e


    def _message(self, el: Any) -> Message | None:
        name = el.get("name")
        raw_id = el.get("id")
        if not name or raw_id is None:
            return None  # the XSD reports the missing attribute
        try:
            msgid = int(raw_id.strip())
        except ValueError:
            self.error(el, "id", "MSG-ID", f"message {name}: id '{raw_id}' is not an integer", name)
            msgid = -1
        else:
            if not 0 <= msgid <= MAX_MSG_ID:
                self.error(el, "id", "MSG-ID-RANGE",
                           f"message {name}: id {msgid} is outside MAVLink 2's 24-bit range 0..{MAX_MSG_ID}",
                           name)
        msg = Message(msgid, name, self.loc(el, "name"))
        in_ext = False
        ext_el: Any = None
        broken = msgid < 0
        for child in el:
            tag = child.tag
            if tag == "field":
                f = self._field(msg, child, in_ext)
                if f is None:
                    broken = True
                else:
                    msg.fields.append(f)
            elif tag == "extensions":
                if in_ext:
                    self.error(child, None, "EXTENSIONS",
                               f"message {name}: more than one <extensions/> marker", name)
                in_ext, ext_el = True, child
            elif tag == "description":
                msg.description = _text(child)
            elif tag in ("deprecated", "superseded"):
                msg.deprecated = _deprecation(child)
            elif tag == "wip":
                msg.wip = True
        if ext_el is not None and not any(f.extension for f in msg.fields):
            self.error(ext_el, None, "EXTENSIONS",
                       f"message {name}: <extensions/> is not followed by any field", name)
            self.covered.add((el.sourceline or 1, None))
        if not broken and not msg.fields:
            return None  # XSD: a message needs at least one field
        msg.complete = not broken
        msg.finalize()
        return msg

    def _field(self, msg: Message, el: Any, extension: bool) -> Field | None:
        a = el.attrib
        name = a.get("name")
        raw_type = a.get("type")
        if not name or raw_type is None:
            return None
        parsed = _parse_type(raw_type)
        if parsed is None:
            self.error(el, "type", "FIELD-TYPE",
                       f"{msg.name}.{name}: '{raw_type}' is not a MAVLink type "
                       f"(one of {', '.join(BASE_TYPES)}, optionally with [N])", name)
            return None
        base, length, mavlink_version = parsed
        if length < 0:
            self.error(el, "type", "ARRAY-LENGTH",
                       f"{msg.name}.{name}: array length {-length - 1} is outside 1..255 "
                       "(MAVLink encodes it in one byte of CRC_EXTRA)", name)
            return None
        if mavlink_version and extension:
            self.error(el, "type", "EXTENSIONS",
                       f"{msg.name}.{name}: uint8_t_mavlink_version cannot be an extension field", name)
        return Field.at(self.src, el.sourceline or 1, name, base, length, a.get("enum") or None, extension,
                        mavlink_version, el)


def field_details(el: Any) -> dict[str, Any]:
    """What only the generators need of a <field> element."""
    a = el.attrib
    text = (el.text or "").strip()
    for sub in el:
        if sub.tag == "description":
            text = (text + " " + _text(sub)).strip()
    return {
        "description": text,
        "display": a.get("display"),
        "units": a.get("units"),
        "multiplier": a.get("multiplier"),
        "print_format": a.get("print_format"),
        "invalid": a.get("invalid"),
        "instance": a.get("instance") == "true",
    }


def entry_details(el: Any) -> tuple[str, list[EnumParam], Deprecation | None, bool]:
    """Description, params, deprecation and wip of an <entry> element."""
    description, params, deprecated, wip = "", [], None, False
    for sub in el:
        tag = sub.tag
        if tag == "description":
            description = _text(sub)
        elif tag == "param":
            params.append(_param(sub))
        elif tag in ("deprecated", "superseded"):
            deprecated = _deprecation(sub)
        elif tag == "wip":
            wip = True
    return description, params, deprecated, wip


def _param(el: Any) -> EnumParam:
    try:
        index = int(el.get("index", "0"))
    except ValueError:
        index = 0
    return EnumParam(
        index,
        _text(el),
        label=el.get("label"),
        units=el.get("units"),
        enum=el.get("enum"),
        reserved=el.get("reserved") == "true",
        default=el.get("default"),
        min_value=el.get("minValue"),
        max_value=el.get("maxValue"),
        increment=el.get("increment"),
    )


_TYPE_CACHE: dict[str, tuple[str, int, bool] | None] = {}


def _parse_type(raw: str) -> tuple[str, int, bool] | None:
    """'uint8_t[4]' -> ('uint8_t', 4, False); a bad array length comes back as -(length+1);
    None if not a MAVLink type. Memoised: dialects use a few dozen distinct spellings."""
    try:
        return _TYPE_CACHE[raw]
    except KeyError:
        pass
    m = _TYPE_RE.match(raw.strip())
    result: tuple[str, int, bool] | None = None
    if m:
        base, digits = m.group(1), m.group(2)
        length = int(digits) if digits is not None else 0
        mavlink_version = False
        if base == "uint8_t_mavlink_version" and digits is None:
            base, mavlink_version = "uint8_t", True
        elif base == "array":
            base = "int8_t"  # legacy spelling mavgen still accepts
        if base in BASE_TYPES:
            if digits is not None and not 1 <= length <= 255:
                length = -length - 1
            result = (base, length, mavlink_version)
    _TYPE_CACHE[raw] = result
    return result


class _Loader:
    def __init__(self, include_dirs: list[str], rep: Reporter, schema: bool) -> None:
        self.include_dirs = [os.path.abspath(d) for d in include_dirs]
        self.rep = rep
        self.schema = schema
        self.files: dict[str, DialectFile | None] = {}  # realpath -> file (None: unreadable)
        self.order: list[DialectFile] = []  # post-order: dependencies first
        self.shown: dict[str, str] = {}  # realpath -> path as the user will see it
        self.by_name: dict[str, str] = {}  # file name (case-folded) -> realpath of the first loaded
        self.incomplete = False  # an include is missing or unreadable
        self.edges: list[tuple[str, str, Loc, str]] = []  # includer, included (realpaths), where, as written

    def mavgen_depth(self, root: str) -> None:
        """Warn, once per chain, where a file is included deeper than pymavlink's mavgen follows.
        mavgen expands includes in rounds (breadth first), so a file's depth is its shortest chain."""
        parents: dict[str, tuple[str, Loc, str] | None] = {root: None}
        frontier, depth = [root], 0
        while frontier and depth <= MAVGEN_INCLUDE_NESTING:
            depth += 1
            nxt = []
            for f in frontier:
                for a, b, loc, name in self.edges:
                    if a == f and b not in parents:
                        parents[b] = (a, loc, name)
                        nxt.append(b)
            frontier = nxt
        for f in frontier if depth > MAVGEN_INCLUDE_NESTING else []:
            chain, at = [f], parents[f]
            assert at is not None
            _, loc, name = at
            while (up := parents[chain[-1]]) is not None:
                chain.append(up[0])
            shown = " -> ".join(os.path.basename(self.shown.get(p, p)) for p in reversed(chain))
            self.rep.warning(loc, "INCLUDE-DEPTH-MAVGEN",
                             f"includes nested {depth} deep ({shown}); pymavlink's mavgen follows includes only "
                             f"{MAVGEN_INCLUDE_NESTING} deep and stops with 'ERROR in includes tree, no base found!': "
                             "other MAVLink tools cannot build this dialect (fold a level into its includer)", name)

    def search_path(self, includer: str) -> list[str]:
        return [os.path.dirname(includer), *self.include_dirs]

    def resolve(self, includer: str, name: str) -> tuple[str, str | None] | None:
        """Where an include is, and whose shipped copy it is (None: the user's own)."""
        for d in self.search_path(includer):
            cand = os.path.normpath(os.path.join(d, name))
            if os.path.isfile(cand):
                return cand, None
        if _bare(name):
            for d, whose in shipped_dirs():
                cand = os.path.join(d, name)
                if os.path.isfile(cand):
                    return cand, whose
        return None

    def missing(self, includer: str, name: str, loc: Loc) -> None:
        self.incomplete = True
        looked = ", ".join(_short_dir(d) for d in self.search_path(includer))
        if _bare(name):
            looked = ", ".join([looked, *(_short_dir(d) for d, _ in shipped_dirs())])
        else:
            looked += "; a path with a folder part is not looked up among the shipped dialects"
        self.rep.error(loc, "INCLUDE-MISSING", f"cannot find included file '{name}' (looked in {looked})", name)

    def load(self, path: str, stack: list[str], at: Loc | None) -> DialectFile | None:
        real = os.path.realpath(path)
        if real in self.files:
            return self.files[real]
        self.shown[real] = path
        self.by_name.setdefault(os.path.basename(real).casefold(), real)
        try:
            pf = parse_file(path)
        except Unreadable as e:
            self.files[real] = None
            self.incomplete = True
            if at is None:
                raise LoadError(path, e.code, e.message, e.line, e.col) from None
            self.rep.raw(path, e.line, e.col, "error", e.code, e.message)
            return None
        reader = _FileReader(pf, self.rep)
        df = reader.read()
        if self.schema:
            schema_check(pf, self.rep, reader.covered)
        self.files[real] = df
        stack = stack + [real]
        for name, loc in df.includes:
            if not name:
                self.rep.error(loc, "INCLUDE-MISSING", "empty <include>")
                continue
            found = self.resolve(path, name)
            if found is None:
                self.missing(path, name, loc)
                continue
            target, whose = found
            treal = os.path.realpath(target)
            first = self.by_name.get(os.path.basename(treal).casefold(), treal)
            if first != treal and (is_shipped(first) or is_shipped(treal)):
                self.rep.note(loc, "INCLUDE-SHIPPED", f"'{name}' is already loaded from "
                              f"{display_path(self.shown[first])}; that copy is used, not {display_path(target)}",
                              name)
                target, treal = self.shown[first], first
            elif whose is not None:
                self.rep.note(loc, "INCLUDE-SHIPPED", f"'{name}' is {whose} copy ({display_path(target)})", name)
            if treal in stack:
                chain = stack[stack.index(treal):] + [treal]
                shown = " -> ".join(os.path.basename(self.shown.get(p, p)) for p in chain)
                self.rep.error(loc, "INCLUDE-CYCLE", f"include cycle: {shown}", name)
                continue
            if len(stack) >= MAX_INCLUDE_DEPTH:
                self.rep.error(loc, "INCLUDE-DEPTH", f"includes nested deeper than {MAX_INCLUDE_DEPTH} files", name)
                continue
            self.edges.append((real, treal, loc, name))
            sub = self.load(target, stack, loc)
            if sub is not None:
                df.resolved.append(treal)
        self.order.append(df)
        return df


def resolve_include(includer: str, name: str, include_dirs: list[str]) -> str | None:
    """Where `<include>name</include>` in the file `includer` leads (a path), or None: the rule
    the loader follows, for a caller that checks that an earlier resolution still holds."""
    found = _Loader(include_dirs, Reporter(), False).resolve(includer, name)
    return found[0] if found is not None else None


def _bare(name: str) -> bool:
    """A file name without a folder part: only such a name is looked up among the shipped dialects."""
    return name == os.path.basename(name) and "\\" not in name and name not in (".", "..")


def _short_dir(d: str) -> str:
    for shipped, label in ((pymavlink_dialects_dir(), "pymavlink's dialects"),
                           (ttctl_dialects_dir(), "ttctl's shipped dialects")):
        if shipped and os.path.realpath(d) == os.path.realpath(shipped):
            return label
    return display_path(d) or "."


class _AutoEntries:
    """The auto-valued entries of a merged enum in merge order, in a tree of minimum values
    over positions: finding the next one at or after a position whose value is at most some
    bound costs O(log n), so merging many parts of one enum stays near linear."""

    def __init__(self) -> None:
        self.entries: list[EnumEntry] = []
        self.size = 1
        self.tree: list[float] = [float("inf")] * 2

    def append(self, entry: EnumEntry) -> None:
        if len(self.entries) == self.size:
            self.size *= 2
            self.tree = [float("inf")] * (2 * self.size)
            for i, x in enumerate(self.entries):
                self.tree[self.size + i] = x.value
            for i in range(self.size - 1, 0, -1):
                self.tree[i] = min(self.tree[2 * i], self.tree[2 * i + 1])
        self.entries.append(entry)
        self._set(len(self.entries) - 1, entry.value)

    def _set(self, i: int, value: int) -> None:
        i += self.size
        self.tree[i] = value
        i //= 2
        while i:
            self.tree[i] = min(self.tree[2 * i], self.tree[2 * i + 1])
            i //= 2

    def _first_at_most(self, start: int, bound: int) -> int | None:
        """The first position >= start whose value is <= bound, or None."""
        tree, size = self.tree, self.size

        def down(node: int, lo: int, hi: int) -> int | None:
            if hi <= start or tree[node] > bound:
                return None
            if node >= size:
                return lo
            mid = (lo + hi) // 2
            found = down(2 * node, lo, mid)
            return found if found is not None else down(2 * node + 1, mid, hi)

        return down(1, 0, size)

    def renumber(self, highest: int) -> int:
        """mavgen's rule, in merge order: each auto-valued entry whose value is at most
        `highest` becomes highest + 1, which is the new highest. Returns the last highest."""
        i = self._first_at_most(0, highest)
        while i is not None:
            entry = self.entries[i]
            entry.value = highest = highest + 1
            self._set(i, entry.value)
            i = self._first_at_most(i + 1, highest)
        return highest


def merge_enums(files: list[DialectFile], rep: Reporter) -> list[Enum]:
    """Merge same-named enums across files (first definition wins its header), adjusting
    auto-assigned values as mavgen does, then sort entries by value."""
    merged: dict[str, Enum] = {}
    # per merged enum: its lowest value (a lower bound once entries are renumbered upwards,
    # which only ever makes the overlap test below run a renumbering that changes nothing),
    # its highest value, and its auto-valued entries
    state: dict[str, tuple[int, int, _AutoEntries]] = {}
    for df in files:
        for e in df.enums:
            first = merged.get(e.name)
            lo_new = min((x.value for x in e.entries), default=0)
            hi_new = max((x.value for x in e.entries), default=0)
            if first is None:
                m = merged[e.name] = Enum(e.name, e.loc, e.description, e.bitmask)
                m.entries = list(e.entries)
                m.deprecated, m.wip, m.parts = e.deprecated, e.wip, [e.loc]
                autos = _AutoEntries()
                for x in e.entries:
                    if x.autovalue:
                        autos.append(x)
                state[e.name] = (lo_new, hi_new, autos)
                continue
            lo_old, hi_old, autos = state[e.name]
            if first.entries and lo_old <= hi_new and hi_old >= lo_new:
                hi_new = autos.renumber(hi_new)
            for x in e.entries:
                if x.autovalue:
                    autos.append(x)
            if first.entries or e.entries:
                lo_old = min(lo_old, lo_new) if first.entries else lo_new
                hi_old = max(hi_old, hi_new) if first.entries else hi_new
            state[e.name] = (lo_old, hi_old, autos)
            if e.bitmask != first.bitmask:
                rep.warning(e.loc.at("bitmask"), "ENUM-MERGE",
                            f"enum {e.name} is {'a bitmask' if e.bitmask else 'not a bitmask'} here but "
                            f"{'is' if first.bitmask else 'is not'} at {first.loc.short()}", e.name)
            first.entries.extend(e.entries)
            first.parts.append(e.loc)
            if not first.description:
                first.description = e.description
    for e in merged.values():
        e.entries.sort(key=lambda x: x.value)
    return list(merged.values())


def load_dialect(path: str, include_dirs: list[str] | None = None, schema: bool = True) -> LoadResult:
    """Load a dialect and everything it includes. Raises LoadError only when the root file
    itself is unreadable; every other problem is a diagnostic in the result."""
    rep = Reporter()
    loader = _Loader(include_dirs or [], rep, schema)
    root = loader.load(path, [], None)
    assert root is not None
    loader.mavgen_depth(os.path.realpath(path))
    files = loader.order
    enums = merge_enums(files, rep)
    messages = [m for f in files for m in f.messages]
    dialect = Dialect(root, files, messages, enums)
    dialect.incomplete = loader.incomplete
    order = [f.path for f in reversed(files)]
    for shown in loader.shown.values():
        if shown not in order:
            order.append(shown)
    return LoadResult(dialect, rep, order)
