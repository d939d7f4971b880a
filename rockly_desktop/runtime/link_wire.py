"""The wire between a link host and its program's process: one JSON object a line, each at most
``MAX_LINE`` bytes, on a socket pair.

Values cross it as JSON, with what ROS messages hold and JSON does not: bytes (``{"__bytes__": base64}``),
``array.array`` and tuples (as lists). An error raised by the host's backend crosses as its kind and its
text in the run's language, and is raised again on the program's side as the same kind (see
``error_record`` and ``raised_error``).
"""
import array
import base64
import json

from rockly_desktop.core.errors import (
    DefinitionNotLearnt,
    ProgramStopped,
    RobotCommandError,
    RobotConnectionLost,
    RobotTimeout,
)

MAX_LINE = 16 * 1024 * 1024  # a camera image's latest message fits; a program's own line never needs more

_ERRORS = {error.__name__: error for error in (
    ProgramStopped, RobotTimeout, RobotConnectionLost, DefinitionNotLearnt, RobotCommandError,
    ValueError, TypeError, KeyError, IndexError, AttributeError, OverflowError, ZeroDivisionError)}


class LineTooLong(ValueError):
    """A line on the wire is longer than ``MAX_LINE``: the other side is broken or hostile."""


def _plain(value):
    if isinstance(value, (bytes, bytearray, memoryview)):
        return {"__bytes__": base64.b64encode(bytes(value)).decode("ascii")}
    if isinstance(value, (array.array, tuple, set, frozenset)):
        return list(value)
    raise TypeError(f"a {type(value).__name__} cannot cross to the robot's process")


def _revived(record: dict):
    if len(record) == 1 and "__bytes__" in record:
        return base64.b64decode(record["__bytes__"])
    return record


def encoded(record: dict) -> bytes:
    """``record`` as one line of the wire (LineTooLong past ``MAX_LINE``)."""
    line = (json.dumps(record, default=_plain, ensure_ascii=False, separators=(",", ":")) + "\n").encode("utf-8")
    if len(line) > MAX_LINE:
        raise LineTooLong(f"{len(line)} bytes on one line; the wire takes at most {MAX_LINE}")
    return line


def decoded(line: bytes) -> dict:
    """One line of the wire as its record; ValueError for anything but a JSON object."""
    record = json.loads(line.decode("utf-8"), object_hook=_revived)
    if not isinstance(record, dict):
        raise ValueError("a line of the wire is not a JSON object")
    return record


class LineReader:
    """Reads the wire's lines from a socket; ``read()`` is None once the other side closed it."""

    def __init__(self, sock):
        self._file = sock.makefile("rb", buffering=65536)

    def read(self):
        """The next record, None at the end; LineTooLong or ValueError for a broken line."""
        line = self._file.readline(MAX_LINE + 1)
        if not line:
            return None
        if len(line) > MAX_LINE:
            raise LineTooLong(f"a line longer than {MAX_LINE} bytes")
        return decoded(line)

    def close(self):
        """Let go of the reading side."""
        self._file.close()


def error_record(error: BaseException, language: str) -> dict:
    """An error of the host's backend as it crosses the wire: its kind and its text in ``language``."""
    text = error.in_language(language) if hasattr(error, "in_language") else str(error)
    kind = type(error).__name__ if type(error).__name__ in _ERRORS else _nearest_kind(error)
    return {"kind": kind, "text": text}


def _nearest_kind(error: BaseException) -> str:
    for kind, known in _ERRORS.items():
        if isinstance(error, known):
            return kind
    return "RuntimeError"


def raised_error(record: dict) -> BaseException:
    """The error an error record names, to raise on the program's side."""
    kind = _ERRORS.get(str(record.get("kind")), RuntimeError)
    return kind(str(record.get("text", "")))
