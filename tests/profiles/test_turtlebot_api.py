"""The TurtleBot's commands (profiles/turtlebot/rockly_turtlebot/api.py) on the real simulator.

Each command drives the built-in simulated TurtleBot (rockly_turtlebot/sim.py) in a real
SimWorld with its own 30 Hz clock thread, SPEED times faster than real time. What the
commands send is read where it reaches the world (``world.subscribe``); where the robot
ends up is read from the simulator's snapshot. Every wait is on a condition, never a sleep.
"""
import math
import sys
import time

import pytest
from background import Background
from profile_copies import REPO, SHARED_TOOLBOXES
from sim_tools import HoldWatcher, eventually_in, later, pose

from rockly_desktop.core.errors import ProgramStopped, RobotCommandError
from rockly_desktop.executor.control import RunControl
from rockly_desktop.profiles.profile import load_profile
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.safe_stop import run_safe_stop
from rockly_desktop.robot.sim.sim_world import SimBackend, SimWorld

TURTLEBOT_DIR = REPO / "profiles" / "turtlebot"
PROFILE = load_profile(TURTLEBOT_DIR, SHARED_TOOLBOXES)
TurtleBot = PROFILE.load_object("api")
SimTurtleBot = PROFILE.load_object("simulator")
api = sys.modules[TurtleBot.__module__]

SPEED = 10
POSITION = 0.02    # m
ANGLE = 2.0        # degrees
STOP_BOUND = 0.1   # s from a stop request to ProgramStopped in the program's thread
EMPTY_ROOM = (-0.5, -1.5, 3.5, 1.5)


@pytest.fixture
def world():
    return SimWorld()


@pytest.fixture
def make_sim(world):
    started = []

    def make(**options):
        sim = SimTurtleBot(world, speed=SPEED, **options)
        sim.start()
        started.append(sim)
        return sim

    yield make
    for sim in started:
        sim.safe_stop()
        sim.shutdown()


@pytest.fixture
def sim(make_sim):
    """The default room: walls, three boxes, the robot at the origin facing +x (1.9 m to the first box)."""
    return make_sim()


@pytest.fixture
def control():
    control = RunControl()
    yield control
    control.request_stop()   # ends a program a failed test left holding or waiting


@pytest.fixture
def robot(world, sim, control):
    return TurtleBot(SimBackend(world, control.interrupt))


@pytest.fixture
def hold(control, sim):
    watcher = HoldWatcher(control, sim)
    control.on_hold = watcher
    return watcher


def heading(snapshot):
    return math.degrees(snapshot["theta"])


def degrees_between(theta, degrees):
    """The smallest angle, in degrees, from the heading ``theta`` (radians) to ``degrees``."""
    return math.degrees(math.remainder(theta - math.radians(degrees), math.tau))


def record_twists(world):
    """(linear.x, angular.z) of every later /cmd_vel, in order."""
    seen = []
    world.subscribe("/cmd_vel", lambda m: seen.append(((m.get("linear") or {}).get("x", 0.0),
                                                       (m.get("angular") or {}).get("z", 0.0))))
    return seen


# --- driving and turning ----------------------------------------------------------------------


@pytest.mark.parametrize("direction, sign", [("forward", 1), ("backward", -1)])
def test_drive_moves_the_distance_along_the_heading_and_stops(world, sim, robot, direction, sign):
    twists = record_twists(world)
    robot.drive(0.5 if direction == "forward" else 0.3, direction)
    end = later(world, sim, 0.5)
    assert end["x"] == pytest.approx(sign * (0.5 if direction == "forward" else 0.3), abs=POSITION)
    assert end["y"] == pytest.approx(0.0, abs=1e-6) and end["theta"] == pytest.approx(0.0, abs=1e-6)
    assert (end["linear"], end["angular"]) == (0.0, 0.0), "the robot did not stop at the end"
    assert twists[0] == (sign * api.LINEAR_SPEED, 0.0), "it did not start at 0.15 m/s"
    assert twists[-1] == (0.0, 0.0)
    assert all(abs(v) <= api.LINEAR_SPEED + 1e-9 and w == 0.0 for v, w in twists)


