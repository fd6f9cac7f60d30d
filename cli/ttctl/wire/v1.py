"""MAVLink 1 frames from ground stations that speak it, and answers to them in kind (sans-IO).

pymavlink speaks MAVLink 1 unless told otherwise (MAVLINK20 unset), and so do older ground
stations; ttctl's link and ends speak MAVLink 2. A MAVLink 1 frame (magic 0xFE, 8 bytes of
framing: len, seq, sysid, compid, msgid < 256, payload, CRC-16/MCRF4XX over it with the
message's CRC_EXTRA) carries the same payload as MAVLink 2 without the extension fields, so it
is upgraded by re-framing: the MAVLink 2 parser then sees an ordinary frame. Answers go back to a
station that spoke MAVLink 1 as MAVLink 1 when the message allows it (msgid < 256; the payload
padded to its full length and cut to the fields MAVLink 1 has); those that cannot (msgid 256 and
up) are counted and named once. See the MAVLink guide, "Serialization" and "MAVLink 2".
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from fastcrc import crc16

V1_MAGIC = 0xFE
V2_MAGIC = 0xFD
V1_OVERHEAD = 8  # magic, len, seq, sysid, compid, msgid, CRC (2)
V2_HEADER = 10
SIGNED = 0x01
MAX_BUFFER = 4096  # a stream that never completes a frame is not held beyond this


def _crc(body: bytes, extra: int) -> int:
    return int(crc16.mcrf4xx(body + bytes((extra,))))


class Upgrader:
    """Turns a station's bytes into MAVLink 2 bytes: MAVLink 1 frames re-framed (those with a
    bad CRC or a msgid the dialect lacks are dropped and counted), MAVLink 2 frames and anything
    else passed on unchanged for the MAVLink 2 parser. Holds at most one incomplete frame."""

    def __init__(self, registry: dict[int, Any], on_unknown: Callable[[int], None] | None = None) -> None:
        self.registry = registry
        self.on_unknown = on_unknown
        self._buf = b""
        self.v1_frames = 0  # upgraded
        self.v1_bad_crc = 0
        self.v1_unknown = 0  # msgids the dialect lacks
        self.saw_v1 = False
        self.saw_v2 = False

    def feed(self, data: bytes, datagram: bool = False) -> bytes:
        """`datagram`: `data` is one whole UDP datagram (no frame spans two): what is left
        incomplete at its end is passed on as it is, not held for the next one."""
        buf = self._buf + bytes(data)
        out = bytearray()
        i, n = 0, len(buf)
        while i < n:
            magic = buf[i]
            if magic == V2_MAGIC:
                if n - i < 3:
                    break
                total = V2_HEADER + buf[i + 1] + 2 + (13 if buf[i + 2] & SIGNED else 0)
                if n - i < total:
                    break
                out += buf[i:i + total]
                self.saw_v2 = True
                i += total
            elif magic == V1_MAGIC:
                if n - i < 2:
                    break
                total = V1_OVERHEAD + buf[i + 1]
                if n - i < total:
                    break
                frame = buf[i:i + total]
                if self.registry.get(buf[i + 5]) is None:
                    # its CRC cannot be checked without CRC_EXTRA, so it may be no frame at all: from a
                    # station that has sent good MAVLink 1 frames it is counted and named once
                    if self.saw_v1:
                        self.v1_unknown += 1
                        if self.on_unknown is not None:
                            self.on_unknown(buf[i + 5])
                    out.append(buf[i])
                    i += 1
                    continue
                up = self._upgrade(frame)
                if up is None:
                    out.append(buf[i])  # not a frame after all: resynchronise after its magic
                    i += 1
                    continue
                out += up
                i += total
            else:
                j = i + 1
                while j < n and buf[j] not in (V1_MAGIC, V2_MAGIC):
                    j += 1
                out += buf[i:j]  # the MAVLink 2 parser counts what it skips
                i = j
        rest = buf[i:]
        if datagram:
            out += rest  # the MAVLink 2 parser keeps or drops it as it would without us
            rest = b""
        self._buf = rest if len(rest) <= MAX_BUFFER else b""
        return bytes(out)

    def reset(self) -> None:
        self._buf = b""

    def _upgrade(self, frame: bytes) -> bytes | None:
        length, seq, sysid, compid, msgid = frame[1], frame[2], frame[3], frame[4], frame[5]
        info = self.registry[msgid]
        got = frame[-2] | frame[-1] << 8
        if _crc(frame[1:-2], info.crc_extra) != got:
            self.v1_bad_crc += 1
            return None
        self.v1_frames += 1
        self.saw_v1 = True
        payload = frame[6:6 + length]
        header = bytes((V2_MAGIC, length, 0, 0, seq, sysid, compid, msgid, 0, 0))
        body = header[1:] + payload
        crc = _crc(body, info.crc_extra)
        return header + payload + bytes((crc & 0xFF, crc >> 8))


def downgrade(frame: bytes, registry: dict[int, Any]) -> bytes | None:
    """A MAVLink 2 frame as MAVLink 1, or None when MAVLink 1 cannot carry it (msgid over 255,
    a message the dialect lacks). A signature is dropped: MAVLink 1 has none."""
    if len(frame) < V2_HEADER + 2 or frame[0] != V2_MAGIC:
        return None
    msgid = frame[7] | frame[8] << 8 | frame[9] << 16
    info = registry.get(msgid)
    if msgid > 255 or info is None:
        return None
    payload = frame[V2_HEADER:V2_HEADER + frame[1]]
    payload = (payload + bytes(max(0, info.length - len(payload))))[:info.min_length]
    body = bytes((len(payload), frame[4], frame[5], frame[6], msgid)) + payload
    crc = _crc(body, info.crc_extra)
    return bytes((V1_MAGIC,)) + body + bytes((crc & 0xFF, crc >> 8))


__all__ = ["Upgrader", "downgrade"]
