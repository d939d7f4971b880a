"""A teacher's limits on ROS 2 hold whatever name a program gives: checked on the wire by a plain rclpy
robot in another process (tests/robot/ros2/ros2_test_node.py) recording /cmd_vel and /chatter.

rclpy expands ``{ns}``, ``{namespace}``, ``{node}`` and ``~`` and applies remappings before a name
reaches the graph; the limits compare what it resolves to (asked of the helper's node)."""
import itertools

import pytest
from hypothesis import HealthCheck, event, example, given, settings
from hypothesis import strategies as st
from waiting import eventually

from rockly_desktop.core.errors import RobotCommandError
from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.run_setup import make_runner
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.wrappers.limits import Capability, LimitedBackend, Limits
from rockly_desktop.robot.wrappers.ros_versions import link_backend
from rockly_desktop.robot.wrappers.wrapped_backend import WrappedBackend

TALK = Capability("talk", "Talking", topics=frozenset({"/chatter"}))
MARKS = itertools.count(1)


def twists(test_robot):
    return [line["message"] for line in test_robot.received("/cmd_vel")]


def chatter(test_robot):
    return [line["message"]["data"] for line in test_robot.received("/chatter")]


def marked_cmd_vel(ros2_robot, test_robot):
    """Send a zero Twist marked by its angular.z on /cmd_vel and wait until the robot has it: what a
    program sent before is on the wire by then."""
    mark = float(next(MARKS))
    ros2_robot.backend(Interrupt()).publish("/cmd_vel", "geometry_msgs/Twist", {"angular": {"z": mark}})
    eventually(lambda: any(message["angular"]["z"] == mark for message in twists(test_robot)))


def marked_chatter(ros2_robot, test_robot):
    mark = f"mark {next(MARKS)}"
    ros2_robot.backend(Interrupt()).publish("/chatter", "std_msgs/String", {"data": mark})
    eventually(lambda: mark in chatter(test_robot))


def talk_switched_off(ros2_robot):
    return LimitedBackend(link_backend(ros2_robot, Interrupt()), Limits(switched_off=frozenset({"talk"})),
                          capabilities=[TALK])


@pytest.mark.parametrize("name", ["{ns}cmd_vel", "{namespace}cmd_vel"])
def test_the_generic_publish_block_under_a_speed_limit_puts_nothing_faster_on_the_wire(ros2_robot, test_robot,
                                                                                       turtlebot, name):
    before = len(twists(test_robot))
    code = f"ros.publish_message({name!r}, 'geometry_msgs/Twist', {{'linear': {{'x': 1.0}}}})\n"
    result = make_runner(turtlebot, ros2_robot, {"code": code, "variables": {}}, RunControl(), lambda event: None,
                         "en", Limits(max_speed=0.1)).run()
    assert result.outcome == "finished", result.message
    eventually(lambda: len(twists(test_robot)) >= before + 2)  # the program's Twist, the safe stop's zero one
    sent = [message["linear"]["x"] for message in twists(test_robot)[before:]]
    assert max(sent) == 0.1 and all(abs(x) <= 0.1 for x in sent), sent


@pytest.mark.parametrize("name", ["{ns}chatter", "{namespace}chatter", "chatter"])
def test_a_switched_off_topic_is_refused_by_any_name_rclpy_expands_to_it(ros2_robot, test_robot, name):
    with pytest.raises(RobotCommandError, match="switched off “Talking”"):
        talk_switched_off(ros2_robot).publish(name, "std_msgs/String", {"data": f"sent as {name}"})
    marked_chatter(ros2_robot, test_robot)
    assert f"sent as {name}" not in chatter(test_robot)


def test_a_switched_off_service_and_action_are_refused_by_names_rclpy_expands_to_them(ros2_robot):
    """The test robot serves /set_light and /fibonacci: switched off, neither is reached by another spelling."""
    lights = Capability("lights", "Lights", services=frozenset({"/set_light"}), actions=frozenset({"fibonacci"}))
    backend = LimitedBackend(link_backend(ros2_robot, Interrupt()), Limits(switched_off=frozenset({"lights"})),
                             capabilities=[lights])
    with pytest.raises(RobotCommandError, match="switched off “Lights”"):
        backend.call_service("{ns}set_light", "std_srvs/SetBool", {"data": True}, 5.0)
    with pytest.raises(RobotCommandError, match="switched off “Lights”"):
        backend.send_goal("{namespace}fibonacci", "test_msgs/Fibonacci", {"order": 3})


