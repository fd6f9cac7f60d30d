"""MCAP at the speed a pose stream needs: a chunk writer that packs Message records itself, and a
reader that walks the Message records inside chunks with `struct.unpack_from`.

Why: the mcap library's Writer.add_message costs ~12 us a message (a dataclass, a dozen small
`write` calls into a BytesIO, statistics updated per message) and its reader ~10 us a record
(ReadDataStream's per-field reads); at ~1,900 messages a second while recording, and 1.1 million
in a 10-minute replay, that alone was a tenth of the recording budget and a third of the replay
one. Here a Message record is one bytes object the caller packs with one Struct (record header and
CDR body together, see `codecs`), appended to the open chunk with its message-index entry;
statistics and chunk times are worked out per chunk from the message indexes.

The library stays in charge of everything that is not per message: every other record is written
and read with its `mcap.records` classes, chunks are decompressed and CRC-checked by its
`get_chunk_data_stream`; only the walk from record to record is ours (`struct`). `ChunkWriter`
mirrors `mcap.writer.Writer` (same defaults: chunks of `chunk_size` bytes, zstd, CRCs, message,
chunk, metadata and attachment indexes, statistics, repeated schemas and channels, summary
offsets), and writes byte for byte the file the library writes for the same calls
(tests/test_hmd_codecs.py checks it), so Foxglove and `ros2 bag` see a library-made file, message
indexes included (they let Foxglove seek).
"""

from __future__ import annotations

import zlib
from collections.abc import Iterator
from struct import Struct
from typing import IO, Any

from ttctl.errors import Fail

MAGIC = b"\x89MCAP0\r\n"
_SCHEMA, _CHANNEL, MESSAGE = 0x03, 0x04, 0x05
MESSAGE_INDEX = 0x07
_MESSAGE_HEAD = "BQHIQQ"  # opcode, record length, channel_id, sequence, log_time, publish_time
MESSAGE_HEAD_SIZE = 31
_MESSAGE_RECORD = Struct("<" + _MESSAGE_HEAD)
_RECORD = Struct("<BQ")


def message_format(body: str) -> str:
    """The struct format (no byte order) of a whole Message record whose data is `body`:
    pack it with (MESSAGE, MESSAGE_HEAD_SIZE - 9 + body size, channel_id, sequence, log_time,
    publish_time, *body's arguments)."""
    return _MESSAGE_HEAD + body


