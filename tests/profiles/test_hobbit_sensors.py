"""HOBBIT's sensor commands on the real simulator: battery, position, head, emotion, arm motion, any field."""
import threading

import pytest

from rockly_desktop.core.errors import RobotCommandError
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.sim.sim_world import SimBackend, SimWorld


@pytest.fixture
def robot(hobbit):
    world = SimWorld()
    simulator = hobbit.load_object("simulator")(world, speed=20)
    simulator.start()
    yield hobbit.load_object("api")(SimBackend(world, Interrupt())), simulator, world
    simulator.shutdown()


def test_battery_and_position_follow_the_robot(robot):
    commands, simulator, _ = robot
    assert 95 < commands.battery_level() <= 100
    commands.drive(0.5)
    commands.turn(90, "left")
    assert commands.position("x") == pytest.approx(0.5, abs=0.02)
    assert commands.position("y") == pytest.approx(0.0, abs=0.02)
    assert commands.position("heading") == pytest.approx(90, abs=2)
    with pytest.raises(RobotCommandError, match="coordinate"):
        commands.position("z")


def test_head_and_emotion_report_the_last_command(robot):
    commands, _, _ = robot
    assert (commands.head_position(), commands.emotion()) == ("center_center", "NEUTRAL")
    commands.look("down_left")
    commands.show_emotion("VHAPPY")
    assert (commands.head_position(), commands.emotion()) == ("down_left", "VHAPPY")


def test_arm_is_moving_only_while_it_moves(robot):
    commands, simulator, world = robot
    assert commands.arm_is_moving() is False
    mover = threading.Thread(target=commands.move_arm, args=("candle",))
    mover.start()
    simulator_moving = world.wait_for(lambda: simulator.snapshot()["arm_target"] is not None, 5)
    assert simulator_moving and commands.arm_is_moving() is True
    mover.join(10)
    assert commands.arm_is_moving() is False


def test_latest_value_reads_any_field_and_names_a_wrong_one(robot):
    commands, _, _ = robot
    commands.drive(0.3)
    assert commands.latest_value("/odom", "pose.pose.position.x") == pytest.approx(0.3, abs=0.02)
    with pytest.raises(RobotCommandError, match="no field 'pose.nose'"):
        commands.latest_value("/odom", "pose.nose")
