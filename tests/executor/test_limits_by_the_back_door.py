"""The ways around a teacher's limits, closed on the real simulator: velocities of other types or that
are no numbers, a switched-off part reached by its action's own names, motions at the robot's own
speed, and a profile under another id."""
import math

import pytest
from profile_copies import copy_profile

from rockly_desktop.core.errors import ManifestError
from rockly_desktop.core.paths import shared_toolboxes_dir
from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.run_setup import limits_line, make_runner
from rockly_desktop.profiles.profile import load_profile
from rockly_desktop.robot.sim.link import SimulatedRobot
from rockly_desktop.robot.sim.simulator import twist_velocity
from rockly_desktop.robot.wrappers.limits import Limits
from rockly_desktop.settings.teacher import TeacherSettings

ARM_OFF = Limits(switched_off=frozenset({"arm"}))


@pytest.fixture
def robot(hobbit):
    robot = SimulatedRobot(hobbit, speed=1.0)
    yield robot
    robot.shutdown()


def run(profile, robot, code, limits=None, language="en"):
    return make_runner(profile, robot, {"code": code, "variables": {}}, RunControl(), lambda event: None,
                       language, limits).run()


def heard(robot, topic):
    seen = []
    robot.world.subscribe(topic, seen.append)
    return seen


# --- item 2: what a limit cannot keep, and what a simulator would not get from a real ROS ---------------

@pytest.mark.parametrize("value", ["1.0", True, [1.0], None])
def test_a_simulated_robot_takes_no_text_or_bool_for_a_speed(value):
    assert twist_velocity({"linear": {"x": value}}) is None
    assert twist_velocity({"twist": {"angular": {"z": value}}}) is None
    assert twist_velocity({"linear": {"x": 1}, "angular": {"z": 0.5}}) == (1.0, 0.5)


@pytest.mark.parametrize(("msg_type", "value", "language", "message"), [
    ("lab_msgs/Twist", 1.0, "en", "the simulated robot listens on /cmd_vel for geometry_msgs/Twist, not lab_msgs/Twist:"
                                  " a real ROS would not deliver this message either"),
    ("lab_msgs/Twist", 1.0, "de", "Der simulierte Roboter hört auf /cmd_vel auf geometry_msgs/Twist, nicht auf "
                                  "lab_msgs/Twist: ein echtes ROS würde diese Nachricht auch nicht zustellen"),
    ("geometry_msgs/Twist", "1.0", "en", "a real ROS would refuse this geometry_msgs/Twist on /cmd_vel: "
                                         "the field linear.x needs a number, not '1.0'"),
    ("geometry_msgs/Twist", True, "en", "a real ROS would refuse this geometry_msgs/Twist on /cmd_vel: "
                                        "the field linear.x needs a number, not True"),
])
def test_the_simulator_refuses_a_velocity_a_real_ros_would_not_deliver(hobbit, robot, msg_type, value, language,
                                                                       message):
    seen, start = heard(robot, "/cmd_vel"), robot.snapshot()
    code = f"robot.backend.publish('/cmd_vel', {msg_type!r}, {{'linear': {{'x': {value!r}}}}})\n"
    result = run(hobbit, robot, code, language=language)
    assert result.outcome == "error" and result.message.endswith(message)
    assert all(twist_velocity(twist) == (0.0, 0.0) for twist in seen)  # only the safe stop's
    assert robot.snapshot()["x"] == start["x"]


@pytest.mark.parametrize(("msg_type", "message", "said"), [
    ("lab_msgs/Twist", {"linear": {"x": 1.0}}, "can only be kept on /cmd_vel for geometry_msgs/Twist / "
                                               "geometry_msgs/TwistStamped, not for lab_msgs/Twist"),
    ("geometry_msgs/Twist", {"linear": {"x": "1.0"}}, "needs real numbers on /cmd_vel: linear.x is '1.0'"),
    ("geometry_msgs/Twist", {"angular": {"z": True}}, "needs real numbers on /cmd_vel: angular.z is True"),
    ("geometry_msgs/Twist", {"linear": 5}, "needs real numbers on /cmd_vel: linear is 5"),
    ("geometry_msgs/TwistStamped", {"twist": {"linear": {"x": "2"}}}, "twist.linear.x is '2'"),
    ("geometry_msgs/Twist", {"twist": {"linear": {"x": 2.0}}}, "twist is"),
])
def test_under_a_speed_limit_only_a_twist_of_numbers_passes(hobbit, robot, msg_type, message, said):
    seen = heard(robot, "/cmd_vel")
    result = run(hobbit, robot, f"robot.backend.publish('/cmd_vel', {msg_type!r}, {message!r})\n",
                 Limits(max_speed=0.1))
    assert result.outcome == "error" and said in result.message
    assert all(twist_velocity(twist) == (0.0, 0.0) for twist in seen)


