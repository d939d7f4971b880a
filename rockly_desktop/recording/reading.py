"""Reading a recording back: its metadata, program, Rockly's events and the robot's topics.

The file is read from the start, record by record, so a recording cut short by a crash
(no summary, a half-written last chunk) reads up to its last complete chunk and says it
was cut (``complete`` is False). A file that is no MCAP, or no recording of Rockly's,
raises ``RecordingUnreadable`` with a message saying which.
"""
import json
from dataclasses import dataclass, field
from itertools import pairwise

from mcap.exceptions import McapError
from mcap.records import Attachment, Channel, Footer, Message, Metadata, Schema
from mcap.stream_reader import StreamReader

from rockly_desktop.core.errors import RocklyError
from rockly_desktop.recording import channels


class RecordingUnreadable(RocklyError):
    """The file is not a recording Rockly can read (the message says why)."""


@dataclass(frozen=True)
class Entry:
    """One of Rockly's events: ``time`` in seconds since the recording began, its ``channel`` and ``data``."""

    time: float
    channel: str
    data: dict


@dataclass
class Recording:
    """A recording as read: metadata, the ``.rockly`` program (bytes or None), Rockly's events in
    time order, message counts per topic, the robot topics' message times (``topic_times``,
    seconds), their messages as stored (``topic_data``, bytes in the same order), each robot topic's
    ``Schema`` record (``topic_schemas``), channels as ``{topic: (message encoding, schema name,
    schema encoding)}``, the first event's time (ns since the epoch) and whether the file was finished."""

    path: str
    metadata: dict = field(default_factory=dict)
    program: bytes = None
    entries: list = field(default_factory=list)
    counts: dict = field(default_factory=dict)
    topic_times: dict = field(default_factory=dict)
    topic_data: dict = field(default_factory=dict)
    topic_schemas: dict = field(default_factory=dict)
    channels: dict = field(default_factory=dict)
    start_ns: int = 0
    complete: bool = False

    @property
    def duration(self) -> float:
        """Seconds from the first to the last of Rockly's events."""
        return self.entries[-1].time if self.entries else 0.0

    def on(self, channel: str) -> list:
        """The entries of one of Rockly's channels, in time order."""
        return [entry for entry in self.entries if entry.channel == channel]


def read_recording(path) -> Recording:
    """Read ``path``; raises RecordingUnreadable for a file that is not a Rockly recording."""
    recording = Recording(str(path))
    schemas, topic_of, rockly, robot = {}, {}, [], {}
    try:
        stream = open(path, "rb")
    except OSError as error:
        raise RecordingUnreadable(f"{path} cannot be read: {error.strerror}") from None
    with stream:
        try:
            for record in StreamReader(stream, record_size_limit=1 << 30).records:
                if isinstance(record, Schema):
                    schemas[record.id] = record
                elif isinstance(record, Channel):
                    schema = schemas.get(record.schema_id)
                    topic_of[record.id] = record.topic
                    if schema is not None and not record.topic.startswith("/rockly/"):
                        recording.topic_schemas[record.topic] = schema
                    recording.channels[record.topic] = (record.message_encoding, schema.name if schema else "",
                                                        schema.encoding if schema else "")
                elif isinstance(record, Message):
                    topic = topic_of.get(record.channel_id, "?")
                    recording.counts[topic] = recording.counts.get(topic, 0) + 1
                    if topic.startswith("/rockly/"):
                        rockly.append((record.log_time, topic, record.data))
                    else:
                        robot.setdefault(topic, []).append((record.log_time, record.data))
                elif isinstance(record, Metadata) and record.name == channels.METADATA:
                    recording.metadata = dict(record.metadata)
                elif isinstance(record, Attachment) and record.name == channels.PROGRAM_ATTACHMENT:
                    recording.program = bytes(record.data)
                elif isinstance(record, Footer):
                    recording.complete = True
        except McapError as error:
            if not recording.metadata:  # not even the start of a recording
                raise RecordingUnreadable(f"{path} is not an MCAP recording ({error})") from None
        except Exception as error:  # a record cut short or garbled: the file ends there
            if not recording.metadata:
                raise RecordingUnreadable(f"{path} is not an MCAP recording ({type(error).__name__})") from None
    if not recording.metadata:
        raise RecordingUnreadable(f"{path} is an MCAP file, but no recording of a Rockly run")
    if any(later[0] < earlier[0] for earlier, later in pairwise(rockly)):  # the writer writes in time order, so
        rockly.sort(key=lambda item: item[0])  # this is rare: sorting 2 million in C held the GIL 0.07 s
    recording.start_ns = rockly[0][0] if rockly else 0
    rockly.reverse()  # taken from the end, each record is freed as its entry is made (all at once, a million
    while rockly:     # of them held the GIL for a tenth of a second)
        stamp, topic, data = rockly.pop()
        recording.entries.append(Entry((stamp - recording.start_ns) / 1e9, topic, json.loads(data)))
    for topic, messages in robot.items():
        messages.sort(key=lambda item: item[0])
        recording.topic_times[topic] = [(stamp - recording.start_ns) / 1e9 for stamp, _data in messages]
        recording.topic_data[topic] = [data for _stamp, data in messages]
    return recording
