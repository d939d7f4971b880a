"""What differs per ROS version (``ros_versions``): resolved per robot, and sent as the robot wants it.

The TurtleBot declares ``/cmd_vel: {jazzy: geometry_msgs/TwistStamped}``. On the real built-in
simulator declared as a Jazzy robot, its commands, its safe stop and a teacher's limit clamp all
send TwistStamped; declared as nothing (or as Humble), Twist. What reaches the simulated world is
read with its type (``world.tap``).
"""
import math

import pytest
from profile_copies import REPO, SHARED_TOOLBOXES

from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.run_setup import make_runner
from rockly_desktop.profiles.profile import load_profile
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.sim.link import SimulatedRobot
from rockly_desktop.robot.sim.sim_world import SimBackend, SimWorld
from rockly_desktop.robot.wrappers.limits import LimitedBackend, Limits
from rockly_desktop.robot.wrappers.ros_versions import (
    VersionedBackend,
    converted,
    declared_type,
    link_backend,
    robot_type,
    stamped_part,
)

TURTLEBOT = load_profile(REPO / "profiles" / "turtlebot", SHARED_TOOLBOXES)
TWIST, STAMPED = "geometry_msgs/Twist", "geometry_msgs/TwistStamped"
VARIANTS = {"jazzy": STAMPED}


@pytest.mark.parametrize(("version", "distribution", "wanted"), [
    ("ros1", None, TWIST), ("ros2", None, TWIST), (None, None, TWIST), ("ros2", "humble", TWIST),
    ("ros2", "iron", TWIST), ("ros2", "jazzy", STAMPED), ("ros2", "kilted", STAMPED), ("ros2", "rolling", STAMPED),
    (None, "jazzy", STAMPED), ("ros2", "a-distribution-after-rolling", STAMPED),
])
def test_a_distribution_key_counts_from_that_distribution_on(version, distribution, wanted):
    assert declared_type(TWIST, VARIANTS, version, distribution) == wanted


def test_the_most_specific_key_wins_and_a_version_key_covers_its_distributions():
    variants = {"ros1": "a/One", "ros2": "a/Two", "iron": "a/Iron", "kilted": "a/Kilted"}
    assert [declared_type("a/Base", variants, "ros2", name) for name in ("humble", "iron", "jazzy", "kilted")] == [
        "a/Two", "a/Iron", "a/Iron", "a/Kilted"]
    assert declared_type("a/Base", variants, "ros1") == "a/One"
    assert declared_type("a/Base", variants, "ros2") == "a/Two"


@pytest.mark.parametrize(("listed", "declared", "wanted"), [
    (["geometry_msgs/msg/Twist", "geometry_msgs/msg/TwistStamped"], None, STAMPED),  # the robot's is the stamped
    (["geometry_msgs/msg/Twist"], "jazzy", TWIST),    # a Jazzy robot set back to Twist: the graph wins
    ([], "jazzy", STAMPED), (None, "jazzy", STAMPED),  # nothing listed: the declared distribution
    ([], None, TWIST),
])
def test_the_robots_graph_decides_before_any_declared_distribution(listed, declared, wanted):
    assert robot_type(TWIST, VARIANTS, "ros2", declared, listed) == wanted


def test_a_twist_becomes_a_stamped_twist_and_back():
    twist = {"linear": {"x": 0.1}, "angular": {"z": 0.2}}
    stamped = converted(twist, TWIST, "geometry_msgs/msg/TwistStamped")
    assert stamped["twist"] == twist and stamped["header"]["frame_id"] == "base_link"
    assert stamped["header"]["stamp"]["secs"] > 0 and 0 <= stamped["header"]["stamp"]["nsecs"] < 1e9
    assert converted(stamped, STAMPED, TWIST) == twist
    assert stamped_part(stamped, STAMPED) == twist and stamped_part(twist, TWIST) == twist
    assert converted({"data": "x"}, "std_msgs/String", STAMPED) == {"data": "x"}  # nothing to convert


@pytest.fixture
def sent():
    """A simulated TurtleBot world and what reaches its /cmd_vel: (type, message)."""
    world, seen = SimWorld(), []
    world.tap(lambda topic, msg_type, message: seen.append((msg_type, message)) if topic == "/cmd_vel" else None)
    return world, seen


