"""An MCAP file's records read within bounds: a hostile or broken file costs bounded memory and time.

``read_records(stream, report, bounds)`` yields the Schema, Channel, Message, Metadata, Attachment, DataEnd
and Footer records in file order (a chunk's records in its place). What it leaves out it counts
in a ``ReadReport``: a record or chunk bigger than its bound is skipped unread (a seek, never a
read of gigabytes), one that is garbled is skipped, and reading stops where the file stops making
sense (cut short mid-record, or zeros where a record should begin: a sparse or zero-filled tail)
or where the bounds on everything read (bytes decompressed, records) are reached.
"""
import io
import struct
import zlib
from dataclasses import dataclass

import lz4.frame
import zstandard
from mcap.data_stream import ReadDataStream
from mcap.records import Attachment, Channel, Chunk, DataEnd, Footer, Message, Metadata, Schema

MAGIC = b"\x89MCAP0\r\n"
_HEADER = struct.Struct("<BQ")
_MESSAGE_HEAD = struct.Struct("<HIQQ")  # channel id, sequence, log time, publish time; then the data
_READERS = {0x02: Footer.read, 0x03: Schema.read, 0x04: Channel.read, 0x09: Attachment.read,
            0x0C: Metadata.read, 0x0F: DataEnd.read}
_MESSAGE, _CHUNK = 0x05, 0x06
MiB = 1 << 20


@dataclass(frozen=True)
class Bounds:
    """How much one file may cost: one record as stored and one chunk decompressed (bigger ones are
    skipped), all chunks decompressed and all records together (reading stops there)."""

    record_bytes: int = 64 * MiB
    chunk_bytes: int = 64 * MiB
    total_bytes: int = 1024 * MiB
    records: int = 2_000_000


@dataclass
class ReadReport:
    """What reading left out: ``too_big`` records or chunks skipped for their size, ``damaged`` ones
    that could not be read, and ``stopped`` early ('' read to the end, 'too_big' at the bounds); the
    ``records`` and bytes ``decompressed`` so far."""

    too_big: int = 0
    damaged: int = 0
    stopped: str = ""
    records: int = 0
    decompressed: int = 0


class NotMcap(Exception):
    """The file does not begin with MCAP's magic bytes."""


class _Stop(Exception):
    """Reading ends here."""


def read_records(stream, report: ReadReport, bounds: Bounds):
    """The records of the MCAP file open in ``stream`` (binary, seekable), counting in ``report``
    what is left out; raises NotMcap when it is no MCAP file."""
    if stream.read(len(MAGIC)) != MAGIC:
        raise NotMcap()
    size = stream.seek(0, io.SEEK_END)
    stream.seek(len(MAGIC))
    try:
        while True:
            head = stream.read(_HEADER.size)
            if len(head) < _HEADER.size:
                return  # the end, or cut short mid-record
            opcode, length = _HEADER.unpack(head)
            if opcode == 0 or length > size - stream.tell():
                return  # zeros or a record running past the end: the file is cut or garbled from here
            _count(report, bounds)
            if length > bounds.record_bytes:
                report.too_big += 1
                stream.seek(length, io.SEEK_CUR)
                continue
            body = stream.read(length)
            if opcode == _CHUNK:
                yield from _chunk_records(body, report, bounds)
            else:
                record = _parse(opcode, body, report)
                if record is not None:
                    yield record
                if isinstance(record, Footer):
                    return
    except _Stop:
        report.stopped = "too_big"


def _count(report: ReadReport, bounds: Bounds):
    report.records += 1
    if report.records > bounds.records:
        raise _Stop()


def _parse(opcode: int, body: bytes, report: ReadReport):
    """The record of ``opcode`` in ``body``; None for one Rockly does not read, or a garbled one (counted)."""
    if opcode == _MESSAGE:  # most records: read straight from the bytes
        if len(body) < _MESSAGE_HEAD.size:
            report.damaged += 1
            return None
        channel_id, sequence, log_time, publish_time = _MESSAGE_HEAD.unpack_from(body)
        return Message(channel_id=channel_id, sequence=sequence, log_time=log_time, publish_time=publish_time,
                       data=bytes(body[_MESSAGE_HEAD.size:]))
    if opcode not in _READERS:
        return None
    try:
        return _READERS[opcode](ReadDataStream(io.BytesIO(body)))
    except Exception:  # a record cut or garbled inside: left out
        report.damaged += 1
        return None


def _chunk_records(body: bytes, report: ReadReport, bounds: Bounds):
    try:
        chunk = Chunk.read(ReadDataStream(io.BytesIO(body)))
    except Exception:
        report.damaged += 1
        return
    if chunk.uncompressed_size > bounds.chunk_bytes:
        report.too_big += 1
        return
    if report.decompressed + chunk.uncompressed_size > bounds.total_bytes:
        raise _Stop()
    data = _decompressed(chunk)
    if data is None or (chunk.uncompressed_crc and zlib.crc32(data) != chunk.uncompressed_crc):
        report.damaged += 1
        return
    report.decompressed += len(data)
    view, offset, end = memoryview(data), 0, len(data)  # records are read from it without copies
    while offset + _HEADER.size <= end:
        opcode, length = _HEADER.unpack_from(data, offset)
        offset += _HEADER.size
        if opcode == 0 or length > end - offset:
            report.damaged += 1
            return
        _count(report, bounds)
        record = _parse(opcode, view[offset:offset + length], report)
        offset += length
        if record is not None:
            yield record


def _decompressed(chunk: Chunk):
    """The chunk's records, decompressed to at most its stated size (a chunk that says it is small
    but inflates further is damaged); None when they cannot be."""
    limit = chunk.uncompressed_size
    try:
        if chunk.compression == "":
            data = chunk.data
        elif chunk.compression == "zstd":
            data = zstandard.ZstdDecompressor().stream_reader(io.BytesIO(chunk.data)).read(limit + 1)
        elif chunk.compression == "lz4":
            data = lz4.frame.LZ4FrameDecompressor().decompress(chunk.data, max_length=limit + 1)
        else:
            return None
    except Exception:  # not what its compression says
        return None
    return data if len(data) == limit else None
