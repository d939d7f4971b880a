"""After STOP the window reads the run's recording in a thread of its own (real QtWebEngine + Blockly).

Read on the GUI thread, a long run's recording froze the window after STOP: 0.6 s after a run of
two minutes, 2.2 s after nine. The tests watch which thread reads, and hold the reading to see
the window go on meanwhile.
"""
import threading

from page_tools import call_page
from program_builder import block, number, stack, text, workspace
from test_replay import highlighted

from rockly_desktop.recording import reading
from rockly_desktop.ui.replay import replay
from rockly_desktop.ui.replay.recording_reader import release


def counting_and_printing_forever():
    ws = workspace(block("controls_whileUntil", {"MODE": "WHILE"}, {
        "BOOL": block("logic_boolean", {"BOOL": "TRUE"}),
        "DO": stack(block("math_change", {"VAR": {"id": "n"}}, {"DELTA": number(1)}, id="count"),
                    block("text_print", inputs={"TEXT": text("tick")}, id="say"))}))
    ws["variables"] = [{"name": "n", "id": "n"}]
    return ws


class Readings:
    """The threads that read a recording (``read_recording``), each noted when its reading begins, and how many
    readings have not ended; with a ``hold`` (an Event), each reading waits for it first (10 s at most)."""

    def __init__(self, monkeypatch, hold=None):
        self.threads = []
        self.under_way = 0
        self._hold = hold
        self._read = reading.read_recording
        monkeypatch.setattr(reading, "read_recording", self._noted)

    def _noted(self, path):
        self.threads.append(threading.current_thread())
        self.under_way += 1
        try:
            if self._hold is not None:
                self._hold.wait(10)
            return self._read(path)
        finally:
            self.under_way -= 1


def test_after_stop_the_recording_is_read_outside_the_gui_thread_and_its_replay_works(qtbot, window, monkeypatch):
    readings = Readings(monkeypatch)
    call_page(qtbot, window.editor, "load", {"workspace": counting_and_printing_forever()})
    window.runs.run()
    qtbot.waitUntil(lambda: window.console.lines().count("tick") > 100, timeout=20000)
    with qtbot.waitSignal(window.runs.sig_finished, timeout=20000):
        window.runs.stop()

    qtbot.waitUntil(window.replay_bar.isVisible, timeout=10000)
    assert readings.threads and threading.main_thread() not in readings.threads
    window.replay_bar.jump_to(window.replay_bar.duration)
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == [window.replay.moments.at(window.replay_bar.duration).block],
                    timeout=5000)
    assert int(window.variables.values()["n"]) > 0
    lines = window.console.recorded_lines()
    assert any(line.endswith("  tick") for line in lines)
    assert any(line.endswith("more lines were printed too fast to record") for line in lines)  # a tight loop


def test_the_window_goes_on_while_a_recording_is_read_and_a_run_started_meanwhile_keeps_it_hidden(
        qtbot, window, monkeypatch):
    hold = threading.Event()
    readings = Readings(monkeypatch, hold)
    released = []
    monkeypatch.setattr(replay, "release", lambda data: released.append(data) or release(data))
    call_page(qtbot, window.editor, "load", {"workspace": counting_and_printing_forever()})
    window.runs.run()
    qtbot.waitUntil(lambda: window.runs.state == "running", timeout=20000)
    with qtbot.waitSignal(window.runs.sig_finished, timeout=20000):
        window.runs.stop()
    qtbot.waitUntil(lambda: len(readings.threads) == 1, timeout=10000)
    first_recording = window.runs.last_recording

    window.runs.run()  # while the last run's recording is still being read
    qtbot.waitUntil(lambda: window.runs.state == "running", timeout=20000)
    assert readings.under_way == 1 and not window.replay_bar.isVisible()
    hold.set()
    qtbot.waitUntil(lambda: window.replay.wait_for_reading(0), timeout=10000)
    qtbot.wait(50)  # the reading's end is a queued signal: let the window take it
    assert not window.replay_bar.isVisible()  # the finished reading was for the run before this one
    assert len(released) == 1  # what it read is let go outside the GUI thread

    with qtbot.waitSignal(window.runs.sig_finished, timeout=20000):
        window.runs.stop()
    qtbot.waitUntil(window.replay_bar.isVisible, timeout=10000)
    assert window.runs.last_recording != first_recording
    assert window.replay.moments.recording.path == str(window.runs.last_recording)
