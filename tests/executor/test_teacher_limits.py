"""A teacher's limits hold on the real simulator: speeds are clamped, switched-off capabilities refused."""
import math

import pytest

from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.events import OutputPrinted
from rockly_desktop.executor.run_setup import limits_line, make_runner
from rockly_desktop.robot.sim.link import SimulatedRobot
from rockly_desktop.robot.wrappers.limits import Limits

FAST = "ros.publish_message('/cmd_vel', 'geometry_msgs/Twist', {'linear': {'x': %s}, 'angular': {'z': %s}})\n"


@pytest.fixture
def robot(hobbit):
    robot = SimulatedRobot(hobbit, speed=1.0)
    yield robot
    robot.shutdown()


def run(profile, robot, code, limits, language="en"):
    events = []
    result = make_runner(profile, robot, {"code": code, "variables": {}}, RunControl(), events.append,
                         language, limits).run()
    return result, [event.text for event in events if isinstance(event, OutputPrinted)]


def velocities(robot):
    """Every /cmd_vel the simulated robot receives, as (linear x, angular z)."""
    seen = []
    robot.world.subscribe("/cmd_vel", lambda message: seen.append(
        (message.get("linear", {}).get("x", 0.0), message.get("angular", {}).get("z", 0.0))))
    return seen


def test_drive_commands_are_clamped_to_the_maximum_speeds_and_said_once(hobbit, robot):
    seen = velocities(robot)
    code = FAST % (2.0, -3.0) + FAST % (-1.5, 0.1) + "robot.backend.sleep(0.05)\n"
    result, output = run(hobbit, robot, code, Limits(max_speed=0.2, max_turn=30))
    assert result.outcome == "finished", result.message
    assert seen[:2] == [(0.2, pytest.approx(-math.radians(30))), (-0.2, 0.1)]
    assert all(abs(x) <= 0.2 and abs(z) <= math.radians(30) + 1e-9 for x, z in seen)
    assert output == ["Speed limit: the robot drives at most 0.2 m/s (set by the teacher).",
                      "Speed limit: the robot turns at most 30°/s (set by the teacher)."]


def test_without_limits_the_speed_is_the_programs(hobbit, robot):
    seen = velocities(robot)
    result, output = run(hobbit, robot, FAST % (2.0, 0.0), None)
    assert result.outcome == "finished" and seen[0] == (2.0, 0.0) and output == []


def test_the_turtlebots_drive_block_is_clamped_too(registry):
    turtlebot = registry.get("turtlebot")
    robot = SimulatedRobot(turtlebot, speed=20.0)
    try:
        seen = velocities(robot)
        result, output = run(turtlebot, robot, "robot.drive_for(0.2, 0.5)\n", Limits(max_speed=0.05))
    finally:
        robot.shutdown()
    assert result.outcome == "finished", result.message
    assert seen and max(abs(x) for x, _z in seen) == 0.05
    assert len(output) == 1


@pytest.mark.parametrize(("language", "message"), [
    ("en", "The robot could not do this: the teacher switched off “Arm and gripper” for this robot"),
    ("de", "Das konnte der Roboter nicht tun: "
           "Die Lehrkraft hat „Arm und Greifer“ für diesen Roboter ausgeschaltet"),
])
def test_a_switched_off_capability_fails_with_a_clear_message(hobbit, robot, language, message):
    goals = []
    robot.world.tap(lambda topic, msg_type, value: goals.append(topic) if "hobbit_arm" in topic else None)
    result, _output = run(hobbit, robot, "robot.gripper('open')\n", Limits(switched_off=frozenset({"arm"})), language)
    assert result.outcome == "error"
    assert result.message == message
    assert goals == []


def test_navigation_off_refuses_its_action_and_topic_but_not_the_arm(hobbit, robot):
    limits = Limits(switched_off=frozenset({"navigation"}))
    result, _ = run(hobbit, robot, "robot.navigate_to(1, 0)\n", limits)
    assert "Navigation" in result.message
    code = "robot.backend.publish('/move_base_simple/goal', 'geometry_msgs/PoseStamped', {})\n"
    assert "Navigation" in run(hobbit, robot, code, limits)[0].message
    assert run(hobbit, robot, "robot.gripper('open')\n", limits)[0].outcome == "finished"


# --- HOBBIT's discrete drive and turn: the base's own speed against the teacher's -----------------

DRIVE_AND_TURN = "robot.drive(0.5)\nrobot.turn(90, 'left')\n"


def base_motion(robot):
    """The discrete motion commands and the speeds the simulated base reports on /odom (m/s, °/s)."""
    commands, speeds = [], []
    robot.world.subscribe("/DiscreteMotionCmd", lambda message: commands.append(message.get("data")))
    robot.world.subscribe("/odom", lambda message: speeds.append(
        (message["twist"]["twist"]["linear"]["x"], math.degrees(message["twist"]["twist"]["angular"]["z"]))))
    return commands, speeds


