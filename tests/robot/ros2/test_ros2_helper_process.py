"""The ROS 2 helper process's life: its death fails a waiting command at once, its end sends the
safe stop, and no ROS 2 at all says which set-up step is missing."""
import os
import signal
import subprocess
import sys
import threading
from pathlib import Path

import pytest
from waiting import eventually

from rockly_desktop.core.errors import RobotConnectionLost
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.ros2.client import Ros2Helper
from rockly_desktop.robot.ros2.environment import PROJECT_ROOT, Ros2Unavailable
from rockly_desktop.robot.ros2.link import Ros2Robot


@pytest.fixture
def own_helper():
    """A test that ends or kills the helper gets its own (and leaves none behind)."""
    Ros2Helper.close_current()
    yield
    Ros2Helper.close_current()


def test_a_killed_helper_fails_the_waiting_command_at_once(own_helper, test_robot, turtlebot, ros2_settings):
    robot = Ros2Robot(turtlebot, ros2_settings)
    backend = robot.backend(Interrupt())
    errors = []

    def wait():
        try:
            backend.wait_for_message("/nobody_publishes_this", "std_msgs/String", 60)
        except Exception as error:
            errors.append(error)

    waiter = threading.Thread(target=wait)
    waiter.start()
    eventually(lambda: robot.graph._topics)  # subscribed: it is waiting now
    os.kill(robot.helper.process.pid, signal.SIGKILL)
    waiter.join(timeout=10)  # far less than the wait's 60 s: the pipe's end is seen at once
    assert not waiter.is_alive()
    assert isinstance(errors[0], RobotConnectionLost)
    assert "ROS 2 helper process ended" in str(errors[0]) and "-9" in str(errors[0])
    assert "Hilfsprozess" in errors[0].in_language("de")
    with pytest.raises(RobotConnectionLost):
        backend.publish("/cmd_vel", "geometry_msgs/Twist", {})
    assert robot.health()[0].level != "green"  # red while replaced, amber once a new helper took over


def test_a_new_link_after_the_helper_died_starts_a_new_one(own_helper, test_robot, turtlebot, ros2_settings):
    first = Ros2Robot(turtlebot, ros2_settings)
    killed = first.helper
    killed.process.kill()
    eventually(lambda: killed.lost)
    second = Ros2Robot(turtlebot, ros2_settings)
    assert second.helper is not killed
    assert second.backend(Interrupt()).get_param("test_robot:robot_name") == "tb"


def last_forward_speed(test_robot):
    """The linear x of the last /cmd_vel the test robot heard (None before the first)."""
    heard = test_robot.received("/cmd_vel")
    return heard[-1]["message"]["linear"]["x"] if heard else None


@pytest.mark.parametrize("ending", ["SIGTERM", "end of stdin"])
def test_the_helpers_last_act_is_the_safe_stop(own_helper, test_robot, turtlebot, ros2_settings, ending):
    robot = Ros2Robot(turtlebot, ros2_settings)
    robot.backend(Interrupt()).publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.2}})
    eventually(lambda: last_forward_speed(test_robot) == 0.2)
    ended = robot.helper  # the link replaces it once lost: ``robot.helper`` is then the new one
    if ending == "SIGTERM":
        ended.process.send_signal(signal.SIGTERM)
    else:
        ended.process.stdin.close()
    eventually(lambda: ended.lost)
    eventually(lambda: last_forward_speed(test_robot) == 0.0)
    # the link replaces its lost helper (and starts a new spare): wait, so the teardown ends those too
    eventually(lambda: robot.replaced is not None)


def test_without_ros2_the_message_names_the_set_up_step(own_helper, turtlebot, ros2_settings, monkeypatch, tmp_path):
    monkeypatch.setenv("ROCKLY_ROS2_PYTHON", str(tmp_path / "no-venv" / "bin" / "python"))
    with pytest.raises(Ros2Unavailable, match="make ros2") as raised:
        Ros2Robot(turtlebot, ros2_settings)
    assert raised.value.reason == "no_ros2"


def test_a_helper_that_cannot_start_says_why(own_helper, turtlebot, ros2_settings, monkeypatch, tmp_path):
    broken = tmp_path / "python"
    broken.write_text("#!/bin/sh\necho 'no rclpy here' >&2\nexit 3\n")
    broken.chmod(0o755)
    monkeypatch.setenv("ROCKLY_ROS2_PYTHON", str(broken))
    with pytest.raises(Ros2Unavailable, match="no rclpy here") as raised:
        Ros2Robot(turtlebot, ros2_settings)
    assert raised.value.reason == "helper_failed"


PARENT = r'''
import sys
from types import SimpleNamespace
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.ros2.environment import Ros2Settings
from rockly_desktop.robot.ros2.link import Ros2Robot
profile = SimpleNamespace(ros_interface={}, safe_stop=[
    {"publish": {"topic": "/cmd_vel", "type": "geometry_msgs/Twist", "message": {}}}])
robot = Ros2Robot(profile, Ros2Settings(domain_id=int(sys.argv[1]), discovery="localhost"))
robot.backend(Interrupt()).publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.3}})
print(robot.helper.process.pid, flush=True)
sys.stdin.read()
'''


def _running(pid: int) -> bool:
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return False
    return stat[stat.rindex(")") + 2] != "Z"


def test_when_rockly_dies_its_helper_stops_the_robot_and_ends(test_robot, ros2_settings):
    parent = subprocess.Popen([sys.executable, "-c", PARENT, str(ros2_settings.domain_id)], stdin=subprocess.PIPE,
                              stdout=subprocess.PIPE, text=True, cwd=PROJECT_ROOT,
                              env={**os.environ, "PYTHONPATH": str(PROJECT_ROOT)})
    try:
        helper_pid = int(parent.stdout.readline())
        # as the module's first test the robot has heard nothing yet: no last message to read before this one
        eventually(lambda: last_forward_speed(test_robot) == 0.3)
    finally:
        parent.kill()  # no atexit, no close: only the pipe's end tells the helper
        parent.wait()
    eventually(lambda: last_forward_speed(test_robot) == 0.0)
    eventually(lambda: not _running(helper_pid))


def test_a_safe_stop_of_a_type_ros2_lacks_fails_naming_the_package(own_helper, ros2_settings):
    from types import SimpleNamespace

    profile = SimpleNamespace(ros_interface={}, safe_stop=[
        {"publish": {"topic": "/head/move", "type": "hobbit_msgs/HeadMove", "message": {}}},
        {"publish": {"topic": "/cmd_vel", "type": "geometry_msgs/Twist", "message": {}}}])
    robot = Ros2Robot(profile, ros2_settings)
    failures = robot.safe_stop()
    assert len(failures) == 1 and "hobbit_msgs" in failures[0] and "not installed" in failures[0]
    robot.backend(Interrupt()).publish("/cmd_vel", "geometry_msgs/Twist", {})  # nothing left to report later
