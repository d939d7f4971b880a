"""The simulated HOBBIT (profiles/hobbit/rockly_hobbit/sim.py), driven through the real HOBBIT commands.

Every test runs the simulator's own clock (real threads) at SPEED times real time and
waits on conditions, never for a fixed time.
"""
import math
import sys
import threading
import time

import pytest
from background import Background
from profile_copies import HOBBIT_DIR, SHARED_TOOLBOXES
from sim_tools import eventually_in, later, pose

from rockly_desktop.core.errors import ProgramStopped, RobotCommandError, RobotTimeout
from rockly_desktop.profiles.profile import load_profile
from rockly_desktop.robot.interface import GoalStatus
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.safe_stop import run_safe_stop
from rockly_desktop.robot.sim.sim_world import SimBackend, SimWorld
from rockly_desktop.robot.sim.tablet import TabletQuestion

PROFILE = load_profile(HOBBIT_DIR, SHARED_TOOLBOXES)


def _load(module_name):
    """A module of HOBBIT's package ``rockly_hobbit``, imported the way Rockly imports the profile."""
    PROFILE.load_object("simulator" if module_name == "sim" else "api")
    return sys.modules[f"rockly_hobbit.{module_name}"]


api = _load("api")
sim_module = _load("sim")
Hobbit, SimHobbit = api.Hobbit, sim_module.SimHobbit

SPEED = 25
STOP_BOUND = 0.05  # s from a stop request to ProgramStopped in the program's thread
POSITION = 0.02    # m
ANGLE = 2.0        # degrees
ARM = "hobbit_arm", "hobbit_msgs/ArmServerAction"
NAV = "move_base", "move_base_msgs/MoveBaseAction"
TABLET_TEXTS = ['He said "hello"', "it's me", "first line\nsecond line", "Grüße, 日本語 😀", "a\\b {x} %s",
                "  spaced\tout \n", ""]


class ScriptedTablet:
    """The person at the tablet: answers from a list; records what was asked, shown and announced."""

    def __init__(self, answers=()):
        self.answers = list(answers)
        self.asked = []
        self.notices = []
        self.shown_while_asking = []
        self.robot = None

    def ask(self, question, text, timeout, interrupt):
        self.asked.append((question, text, timeout))
        self.shown_while_asking.append(self.robot.snapshot()["tablet"])
        return self.answers.pop(0)

    def notify(self, text):
        self.notices.append(text)


class SilentTablet:
    """A tablet nobody answers: ``ask`` waits (interruptibly) until its timeout."""

    def __init__(self):
        self.asking = threading.Event()

    def ask(self, question, text, timeout, interrupt):
        self.asking.set()
        interrupt.wait_until(lambda: False, timeout)
        raise RobotTimeout("nobody answered")

    def notify(self, text):
        pass


@pytest.fixture
def world():
    return SimWorld()


@pytest.fixture
def tablet():
    return ScriptedTablet()


@pytest.fixture
def sim(world, tablet):
    robot = SimHobbit(world, tablet=tablet, speed=SPEED)
    tablet.robot = robot
    robot.start()
    yield robot
    robot.safe_stop()
    robot.shutdown()


@pytest.fixture
def interrupt():
    return Interrupt()


@pytest.fixture
def backend(world, interrupt, sim):
    return SimBackend(world, interrupt)


@pytest.fixture
def hobbit(backend):
    return Hobbit(backend)


def record(world, topic):
    """The ``data`` of every later message on ``topic``, in order."""
    seen = []
    world.subscribe(topic, lambda message: seen.append(message.get("data")))
    return seen


def record_snapshots(world, sim):
    """``sim.snapshot()`` at every later simulator tick."""
    seen = []
    world.subscribe("/odom", lambda message: seen.append(sim.snapshot()))
    return seen


def quaternion(degrees):
    yaw = math.radians(degrees)
    return 0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2)


def nav_goal(x, y, degrees):
    qx, qy, qz, qw = quaternion(degrees)
    return {"target_pose": {"header": {"frame_id": "map"}, "pose": {
        "position": {"x": x, "y": y, "z": 0.0}, "orientation": {"x": qx, "y": qy, "z": qz, "w": qw}}}}


def arm_goal(command, joints=()):
    return {"command": {"data": command}, "velocity": 0.0, "joints": [{"joint_values": list(v)} for v in joints]}


