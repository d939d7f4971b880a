"""HOBBIT's commands (profiles/hobbit/rockly_hobbit/api.py): argument checks, the exact ROS values they send, pausing.

The commands drive the built-in simulated HOBBIT (profiles/hobbit/rockly_hobbit/sim.py) in a
real SimWorld. What they send is read where it reaches that world: topic messages through
``world.subscribe`` (their types from ``world.topics()``), service calls and action goals
noted by ``ObservedSimBackend`` on their way into the real SimBackend, and dialogs by the
person at the tablet. What the simulator then does with them (poses, arm states, tablet
views) is tested in test_hobbit_sim.py. Every wait is on a condition, never a fixed time.
"""
import copy
import math
import re
import sys
import time

import pytest
from background import Background
from profile_copies import HOBBIT_DIR, SHARED_TOOLBOXES
from sim_tools import HoldWatcher, eventually_in, later, pose

from rockly_desktop.core.errors import ProgramStopped, RobotCommandError
from rockly_desktop.executor.control import RunControl
from rockly_desktop.profiles.profile import load_profile
from rockly_desktop.robot.sim.sim_world import SimBackend, SimWorld
from rockly_desktop.robot.sim.tablet import TabletQuestion

PROFILE = load_profile(HOBBIT_DIR, SHARED_TOOLBOXES)


def _load(module_name):
    """A module of HOBBIT's package ``rockly_hobbit``, imported the way Rockly imports the profile."""
    PROFILE.load_object("simulator" if module_name == "sim" else "api")
    return sys.modules[f"rockly_hobbit.{module_name}"]


api = _load("api")
SimHobbit = _load("sim").SimHobbit
Hobbit = api.Hobbit

SPEED = 20
POSITION = 0.02  # m
ANGLE = 2.0      # degrees
TABLET_TEXTS = ['He said "hello"', "it's me", "first line\nsecond line", "Grüße, 日本語 😀", "a\\b {x} %s", ""]


class ObservedSimBackend(SimBackend):
    """The real SimBackend; notes each service call and action goal, with its ROS type, then passes it on unchanged.

    The simulator answers them itself: tablet answers, goal outcomes and timing are real.
    """

    def __init__(self, world, interrupt):
        super().__init__(world, interrupt)
        self.service_calls = []
        self.goals = []

    def call_service(self, name, srv_type, request, timeout):
        self.service_calls.append((name, srv_type, copy.deepcopy(request), timeout))
        return super().call_service(name, srv_type, request, timeout)

    def send_goal(self, action, action_type, goal, feedback=None):
        self.goals.append((action, action_type, copy.deepcopy(goal)))
        return super().send_goal(action, action_type, goal, feedback)


class AnsweringTablet:
    """The person at the simulated tablet: answers from a list, notes every question and notice."""

    def __init__(self):
        self.answers = []
        self.asked = []
        self.notices = []

    def ask(self, question, text, timeout, interrupt):
        self.asked.append((question, text, timeout))
        return self.answers.pop(0)

    def notify(self, text):
        self.notices.append(text)


@pytest.fixture
def world():
    return SimWorld()


@pytest.fixture
def tablet():
    return AnsweringTablet()


@pytest.fixture
def sim(world, tablet):
    robot = SimHobbit(world, tablet=tablet, speed=SPEED)
    robot.start()
    yield robot
    robot.safe_stop()
    robot.shutdown()


@pytest.fixture
def control():
    control = RunControl()
    yield control
    control.request_stop()  # ends a program a failed test left holding or waiting


@pytest.fixture
def backend(world, sim, control):
    return ObservedSimBackend(world, control.interrupt)


@pytest.fixture
def hobbit(backend):
    return Hobbit(backend)


@pytest.fixture
def hold(control, sim):
    watcher = HoldWatcher(control, sim)
    control.on_hold = watcher
    return watcher


def record(world, *topics):
    """Every later message on ``topics`` as ``(topic, message)``, in the order they were published."""
    seen = []
    for topic in topics:
        world.subscribe(topic, lambda message, topic=topic: seen.append((topic, message)))
    return seen


def record_data(world, topic):
    """The ``data`` of every later message on ``topic``, in order."""
    seen = []
    world.subscribe(topic, lambda message: seen.append(message.get("data")))
    return seen


def degrees_between(theta, degrees):
    """The smallest angle, in degrees, from the heading ``theta`` (radians) to ``degrees``."""
    return math.degrees(math.remainder(theta - math.radians(degrees), math.tau))


