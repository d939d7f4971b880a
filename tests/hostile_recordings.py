"""Recordings built to hurt a reader: huge zero messages in tiny compressed chunks, a sparse file,
events that are no JSON. Each starts as a real Rockly recording (metadata, a run's events)."""
import json
import os
import struct

import zstandard
from mcap.writer import CompressionType, Writer

from rockly_desktop.recording import channels

MiB = 1 << 20
SECOND = 1_000_000_000


def _event_channel(writer, topic):
    name, schema = channels.SCHEMAS[topic]
    schema_id = writer.register_schema(name=name, encoding="jsonschema", data=json.dumps(schema).encode())
    return writer.register_channel(topic=topic, message_encoding="json", schema_id=schema_id)


class RecordingBuilder:
    """A Rockly recording written with the mcap library: ``event`` adds one of Rockly's events (as
    JSON, or as the raw bytes given), ``raw`` puts bytes between records; ``finish`` ends the file."""

    def __init__(self, path, compression=CompressionType.ZSTD):
        self.stream = open(path, "wb")
        self.writer = Writer(self.stream, compression=compression)
        self.writer.start(profile="", library="rockly")
        self.writer.add_metadata(channels.METADATA, {"program": "tour.rockly", "profile": "hobbit", "robot": "sim",
                                                     "started": "2026-05-01T09:00:00+00:00"})
        self._channels = {}

    def event(self, seconds: float, topic: str, value):
        if topic not in self._channels:
            self._channels[topic] = _event_channel(self.writer, topic)
        data = value if isinstance(value, bytes) else json.dumps(value).encode()
        stamp = int(seconds * SECOND) + SECOND
        self.writer.add_message(self._channels[topic], log_time=stamp, data=data, publish_time=stamp)

    def raw(self, data: bytes):
        self.writer.flush()  # the open chunk first: what comes after lies between whole records
        self.stream.write(data)

    def finish(self):
        self.writer.finish()
        self.stream.close()


def zero_message_chunk(channel_id: int, size: int, stated_size: int = None) -> bytes:
    """A zstd chunk holding one message of ``size`` zero bytes (a few KB per 100 MB), stating its
    decompressed size as ``stated_size`` (default: the truth)."""
    compressor = zstandard.ZstdCompressor(level=1).compressobj()
    head = struct.pack("<BQHIQQ", 0x05, 22 + size, channel_id, 0, SECOND, SECOND)
    parts, zeros, left = [compressor.compress(head)], bytes(MiB), size
    while left:
        parts.append(compressor.compress(zeros[:min(left, MiB)]))
        left -= min(left, MiB)
    parts.append(compressor.flush())
    compressed = b"".join(parts)
    stated = len(head) + size if stated_size is None else stated_size
    compression = b"zstd"
    body = (struct.pack("<QQQI", SECOND, SECOND, stated, 0) + struct.pack("<I", len(compression)) + compression
            + struct.pack("<Q", len(compressed)) + compressed)
    return struct.pack("<BQ", 0x06, len(body)) + body


def with_zero_chunks(path, count: int, size: int, stated_size: int = None):
    """A finished Rockly recording with ``count`` chunks of one ``size``-byte zero message each on a
    robot topic, between a run's start and end."""
    builder = RecordingBuilder(path)
    builder.event(0.0, channels.RUN, {"event": "start"})
    schema_id = builder.writer.register_schema(name="std_msgs/String", encoding="ros1msg", data=b"string data")
    channel_id = builder.writer.register_channel(topic="/camera", message_encoding="ros1", schema_id=schema_id)
    builder.event(0.5, channels.BLOCKS, {"block": "look", "type": "hobbit_head"})
    chunk = zero_message_chunk(channel_id, size, stated_size)
    for _ in range(count):
        builder.raw(chunk)
    builder.event(1.0, channels.RUN, {"event": "end", "outcome": "finished"})
    builder.finish()


def sparse(path, size: int):
    """A Rockly recording's first records, then zeros (a hole: no disk used) up to ``size`` bytes."""
    builder = RecordingBuilder(path)
    builder.event(0.0, channels.RUN, {"event": "start"})
    builder.writer.flush()
    builder.stream.close()
    os.truncate(path, size)
