"""Deflate for the file transfer (TT_FILE_FLAGS_DEFLATE): what a sender offers instead of the
file when it saves, and how a receiver inflates what arrived, bounded by the size offered.

The offered bytes are a zlib stream (RFC 1950, as zlib.compress, java.util.zip.Deflater and C
zlib's compress2 write by default) of the file; the offer's metadata is the original file's
SHA-256, its size (uint32 little-endian) and its name, so the receiver checks the SHA-256 on
the inflated bytes. The stream is deterministic (one level, one strategy, whole-file), so a
restarted sender offering the same file offers the same bytes and the receiver's partial
stream resumes.

A sender compresses only when it saves: a sample first (cheap; JPEG, zip and other compressed
data stop there), then the whole file, kept only if it is clearly smaller.
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import tempfile
import zlib
from pathlib import Path
from typing import Any

from .names import MAX_NAME_BYTES, SHA_LEN

LEVEL = 6  # zlib's default: every implementation writes the same stream for it
SAMPLE = 64 * 1024  # bytes deflated to decide whether the rest is worth it
SAMPLE_RATIO = 0.9  # the sample must shrink below this
KEEP_RATIO = 0.97  # the whole stream must be below this fraction of the file
IN_MEMORY = 8 << 20  # streams up to this size stay in memory; larger go to a temporary file
CHUNK = 1 << 16
DEFLATE_META = SHA_LEN + 4  # SHA-256, original size, then the name
MAX_DEFLATE_NAME = MAX_NAME_BYTES - 4  # 219: a longer name goes uncompressed

__all__ = ["DEFLATE_META", "MAX_DEFLATE_NAME", "DeflatedSource", "InflateError", "deflate_meta", "deflated",
           "inflate_to", "parse_deflate_meta"]


class InflateError(Exception):
    """A stream that does not inflate to the file offered; the message says why, in words."""


def deflate_meta(sha256: bytes, original: int, name_raw: bytes) -> bytes:
    return sha256 + original.to_bytes(4, "little") + name_raw


def parse_deflate_meta(meta: bytes) -> tuple[bytes, int, bytes] | None:
    """(SHA-256, original size, name bytes) of a deflate offer's metadata; None if too short."""
    if len(meta) <= DEFLATE_META:
        return None
    return meta[:SHA_LEN], int.from_bytes(meta[SHA_LEN:DEFLATE_META], "little"), meta[DEFLATE_META:]


class DeflatedSource:
    """The zlib stream of a source, read by offset like the file itself; `sha256` and
    `original` are the file's (what the receiver checks), `size` is the stream's."""

    deflated = True

    def __init__(self, raw: Any, stream: bytes | None, spool: Any, size: int) -> None:
        self.raw = raw
        self.path = raw.path
        self.sha256 = raw.sha256
        self.original = raw.size
        self.size = size
        self._data = stream
        self._spool = spool  # an unnamed temporary file holding a large stream

    def read(self, offset: int, length: int) -> bytes:
        if self._data is not None:
            return self._data[offset:offset + length]
        return os.pread(self._spool.fileno(), length, offset)

    def changed(self) -> bool:
        return bool(self.raw.changed())

    def close(self) -> None:
        if self._spool is not None:
            self._spool.close()
            self._spool = None

    @property
    def ratio(self) -> float:
        return self.original / self.size if self.size else 1.0


def _chunks(raw: Any, start: int = 0) -> Any:
    pos = start
    while pos < raw.size:
        chunk = raw.read(pos, min(CHUNK, raw.size - pos))
        if not chunk:
            return
        yield chunk
        pos += len(chunk)


def deflated(raw: Any, name_raw: bytes) -> DeflatedSource | None:
    """The source deflated, or None when that would not save (incompressible data, a tiny
    file, a name too long for a deflate offer's metadata)."""
    if len(name_raw) > MAX_DEFLATE_NAME or raw.size < 2 * 100:  # less than two packets: nothing to win
        return None
    sample = raw.read(0, min(SAMPLE, raw.size))
    if len(zlib.compress(sample, LEVEL)) >= SAMPLE_RATIO * len(sample):
        return None
    limit = int(KEEP_RATIO * raw.size)
    z = zlib.compressobj(LEVEL)
    spool: Any = None
    parts: list[bytes] = []
    size = 0
    try:
        for out in _outputs(z, raw):
            size += len(out)
            if size >= limit:
                _drop(spool)
                return None
            if spool is None and size > IN_MEMORY:
                spool = tempfile.TemporaryFile(prefix="ttctl-deflate-")  # noqa: SIM115 (kept by the source)
                spool.write(b"".join(parts))
                parts = []
            if spool is not None:
                spool.write(out)
            else:
                parts.append(out)
        if spool is not None:
            spool.flush()
            return DeflatedSource(raw, None, spool, size)
        return DeflatedSource(raw, b"".join(parts), None, size)
    except OSError:
        _drop(spool)
        return None  # no room for the temporary stream: send the file as it is


def _outputs(z: Any, raw: Any) -> Any:
    for chunk in _chunks(raw):
        yield z.compress(chunk)
    yield z.flush()


def _drop(spool: Any) -> None:
    if spool is not None:
        spool.close()


def _zlib_words(e: zlib.error) -> str:
    """zlib's complaint in ttctl's terms: its detail when it gives one ("invalid stored block
    lengths"), never its bare status codes ("Error 2 while decompressing data" is Z_NEED_DICT)."""
    text = str(e)
    if ": " in text:
        return f"the stream does not inflate ({text.split(': ', 1)[1]})"
    if text.startswith("Error 2 "):
        return "the stream asks for a preset dictionary, which a ttctl stream never uses"
    return "the stream does not inflate (it is not a zlib stream as ttctl makes them)"


def inflate_to(src_fd: int, stream_size: int, dest: Path, original: int, sha256: bytes) -> None:
    """Inflate the zlib stream held in the first `stream_size` bytes of `src_fd` into `dest`
    (created, fsynced), never writing more than `original` bytes; InflateError, with `dest`
    removed, unless it inflates to exactly `original` bytes whose SHA-256 is `sha256`."""
    z = zlib.decompressobj()
    h = hashlib.sha256()
    written = 0
    fd = os.open(dest, os.O_WRONLY | os.O_CREAT | os.O_TRUNC | os.O_CLOEXEC, 0o644)
    ok = False
    try:
        pos = 0
        while True:
            if z.unconsumed_tail:
                data = z.unconsumed_tail
            elif pos < stream_size:
                data = os.pread(src_fd, min(CHUNK, stream_size - pos), pos)
                if not data:
                    raise InflateError("the stream is shorter than offered")
                pos += len(data)
            else:
                break
            try:
                out = z.decompress(data, original - written + 1)
            except zlib.error as e:
                raise InflateError(_zlib_words(e)) from None
            if written + len(out) > original:
                raise InflateError(f"the stream inflates to more than the {original} bytes offered")
            if out:
                os.write(fd, out)
                h.update(out)
                written += len(out)
            if z.eof:
                break
        if not z.eof:
            raise InflateError(f"the stream ends early: it inflates to {written} of the {original} bytes offered")
        if z.unused_data or pos < stream_size:
            raise InflateError("the stream has bytes after its end")
        if written != original:
            raise InflateError(f"the stream inflates to {written} bytes, not the {original} offered")
        if h.digest() != sha256:
            raise InflateError("the SHA-256 of the inflated bytes differs from the offer's")
        os.fsync(fd)
        ok = True
    finally:
        os.close(fd)
        if not ok:
            with contextlib.suppress(FileNotFoundError):
                dest.unlink()
