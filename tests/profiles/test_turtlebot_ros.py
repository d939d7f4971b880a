"""`rockly sim turtlebot --ros` on a real ROS master, driven by the TurtleBot's commands through RosRobot.

The master and the simulator are started with ros_helpers' RosMaster and RocklyProcess. This
test has a master of its own, not the session's ``ros_master``: there the simulated HOBBIT may
be running, and it too publishes /odom and /battery_state and follows /cmd_vel. The commands
run in a child process (a ROS node of its own), because a process is one node on one master
and this test process may already be one on the session's master.
"""
import json
import math
import subprocess
import sys

import pytest
from ros_helpers import REPO, RocklyProcess, RosMaster, ros_environment

CLIENT = r"""
import json, math, sys
import rosgraph
from rockly_desktop.robot.ros1.link import RosRobot
from rockly_desktop.profiles.registry import ProfileRegistry
from rockly_desktop.robot.interrupt import Interrupt

profile = ProfileRegistry.discover().get("turtlebot")
robot = RosRobot(profile, sys.argv[1])
backend = robot.backend(Interrupt())
turtlebot = profile.load_object("api")(backend)

def where():
    odometry = backend.wait_for_message("/odom", "nav_msgs/Odometry", 10)
    position = odometry["pose"]["pose"]["position"]
    return [position["x"], position["y"]]

report = {"start": where(), "ahead_before": turtlebot.distance("ahead"), "left_before": turtlebot.distance("left")}
turtlebot.drive(0.3)
report.update(end=where(), ahead_after=turtlebot.distance("ahead"),
              closer_than_2=turtlebot.obstacle_closer_than(2.0), closer_than_1=turtlebot.obstacle_closer_than(1.0))
turtlebot.turn(90, "left")
odometry = backend.wait_for_message("/odom", "nav_msgs/Odometry", 10)
q = odometry["pose"]["pose"]["orientation"]
report["heading"] = math.degrees(math.atan2(2 * q["w"] * q["z"], 1 - 2 * q["z"] ** 2))
scan = backend.wait_for_message("/scan", "sensor_msgs/LaserScan", 10)
report["scan"] = {"beams": len(scan["ranges"]), "angle_min": scan["angle_min"],
                  "increment": scan["angle_increment"], "range_min": scan["range_min"], "range_max": scan["range_max"],
                  "infinite": sum(1 for r in scan["ranges"] if r == math.inf)}
report["battery"] = turtlebot.battery_level()
report["safe_stop_failures"] = robot.safe_stop()
report["types"] = dict(rosgraph.Master("/turtlebot_test").getTopicTypes())
print("REPORT " + json.dumps(report))
"""


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    """What the commands saw and did on the ROS-level simulated TurtleBot (one run, several checks)."""
    home = tmp_path_factory.mktemp("turtlebot_ros")
    master = RosMaster(home).start()
    simulator = None
    try:
        simulator = RocklyProcess(["sim", "turtlebot", "--ros", "--master", master.uri, "--speed", "10"],
                                  master, ready_line="on ROS")
        result = subprocess.run([sys.executable, "-c", CLIENT, master.uri], capture_output=True, text=True,
                                timeout=120, cwd=REPO, env=ros_environment(master.uri, home / "client"))
    finally:
        if simulator is not None:
            simulator.stop()
        master.stop()
    assert result.returncode == 0, result.stderr
    (line,) = [line for line in result.stdout.splitlines() if line.startswith("REPORT ")]
    return json.loads(line[len("REPORT "):])


def test_the_simulator_serves_the_turtlebots_topics_with_their_types(report):
    types = report["types"]
    assert types["/cmd_vel"] == "geometry_msgs/Twist"
    assert types["/odom"] == "nav_msgs/Odometry"
    assert types["/scan"] == "sensor_msgs/LaserScan"
    assert types["/battery_state"] == "sensor_msgs/BatteryState"


def test_drive_over_ros_moves_it_and_the_laser_sees_the_box_come_closer(report):
    (x0, y0), (x1, y1) = report["start"], report["end"]
    assert (x1 - x0, y1 - y0) == (pytest.approx(0.3, abs=0.02), pytest.approx(0.0, abs=0.005))
    assert report["ahead_before"] == pytest.approx(1.9, abs=0.02)     # the first box, from the start
    assert report["ahead_after"] == pytest.approx(1.6, abs=0.02)
    assert report["left_before"] == pytest.approx(1.5, abs=0.02)      # the wall
    assert (report["closer_than_2"], report["closer_than_1"]) == (True, False)


def test_turn_over_ros(report):
    assert report["heading"] == pytest.approx(90, abs=2)


def test_the_scan_crosses_ros_whole_with_its_infinite_beams(report):
    scan = report["scan"]
    assert scan["beams"] == 360 and scan["angle_min"] == 0.0
    assert scan["increment"] == pytest.approx(2 * math.pi / 360)
    assert (scan["range_min"], scan["range_max"]) == (pytest.approx(0.12), pytest.approx(3.5))
    assert scan["infinite"] > 0, "beyond 3.5 m the beams should read inf"


def test_battery_and_safe_stop_over_ros(report):
    assert 95 < report["battery"] <= 100
    assert report["safe_stop_failures"] == []
