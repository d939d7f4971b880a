"""HOBBIT's solid house (rockly_hobbit/world.yaml): bumps, refused navigation goals, putting the robot back.

The real simulator runs its own clock at SPEED times real time; the real commands drive it
through a SimBackend. Tests wait on conditions, never for a fixed time.
"""
import math
import sys

import pytest
from profile_copies import HOBBIT_DIR, SHARED_TOOLBOXES
from sim_tools import eventually_in

from rockly_desktop.core.errors import RobotCommandError
from rockly_desktop.executor.problems import explain
from rockly_desktop.profiles.profile import load_profile
from rockly_desktop.robot.interface import GoalStatus
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.sim.sim_world import SimBackend, SimWorld

PROFILE = load_profile(HOBBIT_DIR, SHARED_TOOLBOXES)
SimHobbit = PROFILE.load_object("simulator")
Hobbit = PROFILE.load_object("api")
WORLD = sys.modules["rockly_hobbit.world"].WORLD
SPEED = 25
NAV = "move_base", "move_base_msgs/MoveBaseAction"
RADIUS = 0.275


@pytest.fixture
def world():
    return SimWorld()


@pytest.fixture
def sim(world):
    robot = SimHobbit(world, speed=SPEED)
    robot.start()
    yield robot
    robot.safe_stop()
    robot.shutdown()


@pytest.fixture
def backend(world, sim):
    return SimBackend(world, Interrupt())


@pytest.fixture
def hobbit(backend):
    return Hobbit(backend)


def bumper_presses(world):
    presses = []
    world.subscribe("/bumper", lambda message: message.get("data") and presses.append(True))
    return presses


def nav_goal(x, y):
    return {"target_pose": {"header": {"frame_id": "map"}, "pose": {
        "position": {"x": x, "y": y, "z": 0.0}, "orientation": {"x": 0.0, "y": 0.0, "z": 0.0, "w": 1.0}}}}


def test_the_world_data_is_the_house_the_view_draws():
    PROFILE.simulator_view_class()
    geometry = sys.modules["rockly_hobbit.view.geometry"]
    assert geometry.ROOM == WORLD.area and geometry.BASE_RADIUS == WORLD.radius == RADIUS
    x0, y0, x1, y1 = WORLD.area
    walls = [o for o in WORLD.obstacles if o.kind == "wall"]
    # the walls close the room except for the door the view draws in the bottom wall
    assert {round(o.bounds[1], 2) for o in walls if o.id.startswith("wall_bottom")} == {round(y0 - geometry.WALL, 2)}
    door_from, door_to = geometry.DOOR
    assert WORLD.obstacle("wall_bottom_left").bounds[2] == door_from
    assert WORLD.obstacle("wall_bottom_right").bounds[0] == door_to
    assert {o.id for o in WORLD.obstacles if o.kind == "furniture"} >= {"sofa", "table", "shelf"}
    assert WORLD.fits(0.0, 0.0)


def test_a_drive_into_the_outer_wall_stops_at_contact_and_says_what_it_hit(world, sim, hobbit):
    presses = bumper_presses(world)
    with pytest.raises(RobotCommandError) as caught:
        hobbit.drive(3.0, "backward")
    snapshot = sim.snapshot()
    assert snapshot["x"] == pytest.approx(WORLD.area[0] + RADIUS, abs=1e-3)   # touching the left wall
    assert (snapshot["y"], snapshot["linear"], snapshot["bumped"]) == (pytest.approx(0.0, abs=1e-9), 0.0, "wall_left")
    assert presses, "the bumper never reported the bump"
    assert str(caught.value) == "HOBBIT bumped into the wall"
    assert caught.value.in_language("de") == "HOBBIT ist gegen die Wand gestoßen"
    eventually_in(world, lambda: sim.snapshot()["motion"] == "idle")


