"""Where the shipped templates and dialects are: inside the wheel (ttctl/_data) or, in a
source checkout / editable install, at the top of the repository."""

from __future__ import annotations

from pathlib import Path

_PKG = Path(__file__).resolve().parent


def data_dir(name: str) -> Path:
    """`templates` or `dialects`."""
    packaged = _PKG / "_data" / name
    if packaged.is_dir():
        return packaged
    checkout = _PKG.parent.parent / name
    if checkout.is_dir():
        return checkout
    raise FileNotFoundError(f"ttctl's {name} folder is missing (looked in {packaged} and {checkout})")


def shipped_dialect(name: str = "ttapi") -> Path:
    return data_dir("dialects") / f"{name}.xml"