# --- start-up -----------------------------------------------------------------------------


def test_starts_at_home_with_its_topics_published(world, sim):
    state = sim.snapshot()
    assert pose(state) == (0.0, 0.0, 0.0)
    assert {key: state[key] for key in ("motion", "nav_goal", "head", "emotion", "arm", "arm_target", "gripper",
                                        "turntable", "battery", "tablet", "notices")} == {
        "motion": "idle", "nav_goal": None, "head": "center_center", "emotion": "NEUTRAL", "arm": "home",
        "arm_target": None, "gripper": "closed", "turntable": "stored", "battery": 100.0, "tablet": None,
        "notices": []}
    assert world.latest("/DiscreteMotionState") == {"data": "Idle"}
    assert world.latest("/bumper") == {"data": False}
    assert world.latest("/battery_state")["percentage"] == 1.0
    assert world.latest("/odom")["pose"]["pose"]["position"] == {"x": 0.0, "y": 0.0, "z": 0.0}


def test_simulated_time_runs_at_the_given_speed(world, sim):
    started_real, started_sim = time.monotonic(), sim.snapshot()["time"]
    state = later(world, sim, 5.0)
    real = time.monotonic() - started_real
    assert state["time"] - started_sim == pytest.approx(real * SPEED, rel=0.5)


def test_speed_must_be_positive(world):
    with pytest.raises(ValueError, match="the simulation speed must be positive, not 0"):
        SimHobbit(world, speed=0)


def test_starting_twice_is_refused(sim):
    with pytest.raises(RuntimeError, match="the simulated HOBBIT was already started"):
        sim.start()


def test_profile_names_the_simulator():
    assert load_profile(HOBBIT_DIR, SHARED_TOOLBOXES).manifest["simulator"] == "rockly_hobbit.sim:SimHobbit"


def test_profile_simulator_loads_as_the_simulator_class(monkeypatch):
    monkeypatch.setattr(sys, "path", list(sys.path))
    before = set(sys.modules)
    try:
        simulator = load_profile(HOBBIT_DIR, SHARED_TOOLBOXES).load_object("simulator")
        assert (simulator.__module__, simulator.__name__) == ("rockly_hobbit.sim", "SimHobbit")
    finally:
        for name in set(sys.modules) - before:
            if name.startswith("rockly_hobbit"):
                del sys.modules[name]


# --- driving and turning ----------------------------------------------------------------------


def test_drive_forward_one_metre(world, sim, hobbit):
    states = record(world, "/DiscreteMotionState")
    hobbit.drive(1, "forward")
    state = sim.snapshot()
    assert (state["x"], state["y"]) == (pytest.approx(1.0, abs=POSITION), pytest.approx(0.0, abs=POSITION))
    assert math.degrees(state["theta"]) == pytest.approx(0.0, abs=ANGLE)
    assert (state["motion"], state["linear"], state["angular"]) == ("idle", 0.0, 0.0)
    assert states == ["Moving", "Idle"]


def test_drive_takes_the_time_the_base_needs(world, sim, hobbit):
    started = sim.snapshot()["time"]
    hobbit.drive(1.5)
    assert sim.snapshot()["time"] - started >= 1.5 / sim_module.LINEAR_SPEED


def test_drive_backward_half_a_metre(sim, hobbit):
    hobbit.drive(0.5, "backward")
    state = sim.snapshot()
    assert (state["x"], state["y"]) == (pytest.approx(-0.5, abs=POSITION), pytest.approx(0.0, abs=POSITION))


def test_drive_leaves_a_trail(sim, hobbit):
    hobbit.drive(1)
    trail = sim.snapshot()["trail"]
    assert trail[0] == (0.0, 0.0) and len(trail) >= 3
    assert trail[-1] == pytest.approx((1.0, 0.0), abs=POSITION)
    assert all(y == pytest.approx(0.0, abs=1e-9) for _x, y in trail)


def test_drive_zero_metres_does_nothing_and_ends(world, sim, hobbit):
    commands = record(world, "/DiscreteMotionCmd")
    hobbit.drive(0)
    assert pose(sim.snapshot()) == (0.0, 0.0, 0.0)
    assert commands == []


