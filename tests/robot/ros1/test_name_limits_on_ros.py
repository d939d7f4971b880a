"""A teacher's limits on ROS 1 hold whatever name a program gives: checked on the wire by a plain rospy
node in another process (ros1_recorder_node.py) recording /cmd_vel and /chatter, on a real master.

rospy resolves a name in the node's namespace, ``~`` under the node's own name, and applies the
command line's remappings; the limits compare what it resolves to. Rockly's node here is as if started
with the remappings REMAPS (rospy's own table, set as ``init_node`` sets it from the command line)."""
import itertools
import sys
from pathlib import Path

import pytest
from hypothesis import HealthCheck, event, example, given, settings
from hypothesis import strategies as st
from json_line_node import JsonLineNode
from ros_helpers import ros_environment
from waiting import eventually

from rockly_desktop.core.errors import RobotCommandError
from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.run_setup import limited_backend, make_runner
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.wrappers.limits import Capability, LimitedBackend, Limits
from rockly_desktop.robot.wrappers.ros_versions import link_backend

RECORDER = Path(__file__).parent / "ros1_recorder_node.py"
REMAPS = ["teleop:=/cmd_vel", "~drive:=/cmd_vel", "talk:=/chatter", "~say:=/chatter", "grab:=hobbit_arm"]
TALK = Capability("talk", "Talking", topics=frozenset({"/chatter"}))
MARKS = itertools.count(1)


class Recorder(JsonLineNode):
    """The plain rospy node's process and what it printed."""

    def __init__(self, master):
        super().__init__([sys.executable, RECORDER], ros_environment(master.uri, master.home / "recorder"),
                         "the recorder")

    def received(self, topic):
        return [line["message"] for line in list(self.lines) if line["topic"] == topic]


@pytest.fixture(scope="module")
def recorder(ros_master):
    recorder = Recorder(ros_master)
    yield recorder
    recorder.stop()


@pytest.fixture(scope="module")
def rockly(ros_master, recorder, hobbit):
    """This process as Rockly's node, with the HOBBIT profile and the remappings REMAPS."""
    import rospy.names

    from rockly_desktop.robot.ros1.link import RosRobot

    robot = RosRobot(hobbit, ros_master.uri)
    rospy.names.reload_mappings(REMAPS)
    rospy.names.initialize_mappings(rospy.get_name())
    yield robot
    rospy.names.reload_mappings(sys.argv)  # as init_node read them
    rospy.names.initialize_mappings(rospy.get_name())
    robot.shutdown()


def twists(recorder):
    return recorder.received("/cmd_vel")


def chatter(recorder):
    return [message["data"] for message in recorder.received("/chatter")]


def marked(rockly, recorder, topic):
    """Send a marked message on ``topic`` and wait until the recorder has it: rospy sends a topic's
    messages in order whatever name its publisher was given, so what a program sent is there by then."""
    mark = next(MARKS)
    backend = rockly.backend(Interrupt())
    if topic == "/cmd_vel":
        backend.publish(topic, "geometry_msgs/Twist", {"angular": {"z": float(mark)}})
        eventually(lambda: any(message["angular"]["z"] == mark for message in twists(recorder)))
    else:
        backend.publish(topic, "std_msgs/String", {"data": f"mark {mark}"})
        eventually(lambda: f"mark {mark}" in chatter(recorder))


def talk_switched_off(rockly):
    return LimitedBackend(link_backend(rockly, Interrupt()), Limits(switched_off=frozenset({"talk"})),
                          capabilities=[TALK])


@pytest.mark.parametrize("name", ["teleop", "~drive"])
def test_the_generic_publish_block_under_a_speed_limit_holds_through_a_remapping(rockly, recorder, hobbit, name):
    before = len(twists(recorder))
    code = f"ros.publish_message({name!r}, 'geometry_msgs/Twist', {{'linear': {{'x': 1.0}}}})\n"
    result = make_runner(hobbit, rockly, {"code": code, "variables": {}}, RunControl(), lambda event: None,
                         "en", Limits(max_speed=0.1)).run()
    assert result.outcome == "finished", result.message
    eventually(lambda: len(twists(recorder)) >= before + 2)  # the program's Twist, the safe stop's zero one
    sent = [message["linear"]["x"] for message in twists(recorder)[before:]]
    assert max(sent) == 0.1 and all(abs(x) <= 0.1 for x in sent), sent


