"""The window on a robot over ROS 2: a plain rclpy test robot (publishing /odom) on this run's own
domain, chosen in the Run-on box as "Real robot (ROS 2)…" through the connection dialog."""
import os
import signal
import threading

import pytest
from page_tools import call_page
from program_builder import block, number, stack, text, workspace
from waiting import eventually

from rockly_desktop.robot.links import link_kind
from rockly_desktop.ui.robot.connection_dialog import ConnectionDialog
from rockly_desktop.ui.texts import tr

ROS2 = link_kind("ros2")


@pytest.fixture
def ros2_window(qtbot, window, test_robot, ros2_settings, monkeypatch):
    """The window connected to the test robot: the dialog (shown, its fields filled in as a person
    would) is accepted; the ROS 2 helper ends with the window."""
    return connected(window, ros2_settings, monkeypatch)


def connected(window, ros2_settings, monkeypatch):
    """``window`` connected to the test robot through the connection dialog, its fields filled in."""
    asked = []

    def fill_in(dialog):
        asked.append({name: (field.currentData() if hasattr(field, "currentData") else field.text())
                      for name, field in dialog.fields.items()})
        dialog.fields["domain_id"].setText(str(ros2_settings.domain_id))
        dialog.fields["discovery"].setCurrentIndex(dialog.fields["discovery"].findData("localhost"))
        return 1

    monkeypatch.setattr(ConnectionDialog, "exec", fill_in)
    backend = window.run_toolbar.backend
    backend.setCurrentIndex(backend.findData("ros2"))
    assert window.robots.kind == "ros2" and len(asked) == 1
    assert list(asked[0]) == ["domain_id", "discovery", "peers", "ros_distribution"]
    window.asked = asked
    return window


def test_the_run_on_box_offers_ros2_in_the_windows_language(qtbot, window):
    backend = window.run_toolbar.backend
    assert backend.itemText(backend.findData("ros2")) == tr("backend_ros2", "en") == "Real robot (ROS 2)…"


def test_choosing_ros2_connects_shows_the_domain_and_remembers_the_settings(qtbot, ros2_window, ros2_settings):
    where = f"domain {ros2_settings.domain_id}, localhost"
    qtbot.waitUntil(lambda: "ROS connected" in ros2_window.robots.status.text(), timeout=5000)
    assert where in ros2_window.robots.status.text() and ros2_window.robots.status.isVisible()
    assert ros2_window.settings.link_connection(ROS2, "hobbit") == {
        "domain_id": str(ros2_settings.domain_id), "discovery": "localhost", "peers": None,
        "ros_distribution": "auto"}
    health = ros2_window.health
    qtbot.waitUntil(lambda: where in health.toolTip(), timeout=10000)
    assert "ROS 2" in health.toolTip()


def test_a_german_window_says_the_domain_in_german(qtbot, german_window, test_robot, ros2_settings, monkeypatch):
    window = connected(german_window, ros2_settings, monkeypatch)
    where = f"Domäne {ros2_settings.domain_id}, localhost"
    qtbot.waitUntil(lambda: where in window.robots.status.text(), timeout=5000)
    assert "domain" not in window.robots.status.text()
    qtbot.waitUntil(lambda: where in window.health.toolTip(), timeout=10000)


def test_the_topic_monitor_lists_the_ros2_graph(qtbot, ros2_window):
    monitor = ros2_window.monitor_dock.widget()
    qtbot.waitUntil(lambda: monitor.refresh() or monitor.table_model.row_of("/odom") is not None, timeout=20000)
    row = monitor.table_model.row_of("/odom")
    cells = [monitor.table_model.index(row, column).data() for column in range(monitor.table_model.columnCount())]
    assert cells[1] == "nav_msgs/Odometry" and cells[2] == "1"


def test_stop_publishes_the_profiles_safe_stop_over_ros2(qtbot, ros2_window, test_robot):
    call_page(qtbot, ros2_window.editor, "load", {"workspace": workspace(
        block("ros_wait", inputs={"seconds": number(60)}, id="wait"))})
    before = len(test_robot.received("/cmd_vel"))
    ros2_window.runs.run()
    qtbot.waitUntil(lambda: ros2_window.runs.state == "running", timeout=10000)
    with qtbot.waitSignal(ros2_window.runs.sig_finished, timeout=10000) as blocker:
        ros2_window.run_toolbar.stop_action.trigger()
    assert blocker.args[0].outcome == "stopped"
    eventually(lambda: len(test_robot.received("/cmd_vel")) > before, timeout=10)
    stop = test_robot.received("/cmd_vel")[-1]
    assert stop["type"] == "Twist" and stop["message"]["linear"] == {"x": 0.0, "y": 0.0, "z": 0.0}


