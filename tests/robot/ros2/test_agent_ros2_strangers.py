"""Strangers on the robot's ROS 2 domain against the agent's topics (``rockly agent --backend ros2``, the TurtleBot
simulated; the checks: tests/agent_strangers.py): a plain rclpy node publishes requests in clear, replays what a
paired laptop sent, forges a paired laptop's name or box, and listens to everything; the laptop pairs over ROS 2."""
from pathlib import Path

import pytest
from agent_strangers import (
    Laptop,
    Stranger,
    a_client_from_before_pairing_is_told_to_update_and_pair,
    a_forged_name_or_box_leaves_the_editor_in_control,
    a_listener_reads_nothing,
    recorded_boxes_of_a_start_and_a_stop_are_ignored,
    requests_in_clear_are_refused_and_nothing_runs,
)
from agent_tools import AgentProcess
from ros2_fixtures import ROS2_PYTHON
from test_standalone_on_ros2 import long_drive_exported, turtlebot_sim_on_ros2

STRANGER = Path(__file__).parent / "ros2_agent_stranger.py"


@pytest.fixture(scope="module")
def robot(tmp_path_factory, ros2_settings):
    """``(settings, "long"'s standalone export)``: the TurtleBot simulated on ROS 2; "long" drives at 0.1 m/s for
    120 s (long enough for every case here)."""
    folder = tmp_path_factory.mktemp("agent-strangers-ros2")
    exported, _source = long_drive_exported(folder)
    simulator = turtlebot_sim_on_ros2(["--domain", str(ros2_settings.domain_id), "--discovery", "localhost"])
    yield ros2_settings, exported
    simulator.terminate()
    simulator.wait(30)
    simulator.stdout.close()
    simulator.stderr.close()


@pytest.fixture
def scene(robot, tmp_path):
    """``(laptop, stranger, program)``: a fresh agent, a laptop paired with it over ROS 2, and a stranger on the
    domain that heard all of it."""
    settings, program = robot
    laptop = Laptop(["--domain", settings.domain_id], settings.environment(), tmp_path / "laptop")
    agent = AgentProcess(tmp_path / "library", "--domain", settings.domain_id, "--discovery", "localhost",
                         backend="ros2", env=laptop.env)
    stranger = Stranger([ROS2_PYTHON, STRANGER], laptop.env)
    try:
        laptop.pair(tmp_path / "library")
        yield laptop, stranger, program
    finally:
        stranger.stop()
        agent.stop()


def test_a_strangers_send_and_start_in_clear_are_refused_and_nothing_runs(scene, tmp_path):
    laptop, stranger, _ = scene
    requests_in_clear_are_refused_and_nothing_runs(laptop, stranger, tmp_path)


def test_a_listener_reads_nothing_of_the_pairing_the_programs_or_the_run(scene):
    laptop, stranger, program = scene
    a_listener_reads_nothing(laptop, stranger, program, "turtlebot_drive_for")


def test_recorded_boxes_of_a_start_and_a_stop_are_ignored(scene):
    recorded_boxes_of_a_start_and_a_stop_are_ignored(*scene)


def test_a_forged_name_or_box_leaves_the_editor_in_control(scene):
    a_forged_name_or_box_leaves_the_editor_in_control(*scene)


def test_a_client_from_before_pairing_is_told_to_update_and_pair(scene):
    _, stranger, _ = scene
    a_client_from_before_pairing_is_told_to_update_and_pair(stranger)
