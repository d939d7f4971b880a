"""A TurtleBot on ROS 2 Jazzy wants TwistStamped on /cmd_vel: Rockly learns it from the robot's graph.

The robot is a plain rclpy node in another process (ros2_stamped_node.py) on a domain of this
module's own, localhost only. Nobody declares a distribution: the type of the robot's /cmd_vel
subscriber decides, and the TurtleBot's commands and its safe stop arrive as TwistStamped.
"""
import json
import os
import signal
import subprocess
import threading
from pathlib import Path

import pytest
from ros2_fixtures import requests_to
from waiting import eventually

from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.run_setup import make_runner
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.ros2.client import Ros2Helper
from rockly_desktop.robot.ros2.environment import PROJECT_ROOT, Ros2Settings
from rockly_desktop.robot.ros2.link import Ros2Robot
from rockly_desktop.robot.wrappers import ros_versions
from rockly_desktop.robot.wrappers.ros_versions import link_backend

ROS2_PYTHON = PROJECT_ROOT / ".venv-ros2" / "bin" / "python"
STAMPED_NODE = Path(__file__).with_name("ros2_stamped_node.py")
DOMAIN_ID = 200 + os.getpid() % 30  # not the other ROS 2 tests' domains (100-199)


@pytest.fixture(scope="module")
def settings():
    if not ROS2_PYTHON.exists():
        pytest.fail(f"the ROS 2 tests need {ROS2_PYTHON}: run 'make ros2' first")
    return Ros2Settings(domain_id=DOMAIN_ID, discovery="localhost")


@pytest.fixture(scope="module")
def heard(settings):
    """What the Jazzy-style test robot got on /cmd_vel (one dict per message), while it runs."""
    process = subprocess.Popen([str(ROS2_PYTHON), str(STAMPED_NODE)], stdin=subprocess.PIPE,
                               stdout=subprocess.PIPE, text=True, env=settings.environment())
    lines = []
    assert json.loads(process.stdout.readline() or "{}").get("ready"), "the ROS 2 test node did not start"
    threading.Thread(target=lambda: lines.extend(json.loads(line) for line in process.stdout), daemon=True).start()
    yield lines
    process.stdin.close()
    try:
        process.wait(timeout=10)
    except subprocess.TimeoutExpired:
        process.kill()
        process.wait()


@pytest.fixture
def link(heard, registry, settings):
    """Rockly's ROS 2 link to the test robot with the TurtleBot profile, through a helper of its own."""
    Ros2Helper.close_current()
    robot = Ros2Robot(registry.get("turtlebot"), settings)
    yield robot
    if not robot.helper.lost:
        robot.shutdown()
    Ros2Helper.close_current()


def graph_lists_twist_stamped(link):
    """True once the helper's graph lists the robot's TwistStamped subscriber on /cmd_vel."""
    return "geometry_msgs/msg/TwistStamped" in link.backend(Interrupt()).topic_types("/cmd_vel")


def test_the_turtlebots_commands_and_safe_stop_reach_a_jazzy_robot_as_twist_stamped(link, heard, registry):
    eventually(lambda: graph_lists_twist_stamped(link), timeout=20)
    # written for a Twist, as every TurtleBot program is (the TurtleBot's drive also reads
    # /sensor_state, whose turtlebot3_msgs this ROS 2 environment lacks)
    code = "ros.publish_message('/cmd_vel', 'geometry_msgs/Twist', {'linear': {'x': 0.1}})\nrobot.stop()\n"
    runner = make_runner(registry.get("turtlebot"), link, {"code": code, "variables": {}}, RunControl(),
                         lambda event: None)
    result = runner.run()
    assert result.outcome == "finished", result.message
    # the drive, then the stop and the run's safe stop after it (the last heard is a stop)
    eventually(lambda: any(line["message"]["linear"]["x"] == pytest.approx(0.1) for line in heard)
               and heard[-1]["message"]["linear"]["x"] == 0.0, timeout=30)  # a new publisher type: matched anew
    assert {line["type"] for line in heard} == {"TwistStamped"}
    assert all(line["frame_id"] == "base_link" and line["stamped"] for line in heard)
    count = len(heard)
    link.backend(Interrupt()).publish("/cmd_vel", "geometry_msgs/TwistStamped", {"twist": {"linear": {"x": 0.05}}})
    eventually(lambda: len(heard) > count)
    assert link.safe_stop() == []
    eventually(lambda: heard[-1]["message"]["linear"]["x"] == 0.0 and len(heard) > count + 1)