def amount_of(command, kind):
    """The number in a ``Move <metres>`` / ``Turn <degrees>`` discrete motion command."""
    word, amount = command.split()
    assert word == kind, command
    return float(amount)


def tablet_request(dialog_type, text):
    """The /MMUI request that shows (and says) ``text`` as HOBBIT's tablet expects it."""
    return {"sessionID": "0", "requestText": "", "params": [
        {"name": "type", "value": dialog_type}, {"name": "text", "value": text},
        {"name": "speak", "value": text}, {"name": "Timeout", "value": "60"}]}


def tablet_function(function_type):
    return {"sessionID": "0", "requestText": "", "params": [{"name": "type", "value": function_type}]}


# --- refused arguments: an error naming what is wrong, and nothing reaches the robot -------------


@pytest.fixture
def assert_nothing_reached_the_robot(world, sim, backend):
    """A check that since the test began no topic got its first message, no service was called, no goal sent."""
    topics_before = world.topics()

    def check():
        assert world.topics() == topics_before, "a refused command published something"
        assert (backend.service_calls, backend.goals) == ([], [])

    return check


@pytest.mark.parametrize("command, argument, what, choices", [
    ("look", "sideways", "head position", api.HEAD_POSITIONS),
    ("look", "CENTER_CENTER", "head position", api.HEAD_POSITIONS),
    ("show_emotion", "ANGRY", "emotion", api.EMOTIONS),
    ("show_emotion", "happy", "emotion", api.EMOTIONS),
    ("move_arm", "MoveToCandle", "arm position", ["candle", "home", "floor", "table", "tray"]),
    ("turntable", "spin", "turntable action", ["learn", "store", "clockwise", "counterclockwise"]),
    ("gripper", "OpenGripper", "gripper action", ["open", "close"]),
    ("gripper", "half", "gripper action", ["open", "close"]),
    ("change_volume", "max", "volume change", ["louder", "quieter"]),
])
def test_unknown_choice_is_refused_listing_the_valid_ones(hobbit, assert_nothing_reached_the_robot,
                                                           command, argument, what, choices):
    with pytest.raises(RobotCommandError) as caught:
        getattr(hobbit, command)(argument)
    listed = ", ".join(repr(choice) for choice in choices)
    assert str(caught.value) == f"unknown {what} {argument!r}; use one of {listed}"
    assert_nothing_reached_the_robot()


@pytest.mark.parametrize("command, args, what, bad, choices", [
    ("drive", (1, "sideways"), "direction", "sideways", ["forward", "backward"]),
    ("drive", (1, "+"), "direction", "+", ["forward", "backward"]),
    ("turn", (90, "up"), "direction", "up", ["left", "right"]),
    ("publish", ("/chatter", "Int32", 1), "message type", "Int32", ["String", "Bool", "Float64", "Int64", "UInt64"]),
])
def test_unknown_direction_or_type_is_refused_listing_the_valid_ones(hobbit, assert_nothing_reached_the_robot,
                                                                      command, args, what, bad, choices):
    with pytest.raises(RobotCommandError) as caught:
        getattr(hobbit, command)(*args)
    listed = ", ".join(repr(choice) for choice in choices)
    assert str(caught.value) == f"unknown {what} {bad!r}; use one of {listed}"
    assert_nothing_reached_the_robot()


@pytest.mark.parametrize("command, args, what", [
    ("drive", ("far",), "the distance"),
    ("drive", (None,), "the distance"),
    ("drive", (True,), "the distance"),
    ("drive", ("1",), "the distance"),
    ("turn", ([90],), "the angle"),
    ("navigate_to", (1, 2, "north"), "the heading"),
    ("navigate_to_pose", (0, 0, 0, 0, 0, 0, "one"), "quat w"),
    ("wait", ("5",), "the waiting time"),
])
def test_non_number_is_refused_naming_what_it_should_be(hobbit, assert_nothing_reached_the_robot, command, args, what):
    with pytest.raises(RobotCommandError) as caught:
        getattr(hobbit, command)(*args)
    bad = next(value for value in args if not isinstance(value, (int, float)) or isinstance(value, bool))
    assert str(caught.value) == f"{what} must be a number, not {bad!r}"
    assert_nothing_reached_the_robot()


@pytest.mark.parametrize("joints", [[0, 0, 0, 0, 0], [0] * 7, [], "123456", 6, None],
                         ids=["five", "seven", "none", "a string", "a number", "null"])
