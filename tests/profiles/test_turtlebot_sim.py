"""The simulated TurtleBot (profiles/turtlebot/rockly_turtlebot/sim.py and arena.py): its room, its laser,
its bumper-like stops, its odometry and battery, and the messages it publishes.

The simulator runs its own 30 Hz clock thread, SPEED times faster than real time; tests wait
on conditions (the world's messages), never for a fixed time. It is driven by raw /cmd_vel
messages here, as any ROS node would; the commands are tested in test_turtlebot_api.py.
"""
import math
import sys
import threading

import pytest
from profile_copies import REPO, SHARED_TOOLBOXES
from sim_tools import eventually_in, later

from rockly_desktop.profiles.profile import load_profile
from rockly_desktop.robot.sim.sim_world import SimWorld

PROFILE = load_profile(REPO / "profiles" / "turtlebot", SHARED_TOOLBOXES)
SimTurtleBot = PROFILE.load_object("simulator")
sim_module = sys.modules[SimTurtleBot.__module__]
arena_module = sys.modules[SimTurtleBot.__module__.rsplit(".", 1)[0] + ".arena"]

SPEED = 10
RADIUS = 0.105
ROOM = (-0.5, -1.5, 3.5, 1.5)


@pytest.fixture
def world():
    return SimWorld()


@pytest.fixture
def make_sim(world):
    started = []

    def make(**options):
        sim = SimTurtleBot(world, speed=options.pop("speed", SPEED), **options)
        sim.start()
        started.append(sim)
        return sim

    yield make
    for sim in started:
        sim.shutdown()


def drive(world, linear=0.0, angular=0.0):
    world.publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": linear}, "angular": {"z": angular}})


def next_message(world, topic):
    seen = []
    unsubscribe = world.subscribe(topic, seen.append)
    try:
        eventually_in(world, lambda: seen)
    finally:
        unsubscribe()
    return seen[0]


def expected_wall_distance(room, x, y, angle):
    """Where a ray from (x, y) at ``angle`` leaves the rectangle ``room``, worked out by hand."""
    x0, y0, x1, y1 = room
    c, s = math.cos(angle), math.sin(angle)
    candidates = []
    if c > 1e-12:
        candidates.append((x1 - x) / c)
    if c < -1e-12:
        candidates.append((x0 - x) / c)
    if s > 1e-12:
        candidates.append((y1 - y) / s)
    if s < -1e-12:
        candidates.append((y0 - y) / s)
    return min(candidates)


# --- the room -------------------------------------------------------------------------------------


def test_the_default_room_is_4_by_3_metres_with_three_boxes_and_the_robot_fits_at_the_origin(world, make_sim):
    snapshot = make_sim().snapshot()
    assert snapshot["room"] == ROOM and snapshot["room_size"] == (4.0, 3.0)
    assert len(snapshot["boxes"]) == 3
    assert (snapshot["x"], snapshot["y"], snapshot["theta"]) == (0.0, 0.0, 0.0)
    assert snapshot["radius"] == RADIUS
    assert snapshot["bumped"] is False and snapshot["bumps"] == 0
    for key in ("trail", "linear", "angular", "scan", "battery", "time"):
        assert key in snapshot


@pytest.mark.parametrize("options, problem", [
    ({"start": (3.45, 0.0, 0.0)}, "does not fit"),
    ({"start": (2.0, -0.1, 0.0)}, "does not fit"),                      # inside the first box
    ({"boxes": [(1.0, 1.0, 0.5, 2.0)]}, "min < max"),
    ({"speed": 0}, "positive"),
])
def test_impossible_set_ups_are_refused(world, options, problem):
    with pytest.raises(ValueError, match=problem):
        SimTurtleBot(world, **options)


# --- the laser ------------------------------------------------------------------------------------


def test_the_scan_message_is_a_360_beam_laser_scan(world, make_sim):
    make_sim()
    scan = next_message(world, "/scan")
    assert dict(world.topics())["/scan"] == "sensor_msgs/LaserScan"
    assert len(scan["ranges"]) == 360
    assert scan["angle_min"] == 0.0
    assert scan["angle_increment"] == pytest.approx(2 * math.pi / 360)
    assert scan["angle_max"] == pytest.approx(2 * math.pi * 359 / 360)
    assert (scan["range_min"], scan["range_max"]) == (0.12, 3.5)
    assert scan["header"]["frame_id"] == "base_scan"


@pytest.mark.parametrize("theta_degrees", [0, 90, -135, 30])
def test_every_beam_measures_the_wall_it_points_at_counter_clockwise_from_ahead(world, make_sim, theta_degrees):
    room = (-0.5, -1.0, 2.0, 1.0)
    theta = math.radians(theta_degrees)
    make_sim(room=room, boxes=[], start=(0.3, 0.2, theta))
    ranges = next_message(world, "/scan")["ranges"]
    for index, measured in enumerate(ranges):
        expected = expected_wall_distance(room, 0.3, 0.2, theta + math.radians(index))
        assert measured == pytest.approx(expected, abs=1e-6), f"beam {index}"


