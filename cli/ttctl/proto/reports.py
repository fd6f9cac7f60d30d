"""A receiver's report of what it holds, in its two wire forms (sans-IO): TT_FILE_STATUS's list
of missing ranges, and TT_FILE_MAP's bit per frame for when the gaps are more than a status
lists (a sender that reads maps says so with TT_FILE_FLAGS_MAP in its offer). The receiver
builds maps here (receiver.py builds statuses, which also carry results); the sender reads both
here into one `Report`, which sender.py applies; and which offer flags a refusal's words name
(`refused_flags`: a receiver from before TT_FILE_MAP refuses its flag by name).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from .transfer import MAP_MORE, RANGES_MORE


@dataclass(frozen=True)
class Report:
    """Bytes below `rc`, and in [region, end) outside `missing`, have arrived; past `end` they
    are unknown when `truncated` (more reports follow), else the sent ones are missing."""

    rc: int
    region: int
    end: int
    missing: list[tuple[int, int]]
    truncated: bool


def read_status(msg: Any, size: int) -> Report:
    """A TT_FILE_STATUS in progress, clamped to a file of `size` bytes."""
    rc = min(msg.received_contiguous, size)
    region = max(rc, min(msg.region_start, size))
    end = max(region, min(msg.received_end, size))
    n = min(msg.range_count & ~RANGES_MORE, len(msg.ranges) // 2)
    pairs = list(msg.ranges)
    missing = [(max(pairs[2 * i], region), min(pairs[2 * i + 1], end)) for i in range(n)]
    # a status listing every pair it has room for says, as the flag does, that more may follow
    truncated = bool(msg.range_count & RANGES_MORE) or n >= len(msg.ranges) // 2
    return Report(rc, region, end, [(a, b) for a, b in missing if a < b], truncated)


def read_map(msg: Any, size: int) -> Report:
    """A TT_FILE_MAP, clamped to a file of `size` bytes (its region starts at or just below
    received_contiguous, on the grid of the frames)."""
    rc = min(msg.received_contiguous, size)
    region = min(msg.region_start, size)
    end = max(region, rc, min(msg.received_end, size))
    return Report(rc, region, end, map_gaps(region, end, msg.chunk, bytes(msg.map)), bool(msg.flags & MAP_MORE))


def map_gaps(region: int, end: int, chunk: int, bits: bytes) -> list[tuple[int, int]]:
    """A TT_FILE_MAP's missing ranges: [region, end) cut into chunks of `chunk` bytes (the last
    shorter), those whose bit is clear (a bit each, least significant first; bits past the map's
    bytes clear too, as MAVLink 2 truncates trailing zero bytes), adjacent ones joined."""
    chunk = max(1, chunk)
    missing: list[tuple[int, int]] = []
    for i in range(min(8 * len(bits), -(-(end - region) // chunk))):
        if not bits[i >> 3] >> (i & 7) & 1:
            a, b = region + i * chunk, min(end, region + (i + 1) * chunk)
            if missing and missing[-1][1] == a:
                missing[-1] = (missing[-1][0], b)
            else:
                missing.append((a, b))
    past = region + 8 * len(bits) * chunk  # a region longer than its bits (no receiver sends one): missing
    if past < end:
        if missing and missing[-1][1] == past:
            missing[-1] = (missing[-1][0], end)
        else:
            missing.append((past, end))
    return missing


def map_regions(rc: int, last: int, last_offset: int, chunk: int, gaps: list[tuple[int, int]], map_bytes: int,
                burst: int) -> list[tuple[int, int, bytes, bool]]:
    """The maps of a report: (region start, region end, bits, more follow?) for at most `burst`
    successive regions of `8 * map_bytes` chunks from at or just below `rc` to `last`, on the grid
    of the latest frame (at `last_offset`: frames are lost whole, so a lost one is one clear bit);
    `gaps` are the missing ranges in [rc, last), ascending."""
    out = []
    start = max(0, rc - (rc - last_offset) % chunk)
    k = 0
    for _ in range(burst):
        end = min(last, start + 8 * map_bytes * chunk)
        m = bytearray(map_bytes)
        for i in range(-(-(end - start) // chunk)):
            m[i >> 3] |= 1 << (i & 7)
        while k < len(gaps) and gaps[k][0] < end:
            a, b = gaps[k]
            for i in range((max(a, start) - start) // chunk, (min(b, end) - 1 - start) // chunk + 1):
                m[i >> 3] &= ~(1 << (i & 7))
            if b > end:
                break
            k += 1
        more = end < last
        out.append((start, end, bytes(m), more))
        start = end
        if not more:
            break
    return out



def refused_flags(reason: str | None) -> int:
    """The offer flags a receiver's words say it does not understand ("offer flags 0x0c not
    understood here", as ttctl's receivers in every runtime say it); 0 if they name none."""
    at = (reason or "").find("offer flags 0x")
    try:
        return int((reason or "")[at + 14:at + 16], 16) if at >= 0 else 0
    except ValueError:
        return 0


__all__ = ["Report", "map_gaps", "map_regions", "read_map", "read_status", "refused_flags"]