class ChunkWriter:
    """mcap.writer.Writer's file, with a fast path for messages (`add_record`). Schemas and
    channels go into the open chunk (and again into the summary), metadata between chunks."""

    def __init__(self, stream: IO[bytes], chunk_size: int = 1024 * 1024, compression: str = "zstd") -> None:
        from mcap.data_stream import RecordBuilder

        if compression == "zstd":
            import zstandard

            self._compress: Any = zstandard.compress
        elif compression == "lz4":
            import lz4.frame

            self._compress = lz4.frame.compress
        elif compression == "":
            self._compress = None
        else:
            raise ValueError(f"unknown chunk compression {compression!r}")
        self._stream = stream
        self._compression = compression
        self._chunk_size = chunk_size
        self._builder = RecordBuilder()
        self._pos = 0  # bytes written to the stream
        self._parts: list[bytes] = []  # the open chunk's records
        self._size = 0  # their length
        self._order: list[int] = []  # channels with messages in the open chunk, in order of their first
        self._index: dict[int, list[int]] = {}  # channel -> log_time, offset, log_time, offset, ... (open chunk)
        self._schemas: list[Any] = []
        self._channels: list[Any] = []
        self._counts: dict[int, int] = {}  # messages per channel, in order of each one's first
        self._chunk_indexes: list[Any] = []
        self._metadata_indexes: list[Any] = []
        self._start_time: int | None = None
        self._end_time = 0

    # ------------------------------------------------------------------------------ the library's calls

    def start(self, profile: str = "", library: str = "") -> None:
        from mcap.records import Header

        self._write(MAGIC)
        Header(profile, library).write(self._builder)
        self._flush()

    def add_metadata(self, name: str, data: dict[str, str]) -> None:
        from mcap.records import Metadata, MetadataIndex

        self._flush()
        offset = self._pos
        Metadata(name=name, metadata=data).write(self._builder)
        self._metadata_indexes.append(MetadataIndex(offset=offset, length=self._builder.count, name=name))
        self._flush()

    def register_schema(self, name: str, encoding: str, data: bytes) -> int:
        from mcap.records import Schema

        schema = Schema(id=len(self._schemas) + 1, data=data, encoding=encoding, name=name)
        self._schemas.append(schema)
        self._add_to_chunk(schema)
        return int(schema.id)

    def register_channel(self, topic: str, message_encoding: str, schema_id: int,
                         metadata: dict[str, str] | None = None) -> int:
        from mcap.records import Channel

        channel = Channel(id=len(self._channels) + 1, topic=topic, message_encoding=message_encoding,
                          schema_id=schema_id, metadata=dict(metadata or {}))
        self._channels.append(channel)
        self._index[channel.id] = []
        self._add_to_chunk(channel)
        return int(channel.id)

    def add_message(self, channel_id: int, log_time: int, data: bytes, publish_time: int, sequence: int = 0) -> None:
        record = _MESSAGE_RECORD.pack(MESSAGE, 22 + len(data), channel_id, sequence, log_time, publish_time) + data
        self.add_record(channel_id, self._index[channel_id], log_time, record)

    # ------------------------------------------------------------------------------ the fast path

    def index(self, channel_id: int) -> list[int]:
        """The channel's message-index list: pass it to `add_record` (it lives as long as the writer)."""
        return self._index[channel_id]

    def add_record(self, channel_id: int, index: list[int], log_time: int, record: bytes) -> None:
        """A whole Message record of `channel_id` (see `message_format`)."""
        if not index:
            self._order.append(channel_id)
        index.append(log_time)
        index.append(self._size)
        self._parts.append(record)
        self._size += len(record)
        if self._size > self._chunk_size:
            self._finish_chunk()

    def add_three(self, group: tuple[Any, ...], log_time: int, records: bytes) -> None:
        """Three whole Message records of one log time packed together (a pose sample's /tf,
        pose and twist: one Struct.pack). `group` is (channel_id, index, record length) of each,
        flattened. Chunks end where they would with the records added one by one."""
        c1, i1, n1, c2, i2, n2, c3, i3, n3 = group
        size = self._size
        if size + n1 + n2 > self._chunk_size:  # the chunk ends after the first or the second
            self.add_record(c1, i1, log_time, records[:n1])
            self.add_record(c2, i2, log_time, records[n1:n1 + n2])
            self.add_record(c3, i3, log_time, records[n1 + n2:])
            return
        if not i1:
            self._order.append(c1)
        i1 += (log_time, size)
        if not i2:
            self._order.append(c2)
        i2 += (log_time, size + n1)
        if not i3:
            self._order.append(c3)
        i3 += (log_time, size + n1 + n2)
        self._parts.append(records)
        self._size = size = size + n1 + n2 + n3
        if size > self._chunk_size:
            self._finish_chunk()

    # ------------------------------------------------------------------------------ chunks and the end

    def _add_to_chunk(self, record: Any) -> None:
        from mcap.data_stream import RecordBuilder

        b = RecordBuilder()
        record.write(b)
        data = b.end()
        self._parts.append(data)
        self._size += len(data)
        if self._size > self._chunk_size:
            self._finish_chunk()

    def _write(self, data: bytes) -> None:
        self._stream.write(data)
        self._pos += len(data)

    def _flush(self) -> None:
        data = self._builder.end()
        if data:
            self._write(data)

    def _finish_chunk(self) -> None:
        from mcap.records import Chunk, ChunkIndex

        if not self._order:  # schemas and channels only: they wait for a message, as in the library
            return
        data = b"".join(self._parts)
        start = min(min(self._index[c][0::2]) for c in self._order)
        end = max(max(self._index[c][0::2]) for c in self._order)
        self._start_time = start if self._start_time is None else min(start, self._start_time)
        self._end_time = max(end, self._end_time)
        compressed = self._compress(data) if self._compress is not None else data
        chunk = Chunk(compression=self._compression, data=compressed, message_start_time=start, message_end_time=end,
                      uncompressed_crc=zlib.crc32(data), uncompressed_size=len(data))
        self._flush()
        chunk_start = self._pos
        chunk.write(self._builder)
        chunk_length = self._builder.count
        self._flush()
        offsets: dict[int, int] = {}
        indexes: list[bytes] = []
        at = self._pos
        for channel_id in self._order:
            entries = self._index[channel_id]
            n = len(entries)
            offsets[channel_id] = at
            indexes.append(Struct(f"<BQHI{n}Q").pack(MESSAGE_INDEX, 6 + 8 * n, channel_id, 8 * n, *entries))
            at += 15 + 8 * n
            self._counts[channel_id] = self._counts.get(channel_id, 0) + n // 2
            entries.clear()
        index_data = b"".join(indexes)
        self._write(index_data)
        self._chunk_indexes.append(ChunkIndex(
            message_start_time=start, message_end_time=end, chunk_start_offset=chunk_start, chunk_length=chunk_length,
            message_index_offsets=offsets, message_index_length=len(index_data), compression=self._compression,
            compressed_size=len(compressed), uncompressed_size=len(data)))
        self._parts.clear()
        self._order.clear()
        self._size = 0

    def finish(self) -> None:
        """The last chunk, the summary (schemas, channels, statistics, chunk, attachment and
        metadata indexes, summary offsets), the footer and the closing magic."""
        from mcap.data_stream import RecordBuilder
        from mcap.opcode import Opcode
        from mcap.records import DataEnd, Footer, Statistics, SummaryOffset

        self._finish_chunk()
        DataEnd(0).write(self._builder)
        self._flush()
        summary_start = self._pos
        summary = RecordBuilder()
        offsets = []
        stats = Statistics(attachment_count=0, channel_count=len(self._channels), channel_message_counts=self._counts,
                           chunk_count=len(self._chunk_indexes), message_count=sum(self._counts.values()),
                           metadata_count=len(self._metadata_indexes), message_start_time=self._start_time or 0,
                           message_end_time=self._end_time, schema_count=len(self._schemas))
        groups: list[tuple[int, list[Any]]] = [(Opcode.SCHEMA, self._schemas), (Opcode.CHANNEL, self._channels),
                                               (Opcode.STATISTICS, [stats]), (Opcode.CHUNK_INDEX, self._chunk_indexes),
                                               (Opcode.ATTACHMENT_INDEX, []),
                                               (Opcode.METADATA_INDEX, self._metadata_indexes)]
        for opcode, records in groups:
            group_start = summary.count
            for record in records:
                record.write(summary)
            offsets.append(SummaryOffset(group_opcode=opcode, group_start=summary_start + group_start,
                                         group_length=summary.count - group_start))
        summary_offset_start = summary_start + summary.count
        for offset in offsets:
            offset.write(summary)
        data = summary.end()
        crc = zlib.crc32(_FOOTER_HEAD.pack(Opcode.FOOTER, 20, summary_start if data else 0, summary_offset_start),
                         zlib.crc32(data))
        self._write(data)
        Footer(summary_start=summary_start if data else 0, summary_offset_start=summary_offset_start,
               summary_crc=crc).write(self._builder)
        self._flush()
        self._write(MAGIC)