def test_a_very_short_drive_is_not_missed(world, sim, hobbit):
    states = record(world, "/DiscreteMotionState")
    hobbit.drive(0.01)
    assert states == ["Moving", "Idle"]


def test_even_a_zero_motion_reports_idle_a_whole_control_cycle_after_the_command(world, sim):
    """So a program that starts listening for Idle just after sending the command cannot miss it."""
    seen = []
    world.subscribe("/DiscreteMotionState", lambda message: seen.append(message["data"]))
    world.subscribe("/odom", lambda message: seen.append("tick"))
    world.publish("/DiscreteMotionCmd", "std_msgs/String", {"data": "Move 0"})
    eventually_in(world, lambda: "Idle" in seen)
    after_command = seen[seen.index("Moving"):]
    assert after_command[:2] == ["Moving", "tick"], after_command
    assert after_command.index("Idle") == 2


@pytest.mark.parametrize("direction, degrees", [("left", 90.0), ("right", -90.0)])
def test_turn_ninety_degrees(world, sim, hobbit, direction, degrees):
    states = record(world, "/DiscreteMotionState")
    hobbit.turn(90, direction)
    state = sim.snapshot()
    assert math.degrees(state["theta"]) == pytest.approx(degrees, abs=ANGLE)
    assert (state["x"], state["y"]) == (0.0, 0.0)
    assert states == ["Turning", "Idle"]


def test_drive_goes_the_way_the_robot_faces(sim, hobbit):
    hobbit.turn(90, "left")
    hobbit.drive(1)
    state = sim.snapshot()
    assert (state["x"], state["y"]) == (pytest.approx(0.0, abs=POSITION), pytest.approx(1.0, abs=POSITION))


def test_odometry_reports_the_pose(world, sim, hobbit):
    hobbit.turn(90, "left")
    hobbit.drive(1)
    eventually_in(world, lambda: world.latest("/odom")["pose"]["pose"]["position"]["y"] > 0.98)
    odom = world.latest("/odom")["pose"]["pose"]
    assert odom["position"]["x"] == pytest.approx(0.0, abs=POSITION)
    assert odom["orientation"]["z"] == pytest.approx(math.sin(math.radians(45)), abs=0.01)
    assert odom["orientation"]["w"] == pytest.approx(math.cos(math.radians(45)), abs=0.01)


def test_malformed_discrete_motion_is_ignored_with_a_warning(world, sim, caplog):
    states = record(world, "/DiscreteMotionState")
    world.publish("/DiscreteMotionCmd", "std_msgs/String", {"data": "Jump 2"})
    world.publish("/DiscreteMotionCmd", "std_msgs/String", {"data": "Move far"})
    assert pose(later(world, sim)) == (0.0, 0.0, 0.0)
    assert states == []
    assert "ignored the discrete motion 'Jump 2'" in caplog.text
    assert "ignored the discrete motion 'Move far'" in caplog.text


# --- velocity ----------------------------------------------------------------------------------


def test_velocity_command_drives_straight_and_shows_in_odometry(world, sim):
    world.publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.3}})
    eventually_in(world, lambda: sim.snapshot()["x"] > 0.5)
    state = sim.snapshot()
    assert (state["motion"], state["linear"], state["y"], state["theta"]) == ("moving", 0.3, 0.0, 0.0)
    assert world.latest("/odom")["twist"]["twist"]["linear"]["x"] == 0.3


def test_velocity_command_turns_on_the_spot(world, sim):
    world.publish("/cmd_vel", "geometry_msgs/Twist", {"angular": {"z": 0.5}})
    eventually_in(world, lambda: sim.snapshot()["theta"] > 0.5)
    state = sim.snapshot()
    assert (state["motion"], state["x"], state["y"], state["angular"]) == ("turning", 0.0, 0.0, 0.5)


def test_velocity_command_follows_a_unicycle_arc(world, sim):
    world.publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.3}, "angular": {"z": 0.3}})
    eventually_in(world, lambda: sim.snapshot()["theta"] > 1.0)
    x, y, theta = pose(sim.snapshot())
    assert math.hypot(x, y - 1.0) == pytest.approx(1.0, abs=1e-9)  # radius v / w around (0, 1)
    assert math.atan2(y - 1.0, x) == pytest.approx(theta - math.pi / 2, abs=1e-9)


