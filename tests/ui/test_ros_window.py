"""The window on a robot over ROS 1 (the ROS-level simulator in its own process, a real master)."""
import sys

import pytest
from page_tools import call_page
from program_builder import block, number, stack, workspace
from ros_helpers import feed_hears

from rockly_desktop.robot.links import link_kind
from rockly_desktop.ui.robot.connection_dialog import ConnectionDialog

ROS1 = link_kind("ros1")


@pytest.fixture
def ros_window(window, ros_master, hobbit_on_ros, monkeypatch):
    window.settings.remember_link_connection(ROS1, "hobbit", {"master": ros_master.uri, "host": "127.0.0.1"})
    monkeypatch.setattr(ConnectionDialog, "exec", lambda dialog: 1)
    backend = window.run_toolbar.backend
    backend.setCurrentIndex(backend.findData("ros1"))
    assert window.robots.kind == "ros1"
    return window


def test_choosing_ros_connects_and_shows_the_status(qtbot, ros_window):
    qtbot.waitUntil(lambda: "ROS connected" in ros_window.robots.status.text(), timeout=5000)
    assert ros_window.robots.status.isVisible()
    assert "real robot" in ros_window.simulator_dock.widget().text()


def test_a_program_runs_on_the_robot_over_ros(qtbot, ros_window):
    # A turn, not a drive: the session's ROS-level HOBBIT is wherever earlier tests left it (CI saw a drive
    # bump into a wall), and the round robot turning on the spot touches nothing new.
    call_page(qtbot, ros_window.editor, "load", {"workspace": workspace(stack(
        block("hobbit_emo", {"emotion": "HAPPY"}), block("hobbit_turn", {"direction": "+"}, {"angle": number(90)}),
        block("hobbit_arm_gripper", {"movement": "OpenGripper"})))})
    with qtbot.waitSignal(ros_window.runs.sig_finished, timeout=30000) as blocker:
        ros_window.runs.run()
    assert blocker.args[0].outcome == "finished", blocker.args[0]


def test_an_unreachable_master_is_refused_and_the_simulator_stays(qtbot, window, monkeypatch):
    from PySide6.QtWidgets import QMessageBox

    window.settings.remember_link_connection(ROS1, "hobbit", {"master": "http://127.0.0.1:9"})
    monkeypatch.setattr(ConnectionDialog, "exec", lambda dialog: 1)
    warnings = []
    monkeypatch.setattr(QMessageBox, "exec", lambda box: warnings.append(box.text()))
    backend = window.run_toolbar.backend
    backend.setCurrentIndex(backend.findData("ros1"))
    # Either nothing answers there, or this process's one ROS node already uses the session's master.
    assert warnings and "http://127.0.0.1:9" in warnings[0]
    assert window.robots.kind == "sim" and backend.currentData() == "sim"


def test_choosing_ros_without_rospy_names_the_set_up_step_and_asks_nothing(qtbot, window, monkeypatch):
    from PySide6.QtWidgets import QMessageBox

    monkeypatch.setitem(sys.modules, "rospy", None)  # as on a computer without ROS 1
    asked, shown = [], []
    monkeypatch.setattr(ConnectionDialog, "exec", lambda dialog: asked.append(dialog) or 1)
    monkeypatch.setattr(QMessageBox, "exec", lambda box: shown.append((box.text(), box.informativeText())))
    backend = window.run_toolbar.backend
    backend.setCurrentIndex(backend.findData("ros1"))
    assert not asked and window.robots.kind == "sim" and backend.currentData() == "sim"
    assert shown == [("ROS 1 is not installed on this computer, so Rockly cannot reach a real robot.",
                      "Use the built-in simulator, or ask an adult to set up ROS 1: "
                      "“make setup” in Rockly's folder installs it (rospy).")]


def test_the_status_shows_a_lost_master_and_its_return(qtbot, ros_window, ros_master):
    qtbot.waitUntil(lambda: "ROS connected" in ros_window.robots.status.text(), timeout=5000)
    ros_master.stop()
    try:
        qtbot.waitUntil(lambda: "lost" in ros_window.robots.status.text(), timeout=3000)
        assert "#c62828" in ros_window.robots.status.styleSheet()
    finally:
        ros_master.start()
    qtbot.waitUntil(lambda: "ROS connected" in ros_window.robots.status.text(), timeout=5000)
    call_page(qtbot, ros_window.editor, "load", {"workspace": workspace(block("hobbit_emo", {"emotion": "SAD"}))})
    with qtbot.waitSignal(ros_window.runs.sig_finished, timeout=30000) as blocker:
        ros_window.runs.run()
    assert blocker.args[0].outcome == "finished", blocker.args[0]


