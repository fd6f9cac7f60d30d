"""Text helpers shared by the language modules."""

from __future__ import annotations


def wrap(text: str, width: int) -> list[str]:
    """Greedy word wrap: what textwrap.wrap(text, width, break_long_words=False,
    break_on_hyphens=False) gives for text of single-space-separated words, several times
    faster (the generators wrap tens of thousands of doc comments)."""
    lines: list[str] = []
    line: list[str] = []
    size = 0
    for word in text.split():
        if line and size + 1 + len(word) > width:
            lines.append(" ".join(line))
            line, size = [word], len(word)
        else:
            size += len(word) + (1 if line else 0)
            line.append(word)
    if line:
        lines.append(" ".join(line))
    return lines
