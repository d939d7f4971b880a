"""The pure runner: block hooks, pause/step/continue, breakpoints, stop, errors, safe stop. No Qt."""
import threading
import time

import pytest
from fake_time import FakeTime
from waiting import eventually

from rockly_desktop.core.errors import RobotCommandError
from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.events import OutputPrinted, RunFinished, RunPaused, RunResumed, VariablesChanged
from rockly_desktop.executor.runner import ProgramRunner
from rockly_desktop.robot import interrupt

PROGRAM = """\
__rockly__.block('a')
count = 0
__rockly__.block('b')
for i in range(3):
  __rockly__.check()
  __rockly__.block('c')
  count = count + 1
__rockly__.block('d')
print('done', count)
"""


class Recorder:
    """Collects events from the worker thread and lets a test wait for one."""

    def __init__(self):
        self.events = []
        self._changed = threading.Condition()

    def __call__(self, event):
        with self._changed:
            self.events.append(event)
            self._changed.notify_all()

    def wait_for(self, predicate, timeout=5.0):
        with self._changed:
            assert self._changed.wait_for(lambda: any(predicate(e) for e in self.events), timeout), self.events

    def of(self, kind):
        return [event for event in self.events if isinstance(event, kind)]


def start(code, control, namespace=None, variables=None, on_end=None):
    recorder = Recorder()
    runner = ProgramRunner(code, namespace or {}, control, recorder, variables, on_end)
    thread = threading.Thread(target=runner.run)
    thread.start()
    return runner, recorder, thread


def run_to_end(code, control=None, **kwargs):
    runner, recorder, thread = start(code, control or RunControl(), **kwargs)
    thread.join(10)
    assert not thread.is_alive()
    return runner, recorder


def test_a_program_runs_to_its_end_and_prints():
    ended = []
    runner, recorder = run_to_end(PROGRAM, variables={"count": "count"}, on_end=lambda: ended.append(True))
    assert recorder.of(OutputPrinted) == [OutputPrinted("done 3")]
    assert recorder.events[-1] == RunFinished("finished")
    assert recorder.of(VariablesChanged)[-1].values == {"count": "3"}
    assert ended == [True]


def test_breakpoint_pauses_before_the_block_each_time_it_is_reached():
    control = RunControl(breakpoints={"c"})
    runner, recorder, thread = start(PROGRAM, control, variables={"count": "count"})
    for expected_count in ("0", "1", "2"):
        recorder.wait_for(lambda e, expected_count=expected_count:
                          isinstance(e, RunPaused) and len(recorder.of(RunPaused)) == int(expected_count) + 1)
        assert recorder.of(RunPaused)[-1] == RunPaused("c", "breakpoint")
        assert recorder.of(VariablesChanged)[-1].values == {"count": expected_count}
        control.resume()
    thread.join(5)
    assert recorder.events[-1] == RunFinished("finished")
    assert len(recorder.of(RunResumed)) == 3


def step_through(code, variables=None):
    """Run ``code`` one block at a time (Step after each pause); return the block ids and the recorder."""
    control = RunControl()
    control.step()
    runner, recorder, thread = start(code, control, variables=variables)
    visited = []
    while True:
        recorder.wait_for(lambda e: isinstance(e, (RunPaused, RunFinished)) and
                          len(recorder.of(RunPaused)) + len(recorder.of(RunFinished)) > len(visited))
        if recorder.of(RunFinished):
            break
        visited.append(recorder.of(RunPaused)[-1].block_id)
        control.step()
    thread.join(5)
    return visited, recorder


def test_stepping_visits_every_block_in_order():
    visited, recorder = step_through(PROGRAM)
    assert visited == ["a", "b", "c", "c", "c", "d"]
    assert {event.reason for event in recorder.of(RunPaused)} == {"step"}
    assert recorder.events[-1] == RunFinished("finished")


def test_pause_request_pauses_a_running_loop_and_continue_resumes_it():
    control = RunControl()
    code = "n = 0\nwhile n < 10 ** 9:\n  __rockly__.check()\n  __rockly__.block('loop')\n  n = n + 1\n"
    runner, recorder, thread = start(code, control)
    control.request_pause()
    recorder.wait_for(lambda e: isinstance(e, RunPaused))
    assert recorder.of(RunPaused)[-1] == RunPaused("loop", "pause")
    control.resume()
    recorder.wait_for(lambda e: isinstance(e, RunResumed))
    control.request_stop()
    thread.join(5)
    assert recorder.events[-1].outcome == "stopped"


