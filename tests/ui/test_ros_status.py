"""ROS status that agrees with itself: the status bar says what the health light sees, a robot switch
keeps the connection the person chose, and the Topic monitor counts Rockly's own publishers.

Against a plain rclpy test robot (tests/ros2_fixtures.py) in its own process on this run's own domain,
and a real ROS master with the ROS-level HOBBIT simulator for ROS 1."""
import pytest
import ros2_fixtures
from page_tools import call_page
from program_builder import block, number, stack, workspace
from screenshots import screenshot

from rockly_desktop.robot.links import link_kind
from rockly_desktop.ui.robot.connection_dialog import ConnectionDialog
from rockly_desktop.ui.robot.health_bar import COLOURS
from rockly_desktop.ui.texts import tr

ROS1, ROS2 = link_kind("ros1"), link_kind("ros2")


@pytest.fixture
def vanishing_robot(ros2_settings):
    """A test robot of this test's own, which the test may end."""
    robot = ros2_fixtures.TestRobot(ros2_settings)
    yield robot
    if robot.process.poll() is None:
        robot.stop()


def choose_ros2(window, domain_id, discovery="localhost"):
    """Choose "Real robot (ROS 2)…" in the Run-on box, giving ``domain_id`` and ``discovery`` in its dialog;
    returns the settings the dialog offered."""
    offered = []

    def fill_in(dialog):
        offered.append({name: (field.currentData() if hasattr(field, "currentData") else field.text())
                        for name, field in dialog.fields.items()})
        dialog.fields["domain_id"].setText(str(domain_id))
        dialog.fields["discovery"].setCurrentIndex(dialog.fields["discovery"].findData(discovery))
        return 1

    original = ConnectionDialog.exec
    ConnectionDialog.exec = fill_in
    try:
        backend = window.run_toolbar.backend
        backend.setCurrentIndex(backend.findData("ros2"))
    finally:
        ConnectionDialog.exec = original
    assert window.robots.kind == "ros2"
    return offered


def status_colour(window) -> str:
    return window.robots.status.styleSheet().split("color:")[1].split(";")[0].strip()


def test_after_the_robot_vanishes_the_status_bar_and_the_health_light_say_the_same(
        qtbot, window, vanishing_robot, ros2_settings):
    choose_ros2(window, ros2_settings.domain_id)
    status, health = window.robots.status, window.health
    qtbot.waitUntil(lambda: "/odom" in health.toolTip() and tr("ros_partly", "en") in status.text(), timeout=20000)
    assert status_colour(window) == COLOURS[health.level]  # HOBBIT's other parts are not on the test robot
    vanishing_robot.stop()
    qtbot.waitUntil(lambda: tr("ros_silent", "en") in status.text(), timeout=20000)
    qtbot.waitUntil(lambda: health.level == "red" and status_colour(window) == COLOURS["red"], timeout=20000)
    assert health.text().endswith(tr("health_red", "en"))
    assert f"domain {ros2_settings.domain_id}" in status.text()
    screenshot(window.statusBar(), "status_after_the_robot_vanished")


def test_a_robot_switch_on_ros2_keeps_the_domain_and_discovery_the_person_chose(
        qtbot, window, vanishing_robot, ros2_settings):
    from rockly_desktop.robot.ros2.environment import Ros2Settings

    choose_ros2(window, ros2_settings.domain_id)
    helper = window.robot().helper
    window.choose_profile("turtlebot")
    qtbot.waitUntil(lambda: window.profile.id == "turtlebot", timeout=15000)
    robot = window.robot()
    assert robot.profile.id == "turtlebot" and window.robots.kind == "ros2"
    assert robot.settings == Ros2Settings(domain_id=ros2_settings.domain_id, discovery="localhost")
    assert robot.helper is helper and not helper.lost  # the same graph, not domain 0 on the subnet
    assert window.settings.link_connection(ROS2, "turtlebot")["domain_id"] == str(ros2_settings.domain_id)
    qtbot.waitUntil(lambda: f"domain {ros2_settings.domain_id}, localhost" in window.robots.status.text(),
                    timeout=10000)
    qtbot.waitUntil(lambda: "/odom" in window.health.toolTip() and window.robots.status.isVisible(), timeout=20000)


def publishers_cell(monitor, topic: str):
    """The Publishers cell of ``topic``'s row in the Topic monitor (after it looked at the graph), or None."""
    monitor.refresh()
    model = monitor.table_model
    row = model.row_of(topic)
    return None if row < 0 else model.index(row, 2).data()


def drive_and_look_at_the_monitor(qtbot, window, name: str):
    """Run a program driving HOBBIT far; while it drives, the Topic monitor counts Rockly's /cmd_vel
    publisher as Rockly's. Then stop it."""
    window.monitor_dock.raise_()
    call_page(qtbot, window.editor, "load", {"workspace": workspace(stack(
        block("hobbit_move", {"direction": "+"}, {"speed": number(500)}),
        block("ros_wait", inputs={"seconds": number(60)})))})
    window.runs.run()
    qtbot.waitUntil(lambda: window.runs.state == "running", timeout=15000)
    monitor = window.monitor_dock.widget()
    qtbot.waitUntil(lambda: publishers_cell(monitor, "/cmd_vel") == "1 (Rockly)", timeout=20000)
    assert window.runs.state == "running"
    row = monitor.table_model.row_of("/cmd_vel")
    assert monitor.table_model.index(row, 1).data() == "geometry_msgs/Twist"
    screenshot(window.monitor_dock, name)
    with qtbot.waitSignal(window.runs.sig_finished, timeout=15000):
        window.run_toolbar.stop_action.trigger()


def test_the_topic_monitor_counts_rocklys_publisher_on_cmd_vel_while_a_program_drives_over_ros2(
        qtbot, window, vanishing_robot, ros2_settings):
    choose_ros2(window, ros2_settings.domain_id)
    window.robot().follow_graph()
    drive_and_look_at_the_monitor(qtbot, window, "topic_monitor_cmd_vel_ros2")
    # the test robot heard Rockly on /cmd_vel (the safe stop's zero comes over the wire after the run ends)
    qtbot.waitUntil(lambda: bool(vanishing_robot.received("/cmd_vel")), timeout=10000)
    monitor = window.monitor_dock.widget()
    qtbot.waitUntil(lambda: publishers_cell(monitor, "/odom") == "1", timeout=10000)  # the robot's own: a count


def test_the_topic_monitor_counts_rocklys_publisher_on_cmd_vel_while_a_program_drives_over_ros1(
        qtbot, window, ros_master, hobbit_on_ros, monkeypatch):
    window.settings.remember_link_connection(ROS1, "hobbit", {"master": ros_master.uri, "host": "127.0.0.1"})
    monkeypatch.setattr(ConnectionDialog, "exec", lambda dialog: 1)
    backend = window.run_toolbar.backend
    backend.setCurrentIndex(backend.findData("ros1"))
    assert window.robots.kind == "ros1"
    drive_and_look_at_the_monitor(qtbot, window, "topic_monitor_cmd_vel_ros1")