def test_a_ros_2_type_name_of_a_twist_is_clamped_like_the_twist(hobbit, robot):
    seen = heard(robot, "/cmd_vel")
    code = "robot.backend.publish('/cmd_vel', 'geometry_msgs/msg/Twist', {'linear': {'x': 2.0}})\n"
    assert run(hobbit, robot, code, Limits(max_speed=0.1)).outcome == "finished"
    assert twist_velocity(seen[0]) == (0.1, 0.0)


# --- item 3: a switched-off part by its action's own names; motions at the robot's own speed ---------

@pytest.mark.parametrize("code", [
    "robot.backend.publish('/hobbit_arm/goal', 'hobbit_msgs/ArmServerActionGoal', {})",
    "robot.backend.publish('hobbit_arm/goal', 'hobbit_msgs/ArmServerActionGoal', {})",
    "robot.backend.call_service('/hobbit_arm/_action/send_goal', 'hobbit_msgs/ArmServer_SendGoal', {}, 1)",
    "robot.backend.call_service('hobbit_arm/_action/get_result', 'hobbit_msgs/ArmServer_GetResult', {}, 1)",
    "ros.send_goal('/hobbit_arm', 'hobbit_msgs/ArmServerAction', {'command': {'data': 'MoveToCandle'}})",
])
def test_a_switched_off_arm_is_refused_by_every_name_of_its_action(hobbit, robot, code):
    goals, arm = heard(robot, "/hobbit_arm/goal"), robot.snapshot()["arm"]
    result = run(hobbit, robot, code + "\n", ARM_OFF)
    assert result.message.endswith("the teacher switched off “Arm and gripper” for this robot")
    assert goals == [] and robot.snapshot()["arm"] == arm and robot.snapshot()["arm_target"] is None


def test_cancelling_a_switched_off_arm_still_passes(hobbit, robot):
    code = "robot.backend.publish('/hobbit_arm/cancel', 'actionlib_msgs/GoalID', {})\nros.cancel_goals('hobbit_arm')\n"
    assert run(hobbit, robot, code, ARM_OFF).outcome == "finished"


@pytest.mark.parametrize("code", [
    "robot.publish('/DiscreteMotionCmd', 'String', 'Move 2')",
    "ros.publish('DiscreteMotionCmd', 'String', 'Turn 180')",
    "ros.send_goal('move_base', 'move_base_msgs/MoveBaseAction', {})",
    "robot.backend.publish('/move_base/goal', 'move_base_msgs/MoveBaseActionGoal', {})",
    "robot.backend.publish('/move_base_simple/goal', 'geometry_msgs/PoseStamped', {})",
])
@pytest.mark.parametrize(("limits", "language", "said"), [
    (Limits(max_speed=0.1), "en", "moves the robot at its own speed, which the teacher's speed limit cannot slow "
                                  "down; drive with velocity commands (the drive and turn blocks) instead"),
    (Limits(max_turn=10), "de", "bewegt den Roboter mit seinem eigenen Tempo, das die Tempogrenze der Lehrkraft "
                                "nicht bremsen kann"),
])
def test_motions_at_the_bases_own_speed_are_refused_under_a_lower_limit(hobbit, robot, code, limits, language, said):
    commands, start = heard(robot, "/DiscreteMotionCmd"), robot.snapshot()
    result = run(hobbit, robot, code + "\n", limits, language)
    assert result.outcome == "error" and said in result.message
    assert set(message["data"] for message in commands) <= {"Stop"}
    end = robot.snapshot()
    assert (end["x"], end["theta"], end["nav_goal"]) == (start["x"], start["theta"], None)


def test_at_or_above_the_bases_own_speeds_a_discrete_motion_and_a_stop_pass(hobbit, robot):
    commands = heard(robot, "/DiscreteMotionCmd")
    code = "robot.publish('/DiscreteMotionCmd', 'String', 'Move 0.01')\nrobot.stop()\n"
    assert run(hobbit, robot, code, Limits(max_speed=0.3, max_turn=45)).outcome == "finished"
    assert [message["data"] for message in commands][:2] == ["Move 0.01", "Stop"]
    assert run(hobbit, robot, "robot.stop()\n", Limits(max_speed=0.1)).outcome == "finished"