def test_stop_halts_a_velocity_command(world, sim, hobbit):
    world.publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.3}})
    eventually_in(world, lambda: sim.snapshot()["x"] > 0.1)
    hobbit.stop()
    stopped = sim.snapshot()
    assert (stopped["motion"], stopped["linear"]) == ("idle", 0.0)
    assert pose(later(world, sim)) == pose(stopped)


def test_stop_from_another_program_ends_a_drive_early(world, sim, hobbit):
    drive = Background(lambda: hobbit.drive(5))
    eventually_in(world, lambda: sim.snapshot()["x"] > 0.2)
    Hobbit(SimBackend(world, Interrupt())).stop()
    assert drive.join().error is None
    stopped = sim.snapshot()
    assert 0.2 < stopped["x"] < 5 and stopped["motion"] == "idle"
    assert pose(later(world, sim)) == pose(stopped)
    assert world.latest("/DiscreteMotionState") == {"data": "Idle"}


# --- navigation ---------------------------------------------------------------------------------


def test_navigate_to_a_position_and_heading(world, sim, hobbit):
    states = record_snapshots(world, sim)
    hobbit.navigate_to(1, 1.2, 90)
    state = sim.snapshot()
    assert (state["x"], state["y"]) == (pytest.approx(1.0, abs=POSITION), pytest.approx(1.2, abs=POSITION))
    assert math.degrees(state["theta"]) == pytest.approx(90.0, abs=ANGLE)
    assert (state["motion"], state["nav_goal"]) == ("idle", None)
    assert ("navigating", (1.0, 1.2)) in [(seen["motion"], seen["nav_goal"]) for seen in states]


def test_navigate_to_a_full_pose(sim, hobbit):
    hobbit.navigate_to_pose(-0.5, 0.5, 0, *quaternion(-45))
    state = sim.snapshot()
    assert (state["x"], state["y"]) == (pytest.approx(-0.5, abs=POSITION), pytest.approx(0.5, abs=POSITION))
    assert math.degrees(state["theta"]) == pytest.approx(-45.0, abs=ANGLE)


def test_navigation_turns_toward_the_goal_before_driving(world, sim, hobbit):
    states = record_snapshots(world, sim)
    hobbit.navigate_to(0, 1, 0)
    assert all(seen["x"] == pytest.approx(0.0, abs=1e-9) for seen in states)
    assert all(seen["theta"] == pytest.approx(math.pi / 2) for seen in states if 0 < seen["y"] < 1)
    assert max(seen["theta"] for seen in states) == pytest.approx(math.pi / 2)
    assert math.degrees(sim.snapshot()["theta"]) == pytest.approx(0.0, abs=ANGLE)


def test_navigation_feedback_is_the_base_position(sim, backend):
    feedback = []
    outcome = backend.send_goal(*NAV, nav_goal(1, 0, 0), feedback.append).wait(10)
    assert (outcome.status, outcome.result) == (GoalStatus.SUCCEEDED, {})
    assert len(feedback) >= 2
    assert {message["base_position"]["header"]["frame_id"] for message in feedback} == {"map"}
    xs = [message["base_position"]["pose"]["position"]["x"] for message in feedback]
    assert xs == sorted(xs) and xs[-1] > 0.5


def test_cancelled_navigation_is_preempted_and_the_base_stops(world, sim, backend):
    handle = backend.send_goal(*NAV, nav_goal(4.5, 0, 0))
    eventually_in(world, lambda: sim.snapshot()["x"] > 0.2)
    handle.cancel()
    assert handle.wait(5).status is GoalStatus.PREEMPTED
    stopped = sim.snapshot()
    assert (stopped["motion"], stopped["nav_goal"], stopped["linear"]) == ("idle", None, 0.0)
    assert pose(later(world, sim)) == pose(stopped)


def test_goal_without_a_valid_orientation_is_aborted(sim, backend):
    goal = nav_goal(1, 1, 0)
    goal["target_pose"]["pose"]["orientation"] = {"x": 0.0, "y": 0.0, "z": 0.0, "w": 0.0}
    assert backend.send_goal(*NAV, goal).wait(5).status is GoalStatus.ABORTED
    assert sim.snapshot()["motion"] == "idle"


