"""Recording figures, recording on vs off, measured in the same run.

(a) per-block cost: a 100,000-iteration loop shaped like the generated code
    (``__rockly__.check()``, ``__rockly__.block(ID)``, one statement), run without and
    with a recording (blocks beyond the recorder's budget are sampled, so a tight loop
    costs one extra test per block);
(b) a 1 kHz topic: the cost per message of the state store taking it, without and with
    a recording listening (rate cap 10 per second: most messages are counted and left out);
(c) GUI event-loop delay p99 in the main window while a tight loop runs at full speed,
    with the window's recording off (kept: 0) and on;
(d) values on the blocks: the same loop whose statement holds two expression blocks, the
    code as the page writes it with values off and on (each expression's value through
    ``__rockly__.value(ID, ...)``), both recorded.

    python benchmarks/recording.py
"""
import statistics
import tempfile
import time
from numbers import Number
from pathlib import Path

import _paths  # noqa: F401 - its set-up: Rockly and the tests' helpers importable, Qt offscreen

ITERATIONS = 100_000
MESSAGES = 100_000
AIM = 1.2
CODE = f"""n = 0
for count in range({ITERATIONS}):
    __rockly__.check()
    __rockly__.block('change')
    n = (n if isinstance(n, Number) else 0) + 1
"""


VALUES_OFF = f"""n = 0
for count in range({ITERATIONS}):
    __rockly__.check()
    __rockly__.block('set')
    n = (n + 1) % 7
"""
VALUES_ON = f"""n = 0
for count in range({ITERATIONS}):
    __rockly__.check()
    __rockly__.block('set')
    n = __rockly__.value('rest', (__rockly__.value('sum', (__rockly__.value('get', (n)) + 1)) % 7))
"""


def run_once(recorder=None, code=CODE) -> float:
    from rockly_desktop.executor.control import RunControl
    from rockly_desktop.executor.runner import ProgramRunner

    runner = ProgramRunner(code, {"Number": Number}, RunControl(), lambda event: None, {"n": "n"},
                           entered=None if recorder is None else recorder.blocks)
    if recorder is not None:
        recorder.follow(runner.hooks, runner.variables_snapshot, values=runner.values_snapshot)
    started = time.perf_counter()
    result = runner.run()
    elapsed = time.perf_counter() - started
    assert result.outcome == "finished", result
    return elapsed


def per_block(folder: Path):
    from rockly_desktop.recording.recorder import Recorder

    off, on = [], []
    for trial in range(7):  # interleaved, so both see the same machine
        off.append(run_once())
        recorder = Recorder(folder / f"blocks{trial}.mcap")
        recorder.start({"program": "benchmark"})
        try:
            on.append(run_once(recorder))
        finally:
            recorder.close()
    plain, recorded = statistics.median(off), statistics.median(on)
    print(f"(a) {ITERATIONS:,}-iteration loop: per block {plain / ITERATIONS * 1e9:.0f} ns without a recording, "
          f"{recorded / ITERATIONS * 1e9:.0f} ns with one, ratio {recorded / plain:.2f} (aim <= {AIM})")


def per_value_block(folder: Path):
    from rockly_desktop.recording.recorder import Recorder

    times = {VALUES_OFF: [], VALUES_ON: []}
    for trial in range(7):
        for code, found in times.items():
            recorder = Recorder(folder / f"values{trial}.mcap")
            recorder.start({"program": "benchmark"})
            try:
                found.append(run_once(recorder, code))
            finally:
                recorder.close()
    plain, watched = statistics.median(times[VALUES_OFF]), statistics.median(times[VALUES_ON])
    print(f"(d) values on the blocks (3 expression blocks a statement, recorded): per statement "
          f"{plain / ITERATIONS * 1e9:.0f} ns with values off, {watched / ITERATIONS * 1e9:.0f} ns on, ratio "
          f"{watched / plain:.2f}; {(watched - plain) / ITERATIONS / 3 * 1e9:.0f} ns per expression block")


def per_message(folder: Path):
    from rockly_desktop.core.state_store import StateStore
    from rockly_desktop.recording.recorder import Recorder

    def feed(store):
        message = {"data": 1.0}
        started = time.perf_counter()
        for _ in range(MESSAGES):
            store.record("/fast", "std_msgs/Float64", message)
        return time.perf_counter() - started

    off, on = [], []
    for trial in range(7):
        off.append(feed(StateStore()))
        store, recorder = StateStore(), Recorder(folder / f"topic{trial}.mcap", topic_rate=10)
        recorder.start({"program": "benchmark"})
        store.add_listener(recorder.topic)
        try:
            on.append(feed(store))
        finally:
            recorder.close()
    plain, recorded = statistics.median(off), statistics.median(on)
    print(f"(b) 1 kHz topic: {plain / MESSAGES * 1e6:.2f} µs a message without a recording, "
          f"{recorded / MESSAGES * 1e6:.2f} µs with one, ratio {recorded / plain:.2f}; "
          f"at 1 kHz that is {recorded * 1000 / MESSAGES * 100:.2f}% of one core")


def gui_while_recording(folder: Path):
    from executor import event_loop_delays, p99  # benchmarks/executor.py: the same measurement
    from program_builder import block, number, stack, workspace
    from PySide6.QtCore import QCoreApplication, QEvent, QEventLoop, QTimer

    from rockly_desktop.app import build_main_window, create_application
    from rockly_desktop.settings.app_settings import AppSettings

    app = create_application()
    settings_path = str(folder / "settings.ini")
    settings = AppSettings(settings_path)
    settings.recordings_folder = str(folder / "recordings")
    settings.sync()
    window = build_main_window(settings_path)
    window.show()
    loop = QEventLoop()
    window.editor.sig_ready.connect(loop.quit)
    window.start()
    loop.exec()
    forever = block("logic_boolean", {"BOOL": "TRUE"})
    count_up = block("math_change", {"VAR": {"id": "n"}}, {"DELTA": number(1)})
    tight = block("controls_whileUntil", {"MODE": "WHILE"}, {"BOOL": forever, "DO": count_up})
    ws = workspace(stack(block("variables_set", {"VAR": {"id": "n"}}, {"VALUE": number(0)}), tight))
    ws["variables"] = [{"name": "n", "id": "n"}]
    window.editor.call("load", {"workspace": ws}, lambda _result, _error: loop.quit())
    loop.exec()
    window.runs.sig_state_changed.connect(lambda state: state in ("running", "idle") and loop.quit())
    delays = {}
    for kept in (0, 20, 0, 20):  # off, on, twice each
        window.settings.recordings_kept = kept
        window.runs.run()
        loop.exec()
        delays.setdefault(kept, []).extend(event_loop_delays(app, 3))
        window.runs.stop()
        loop.exec()
    print(f"(c) GUI event-loop delay p99 while a tight loop runs: {p99(delays[0]) * 1000:.1f} ms without a "
          f"recording, {p99(delays[20]) * 1000:.1f} ms recording (aim <= 30 ms)")
    window.document.modified = False
    window.close()
    window.deleteLater()
    QTimer.singleShot(200, loop.quit)
    loop.exec()
    QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)


if __name__ == "__main__":
    with tempfile.TemporaryDirectory() as folder:
        per_block(Path(folder))
        per_message(Path(folder))
        gui_while_recording(Path(folder))
        per_value_block(Path(folder))
