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


SLICE = 500  # element children per container in one validation unit

# What a later slice of a container repeats from its start so that its slice is read in the same
# context: the children before the first repeated one (description, wip, deprecated...), and
# for a message its first field too (a message needs one before <extensions/>).
_REPEATED = {"message": "field", "enum": "entry", "entry": "param"}


def _units(root: Any) -> tuple[list[Any], dict[Any, Any]]:
    """What to hand to the XSD validator: the document itself, or for a large one pieces of it
    in which no element has more than about SLICE children. libxml2 names each error's node by
    its position among its siblings, which costs as many steps as there are siblings before
    it: 60,000 broken messages (or 200,000 broken fields of one message) took minutes in one
    piece, a second in slices. Every element is in some piece; pieces keep source lines and
    repeat what they need around a slice (an ancestor's leading children, an empty
    <messages/>). Also returns, for each element copied without its children into several
    pieces, the original element."""
    marked = _big_containers(root)
    if not marked:
        return [root.getroottree()], {}
    origin: dict[Any, Any] = {}
    pieces = _pieces(root, marked, origin)
    messages = next((c for c in root if c.tag == "messages"), None)
    for piece in pieces:
        if piece.find("messages") is None:  # required; an empty one is valid
            piece.append(_shell(messages) if messages is not None else piece.makeelement("messages", {}))
    return pieces, origin


def _big_containers(root: Any) -> set[Any]:
    """Elements with more than SLICE children, and their ancestors."""
    marked: set[Any] = set()
    for el in root.iter():
        if len(el) > SLICE:
            while el is not None and el not in marked:
                marked.add(el)
                el = el.getparent()
    return marked


def _shell(el: Any) -> Any:
    """A copy of `el` without its children, on its source line, in a document of its own."""
    from lxml import etree

    c = etree.Element(el.tag, dict(el.attrib))
    c.text = el.text
    c.sourceline = el.sourceline
    return c


def _pieces(el: Any, marked: set[Any], origin: dict[Any, Any]) -> list[Any]:
    import copy

    if el not in marked:
        return [copy.deepcopy(el)]
    kids = [k for k in el if isinstance(k.tag, str)]  # comments and PIs do not matter to the XSD
    context: list[Any] = []
    repeated = _REPEATED.get(el.tag)
    if repeated is not None:
        for k in kids:
            if k.tag == repeated:
                if el.tag == "message":
                    context.append(k)
                break
            context.append(k)

    def piece(lead: list[Any]) -> Any:
        p = _shell(el)
        origin[p] = el
        p.extend(copy.deepcopy(k) for k in lead)
        return p

    pieces = []
    i = 0
    while i < len(kids):
        end = i + SLICE
        while end < len(kids) and kids[end - 1].tag == "extensions":
            end += 1  # <extensions/> needs the field after it in the same piece
        group = kids[i:end]
        i = end
        main = piece([k for k in context if k not in group])
        extra = []
        for k in group:
            sub = _pieces(k, marked, origin)
            main.append(sub[0])
            for s in sub[1:]:
                p = piece([c for c in context if c is not k])
                p.append(s)
                extra.append(p)
        pieces.append(main)
        pieces.extend(extra)
    return pieces


_CONTENT_ERRORS = ("This element is not expected", "Missing child element")


def _sliced_parent(unit: Any, err: Any, origin: dict[Any, Any]) -> Any:
    """For an error about an element's content (reported once per element) in a piece, the
    original element whose content it is, if that element was split across pieces."""
    if not any(t in err.message for t in _CONTENT_ERRORS) or not err.path:
        return None
    from lxml import etree

    steps = err.path.split("/", 2)  # "/mavlink/messages/message[3]": from the piece's root
    try:
        nodes = unit.xpath(steps[2]) if len(steps) > 2 else [unit]
    except etree.XPathError:
        return None
    if not nodes or not isinstance(nodes[0], etree._Element):
        return None
    node = nodes[0] if "Missing child element" in err.message else nodes[0].getparent()
    return origin.get(node)


def schema_check(pf: ParsedFile, rep: Reporter, covered: set[tuple[int, str | None]]) -> None:
    """Report XSD violations, skipping (line, attribute) pairs the loader already explained."""
    schema = _schema()
    if schema is None:
        rep.raw(pf.path, 1, 1, "warning", "XSD", "pymavlink's mavschema.xsd not found; schema check skipped")
        return
    units, origin = _units(pf.root)
    found = []
    seen: set[tuple[int, str]] = set()
    for unit in units:
        if schema.validate(unit):
            continue
        for err in schema.error_log:
            if (err.line, err.message) not in seen:  # what several pieces repeat, once
                seen.add((err.line, err.message))
                found.append((err, _sliced_parent(unit, err, origin) if origin else None))
    found.sort(key=lambda e: e[0].line)
    errors = []
    parents: set[Any] = set()
    for err, parent in found:
        if parent is not None:  # libxml2 reports one content error per element: so do the pieces
            if parent in parents:
                continue
            parents.add(parent)
        errors.append(err)
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
