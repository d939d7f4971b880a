"""A run's events as JSON lines: how something outside the run (a window attaching, the robot's agent, a
test) follows it block by block.

One JSON object per line (UTF-8, ``\\n`` at its end), each naming its ``event``:

    {"event": "started", "format": 1, "rockly": "0.1.0", "program": "square.rockly", "profile": "my_robot",
     "profile_version": "1.0.0", "backend": "sim", "pid": 4242}
    {"event": "block", "id": "b7", "type": "my_robot_move"}        the program is about to run block b7
    {"event": "print", "text": "hello"}                               one line the program printed
    {"event": "paused", "block": "b7", "reason": "breakpoint"}        (or "step", "pause")
    {"event": "resumed"}
    {"event": "variables", "values": {"count": "3"}}                  Blockly names, values as people read them
    {"event": "finished", "outcome": "finished", "block": null, "message": null, "by_robot": false}
                                                                      (outcome "stopped" or "error"; after the
                                                                      robot's safe stop ran)
    {"event": "exit", "status": 0}                                    the last line: the process's exit status

A reader may come and go: a stream that can no longer be written (the reader closed its end) is left
alone and the run goes on. Lines of a later ``format`` only add keys or events; a reader ignores
what it does not know.
"""
import json
import os
import threading

from rockly_desktop import __version__
from rockly_desktop.executor.events import (
    BlockEntered,
    OutputPrinted,
    RunFinished,
    RunPaused,
    RunResumed,
    VariablesChanged,
)

FORMAT = 1


def event_record(event, types: dict) -> dict:
    """The JSON object for one executor event (``types``: block id -> block type); None for one the stream
    does not carry."""
    if isinstance(event, BlockEntered):
        return {"event": "block", "id": event.block_id, "type": types.get(event.block_id)}
    if isinstance(event, OutputPrinted):
        return {"event": "print", "text": event.text}
    if isinstance(event, RunPaused):
        return {"event": "paused", "block": event.block_id, "reason": event.reason}
    if isinstance(event, RunResumed):
        return {"event": "resumed"}
    if isinstance(event, VariablesChanged):
        return {"event": "variables", "values": dict(event.values)}
    if isinstance(event, RunFinished):
        return {"event": "finished", "outcome": event.outcome, "block": event.block_id, "message": event.message,
                "by_robot": event.by_robot}
    return None


def started_record(program: str, profile_id: str, profile_version: str, backend: str) -> dict:
    """The first line of a run's stream: what runs where, and which process it is."""
    return {"event": "started", "format": FORMAT, "rockly": __version__, "program": program, "profile": profile_id,
            "profile_version": profile_version, "backend": backend, "pid": os.getpid()}


class EventStream:
    """Writes a run's events to ``stream`` (a text file, a FIFO, standard output) as JSON lines."""

    def __init__(self, stream, types: dict):
        self._stream = stream
        self._types = types
        self._lock = threading.Lock()
        self.open = True

    def event(self, event):
        """Write one executor event (an event the stream does not carry is skipped)."""
        record = event_record(event, self._types)
        if record is not None:
            self.write(record)

    def write(self, record: dict):
        """Write ``record`` as one line, at once (flushed); a reader that went away ends the writing only."""
        line = json.dumps(record, ensure_ascii=False) + "\n"
        with self._lock:
            if not self.open:
                return
            try:
                self._stream.write(line)
                self._stream.flush()
            except (OSError, ValueError):  # the reader closed its end (EPIPE), or the file was closed
                self.open = False


def record_event(record: dict):
    """The executor event one of the stream's records says (``event_record``'s inverse); None for a record of
    another kind (``started``, ``exit``) or one it does not know."""
    kind = record.get("event")
    if kind == "block":
        return BlockEntered(str(record.get("id")))
    if kind == "print":
        return OutputPrinted(str(record.get("text")))
    if kind == "paused":
        return RunPaused(record.get("block"), str(record.get("reason")))
    if kind == "resumed":
        return RunResumed()
    if kind == "variables":
        values = record.get("values")
        return VariablesChanged(dict(values) if isinstance(values, dict) else {})
    if kind == "finished":
        return RunFinished(str(record.get("outcome")), record.get("block"), record.get("message"),
                           record.get("details"), bool(record.get("by_robot")))
    return None