def test_arm_joints_need_exactly_six_values(hobbit, assert_nothing_reached_the_robot, joints):
    with pytest.raises(RobotCommandError) as caught:
        hobbit.move_arm_to_joints(joints)
    assert str(caught.value) == f"the arm needs exactly 6 joint values, not {joints!r}"
    assert_nothing_reached_the_robot()


def test_arm_joint_that_is_not_a_number_is_refused(hobbit, assert_nothing_reached_the_robot):
    with pytest.raises(RobotCommandError, match=r"^a joint value must be a number, not 'x'$"):
        hobbit.move_arm_to_joints([0, 0, "x", 0, 0, 0])
    assert_nothing_reached_the_robot()


# --- topics -------------------------------------------------------------------------------------


@pytest.mark.parametrize("command, value, topic", [
    ("look", "up_left", "/head/move"),
    ("show_emotion", "VHAPPY", "/head/emo"),
])
def test_head_and_eyes_publish_the_value_as_a_string(world, hobbit, command, value, topic):
    sent = record(world, topic)
    getattr(hobbit, command)(value)
    assert sent == [(topic, {"data": value})]
    assert dict(world.topics())[topic] == "std_msgs/String"


@pytest.mark.parametrize("command, args, motion", [
    ("drive", (2, "forward"), "Move 2"),
    ("drive", (0.5, "backward"), "Move -0.5"),
    ("turn", (90, "left"), "Turn 90"),
    ("turn", (180, "right"), "Turn -180"),
])
def test_drive_and_turn_send_one_discrete_motion_and_return_when_the_base_is_idle(world, sim, hobbit,
                                                                                  command, args, motion):
    commands = record_data(world, "/DiscreteMotionCmd")
    states = record_data(world, "/DiscreteMotionState")
    getattr(hobbit, command)(*args)
    assert commands == [motion]
    assert dict(world.topics())["/DiscreteMotionCmd"] == "std_msgs/String"
    assert states[-1] == "Idle" and sim.snapshot()["motion"] == "idle"


def test_stop_halts_discrete_motion_then_velocity(world, hobbit):
    sent = record(world, "/DiscreteMotionCmd", "/cmd_vel")
    hobbit.stop()
    assert sent == [("/DiscreteMotionCmd", {"data": "Stop"}), ("/cmd_vel", {})]
    types = dict(world.topics())
    assert (types["/DiscreteMotionCmd"], types["/cmd_vel"]) == ("std_msgs/String", "geometry_msgs/Twist")


@pytest.mark.parametrize("message_type, value, ros_type", [
    ("String", "hi 😀", "std_msgs/String"),
    ("Bool", True, "std_msgs/Bool"),
    ("Float64", 1.5, "std_msgs/Float64"),
    ("Int64", -3, "std_msgs/Int64"),
    ("UInt64", 7, "std_msgs/UInt64"),
])
def test_publish_sends_the_value_as_a_std_msgs_message(world, hobbit, message_type, value, ros_type):
    sent = record(world, "/chatter")
    hobbit.publish("/chatter", message_type, value)
    assert sent == [("/chatter", {"data": value})]
    assert dict(world.topics())["/chatter"] == ros_type


# --- actions ------------------------------------------------------------------------------------


def arm_goal(command, joints=()):
    return ("hobbit_arm", "hobbit_msgs/ArmServerAction",
            {"command": {"data": command}, "velocity": 0.0, "joints": [{"joint_values": list(v)} for v in joints]})


@pytest.mark.parametrize("command, argument, arm_command", [
    ("gripper", "open", "OpenGripper"),
    ("gripper", "close", "CloseGripper"),
    ("move_arm", "floor", "MoveToPreGraspFloor"),
    ("move_arm", "candle", "MoveToCandle"),
    ("turntable", "counterclockwise", "TurnTurntableCCW"),
    ("turntable", "learn", "MoveToLearning"),
])
def test_arm_commands_send_one_goal_to_the_arm_server(sim, backend, hobbit, command, argument, arm_command):
    getattr(hobbit, command)(argument)
    assert backend.goals == [arm_goal(arm_command)]
    assert sim.snapshot()["arm_target"] is None, "the command returned before the arm was done"


def test_arm_joints_are_sent_as_one_vector_of_numbers(backend, hobbit):
    hobbit.move_arm_to_joints((10, 20.5, -30, 0, 45, 90))
    assert backend.goals == [arm_goal("MoveToJointValues", [[10.0, 20.5, -30.0, 0.0, 45.0, 90.0]])]
    (_action, _type, goal), = backend.goals
    assert all(type(value) is float for value in goal["joints"][0]["joint_values"])


