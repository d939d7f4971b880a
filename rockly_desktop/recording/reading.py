"""Reading a recording back: its metadata, program, Rockly's events and the robot's topics.

The file is read from the start, record by record, so a recording cut short by a crash or a
full disk (no summary, a half-written last chunk) reads up to its last complete chunk and says
it was cut (``complete`` is False). Reading is bounded (``mcap_records``): what is too big or
damaged is left out and counted, an event of Rockly's that is not what its channel holds
(bad JSON, wrong fields) too, and the robot's topics keep at most ``ROBOT_BYTES``; ``notes()``
says what was left out. A file that is no MCAP, or no recording of Rockly's, raises
``RecordingUnreadable`` with a message saying which.
"""
import json
from dataclasses import dataclass, field
from itertools import islice

from mcap.records import Attachment, Channel, DataEnd, Footer, Message, Metadata, Schema

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import RocklyError
from rockly_desktop.recording import channels
from rockly_desktop.recording.mcap_records import Bounds, NotMcap, ReadReport, read_records

ROBOT_BYTES = 128 << 20   # the robot's messages kept, in all (beyond: left out, said)
EVENT_BYTES = 1 << 20     # one event of Rockly's (beyond: damaged)
BOUNDS = Bounds()


class RecordingUnreadable(RocklyError):
    """The file is not a recording Rockly can read (the message says why, in any language)."""

    def __init__(self, key: str, **values):
        self.message = app_local_text(key, **values)
        super().__init__(str(self.message))

    def in_language(self, language: str) -> str:
        """The message in ``language``."""
        return self.message.in_language(language)


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
    schema encoding)}``, the first event's time (ns since the epoch) and whether the file was finished;
    what reading left out: ``too_big`` and ``damaged`` parts, ``read_in_part`` (it stopped at its
    bounds) and ``robot_until`` (the robot's topics are kept up to these seconds; None: all)."""

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
    too_big: int = 0
    damaged: int = 0
    read_in_part: bool = False
    robot_until: float = None

    @property
    def duration(self) -> float:
        """Seconds from the first to the last of Rockly's events."""
        return self.entries[-1].time if self.entries else 0.0

    def on(self, channel: str) -> list:
        """The entries of one of Rockly's channels, in time order."""
        return [entry for entry in self.entries if entry.channel == channel]

    def notes(self) -> list:
        """What reading left out, as texts to put into a language (empty: nothing)."""
        notes = []
        if self.read_in_part:
            notes.append(app_local_text("recording_read_in_part", seconds=round(self.duration, 1)))
        if self.too_big:
            notes.append(app_local_text("recording_left_out_too_big", count=self.too_big))
        if self.damaged:
            notes.append(app_local_text("recording_left_out_damaged", count=self.damaged))
        if self.robot_until is not None:
            notes.append(app_local_text("recording_robot_topics_cut", seconds=round(self.robot_until, 1)))
        return notes


def read_recording(path, bounds: Bounds = BOUNDS) -> Recording:
    """Read ``path`` within ``bounds``; raises RecordingUnreadable for a file that is not a Rockly recording."""
    recording = Recording(str(path))
    report = ReadReport()
    try:
        stream = open(path, "rb")
    except OSError as error:
        raise RecordingUnreadable("recording_cannot_read", path=path, reason=error.strerror or error) from None
    with stream:
        try:
            rockly, robot = _read(stream, recording, report, bounds)
        except NotMcap:
            raise RecordingUnreadable("recording_not_mcap", path=path) from None
        except OSError as error:
            raise RecordingUnreadable("recording_cannot_read", path=path, reason=error.strerror or error) from None
    if not recording.metadata:
        raise RecordingUnreadable("recording_not_rockly", path=path)
    recording.too_big, recording.read_in_part = report.too_big, report.stopped == "too_big"
    recording.damaged += report.damaged
    # the writer writes in time order, so this is rare: sorting 2 million in C held the GIL 0.07 s
    if any(later[0] < earlier[0] for earlier, later in zip(rockly, islice(rockly, 1, None))):
        rockly.sort(key=lambda item: item[0])
    recording.start_ns = rockly[0][0] if rockly else 0
    rockly.reverse()  # taken from the end, each record is freed as its entry is made (all at once, a million
    while rockly:     # of them held the GIL for a tenth of a second)
        stamp, topic, data = rockly.pop()
        recording.entries.append(Entry((stamp - recording.start_ns) / 1e9, topic, data))
    if recording.robot_until is not None:
        recording.robot_until = (recording.robot_until - recording.start_ns) / 1e9
    for topic, messages in robot.items():
        messages.sort(key=lambda item: item[0])
        recording.topic_times[topic] = [(stamp - recording.start_ns) / 1e9 for stamp, _data in messages]
        recording.topic_data[topic] = [data for _stamp, data in messages]
    return recording


def _read(stream, recording: Recording, report: ReadReport, bounds: Bounds) -> tuple:
    """Rockly's events ``[(log ns, channel, data)]`` and the robot's messages ``{topic: [(log ns, bytes)]}``;
    fills in the rest of ``recording``."""
    schemas, topic_of, rockly, robot, robot_bytes = {}, {}, [], {}, 0
    for record in read_records(stream, report, bounds):
        if isinstance(record, Message):
            topic = topic_of.get(record.channel_id, "?")
            recording.counts[topic] = recording.counts.get(topic, 0) + 1
            if topic.startswith("/rockly/"):
                if topic not in channels.SCHEMAS:  # a later Rockly's channel
                    continue
                data = _event(topic, record.data)
                if data is None:
                    recording.damaged += 1
                else:
                    rockly.append((record.log_time, topic, data))
            elif robot_bytes + len(record.data) <= ROBOT_BYTES:
                robot_bytes += len(record.data)
                robot.setdefault(topic, []).append((record.log_time, record.data))
            elif recording.robot_until is None or record.log_time < recording.robot_until:
                recording.robot_until = record.log_time
        elif isinstance(record, Schema):
            schemas[record.id] = record
        elif isinstance(record, Channel):
            schema = schemas.get(record.schema_id)
            topic_of[record.id] = record.topic
            if schema is not None and not record.topic.startswith("/rockly/"):
                recording.topic_schemas[record.topic] = schema
            recording.channels[record.topic] = (record.message_encoding, schema.name if schema else "",
                                                schema.encoding if schema else "")
        elif isinstance(record, Metadata) and record.name == channels.METADATA:
            recording.metadata = dict(record.metadata)
        elif isinstance(record, Attachment) and record.name == channels.PROGRAM_ATTACHMENT:
            recording.program = bytes(record.data)
        elif isinstance(record, (DataEnd, Footer)):  # everything the run wrote is there
            recording.complete = True
    return rockly, robot


def _event(topic: str, data: bytes):
    """One of Rockly's events as the channel ``topic`` holds them, or None when it is not (left out)."""
    if len(data) > EVENT_BYTES:
        return None
    try:
        value = json.loads(data)
    except (ValueError, RecursionError):
        return None
    return value if channels.fits(topic, value) else None
