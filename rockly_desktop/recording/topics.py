"""The robot's recorded topics, decoded as the panels read them: messages as dicts, by time.

ROS 1 topics are decoded with mcap-ros1-support, ROS 2 ones (``cdr``) with mcap-ros2-support
(imported when a recording has some), from the schema the file carries (no ROS installation
needed), JSON ones as they are; a topic is decoded when it is first asked for.
``at(seconds)`` is a read-only stand-in for the robot's state store at a moment of the run
(``latest(topic)``), what the state panels read during a replay.
"""
import bisect
import json

from mcap_ros1.decoder import DecoderFactory

from rockly_desktop.core.state_store import field_value
from rockly_desktop.recording.reading import Recording


def message_dict(message):
    """A decoded ROS message (fields in ``__slots__``) as nested dicts and lists, as the state store holds them."""
    if isinstance(message, (list, tuple)):
        return [message_dict(item) for item in message]
    if isinstance(message, (bytes, bytearray)):
        return list(message)
    slots = getattr(message, "__slots__", None)
    if slots:
        return {name: message_dict(getattr(message, name)) for name in slots}
    return message


class RecordedTopics:
    """The robot topics of ``recording``: ``names``, ``times(topic)``, ``messages(topic)``, ``latest_at``."""

    def __init__(self, recording: Recording):
        self.recording = recording
        self._decoded = {}
        self._ros1 = DecoderFactory()
        self._ros2 = None

    @property
    def names(self) -> list:
        """The recorded robot topics, sorted."""
        return sorted(self.recording.topic_times)

    def times(self, topic: str) -> list:
        """The seconds (since the recording began) of ``topic``'s messages."""
        return self.recording.topic_times.get(topic, [])

    def messages(self, topic: str) -> list:
        """``topic``'s messages as dicts, in time order (None for one that cannot be decoded)."""
        if topic not in self._decoded:
            self._decoded[topic] = [self._decode(topic, data) for data in self.recording.topic_data.get(topic, [])]
        return self._decoded[topic]

    def _decode(self, topic: str, data: bytes):
        encoding = self.recording.channels.get(topic, ("",))[0]
        try:
            if encoding == "json":
                return json.loads(data)
            decoder = self._factory(encoding).decoder_for(encoding, self.recording.topic_schemas.get(topic))
            return message_dict(decoder(data)) if decoder else None
        except Exception:  # a message the schema does not fit: that one is left out
            return None

    def _factory(self, encoding: str):
        if encoding != "cdr":
            return self._ros1
        if self._ros2 is None:
            from mcap_ros2.decoder import DecoderFactory as Ros2DecoderFactory

            self._ros2 = Ros2DecoderFactory()
        return self._ros2

    def latest_at(self, topic: str, seconds: float):
        """The newest message of ``topic`` at ``seconds``, or None."""
        index = bisect.bisect_right(self.times(topic), seconds)
        return self.messages(topic)[index - 1] if index else None

    def series(self, topic: str, path: str) -> tuple:
        """(times, numbers) of a numeric field over the whole recording."""
        times, numbers = [], []
        for stamp, message in zip(self.times(topic), self.messages(topic)):
            try:
                number = field_value(message, path) if message is not None else None
            except KeyError:
                continue
            if isinstance(number, (int, float)) and not isinstance(number, bool):
                times.append(stamp)
                numbers.append(float(number))
        return times, numbers

    def at(self, seconds: float) -> "TopicsAt":
        """The topics as a state store held them ``seconds`` into the run."""
        return TopicsAt(self, seconds)


class TopicsAt:
    """A read-only state store at one moment, as far as the state panels read one: ``latest(topic)``."""

    def __init__(self, topics: RecordedTopics, seconds: float):
        self.topics = topics
        self.seconds = seconds

    def latest(self, topic: str):
        """The newest message on ``topic`` at this moment, or None."""
        return self.topics.latest_at(topic, self.seconds)
