"""A hung or killed ROS 2 helper, against a healthy one in the same run (for ``faults.py``).

A plain rclpy node in its own process (not Rockly's helper: that is what hangs) records every
Twist it gets on /cmd_vel with its arrival time. The TurtleBot program drives and waits; then
  - baseline: STOP -> zero velocity on the wire with a healthy helper;
  - hung: the helper is stopped (SIGSTOP) and STOP pressed at once -> zero velocity on the wire
    (the hung helper is found out, ended, and the spare sends the safe stop);
  - the time to find out a hung helper (SIGSTOP -> lost) and a killed one (kill -9 -> lost), and
    kill -9 -> zero velocity on the wire;
  - the longest health look (what the window's health light asks twice a second, on its thread)
    while the helper hangs, against the longest with a healthy helper.
Between faults the spare that took over is given SPARE_SETTLE to discover the robot (a spare
started a moment ago has not met it yet, as a real spare has, minutes after connecting).

    python benchmarks/_fault_helper.py
"""
import json
import os
import signal
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

from _paths import REPO

ROS2_PYTHON = REPO / ".venv-ros2" / "bin" / "python"
BASELINE_TRIALS = 10
FAULT_TRIALS = 3  # of each fault: each ends a helper, and its spare takes over
SPARE_SETTLE = 5.0  # seconds a new spare has to discover the robot before the next fault
SETTLE = 0.2  # seconds the drive runs before the stop or the fault
DRIVE_AND_WAIT = "robot.backend.publish('/cmd_vel', 'geometry_msgs/Twist', {'linear': {'x': 0.2}})\nrobot.wait(60)\n"

RECORDER = r'''
import json, sys, threading, time, rclpy
from geometry_msgs.msg import Twist
from rclpy.executors import SingleThreadedExecutor
rclpy.init()
node = rclpy.create_node("rockly_bench_cmd_vel_recorder")
node.create_subscription(Twist, "/cmd_vel", lambda m: print(json.dumps([time.time(), m.linear.x]), flush=True), 100)
executor = SingleThreadedExecutor()
executor.add_node(node)
threading.Thread(target=executor.spin, daemon=True).start()
print(json.dumps("ready"), flush=True)
sys.stdin.read()
'''