def test_simple_goal_topic_drives_there(world, sim):
    world.publish("/move_base_simple/goal", "geometry_msgs/PoseStamped", nav_goal(0.5, -0.5, 180)["target_pose"])
    eventually_in(world, lambda: sim.snapshot()["motion"] == "navigating")
    eventually_in(world, lambda: sim.snapshot()["motion"] == "idle")
    state = sim.snapshot()
    assert (state["x"], state["y"]) == (pytest.approx(0.5, abs=POSITION), pytest.approx(-0.5, abs=POSITION))
    assert abs(math.degrees(state["theta"])) == pytest.approx(180.0, abs=ANGLE)


def test_a_newer_base_command_preempts_navigation(world, sim, backend):
    handle = backend.send_goal(*NAV, nav_goal(4.5, 0, 0))
    eventually_in(world, lambda: sim.snapshot()["x"] > 0.2)
    world.publish("/cmd_vel", "geometry_msgs/Twist", {})
    assert handle.wait(5).status is GoalStatus.PREEMPTED
    assert sim.snapshot()["motion"] == "idle"


# --- head and eyes ---------------------------------------------------------------------------------


@pytest.mark.parametrize("position", api.HEAD_POSITIONS)
def test_look(sim, hobbit, position):
    hobbit.look("up_left" if position != "up_left" else "down_right")
    hobbit.look(position)
    assert sim.snapshot()["head"] == position


def test_all_thirteen_head_positions_are_known():
    assert len(set(api.HEAD_POSITIONS)) == 13 and set(api.HEAD_POSITIONS) == sim_module.HEAD_POSITIONS


def test_unknown_head_position_is_ignored_with_a_warning(world, sim, caplog):
    world.publish("/head/move", "std_msgs/String", {"data": "backwards"})
    world.publish("/head/move", "std_msgs/String", {"data": ["up"]})
    assert sim.snapshot()["head"] == "center_center"
    assert "unknown head position 'backwards' ignored" in caplog.text


@pytest.mark.parametrize("emotion", api.EMOTIONS)
def test_show_emotion(sim, hobbit, emotion):
    hobbit.show_emotion("SAD" if emotion != "SAD" else "HAPPY")
    hobbit.show_emotion(emotion)
    assert sim.snapshot()["emotion"] == emotion


def test_an_unknown_emotion_is_refused_to_the_program_naming_the_known_ones(world, sim):
    with pytest.raises(RobotCommandError) as refused:
        world.publish("/head/emo", "std_msgs/String", {"data": "ANGRY"})
    assert sim.snapshot()["emotion"] == "NEUTRAL"
    assert str(refused.value).startswith("The simulated HOBBIT does not know the emotion 'ANGRY'. It knows: CONCERNED,")
    assert refused.value.in_language("de").startswith("Der simulierte HOBBIT kennt das Gefühl 'ANGRY' nicht.")


# --- arm, gripper, turntable ----------------------------------------------------------------------


@pytest.mark.parametrize("position, seconds", [("candle", 4.0), ("home", 4.0), ("floor", 5.0), ("table", 4.0),
                                               ("tray", 3.5)])
def test_move_arm(world, sim, hobbit, position, seconds):
    states = record_snapshots(world, sim)
    started = sim.snapshot()["time"]
    hobbit.move_arm(position)
    state = sim.snapshot()
    assert (state["arm"], state["arm_target"], state["arm_progress"]) == (position, None, 0.0)
    assert seconds <= state["time"] - started < seconds + 5
    assert position in [seen["arm_target"] for seen in states]


@pytest.mark.parametrize("action, gripper", [("open", "open"), ("close", "closed")])
def test_gripper(sim, hobbit, action, gripper):
    hobbit.gripper("open" if action == "close" else "close")
    started = sim.snapshot()["time"]
    hobbit.gripper(action)
    state = sim.snapshot()
    assert (state["gripper"], state["arm"]) == (gripper, "home")
    assert 1.0 <= state["time"] - started < 6.0


def test_turntable_learn_turn_and_store(sim, hobbit):
    hobbit.turntable("learn")
    assert (sim.snapshot()["arm"], sim.snapshot()["turntable"]) == ("learning", "out")
    hobbit.turntable("clockwise")
    assert sim.snapshot()["turntable_angle"] == pytest.approx(330.0)
    hobbit.turntable("counterclockwise")
    hobbit.turntable("counterclockwise")
    assert sim.snapshot()["turntable_angle"] == pytest.approx(30.0)
    started = sim.snapshot()["time"]
    hobbit.turntable("store")
    state = sim.snapshot()
    assert (state["arm"], state["turntable"]) == ("home", "stored")
    assert state["time"] - started >= 3.0


