"""Executor figures, each against a baseline measured in the same run.

(a) per-block overhead: a Blockly-generated 100,000-iteration loop, instrumented, vs the
    same generated Python without instrumentation;
(b) stop latency: stop request -> zero velocity on /cmd_vel, while the program sleeps,
    drives and spins in a tight loop (baseline: publishing the zero Twist directly);
(c) GUI responsiveness: event-loop delay p99 in the main window while a tight loop runs
    at full speed, vs the idle window.

    python benchmarks/executor.py
"""
import statistics
import threading
import time
from pathlib import Path

import _paths  # noqa: F401 - its set-up: Rockly and the tests' helpers importable, Qt offscreen
from program_builder import block, number, stack, workspace

ITERATIONS = 100_000
STOP_TRIALS = 15


def counting_loop():
    counter = block("math_change", {"VAR": {"id": "n"}}, {"DELTA": number(1)})
    ws = workspace(stack(block("variables_set", {"VAR": {"id": "n"}}, {"VALUE": number(0)}),
                         block("controls_repeat_ext", inputs={"TIMES": number(ITERATIONS), "DO": counter})))
    ws["variables"] = [{"name": "n", "id": "n"}]
    return ws


def time_run(code, control_factory, repeats=5):
    from rockly_desktop.executor.runner import ProgramRunner

    timings = []
    for _ in range(repeats):
        runner = ProgramRunner(code, {}, control_factory(), lambda event: None)
        started = time.perf_counter()
        result = runner.run()
        timings.append(time.perf_counter() - started)
        assert result.outcome == "finished", result
    return statistics.median(timings)


def per_block_overhead(editor):
    from rockly_desktop.executor.control import RunControl

    editor.call_and_wait("load", {"workspace": counting_loop()})
    plain = editor.call_and_wait("getState")["python"]
    instrumented = editor.call_and_wait("getRunCode")["code"]
    baseline = time_run(plain, RunControl)
    measured = time_run(instrumented, RunControl)
    print(f"(a) {ITERATIONS:,}-iteration generated loop: plain {baseline * 1000:.1f} ms, instrumented "
          f"{measured * 1000:.1f} ms, ratio {measured / baseline:.2f} (aim <= 3)")


def stop_latencies(hobbit, program_code, settle):
    """Seconds from request_stop to the zero Twist arriving on /cmd_vel, per trial."""
    from rockly_desktop.executor.control import RunControl
    from rockly_desktop.executor.run_setup import make_runner
    from rockly_desktop.robot.sim.link import SimulatedRobot

    robot = SimulatedRobot(hobbit, speed=1.0)
    zero_seen = threading.Event()
    arrivals = []

    def on_twist(message):
        if not (message.get("linear") or {}).get("x") and not (message.get("angular") or {}).get("z"):
            arrivals.append(time.perf_counter())
            zero_seen.set()

    robot.world.subscribe("/cmd_vel", on_twist)
    latencies = []
    try:
        for _ in range(STOP_TRIALS):
            control = RunControl()
            runner = make_runner(hobbit, robot, {"code": program_code, "variables": {}}, control, lambda e: None)
            thread = threading.Thread(target=runner.run)
            thread.start()
            time.sleep(settle)
            zero_seen.clear()
            arrivals.clear()
            requested = time.perf_counter()
            control.request_stop()
            assert zero_seen.wait(5), "no zero Twist after stop"
            latencies.append(arrivals[0] - requested)
            thread.join(5)
    finally:
        robot.shutdown()
    return latencies


def direct_publish_latencies(hobbit):
    from rockly_desktop.robot.interrupt import Interrupt
    from rockly_desktop.robot.sim.link import SimulatedRobot

    robot = SimulatedRobot(hobbit, speed=1.0)
    arrivals = []
    robot.world.subscribe("/cmd_vel", lambda message: arrivals.append(time.perf_counter()))
    backend = robot.backend(Interrupt())
    latencies = []
    for _ in range(STOP_TRIALS):
        arrivals.clear()
        started = time.perf_counter()
        backend.publish("/cmd_vel", "geometry_msgs/Twist", {})
        latencies.append(arrivals[0] - started)
    robot.shutdown()
    return latencies


