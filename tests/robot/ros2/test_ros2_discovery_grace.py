"""A fresh ROS 2 helper's first seconds are discovery (``wire.DISCOVERY_SECONDS``): a program's wait for a topic's
first message does not count them, so a robot's publisher discovered late on a busy machine is still heard (the
TurtleBot's first drive waits 3 s for /odom; on a loaded machine its first odometry took 3.1 s). The words still
name the program's own time."""
import subprocess
import time

import pytest
from ros2_fixtures import ROS2_PYTHON

from rockly_desktop.core.errors import RobotTimeout
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.ros2.backend import Ros2Backend, Ros2Graph
from rockly_desktop.robot.ros2.client import Ros2Helper

LATE_PUBLISHER = r'''
import rclpy
from std_msgs.msg import String
rclpy.init()
node = rclpy.create_node("late_publisher")
news = node.create_publisher(String, "/rockly_late_news", 10)
node.create_timer(0.1, lambda: news.publish(String(data="late but here")))
rclpy.spin(node)
'''


@pytest.fixture
def fresh_helper(ros2_settings):
    """A ROS 2 helper of the test's own, just said hello."""
    helper = Ros2Helper(ros2_settings)
    yield helper
    helper.close()


def test_a_publisher_discovered_after_the_helper_started_is_heard(fresh_helper, ros2_settings):
    backend = Ros2Backend(Ros2Graph(fresh_helper), Interrupt())
    publisher = subprocess.Popen([str(ROS2_PYTHON), "-c", LATE_PUBLISHER], env=ros2_settings.environment(),
                                 stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        # the publisher's own start (rclpy's import alone) and its discovery take longer than half a second
        message = backend.wait_for_message("/rockly_late_news", "std_msgs/String", 0.5)
    finally:
        publisher.terminate()
        publisher.wait(30)
    assert message["data"] == "late but here"


def test_a_timeout_names_the_programs_own_time_after_the_discovery(fresh_helper):
    backend = Ros2Backend(Ros2Graph(fresh_helper), Interrupt())
    left, began = fresh_helper.discovery_left(), time.monotonic()
    with pytest.raises(RobotTimeout, match="within 0.2 s"):
        backend.wait_for_message("/nobody_publishes_this", "std_msgs/String", 0.2)
    assert time.monotonic() - began >= left + 0.2
    assert fresh_helper.discovery_left() == 0.0