def test_turntable_turns_gradually(world, sim, hobbit):
    states = record_snapshots(world, sim)
    hobbit.turntable("counterclockwise")
    assert any(0.0 < seen["turntable_angle"] < 30.0 for seen in states)


def test_move_arm_to_joints(sim, hobbit):
    hobbit.move_arm_to_joints([10, 20, 30, 40, 50, 60])
    assert (sim.snapshot()["arm"], sim.snapshot()["arm_target"]) == ("joints", None)


def test_arm_goal_sends_feedback_and_a_true_result(sim, backend):
    feedback = []
    outcome = backend.send_goal(*ARM, arm_goal("MoveToCandle"), feedback.append).wait(10)
    assert (outcome.status, outcome.result) == (GoalStatus.SUCCEEDED, {"result": {"data": True}})
    assert len(feedback) >= 2
    assert all(set(message) == {"feedback"} and message["feedback"]["data"].startswith("MoveToCandle ")
               for message in feedback)


def test_arm_follows_a_trajectory(sim, backend):
    started = sim.snapshot()["time"]
    goal = arm_goal("MoveAlongTrajectory", [[0, 10, 20, 30, 40, 50], [5, 15, 25, 35, 45, 55]])
    assert backend.send_goal(*ARM, goal).wait(10).status is GoalStatus.SUCCEEDED
    assert sim.snapshot()["arm"] == "joints"
    assert sim.snapshot()["time"] - started >= 5.0


@pytest.mark.parametrize("goal", [
    arm_goal("MoveToMoon"),
    arm_goal("MoveToJointValues"),
    arm_goal("MoveToJointValues", [[1, 2, 3, 4, 5]]),
    arm_goal("MoveToJointValues", [[1, 2, 3, 4, 5, 6], [1, 2, 3, 4, 5, 6]]),
    arm_goal("MoveAlongTrajectory"),
], ids=["unknown command", "no joints", "five joints", "two vectors", "empty trajectory"])
def test_arm_goal_the_server_cannot_do_is_aborted(sim, backend, goal):
    outcome = backend.send_goal(*ARM, goal).wait(5)
    assert (outcome.status, outcome.result) == (GoalStatus.ABORTED, {"result": {"data": False}})
    assert (sim.snapshot()["arm"], sim.snapshot()["arm_target"]) == ("home", None)


def test_cancelled_arm_goal_is_preempted_and_the_arm_stays_where_it_was(world, sim, backend):
    handle = backend.send_goal(*ARM, arm_goal("MoveToCandle"))
    eventually_in(world, lambda: sim.snapshot()["arm_progress"] > 0.2)
    handle.cancel()
    outcome = handle.wait(5)
    assert (outcome.status, outcome.result) == (GoalStatus.PREEMPTED, {"result": {"data": False}})
    stopped = sim.snapshot()
    assert (stopped["arm"], stopped["arm_target"], stopped["arm_progress"]) == ("joints", None, 0.0)
    assert later(world, sim)["arm"] == "joints"


def test_cancelled_gripper_goal_leaves_the_gripper_as_it_was(world, interrupt):
    # In real time: at the tests' speed the whole motion takes 50 ms, which a loaded machine can miss.
    sim = SimHobbit(world, speed=1.0)
    sim.start()
    try:
        handle = SimBackend(world, interrupt).send_goal(*ARM, arm_goal("OpenGripper"))
        eventually_in(world, lambda: sim.snapshot()["arm_progress"] > 0.0)
        handle.cancel()
        assert handle.wait(5).status is GoalStatus.PREEMPTED
        assert later(world, sim, 0.2)["gripper"] == "closed"
    finally:
        sim.safe_stop()
        sim.shutdown()


def test_a_new_arm_goal_preempts_the_running_one(sim, backend):
    first = backend.send_goal(*ARM, arm_goal("MoveToCandle"))
    second = backend.send_goal(*ARM, arm_goal("MoveToTray"))
    assert first.wait(10).status is GoalStatus.PREEMPTED
    assert second.wait(10).status is GoalStatus.SUCCEEDED
    assert sim.snapshot()["arm"] == "tray"