def test_a_drive_under_only_a_turn_limit_goes_by_velocity_and_ends_where_asked(hobbit):
    robot = SimulatedRobot(hobbit, speed=20.0)
    try:
        commands = heard(robot, "/DiscreteMotionCmd")
        start = robot.snapshot()
        result = run(hobbit, robot, "robot.drive(0.5)\n", Limits(max_turn=20))
        end = robot.snapshot()
    finally:
        robot.shutdown()
    assert result.outcome == "finished", result.message
    assert set(message["data"] for message in commands) <= {"Stop"}
    assert math.hypot(end["x"] - start["x"], end["y"] - start["y"]) == pytest.approx(0.5, abs=0.005)


@pytest.mark.parametrize(("own_speed", "problem"), [
    ({"speed": -1}, "'speed' must be a number above zero"),
    ({"turn": True}, "'turn' must be a number above zero"),
    ({"topics": "/DiscreteMotionCmd"}, "'topics' must be a list of names"),
    ({"fast": 1}, "unknown key(s) ['fast']"),
])
def test_a_wrong_own_speed_in_a_manifest_is_named(tmp_path, own_speed, problem):
    copy = copy_profile(tmp_path / "robo", "robo")
    copy.edit("profile.yaml", lambda data: data.update(own_speed=own_speed))
    with pytest.raises(ManifestError, match="own_speed") as caught:
        load_profile(copy.root, shared_toolboxes_dir())
    assert problem in str(caught.value)


# --- item 4: a profile without limits of its own ------------------------------------------------------------

class Store(dict):
    """A plain value/setValue store, as TeacherSettings needs (no allKeys)."""

    def value(self, key):
        return self.get(key)

    def setValue(self, key, value):
        self[key] = value


def test_a_profile_without_its_own_limits_gets_the_strictest_ones_set():
    teacher = TeacherSettings(Store())
    assert teacher.limits("hobbit_copy").is_open  # nothing set anywhere: nothing limited
    teacher.set_limits("hobbit", max_speed=0.2, max_turn=30, switched_off={"arm"})
    teacher.set_limits("turtlebot", max_speed=0.1, switched_off={"lidar"})
    assert teacher.limits("hobbit_copy") == Limits(0.1, 30, frozenset({"arm", "lidar"}))
    assert teacher.switched_off("hobbit_copy") == ["arm", "lidar"]
    assert not teacher.has_own_limits("hobbit_copy") and teacher.has_own_limits("hobbit")
    teacher.set_limits("hobbit_copy")  # the teacher's own choice for it: nothing limited
    assert teacher.limits("hobbit_copy").is_open
    assert teacher.limits("hobbit") == Limits(0.2, 30, frozenset({"arm"}))


def test_limits_kept_before_the_list_of_limited_profiles_are_found_too(tmp_path):
    from PySide6.QtCore import QSettings

    store = QSettings(str(tmp_path / "old.ini"), QSettings.Format.IniFormat)
    for key, value in (("max_speed", 0.15), ("max_turn", ""), ("switched_off", "arm")):
        store.setValue(f"teacher/hobbit/{key}", value)
    assert TeacherSettings(store).limits("anything") == Limits(0.15, None, frozenset({"arm"}))


def test_a_copy_of_hobbits_profile_runs_under_hobbits_limits(tmp_path):
    copy = copy_profile(tmp_path / "hobbit_copy", "hobbit_copy")
    (copy.root / "rockly_hobbit").rename(copy.root / "rockly_hobbit_copy")  # one module name, one profile per process
    renamed = {field: ("rockly_hobbit", "rockly_hobbit_copy") for field in ("api", "simulator", "simulator_view")}
    copy.edit("profile.yaml", lambda data: data.update({field: data[field].replace(*names)
                                                        for field, names in renamed.items()}))
    profile = load_profile(copy.root, shared_toolboxes_dir())
    teacher = TeacherSettings(Store())
    teacher.set_limits("hobbit", max_speed=0.1, switched_off={"arm"})
    limits = teacher.limits(profile.id)
    assert limits_line(profile, limits, "en") == ("The teacher's limits apply: driving at most 0.1 m/s; "
                                                  "switched off: Arm and gripper.")
    robot = SimulatedRobot(profile)
    try:
        result = run(profile, robot, "robot.gripper('open')\n", limits)
    finally:
        robot.shutdown()
    assert result.message.endswith("the teacher switched off “Arm and gripper” for this robot")