def test_drive_along_a_turned_heading(world, make_sim, control):
    sim = make_sim(start=(0.0, 0.0, math.radians(90)))
    TurtleBot(SimBackend(world, control.interrupt)).drive(0.8)
    end = sim.snapshot()
    assert (end["x"], end["y"]) == (pytest.approx(0.0, abs=POSITION), pytest.approx(0.8, abs=POSITION))


@pytest.mark.parametrize("angle, direction, expected", [(90, "left", 90), (90, "right", -90), (270, "left", -90),
                                                        (45, "right", -45)])
def test_turn_turns_on_the_spot_and_stops(world, sim, robot, angle, direction, expected):
    twists = record_twists(world)
    robot.turn(angle, direction)
    end = later(world, sim, 0.5)
    assert degrees_between(end["theta"], expected) == pytest.approx(0.0, abs=ANGLE)
    assert (end["x"], end["y"]) == (0.0, 0.0)
    assert (end["linear"], end["angular"]) == (0.0, 0.0)
    sign = 1 if direction == "left" else -1
    assert twists[0] == (0.0, sign * api.ANGULAR_SPEED)
    assert twists[-1] == (0.0, 0.0)


def test_a_square_of_drives_and_turns_comes_back_to_the_start(world, make_sim, control):
    sim = make_sim(boxes=[])
    robot = TurtleBot(SimBackend(world, control.interrupt))
    for _ in range(4):
        robot.drive(0.6)
        robot.turn(90, "left")
    end = sim.snapshot()
    assert math.hypot(end["x"], end["y"]) < 2 * POSITION
    assert degrees_between(end["theta"], 0) == pytest.approx(0.0, abs=ANGLE)


def odom_times(world):
    """The simulated time of every later /odom (one per tick of the simulator's clock)."""
    seen = []
    world.subscribe("/odom", lambda m: seen.append(m["header"]["stamp"]["secs"] + m["header"]["stamp"]["nsecs"] / 1e9))
    return seen


def test_drive_for_drives_at_that_speed_for_that_long(world, sim, robot):
    twists = record_twists(world)
    ticks = odom_times(world)
    start = sim.snapshot()
    robot.drive_for(0.1, 3)
    end = later(world, sim, 0.5)
    # The stop takes effect at the clock's next tick: on a loaded machine a tick can span more
    # simulated time than usual, and the robot drives on for that long.
    longest_tick = max(b - a for a, b in zip(ticks, ticks[1:], strict=False))
    assert end["x"] - start["x"] == pytest.approx(0.3, abs=POSITION + 0.1 * longest_tick)
    assert end["linear"] == 0.0
    assert twists[0] == (0.1, 0.0) and twists[-1] == (0.0, 0.0)
    assert end["time"] - start["time"] >= 3.0


def test_drive_for_backward_and_for_no_time(world, sim, robot):
    robot.drive_for(-0.2, 1.5)
    assert sim.snapshot()["x"] == pytest.approx(-0.3, abs=POSITION)
    twists = record_twists(world)
    robot.drive_for(0.2, 0)
    robot.drive_for(0.2, -4)
    assert twists == [], "a drive for no time moved the robot"


def test_stop_halts_a_robot_driving_on_its_own(world, sim, robot):
    world.publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.1}, "angular": {"z": 0.3}})
    eventually_in(world, lambda: sim.snapshot()["linear"] == 0.1)
    robot.stop()
    halted = later(world, sim, 0.1)
    assert (halted["linear"], halted["angular"]) == (0.0, 0.0)
    assert pose(later(world, sim)) == pose(halted)