@pytest.mark.parametrize(("name", "language", "message"), [
    ("~/../chatter", "en", "“~/../chatter” is not a valid ROS name on this robot"),
    ("{ns}/chatter", "de", "„{ns}/chatter“ ist auf diesem Roboter kein gültiger ROS-Name"),
])
def test_a_name_ros2_refuses_is_refused_under_a_limit_with_a_clear_message(ros2_robot, name, language, message):
    with pytest.raises(RobotCommandError) as refused:
        talk_switched_off(ros2_robot).publish(name, "std_msgs/String", {"data": "x"})
    assert refused.value.in_language(language) == message


# --- fuzzing the names: substitutions, ~, relative names, double and trailing slashes, look-alikes

LEADS = ["{ns}", "", "/", "//", "~", "~/", "{namespace}", "{ns}/", "{node}/", "/{node}/", "{unknown}", " "]
TRAILS = ["", "/", "//", " ", "\u200b"]
SEPARATORS = ["/", "//", ""]


def mostly_first(options):
    """One of ``options``, the first (the form most likely to reach a limited name) half of the time."""
    return st.one_of(st.just(options[0]), st.sampled_from(options))


def names(pieces):
    """Names built of ``pieces`` between the ways ROS 2 may begin, separate and end a name."""
    body = st.lists(st.tuples(mostly_first(pieces), mostly_first(SEPARATORS)), min_size=1, max_size=3).map(
        lambda parts: "".join(piece + separator for piece, separator in parts[:-1]) + parts[-1][0])
    return st.builds(lambda lead, middle, trail: lead + middle + trail,
                     mostly_first(LEADS), body, mostly_first(TRAILS))


# Disjoint: a name of one never reaches the other's topic (one type per topic in the helper's participant).
VELOCITY_PIECES = ["cmd_vel", "cmd", "vel", "cmd_vеl", "ϲmd_vel", "cmd\u00a0vel", "..", ".", "_", "Cmd_Vel", "1cmd"]
TALK_PIECES = ["chatter", "chat", "сhatter", "chatter\u200d", "..", ".", "~", "_talk", "Chatter"]


@pytest.mark.timeout(600)
@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=names(VELOCITY_PIECES))
@example(name="{ns}cmd_vel")
@example(name="{namespace}cmd_vel")
def test_fuzzed_names_put_no_velocity_above_the_limit_on_the_wire(ros2_robot, test_robot, name):
    """Whatever the name: refused, or nothing faster than 0.1 m/s reaches the robot's /cmd_vel."""
    backend = LimitedBackend(link_backend(ros2_robot, Interrupt()), Limits(max_speed=0.1), ["/cmd_vel"])
    try:
        backend.publish(name, "geometry_msgs/Twist", {"linear": {"x": 1.0}})
    except RobotCommandError:
        event("refused")
    else:
        event("sent")
    marked_cmd_vel(ros2_robot, test_robot)
    assert all(abs(message["linear"]["x"]) <= 0.1 for message in twists(test_robot))


@pytest.mark.timeout(600)
@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=names(TALK_PIECES))
@example(name="{ns}chatter")
def test_fuzzed_names_reach_no_switched_off_topic_on_the_wire(ros2_robot, test_robot, name):
    """Whatever the name: refused, or nothing reaches the robot's /chatter, which is switched off."""
    token = f"fuzz {next(MARKS)}"
    try:
        talk_switched_off(ros2_robot).publish(name, "std_msgs/String", {"data": token})
    except RobotCommandError as error:
        event("refused: switched off" if "switched off" in str(error) else "refused: no name")
    else:
        event("sent")
    marked_chatter(ros2_robot, test_robot)
    assert token not in chatter(test_robot)


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=names(TALK_PIECES + VELOCITY_PIECES) | st.text(max_size=12))
def test_fuzzed_names_are_refused_exactly_when_rclpy_resolves_them_to_a_switched_off_topic(ros2_robot, name):
    """In the helper, cheaply: refused for a switched-off capability iff rclpy's expansion and remapping
    (``Node.resolve_topic_name``, asked directly) gives /chatter; refused as no name iff rcl refuses it."""
    truth = ros2_robot.helper.call("resolve", name, False)
    backend = LimitedBackend(Swallowing(link_backend(ros2_robot, Interrupt())),
                             Limits(switched_off=frozenset({"talk"})), capabilities=[TALK])
    try:
        backend.publish(name, "std_msgs/String", {"data": "x"})
    except RobotCommandError as error:
        refused = "switched off" if "switched off" in str(error) else "bad name"
    else:
        refused = None
    assert refused == {None: "bad name", "/chatter": "switched off"}.get(truth)


class Swallowing(WrappedBackend):
    """The ROS 2 backend resolving names, sending nothing."""

    def publish(self, topic, msg_type, message):
        pass
