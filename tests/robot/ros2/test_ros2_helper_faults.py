"""A ROS 2 helper that hangs (SIGSTOP) or dies (kill -9) while a program drives: it is found out,
ended, and a spare helper sends the safe stop, which the plain rclpy test robot gets within the
2 s promise; the run fails saying why, STOP works, and the next run goes through the new helper."""
import os
import signal
import threading
import time

import pytest
from waiting import eventually

from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.events import RunFinished
from rockly_desktop.executor.run_setup import make_runner
from rockly_desktop.robot.ros2.client import Ros2Helper
from rockly_desktop.robot.ros2.link import Ros2Robot

PROMISE = 2.0  # seconds from the fault to zero velocity on the wire
FAULTS = {"hung": signal.SIGSTOP, "killed": signal.SIGKILL}


def drive_and_wait(speed: float) -> str:
    return f"robot.backend.publish('/cmd_vel', 'geometry_msgs/Twist', {{'linear': {{'x': {speed}}}}})\nrobot.wait(60)\n"


@pytest.fixture
def faulty_link(test_robot, turtlebot, ros2_settings):
    """The TurtleBot over ROS 2 with a helper of its own; the helpers a test stopped are ended at
    the end (none is left stopped, alive or a zombie)."""
    Ros2Helper.close_current()
    robot = Ros2Robot(turtlebot, ros2_settings)
    robot.faulted = []
    yield robot
    robot.shutdown()
    Ros2Helper.close_current()
    for process in robot.faulted:
        if process.poll() is None:
            os.kill(process.pid, signal.SIGCONT)
            process.kill()
        process.wait(timeout=10)


def spare_knows_the_robot() -> bool:
    """True once the spare helper has discovered the test robot (a spare is minutes old when a fault comes;
    one started a moment ago may not have met the robot yet: DDS discovery takes a few seconds here)."""
    spare = Ros2Helper.spare()
    if spare is None or spare.lost:
        return False
    spare.started()
    return "/odom" in [name for name, _types, _count in spare.call("graph", timeout=5.0)["topics"]]


def fault(robot, kind: str) -> float:
    """SIGSTOP or kill -9 the link's helper once the spare is ready; when it was done (``time.monotonic()``)."""
    eventually(spare_knows_the_robot, timeout=20)
    robot.faulted.append(robot.helper.process)
    os.kill(robot.helper.process.pid, FAULTS[kind])
    return time.monotonic()


class Run:
    """A program running on its own thread, as the window runs it; ``events`` are what it reported."""

    def __init__(self, robot, code):
        self.control = RunControl()
        self.events = []
        runner = make_runner(robot.profile, robot, {"code": code, "variables": {}}, self.control, self.events.append)
        self.thread = threading.Thread(target=runner.run)
        self.thread.start()

    def finished(self, timeout=10.0) -> RunFinished:
        self.thread.join(timeout)
        assert not self.thread.is_alive()
        return [event for event in self.events if isinstance(event, RunFinished)][-1]


def speed_on_the_wire(test_robot):
    """The linear speed of the last Twist the test robot got on /cmd_vel (None: none yet)."""
    received = test_robot.received("/cmd_vel")
    return received[-1]["message"]["linear"]["x"] if received else None


def stopped_within_the_promise(test_robot, since: float):
    eventually(lambda: speed_on_the_wire(test_robot) == 0.0, timeout=10)
    assert time.monotonic() - since < PROMISE


@pytest.mark.parametrize("kind", FAULTS)
def test_a_lost_helper_is_replaced_the_robot_stopped_and_the_next_run_works(faulty_link, test_robot, kind):
    robot = faulty_link
    first = robot.helper
    run = Run(robot, drive_and_wait(0.2))
    eventually(lambda: speed_on_the_wire(test_robot) == 0.2)
    faulted_at = fault(robot, kind)
    stopped_within_the_promise(test_robot, faulted_at)
    finished = run.finished()
    assert finished.outcome == "error" and "ROS 2 helper process ended" in finished.message
    eventually(lambda: first.process.poll() is not None)  # a hung helper is ended, not left stopped
    if kind == "hung":
        assert first.hung and "said nothing for" in finished.message
    eventually(lambda: robot.replaced is not None)
    link = robot.health()[0]
    assert link.level == "amber" and "the ROS 2 helper was replaced" in str(link.detail)
    assert "sent the robot its safe stop" in str(link.detail) and "ersetzt" in link.detail.in_language("de")
    assert robot.status().state == "connected" and robot.helper is not first

    again = Run(robot, drive_and_wait(0.1))  # no reconnect
    eventually(lambda: speed_on_the_wire(test_robot) == 0.1)
    again.control.request_stop()
    assert again.finished().outcome == "stopped"
    eventually(lambda: speed_on_the_wire(test_robot) == 0.0)


def test_stop_while_the_helper_hangs_reaches_the_robot_within_2_s(faulty_link, test_robot):
    robot = faulty_link
    run = Run(robot, drive_and_wait(0.2))
    eventually(lambda: speed_on_the_wire(test_robot) == 0.2)
    faulted_at = fault(robot, "hung")
    run.control.request_stop()
    stopped_within_the_promise(test_robot, faulted_at)
    assert run.finished().outcome in ("stopped", "error")



def test_a_refused_message_left_unsaid_by_the_program_does_not_keep_the_safe_stop_from_the_robot(faulty_link,
                                                                                                 test_robot):
    """A publish the helper refuses is said by the next command; when the program ends right after it,
    that next command is the safe stop's zero velocity, which must still reach the robot."""
    robot = faulty_link
    code = ("robot.backend.publish('/cmd_vel', 'geometry_msgs/Twist', {'linear': {'x': 0.2}})\n"
            "robot.wait(0.5)\n"
            "robot.backend.publish('/cmd_vel', 'geometry_msgs/Twist', {'linear': {'x': 'fast'}})\n")
    run = Run(robot, code)
    eventually(lambda: speed_on_the_wire(test_robot) == 0.2)
    run.finished()
    eventually(lambda: speed_on_the_wire(test_robot) == 0.0)
