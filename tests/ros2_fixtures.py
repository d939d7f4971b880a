"""Fixtures for the ROS 2 tests (a plugin conftest.py loads, as ``ros_fixtures`` for ROS 1): a plain
rclpy test robot in its own process, on a domain of this test run's own, localhost only, and
Rockly's ROS 2 link to it."""
import contextlib
import os
from pathlib import Path

import pytest
from json_line_node import JsonLineNode

from rockly_desktop.robot.ros2.environment import PROJECT_ROOT, Ros2Settings

ROS2_PYTHON = PROJECT_ROOT / ".venv-ros2" / "bin" / "python"
# The test robot may run another ROS 2 distribution (a Python with its rclpy), to check the wire
# between them: ROCKLY_TEST_ROBOT_PYTHON=/path/to/jazzy-venv/bin/python
TEST_ROBOT_PYTHON = os.environ.get("ROCKLY_TEST_ROBOT_PYTHON") or str(ROS2_PYTHON)
TEST_NODE = Path(__file__).parent / "robot" / "ros2" / "ros2_test_node.py"
DOMAIN_ID = 100 + os.getpid() % 100  # this run's own: parallel runs on one machine do not meet


@contextlib.contextmanager
def requests_to(helper):
    """The names of the requests Rockly sends ``helper`` (``call``) while the block runs, as a list."""
    asked = []
    call = helper.call
    helper.call = lambda op, *args, **options: asked.append(op) or call(op, *args, **options)
    try:
        yield asked
    finally:
        del helper.call


@contextlib.contextmanager
def plain_node(settings, script: Path, name: str):
    """A plain rclpy test node (``script``, run with the test robot's Python) on the run's domain, as a JsonLineNode
    called ``name`` in its messages; stopped after."""
    node = JsonLineNode([TEST_ROBOT_PYTHON, script], settings.environment(), name)
    try:
        yield node
    finally:
        node.stop()


@pytest.fixture(scope="session")
def ros2_settings():
    """The link settings of this test run: its own domain id, discovery on this machine only."""
    if not ROS2_PYTHON.exists():
        pytest.fail(f"the ROS 2 tests need {ROS2_PYTHON}: run 'make ros2' first")
    return Ros2Settings(domain_id=DOMAIN_ID, discovery="localhost")


class TestRobot(JsonLineNode):
    """The test node process (tests/robot/ros2/ros2_test_node.py) and what it printed."""

    def __init__(self, settings):
        super().__init__([TEST_ROBOT_PYTHON, TEST_NODE], settings.environment(), "the ROS 2 test node")

    def received(self, topic) -> list:
        """The messages the test node got on ``topic``, as {"type", "message"} dicts."""
        return [line for line in list(self.lines) if line.get("topic") == topic]


@pytest.fixture(scope="module")
def test_robot(ros2_settings):
    robot = TestRobot(ros2_settings)
    yield robot
    robot.stop()


@pytest.fixture(scope="module")
def turtlebot(registry):
    return registry.get("turtlebot")


@pytest.fixture(scope="module")
def ros2_robot(test_robot, turtlebot, ros2_settings):
    """Rockly's ROS 2 link to the test robot, with the TurtleBot profile; its helper ends with the module."""
    from rockly_desktop.robot.ros2.client import Ros2Helper
    from rockly_desktop.robot.ros2.link import Ros2Robot

    robot = Ros2Robot(turtlebot, ros2_settings)
    yield robot
    robot.shutdown()
    Ros2Helper.close_current()
