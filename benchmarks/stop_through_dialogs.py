"""STOP with a modal dialog open, against STOP without one, in the same run (issue 29; decision 032).

A real window (offscreen) runs a program; a click at STOP goes to the window as the window system delivers it
(QTest on its QWindow, where a modal dialog would block it). Timed from the click:
  - on the built-in simulator: until the simulated robot's speed is zero;
  - on HOBBIT over ROS 1 (a real master, the ROS-level simulator in its own process): until an independent
    node (tests/wire_recorder.py, a process of its own) receives the zero Twist on /cmd_vel.
Each kind alternates a trial with a Rockly message box open and one without. Aim: the same, within 10 ms.

    python benchmarks/stop_through_dialogs.py
"""
import os
import statistics
import tempfile
import time
from pathlib import Path

from _paths import REPO  # noqa: F401 - its set-up: Rockly and the tests' helpers importable, Qt offscreen
from program_builder import block, number, workspace

TRIALS = 8  # of each kind, with and without a dialog


def wait_until(predicate, timeout=30.0):
    """Process Qt events until ``predicate()``; the moment it became true (``time.perf_counter``)."""
    from PySide6.QtCore import QCoreApplication

    deadline = time.monotonic() + timeout
    while not predicate():
        if time.monotonic() > deadline:
            raise TimeoutError("the condition never came")
        QCoreApplication.processEvents()
        time.sleep(0.0002)
    return time.perf_counter()


def open_window(settings_path):
    from PySide6.QtCore import QEventLoop

    from rockly_desktop.app import build_main_window

    window = build_main_window(settings_path)
    window.simulator_speed = 1.0
    window.show()
    loop = QEventLoop()
    window.editor.sig_ready.connect(loop.quit)
    window.start()
    loop.exec()
    return window


def load(window, program):
    done = []
    window.editor.call("load", {"workspace": workspace(program)}, lambda _result, _error: done.append(True))
    wait_until(lambda: bool(done))


def click_stop(window):
    from PySide6.QtCore import Qt
    from PySide6.QtTest import QTest

    button = window.run_toolbar.widgetForAction(window.run_toolbar.stop_action)
    QTest.mouseClick(window.windowHandle(), Qt.MouseButton.LeftButton, Qt.KeyboardModifier.NoModifier,
                     button.mapTo(window, button.rect().center()))


def trial(window, under_way, stopped, with_dialog: bool) -> tuple:
    """Seconds from the click at STOP to STOP's action and to ``stopped()``, with a message box open or not."""
    from PySide6.QtWidgets import QMessageBox

    from rockly_desktop.ui.message_boxes import plain_message_box

    assert window.runs.run()
    wait_until(lambda: window.runs.state == "running" and under_way())
    box = None
    if with_dialog:
        box = plain_message_box(window, QMessageBox.Icon.Information, "Rockly", "A message")
        box.open()
        wait_until(box.isVisible)
    triggered = []

    def note():
        triggered.append(time.perf_counter())

    window.run_toolbar.stop_action.triggered.connect(note)
    clicked = time.perf_counter()
    click_stop(window)
    latency = wait_until(stopped, timeout=10) - clicked
    window.run_toolbar.stop_action.triggered.disconnect(note)
    wait_until(lambda: window.runs.state == "idle")
    if box is not None:
        box.reject()
        box.deleteLater()
    return triggered[0] - clicked, latency


def compare(name, window, under_way, stopped, before_each=lambda: None):
    times = {True: [], False: []}
    for _ in range(TRIALS):
        for with_dialog in (False, True):
            before_each()
            times[with_dialog].append(trial(window, under_way, stopped, with_dialog))
    for part, what in ((0, "click -> STOP's action"), (1, "click -> stopped")):
        without = [pair[part] for pair in times[False]]
        within = [pair[part] for pair in times[True]]
        plain, through = statistics.median(without), statistics.median(within)
        print(f"{name}: {what}, median of {TRIALS}: without a dialog {plain * 1000:.2f} ms (max "
              f"{max(without) * 1000:.2f}), with a message box open {through * 1000:.2f} ms (max "
              f"{max(within) * 1000:.2f}); difference {(through - plain) * 1000:+.2f} ms, ratio {through / plain:.2f}",
              flush=True)


def on_the_simulator(window):
    load(window, block("hobbit_move", {"direction": "+"}, {"speed": number(100)}))
    compare("simulator", window, lambda: window.robot().snapshot()["linear"] != 0,
            lambda: window.robot().snapshot()["linear"] == 0,
            before_each=lambda: window.robots.reset())


def on_ros1(window, master):
    import struct

    from wire_recorder import WireRecorder

    from rockly_desktop.robot.links import link_kind
    from rockly_desktop.ui.robot.connection_dialog import ConnectionDialog

    window.settings.remember_link_connection(link_kind("ros1"), "hobbit", {"master": master.uri, "host": "127.0.0.1"})
    ConnectionDialog.exec = lambda dialog: 1  # the connection as remembered
    backend = window.run_toolbar.backend
    backend.setCurrentIndex(backend.findData("ros1"))
    wait_until(lambda: "ROS connected" in window.robots.status.text())
    recorder = WireRecorder(master, ["/cmd_vel", "/DiscreteMotionCmd"])
    try:
        load(window, block("hobbit_turn", {"direction": "+"}, {"angle": number(360000)}))  # no wall in the way
        counts = {}

        def under_way():
            commands = recorder.on("/DiscreteMotionCmd")
            counts["twists"] = len(recorder.on("/cmd_vel"))
            return len(commands) > counts.get("commands", 0) and commands[-1][1][4:].startswith(b"Turn")

        def zero_twist():
            twists = recorder.on("/cmd_vel")
            return len(twists) > counts["twists"] and struct.unpack("<6d", twists[-1][1]) == (0,) * 6

        def before_each():
            counts["commands"] = len(recorder.on("/DiscreteMotionCmd"))

        compare("ROS 1 wire", window, under_way, zero_twist, before_each)
    finally:
        recorder.stop()


def main():
    from PySide6.QtCore import QCoreApplication, QEvent
    from ros_helpers import RocklyProcess, RosMaster, ros_environment

    from rockly_desktop.app import create_application

    with tempfile.TemporaryDirectory() as folder:
        master = RosMaster(Path(folder) / "ros").start()
        os.environ.update(ros_environment(master.uri, master.home))
        hobbit = RocklyProcess(["sim", "hobbit", "--ros", "--no-window", "--master", master.uri, "--speed", "1"],
                               master, ready_line="on ROS")
        create_application()
        window = open_window(Path(folder) / "settings.ini")
        try:
            on_the_simulator(window)
            on_ros1(window, master)
        finally:
            window.runs.shutdown()
            window.document.modified = False
            window.close()
            window.deleteLater()
            QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)  # no page left for exit
            hobbit.stop()
            master.stop()


if __name__ == "__main__":
    main()