def test_arm_command_the_robot_does_not_finish_raises_naming_it(world, sim, hobbit):
    moving = Background(lambda: hobbit.move_arm("floor"))
    eventually_in(world, lambda: sim.snapshot()["arm_progress"] > 0)
    sim.safe_stop()  # what ends a run: it cancels the arm goal
    error = moving.join().error
    assert isinstance(error, RobotCommandError), error
    assert str(error) == "the robot could not finish the arm command MoveToPreGraspFloor (preempted)"


def test_navigate_to_sends_a_map_pose_facing_the_heading(backend, hobbit):
    hobbit.navigate_to(1.5, -2, 90)
    (action, action_type, goal), = backend.goals
    assert (action, action_type) == ("move_base", "move_base_msgs/MoveBaseAction")
    pose_stamped = goal["target_pose"]
    assert pose_stamped["header"] == {"frame_id": "map"}
    assert pose_stamped["pose"]["position"] == {"x": 1.5, "y": -2.0, "z": 0.0}
    orientation = pose_stamped["pose"]["orientation"]
    assert (orientation["x"], orientation["y"]) == (0.0, 0.0)
    assert orientation["z"] == pytest.approx(math.sqrt(0.5))
    assert orientation["w"] == pytest.approx(math.sqrt(0.5))


def test_navigate_to_pose_sends_the_pose_as_given(backend, hobbit):
    hobbit.navigate_to_pose(-0.5, 0.5, 0, 0, 0, -0.6, 0.8)
    (_action, _type, goal), = backend.goals
    assert goal == {"target_pose": {"header": {"frame_id": "map"}, "pose": {
        "position": {"x": -0.5, "y": 0.5, "z": 0.0}, "orientation": {"x": 0.0, "y": 0.0, "z": -0.6, "w": 0.8}}}}


def test_navigation_the_robot_refuses_raises_naming_it(hobbit):
    with pytest.raises(RobotCommandError) as caught:
        hobbit.navigate_to_pose(1, 1, 0, 0, 0, 0, 0)  # no orientation at all
    assert str(caught.value).startswith("HOBBIT could not reach the goal: not a valid goal pose")


# --- tablet (/MMUI service) -----------------------------------------------------------------------


@pytest.mark.parametrize("text", TABLET_TEXTS)
def test_show_info_sends_and_speaks_the_text_exactly_as_given(backend, hobbit, text):
    hobbit.show_info(text)
    (name, srv_type, request, _timeout), = backend.service_calls
    assert (name, srv_type) == ("/MMUI", "hobbit_msgs/Request")
    assert request == tablet_request("D_PLAIN", text)


@pytest.mark.parametrize("command, dialog_type, question, answer", [
    ("show_info", "D_PLAIN", None, None),
    ("show_info_and_wait", "D_OK", TabletQuestion.OK, ""),
    ("ask_yes_no", "D_YES_NO", TabletQuestion.YES_NO, "yes"),
    ("ask_text", "D_NAME", TabletQuestion.TEXT, "Anna"),
])
def test_each_tablet_command_sends_its_dialog_type(tablet, backend, hobbit, command, dialog_type, question, answer):
    text = 'Say "yes"\nor no: Grüße 😀'
    tablet.answers = [] if answer is None else [answer]
    getattr(hobbit, command)(text)
    assert [request for _name, _type, request, _timeout in backend.service_calls] == [
        tablet_request(dialog_type, text)]
    assert tablet.asked == ([] if answer is None else [(question, text, api.DIALOG_TIMEOUT)])
    assert tablet.answers == [], "the answer was not asked for"


@pytest.mark.parametrize("answer, expected", [("Yes ", True), (" YES\n", True), ("", False), ("yes please", False)])
def test_ask_yes_no_is_true_only_for_a_yes_answer(tablet, hobbit, answer, expected):
    tablet.answers = [answer]
    assert hobbit.ask_yes_no("Shall we play?") is expected


@pytest.mark.parametrize("command, args, function_type, notice", [
    ("change_volume", ("louder",), "F_LOUDER", "volume 60 %"),
    ("change_volume", ("quieter",), "F_QUIETER", "volume 40 %"),
    ("call_sos", (), "F_CALLSOS", "SOS call started"),
])
def test_tablet_functions_send_only_their_type(tablet, backend, hobbit, command, args, function_type, notice):
    getattr(hobbit, command)(*args)
    (name, srv_type, request, _timeout), = backend.service_calls
    assert (name, srv_type, request) == ("/MMUI", "hobbit_msgs/Request", tablet_function(function_type))
    assert tablet.notices == [notice]