_FOOTER_HEAD = Struct("<BQQQ")


# ---------------------------------------------------------------------------------------------- reading


Message = tuple[int, int, int, int, bytes]  # channel_id, sequence, log_time, publish_time, data


def iter_records(path: str, size: int, truncated: bool, skip: set[int] | None = None,
                 chunks: str = "open") -> Iterator[Any]:
    """The file's records in order, chunks opened: mcap.records objects for everything but
    messages, which come as `Message` tuples (none for the channel ids in `skip`, which the
    caller may add to as Channel records arrive). With `chunks` "record", Chunk records come
    unopened instead; with "bytes", as their decompressed, CRC-checked contents, which the
    caller walks itself (see `walk_error` for what to do when that fails). Message indexes are
    skipped unparsed (the library's reader spends ~6 us a message on them, and a linear replay
    has no use for them). Chunk CRCs are checked, and the data section's when the file has one;
    at a truncated file's cut-off the records simply end (after the last chunk that is complete:
    its CRC checks), anywhere else damage is a Fail."""
    from mcap.records import Chunk

    skip = set() if skip is None else skip
    with open(path, "rb") as f:
        records = _outer_records(f, size)
        inner: Iterator[Any] | None = None
        while True:
            try:
                if inner is not None:  # within a chunk
                    try:
                        item = next(inner)
                    except StopIteration:
                        inner = None
                        continue
                else:
                    item = next(records)
                    if type(item) is Chunk and chunks != "record":
                        if chunks == "bytes":
                            item = chunk_data(item)
                        else:
                            inner = _walk(chunk_data(item), skip)
                            continue
                    if type(item) is tuple and item[0] in skip:
                        continue
            except StopIteration:
                return
            except Exception as e:  # the library raises many kinds (struct, zstd, lz4, CRC, EOF)
                if truncated:
                    return
                raise Fail(f"{path}: damaged MCAP file ({str(e) or type(e).__name__})") from None
            yield item


