"""The robot's safe stop runs however a run ends: finished, stopped or failed (real simulator)."""
import threading

import pytest

from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.run_setup import make_runner
from rockly_desktop.robot.sim.link import SimulatedRobot

DRIVE_ON = "robot.backend.publish('/cmd_vel', 'geometry_msgs/Twist', {'linear': {'x': 0.3}, 'angular': {'z': 0.2}})\n"
ARM_GOAL = ("robot.backend.send_goal('hobbit_arm', 'hobbit_msgs/ArmServerAction', "
            "{'command': {'data': 'MoveToCandle'}})\n")


@pytest.fixture
def robot(hobbit):
    robot = SimulatedRobot(hobbit, speed=1.0)
    yield robot
    robot.shutdown()


def run(hobbit, robot, code, control=None):
    control = control or RunControl()
    return make_runner(hobbit, robot, {"code": code, "variables": {}}, control, lambda event: None).run()


def moving(snapshot):
    return snapshot["linear"] != 0 or snapshot["angular"] != 0 or snapshot["arm_target"] is not None


def comes_to_rest(robot):
    """The simulator obeys the safe stop within its next control cycles."""
    return robot.world.wait_for(lambda: not moving(robot.snapshot()), 0.5)


def test_a_program_that_ends_while_the_robot_moves_leaves_it_still(hobbit, robot):
    result = run(hobbit, robot, DRIVE_ON + ARM_GOAL + "robot.backend.sleep(0.2)\n")
    assert result.outcome == "finished"
    assert comes_to_rest(robot), robot.snapshot()


def test_a_program_that_fails_leaves_the_robot_still(hobbit, robot):
    result = run(hobbit, robot, DRIVE_ON + ARM_GOAL + "x = 1 / 0\n")
    assert result.outcome == "error"
    assert comes_to_rest(robot), robot.snapshot()


def test_a_stopped_program_leaves_the_robot_still(hobbit, robot):
    control = RunControl()
    outcome = []
    thread = threading.Thread(target=lambda: outcome.append(run(hobbit, robot, DRIVE_ON + "robot.wait(60)\n", control)))
    thread.start()
    robot.world.wait_for(lambda: robot.snapshot()["linear"] > 0, 5)
    control.request_stop()
    thread.join(5)
    assert outcome[0].outcome == "stopped"
    assert comes_to_rest(robot), robot.snapshot()