def test_call_service_passes_the_request_unchanged_and_returns_the_response(tablet, backend, hobbit):
    tablet.answers = ["Anna Grüße"]
    request = {"sessionID": "7", "params": [{"name": "type", "value": "D_NAME"}, {"name": "text", "value": "Name?"}]}
    response = hobbit.call_service("/MMUI", "hobbit_msgs/Request", request)
    assert response == {"params": [{"name": "result", "value": "Anna Grüße"}]}
    assert backend.service_calls == [("/MMUI", "hobbit_msgs/Request", request, api.DIALOG_TIMEOUT)]
    assert tablet.asked == [(TabletQuestion.TEXT, "Name?", 60.0)]


# --- waiting ------------------------------------------------------------------------------------


def test_wait_for_a_negative_time_returns_at_once(hobbit):
    started = time.monotonic()
    hobbit.wait(-3)
    assert time.monotonic() - started < 1.0


# --- pausing a drive or a turn --------------------------------------------------------------------


def test_pause_halts_a_drive_part_way_and_continue_drives_the_rest(world, sim, control, hold, hobbit):
    commands = record_data(world, "/DiscreteMotionCmd")
    drive = Background(lambda: hobbit.drive(1.0))
    eventually_in(world, lambda: sim.snapshot()["x"] > 0.1)
    control.request_pause()

    held = hold.wait_until_held()
    assert (held["motion"], held["linear"]) == ("idle", 0.0)
    assert 0.1 < held["x"] < 1.0 - POSITION
    assert pose(later(world, sim)) == pose(held), "the base moved while the program held"
    assert drive.thread.is_alive()

    control.resume()
    assert drive.join().error is None
    assert sim.snapshot()["x"] == pytest.approx(1.0, abs=POSITION)
    assert len(hold.snapshots) == 1, "the rest of the drive held again"
    first, stop, rest = commands
    assert (first, stop) == ("Move 1", "Stop")
    assert amount_of(rest, "Move") == pytest.approx(1.0 - held["x"], abs=0.001)


def test_pause_halts_a_turn_past_half_way_round_and_continue_turns_the_rest(world, sim, control, hold, hobbit):
    commands = record_data(world, "/DiscreteMotionCmd")
    turn = Background(lambda: hobbit.turn(270, "left"))
    eventually_in(world, lambda: sim.snapshot()["theta"] < 0)  # turning left from 0, so past 180 degrees
    control.request_pause()

    held = hold.wait_until_held()
    assert (held["motion"], held["angular"]) == ("idle", 0.0)
    turned = math.degrees(held["theta"]) % 360
    assert 180 < turned < 270 - ANGLE
    assert pose(later(world, sim)) == pose(held), "the base turned while the program held"

    control.resume()
    assert turn.join().error is None
    assert degrees_between(sim.snapshot()["theta"], 270) == pytest.approx(0.0, abs=ANGLE)
    first, stop, rest = commands
    assert (first, stop) == ("Turn 270", "Stop")
    assert amount_of(rest, "Turn") == pytest.approx(270 - turned, abs=0.1)


def test_pause_of_a_backward_drive_continues_backward(world, sim, control, hold, hobbit):
    drive = Background(lambda: hobbit.drive(0.6, "backward"))
    eventually_in(world, lambda: sim.snapshot()["x"] < -0.1)
    control.request_pause()
    held = hold.wait_until_held()
    assert -0.6 + POSITION < held["x"] < -0.1
    control.resume()
    assert drive.join().error is None
    assert sim.snapshot()["x"] == pytest.approx(-0.6, abs=POSITION)


def test_stop_while_a_drive_holds_ends_the_program_and_the_base_stays_where_it_halted(world, sim, control, hold,
                                                                                     hobbit):
    commands = record_data(world, "/DiscreteMotionCmd")
    drive = Background(lambda: hobbit.drive(1.0))
    eventually_in(world, lambda: sim.snapshot()["x"] > 0.1)
    control.request_pause()
    held = hold.wait_until_held()

    control.request_stop()
    assert isinstance(drive.join().error, ProgramStopped), drive.error
    assert commands == ["Move 1", "Stop"], "the rest of the drive was sent after the stop"
    assert pose(later(world, sim)) == pose(held)



