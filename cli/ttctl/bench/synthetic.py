"""Large valid dialects made up for benchmarks: `ttctl bench validate --synthetic N`."""

from __future__ import annotations

from pathlib import Path

# field sets rotated over the messages: scalars, arrays, a char array, an enum field, an
# extension; names kept short so that 60,000 messages stay under the 8 MiB input cap
_SHAPES = [
    '<field type="uint32_t" name="a">a</field>',
    '<field type="float" name="x">x</field><field type="int8_t" name="y">y</field>',
    '<field type="char[8]" name="s">s</field>',
    '<field type="uint8_t" name="b" enum="E">b</field>',
    '<field type="double[2]" name="d">d</field>',
    '<field type="uint16_t" name="n">n</field><extensions/><field type="int8_t" name="e">e</field>',
]


def synthetic_dialect(n: int, path: Path) -> Path:
    """Write a standalone dialect with `n` messages (ids from 1) to `path`."""
    parts = ['<?xml version="1.0"?>\n<mavlink><version>3</version><dialect>0</dialect><enums>'
             '<enum name="E"><entry value="0" name="E_A"/><entry value="1" name="E_B"/></enum></enums><messages>\n']
    for i in range(1, n + 1):
        parts.append(f'<message id="{i}" name="M{i}"><description>m</description>{_SHAPES[i % len(_SHAPES)]}'
                     '</message>\n')
    parts.append("</messages></mavlink>\n")
    path.write_text("".join(parts))
    return path
