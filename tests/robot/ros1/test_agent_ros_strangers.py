"""Strangers on the robot's ROS 1 master against the agent's topics (``rockly agent --backend ros1``, HOBBIT
simulated; the checks: tests/agent_strangers.py): a plain rospy node publishes requests in clear, replays what a
paired laptop sent, forges a paired laptop's name or box, and listens to everything; the laptop pairs over ROS."""
import sys
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
from agent_tools import AgentProcess, hobbit_on_ros_with_wire, put_back_on_own_master
from program_builder import block, number, rockly_document
from ros_helpers import ros_environment
from standalone_tools import export_standalone

STRANGER = Path(__file__).parent / "ros1_agent_stranger.py"


@pytest.fixture(scope="module")
def robot(tmp_path_factory):
    """``(master, "far"'s standalone export)``: HOBBIT simulated on a master of its own; "far" drives 50 m (long
    enough for every case here)."""
    folder = tmp_path_factory.mktemp("agent-strangers")
    far = folder / "far.rockly"
    far.write_text(rockly_document([block("hobbit_move", {"direction": "+"}, {"speed": number(50)}, id="far")]))
    with hobbit_on_ros_with_wire(folder) as (master, _wire):
        yield master, export_standalone(far, folder / "far.py", "--language", "en")


@pytest.fixture
def scene(robot, tmp_path):
    """``(laptop, stranger, program)``: a fresh agent, a laptop paired with it over ROS, and a stranger on the
    master that heard all of it."""
    master, program = robot
    put_back_on_own_master(master)  # earlier drives would have taken HOBBIT into a wall
    laptop = Laptop(["--master", master.uri], ros_environment(master.uri, master.home), tmp_path / "laptop")
    agent = AgentProcess(tmp_path / "library", "--master", master.uri, backend="ros1", env=laptop.env)
    stranger = Stranger([sys.executable, STRANGER], laptop.env)
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
    a_listener_reads_nothing(laptop, stranger, program, "hobbit_move")


def test_recorded_boxes_of_a_start_and_a_stop_are_ignored(scene):
    recorded_boxes_of_a_start_and_a_stop_are_ignored(*scene)


def test_a_forged_name_or_box_leaves_the_editor_in_control(scene):
    a_forged_name_or_box_leaves_the_editor_in_control(*scene)


def test_a_client_from_before_pairing_is_told_to_update_and_pair(scene):
    _, stranger, _ = scene
    a_client_from_before_pairing_is_told_to_update_and_pair(stranger)
