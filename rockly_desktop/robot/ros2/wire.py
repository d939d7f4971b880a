"""The protocol between Rockly and its ROS 2 helper: length-prefixed pickled tuples over pipes.

A frame is a 4-byte big-endian length and a pickle (protocol 5) of a tuple. Both ends are
this package (the helper is Rockly's own child on anonymous pipes), so pickle is safe here
and is the fastest standard-library encoding of the nested dicts, bytes and NaNs ROS
messages hold (faster than JSON; msgpack would be a new dependency on both sides).

Rockly → helper: ``(CALL, id, op, args)`` wants an answer, ``(CAST, 0, op, args)`` does not.
Helper → Rockly: ``(REPLY, id, ok, value)`` answers a call (when not ok, value is ``(kind, words)``:
'timeout' or 'command', and the error's words, see ``said``); ``(EVENT, kind, key, data)`` reports
messages, feedback, goal ends and failures of casts (``(kind, words)`` too).
The helper's first frame is ``(EVENT, "hello", PROTOCOL, info)``; a client refuses another
protocol version. From then on it says ``(EVENT, "alive", None, None)`` every HEARTBEAT_SECONDS,
whatever its requests are doing: a helper silent for longer is hung (``client``).
Standard library only: the helper's Python imports this too.
"""
import pickle
import struct

PROTOCOL = 4
HEARTBEAT_SECONDS = 0.2
# A new DDS participant may take 2 s (a busy machine: more) to discover the others: a fresh helper's waits for
# what the graph holds (a subscriber to match, a topic's type, a first message) count only after this much.
DISCOVERY_SECONDS = 5.0
CALL, CAST, REPLY, EVENT = "call", "cast", "reply", "event"

_HEADER = struct.Struct(">I")


class TextError(Exception):
    """An error (in the helper) whose words are Rockly's catalogue text ``key`` with ``values``:
    Rockly's side says it in the run's language (``resources/locale``; the helper reads no catalogue)."""

    def __init__(self, key: str, **values):
        super().__init__(key, values)
        self.key = key
        self.values = values

    def __str__(self) -> str:
        return f"{self.key} {self.values}"


def said(error: Exception):
    """``error``'s words as they cross the pipe: ``(key, values)`` of a TextError, else its plain text."""
    return (error.key, error.values) if isinstance(error, TextError) else str(error)


def encode(frame: tuple) -> bytes:
    """One frame as bytes to write."""
    body = pickle.dumps(frame, protocol=5)
    return _HEADER.pack(len(body)) + body


def read_frame(stream):
    """The next frame from a binary stream, or None at its end (the other side is gone)."""
    header = stream.read(_HEADER.size)
    if len(header) < _HEADER.size:
        return None
    size, = _HEADER.unpack(header)
    body = stream.read(size)
    if len(body) < size:
        return None
    return pickle.loads(body)
