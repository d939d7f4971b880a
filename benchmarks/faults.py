"""Faults and hostile programs, each against a baseline measured in the same run.

(a) STOP latency and the GUI's longest event-loop stall while a program prints in an endless
    loop, against the same loop without printing (aims: STOP <= 50 ms, no stall > 100 ms);
(b) how long ``9 ** 999999999`` holds the run before it fails, against a loop of 1,000 usual
    powers (aim: the window never freezes: milliseconds);
(c) the time from killing the robot's ROS node (kill -9) mid-drive to the block's error, against
    the time from killing the master to the error (the watchdog's own figure);
(d) a hung (SIGSTOP) or killed ROS 2 helper: STOP -> zero velocity on the wire, against a healthy
    helper's (``_fault_helper.py``; aim <= 2 s);
(e) the window's longest stall after STOP for runs of 10 s, 2 min and 10 min, against a 1 s run
    (``_fault_stall.py``; aim <= 100 ms);
(f) memory under a 1 MB x 100 Hz camera for 60 s, against a 16-byte stream (``_fault_memory.py``;
    bound 250 MB).
Each of (d)-(f) runs in a process of its own.

    python benchmarks/faults.py
"""
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from _paths import REPO

sys.path.insert(0, str(REPO / "benchmarks"))
from executor import event_loop_delays
from program_builder import block, number, rockly_document, stack, text, workspace

STOP_TRIALS = 5


def forever(body):
    return block("controls_whileUntil", {"MODE": "WHILE"}, {"BOOL": block("logic_boolean", {"BOOL": "TRUE"}),
                                                             "DO": body})


def counting():
    return block("math_change", {"VAR": {"id": "n"}}, {"DELTA": number(1)})


def run_in_window(app, window, program, seconds):
    """Run ``program`` for ``seconds`` while measuring event-loop delays; then STOP. (delays, stop latency)."""
    from PySide6.QtCore import QEventLoop

    loop = QEventLoop()
    window.editor.call("load", {"workspace": program}, lambda _result, _error: loop.quit())
    loop.exec()
    def running(state):
        if state == "running":
            loop.quit()

    def finished(_result):
        stopped.append(time.perf_counter())
        loop.quit()

    window.runs.sig_state_changed.connect(running)
    window.runs.run()
    loop.exec()
    delays = event_loop_delays(app, seconds)
    stopped = []
    window.runs.sig_finished.connect(finished)
    asked = time.perf_counter()
    window.runs.stop()
    loop.exec()
    window.runs.sig_state_changed.disconnect(running)  # only these: the window's own handlers stay
    window.runs.sig_finished.disconnect(finished)
    return delays, stopped[0] - asked


def endless_print(settings_path):
    from PySide6.QtCore import QCoreApplication, QEvent, QEventLoop

    from rockly_desktop.app import build_main_window, create_application

    app = create_application()
    window = build_main_window(settings_path)
    window.show()
    loop = QEventLoop()
    window.editor.sig_ready.connect(loop.quit)
    window.start()
    loop.exec()
    results = {}
    for name, body in (("counting", counting()), ("printing", block("text_print", inputs={"TEXT": text("tick")}))):
        program = workspace(stack(block("variables_set", {"VAR": {"id": "n"}}, {"VALUE": number(0)}), forever(body)))
        program["variables"] = [{"name": "n", "id": "n"}]
        runs = [run_in_window(app, window, program, 1.5) for _ in range(STOP_TRIALS)]
        stall = max(max(delays) for delays, _stop in runs)
        stops = [stop for _delays, stop in runs]
        results[name] = (stall, statistics.median(stops), max(stops))
    base, printing = results["counting"], results["printing"]
    print(f"(a) endless loop, STOP latency median/max: counting {base[1] * 1000:.1f}/{base[2] * 1000:.1f} ms, "
          f"printing {printing[1] * 1000:.1f}/{printing[2] * 1000:.1f} ms (aim max <= 50 ms); longest GUI stall: "
          f"counting {base[0] * 1000:.0f} ms, printing {printing[0] * 1000:.0f} ms (aim <= 100 ms), "
          f"ratio {printing[0] / max(base[0], 1e-4):.2f}; console lines kept: {len(window.console.lines())}")
    window.document.modified = False
    window.close()
    window.deleteLater()
    QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)


def big_power():
    from rockly_desktop.executor.control import RunControl
    from rockly_desktop.executor.runner import ProgramRunner

    def timed(code):
        runner = ProgramRunner(code, {}, RunControl(), lambda _event: None)
        started = time.perf_counter()
        result = runner.run()
        return time.perf_counter() - started, result.outcome

    usual, _ = timed("for i in range(1000):\n    x = __rockly__.power(i, 3)\n")
    huge, outcome = timed("x = __rockly__.power(9, 999999999)\n")
    print(f"(b) 9 ** 999999999 ends the run ({outcome}) after {huge * 1000:.2f} ms; 1,000 usual powers take "
          f"{usual * 1000:.2f} ms (ratio {huge / usual:.2f}); without the guard Python holds the run for minutes")


def killed_node(folder):
    from ros_helpers import RocklyProcess, RosMaster, messages_received
    from waiting import eventually

    results = {}
    for what in ("robot node", "master"):
        master = RosMaster(Path(folder) / f"ros-{what.replace(' ', '-')}").start()
        simulator = RocklyProcess(["sim", "hobbit", "--ros", "--no-window", "--master", master.uri, "--speed", "0.05"],
                                  master, ready_line="on ROS")
        source = Path(folder) / "drive.rockly"
        source.write_text(rockly_document([block("hobbit_move", {"direction": "+"}, {"speed": number(50)}, id="cmd")]))
        run = RocklyProcess(["run", source, "--backend", "ros1", "--master", master.uri], master,
                            ready_line="block   cmd")
        try:
            eventually(lambda uri=master.uri: messages_received(uri, "/DiscreteMotionCmd") >= 1)
            killed = time.monotonic()
            (simulator.process.kill if what == "robot node" else master.stop)()
            for line in run.process.stderr:
                if line.startswith("error in block"):
                    results[what] = time.monotonic() - killed
                    break
            run.process.wait(30)
        except subprocess.TimeoutExpired:
            results[what] = float("nan")
        finally:
            run.stop()
            simulator.stop()
            master.stop()
    print(f"(c) killed mid-drive -> the block's error: robot node (kill -9) {results['robot node']:.2f} s, "
          f"master {results['master']:.2f} s (ratio {results['robot node'] / results['master']:.2f}; "
          f"the motion's own timeout is 120 s; aim <= 2 s)")


def main():
    with tempfile.TemporaryDirectory() as folder:
        endless_print(str(Path(folder) / "settings.ini"))
        big_power()
        killed_node(folder)
    failed = 0
    for part in ("_fault_helper.py", "_fault_stall.py", "_fault_memory.py"):
        failed |= subprocess.call([sys.executable, str(REPO / "benchmarks" / part)])
    sys.exit(failed)


if __name__ == "__main__":
    main()