def _outer_records(f: IO[bytes], limit: int) -> Iterator[Any]:
    """What mcap's StreamReader(validate_crcs=True, emit_chunks=True) gives, the records parsed by
    the library's classes, except Message records (tuples) and message indexes (left out)."""
    from io import BytesIO

    from mcap import records as r
    from mcap.data_stream import ReadDataStream
    from mcap.exceptions import EndOfFile, InvalidMagic, RecordLengthLimitExceeded
    from mcap.stream_reader import CRCValidationError

    readers = {0x09: r.Attachment, 0x0A: r.AttachmentIndex, 0x04: r.Channel, 0x06: r.Chunk, 0x08: r.ChunkIndex,
               0x0F: r.DataEnd, 0x02: r.Footer, 0x01: r.Header, 0x0C: r.Metadata, 0x0D: r.MetadataIndex,
               0x03: r.Schema, 0x0B: r.Statistics, 0x0E: r.SummaryOffset}
    magic = f.read(len(MAGIC))
    if magic != MAGIC:
        raise InvalidMagic(tuple(magic))
    crc = zlib.crc32(magic)  # of the data section, for a DataEnd that carries one
    in_data = True
    while True:
        head = f.read(9)
        if len(head) < 9:
            raise EndOfFile()
        opcode, length = _RECORD.unpack(head)
        if length > limit:
            raise RecordLengthLimitExceeded(opcode, length, limit)
        body = f.read(length)
        if len(body) < length:
            raise EndOfFile()
        before = crc
        if in_data:
            crc = zlib.crc32(body, zlib.crc32(head, crc))
        if opcode == MESSAGE_INDEX:
            if length < 6 or _U32.unpack_from(body, 2)[0] != length - 6:
                raise ValueError(f"message index record of {length} bytes with a bad entry count")
            continue
        if opcode == MESSAGE:
            if length < 22:
                raise EndOfFile()
            ch, seq, log_time, publish_time = _MESSAGE_FIELDS.unpack_from(body)
            yield ch, seq, log_time, publish_time, body[22:]
            continue
        cls = readers.get(opcode)
        if cls is None:
            continue  # unknown record types are skipped, as the library does
        rec = cls.read(ReadDataStream(BytesIO(body)))
        if opcode == 0x0F:
            in_data = False
            if rec.data_section_crc not in (0, before):
                raise CRCValidationError(expected=rec.data_section_crc, actual=before, record=rec)
        yield rec
        if opcode == 0x02:
            if f.read(len(MAGIC)) != MAGIC:
                raise InvalidMagic("at the end")
            return


_U32 = Struct("<I")
_MESSAGE_FIELDS = Struct("<HIQQ")


def chunk_data(chunk: Any) -> bytes:
    """A chunk's records, decompressed and CRC-checked (by the library)."""
    from mcap.stream_reader import get_chunk_data_stream

    stream, n = get_chunk_data_stream(chunk, validate_crc=True)
    data: bytes = stream.read(n)
    if len(data) != n:
        raise ValueError("chunk shorter than its size")
    return data


def walk_error(path: str, truncated: bool, e: Exception) -> Fail | None:
    """What a failure to walk a chunk's records means: the end of a truncated file (None), or a
    damaged one."""
    return None if truncated else Fail(f"{path}: damaged MCAP file ({str(e) or type(e).__name__})")


def inner_record(opcode: int, body: bytes) -> Any:
    """A Schema or Channel record found in a chunk, parsed by the library; None for the rest."""
    from io import BytesIO

    from mcap.data_stream import ReadDataStream
    from mcap.records import Channel, Schema

    if opcode == _CHANNEL:
        return Channel.read(ReadDataStream(BytesIO(body)))
    if opcode == _SCHEMA:
        return Schema.read(ReadDataStream(BytesIO(body)))
    return None


def _walk(data: bytes, skip: set[int]) -> Iterator[Any]:
    """The records of one chunk: Message tuples, and Schema and Channel records."""
    pos, n = 0, len(data)
    unpack_message = _MESSAGE_RECORD.unpack_from
    while pos < n:
        if data[pos] == MESSAGE and pos + MESSAGE_HEAD_SIZE <= n:
            _, length, ch, seq, log_time, publish_time = unpack_message(data, pos)
            end = pos + 9 + length
            if length < 22 or end > n:
                raise ValueError(f"message record of {length} bytes at {pos} of a {n}-byte chunk")
            if ch not in skip:
                yield ch, seq, log_time, publish_time, data[pos + MESSAGE_HEAD_SIZE:end]
            pos = end
            continue
        opcode, length = _RECORD.unpack_from(data, pos)
        end = pos + 9 + length
        if end > n:
            raise ValueError(f"record of {length} bytes at {pos} of a {n}-byte chunk")
        rec = inner_record(opcode, data[pos + 9:end])
        if rec is not None:
            yield rec
        pos = end


__all__ = ["MAGIC", "MESSAGE", "MESSAGE_HEAD_SIZE", "ChunkWriter", "Message", "chunk_data", "inner_record",
           "iter_records", "message_format", "walk_error"]
