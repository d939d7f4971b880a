"""One MCAP file being written: channels made as they are first used, chunks closed on demand.

Rockly's own events go in JSON channels (``json`` messages, a ``jsonschema`` schema); a
robot's topics go in channels of the run's encoder's encodings (``ros1`` with ``ros1msg``
schemas, ``cdr`` with ``ros2msg`` ones) when it can serialise them, else in a JSON channel
named like the topic.
"""
import json

from mcap.writer import CompressionType, Writer

LIBRARY = "rockly"
CHUNK_BYTES = 256 * 1024


def json_bytes(value) -> bytes:
    """``value`` as compact JSON (what JSON cannot hold, as its ``repr``)."""
    return json.dumps(value, separators=(",", ":"), ensure_ascii=False, default=repr).encode("utf-8")


class McapFile:
    """Writes one recording to ``path`` (opened at once, created or replaced)."""

    def __init__(self, path):
        self._stream = open(path, "wb")
        self._writer = Writer(self._stream, chunk_size=CHUNK_BYTES, compression=CompressionType.ZSTD)
        self._writer.start(profile="", library=LIBRARY)
        self._schemas = {}
        self._channels = {}
        self.counts = {}

    def _schema(self, name: str, encoding: str, data: bytes) -> int:
        key = (name, encoding, data)
        if key not in self._schemas:
            self._schemas[key] = self._writer.register_schema(name=name, encoding=encoding, data=data)
        return self._schemas[key]

    def _channel(self, topic: str, message_encoding: str, schema_id: int) -> int:
        key = (topic, message_encoding, schema_id)
        if key not in self._channels:
            self._channels[key] = self._writer.register_channel(topic=topic, message_encoding=message_encoding,
                                                                schema_id=schema_id)
        return self._channels[key]

    def _add(self, channel_id: int, topic: str, log_ns: int, data: bytes):
        self._writer.add_message(channel_id, log_time=log_ns, data=data, publish_time=log_ns)
        self.counts[topic] = self.counts.get(topic, 0) + 1

    def write_json(self, topic: str, schema_name: str, schema: dict, log_ns: int, value):
        """A message of ``value`` as JSON on ``topic``, whose JSON ``schema`` is named ``schema_name``."""
        schema_id = self._schema(schema_name, "jsonschema", json_bytes(schema))
        self._add(self._channel(topic, "json", schema_id), topic, log_ns, json_bytes(value))

    def write_ros(self, topic: str, encodings: tuple, schema_name: str, definition: str, log_ns: int, data: bytes):
        """A serialised ROS message whose ``encodings`` are (message encoding, schema encoding): ('ros1',
        'ros1msg') or ('cdr', 'ros2msg'); its schema is named ``schema_name``, with the full ``definition``
        text (as rosbag and rosbag2 keep it)."""
        message_encoding, schema_encoding = encodings
        schema_id = self._schema(schema_name, schema_encoding, definition.encode("utf-8"))
        self._add(self._channel(topic, message_encoding, schema_id), topic, log_ns, data)

    def attach(self, log_ns: int, name: str, media_type: str, data: bytes):
        """Store a file (the program) in the recording."""
        self._writer.add_attachment(create_time=log_ns, log_time=log_ns, name=name, media_type=media_type, data=data)

    def metadata(self, name: str, values: dict):
        """Store a named set of texts."""
        self._writer.add_metadata(name, {key: str(value) for key, value in values.items()})

    def flush(self):
        """Close the open chunk and push it to disk, so a crash after this loses nothing written before."""
        self._writer.flush()

    def close(self):
        """Write the summary (indexes, statistics) and close the file."""
        try:
            self._writer.finish()
        finally:
            self._stream.close()