def test_the_scan_sees_a_box_placed_ahead_at_its_distance(world, make_sim):
    sim = make_sim(boxes=[(1.25, -0.2, 1.6, 0.2)])
    scan = next_message(world, "/scan")
    assert scan["ranges"][0] == pytest.approx(1.25, abs=0.02)
    # the box's face is 0.4 m wide: the beams that hit it are exactly those that reach x = 1.25 within |y| <= 0.2
    for index in list(range(0, 12)) + list(range(349, 360)):
        angle = math.radians(index)
        hits_face = abs(1.25 * math.tan(angle)) <= 0.2
        assert (scan["ranges"][index] == pytest.approx(1.25 / math.cos(angle), abs=1e-6)) == hits_face, index
    assert sim.snapshot()["scan"] == scan["ranges"]


def test_the_scan_follows_the_robot(world, make_sim):
    sim = make_sim(boxes=[(1.25, -0.2, 1.6, 0.2)])
    drive(world, 0.2)
    eventually_in(world, lambda: sim.snapshot()["x"] > 0.5)
    drive(world)
    stopped = later(world, sim, 0.2)
    assert stopped["scan"][0] == pytest.approx(1.25 - stopped["x"], abs=1e-6)


def test_beyond_range_is_inf_and_too_close_is_minus_inf(world, make_sim):
    make_sim(room=(-5.0, -0.3, 5.0, 5.0), boxes=[], start=(0.0, -0.19, 0.0))
    ranges = next_message(world, "/scan")["ranges"]
    assert ranges[0] == math.inf and ranges[90] == math.inf         # 5 m away: out of range
    assert ranges[270] == -math.inf                                   # the wall 0.11 m to the right
    assert all(r == math.inf or r == -math.inf or 0.12 <= r <= 3.5 for r in ranges)


def test_ray_casting_is_vectorised_over_every_beam():
    arena = arena_module.Arena(ROOM, arena_module.BOXES)
    angles = [math.radians(i) for i in range(360)]
    ranges = arena.cast(0.0, 0.0, angles)
    assert ranges.shape == (360,)
    assert ranges[0] == pytest.approx(1.9)         # the first box
    assert ranges[180] == pytest.approx(0.5)       # the wall behind


# --- moving and bumping ---------------------------------------------------------------------------


def test_velocity_commands_move_it_as_a_unicycle(world, make_sim):
    sim = make_sim(boxes=[], room=(-5.0, -5.0, 5.0, 5.0))
    drive(world, 0.2, 0.5)
    start = later(world, sim, 0.1)
    end = later(world, sim, 2.0)
    # on a circle of radius v / w = 0.4 m
    centre = (start["x"] - 0.4 * math.sin(start["theta"]), start["y"] + 0.4 * math.cos(start["theta"]))
    assert math.dist(centre, (end["x"], end["y"])) == pytest.approx(0.4, abs=1e-6)
    assert (end["linear"], end["angular"]) == (0.2, 0.5)


def test_velocities_are_limited_to_the_turtlebots(world, make_sim):
    sim = make_sim()
    drive(world, 1.0, -9.0)
    eventually_in(world, lambda: sim.snapshot()["linear"] != 0)
    assert (sim.snapshot()["linear"], sim.snapshot()["angular"]) == (0.22, -2.84)


def test_a_bad_velocity_is_ignored(world, make_sim):
    sim = make_sim()
    world.publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": "fast"}})
    world.publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": math.nan}})
    assert later(world, sim)["x"] == 0.0


@pytest.mark.parametrize("speed", [4, 20])
def test_driving_into_a_wall_stops_the_robot_touching_it(world, make_sim, speed):
    sim = make_sim(boxes=[], speed=speed)
    drive(world, 0.22)
    eventually_in(world, lambda: sim.snapshot()["bumped"], timeout=60)
    stopped = later(world, sim, 0.5)
    assert stopped["x"] == pytest.approx(3.5 - RADIUS, abs=0.001)
    assert (stopped["linear"], stopped["angular"], stopped["bumps"]) == (0.0, 0.0, 1)
    assert later(world, sim)["x"] == stopped["x"], "it went on pushing"


def test_driving_into_a_box_at_an_angle_stops_touching_it(world, make_sim):
    sim = make_sim(boxes=[(1.0, 0.3, 1.4, 0.7)], start=(0.0, 0.0, math.radians(20)))
    drive(world, 0.2)
    eventually_in(world, lambda: sim.snapshot()["bumped"])
    stopped = later(world, sim, 0.3)
    assert stopped["linear"] == 0.0
    gap = max(1.0 - stopped["x"], 0.0, stopped["x"] - 1.4), max(0.3 - stopped["y"], 0.0, stopped["y"] - 0.7)
    assert math.hypot(*gap) == pytest.approx(RADIUS, abs=0.001)


