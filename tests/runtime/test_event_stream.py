"""The run's event stream (runtime/event_stream.py): one JSON object per line, and a reader that goes away
never stops the run."""
import json
import os

from rockly_desktop.executor.events import BlockEntered, OutputPrinted, RunFinished, RunPaused, VariablesChanged
from rockly_desktop.runtime.event_stream import EventStream


def test_each_event_is_one_json_line_naming_its_block_type(tmp_path):
    path = tmp_path / "events.jsonl"
    with path.open("w", encoding="utf-8") as stream:
        events = EventStream(stream, {"b1": "hobbit_move"})
        for event in (BlockEntered("b1"), OutputPrinted("zwei\u00a0Wörter \"quoted\""), RunPaused("b1", "step"),
                      VariablesChanged({"n": "3"}), RunFinished("error", "b1", "no", "trace")):
            events.event(event)
    assert [json.loads(line) for line in path.read_text(encoding="utf-8").splitlines()] == [
        {"event": "block", "id": "b1", "type": "hobbit_move"},
        {"event": "print", "text": "zwei\u00a0Wörter \"quoted\""},
        {"event": "paused", "block": "b1", "reason": "step"},
        {"event": "variables", "values": {"n": "3"}},
        {"event": "finished", "outcome": "error", "block": "b1", "message": "no", "by_robot": False},
    ]


def test_a_reader_closing_its_end_stops_the_writing_not_the_run():
    read, write = os.pipe()
    stream = os.fdopen(write, "w", encoding="utf-8")
    events = EventStream(stream, {})
    events.event(BlockEntered("b1"))
    os.close(read)  # the window detached
    events.event(BlockEntered("b2"))  # EPIPE: no exception reaches the program
    events.event(BlockEntered("b3"))
    assert not events.open
    try:
        stream.close()
    except BrokenPipeError:
        pass