def test_wait_waits_and_a_negative_time_returns_at_once(robot):
    started = time.monotonic()
    robot.wait(0.2)
    assert time.monotonic() - started >= 0.2
    started = time.monotonic()
    robot.wait(-3)
    assert time.monotonic() - started < 1.0  # far from the 3 s a negative wait must not take


# --- bumping --------------------------------------------------------------------------------


def test_drive_into_a_box_stops_at_it_and_says_so(world, make_sim, control):
    sim = make_sim(boxes=[(0.805, -0.3, 1.2, 0.3)])
    robot = TurtleBot(SimBackend(world, control.interrupt))
    with pytest.raises(RobotCommandError) as caught:
        robot.drive(1.5)
    end = later(world, sim, 0.5)
    assert end["x"] == pytest.approx(0.805 - 0.105, abs=0.001)
    assert (end["linear"], end["bumped"], end["bumps"]) == (0.0, True, 1)
    assert str(caught.value) == "The TurtleBot bumped into the red box"
    assert caught.value.in_language("de") == "Der TurtleBot ist gegen die rote Kiste gestoßen"
    robot.drive(0.3, "backward")   # it can back away
    assert sim.snapshot()["x"] == pytest.approx(0.7 - 0.3, abs=POSITION)
    assert sim.snapshot()["bumped"] is False


# --- what the laser sees ------------------------------------------------------------------------

FOUR_BOXES = [(1.0, -0.3, 1.3, 0.3),      # ahead, 1.0 m
              (-0.3, 0.6, 0.3, 0.9),      # left, 0.6 m
              (-0.3, -1.1, 0.3, -0.8),    # right, 0.8 m
              (-0.7, -0.3, -0.4, 0.3)]    # behind, 0.4 m


@pytest.fixture
def boxed_in(world, make_sim, control):
    sim = make_sim(boxes=FOUR_BOXES, room=(-2.0, -2.0, 2.0, 2.0))
    return sim, TurtleBot(SimBackend(world, control.interrupt))


def test_distance_in_each_direction_is_the_nearest_box_there(boxed_in):
    _sim, robot = boxed_in
    measured = {side: robot.distance(side) for side in ("ahead", "left", "right", "behind")}
    assert measured == {"ahead": pytest.approx(1.0, abs=0.02), "left": pytest.approx(0.6, abs=0.02),
                        "right": pytest.approx(0.8, abs=0.02), "behind": pytest.approx(0.4, abs=0.02)}
    assert robot.distance() == measured["ahead"]


def test_distances_turn_with_the_robot(boxed_in):
    _sim, robot = boxed_in
    robot.turn(90, "left")
    assert robot.distance("ahead") == pytest.approx(0.6, abs=0.02)
    assert robot.distance("left") == pytest.approx(0.4, abs=0.02)
    assert robot.distance("behind") == pytest.approx(0.8, abs=0.02)
    assert robot.distance("right") == pytest.approx(1.0, abs=0.02)


def test_distance_looks_15_degrees_to_each_side(world, make_sim, control):
    # a thin post 0.5 m away, 12 degrees to the left of straight ahead: in the sector; at 20 degrees: not
    inside = 0.5 * math.cos(math.radians(12)), 0.5 * math.sin(math.radians(12))
    outside = 1.0 * math.cos(math.radians(-20)), 1.0 * math.sin(math.radians(-20))
    posts = [(x - 0.02, y - 0.02, x + 0.02, y + 0.02) for x, y in (inside, outside)]
    make_sim(boxes=posts, room=(-2.0, -2.0, 2.0, 2.0))
    robot = TurtleBot(SimBackend(world, control.interrupt))
    assert 0.46 < robot.distance("ahead") < 0.5
    robot.turn(20, "right")   # now the far post is straight ahead and the near one 32 degrees left
    assert robot.distance("ahead") == pytest.approx(0.98, abs=0.02)


