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


@lru_cache(maxsize=1)
def ttctl_dialects_dir() -> str | None:
    """ttctl's shipped dialects (dialects/ in a checkout, ttctl/_data/dialects in the wheel)."""
    from ..resources import data_dir

    try:
        return str(data_dir("dialects"))
    except FileNotFoundError:
        return None


def shipped_dirs() -> list[tuple[str, str]]:
    """(folder, whose copy it is) of the dialects ttctl and pymavlink ship, in the order a bare
    include name is looked up there."""
    return [(d, whose) for d, whose in ((ttctl_dialects_dir(), "ttctl's shipped"),
                                        (pymavlink_dialects_dir(), "pymavlink's")) if d is not None]


@lru_cache(maxsize=256)
def is_shipped(path: str) -> bool:
    """Whether a dialect file is one of the shipped copies."""
    folder = os.path.dirname(os.path.realpath(path))
    return any(folder == os.path.realpath(d) for d, _ in shipped_dirs())


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
_LAST_LINE = 65535  # libxml2 keeps a node's line in 16 bits: a copy of a later node has none

# What a later slice of a container repeats from its start so that its slice is read in the same
# context: the children before the first repeated one (description, wip, deprecated...), and
# for a message its first field too (a message needs one before <extensions/>).
_REPEATED = {"message": "field", "enum": "entry", "entry": "param"}


def _units(root: Any) -> tuple[list[Any], dict[Any, Any]]:
    """What to hand to the XSD validator: the document itself, or for a large one pieces of it
    in which no element has more than about SLICE children. libxml2 names each error's node by
    its position among its siblings, which costs as many steps as there are siblings before
    it: 60,000 broken messages (or 200,000 broken fields of one message) took minutes in one
    piece, a second in pieces. Every element is in some piece; pieces repeat what they need
    around a slice (an ancestor's leading children, an empty <messages/>). Also returns the
    original of every element a piece holds directly (copies deeper down mirror their
    original child for child)."""
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
    """A copy of `el` without its children, in a document of its own."""
    from lxml import etree

    c = etree.Element(el.tag, dict(el.attrib))
    c.text = el.text
    if el.sourceline is not None and el.sourceline < _LAST_LINE:
        c.sourceline = el.sourceline
    return c


def _pieces(el: Any, marked: set[Any], origin: dict[Any, Any]) -> list[Any]:
    """Copies of `el` that hold all of it between them: each has its leading children (the
    context), then a slice of the rest, after the last child of the slice before (so that an
    order broken across two slices is still seen); a child that is too large itself comes in
    pieces of its own."""
    import copy

    if el not in marked:
        return [copy.deepcopy(el)]
    kids = [k for k in el if isinstance(k.tag, str)]  # comments and PIs do not matter to the XSD
    context: list[Any] = []
    repeated = _REPEATED.get(el.tag)
    if repeated is not None:
        for k in kids:
            context.append(k)
            if k.tag == repeated:
                if el.tag != "message":
                    context.pop()
                break
    rest = kids[len(context):]

    def piece(lead: list[Any]) -> Any:
        p = _shell(el)
        origin[p] = el
        for k in lead:
            c = copy.deepcopy(k)
            origin[c] = k
            p.append(c)
        return p

    pieces = []
    i = 0
    while True:
        end = i + SLICE
        while end < len(rest) and rest[end - 1].tag == "extensions":
            end += 1  # <extensions/> needs the field after it in the same piece
        before = rest[i - 1:i] if i and rest[i - 1] not in marked else []  # a large one has its own pieces
        main = piece(context + before)
        extra = []
        for k in rest[i:end]:
            sub = _pieces(k, marked, origin)
            origin.setdefault(sub[0], k)
            main.append(sub[0])
            for s in sub[1:]:
                p = piece(context)
                p.append(s)
                extra.append(p)
        pieces.append(main)
        pieces.extend(extra)
        i = end
        if i >= len(rest):
            return pieces


def _original(unit: Any, err: Any, origin: dict[Any, Any]) -> Any:
    """The element of the parsed document an error in a piece is about, or None."""
    from lxml import etree

    steps = (err.path or "").split("/", 2)  # "/mavlink/messages/message[3]": from the piece's root
    if len(steps) < 2:
        return None
    try:
        found = unit.xpath(steps[2]) if len(steps) > 2 else [unit]
    except etree.XPathError:
        return None
    node = found[0] if found and isinstance(found[0], etree._Element) else None
    way: list[int] = []
    while node is not None and node not in origin:  # up to an element whose original is known
        parent = node.getparent()
        if parent is not None:
            way.append(parent.index(node))  # copies keep comments: the same index as in the original
        node = parent
    if node is None:
        return None
    original = origin[node]
    for i in reversed(way):
        original = original[i]
    return original


_NOT_EXPECTED, _MISSING_CHILD = "This element is not expected", "Missing child element"


def schema_check(pf: ParsedFile, rep: Reporter, covered: set[tuple[int, str | None]]) -> None:
    """Report XSD violations, skipping (line, attribute) pairs the loader already explained."""
    schema = _schema()
    if schema is None:
        rep.raw(pf.path, 1, 1, "warning", "XSD", "pymavlink's mavschema.xsd not found; schema check skipped")
        return
    units, origin = _units(pf.root)
    found: list[tuple[int, str, Any]] = []  # line, message, whose content it is about (pieces only)
    for unit in units:
        if schema.validate(unit):
            continue
        for err in schema.error_log:
            line, owner = err.line, None
            content = _NOT_EXPECTED in err.message or _MISSING_CHILD in err.message
            if origin and (content or not 0 < line < _LAST_LINE):
                node = _original(unit, err, origin)
                if node is not None:
                    line = node.sourceline or line
                    if content:
                        owner = node if _MISSING_CHILD in err.message else node.getparent()
            found.append((line, err.message, owner))
    found.sort(key=lambda e: e[0])
    errors: list[tuple[int, str]] = []
    seen: set[tuple[int, str]] = set()
    owners: set[Any] = set()
    for line, message, owner in found:
        if (line, message) in seen:  # what several pieces repeat, once
            continue
        seen.add((line, message))
        if owner is not None:  # as libxml2 in one piece: one error per element about its content
            if owner in owners:
                continue
            owners.add(owner)
        errors.append((line, message))
    for line, message in errors:
        m = _XSD_ATTR_RE.match(message)
        tag, attr, text = (m.group(1), m.group(2), m.group(3)) if m else (None, None, message)
        if (line, attr) in covered or (line, "*") in covered:
            continue
        text = " ".join(text.split())
        text = text.replace("[facet 'pattern'] ", "")
        what = f"<{tag}>" + (f" attribute '{attr}'" if attr else "") if tag else ""
        loc = Loc(pf.source, line, tag, attr)
        rep.error(loc, "XSD", f"{what}: {text}" if what else text)
