"""One MCAP file being written: channels made as they are first used, chunks closed on demand.

Rockly's own events go in JSON channels (``json`` messages, a ``jsonschema`` schema); a
robot's topics go in channels of the run's encoder's encodings (``ros1`` with ``ros1msg``
schemas, ``cdr`` with ``ros2msg`` ones) when it can serialise them, else in a JSON channel
named like the topic.

One writer at a time: the file is locked (``flock``, which the system lets go of when the
process ends, even by ``kill -9``) before it is emptied, so a second run recording to it is
refused (``RecordingHeld``) and the first one's file stays whole. A write that fails (a full
disk) is taken back to the last whole record, so what was written before stays readable, and
nothing more is written.
"""
import errno
import fcntl
import json
import os

from mcap.writer import CompressionType, Writer

from rockly_desktop.core.app_texts import app_text

LIBRARY = "rockly"
CHUNK_BYTES = 256 * 1024
_DISK_FULL = (errno.ENOSPC, errno.EDQUOT)


class RecordingHeld(OSError):
    """Another process is recording to this file (it holds the file's lock)."""


def problem_text(error: OSError, language: str) -> str:
    """Why ``error`` keeps a recording from being written, in ``language``."""
    if isinstance(error, RecordingHeld):
        return app_text("recording_held", language)
    if error.errno in _DISK_FULL:
        return app_text("recording_disk_full", language)
    return error.strerror or str(error)


def held(path) -> bool:
    """Whether a run is recording to ``path`` now (it holds the file's lock)."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_CLOEXEC)
    except OSError:
        return False
    try:
        fcntl.flock(fd, fcntl.LOCK_SH | fcntl.LOCK_NB)
    except BlockingIOError:
        return True
    finally:
        os.close(fd)
    return False


def disk_full(error: OSError) -> bool:
    """Whether ``error`` says the disk (or the user's quota) is full."""
    return error.errno in _DISK_FULL


class _LockedFile:
    """The file a Writer writes to: locked, written through with ``os.write`` (nothing buffered),
    a failed write taken back so the file ends where the last whole write ended, and ``failed`` (its
    error) from then on: every later write raises it."""

    def __init__(self, path):
        self.failed = None
        self._fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_CLOEXEC, 0o644)
        try:
            fcntl.flock(self._fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(self._fd)
            raise RecordingHeld(errno.EWOULDBLOCK, "another run is recording to it", str(path)) from None
        os.ftruncate(self._fd, 0)
        self._position = 0

    def write(self, data) -> int:
        if self.failed is not None:
            raise self.failed
        view, start = memoryview(data), self._position
        try:
            while view:
                written = os.write(self._fd, view)
                view = view[written:]
                self._position += written
        except OSError as error:
            self.failed = error
            os.ftruncate(self._fd, start)  # frees what the failed write took: never fails for a full disk
            raise
        return len(data)

    def tell(self) -> int:
        return self._position

    def flush(self):
        """Nothing is buffered."""

    def close(self):
        if self._fd is not None:
            os.close(self._fd)  # lets go of the lock
            self._fd = None


def json_bytes(value) -> bytes:
    """``value`` as compact JSON (what JSON cannot hold, as its ``repr``)."""
    return json.dumps(value, separators=(",", ":"), ensure_ascii=False, default=repr).encode("utf-8")


class McapFile:
    """Writes one recording to ``path`` (opened at once, created or replaced). Raises OSError when it
    cannot be begun (``RecordingHeld``: another run records to it; a file begun is then removed);
    after a failed write (``failed``) nothing more is written and ``close`` only lets go of the file."""

    def __init__(self, path):
        self.path = path
        self._stream = _LockedFile(path)
        self._writer = Writer(self._stream, chunk_size=CHUNK_BYTES, compression=CompressionType.ZSTD)
        try:
            self._writer.start(profile="", library=LIBRARY)
        except OSError:
            self.discard()
            raise
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

    @property
    def failed(self) -> OSError:
        """The error of the write that failed (nothing is written after it), or None."""
        return self._stream.failed

    def close(self):
        """Write the summary (indexes, statistics) and close the file; after a failed write, only close it."""
        try:
            if self.failed is None:
                self._writer.finish()
        finally:
            self._stream.close()

    def discard(self):
        """Remove and close the file (a recording that could not be begun); removed while still locked, so
        that no other run's file of the same name goes."""
        os.unlink(self.path)
        self._stream.close()
