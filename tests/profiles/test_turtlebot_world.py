"""The TurtleBot's room as one SDK World: the laser sees exactly what the robot bumps into; bumps on
/sensor_state; reset. The real simulator runs its own clock; tests wait on conditions."""
import math

import pytest
from profile_copies import REPO, SHARED_TOOLBOXES
from sim_tools import eventually_in

from rockly_desktop.core.errors import RobotCommandError
from rockly_desktop.profiles.profile import load_profile
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.sim.sim_world import SimBackend, SimWorld

PROFILE = load_profile(REPO / "profiles" / "turtlebot", SHARED_TOOLBOXES)
SimTurtleBot = PROFILE.load_object("simulator")
TurtleBot = PROFILE.load_object("api")
SPEED = 10


@pytest.fixture
def world():
    return SimWorld()


@pytest.fixture
def sim(world):
    robot = SimTurtleBot(world, speed=SPEED)
    robot.start()
    yield robot
    robot.shutdown()


def latest(world, topic):
    seen = []
    world.subscribe(topic, seen.append)
    eventually_in(world, lambda: seen)
    return seen


def test_the_laser_range_toward_a_box_is_the_distance_to_its_edge_in_the_world_data(world, sim):
    scans = latest(world, "/scan")
    arena = sim._arena
    red = arena.obstacle("box_1")
    x0, _y0, _x1, _y1 = red.bounds                    # straight ahead of the start, across the x axis
    assert scans[-1]["ranges"][0] == pytest.approx(x0 - 0.0, abs=1e-9)
    # the beam 40 degrees to the left crosses the blue box's lower edge where the world data says
    bx0, by0, bx1, _by1 = arena.obstacle("box_3").bounds
    angle = math.radians(40)
    assert bx0 < by0 / math.tan(angle) < bx1
    assert scans[-1]["ranges"][40] == pytest.approx(by0 / math.sin(angle), abs=1e-9)
    assert arena.cast(0.0, 0.0, [0.0]).tolist() == [pytest.approx(x0)]


def test_a_drive_into_a_box_stops_at_contact_and_the_bumper_says_so(world, sim):
    states = []
    world.subscribe("/sensor_state", lambda message: message["bumper"] and states.append(message["bumper"]))
    robot = TurtleBot(SimBackend(world, Interrupt()))
    with pytest.raises(RobotCommandError) as caught:
        robot.drive(3.0)
    snapshot = sim.snapshot()
    edge = sim._arena.obstacle("box_1").bounds[0]
    assert snapshot["x"] == pytest.approx(edge - sim._arena.radius, abs=1e-3)
    assert (snapshot["linear"], snapshot["contact"], states[:1]) == (0.0, "box_1", [1])   # BUMPER_FORWARD
    assert str(caught.value) == "The TurtleBot bumped into the red box"
    assert caught.value.in_language("de") == "Der TurtleBot ist gegen die rote Kiste gestoßen"


def test_a_drive_backward_into_the_wall_is_a_backward_bump(world, sim):
    states = []
    world.subscribe("/sensor_state", lambda message: message["bumper"] and states.append(message["bumper"]))
    robot = TurtleBot(SimBackend(world, Interrupt()))
    with pytest.raises(RobotCommandError) as caught:
        robot.drive(1.0, "backward")
    assert sim.snapshot()["x"] == pytest.approx(sim._arena.room[0] + sim._arena.radius, abs=1e-3)
    assert states[:1] == [2] and caught.value.in_language("de") == "Der TurtleBot ist gegen die Wand gestoßen"


def test_reset_puts_the_turtlebot_back(world, sim):
    robot = TurtleBot(SimBackend(world, Interrupt()))
    start = sim.snapshot()
    robot.turn(45)
    with pytest.raises(RobotCommandError):
        robot.drive(3.0)
    sim.reset()
    after = sim.snapshot()
    for key in ("x", "y", "theta", "trail", "linear", "angular", "scan", "bumped", "bumps", "contact"):
        assert after[key] == start[key], key
    assert after["battery"] == 100.0
