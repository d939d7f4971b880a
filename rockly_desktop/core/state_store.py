"""The robot's state as the panels see it: latest message and a bounded history per topic.

Backend threads (rospy callbacks, the simulator's tick) call ``record``; widgets read on
a timer. Memory is bounded whatever the message rate and size: each topic keeps at most
``history`` messages and the arrival times of the last ``rate_window`` seconds, and its
history at most ``topic_bytes`` (16 MB) of messages, less when the topics together would
hold more than ``total_bytes`` (128 MB; each then gets an equal share). Bytes are
``message_bytes``'s estimate. A topic always keeps its newest message, however large;
the oldest go first, and ``TopicInfo.cut`` says when the byte budget cut a topic's history
(a camera's 1 MB images: 16 of them).
"""
import array
import re
import threading
import time
from collections import deque
from dataclasses import dataclass

from rockly_desktop.core.message_size import message_bytes

TOPIC_BYTES = 16 * 2 ** 20
TOTAL_BYTES = 128 * 2 ** 20
_PATH_PART = re.compile(r"([A-Za-z_]\w*)(?:\[(\d+)\])?")
_INDEXABLE = (list, tuple, array.array, bytes, bytearray)


@dataclass(frozen=True)
class TopicInfo:
    """What the store knows of one topic."""

    topic: str
    msg_type: str
    count: int
    rate: float
    age: float
    kept: int = 0
    """Messages in the topic's history now."""
    cut: bool = False
    """Whether the byte budget holds the history below ``StateStore``'s ``history`` count (older messages let go)."""


class _Topic:
    def __init__(self, msg_type):
        self.msg_type = msg_type
        self.count = 0
        self.last = None
        self.shown = (None, None)  # (the newest message as recorded, decoded) once read
        self.history = deque()  # (stamp, message, bytes)
        self.bytes = 0
        self.cut = False
        self.arrivals = deque()

    def trim(self, budget: int):
        """Let the oldest messages go until the history holds ``budget`` bytes (the newest stays)."""
        history = self.history
        while self.bytes > budget and len(history) > 1:
            self.bytes -= history.popleft()[2]
            self.cut = True


def field_value(message, path: str):
    """The value at ``path`` (``pose.pose.position.x``, ``ranges[3]``) in a message dict, or in a
    message object with those attributes (a ROS message not yet decoded); KeyError if absent."""
    value = message
    for part in path.split("."):
        match = _PATH_PART.fullmatch(part)
        if match is None:
            raise KeyError(path)
        if isinstance(value, dict):
            if match.group(1) not in value:
                raise KeyError(path)
            value = value[match.group(1)]
        elif match.group(1) in getattr(value, "__slots__", ()):
            value = getattr(value, match.group(1))
        else:
            raise KeyError(path)
        if match.group(2) is not None:
            index = int(match.group(2))
            if not isinstance(value, _INDEXABLE) or index >= len(value):
                raise KeyError(path)
            value = value[index]
    return value


