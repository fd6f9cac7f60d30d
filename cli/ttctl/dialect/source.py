"""Reading one dialect file safely: size and type checks, no DTDs or entities, no network,
line numbers kept, and the XSD check against pymavlink's mavschema.xsd."""

from __future__ import annotations

import os
import re
from functools import lru_cache
from typing import TYPE_CHECKING, Any, NamedTuple

from .diagnostics import Loc, Reporter, SourceText

if TYPE_CHECKING:
    from lxml import etree

MAX_FILE_BYTES = 8 * 1024 * 1024  # the largest official dialect (common.xml) is 0.6 MB


class Unreadable(Exception):
    """The file could not be read or parsed at all; carries one diagnostic."""

    def __init__(self, code: str, message: str, line: int = 1, col: int = 1) -> None:
        super().__init__(message)
        self.code = code
        self.message = message
        self.line = line
        self.col = col


class ParsedFile(NamedTuple):
    path: str
    source: SourceText
    root: Any  # lxml Element


@lru_cache(maxsize=1)
def pymavlink_dir() -> str | None:
    """pymavlink's package folder, found without importing it."""
    import importlib.util

    spec = importlib.util.find_spec("pymavlink")
    if spec is None or not spec.submodule_search_locations:
        return None
    return next(iter(spec.submodule_search_locations))


@lru_cache(maxsize=1)
def pymavlink_dialects_dir() -> str | None:
    base = pymavlink_dir()
    if base is None:
        return None
    d = os.path.join(base, "dialects", "v20")
    return d if os.path.isdir(d) else None


def read_bytes(path: str) -> bytes:
    try:
        st = os.stat(path)
    except FileNotFoundError:
        raise Unreadable("READ", "no such file") from None
    except OSError as e:
        raise Unreadable("READ", f"cannot read: {e.strerror or e}") from None
    import stat

    if stat.S_ISDIR(st.st_mode):
        raise Unreadable("READ", "is a directory, not a dialect file")
    if not stat.S_ISREG(st.st_mode):
        raise Unreadable("READ", "is not a regular file")
    if st.st_size > MAX_FILE_BYTES:
        raise Unreadable(
            "TOO-LARGE",
            f"file is {st.st_size / 1e6:.1f} MB; dialect files over {MAX_FILE_BYTES // 2**20} MiB are refused",
        )
    try:
        with open(path, "rb") as fh:
            data = fh.read(MAX_FILE_BYTES + 1)
    except OSError as e:
        raise Unreadable("READ", f"cannot read: {e.strerror or e}") from None
    if len(data) > MAX_FILE_BYTES:
        raise Unreadable("TOO-LARGE", f"file grew past {MAX_FILE_BYTES // 2**20} MiB while reading")
    return data


_DTD_RE = re.compile(rb"<!(DOCTYPE|ENTITY)\b", re.IGNORECASE)


def parse_file(path: str) -> ParsedFile:
    """Read and parse; raises Unreadable with a single clear diagnostic."""
    from lxml import etree

    data = read_bytes(path)
    if not data.strip():
        raise Unreadable("XML-SYNTAX", "file is empty")
    m = _DTD_RE.search(data)
    if m:
        line = data.count(b"\n", 0, m.start()) + 1
        col = m.start() - (data.rfind(b"\n", 0, m.start()) + 1) + 1
        raise Unreadable(
            "DTD",
            f"<!{m.group(1).decode().upper()}> is not allowed in a dialect file "
            "(document type declarations and entities can expand without bound or read other files)",
            line,
            col,
        )
    parser = etree.XMLParser(
        resolve_entities=False, no_network=True, load_dtd=False, huge_tree=False, remove_pis=True
    )
    try:
        root = etree.fromstring(data, parser)
    except etree.XMLSyntaxError as e:
        line, col = e.position if e.position else (1, 1)
        msg = (e.msg or str(e)).splitlines()[0]
        msg = re.sub(r",? line \d+, column \d+$", "", msg)
        code = "XML-SYNTAX"
        if "UTF-8" in msg or "encoding" in msg.lower():
            code = "ENCODING"
            msg = f"{msg.rstrip('.! ')}: the file is not valid in its declared encoding (UTF-8 unless declared)"
        raise Unreadable(code, msg, line or 1, col or 1) from None
    return ParsedFile(path, SourceText(path, data), root)


