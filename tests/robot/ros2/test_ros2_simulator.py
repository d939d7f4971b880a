"""`rockly sim PROFILE --ros2`'s core: a profile's simulator served on ROS 2, driven by a plain rclpy node."""
import json
import subprocess
from types import SimpleNamespace

import pytest
from waiting import eventually

from rockly_desktop.robot.interface import GoalStatus
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.ros2.client import Ros2Helper
from rockly_desktop.robot.ros2.environment import PROJECT_ROOT
from rockly_desktop.robot.ros2.link import Ros2Robot
from rockly_desktop.robot.ros2.sim_bridge import Ros2SimulatorNode, serve_simulator

ROS2_PYTHON = PROJECT_ROOT / ".venv-ros2" / "bin" / "python"

DRIVER = r'''
import json, sys, threading, time, rclpy
from geometry_msgs.msg import Twist, TwistStamped
from nav_msgs.msg import Odometry
from rclpy.qos import qos_profile_sensor_data
from sensor_msgs.msg import LaserScan
rclpy.init()
node = rclpy.create_node("plain_driver")
seen = {"odom": [], "scan": 0}
node.create_subscription(Odometry, "/odom", lambda m: seen["odom"].append(m.pose.pose.position.x), 10)
node.create_subscription(LaserScan, "/scan", lambda m: seen.__setitem__("scan", seen["scan"] + 1),
                         qos_profile_sensor_data)
stamped = sys.argv[1:] == ["stamped"]  # a Jazzy TurtleBot's /cmd_vel
drive = node.create_publisher(TwistStamped if stamped else Twist, "/cmd_vel", 10)
threading.Thread(target=rclpy.spin, args=(node,), daemon=True).start()
deadline = time.monotonic() + 30
while not (seen["odom"] and seen["scan"] and drive.get_subscription_count()) and time.monotonic() < deadline:
    time.sleep(0.01)
start = seen["odom"][-1] if seen["odom"] else None
message = TwistStamped() if stamped else Twist()
(message.twist if stamped else message).linear.x = 0.2
while time.monotonic() < deadline and seen["odom"] and seen["odom"][-1] < start + 0.05:
    drive.publish(message)
    time.sleep(0.05)
drive.publish(TwistStamped() if stamped else Twist())
print(json.dumps({"start": start, "end": seen["odom"][-1] if seen["odom"] else None, "scans": seen["scan"]}))
'''


@pytest.fixture
def simulated_turtlebot(turtlebot, ros2_settings):
    Ros2Helper.close_current()
    node = Ros2SimulatorNode(turtlebot, ros2_settings, speed=5.0)
    yield node
    node.shutdown()


def test_a_plain_rclpy_node_drives_the_simulated_turtlebot(simulated_turtlebot, ros2_settings):
    driven = subprocess.run([str(ROS2_PYTHON), "-c", DRIVER], env=ros2_settings.environment(),
                            capture_output=True, text=True, timeout=60)
    result = json.loads(driven.stdout.strip().splitlines()[-1])
    assert result["scans"] > 0
    assert result["end"] >= result["start"] + 0.05
    assert ("/sensor_state", "turtlebot3_msgs/SensorState") in [
        (name, type_name) for name, type_name, _why in simulated_turtlebot.left_out]
    assert "domain" in str(simulated_turtlebot.where)


def test_a_simulator_playing_jazzy_is_driven_with_twist_stamped(turtlebot, ros2_settings):
    """``rockly sim turtlebot --ros2 --ros-distro jazzy``: /cmd_vel is a TwistStamped topic, as on a Jazzy TurtleBot."""
    Ros2Helper.close_current()
    node = serve_simulator(turtlebot, {"domain_id": str(ros2_settings.domain_id), "discovery": "localhost",
                                       "ros_distribution": "jazzy"}, speed=5.0)
    try:
        assert str(node.where).startswith("ROS 2 Jazzy, domain")
        driven = subprocess.run([str(ROS2_PYTHON), "-c", DRIVER, "stamped"], env=ros2_settings.environment(),
                                capture_output=True, text=True, timeout=60)
        result = json.loads(driven.stdout.strip().splitlines()[-1])
        assert result["end"] >= result["start"] + 0.05
    finally:
        node.shutdown()


class _CountingSimulator:
    """A simulator with a service and an action of standard ROS 2 types."""

    def __init__(self, world):
        world.advertise_service("/set_light", lambda request, _interrupt: {
            "success": request["data"], "message": "lit" if request["data"] else "dark"})
        world.advertise_action("/fibonacci", self._count)

    @staticmethod
    def _count(goal, feedback, cancelled):
        sequence = [0, 1]
        for _step in range(goal["order"]):
            if cancelled.wait(0.02):
                return GoalStatus.PREEMPTED, {"sequence": sequence}
            sequence.append(sequence[-1] + sequence[-2])
            feedback({"sequence": sequence})
        return GoalStatus.SUCCEEDED, {"sequence": sequence}

    def start(self):
        pass

    def shutdown(self):
        pass


def test_the_simulators_services_and_actions_are_served_on_ros2(ros2_settings):
    Ros2Helper.close_current()
    interface = {"services": {"/set_light": "std_srvs/SetBool", "/tablet": "hobbit_msgs/Request"},
                 "actions": {"/fibonacci": "test_msgs/FibonacciAction"}}
    profile = SimpleNamespace(ros_interface=interface, safe_stop=[],
                              create=lambda _kind, world, tablet=None, speed=1.0: _CountingSimulator(world))
    node = Ros2SimulatorNode(profile, ros2_settings)
    try:
        assert [name for name, _type, _why in node.left_out] == ["/tablet"]
        backend = Ros2Robot(profile, ros2_settings).backend(Interrupt())
        assert backend.call_service("/set_light", "std_srvs/SetBool", {"data": True}, 10) == {
            "success": True, "message": "lit"}
        feedback = []
        outcome = backend.send_goal("/fibonacci", "test_msgs/Fibonacci", {"order": 3}, feedback.append).wait(10)
        assert outcome.status is GoalStatus.SUCCEEDED and outcome.result == {"sequence": [0, 1, 1, 2, 3]}
        assert len(feedback) == 3
        handle = backend.send_goal("/fibonacci", "test_msgs/Fibonacci", {"order": 1000}, feedback.append)
        eventually(lambda: len(feedback) > 5)
        handle.cancel()
        assert handle.wait(10).status is GoalStatus.PREEMPTED
    finally:
        node.shutdown()