def test_a_robot_at_a_wall_may_turn_and_drive_away(world, make_sim):
    sim = make_sim(boxes=[])
    drive(world, 0.22)
    eventually_in(world, lambda: sim.snapshot()["bumped"])
    drive(world, 0.0, 1.0)
    eventually_in(world, lambda: sim.snapshot()["theta"] > 2.0)   # turning while touching is fine
    drive(world, 0.1)
    eventually_in(world, lambda: sim.snapshot()["x"] < 3.2)
    assert sim.snapshot()["bumps"] == 1 and sim.snapshot()["bumped"] is False


def test_pushing_on_against_a_wall_is_the_same_bump(world, make_sim):
    sim = make_sim(boxes=[])
    drive(world, 0.22)
    eventually_in(world, lambda: sim.snapshot()["bumped"])
    for _ in range(3):
        drive(world, 0.1)
        later(world, sim, 0.2)
    assert sim.snapshot()["bumps"] == 1


# --- odometry, trail, battery ---------------------------------------------------------------------


def test_odometry_says_where_the_robot_is_and_how_it_moves(world, make_sim):
    sim = make_sim()
    drive(world, 0.1, 0.2)
    eventually_in(world, lambda: sim.snapshot()["x"] > 0.1)
    odometry = next_message(world, "/odom")
    snapshot = sim.snapshot()
    position = odometry["pose"]["pose"]["position"]
    q = odometry["pose"]["pose"]["orientation"]
    yaw = math.atan2(2 * q["w"] * q["z"], 1 - 2 * q["z"] ** 2)
    assert abs(position["x"] - snapshot["x"]) < 0.05 and abs(yaw - snapshot["theta"]) < 0.2
    assert odometry["twist"]["twist"]["linear"]["x"] == 0.1
    assert odometry["twist"]["twist"]["angular"]["z"] == 0.2
    assert odometry["header"]["frame_id"] == "odom"
    stamp = odometry["header"]["stamp"]
    assert 0 < stamp["secs"] + stamp["nsecs"] * 1e-9 <= sim.snapshot()["time"]


def test_the_trail_follows_the_robot(world, make_sim):
    sim = make_sim()
    drive(world, 0.2)
    eventually_in(world, lambda: sim.snapshot()["x"] > 0.5)
    trail = sim.snapshot()["trail"]
    assert trail[0] == (0.0, 0.0)
    assert len(trail) >= 5 and all(b[0] > a[0] for a, b in zip(trail, trail[1:], strict=False))
    assert trail[-1][0] > 0.45


def test_the_battery_drains_slowly_and_faster_while_driving(world, make_sim):
    sim = make_sim(boxes=[], room=(-5.0, -5.0, 50.0, 5.0), speed=50)
    start = sim.snapshot()
    standing = later(world, sim, 60)
    idle_drain = (start["battery"] - standing["battery"]) / (standing["time"] - start["time"])
    drive(world, 0.2)
    eventually_in(world, lambda: sim.snapshot()["linear"] > 0)
    moving_start = sim.snapshot()
    moving = later(world, sim, 60)
    busy_drain = (moving_start["battery"] - moving["battery"]) / (moving["time"] - moving_start["time"])
    assert 0.5 / 60 < idle_drain < 2 / 60, "per second: about 1 % a minute standing still"
    assert busy_drain > 1.5 * idle_drain
    battery = next_message(world, "/battery_state")
    assert 0 < battery["percentage"] < 1
    assert battery["percentage"] == pytest.approx(sim.snapshot()["battery"] / 100, abs=0.01)
    assert 11.0 < battery["voltage"] < 12.6
    assert battery["present"] is True


def test_all_four_streams_arrive_every_tick(world, make_sim):
    counts = {"/odom": 0, "/scan": 0, "/battery_state": 0, "/sensor_state": 0}
    for topic in counts:
        world.subscribe(topic, lambda _message, topic=topic: counts.__setitem__(topic, counts[topic] + 1))
    make_sim()
    eventually_in(world, lambda: counts["/odom"] >= 10)
    assert all(abs(count - counts["/odom"]) <= 1 for count in counts.values())
    assert sorted(topic for topic, _type in world.topics()) == ["/battery_state", "/odom", "/scan", "/sensor_state"]


def test_shutdown_ends_the_clock_thread(world):
    def clocks():
        return [thread for thread in threading.enumerate() if thread.name == "simulated TurtleBot"]

    before = clocks()
    sim = SimTurtleBot(world, speed=SPEED)
    sim.start()
    later(world, sim, 0.5)
    assert len(clocks()) == len(before) + 1
    sim.shutdown()
    assert clocks() == before