class Recorder:
    """The plain rclpy node recording /cmd_vel: ``heard`` is [(arrival time.time(), linear.x)]."""

    def __init__(self, env):
        self.process = subprocess.Popen([str(ROS2_PYTHON), "-c", RECORDER], env=env, stdin=subprocess.PIPE,
                                        stdout=subprocess.PIPE, text=True)
        assert json.loads(self.process.stdout.readline()) == "ready"
        self.heard = []
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self):
        for line in self.process.stdout:
            self.heard.append(tuple(json.loads(line)))

    def first_zero_after(self, since: float, timeout: float = 10.0):
        """Arrival time of the first zero Twist after ``since`` (time.time()), or None within ``timeout``."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            for arrived, speed in list(self.heard):
                if arrived >= since and speed == 0.0:
                    return arrived
            time.sleep(0.001)
        return None

    def driving(self, timeout: float = 10.0) -> bool:
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if self.heard and self.heard[-1][1] == 0.2:
                return True
            time.sleep(0.001)
        return False

    def close(self):
        self.process.stdin.close()
        self.process.wait(10)


def start_drive(robot):
    """A run of DRIVE_AND_WAIT on its own thread; its RunControl and thread."""
    from rockly_desktop.executor.control import RunControl
    from rockly_desktop.executor.run_setup import make_runner

    control = RunControl()
    runner = make_runner(robot.profile, robot, {"code": DRIVE_AND_WAIT, "variables": {}}, control, lambda _event: None)
    thread = threading.Thread(target=runner.run)
    thread.start()
    return control, thread


def until_lost(helper, timeout: float = 10.0) -> float:
    """time.monotonic() when ``helper`` is found lost."""
    deadline = time.monotonic() + timeout
    while not helper.lost and time.monotonic() < deadline:
        time.sleep(0.0005)
    return time.monotonic()


def longest_health_look(robot, until) -> float:
    """The longest ``robot.health()`` (seconds) of looks every 10 ms until ``until()`` is true."""
    longest = 0.0
    while not until():
        started = time.perf_counter()
        robot.health()
        longest = max(longest, time.perf_counter() - started)
        time.sleep(0.01)
    return longest


def ms(seconds) -> str:
    return f"{seconds * 1000:.1f} ms"


def run():
    """Measure and print the figures (see the module's docstring)."""
    from rockly_desktop.profiles.registry import ProfileRegistry
    from rockly_desktop.robot.ros2.client import Ros2Helper
    from rockly_desktop.robot.ros2.environment import Ros2Settings
    from rockly_desktop.robot.ros2.link import Ros2Robot

    if not ROS2_PYTHON.exists():
        sys.exit(f"no {ROS2_PYTHON}: run 'make ros2' first")
    settings = Ros2Settings(domain_id=230 + os.getpid() % 3, discovery="localhost")
    home = Path(tempfile.mkdtemp(prefix="rockly-bench-helper-"))
    os.environ.update(ROS_HOME=str(home), ROS_LOG_DIR=str(home / "log"))
    env = settings.environment()
    recorder = Recorder(env)
    robot = Ros2Robot(ProfileRegistry.discover().get("turtlebot"), settings)
    faulted = []
    try:
        time.sleep(SPARE_SETTLE)
        looked_until = time.monotonic() + 1.0
        healthy_look = longest_health_look(robot, lambda: time.monotonic() > looked_until)
        baseline = []
        for _ in range(BASELINE_TRIALS):
            control, thread = start_drive(robot)
            assert recorder.driving(), "the recorder heard no drive"
            time.sleep(SETTLE)
            asked = time.time()
            control.request_stop()
            thread.join(10)
            baseline.append(recorder.first_zero_after(asked) - asked)

        hung_stop, hung_found, killed_found, killed_stop, hung_looks = [], [], [], [], []
        for kind in ["hung"] * FAULT_TRIALS + ["killed"] * FAULT_TRIALS:
            control, thread = start_drive(robot)
            assert recorder.driving(), "the recorder heard no drive"
            time.sleep(SETTLE)
            helper = robot.helper
            faulted.append(helper.process)
            at, wall = time.monotonic(), time.time()
            os.kill(helper.process.pid, signal.SIGSTOP if kind == "hung" else signal.SIGKILL)
            if kind == "hung":
                control.request_stop()  # STOP pressed as the helper hangs
                hung_looks.append(longest_health_look(robot, lambda helper=helper: helper.lost))
                hung_found.append(until_lost(helper) - at)
                hung_stop.append((recorder.first_zero_after(wall) or float("nan")) - wall)
            else:
                killed_found.append(until_lost(helper) - at)
                killed_stop.append((recorder.first_zero_after(wall) or float("nan")) - wall)
            control.request_stop()
            thread.join(10)
            time.sleep(SPARE_SETTLE)

        median = statistics.median(baseline)
        print(f"STOP -> zero velocity on the wire, healthy helper: median {ms(median)}, "
              f"max {ms(max(baseline))} over {BASELINE_TRIALS} stops")
        print(f"STOP -> zero velocity on the wire, hung helper (SIGSTOP, then STOP at once): median "
              f"{ms(statistics.median(hung_stop))}, max {ms(max(hung_stop))} over {FAULT_TRIALS} "
              f"(aim <= 2 s; ratio to healthy {statistics.median(hung_stop) / median:.0f}x)")
        print(f"hung helper found out (SIGSTOP -> lost): median {ms(statistics.median(hung_found))}, "
              f"max {ms(max(hung_found))}")
        print(f"killed helper found out (kill -9 -> lost): median {ms(statistics.median(killed_found))}, "
              f"max {ms(max(killed_found))}; kill -9 -> zero velocity on the wire: median "
              f"{ms(statistics.median(killed_stop))}, max {ms(max(killed_stop))} (aim <= 2 s)")
        print(f"longest health look (on the window's thread) while the helper hangs: {ms(max(hung_looks))}, "
              f"healthy {ms(healthy_look)} (aim <= 100 ms; it took 2 s a look before)")
    finally:
        robot.shutdown()
        Ros2Helper.close_current()
        recorder.close()
        for process in faulted:
            if process.poll() is None:
                os.kill(process.pid, signal.SIGCONT)
                process.kill()
            process.wait(10)


if __name__ == "__main__":
    run()
