"""The robot's state as the panels see it: latest message and a bounded history per topic.

Backend threads (rospy callbacks, the simulator's tick) call ``record``; widgets read on
a timer. Memory is bounded whatever the message rate: each topic keeps at most
``history`` messages and the arrival times of the last ``rate_window`` seconds.
"""
import re
import threading
import time
from collections import deque
from dataclasses import dataclass

_PATH_PART = re.compile(r"([A-Za-z_]\w*)(?:\[(\d+)\])?")


@dataclass(frozen=True)
class TopicInfo:
    """What the store knows of one topic."""

    topic: str
    msg_type: str
    count: int
    rate: float
    age: float


class _Topic:
    def __init__(self, msg_type, history):
        self.msg_type = msg_type
        self.count = 0
        self.last = None
        self.history = deque(maxlen=history)
        self.arrivals = deque()


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
            if not isinstance(value, (list, tuple)) or index >= len(value):
                raise KeyError(path)
            value = value[index]
    return value


class StateStore:
    """Thread-safe latest messages, history and rates per topic."""

    def __init__(self, history: int = 2000, rate_window: float = 2.0, clock=time.monotonic, decode=None):
        """``decode(message) -> dict`` turns recorded message objects into dicts when they are read
        (a ROS feed records messages undecoded, so a 1 kHz topic costs little until someone looks)."""
        self._lock = threading.Lock()
        self._decode = decode
        self._topics = {}
        self._history = history
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

    def record(self, topic: str, msg_type: str, message: dict):
        """Take one message (any thread), and hand it to the listeners."""
        now = self._clock()
        with self._lock:
            entry = self._topics.get(topic)
            if entry is None:
                entry = self._topics[topic] = _Topic(msg_type, self._history)
            entry.count += 1
            entry.last = (now, message)
            entry.history.append((now, message))
            entry.arrivals.append(now)
            while entry.arrivals and entry.arrivals[0] < now - self._rate_window:
                entry.arrivals.popleft()
            self.version += 1
            listeners = self._listeners
        for listener in listeners:
            listener(topic, msg_type, message)

    def latest(self, topic: str):
        """The newest message on ``topic`` as a dict, or None."""
        with self._lock:
            entry = self._topics.get(topic)
            if not entry or not entry.last:
                return None
            stamp, message = entry.last
            if self._decode is not None and not isinstance(message, dict):
                message = self._decode(message)
                entry.last = (stamp, message)
            return message

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
        for stamp, message in samples:
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
                infos.append(TopicInfo(topic, entry.msg_type, entry.count, rate, now - entry.last[0]))
            return infos
