"""HOBBIT's commands (plugins/hobbit/rockly_hobbit/api.py): argument checks and what reaches the robot."""
import importlib.util
import math
import re

import pytest
from profile_copies import HOBBIT_DIR, SHARED_TOOLBOXES

from rockly_desktop.core.errors import RobotCommandError
from rockly_desktop.plugins.profile import load_profile
from rockly_desktop.robot.interface import GoalHandle, GoalOutcome, GoalStatus, RobotBackend


def _load_api_module():
    """Import api.py by its path, leaving sys.path and sys.modules as they were."""
    spec = importlib.util.spec_from_file_location("hobbit_api_under_test", HOBBIT_DIR / "rockly_hobbit" / "api.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


api = _load_api_module()
Hobbit = api.Hobbit


class RecordingGoal(GoalHandle):
    def __init__(self, status):
        self.status = status

    def wait(self, timeout):
        return GoalOutcome(self.status, {})

    def cancel(self):
        pass


class RecordingBackend(RobotBackend):
    """Records every call; answers services, goals and state topics as a test scripts them.

    Minimal stand-in until the simulator exists.
    """

    def __init__(self, service_response=None, goal_status=GoalStatus.SUCCEEDED, motion_states=("Moving", "Idle")):
        self.calls = []
        self.service_response = service_response if service_response is not None else {"params": []}
        self.goal_status = goal_status
        self.motion_states = list(motion_states)
        self.latest_messages = {}

    def publish(self, topic, msg_type, message):
        self.calls.append(("publish", topic, msg_type, message))

    def latest(self, topic, msg_type):
        return self.latest_messages.get(topic)

    def wait_for_message(self, topic, msg_type, timeout):
        self.calls.append(("wait_for_message", topic, msg_type))
        message = {"data": self.motion_states.pop(0)}
        self.latest_messages[topic] = message
        return message

    def call_service(self, name, srv_type, request, timeout):
        self.calls.append(("call_service", name, srv_type, request, timeout))
        return self.service_response

    def send_goal(self, action, action_type, goal, feedback=None):
        self.calls.append(("send_goal", action, action_type, goal))
        return RecordingGoal(self.goal_status)

    def sleep(self, seconds):
        self.calls.append(("sleep", seconds))

    def cancel_all_goals(self, action):
        self.calls.append(("cancel_all_goals", action))


@pytest.fixture
def backend():
    return RecordingBackend()


@pytest.fixture
def robot(backend):
    return Hobbit(backend)


def mmui_params(call) -> dict:
    """The MMUI request's params as {name: value}."""
    kind, name, srv_type, request, timeout = call
    assert (kind, name, srv_type) == ("call_service", "/MMUI", "hobbit_msgs/Request")
    return {param["name"]: param["value"] for param in request["params"]}


# --- refused arguments ------------------------------------------------------------------------


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
def test_unknown_choice_is_refused_listing_the_valid_ones(robot, backend, command, argument, what, choices):
    with pytest.raises(RobotCommandError) as caught:
        getattr(robot, command)(argument)
    message = str(caught.value)
    assert message.startswith(f"unknown {what} {argument!r}; use one of ")
    assert message.endswith(", ".join(repr(choice) for choice in choices))
    assert backend.calls == [], "a refused command sends nothing to the robot"


@pytest.mark.parametrize("command, args, what, bad, choices", [
    ("drive", (1, "sideways"), "direction", "sideways", ["forward", "backward"]),
    ("drive", (1, "+"), "direction", "+", ["forward", "backward"]),
    ("turn", (90, "up"), "direction", "up", ["left", "right"]),
    ("publish", ("/chatter", "Int32", 1), "message type", "Int32", ["String", "Bool", "Float64", "Int64", "UInt64"]),
])
def test_unknown_direction_or_type_is_refused_listing_the_valid_ones(robot, backend, command, args, what, bad, choices):
    with pytest.raises(RobotCommandError) as caught:
        getattr(robot, command)(*args)
    listed = ", ".join(repr(choice) for choice in choices)
    assert str(caught.value) == f"unknown {what} {bad!r}; use one of {listed}"
    assert backend.calls == []


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
def test_non_number_is_refused_naming_what_it_should_be(robot, backend, command, args, what):
    with pytest.raises(RobotCommandError) as caught:
        getattr(robot, command)(*args)
    bad = next(value for value in args if not isinstance(value, (int, float)) or isinstance(value, bool))
    assert str(caught.value) == f"{what} must be a number, not {bad!r}"
    assert backend.calls == []


@pytest.mark.parametrize("joints", [[0, 0, 0, 0, 0], [0] * 7, [], "123456", 6, None],
                         ids=["five", "seven", "none", "a string", "a number", "null"])
def test_arm_joints_need_exactly_six_values(robot, backend, joints):
    with pytest.raises(RobotCommandError, match=r"^the arm needs exactly 6 joint values, not "):
        robot.move_arm_to_joints(joints)
    assert backend.calls == []


def test_arm_joint_that_is_not_a_number_is_refused(robot, backend):
    with pytest.raises(RobotCommandError, match=r"^a joint value must be a number, not 'x'$"):
        robot.move_arm_to_joints([0, 0, "x", 0, 0, 0])
    assert backend.calls == []


# --- what reaches the robot ------------------------------------------------------------------


def test_look_publishes_the_head_position(robot, backend):
    robot.look("up_left")
    assert backend.calls == [("publish", "/head/move", "std_msgs/String", {"data": "up_left"})]


def test_show_emotion_publishes_the_emotion(robot, backend):
    robot.show_emotion("VHAPPY")
    assert backend.calls == [("publish", "/head/emo", "std_msgs/String", {"data": "VHAPPY"})]


@pytest.mark.parametrize("command, argument, arm_command", [
    ("gripper", "open", "OpenGripper"),
    ("gripper", "close", "CloseGripper"),
    ("move_arm", "floor", "MoveToPreGraspFloor"),
    ("move_arm", "candle", "MoveToCandle"),
    ("turntable", "counterclockwise", "TurnTurntableCCW"),
    ("turntable", "learn", "MoveToLearning"),
])
def test_arm_commands_send_a_goal_to_the_arm_server(robot, backend, command, argument, arm_command):
    getattr(robot, command)(argument)
    assert backend.calls == [("send_goal", "hobbit_arm", "hobbit_msgs/ArmServerAction",
                              {"command": {"data": arm_command}, "velocity": 0.0, "joints": []})]


def test_arm_joints_are_sent_as_one_joint_vector(robot, backend):
    robot.move_arm_to_joints((10, 20.5, -30, 0, 45, 90))
    assert backend.calls == [("send_goal", "hobbit_arm", "hobbit_msgs/ArmServerAction",
                              {"command": {"data": "MoveToJointValues"}, "velocity": 0.0,
                               "joints": [{"joint_values": [10.0, 20.5, -30.0, 0.0, 45.0, 90.0]}]})]


@pytest.mark.parametrize("status", [GoalStatus.ABORTED, GoalStatus.PREEMPTED, GoalStatus.REJECTED])
def test_arm_goal_that_does_not_succeed_raises(status):
    robot = Hobbit(RecordingBackend(goal_status=status))
    with pytest.raises(RobotCommandError) as caught:
        robot.gripper("close")
    assert str(caught.value) == f"the robot could not finish the arm command CloseGripper ({status.value})"


@pytest.mark.parametrize("command, args, motion", [
    ("drive", (2, "forward"), "Move 2"),
    ("drive", (0.5, "backward"), "Move -0.5"),
    ("turn", (90, "left"), "Turn 90"),
    ("turn", (180, "right"), "Turn -180"),
])
def test_drive_and_turn_send_a_discrete_motion_and_wait_until_idle(robot, backend, command, args, motion):
    getattr(robot, command)(*args)
    assert backend.calls == [
        ("publish", "/DiscreteMotionCmd", "std_msgs/String", {"data": motion}),
        ("wait_for_message", "/DiscreteMotionState", "std_msgs/String"),
        ("wait_for_message", "/DiscreteMotionState", "std_msgs/String"),
    ]
    assert backend.motion_states == []


def test_stop_halts_discrete_motion_and_velocity(robot, backend):
    robot.stop()
    assert backend.calls == [("publish", "/DiscreteMotionCmd", "std_msgs/String", {"data": "Stop"}),
                             ("publish", "/cmd_vel", "geometry_msgs/Twist", {})]


def test_navigate_to_sends_a_map_pose_facing_the_heading(robot, backend):
    robot.navigate_to(1.5, -2, 90)
    (kind, action, action_type, goal), = backend.calls
    assert (kind, action, action_type) == ("send_goal", "move_base", "move_base_msgs/MoveBaseAction")
    pose = goal["target_pose"]
    assert pose["header"] == {"frame_id": "map"}
    assert pose["pose"]["position"] == {"x": 1.5, "y": -2.0, "z": 0.0}
    orientation = pose["pose"]["orientation"]
    assert (orientation["x"], orientation["y"]) == (0.0, 0.0)
    assert orientation["z"] == pytest.approx(math.sqrt(0.5))
    assert orientation["w"] == pytest.approx(math.sqrt(0.5))


TABLET_TEXTS = ['He said "hello"', "it's me", "first line\nsecond line", "Grüße, 日本語 😀", "a\\b {x} %s", ""]


@pytest.mark.parametrize("text", TABLET_TEXTS)
def test_show_info_sends_the_text_exactly_as_given(robot, backend, text):
    robot.show_info(text)
    (call,) = backend.calls
    params = mmui_params(call)
    assert params["type"] == "D_PLAIN"
    assert params["text"] == text
    assert params["speak"] == text
    assert call[3]["sessionID"] == "0"


def test_show_info_and_wait_asks_for_ok(robot, backend):
    robot.show_info_and_wait("Ready?")
    assert mmui_params(backend.calls[0])["type"] == "D_OK"


@pytest.mark.parametrize("answer, expected", [("yes", True), ("Yes ", True), ("no", False), ("", False)])
def test_ask_yes_no_is_true_only_for_a_yes_answer(answer, expected):
    backend = RecordingBackend(service_response={"params": [{"name": "type", "value": "D_YES_NO"},
                                                            {"name": "result", "value": answer}]})
    assert Hobbit(backend).ask_yes_no("Shall we play?") is expected
    params = mmui_params(backend.calls[0])
    assert (params["type"], params["text"]) == ("D_YES_NO", "Shall we play?")


def test_ask_yes_no_without_an_answer_is_false():
    assert Hobbit(RecordingBackend(service_response={})).ask_yes_no("Hello?") is False


def test_ask_text_returns_what_was_typed(backend):
    backend.service_response = {"params": [{"name": "result", "value": "Anna Grüße"}]}
    assert Hobbit(backend).ask_text("What is your name?") == "Anna Grüße"
    assert mmui_params(backend.calls[0])["type"] == "D_NAME"


@pytest.mark.parametrize("change, function", [("louder", "F_LOUDER"), ("quieter", "F_QUIETER")])
def test_volume_change_calls_the_tablet_function(robot, backend, change, function):
    robot.change_volume(change)
    assert mmui_params(backend.calls[0]) == {"type": function}


def test_publish_sends_a_std_msgs_message(robot, backend):
    robot.publish("/chatter", "Float64", 1.5)
    assert backend.calls == [("publish", "/chatter", "std_msgs/Float64", {"data": 1.5})]


def test_wait_sleeps_and_never_backwards(robot, backend):
    robot.wait(2)
    robot.wait(-3)
    assert backend.calls == [("sleep", 2.0), ("sleep", 0.0)]


def test_call_service_passes_the_parameters_and_returns_the_answer(backend):
    backend.service_response = {"success": True, "message": "done"}
    answer = Hobbit(backend).call_service("/reset", "std_srvs/Trigger", {"force": 1})
    assert answer == {"success": True, "message": "done"}
    assert backend.calls == [("call_service", "/reset", "std_srvs/Trigger", {"force": 1}, api.DIALOG_TIMEOUT)]


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


def test_every_block_template_calls_a_public_hobbit_command(profile):
    for spec in profile.blocks:
        names = re.findall(r"\brobot\.(\w+)\(", spec.code)
        assert names, spec.type
        for name in names:
            assert not name.startswith("_") and callable(getattr(Hobbit, name, None)), (spec.type, name)


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