@pytest.mark.parametrize("name", ["talk", "~say", "//chatter/"])
def test_a_switched_off_topic_is_refused_by_any_name_rospy_resolves_to_it(rockly, recorder, name):
    with pytest.raises(RobotCommandError, match="switched off “Talking”"):
        talk_switched_off(rockly).publish(name, "std_msgs/String", {"data": f"sent as {name}"})
    marked(rockly, recorder, "/chatter")
    assert f"sent as {name}" not in chatter(recorder)


def test_a_switched_off_action_is_refused_by_its_remapped_name(rockly, hobbit):
    backend = limited_backend(hobbit, link_backend(rockly, Interrupt()), Limits(switched_off=frozenset({"arm"})),
                              "de")
    with pytest.raises(RobotCommandError) as refused:
        backend.send_goal("grab", "hobbit_msgs/ArmServerAction", {"command": {"data": "OpenGripper"}})
    assert refused.value.in_language("de") == "die Lehrkraft hat „Arm und Greifer“ für diesen Roboter ausgeschaltet"


@pytest.mark.parametrize(("name", "language", "message"), [
    ("", "en", "“” is not a valid ROS name on this robot"),
    ("cmd vel", "de", "„cmd vel“ ist auf diesem Roboter kein gültiger ROS-Name"),  # the master registers it nowhere
    ("http://robot/cmd_vel", "en", "“http://robot/cmd_vel” is not a valid ROS name on this robot"),
])
def test_a_name_rospy_or_the_master_refuses_is_refused_under_a_limit_with_a_clear_message(rockly, name, language,
                                                                                          message):
    with pytest.raises(RobotCommandError) as refused:
        talk_switched_off(rockly).publish(name, "std_msgs/String", {"data": "x"})
    assert refused.value.in_language(language) == message


# --- fuzzing the names: ~, relative names, remapped names, double and trailing slashes, look-alikes

LEADS = ["", "/", "//", "~", "~/", "{ns}", "./", " "]
TRAILS = ["", "/", "//", " ", "\u200b"]
SEPARATORS = ["/", "//", ""]
VELOCITY_PIECES = ["teleop", "drive", "cmd_vel", "cmd_vеl", "ϲmd_vel", "cmd\u00a0vel", "..", ".", "Cmd_Vel"]
TALK_PIECES = ["talk", "say", "chatter", "сhatter", "chatter\u200d", "..", ".", "Chatter"]


def mostly_first(options):
    """One of ``options``, the first (the form most likely to reach a limited name) half of the time."""
    return st.one_of(st.just(options[0]), st.sampled_from(options))


def names(pieces):
    body = st.lists(st.tuples(mostly_first(pieces), mostly_first(SEPARATORS)), min_size=1, max_size=3).map(
        lambda parts: "".join(piece + separator for piece, separator in parts[:-1]) + parts[-1][0])
    return st.builds(lambda lead, middle, trail: lead + middle + trail,
                     mostly_first(LEADS), body, mostly_first(TRAILS))


@pytest.mark.timeout(600)
@pytest.mark.filterwarnings("ignore:.*is not a legal ROS graph resource name")
@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=names(VELOCITY_PIECES))
@example(name="teleop")
@example(name="~drive")
def test_fuzzed_names_put_no_velocity_above_the_limit_on_the_wire(rockly, recorder, name):
    """Whatever the name: refused, or nothing faster than 0.1 m/s reaches the robot's /cmd_vel."""
    backend = LimitedBackend(link_backend(rockly, Interrupt()), Limits(max_speed=0.1), ["/cmd_vel"])
    try:
        backend.publish(name, "geometry_msgs/Twist", {"linear": {"x": 1.0}})
    except RobotCommandError:
        event("refused")
    else:
        event("sent to /cmd_vel" if backend.resolved(name) == "/cmd_vel" else "sent elsewhere")
    marked(rockly, recorder, "/cmd_vel")
    assert all(abs(message["linear"]["x"]) <= 0.1 for message in twists(recorder))


@pytest.mark.timeout(600)
@pytest.mark.filterwarnings("ignore:.*is not a legal ROS graph resource name")
@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=names(TALK_PIECES))
@example(name="talk")
@example(name="~say")
def test_fuzzed_names_reach_no_switched_off_topic_on_the_wire(rockly, recorder, name):
    """Whatever the name: refused, or nothing reaches the robot's /chatter, which is switched off."""
    token = f"fuzz {next(MARKS)}"
    try:
        talk_switched_off(rockly).publish(name, "std_msgs/String", {"data": token})
    except RobotCommandError as error:
        event("refused: switched off" if "switched off" in str(error) else "refused: no name")
    else:
        event("sent")
    marked(rockly, recorder, "/chatter")
    assert token not in chatter(recorder)
