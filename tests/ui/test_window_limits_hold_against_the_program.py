"""The teacher's limits hold in the window's own runs against any code the program runs (issue 30, decision 041):
the program's code runs in a process of its own, and the window's thread serves it on the robot link under the
limits. A program that walks Python's object graph (``gc.get_objects()``, every thread's frames, closures,
``robot._backend._inner...``) for the link, the backends and the Limits, lifts every Limits it finds and publishes
0.5 m/s through each, drives no faster than the teacher's 0.2 m/s: the simulator's own state and, over ROS 1, an
independent rospy node on the wire see so. Killing the program's process (SIGKILL) or closing the window mid-drive
ends in the safe stop.
"""
import os
import signal
import struct

import pytest
from PySide6.QtCore import QTimer

from rockly_desktop.robot.links import link_kind
from rockly_desktop.settings.app_settings import AppSettings
from rockly_desktop.ui.robot.connection_dialog import ConnectionDialog

HOSTILE = """import gc, sys
found = []
def consider(thing):
    try:
        kind = type(thing).__name__
    except Exception:
        return
    if kind.endswith('Backend') or kind.endswith('Link') or kind in ('Limits', 'HostConnection', 'LinkHost'):
        found.append(thing)
for thing in gc.get_objects():
    consider(thing)
    closure = getattr(thing, '__closure__', None) if type(thing).__name__ == 'function' else None
    for cell in closure or ():
        try:
            consider(cell.cell_contents)
        except ValueError:
            pass
for frame in list(sys._current_frames().values()):
    while frame is not None:
        for value in list(frame.f_locals.values()) + list(frame.f_globals.values()):
            consider(value)
        frame = frame.f_back
found.append(robot._backend)
inner = robot._backend
while getattr(inner, '_inner', None) is not None:
    inner = inner._inner
    found.append(inner)
for thing in found:
    if type(thing).__name__ == 'Limits':
        object.__setattr__(thing, 'max_speed', None)
        object.__setattr__(thing, 'max_turn', None)
    for name in ('limits', '_limits'):
        try:
            object.__setattr__(thing, name, None)
        except Exception:
            pass
fast = {'linear': {'x': 0.5}}  # within what HOBBIT can, beyond the teacher's limit
for thing in found:
    try:
        if type(thing).__name__ == 'HostConnection':
            thing.send({'op': 'limits', 'max_speed': 10})
            thing.call('publish', ['/cmd_vel', 'geometry_msgs/Twist', fast])
        elif type(thing).__name__.endswith('Link'):
            thing.backend(robot._backend.interrupt).publish('/cmd_vel', 'geometry_msgs/Twist', fast)
        else:
            thing.publish('/cmd_vel', 'geometry_msgs/Twist', fast)
    except Exception:
        pass
print('found: ' + ' '.join(sorted(set(type(thing).__name__ for thing in found))))
ros.wait(0.5)
"""

DRIVE_ON = ("while True:\n"
            "    ros.publish_message('/cmd_vel', 'geometry_msgs/Twist', {'linear': {'x': 0.1}})\n"
            "    ros.wait(0.05)\n")


def limited_window(driver, max_speed=0.2):
    """A window whose teacher keeps HOBBIT at ``max_speed`` m/s."""
    AppSettings(driver.settings_path).teacher.set_limits("hobbit", max_speed=max_speed)
    return driver.open_window()


def page_answers(window, monkeypatch, code: str):
    """The page hands ``code`` as the program's run code (as a hand-made or future Python block would)."""
    real = window.editor.call

    def call(name, args=None, callback=None, timeout_ms=None):
        if name == "getRunCode":
            QTimer.singleShot(0, lambda: callback({"code": code, "variables": {}, "breakpoints": []}, None))
            return None
        return real(name, args, callback, timeout_ms)
    monkeypatch.setattr(window.editor, "call", call)


def run_watching(qtbot, window, speed) -> tuple:
    """Run the window's program to its end, reading ``speed()`` every few milliseconds meanwhile: (the fastest seen,
    how the run ended, what it printed)."""
    fastest = [0.0]

    def look():
        fastest[0] = max(fastest[0], abs(speed()))
    watch = QTimer()
    watch.setInterval(5)
    watch.timeout.connect(look)
    watch.start()
    try:
        with qtbot.waitSignal(window.runs.sig_finished, timeout=60000) as blocker:
            assert window.runs.run()
    finally:
        watch.stop()
    look()
    return fastest[0], blocker.args[0], "\n".join(window.console.lines())


def test_a_program_walking_the_object_graph_drives_the_simulator_no_faster_than_the_limit(qtbot, driver,
                                                                                          monkeypatch):
    window = limited_window(driver)
    page_answers(window, monkeypatch, HOSTILE)
    fastest, result, printed = run_watching(qtbot, window, lambda: window.robot().snapshot()["linear"])
    assert result.outcome == "finished", result
    assert 0 < fastest <= 0.2 + 1e-6, fastest  # it drove, held to the teacher's limit
    assert "found: " in printed, printed  # it walked the graph, and found ...
    found = printed.split("found: ", 1)[1].splitlines()[0].split()
    assert "Limits" not in found and "LimitedBackend" not in found and "LinkHost" not in found, found  # ... no limit


