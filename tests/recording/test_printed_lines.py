"""A program printing faster than the recording's tick: a budget of lines a tick is recorded, the rest counted.

Every printed line once went into the recorder's queue: an endless print loop filled it (20,000 a
tick), the writer thread wrote them all while the window waited for the GIL, and the run's end
waited for the backlog (STOP took 0.3 s instead of 0.03 s, ``benchmarks/faults.py`` (a)). The writer
here never ticks before the run ends, so what it finds then is exactly what a tick would.
"""
import pytest
from recorded_reading import channels_and_messages

from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.run_setup import make_runner
from rockly_desktop.executor.run_to_mcap import RunRecording
from rockly_desktop.recording import recorder
from rockly_desktop.recording.moments import Moments
from rockly_desktop.recording.reading import read_recording
from rockly_desktop.recording.timeline import timeline_lines
from rockly_desktop.robot.sim.link import SimulatedRobot

PRINTED = 50_000


@pytest.fixture
def printed_fast(hobbit, tmp_path, monkeypatch):
    """A recording of a run printing PRINTED lines in one (never ending) tick of the writer."""
    monkeypatch.setattr(recorder, "TICK_SECONDS", 3600.0)
    path = tmp_path / "printing.mcap"
    robot = SimulatedRobot(hobbit, speed=10)
    try:
        recording = RunRecording(path, hobbit, robot, "printing.rockly")
        code = {"code": f"for i in range({PRINTED}):\n    print('tick', i)\n"}
        result = make_runner(hobbit, robot, code, RunControl(), lambda event: None, recording=recording).run()
    finally:
        robot.shutdown()
    assert result.outcome == "finished", result
    return path


def test_a_tick_records_its_budget_of_printed_lines_and_counts_the_rest(printed_fast):
    _found, messages = channels_and_messages(printed_fast)
    lines = [message["text"] for message in messages["/rockly/output"] if "text" in message]
    skipped = [message["skipped"] for message in messages["/rockly/output"] if "skipped" in message]
    assert lines == [f"tick {i}" for i in range(recorder.LINES_PER_TICK)]  # the first ones, in order
    assert skipped == [PRINTED - recorder.LINES_PER_TICK]
    assert messages["/rockly/recording"][-1]["overflow"] == 0  # nothing else was crowded out of the queue


def test_the_replay_and_the_timeline_say_how_many_lines_were_not_recorded(printed_fast):
    recording = read_recording(printed_fast)
    moments = Moments(recording)
    assert moments.output == [f"tick {i}" for i in range(recorder.LINES_PER_TICK)]
    printed = moments.printed_lines(lambda count: f"{count} not recorded")
    assert len(printed) == recorder.LINES_PER_TICK + 1
    assert printed[-1].endswith(f"  {PRINTED - recorder.LINES_PER_TICK} not recorded")
    assert moments.at(moments.duration).printed == len(printed)
    assert any(line.endswith(f"print   ({PRINTED - recorder.LINES_PER_TICK} more lines printed too fast to record)")
               for line in timeline_lines(recording))