def test_a_drive_into_the_sofa_stops_at_contact_in_both_languages(world, sim, hobbit):
    presses = bumper_presses(world)
    hobbit.drive(1.0)
    hobbit.turn(90, "left")
    with pytest.raises(RobotCommandError) as caught:
        hobbit.drive(2.0)
    snapshot = sim.snapshot()
    sofa_front = WORLD.obstacle("sofa").bounds[1]
    assert snapshot["y"] == pytest.approx(sofa_front - RADIUS, abs=1e-3)
    assert snapshot["bumped"] == "sofa" and presses
    assert explain(caught.value, "en") == "The robot could not do this: HOBBIT bumped into the sofa"
    assert explain(caught.value, "de") == "Das konnte der Roboter nicht tun: HOBBIT ist gegen das Sofa gestoßen"
    # backing off is no bump, and nothing in the way lets a drive finish
    hobbit.drive(0.5, "backward")
    assert sim.snapshot()["y"] == pytest.approx(sofa_front - RADIUS - 0.5, abs=0.01)


def test_a_navigation_goal_inside_furniture_is_aborted_with_the_reason(world, sim, backend, hobbit):
    table = WORLD.obstacle("table").bounds
    centre = ((table[0] + table[2]) / 2, (table[1] + table[3]) / 2)
    outcome = backend.send_goal(*NAV, nav_goal(*centre)).wait(10)
    assert (outcome.status, outcome.text) == (GoalStatus.ABORTED, "at the goal HOBBIT would bump into the table")
    assert (sim.snapshot()["x"], sim.snapshot()["y"]) == (0.0, 0.0)
    with pytest.raises(RobotCommandError) as caught:
        hobbit.navigate_to(*centre)
    assert str(caught.value) == "HOBBIT could not reach the goal: at the goal HOBBIT would bump into the table"
    assert caught.value.in_language("de") == ("HOBBIT konnte das Ziel nicht erreichen: "
                                              "am Ziel würde HOBBIT gegen den Tisch stoßen")


def test_a_navigation_goal_outside_the_house_is_aborted(sim, backend, hobbit):
    outcome = backend.send_goal(*NAV, nav_goal(7.0, 1.0)).wait(10)
    assert (outcome.status, outcome.text) == (GoalStatus.ABORTED, "the goal (7.00, 1.00) is outside the map")
    with pytest.raises(RobotCommandError) as caught:
        hobbit.navigate_to(7, 1)
    assert caught.value.in_language("de") == ("HOBBIT konnte das Ziel nicht erreichen: "
                                              "das Ziel (7,00, 1,00) liegt außerhalb der Karte")


def test_a_navigation_that_bumps_on_the_way_is_aborted_there(world, sim, hobbit):
    with pytest.raises(RobotCommandError) as caught:
        hobbit.navigate_to(3.0, 2.2)     # the straight way there grazes the sofa's corner
    assert str(caught.value) == "HOBBIT could not reach the goal: HOBBIT bumped into the sofa on the way"
    assert caught.value.in_language("de").endswith("HOBBIT ist unterwegs gegen das Sofa gestoßen")
    snapshot = sim.snapshot()
    assert WORLD.touching(snapshot["x"], snapshot["y"]).id == "sofa" and snapshot["motion"] == "idle"


def test_reset_puts_hobbit_back_as_it_started(world, sim, hobbit):
    start = sim.snapshot()
    hobbit.turn(90, "left")
    with pytest.raises(RobotCommandError):
        hobbit.drive(2.0)
    hobbit.move_arm("candle")
    hobbit.look("up_left")
    hobbit.show_emotion("SAD")
    hobbit.show_info("hello")
    assert sim.snapshot()["battery"] < 100.0
    sim.reset()
    after = sim.snapshot()
    for key in ("x", "y", "theta", "trail", "linear", "angular", "motion", "nav_goal", "head", "emotion", "arm",
                "arm_target", "gripper", "turntable", "turntable_angle", "volume", "tablet", "notices",
                "bumped", "bumps"):
        assert after[key] == start[key], key
    assert after["battery"] == 100.0
    odometry = []
    world.subscribe("/odom", odometry.append)
    eventually_in(world, lambda: odometry)
    assert odometry[-1]["pose"]["pose"]["position"]["x"] == 0.0
    hobbit.drive(0.3)    # and it drives again from there
    assert sim.snapshot()["x"] == pytest.approx(0.3, abs=0.01)
    assert math.isclose(sim.snapshot()["y"], 0.0, abs_tol=1e-9)