def test_obstacle_closer_than(boxed_in):
    _sim, robot = boxed_in
    assert robot.obstacle_closer_than(1.1) is True
    assert robot.obstacle_closer_than(0.9) is False
    assert robot.obstacle_closer_than(0.5, "behind") is True
    assert robot.obstacle_closer_than(0.5, "left") is False
    assert robot.obstacle_closer_than(0.7, "left") is True
    assert robot.obstacle_closer_than(0) is False


def test_nothing_in_range_is_infinitely_far(world, make_sim, control):
    make_sim(boxes=[], room=(-5.0, -5.0, 5.0, 5.0))
    robot = TurtleBot(SimBackend(world, control.interrupt))
    assert robot.distance("ahead") == math.inf
    assert robot.obstacle_closer_than(3.4, "left") is False


def test_something_closer_than_the_laser_measures_counts_as_its_minimum(world, make_sim, control):
    make_sim(boxes=[(0.11, -0.3, 0.5, 0.3)])    # 1 cm in front of the robot's edge
    robot = TurtleBot(SimBackend(world, control.interrupt))
    assert robot.distance("ahead") == pytest.approx(0.12)
    assert robot.obstacle_closer_than(0.2) is True


def test_battery_level_is_a_percentage_that_drains(world, sim, robot):
    first = robot.battery_level()
    assert 99 < first <= 100
    later(world, sim, 30)
    assert robot.battery_level() < first
    assert robot.battery_level() == pytest.approx(sim.snapshot()["battery"], abs=0.2)


# --- refused arguments: an error naming what is wrong, and nothing reaches the robot --------------


@pytest.mark.parametrize("command, args, message", [
    ("drive", ("far",), "the distance must be a number, not 'far'"),
    ("drive", (None,), "the distance must be a number, not None"),
    ("drive", (True,), "the distance must be a number, not True"),
    ("drive", (1, "sideways"), "unknown direction 'sideways'; use one of 'forward', 'backward'"),
    ("turn", ([90],), "the angle must be a number, not [90]"),
    ("turn", (90, "up"), "unknown direction 'up'; use one of 'left', 'right'"),
    ("drive_for", (0.5, 2), "the speed must be between -0.22 and 0.22 m/s (the TurtleBot's top speed), not 0.5"),
    ("drive_for", (-1, 2), "the speed must be between -0.22 and 0.22 m/s (the TurtleBot's top speed), not -1"),
    ("drive_for", ("fast", 2), "the speed must be a number, not 'fast'"),
    ("drive_for", (0.1, "long"), "the time must be a number, not 'long'"),
    ("drive_for", (0.1, math.inf), "the time must be a number, not inf"),
    ("distance", ("up",), "unknown direction 'up'; use one of 'ahead', 'left', 'right', 'behind'"),
    ("obstacle_closer_than", (-1,), "the distance must not be negative, not -1"),
    ("obstacle_closer_than", ("near",), "the distance must be a number, not 'near'"),
    ("obstacle_closer_than", (0.4, "front"),
     "unknown direction 'front'; use one of 'ahead', 'left', 'right', 'behind'"),
    ("wait", ("5",), "the waiting time must be a number, not '5'"),
])
def test_bad_arguments_are_refused_before_anything_moves(world, robot, command, args, message):
    twists = record_twists(world)
    with pytest.raises(RobotCommandError) as caught:
        getattr(robot, command)(*args)
    assert str(caught.value) == message
    assert twists == []


def test_commands_without_a_robot_time_out_naming_the_topic(monkeypatch):
    monkeypatch.setattr(api, "SENSOR_TIMEOUT", 0.2)
    robot = TurtleBot(SimBackend(SimWorld(), Interrupt()))   # nobody publishes anything
    for command, args, topic in (("distance", (), "/scan"), ("battery_level", (), "/battery_state"),
                                 ("drive", (1,), "/odom"), ("drive_for", (0.1, 1), "/odom")):
        with pytest.raises(RobotCommandError, match=f"'{topic}'"):
            getattr(robot, command)(*args)


# --- stopping and pausing ------------------------------------------------------------------------