def test_closing_the_window_ends_the_ros2_helper(qtbot, driver, ros2_window):
    helper = ros2_window.robot().helper.process
    assert helper.poll() is None
    ros2_window.close()
    eventually(lambda: helper.poll() is not None, timeout=10)  # and leak_check finds no process left


def test_choosing_ros2_without_its_environment_names_make_ros2_and_asks_nothing(qtbot, window, monkeypatch, tmp_path):
    from PySide6.QtWidgets import QMessageBox

    monkeypatch.setenv("ROCKLY_ROS2_PYTHON", str(tmp_path / "no-ros2" / "bin" / "python"))
    asked, shown = [], []
    monkeypatch.setattr(ConnectionDialog, "exec", lambda dialog: asked.append(dialog) or 1)
    monkeypatch.setattr(QMessageBox, "exec", lambda box: shown.append((box.text(), box.informativeText())))
    backend = window.run_toolbar.backend
    backend.setCurrentIndex(backend.findData("ros2"))
    assert not asked and window.robots.kind == "sim" and backend.currentData() == "sim"
    assert shown == [("ROS 2 is not set up on this computer, so Rockly cannot reach a robot over ROS 2.",
                      "Use the built-in simulator, or ask an adult to set up ROS 2: “make ros2” in Rockly's "
                      "folder installs it.")]


def test_a_bad_domain_id_is_refused_in_the_windows_words_and_the_simulator_stays(qtbot, window, monkeypatch):
    from PySide6.QtWidgets import QMessageBox

    def fill_in(dialog):
        dialog.fields["domain_id"].setText("300")
        return 1

    shown = []
    monkeypatch.setattr(ConnectionDialog, "exec", fill_in)
    monkeypatch.setattr(QMessageBox, "exec", lambda box: shown.append((box.text(), box.informativeText())))
    backend = window.run_toolbar.backend
    backend.setCurrentIndex(backend.findData("ros2"))
    assert window.robots.kind == "sim" and backend.currentData() == "sim"
    assert shown == [("“300” is not a ROS 2 domain id.",
                      "A domain id is a whole number from 0 to 232; ask the robot's owner for it.")]


def speed_on_the_wire(test_robot):
    received = test_robot.received("/cmd_vel")
    return received[-1]["message"]["linear"]["x"] if received else None


def test_a_hung_helper_never_stalls_the_window_and_a_new_one_stops_the_robot(qtbot, ros2_window, test_robot):
    call_page(qtbot, ros2_window.editor, "load", {"workspace": workspace(stack(
        block("ros_publish_message", {"message_type": "geometry_msgs/Twist"},
              {"topic": text("/cmd_vel"), "field:linear.x": number(0.2)}, id="drive"),
        block("ros_wait", inputs={"seconds": number(60)}, id="wait")))})
    ros2_window.runs.run()
    qtbot.waitUntil(lambda: speed_on_the_wire(test_robot) == 0.2, timeout=10000)
    helper = ros2_window.robot().helper
    asked_from_the_window = []
    write = helper._write

    def watched_write(frame):  # every request to the helper goes out here
        if threading.current_thread() is threading.main_thread():
            asked_from_the_window.append(frame)
        write(frame)

    helper._write = watched_write
    os.kill(helper.process.pid, signal.SIGSTOP)
    try:
        # the window's thread never waits on a hung helper (the health light once asked it, 2 s a look)
        looks = []
        ros2_window.health.sig_refreshed.connect(lambda robot, items: looks.append(items))
        qtbot.waitUntil(lambda: len(looks) >= 4, timeout=20000)
        assert asked_from_the_window == []
        qtbot.waitUntil(lambda: speed_on_the_wire(test_robot) == 0.0, timeout=10000)
        qtbot.waitUntil(lambda: ros2_window.runs.state == "idle", timeout=10000)
        assert ros2_window.runs.last_result.outcome == "error"
        assert "stopped answering" in ros2_window.runs.last_result.message or "said nothing" in \
            ros2_window.runs.last_result.message
        qtbot.waitUntil(lambda: "helper was replaced" in ros2_window.health.toolTip(), timeout=5000)
        assert ros2_window.health.items[0].level == "amber" and "ROS connected" in ros2_window.robots.status.text()
    finally:
        if helper.process.poll() is None:  # never left stopped
            os.kill(helper.process.pid, signal.SIGCONT)
            helper.process.kill()
            helper.process.wait()

    ros2_window.runs.run()  # no reconnect
    qtbot.waitUntil(lambda: ros2_window.runs.state == "running", timeout=10000)
    qtbot.waitUntil(lambda: speed_on_the_wire(test_robot) == 0.2, timeout=10000)
    with qtbot.waitSignal(ros2_window.runs.sig_finished, timeout=10000) as blocker:
        ros2_window.run_toolbar.stop_action.trigger()
    assert blocker.args[0].outcome == "stopped"
    qtbot.waitUntil(lambda: speed_on_the_wire(test_robot) == 0.0, timeout=10000)