def test_the_safe_stop_sends_the_type_a_run_learnt_without_asking_the_graph_again(link, heard, monkeypatch):
    """The zero velocity must not wait for a graph query (one on every stop: milliseconds, more under load)."""
    monkeypatch.setattr(ros_versions, "RECHECK_SECONDS", 0.0)  # a run's backend would ask again at once
    eventually(lambda: graph_lists_twist_stamped(link), timeout=20)
    link_backend(link, Interrupt()).publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.2}})
    eventually(lambda: heard and heard[-1]["message"]["linear"]["x"] == pytest.approx(0.2), timeout=30)
    with requests_to(link.helper) as asked:
        assert link.safe_stop() == []
    assert "graph" not in asked
    eventually(lambda: heard[-1]["message"]["linear"]["x"] == 0.0 and heard[-1]["type"] == "TwistStamped")


def test_a_jazzy_robot_is_driven_while_its_graph_is_followed_for_the_panels(link, heard, registry):
    """The window follows the whole graph; Rockly's own Twist publisher (the safe stop's, made at once)
    must not make it subscribe to /cmd_vel as Twist, which would refuse the TwistStamped publisher."""
    feed = link.follow_graph()
    eventually(lambda: "/cmd_vel" in {topic for topic, _type, _count in feed.graph_topics()}, timeout=20)
    eventually(lambda: graph_lists_twist_stamped(link), timeout=20)
    code = "ros.publish_message('/cmd_vel', 'geometry_msgs/Twist', {'linear': {'x': 0.07}})\n"
    result = make_runner(registry.get("turtlebot"), link, {"code": code, "variables": {}}, RunControl(),
                         lambda event: None).run()
    assert result.outcome == "finished", result.message
    eventually(lambda: any(line["message"]["linear"]["x"] == pytest.approx(0.07) for line in heard), timeout=30)
    assert {line["type"] for line in heard} == {"TwistStamped"}
    assert dict((topic, count) for topic, _type, count in feed.graph_topics())["/cmd_vel"] == 0  # only Rockly's


def test_the_helpers_last_act_stops_a_jazzy_robot_in_the_type_it_was_sent(link, heard):
    eventually(lambda: graph_lists_twist_stamped(link), timeout=20)
    link_backend(link, Interrupt()).publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.2}})
    eventually(lambda: heard and heard[-1]["message"]["linear"]["x"] == pytest.approx(0.2))
    helper = link.helper
    helper.process.send_signal(signal.SIGTERM)
    eventually(lambda: helper.lost)
    eventually(lambda: heard[-1]["message"]["linear"]["x"] == 0.0)
    # stamped now in the robot's frame, as the commands before it (the robot's controller may drop a stamp of 0)
    assert heard[-1]["type"] == "TwistStamped" and heard[-1]["stamped"] and heard[-1]["frame_id"] == "base_link"


def test_a_killed_helpers_replacement_stops_a_jazzy_robot_in_the_type_it_was_sent(link, heard):
    eventually(lambda: graph_lists_twist_stamped(link), timeout=20)
    link_backend(link, Interrupt()).publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.2}})
    eventually(lambda: heard and heard[-1]["message"]["linear"]["x"] == pytest.approx(0.2))
    count = len(heard)
    link.helper.process.kill()  # no last act: the new helper sends the stop
    eventually(lambda: len(heard) > count and heard[-1]["message"]["linear"]["x"] == 0.0)
    assert heard[-1]["type"] == "TwistStamped" and heard[-1]["stamped"] and heard[-1]["frame_id"] == "base_link"
    eventually(lambda: link.replaced is not None and not link.helper.lost)