@lru_cache(maxsize=1)
def _schema() -> etree.XMLSchema | None:
    from lxml import etree

    base = pymavlink_dir()
    if base is None:
        return None
    xsd = os.path.join(base, "generator", "mavschema.xsd")
    try:
        doc = etree.parse(xsd)
    except (OSError, etree.XMLSyntaxError):
        return None
    # As mavgen does without --strict-units: accept any units string.
    ns = {"xs": "http://www.w3.org/2001/XMLSchema"}
    for el in doc.getroot().iterfind('xs:attribute[@name="units"]', ns):
        el.set("type", "xs:string")
    return etree.XMLSchema(doc)


_XSD_ATTR_RE = re.compile(r"^Element '([^']+)'(?:, attribute '([^']+)')?: (.*)$", re.S)


SLICE = 500  # children of a section (or entries of an enum) per validation unit


def _units(root: Any) -> list[Any]:
    """What to hand to the XSD validator: the document itself, or for a large one copies of it
    holding a slice of its messages (or of an enum's entries) each. libxml2 names each error's
    node by its position among its siblings, which costs as many steps as there are siblings
    before it: 60,000 broken messages took minutes in one piece, a second in slices. Copies
    keep their source lines."""
    import copy

    from lxml import etree

    sections = {c.tag: c for c in root if isinstance(c.tag, str)}
    msgs = sections.get("messages")
    enums = sections.get("enums")
    big_enums = [e for e in (enums if enums is not None else []) if len(e) > SLICE]
    if (msgs is None or len(msgs) <= SLICE) and (enums is None or len(enums) <= SLICE) and not big_enums:
        return [root.getroottree()]

    def skeleton(keep: str | None) -> Any:
        r = etree.Element(root.tag, dict(root.attrib))
        for c in root:
            if not isinstance(c.tag, str):
                continue
            if c.tag not in ("messages", "enums"):
                r.append(copy.deepcopy(c))
            elif c.tag != keep:
                r.append(etree.Element(c.tag, dict(c.attrib)))  # the other section, empty
        return r

    units = []
    for tag in ("enums", "messages"):
        section = sections.get(tag)
        if section is None:
            continue
        kids = [k for k in section if not (tag == "enums" and k in big_enums)]
        for i in range(0, max(1, len(kids)), SLICE):
            r = skeleton(tag)
            part = etree.SubElement(r, tag, dict(section.attrib))
            part.extend(copy.deepcopy(k) for k in kids[i:i + SLICE])
            _reorder(r)
            units.append(r)
    for e in big_enums:
        entries = list(e)
        for i in range(0, len(entries), SLICE):
            r = skeleton("enums")
            part = etree.SubElement(r, "enums")
            shell = etree.SubElement(part, e.tag, dict(e.attrib))
            shell.extend(copy.deepcopy(k) for k in entries[i:i + SLICE] if i == 0 or k.tag == "entry")
            _reorder(r)
            units.append(r)
    return units


def _reorder(r: Any) -> None:
    """Sections back in the order the schema wants (enums before messages)."""
    msgs = r.find("messages")
    if msgs is not None:
        r.remove(msgs)
        r.append(msgs)


def schema_check(pf: ParsedFile, rep: Reporter, covered: set[tuple[int, str | None]]) -> None:
    """Report XSD violations, skipping (line, attribute) pairs the loader already explained."""
    schema = _schema()
    if schema is None:
        rep.raw(pf.path, 1, 1, "warning", "XSD", "pymavlink's mavschema.xsd not found; schema check skipped")
        return
    errors = []
    seen: set[tuple[int, str]] = set()
    for unit in _units(pf.root):
        if schema.validate(unit):
            continue
        for err in schema.error_log:
            if (err.line, err.message) not in seen:  # what every slice repeats (the header) once
                seen.add((err.line, err.message))
                errors.append(err)
    errors.sort(key=lambda e: e.line)
    for err in errors:
        m = _XSD_ATTR_RE.match(err.message)
        tag, attr, text = (m.group(1), m.group(2), m.group(3)) if m else (None, None, err.message)
        if (err.line, attr) in covered or (err.line, "*") in covered:
            continue
        text = " ".join(text.split())
        text = text.replace("[facet 'pattern'] ", "")
        what = f"<{tag}>" + (f" attribute '{attr}'" if attr else "") if tag else ""
        loc = Loc(pf.source, err.line, tag, attr)
        rep.error(loc, "XSD", f"{what}: {text}" if what else text)
