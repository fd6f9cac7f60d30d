"""`ttctl gen --lang xml`: the dialect as ONE self-contained MAVLink XML, its includes resolved.

Tools that load a dialect at run time (MAVSDK's MavlinkDirect `load_custom_xml`, libmav) take one
XML text and do not follow <include>. This writes every message of every file (dependencies
first, as mavgen reads them) and every enum as merged across the files, from the loaded model:
fields in their declared order with `<extensions/>` before the first extension field, so the
wire order and CRC_EXTRA that mavgen derives from it are those of the original files. Entry
values are written out (auto-numbered entries included); descriptions, units, enum
references and MAV_CMD parameters are kept; deprecation notes and <wip/> are left out (they do
not change the wire).
"""

from __future__ import annotations

import os
from xml.sax.saxutils import escape, quoteattr

from ..dialect.model import Dialect, Enum, Field, Message


def export_path(d: Dialect) -> str:
    """Where the file goes under the output root."""
    return f"xml/{d.name}.xml"


def _attrs(pairs: list[tuple[str, object]]) -> str:
    return "".join(f" {k}={quoteattr(str(v))}" for k, v in pairs if v is not None and v is not False)


def _text(s: str) -> str:
    return escape(" ".join(s.split()))


def _field(f: Field) -> str:
    pairs: list[tuple[str, object]] = [("type", f.declared_type), ("name", f.name), ("enum", f.enum),
                                       ("units", f.units), ("display", f.display),
                                       ("multiplier", f.multiplier), ("print_format", f.print_format),
                                       ("invalid", f.invalid), ("instance", "true" if f.instance else None)]
    return f"      <field{_attrs(pairs)}>{_text(f.description)}</field>"


def _message(m: Message) -> list[str]:
    out = [f"    <message{_attrs([('id', m.id), ('name', m.name)])}>",
           f"      <description>{_text(m.description)}</description>"]
    extended = False
    for f in m.fields:
        if f.extension and not extended:
            out.append("      <extensions/>")
            extended = True
        out.append(_field(f))
    out.append("    </message>")
    return out


def _enum(e: Enum) -> list[str]:
    out = [f"    <enum{_attrs([('name', e.name), ('bitmask', 'true' if e.bitmask else None)])}>"]
    if e.description:
        out.append(f"      <description>{_text(e.description)}</description>")
    for entry in e.entries:
        out.append(f"      <entry{_attrs([('value', entry.value), ('name', entry.name)])}>")
        if entry.description:
            out.append(f"        <description>{_text(entry.description)}</description>")
        for p in entry.params:
            pairs: list[tuple[str, object]] = [
                ("index", p.index), ("label", p.label), ("units", p.units), ("enum", p.enum),
                ("reserved", "true" if p.reserved else None), ("default", p.default), ("minValue", p.min_value),
                ("maxValue", p.max_value), ("increment", p.increment)]
            out.append(f"        <param{_attrs(pairs)}>{_text(p.description)}</param>")
        out.append("      </entry>")
    out.append("    </enum>")
    return out


def flatten(d: Dialect) -> str:
    files = [os.path.basename(f.path) for f in d.files]
    root = d.root
    lines = ['<?xml version="1.0" encoding="utf-8"?>',
             f"<!-- {escape(os.path.basename(root.path))} with its includes resolved into one file "
             f"({escape(', '.join(files))}) by ttctl gen, language xml, for tools that load one XML and "
             "do not follow includes (MAVSDK's MavlinkDirect load_custom_xml, libmav). -->",
             "<mavlink>",
             f"  <version>{d.version}</version>",
             f"  <dialect>{root.dialect if root.dialect is not None else 0}</dialect>",
             "  <enums>"]
    for e in d.enums:
        lines.extend(_enum(e))
    lines.append("  </enums>")
    lines.append("  <messages>")
    for m in d.messages:
        if m.complete:
            lines.extend(_message(m))
    lines.append("  </messages>")
    lines.append("</mavlink>")
    return "\n".join(lines) + "\n"