# --- tablet ---------------------------------------------------------------------------------------


@pytest.mark.parametrize("text", TABLET_TEXTS)
def test_show_info_shows_the_text_exactly_and_returns_at_once(sim, tablet, hobbit, text):
    hobbit.show_info(text)
    assert tablet.notices == [text]
    assert tablet.asked == []
    assert sim.snapshot()["tablet"] == {"kind": "D_PLAIN", "text": text}


@pytest.mark.parametrize("text", TABLET_TEXTS)
def test_show_info_and_wait_waits_for_the_confirmation(sim, tablet, hobbit, text):
    tablet.answers = [""]
    assert hobbit.show_info_and_wait(text) is None
    assert tablet.asked == [(TabletQuestion.OK, text, api.DIALOG_TIMEOUT)]
    assert tablet.shown_while_asking == [{"kind": "D_OK", "text": text}]
    assert sim.snapshot()["tablet"] is None


@pytest.mark.parametrize("answer, expected", [("yes", True), ("no", False)])
def test_ask_yes_no_returns_the_answer(sim, tablet, hobbit, answer, expected):
    tablet.answers = [answer]
    assert hobbit.ask_yes_no('Shall we "play"?\nSay yes') is expected
    assert tablet.asked == [(TabletQuestion.YES_NO, 'Shall we "play"?\nSay yes', api.DIALOG_TIMEOUT)]
    assert tablet.shown_while_asking == [{"kind": "D_YES_NO", "text": 'Shall we "play"?\nSay yes'}]


@pytest.mark.parametrize("typed", TABLET_TEXTS)
def test_ask_text_returns_what_was_typed(sim, tablet, hobbit, typed):
    tablet.answers = [typed]
    assert hobbit.ask_text("Wie heißt du? 😀") == typed
    assert tablet.asked == [(TabletQuestion.TEXT, "Wie heißt du? 😀", api.DIALOG_TIMEOUT)]


def test_shown_text_stays_until_the_next_tablet_request(sim, tablet, hobbit):
    hobbit.show_info("Hello")
    hobbit.look("up_left")
    assert sim.snapshot()["tablet"] == {"kind": "D_PLAIN", "text": "Hello"}
    tablet.answers = ["yes"]
    hobbit.ask_yes_no("Ready?")
    assert tablet.shown_while_asking == [{"kind": "D_YES_NO", "text": "Ready?"}]
    assert sim.snapshot()["tablet"] is None


def test_without_a_tablet_nobody_can_answer(world):
    robot = SimHobbit(world, speed=SPEED)
    robot.start()
    try:
        hobbit = Hobbit(SimBackend(world, Interrupt()))
        hobbit.show_info("just shown")
        with pytest.raises(RobotCommandError, match=r"^nobody can answer the tablet: 'Shall we play\?'$"):
            hobbit.ask_yes_no("Shall we play?")
        assert robot.snapshot()["tablet"] is None
    finally:
        robot.shutdown()


def test_call_sos_is_a_notice(sim, tablet, hobbit):
    hobbit.call_sos()
    assert tablet.notices == ["SOS call started"]
    assert sim.snapshot()["notices"] == ["SOS call started"]


def test_volume_changes_in_ten_percent_steps_within_bounds(sim, tablet, hobbit):
    hobbit.change_volume("louder")
    assert sim.snapshot()["volume"] == 60
    hobbit.change_volume("quieter")
    hobbit.change_volume("quieter")
    assert sim.snapshot()["volume"] == 40
    for _ in range(8):
        hobbit.change_volume("louder")
    assert sim.snapshot()["volume"] == 100
    assert tablet.notices[:3] == ["volume 60 %", "volume 50 %", "volume 40 %"]
    assert len(sim.snapshot()["notices"]) == 11


def test_notices_are_bounded(sim, hobbit):
    for _ in range(sim_module.NOTICES_KEPT + 5):
        hobbit.call_sos()
    assert len(sim.snapshot()["notices"]) == sim_module.NOTICES_KEPT


def test_unknown_tablet_request_is_refused(sim, backend):
    request = {"sessionID": "0", "requestText": "", "params": [{"name": "type", "value": "D_DANCE"}]}
    with pytest.raises(RobotCommandError, match=r"^the tablet does not know the request type 'D_DANCE'$"):
        backend.call_service("/MMUI", "hobbit_msgs/Request", request, 1)


