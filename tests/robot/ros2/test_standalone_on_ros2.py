"""A standalone export on ROS 2 against ``rockly sim turtlebot --ros2``: SIGTERM mid-drive (a launch file
ending it) sends the robot's safe stop, seen on the wire by a plain rclpy node."""
import signal
import subprocess
import sys

from json_line_node import JsonLineNode
from program_builder import block, number
from ros2_fixtures import ROS2_PYTHON
from standalone_tools import REPO, end, events, exported_program, start_file, wait_for_event
from waiting import eventually

RECORDER = r'''
import json, threading, rclpy
from geometry_msgs.msg import Twist
rclpy.init()
node = rclpy.create_node("plain_wire_recorder")
node.create_subscription(Twist, "/cmd_vel", lambda m: print(json.dumps(
    {"linear": [m.linear.x, m.linear.y, m.linear.z], "angular": [m.angular.x, m.angular.y, m.angular.z]}),
    flush=True), 10)
threading.Thread(target=rclpy.spin, args=(node,), daemon=True).start()
print(json.dumps({"ready": True}), flush=True)
import sys
sys.stdin.read()
'''


def long_drive_exported(folder):
    """``(standalone .py, .rockly)`` of a TurtleBot program that drives at 0.1 m/s for 120 s."""
    return exported_program(folder, block("turtlebot_drive_for", inputs={"speed": number(0.1), "seconds": number(120)},
                                          id="long"), "long", profile="turtlebot")


def turtlebot_sim_on_ros2(on_the_domain) -> subprocess.Popen:
    """``rockly sim turtlebot --ros2`` with the options ``on_the_domain``, once up; the caller ends it. A start
    whose ROS 2 helper Rockly ended as hung (it said nothing for ``HUNG_AFTER``: a starved process on a loaded
    machine, while it loads rclpy) is tried again, as a person would start the simulator again."""
    for _ in range(3):
        simulator = subprocess.Popen([sys.executable, "-m", "rockly_desktop", "sim", "turtlebot", "--ros2",
                                      "--no-window", *on_the_domain], cwd=REPO, text=True, stdout=subprocess.PIPE,
                                     stderr=subprocess.PIPE)
        if any("is up on ROS" in line for line in simulator.stdout):
            return simulator
        simulator.kill()
        simulator.wait(30)
        said = simulator.stderr.read()
        simulator.stdout.close()
        simulator.stderr.close()
        if "so Rockly ended it" not in said:
            break
    raise AssertionError(f"the simulator did not start: {said}")


def test_sigterm_mid_drive_sends_the_safe_stop_on_the_wire(tmp_path, ros2_settings):
    exported, _source = long_drive_exported(tmp_path)
    on_the_domain = ["--domain", str(ros2_settings.domain_id), "--discovery", "localhost"]
    simulator = turtlebot_sim_on_ros2(on_the_domain)
    wire = run = None
    try:
        wire = JsonLineNode([ROS2_PYTHON, "-c", RECORDER], ros2_settings.environment(), "the wire recorder")
        run = start_file(exported, "--backend", "ros2", *on_the_domain, "--events", "-")
        seen = []
        wait_for_event(run, lambda record: record.get("id") == "long", seen)
        eventually(lambda: any(line["linear"][0] == 0.1 for line in list(wire.lines)), timeout=30)  # driving
        run.send_signal(signal.SIGTERM)
        run.wait(60)
        seen += events(run.stdout.read())
        assert run.returncode == 143, run.stderr.read()
        assert seen[-2]["outcome"] == "stopped" and seen[-1] == {"event": "exit", "status": 143}
        zero = {"linear": [0.0, 0.0, 0.0], "angular": [0.0, 0.0, 0.0]}
        eventually(lambda: wire.lines[-1] == zero)  # the safe stop's zero velocity came last
        last_drive = max(i for i, line in enumerate(wire.lines) if line["linear"][0] == 0.1)
        assert zero in wire.lines[last_drive:]
    finally:
        if run is not None:
            end(run)
        if wire is not None:
            wire.stop()
        simulator.terminate()
        simulator.wait(30)