class StateStore:
    """Thread-safe latest messages, history and rates per topic."""

    def __init__(self, history: int = 2000, rate_window: float = 2.0, clock=time.monotonic, decode=None,
                 topic_bytes: int = TOPIC_BYTES, total_bytes: int = TOTAL_BYTES):
        """``decode(message) -> dict`` turns recorded messages into the dicts the panels read, when they are
        read (a ROS feed records messages undecoded, so a 1 kHz topic costs little until someone looks);
        ``topic_bytes`` and ``total_bytes`` bound the histories (see the module's text)."""
        self._lock = threading.Lock()
        self._decode = decode
        self._topics = {}
        self._history = history
        self._topic_bytes = topic_bytes
        self._total_bytes = total_bytes
        self._bytes = 0
        self._rate_window = rate_window
        self._clock = clock
        self._listeners = ()
        self.version = 0

    def add_listener(self, listener):
        """Also hand every message to ``listener(topic, msg_type, message)``, in the thread that records it."""
        with self._lock:
            self._listeners = self._listeners + (listener,)

    def remove_listener(self, listener):
        """Stop handing messages to ``listener``."""
        with self._lock:
            self._listeners = tuple(item for item in self._listeners if item != listener)

    def now(self) -> float:
        """The store's clock (the time its stamps are in)."""
        return self._clock()

    def record(self, topic: str, msg_type: str, message):
        """Take one message (any thread), and hand it to the listeners."""
        now = self._clock()
        size = message_bytes(message)
        with self._lock:
            entry = self._topics.get(topic)
            if entry is None:
                entry = self._topics[topic] = _Topic(msg_type)
            entry.count += 1
            entry.last = (now, message)
            self._bytes -= entry.bytes
            if len(entry.history) >= self._history:
                entry.bytes -= entry.history.popleft()[2]
                entry.cut = False  # the count bounds it, not the bytes
            entry.history.append((now, message, size))
            entry.bytes += size
            entry.trim(self._share())
            self._bytes += entry.bytes
            if self._bytes > self._total_bytes:
                self._trim_all()
            entry.arrivals.append(now)
            while entry.arrivals and entry.arrivals[0] < now - self._rate_window:
                entry.arrivals.popleft()
            self.version += 1
            listeners = self._listeners
        for listener in listeners:
            listener(topic, msg_type, message)

    def _share(self) -> int:
        """The bytes one topic's history may hold now."""
        return min(self._topic_bytes, self._total_bytes // max(1, len(self._topics)))

    def _trim_all(self):
        """Bring every topic's history down to its share (a new topic made the shares smaller)."""
        share = self._share()
        for entry in self._topics.values():
            self._bytes -= entry.bytes
            entry.trim(share)
            self._bytes += entry.bytes

    def topic_budget(self) -> int:
        """The bytes one topic's history may hold now (``topic_bytes``, or an equal share of ``total_bytes``)."""
        with self._lock:
            return self._share()

    def held_bytes(self) -> int:
        """The bytes (``message_bytes``'s estimate) every topic's history holds now."""
        with self._lock:
            return self._bytes

    def latest(self, topic: str):
        """The newest message on ``topic`` as a dict (decoded once, on the first read), or None."""
        with self._lock:
            entry = self._topics.get(topic)
            if not entry or not entry.last:
                return None
            message = entry.last[1]
            if self._decode is None:
                return message
            recorded, decoded = entry.shown
            if recorded is not message:
                decoded = self._decode(message)
                entry.shown = (message, decoded)
            return decoded

    def value(self, topic: str, path: str, default=None):
        """The newest value of a field, or ``default`` when there is none (yet)."""
        message = self.latest(topic)
        try:
            return field_value(message, path) if message is not None else default
        except KeyError:
            return default

    def series(self, topic: str, path: str, since: float = None) -> list:
        """(time, number) pairs of a numeric field from the history, oldest first."""
        with self._lock:
            entry = self._topics.get(topic)
            samples = list(entry.history) if entry else []
        points = []
        for stamp, message, _size in samples:
            if since is not None and stamp < since:
                continue
            try:
                number = field_value(message, path)
            except KeyError:
                continue
            if isinstance(number, (int, float)) and not isinstance(number, bool):
                points.append((stamp, float(number)))
        return points

    def topics(self) -> list:
        """Every topic seen, with its type, message count, rate (Hz) and the age of its newest message."""
        now = self._clock()
        with self._lock:
            infos = []
            for topic, entry in sorted(self._topics.items()):
                recent = [t for t in entry.arrivals if t >= now - self._rate_window]
                spread = recent[-1] - recent[0] if len(recent) > 1 else 0.0
                rate = (len(recent) - 1) / spread if spread > 0 else 0.0
                infos.append(TopicInfo(topic, entry.msg_type, entry.count, rate, now - entry.last[0],
                                       len(entry.history), entry.cut))
            return infos