@pytest.mark.parametrize(("distribution", "wanted"), [("jazzy", STAMPED), ("humble", TWIST), (None, TWIST)])
def test_a_twist_is_sent_as_the_type_the_robot_wants(sent, distribution, wanted):
    world, seen = sent
    backend = VersionedBackend(SimBackend(world, Interrupt()), TURTLEBOT.ros_versions, TURTLEBOT.ros_interface,
                               distribution)
    backend.publish("/cmd_vel", TWIST, {"linear": {"x": 0.1}})
    backend.publish("/odom", "nav_msgs/Odometry", {"header": {}})  # nothing differs there
    assert [msg_type for msg_type, _message in seen] == [wanted]
    assert stamped_part(seen[0][1], wanted) == {"linear": {"x": 0.1}}
    assert backend.type_for("cmd_vel") == wanted and backend.interface()["/cmd_vel"] == wanted
    assert backend.interface()["/odom"] == "nav_msgs/Odometry"


def test_a_profile_declaring_nothing_per_version_keeps_its_backend(hobbit):
    backend = SimBackend(SimWorld(), Interrupt())

    class Link:
        profile = hobbit
        ros_version = None

        @staticmethod
        def backend(interrupt):
            return backend

    assert link_backend(Link, Interrupt()) is backend


def test_a_limit_clamps_a_stamped_twist(sent):
    world, seen = sent
    backend = LimitedBackend(SimBackend(world, Interrupt()), Limits(max_speed=0.1, max_turn=45), ["/cmd_vel"])
    header = {"frame_id": "base_link", "stamp": {"secs": 1, "nsecs": 2}}
    backend.publish("/cmd_vel", STAMPED, {"header": header, "twist": {"linear": {"x": 1.0}, "angular": {"z": -2.0}}})
    assert seen == [(STAMPED, {"header": header, "twist": {"linear": {"x": 0.1},
                                                            "angular": {"z": pytest.approx(-math.radians(45))}}})]


@pytest.fixture
def make_robot():
    robots = []

    def make(distribution):
        robot = SimulatedRobot.open(TURTLEBOT, {"ros_distribution": distribution} if distribution else None,
                                    speed=20.0)
        robots.append(robot)
        seen = []
        robot.world.tap(lambda topic, msg_type, message: seen.append((msg_type, message))
                        if topic == "/cmd_vel" else None)
        return robot, seen

    yield make
    for robot in robots:
        robot.shutdown()


def run(robot, code, limits=None):
    return make_runner(TURTLEBOT, robot, {"code": code, "variables": {}}, RunControl(), lambda event: None,
                       "en", limits).run()


@pytest.mark.parametrize(("distribution", "wanted"), [("jazzy", STAMPED), ("kilted", STAMPED), (None, TWIST)])
def test_the_turtlebots_drive_turn_and_safe_stop_send_the_type_the_robot_wants(make_robot, distribution, wanted):
    robot, seen = make_robot(distribution)
    result = run(robot, "robot.drive(0.1, 'forward')\nrobot.turn(30, 'left')\nrobot.drive_for(0.1, 0.2)\n")
    assert result.outcome == "finished", result.message
    assert {msg_type for msg_type, _message in seen} == {wanted}
    velocities = [stamped_part(message, msg_type) for msg_type, message in seen]
    assert any(velocity.get("linear", {}).get("x", 0) > 0 for velocity in velocities)
    assert any(velocity.get("angular", {}).get("z", 0) > 0 for velocity in velocities)
    assert abs(robot.snapshot()["theta"] - math.radians(30)) < math.radians(3)   # the simulator followed
    seen.clear()
    assert robot.safe_stop() == []
    assert [msg_type for msg_type, _message in seen] == [wanted] and stamped_part(seen[0][1], wanted) == {}


def test_a_teachers_limit_clamps_the_stamped_twists_of_a_jazzy_turtlebot(make_robot):
    robot, seen = make_robot("jazzy")
    result = run(robot, "robot.drive_for(0.2, 0.3)\n", Limits(max_speed=0.05))
    assert result.outcome == "finished", result.message
    speeds = [message["twist"].get("linear", {}).get("x", 0.0) for msg_type, message in seen if msg_type == STAMPED]
    assert len(speeds) == len(seen) and max(speeds) == pytest.approx(0.05)


@pytest.mark.parametrize(("distribution", "wanted"), [("jazzy", STAMPED), (None, TWIST)])
def test_commands_learn_the_resolved_type_through_the_sdk_under_a_teachers_limits(distribution, wanted):
    versioned = VersionedBackend(SimBackend(SimWorld(), Interrupt()), TURTLEBOT.ros_versions,
                                 TURTLEBOT.ros_interface, distribution)
    commands = TURTLEBOT.create("api", LimitedBackend(versioned, Limits(max_speed=0.1), ["/cmd_vel"]))
    assert commands.ros_type("/cmd_vel") == wanted
    assert commands.ros_type("/odom", "nav_msgs/Odometry") == "nav_msgs/Odometry"
    assert TURTLEBOT.create("api", SimBackend(SimWorld(), Interrupt())).ros_type("/cmd_vel", TWIST) == TWIST