# --- waiting, stopping, safe stop -------------------------------------------------------------------


def test_wait_waits_the_given_seconds(sim, hobbit):
    started = time.monotonic()
    hobbit.wait(0.05)
    assert time.monotonic() - started >= 0.05


def stop_program(interrupt, program, started):
    """Run ``program`` in a thread, request a stop once ``started()`` holds; seconds until ProgramStopped."""
    run = Background(program)
    assert Interrupt().wait_until(started, 10), "the program never got going"
    stopped_at = time.monotonic()
    interrupt.request_stop()
    run.join()
    assert isinstance(run.error, ProgramStopped), run.error
    return run.ended_at - stopped_at


def test_stop_request_during_a_drive_then_safe_stop_leaves_the_base_still(world, sim, hobbit, interrupt):
    delay = stop_program(interrupt, lambda: hobbit.drive(5), lambda: sim.snapshot()["x"] > 0.1)
    assert delay < STOP_BOUND
    sim.safe_stop()
    stopped = sim.snapshot()
    assert (stopped["motion"], stopped["linear"], stopped["angular"]) == ("idle", 0.0, 0.0)
    assert stopped["x"] < 5
    assert pose(later(world, sim)) == pose(stopped)
    assert world.latest("/DiscreteMotionState") == {"data": "Idle"}


def test_stop_request_during_an_arm_motion_then_safe_stop_leaves_the_arm_still(world, sim, hobbit, interrupt):
    delay = stop_program(interrupt, lambda: hobbit.move_arm("candle"), lambda: sim.snapshot()["arm_progress"] > 0.1)
    assert delay < STOP_BOUND
    sim.safe_stop()
    stopped = sim.snapshot()
    assert (stopped["arm"], stopped["arm_target"]) == ("joints", None)
    assert later(world, sim, 5.0)["arm"] == "joints"


def test_stop_request_during_a_dialog(world, interrupt):
    tablet = SilentTablet()
    robot = SimHobbit(world, tablet=tablet, speed=SPEED)
    robot.start()
    try:
        hobbit = Hobbit(SimBackend(world, interrupt))
        assert stop_program(interrupt, lambda: hobbit.ask_yes_no("Still there?"), tablet.asking.is_set) < STOP_BOUND
        assert robot.snapshot()["tablet"] is None
    finally:
        robot.shutdown()


def test_stop_request_during_a_wait(sim, hobbit, interrupt):
    waiting = threading.Event()

    def program():
        waiting.set()
        hobbit.wait(30)

    assert stop_program(interrupt, program, waiting.is_set) < STOP_BOUND


def test_profile_safe_stop_from_its_own_backend_stops_arm_and_navigation(world, sim, backend):
    arm = backend.send_goal(*ARM, arm_goal("MoveToPreGraspFloor"))
    navigation = backend.send_goal(*NAV, nav_goal(4.5, 0, 0))
    eventually_in(world, lambda: sim.snapshot()["x"] > 0.1 and sim.snapshot()["arm_progress"] > 0.1)

    actions = load_profile(HOBBIT_DIR, SHARED_TOOLBOXES).manifest["safe_stop"]
    assert run_safe_stop(actions, SimBackend(world, Interrupt())) == []

    assert arm.wait(5).status is GoalStatus.PREEMPTED
    assert navigation.wait(5).status is GoalStatus.PREEMPTED
    stopped = sim.snapshot()
    assert (stopped["motion"], stopped["arm_target"]) == ("idle", None)
    still = later(world, sim)
    assert (pose(still), still["arm"]) == (pose(stopped), stopped["arm"])


# --- battery ----------------------------------------------------------------------------------------


def test_battery_drains_slowly_while_standing(world, sim):
    state = later(world, sim, 6.0)
    assert state["battery"] == pytest.approx(100.0 - state["time"] / 60, abs=1e-9)
    eventually_in(world, lambda: world.latest("/battery_state")["percentage"] < 0.999)


def test_battery_drains_faster_while_moving(sim, hobbit):
    hobbit.drive(1)
    state = sim.snapshot()
    assert state["battery"] < 100.0 - state["time"] / 60 - 0.05