@pytest.mark.parametrize("code", [
    "going()\nwhile True:\n  __rockly__.check()\n",                                  # an empty tight loop
    "going()\nwhile True:\n  __rockly__.check()\n  __rockly__.block('x')\n  y = 1\n", # a loop of blocks
    "__rockly__.block('w')\nrobot_wait(60)\n",                                         # inside a long wait
])
def test_stop_ends_the_program_quickly_wherever_it_is(code):
    control = RunControl()
    ended, going = [], threading.Event()

    def robot_wait(seconds):
        going.set()
        control.interrupt.sleep(seconds)

    runner, recorder, thread = start(code, control, namespace={"robot_wait": robot_wait, "going": going.set},
                                     on_end=lambda: ended.append(time.monotonic()))
    assert going.wait(5)  # it got going; the measurement below is what matters
    requested = time.monotonic()
    control.request_stop()
    thread.join(5)
    assert recorder.events[-1].outcome == "stopped"
    assert ended and ended[0] - requested < 0.5


def test_stop_while_paused_ends_the_run():
    control = RunControl(breakpoints={"b"})
    runner, recorder, thread = start(PROGRAM, control)
    recorder.wait_for(lambda e: isinstance(e, RunPaused))
    control.request_stop()
    thread.join(5)
    assert recorder.events[-1] == RunFinished("stopped", "b")


def test_an_error_names_its_block_in_plain_words_with_the_traceback_at_hand():
    code = "__rockly__.block('ok')\nx = 1\n__rockly__.block('bad')\nx = x / 0\n"
    ended = []
    runner, recorder = run_to_end(code, on_end=lambda: ended.append(True))
    result = recorder.events[-1]
    assert (result.outcome, result.block_id) == ("error", "bad")
    assert result.message == "Dividing by zero is not possible."
    assert "ZeroDivisionError" in result.details and "<rockly program>" in result.details
    assert "runner.py" not in result.details
    assert ended == [True]


def test_a_failing_robot_command_is_reported_on_its_block_as_the_robots_refusal_without_a_traceback():
    def refuse(*_args):
        raise RobotCommandError("the arm is blocked")

    code = "__rockly__.block('arm')\nrobot_move()\n"
    runner, recorder = run_to_end(code, namespace={"robot_move": refuse})
    assert recorder.events[-1] == RunFinished("error", "arm", "The robot could not do this: the arm is blocked",
                                              details=None, by_robot=True)


def test_slow_motion_waits_at_every_block():
    control = RunControl(delay=0.05)
    started = time.monotonic()
    run_to_end(PROGRAM, control)
    assert time.monotonic() - started >= 6 * 0.05


def test_a_failing_safe_stop_is_reported_but_the_run_still_ends():
    def broken_stop():
        raise RuntimeError("no connection")

    runner, recorder = run_to_end("__rockly__.block('a')\n", on_end=broken_stop)
    assert recorder.events[-1] == RunFinished("finished")
    assert OutputPrinted("Warning: the robot could not be stopped safely.") in recorder.events


def test_variables_show_their_blockly_names():
    runner, recorder = run_to_end("my_name = 'Ada'\nscore = [1, 2]\n",
                                  variables={"my name": "my_name", "score": "score", "unset": "unset"})
    assert recorder.of(VariablesChanged)[-1].values == {"my name": "“Ada”", "score": "[1, 2]", "unset": "–"}


def test_pause_inside_a_long_wait_holds_its_clock_until_continue(monkeypatch):
    clock = FakeTime()
    monkeypatch.setattr(interrupt, "time", clock)
    control = RunControl()
    code = "__rockly__.block('w')\nrobot_wait(0.5)\n__rockly__.block('after')\n"
    runner, recorder, thread = start(code, control, namespace={"robot_wait": control.interrupt.sleep})
    eventually(lambda: clock.reads)  # the wait has begun: it ends at 0.5
    clock.now = 0.25
    control.request_pause()
    recorder.wait_for(lambda e: isinstance(e, RunPaused))
    assert recorder.of(RunPaused)[-1] == RunPaused("w", "pause")
    clock.now = 8.25  # much longer than the whole wait: the clock must not run while paused
    control.resume()
    recorder.wait_for(lambda e: isinstance(e, RunResumed))
    clock.read_again()  # the wait is back in its loop, its end moved by the pause
    clock.now = 8.375
    clock.read_again()
    assert not recorder.of(RunFinished)  # 0.125 s of the wait are still to come
    clock.now = 8.5
    thread.join(5)
    assert not thread.is_alive()
    assert recorder.events[-1] == RunFinished("finished")
    assert len(recorder.of(RunPaused)) == 1  # the pause was not repeated at the next block
