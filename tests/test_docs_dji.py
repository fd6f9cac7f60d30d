"""docs/dji/: the aircraft table, the links' numbers and the frame sizes it states are ttctl's own
(profiles.toml, the transfer's Geometry), and every page it links to is there."""

from __future__ import annotations

import re
from pathlib import Path

from ttctl.link.model import load_profile
from ttctl.proto.transfer import WIDE, Geometry

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs" / "dji"


def test_the_frame_table_is_the_geometry() -> None:
    text = (DOCS / "platforms.md").read_text()
    for mtu in (100, 128):
        g, s = Geometry(mtu), Geometry(mtu, signed=True)
        row = next(line for line in text.splitlines() if line.startswith(f"| {'DTT' if mtu == 100 else 'Payload'}"))
        assert f"{g.narrow_cap} {'file bytes ' if not g.narrow_fit else ''}in {g.narrow_frame}" in row, row
        assert f"{s.narrow_cap} in {s.narrow_frame}" in row, row
        assert f"{g.narrow_cap / g.narrow_frame:.3f}".rstrip("0") in row, row
        assert f"{s.narrow_cap / s.narrow_frame:.3f}".rstrip("0") in row, row
    assert f"{WIDE} bytes in {Geometry().wide_frame}" in text


def test_the_profiles_named_are_the_shipped_ones() -> None:
    text = (DOCS / "platforms.md").read_text()
    readme = (ROOT / "README.md").read_text()
    for name, mtu in (("m100", 100), ("m300", 100), ("psdk", 128)):
        assert load_profile(name).mtu == mtu
        assert f"`{name}`" in text and f"`{name}`" in readme
    psdk = load_profile("psdk")
    assert (psdk.capacity_Bps("up", 10), psdk.capacity_Bps("down", 10)) == (3000, 4000)
    assert "3000 B/s up, 4000 B/s down" in text
    assert psdk.down.queue_bytes == 512 and "512-byte" in text


def test_every_linked_page_is_there() -> None:
    """In every page of the manual: README.md and docs/ (the site's pages link relative to docs/)."""
    for page in [*(ROOT / "docs").rglob("*.md"), ROOT / "README.md"]:
        prose = re.sub(r"```.*?```", "", page.read_text(), flags=re.S)  # code blocks hold lambdas, not links
        for target in re.findall(r"\]\(((?!https?:)[^)#]+)(?:#[^)]*)?\)", prose):
            assert (page.parent / target).exists(), f"{page.name} links to {target}, which is not there"