@pytest.mark.parametrize("speed", [1.0, 20.0])
def test_a_drive_and_turn_keep_a_limit_below_the_bases_own_speed_and_end_where_asked(hobbit, speed):
    robot = SimulatedRobot(hobbit, speed=speed)
    try:
        seen, (commands, speeds) = velocities(robot), base_motion(robot)
        result, output = run(hobbit, robot, DRIVE_AND_TURN, Limits(max_speed=0.2, max_turn=30))
        end = robot.snapshot()
    finally:
        robot.shutdown()
    assert result.outcome == "finished", result.message
    assert commands == [] or set(commands) == {"Stop"}, "a discrete motion goes at the base's own speed"
    assert seen and all(abs(x) <= 0.2 and abs(z) <= math.radians(30) + 1e-9 for x, z in seen)
    assert max(abs(x) for x, _ in speeds) == pytest.approx(0.2)
    assert max(abs(z) for _, z in speeds) == pytest.approx(30)
    assert (end["x"], end["y"]) == (pytest.approx(0.5, abs=0.005), pytest.approx(0.0, abs=0.005))
    assert math.degrees(end["theta"]) == pytest.approx(90, abs=0.5)
    assert output == ["Speed limit: the robot drives at most 0.2 m/s (set by the teacher).",
                      "Speed limit: the robot turns at most 30°/s (set by the teacher)."]


def test_a_limit_at_or_above_the_bases_own_speed_keeps_the_discrete_motions(hobbit, robot):
    seen, (commands, _speeds) = velocities(robot), base_motion(robot)
    result, output = run(hobbit, robot, DRIVE_AND_TURN, Limits(max_speed=0.3, max_turn=60))
    assert result.outcome == "finished", result.message
    assert commands == ["Move 0.5", "Turn 90", "Stop"] and output == []  # Stop: the safe stop after the run
    assert set(seen) <= {(0.0, 0.0)}


def test_a_backward_drive_under_a_limit_comes_back_the_asked_distance(hobbit):
    robot = SimulatedRobot(hobbit, speed=20.0)
    try:
        result, _ = run(hobbit, robot, "robot.drive(0.4, 'backward')\nrobot.turn(45, 'right')\n",
                        Limits(max_speed=0.05, max_turn=10))
        end = robot.snapshot()
    finally:
        robot.shutdown()
    assert result.outcome == "finished", result.message
    assert end["x"] == pytest.approx(-0.4, abs=0.005)
    assert math.degrees(end["theta"]) == pytest.approx(-45, abs=0.5)


@pytest.mark.parametrize(("language", "words"), [("en", "faster than the teacher's speed limit"),
                                                 ("de", "schneller als das Tempolimit der Lehrkraft")])
def test_navigation_is_refused_under_a_limit_below_its_speed(hobbit, robot, language, words):
    goals = []
    robot.world.tap(lambda topic, msg_type, value: goals.append(topic) if "move_base" in topic else None)
    result, _ = run(hobbit, robot, "robot.navigate_to(1, 0)\n", Limits(max_speed=0.2), language)
    assert result.outcome == "error" and words in result.message
    assert goals == []


@pytest.mark.parametrize(("limits", "language", "line"), [
    (Limits(), "en", None),
    (Limits(max_turn=45), "en", "The teacher's limits apply: turning at most 45°/s."),
    (Limits(max_speed=0.2, switched_off=frozenset({"arm", "navigation", "unknown"})), "de",
     "Es gelten die Grenzen der Lehrkraft: Fahren höchstens 0,2 m/s; ausgeschaltet: Arm und Greifer, Navigation."),
])
def test_the_line_saying_which_limits_apply(hobbit, limits, language, line):
    assert limits_line(hobbit, limits, language) == line


def test_commands_learn_the_allowed_speed_from_the_backend_they_are_given(hobbit, robot):
    from rockly_desktop.robot.commands import RobotCommands
    from rockly_desktop.robot.interrupt import Interrupt
    from rockly_desktop.robot.wrappers.limits import LimitedBackend

    plain = robot.backend(Interrupt())
    notes = []
    limited = LimitedBackend(plain, Limits(max_speed=0.2, max_turn=90), note=notes.append)
    assert RobotCommands(plain).allowed_speed(0.3) == 0.3                     # no teacher: the robot's own
    assert RobotCommands(limited).allowed_speed(0.3) == 0.2                   # a lower limit
    assert RobotCommands(limited).allowed_speed(0.1) == 0.1                   # a higher one changes nothing
    assert RobotCommands(limited).allowed_speed(1.0, turning=True) == 1.0     # 90°/s is more than 1 rad/s
    assert RobotCommands(limited).allowed_speed(2.0, turning=True) == pytest.approx(math.pi / 2)
    assert notes == ["Speed limit: the robot drives at most 0.2 m/s (set by the teacher).",
                     "Speed limit: the robot turns at most 90°/s (set by the teacher)."]


def test_a_limited_drive_into_the_wall_stops_at_contact_and_says_what_it_hit(hobbit):
    robot = SimulatedRobot(hobbit, speed=20.0)
    try:
        seen = velocities(robot)
        result, _ = run(hobbit, robot, "robot.drive(3, 'backward')\n", Limits(max_speed=0.2))
        end = robot.snapshot()
    finally:
        robot.shutdown()
    assert result.outcome == "error"
    assert result.message == "The robot could not do this: HOBBIT bumped into the wall"
    assert end["bumped"] == "wall_left" and end["linear"] == 0.0
    assert seen[-1] == (0.0, 0.0) and all(abs(x) <= 0.2 for x, _z in seen)