def test_pause_halts_a_drive_under_a_speed_limit_and_continue_drives_the_rest_at_the_limit(world, sim, control, hold,
                                                                                         backend):
    from rockly_desktop.robot.wrappers.limits import LimitedBackend, Limits

    limited = Hobbit(LimitedBackend(backend, Limits(max_speed=0.1), ["/cmd_vel"]))
    twists = record(world, "/cmd_vel")
    drive = Background(lambda: limited.drive(1.0))
    eventually_in(world, lambda: sim.snapshot()["x"] > 0.1)
    control.request_pause()

    held = hold.wait_until_held()
    assert held["linear"] == 0.0
    assert 0.1 < held["x"] < 1.0 - POSITION
    assert pose(later(world, sim)) == pose(held), "the base moved while the program held"

    control.resume()
    assert drive.join().error is None
    assert sim.snapshot()["x"] == pytest.approx(1.0, abs=0.005)
    assert len(hold.snapshots) == 1
    assert all(0.0 <= message["linear"]["x"] <= 0.1 for _topic, message in twists)

# --- blocks and commands agree -------------------------------------------------------------------

CHOICES_BY_BLOCK = {
    ("hobbit_move", "direction"): api.DIRECTIONS,
    ("hobbit_turn", "direction"): api.TURN_DIRECTIONS,
    ("hobbit_arm_move", "movement"): api.ARM_POSITIONS,
    ("hobbit_arm_turntable", "movement"): api.TURNTABLE_ACTIONS,
    ("hobbit_arm_gripper", "movement"): api.GRIPPER_ACTIONS,
}


@pytest.fixture(scope="module")
def profile():
    return load_profile(HOBBIT_DIR, SHARED_TOOLBOXES)


def dropdown(profile, block_type, name):
    return [option[1] for arg in profile.block(block_type).definition["args0"] if arg.get("name") == name
            for option in arg["options"]]


def test_every_block_template_calls_a_public_hobbit_or_ros_command(profile):
    from rockly_desktop.robot.ros_commands import RosCommands

    for spec in profile.blocks:
        calls = re.findall(r"\b(robot|ros)\.(\w+)\(", spec.code)
        assert calls, spec.type
        for owner, name in calls:
            commands = Hobbit if owner == "robot" else RosCommands
            assert not name.startswith("_") and callable(getattr(commands, name, None)), (spec.type, name)


@pytest.mark.parametrize("block_type, field", sorted(CHOICES_BY_BLOCK))
def test_block_values_map_to_valid_command_choices(profile, block_type, field):
    mapping = profile.block(block_type).values[field]
    assert set(mapping.values()) == set(CHOICES_BY_BLOCK[(block_type, field)])


def test_mapped_arm_values_reach_the_robot_as_the_same_arm_command(profile):
    """Block value MoveToX -> Python 'x' -> arm command MoveToX: the round trip is the identity."""
    for block_type in ("hobbit_arm_move", "hobbit_arm_turntable", "hobbit_arm_gripper"):
        table = {**api.ARM_POSITIONS, **api.TURNTABLE_ACTIONS, **api.GRIPPER_ACTIONS}
        for block_value, python_value in profile.block(block_type).values["movement"].items():
            assert table[python_value] == block_value


@pytest.mark.parametrize("block_type, field, choices", [
    ("hobbit_head", "head_position", api.HEAD_POSITIONS),
    ("hobbit_emo", "emotion", api.EMOTIONS),
    ("hobbit_volume", "change", api.VOLUME_CHANGES),
    ("ROS_publisher", "message_type", api.MESSAGE_TYPES),
])
def test_dropdown_values_passed_unmapped_are_valid_command_choices(profile, block_type, field, choices):
    assert field not in profile.block(block_type).values
    assert set(dropdown(profile, block_type, field)) == set(choices)


def test_call_service_takes_json_parameters_and_can_leave_them_out(tablet, backend, hobbit):
    hobbit.call_service("/MMUI", "hobbit_msgs/Request", '{"params": [{"name": "type", "value": "F_LOUDER"}]}')
    with pytest.raises(RobotCommandError, match="request type None"):  # the tablet needs its parameters
        hobbit.call_service("/MMUI", "hobbit_msgs/Request", '{"params": [{"name": "type", "value": "F_QUIETER"}]}',
                            with_parameters=False)
    assert [call[2] for call in backend.service_calls] == [{"params": [{"name": "type", "value": "F_LOUDER"}]}, {}]
    with pytest.raises(RobotCommandError, match="not valid JSON"):
        hobbit.call_service("/MMUI", "hobbit_msgs/Request", "{params")