def test_killing_the_programs_process_mid_drive_stops_the_simulated_robot(qtbot, driver, monkeypatch):
    window = driver.open_window()
    page_answers(window, monkeypatch, DRIVE_ON)
    with qtbot.waitSignal(window.runs.sig_finished, timeout=60000) as blocker:
        assert window.runs.run()
        qtbot.waitUntil(lambda: window.robot().snapshot()["linear"] > 0, timeout=30000)
        os.kill(window.runs.thread.runner.host.process.process.pid, signal.SIGKILL)
    result = blocker.args[0]
    assert result.outcome == "error", result
    snapshot = window.robot().snapshot()
    assert snapshot["linear"] == 0 and snapshot["angular"] == 0


def test_closing_the_window_mid_drive_stops_the_robot_and_ends_the_programs_process(qtbot, driver, monkeypatch):
    window = driver.open_window()
    page_answers(window, monkeypatch, DRIVE_ON)
    robot = window.robot()
    twists = []
    robot.world.subscribe("/cmd_vel", lambda message: twists.append((message.get("linear") or {}).get("x", 0.0)))
    assert window.runs.run()
    qtbot.waitUntil(lambda: window.robot().snapshot()["linear"] > 0, timeout=30000)
    program = window.runs.thread.runner.host.process.process
    seen = len(twists)
    window.document.modified = False
    window.close()
    assert window.runs.thread is None
    assert 0.0 in twists[seen:]  # the safe stop's zero, before the window let go of the robot
    assert program.poll() is not None  # the program's process ended (and was waited for)


@pytest.fixture
def ros_window(driver, ros_master, hobbit_on_ros, monkeypatch):
    ros1 = link_kind("ros1")
    window = limited_window(driver)
    window.settings.remember_link_connection(ros1, "hobbit", {"master": ros_master.uri, "host": "127.0.0.1"})
    monkeypatch.setattr(ConnectionDialog, "exec", lambda dialog: 1)
    backend = window.run_toolbar.backend
    backend.setCurrentIndex(backend.findData("ros1"))
    assert window.robots.kind == "ros1"
    return window


def twists(wire) -> list:
    """``(linear.x, angular.z)`` of every Twist seen on /cmd_vel."""
    return [(twist[0], twist[5]) for twist in (struct.unpack("<6d", raw) for _type, raw in wire.on("/cmd_vel"))]


def test_over_ros1_an_independent_node_sees_no_more_than_the_limit_on_the_wire(qtbot, ros_window, ros_master,
                                                                              monkeypatch):
    from waiting import eventually
    from wire_recorder import WireRecorder

    wire = WireRecorder(ros_master, ["/cmd_vel"])
    try:
        page_answers(ros_window, monkeypatch, HOSTILE)
        with qtbot.waitSignal(ros_window.runs.sig_finished, timeout=60000) as blocker:
            assert ros_window.runs.run()
        assert blocker.args[0].outcome == "finished", blocker.args[0]
        eventually(lambda: any(linear == 0 for linear, _ in twists(wire)), 30)  # the safe stop's zero, at least
        speeds = twists(wire)
        assert all(abs(linear) <= 0.2 + 1e-9 for linear, _ in speeds), speeds
        assert any(linear > 0 for linear, _ in speeds), speeds  # it drove, held to the limit
    finally:
        wire.stop()


def test_over_ros2_an_independent_node_sees_no_more_than_the_limit_on_the_wire(qtbot, driver, test_robot,
                                                                              ros2_settings, monkeypatch):
    from waiting import eventually

    window = limited_window(driver)

    def fill_in(dialog):  # as a person fills in the connection dialog
        dialog.fields["domain_id"].setText(str(ros2_settings.domain_id))
        dialog.fields["discovery"].setCurrentIndex(dialog.fields["discovery"].findData("localhost"))
        return 1
    monkeypatch.setattr(ConnectionDialog, "exec", fill_in)
    backend = window.run_toolbar.backend
    backend.setCurrentIndex(backend.findData("ros2"))
    assert window.robots.kind == "ros2"
    heard_before = len(test_robot.received("/cmd_vel"))
    page_answers(window, monkeypatch, HOSTILE)
    with qtbot.waitSignal(window.runs.sig_finished, timeout=60000) as blocker:
        assert window.runs.run()
    assert blocker.args[0].outcome == "finished", blocker.args[0]

    def speeds():  # what the plain rclpy node heard on /cmd_vel during this run
        return [line["message"]["linear"]["x"] for line in test_robot.received("/cmd_vel")[heard_before:]]
    eventually(lambda: 0.0 in speeds(), 30)  # the safe stop's zero, at least
    assert all(abs(speed) <= 0.2 + 1e-9 for speed in speeds()), speeds()
    assert any(speed > 0 for speed in speeds()), speeds()  # it drove, held to the limit
