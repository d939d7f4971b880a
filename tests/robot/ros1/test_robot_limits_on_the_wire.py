"""The robot keeps its own limits (``rockly agent limits``): a program sent to the agent with no limits of its own
(as a stranger writes one: ``limits: {}`` and a Twist of 3 m/s in its code) drives no faster than the robot's
limit, as an independent rospy node sees on the wire; a broken limits file stops every run instead of lifting
the limits (issue 30)."""
import re
import struct
import subprocess
import sys

import pytest
from agent_tools import REPO, AgentProcess, hobbit_on_ros_with_wire
from program_builder import block, number, rockly_document
from ros_helpers import ros_environment
from standalone_tools import export_standalone
from waiting import eventually

from rockly_desktop.runtime.agent.client import AgentClient

FAST = ("ros.publish_message('/cmd_vel', 'geometry_msgs/Twist', {'linear': {'x': 3.0}, 'angular': {'z': 2.0}})\n"
        "ros.wait(0.5)\n")


@pytest.fixture(scope="module")
def robot(tmp_path_factory):
    """``(master, a stranger's standalone text, wire recorder of /cmd_vel)``."""
    folder = tmp_path_factory.mktemp("robot-limits")
    source = folder / "wait.rockly"
    source.write_text(rockly_document([block("hobbit_wait", inputs={"seconds": number(1)})]))
    exported = export_standalone(source, folder / "wait.py", "--language", "en").read_text()
    stranger = re.sub(r'RUN_CODE = """.*?"""', lambda _: f'RUN_CODE = """{FAST}"""', exported, flags=re.S)
    assert "'limits': {" in stranger and "3.0" in stranger
    with hobbit_on_ros_with_wire(folder) as (master, wire):
        yield master, stranger, wire


def limits_command(config, *args):
    return subprocess.run([sys.executable, "-m", "rockly_desktop", "agent", "--robot-limits", str(config), "limits",
                           *args], capture_output=True, text=True, cwd=REPO, timeout=120)


def speeds_on_the_wire(wire) -> list:
    """``(linear.x, angular.z)`` of every Twist seen on /cmd_vel."""
    return [(twist[0], twist[5]) for twist in (struct.unpack("<6d", raw) for _type, raw in wire.on("/cmd_vel"))]


def run_on_the_agent(master, library, limits_file, standalone) -> dict:
    agent = AgentProcess(library, "--master", master.uri, "--robot-limits", limits_file, backend="ros1",
                         env=ros_environment(master.uri, master.home))
    client = AgentClient("127.0.0.1", agent.port)
    try:
        client.send("fast", standalone)
        client.start("fast")
        eventually(lambda: client.programs()["run"] is None, 60)
        return client.programs()
    finally:
        client.close()
        agent.stop()


def test_a_program_without_limits_drives_no_faster_than_the_robots_own(robot, tmp_path):
    master, stranger, wire = robot
    limits_file = tmp_path / "robot-limits.json"
    set_limits = limits_command(limits_file, "--max-speed", "0.2", "--max-turn", "30")
    assert set_limits.returncode == 0 and "0.2 m/s" in set_limits.stdout, set_limits.stderr
    seen_before = len(wire.on("/cmd_vel"))
    run_on_the_agent(master, tmp_path / "library", limits_file, stranger)
    eventually(lambda: len(wire.on("/cmd_vel")) > seen_before, 30)
    speeds = speeds_on_the_wire(wire)[seen_before:]
    assert any(linear > 0 for linear, _ in speeds), speeds   # it drove: the Twist went out, held to the limit
    assert all(abs(linear) <= 0.2 + 1e-9 and abs(angular) <= 0.5236 + 1e-3 for linear, angular in speeds), speeds


def test_a_broken_limits_file_runs_nothing(robot, tmp_path):
    master, stranger, wire = robot
    limits_file = tmp_path / "robot-limits.json"
    limits_file.write_text('{"max_speed": "fast"}')
    seen_before = len(wire.on("/cmd_vel"))
    run_on_the_agent(master, tmp_path / "library", limits_file, stranger)
    assert [speed for speed in speeds_on_the_wire(wire)[seen_before:] if speed != (0.0, 0.0)] == []
    shown = limits_command(limits_file)
    assert shown.returncode == 1 and "cannot be read" in shown.stderr