def test_stop_during_a_drive_ends_it_quickly_and_the_safe_stop_leaves_the_robot_still(world, sim, control, robot):
    drive = Background(lambda: robot.drive(1.5))
    eventually_in(world, lambda: sim.snapshot()["x"] > 0.2)
    assert sim.snapshot()["linear"] > 0
    asked = time.monotonic()
    control.request_stop()
    assert isinstance(drive.join().error, ProgramStopped), drive.error
    assert drive.ended_at - asked < STOP_BOUND
    assert run_safe_stop(PROFILE.manifest["safe_stop"], SimBackend(world, Interrupt())) == []
    halted = later(world, sim, 0.1)
    assert (halted["linear"], halted["angular"]) == (0.0, 0.0)
    assert pose(later(world, sim)) == pose(halted), "the robot moved after the safe stop"
    assert halted["x"] < 1.5 - POSITION


def test_safe_stop_is_a_zero_velocity(world, sim):
    twists = record_twists(world)
    run_safe_stop(PROFILE.manifest["safe_stop"], SimBackend(world, Interrupt()))
    assert twists == [(0.0, 0.0)]
    assert dict(world.topics())["/cmd_vel"] == "geometry_msgs/Twist"


def test_pause_halts_a_drive_part_way_and_continue_drives_the_rest(world, sim, control, hold, robot):
    drive = Background(lambda: robot.drive(1.0))
    eventually_in(world, lambda: sim.snapshot()["x"] > 0.1)
    control.request_pause()

    held = hold.wait_until_held()
    assert held["linear"] == 0.0
    assert 0.1 < held["x"] < 1.0 - POSITION
    assert pose(later(world, sim)) == pose(held), "the robot moved while the program held"
    assert drive.thread.is_alive()

    twists = record_twists(world)
    control.resume()
    assert drive.join().error is None
    assert sim.snapshot()["x"] == pytest.approx(1.0, abs=POSITION)
    assert len(hold.snapshots) == 1, "the rest of the drive held again"
    assert twists[0] == (api.LINEAR_SPEED, 0.0) and twists[-1] == (0.0, 0.0)


def test_pause_halts_a_turn_past_half_way_round_and_continue_turns_the_rest(world, sim, control, hold, robot):
    turn = Background(lambda: robot.turn(270, "left"))
    eventually_in(world, lambda: sim.snapshot()["theta"] < -0.2)   # turning left from 0, so past 180 degrees
    control.request_pause()
    held = hold.wait_until_held()
    assert held["angular"] == 0.0
    assert 180 < heading(held) % 360 < 270 - ANGLE
    assert pose(later(world, sim)) == pose(held)
    control.resume()
    assert turn.join().error is None
    assert degrees_between(sim.snapshot()["theta"], 270) == pytest.approx(0.0, abs=ANGLE)


def test_pause_holds_the_clock_of_drive_for(world, sim, control, hold, robot):
    drive = Background(lambda: robot.drive_for(0.1, 6))
    eventually_in(world, lambda: sim.snapshot()["x"] > 0.1)
    control.request_pause()
    held = hold.wait_until_held()
    assert held["linear"] == 0.0 and 0.1 < held["x"] < 0.6 - POSITION
    later(world, sim, 3)   # standing while held does not count
    control.resume()
    assert drive.join().error is None
    assert sim.snapshot()["x"] == pytest.approx(0.6, abs=POSITION)


def test_stop_while_a_drive_holds_ends_the_program_and_the_robot_stays(world, sim, control, hold, robot):
    drive = Background(lambda: robot.drive(1.0))
    eventually_in(world, lambda: sim.snapshot()["x"] > 0.1)
    control.request_pause()
    held = hold.wait_until_held()
    twists = record_twists(world)
    control.request_stop()
    assert isinstance(drive.join().error, ProgramStopped), drive.error
    assert twists == [], "the rest of the drive was sent after the stop"
    assert pose(later(world, sim)) == pose(held)