def stop_latency(hobbit):
    cases = {
        "sleeping (robot.wait(60))": ("__rockly__.block('w')\nrobot.wait(60)\n", 0.1),
        "driving (robot.drive(20))": ("__rockly__.block('d')\nrobot.drive(20, 'forward')\n", 0.3),
        "tight loop": ("while True:\n  __rockly__.check()\n  __rockly__.block('l')\n  x = 1\n", 0.1),
    }
    baseline = direct_publish_latencies(hobbit)
    print(f"(b) baseline: publishing a zero Twist directly: median {statistics.median(baseline) * 1000:.2f} ms, "
          f"max {max(baseline) * 1000:.2f} ms")
    for name, (code, settle) in cases.items():
        latencies = stop_latencies(hobbit, code, settle)
        print(f"(b) stop latency while {name}: median {statistics.median(latencies) * 1000:.2f} ms, "
              f"max {max(latencies) * 1000:.2f} ms over {len(latencies)} stops (aim max <= 50 ms)")


def event_loop_delays(app, seconds):
    """Lateness (s) of a 10 ms timer over ``seconds``."""
    from PySide6.QtCore import QElapsedTimer, QEventLoop, QTimer

    delays, clock = [], QElapsedTimer()
    loop = QEventLoop()
    expected = [0.0]

    def tick():
        now = clock.nsecsElapsed() / 1e9
        delays.append(max(0.0, now - expected[0]))
        expected[0] = now + 0.010

    timer = QTimer()
    timer.setInterval(10)
    timer.timeout.connect(tick)
    clock.start()
    expected[0] = 0.010
    timer.start()
    QTimer.singleShot(int(seconds * 1000), loop.quit)
    loop.exec()
    timer.stop()
    return delays


def p99(values):
    return sorted(values)[int(len(values) * 0.99) - 1]


def gui_responsiveness(tmp_settings):
    from PySide6.QtCore import QCoreApplication, QEvent, QEventLoop, QTimer

    from rockly_desktop.app import build_main_window, create_application

    app = create_application()
    window = build_main_window(tmp_settings)
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
    idle = event_loop_delays(app, 3)
    window.runs.sig_state_changed.connect(lambda state: state == "running" and loop.quit())
    window.runs.run()  # the run starts once the page has given its code
    loop.exec()
    busy = event_loop_delays(app, 3)
    window.runs.stop()
    window.runs.shutdown()
    QTimer.singleShot(200, loop.quit)
    loop.exec()
    print(f"(c) GUI event-loop delay, idle window: p99 {p99(idle) * 1000:.1f} ms; while a tight loop runs at full "
          f"speed: p99 {p99(busy) * 1000:.1f} ms (aim <= 30 ms), ratio {p99(busy) / max(p99(idle), 1e-4):.1f}")
    window.document.modified = False
    window.close()
    window.deleteLater()
    # Delete the window (and its web page) now: a page left for interpreter exit crashes QtWebEngine.
    QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)


def main():
    import tempfile

    from rockly_desktop.app import create_application
    from rockly_desktop.bridge.headless import HeadlessEditor
    from rockly_desktop.profiles.registry import ProfileRegistry

    create_application()
    hobbit = ProfileRegistry.discover().get("hobbit")
    editor = HeadlessEditor()
    editor.use_profile(hobbit)
    per_block_overhead(editor)
    editor.close()
    stop_latency(hobbit)
    with tempfile.TemporaryDirectory() as folder:
        gui_responsiveness(str(Path(folder) / "settings.ini"))


if __name__ == "__main__":
    main()