def test_health_turns_red_within_2_s_when_the_master_dies_and_green_when_it_returns(qtbot, ros_window, ros_master):
    import time

    health = ros_window.health
    qtbot.waitUntil(lambda: health.level == "green", timeout=8000)
    assert "/odom" in health.toolTip() and "/MMUI" in health.toolTip() and "hobbit_arm" in health.toolTip()
    ros_master.stop()
    killed = time.monotonic()
    try:
        qtbot.waitUntil(lambda: health.level == "red", timeout=3000)
        assert time.monotonic() - killed < 2.0
    finally:
        ros_master.start()
    qtbot.waitUntil(lambda: health.level == "green", timeout=10000)


def test_state_panels_and_topic_monitor_show_the_ros_robot(qtbot, ros_window):
    feed_hears(ros_window.robot(), {"/head/emo": "std_msgs/String", "/head/move": "std_msgs/String",
                                    "/hobbit_arm/goal": "hobbit_msgs/ArmServerActionGoal",
                                    "/hobbit_arm/result": "hobbit_msgs/ArmServerActionResult"})
    call_page(qtbot, ros_window.editor, "load", {"workspace": workspace(stack(
        block("hobbit_emo", {"emotion": "WONDERING"}), block("hobbit_head", {"head_position": "up_right"}),
        block("hobbit_arm_move", {"movement": "MoveToTray"})))})
    with qtbot.waitSignal(ros_window.runs.sig_finished, timeout=30000) as blocker:
        ros_window.runs.run()
    assert blocker.args[0].outcome == "finished"
    panels = ros_window.state_dock.widget()
    qtbot.waitUntil(lambda: panels.values()["Emotion"] == "wondering" and panels.values()["Looking"] == "up right"
                    and panels.values()["Last command"] == "to the tray" and panels.values()["Command state"] == "done",
                    timeout=5000)
    assert panels.values()["Charge"].endswith("%") and panels.values()["Position x"].endswith(" m")
    monitor = ros_window.monitor_dock.widget()
    qtbot.waitUntil(lambda: monitor.refresh() or monitor.table_model.row_of("/odom") is not None, timeout=5000)
    row = monitor.table_model.row_of("/odom")
    cells = [monitor.table_model.index(row, column).data() for column in range(monitor.table_model.columnCount())]
    assert cells[1] == "nav_msgs/Odometry" and cells[2] == "1"
    assert float(cells[3]) > 0  # the rate arithmetic is checked with a fake clock in tests/core


@pytest.mark.parametrize("language", ["en", "de"])
def test_the_connection_dialog_shows_whole_addresses(qtbot, language):
    dialog = ConnectionDialog(language, "HOBBIT", ROS1, {"master": "http://192.168.100.100:11311"})
    qtbot.addWidget(dialog)
    dialog.show()
    assert list(dialog.fields) == ["master", "host"]
    for edit in dialog.fields.values():
        shown = max(edit.text(), edit.placeholderText(), key=len)
        assert edit.width() > edit.fontMetrics().horizontalAdvance(shown)


def test_the_connection_dialog_asks_for_each_setting_of_a_link_and_they_are_remembered(qtbot, tmp_path, monkeypatch):
    from dataclasses import replace

    from rockly_desktop.robot.links import ConnectionSetting
    from rockly_desktop.settings.app_settings import AppSettings

    monkeypatch.setenv("ROCKLY_TEST_DOMAIN", "7")
    other = replace(ROS1, kind="other", settings_group="other", settings=(
        ConnectionSetting("domain", "connect_master", ("ROCKLY_TEST_DOMAIN",), "0"),
        ConnectionSetting("range", "connect_host", default="SUBNET",
                          choices=(("LOCALHOST", "backend_simulator"), ("SUBNET", "backend_ros1")))))
    dialog = ConnectionDialog("de", "HOBBIT", other, {"range": "LOCALHOST"})
    qtbot.addWidget(dialog)
    assert dialog.values == {"domain": "7", "range": "LOCALHOST"}
    assert dialog.fields["range"].currentText() == "Simulator (eingebaut)"
    dialog.fields["domain"].setText(" 42 ")
    dialog.fields["range"].setCurrentIndex(1)
    settings = AppSettings(tmp_path / "settings.ini")
    settings.remember_link_connection(other, "hobbit", dialog.values)
    assert settings.link_connection(other, "hobbit") == {"domain": "42", "range": "SUBNET"}
    assert settings.link_connection(ROS1, "hobbit") == {"master": None, "host": None}
