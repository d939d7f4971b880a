"""The agent on the robot driving HOBBIT over ROS 1 (``rockly agent --backend ros1`` against ``rockly sim hobbit
--ros``): a STOP, a lost editor with "stop the robot", and the agent killed mid-run each put a zero velocity on
the wire, seen by an independent rospy node."""
import json
import signal
import subprocess
import time

import pytest
from agent_tools import REPO, hobbit_on_ros_with_wire, ros1_agent, zero_velocities
from standalone_tools import exported_program
from test_standalone_on_ros import far_drive
from waiting import eventually

from rockly_desktop.runtime.agent.client import AgentClient


@pytest.fixture(scope="module")
def robot(tmp_path_factory):
    """``(master, the far-drive program exported, wire recorder)``: HOBBIT simulated on ROS, driving 50 m takes
    long enough for every case here."""
    folder = tmp_path_factory.mktemp("agent-ros")
    exported, _source = exported_program(folder, far_drive(), "far")
    with hobbit_on_ros_with_wire(folder) as (master, wire):
        yield master, exported, wire


@pytest.fixture
def agent(robot, tmp_path):
    with ros1_agent(tmp_path / "library", robot[0]) as agent:
        yield agent


def start_driving(agent, exported, events, **send):
    client = AgentClient("127.0.0.1", agent.port, on_event=events.append)
    client.send("far", exported.read_text(), **send)
    client.attach(control=False)
    client.start("far")
    eventually(lambda: any(event.get("id") == "far" for event in events), 60)
    return client


def test_a_stop_puts_a_zero_velocity_on_the_wire(robot, agent):
    _, exported, wire = robot
    events, before = [], zero_velocities(wire)
    client = start_driving(agent, exported, events)
    try:
        assert agent.robot("stop").returncode == 0
        eventually(lambda: zero_velocities(wire) > before, 30)
        eventually(lambda: any(event.get("state") == "ended" for event in events), 60)
    finally:
        client.close()
    assert next(event for event in events if event.get("event") == "finished")["outcome"] == "stopped"


def test_a_lost_editor_stops_the_robot_within_the_time_to_decide(robot, agent):
    _, exported, wire = robot
    events, before = [], zero_velocities(wire)
    client = start_driving(agent, exported, events, on_lost_editor="stop", decide_seconds=1.0)
    editor = subprocess.Popen(agent.robot_command("attach"), cwd=REPO, text=True, stdout=subprocess.PIPE,
                              stderr=subprocess.DEVNULL)
    try:
        assert json.loads(editor.stdout.readline())["controller"] is True
        editor.kill()  # the window's side is gone: its heartbeats end
        killed = time.monotonic()
        editor.communicate()
        eventually(lambda: zero_velocities(wire) > before, 30)
        # the product's promise: the robot stops within the chosen time (1 s), with room for a loaded machine
        assert time.monotonic() - killed < 1.0 + 4.0
        assert zero_velocities(wire) > before
        eventually(lambda: any(event.get("state") == "ended" for event in events), 60)
    finally:
        client.close()
        if editor.poll() is None:
            editor.kill()
            editor.communicate()
    assert next(event for event in events if event.get("state") == "ended")["stopped_for_lost_editor"] is True


def test_the_agent_killed_mid_run_still_leaves_a_zero_velocity_on_the_wire(robot, agent):
    _, exported, wire = robot
    events, before = [], zero_velocities(wire)
    client = start_driving(agent, exported, events)
    client.close()
    agent.process.send_signal(signal.SIGKILL)
    agent.process.wait(10)
    eventually(lambda: zero_velocities(wire) > before, 30)
