"""The agent's calls over ROS 2 (``rockly agent --backend ros2``'s topics in ``/rockly_agent``), against ``rockly sim
turtlebot --ros2`` on the test run's own domain: ``rockly robot --via ros --domain N`` processes send, list, start,
attach and stop; the editor's process killed mid-run stops the robot (a zero velocity on the wire, seen by an
independent rclpy node) within the time to decide; no agent on the domain is told plainly. Every client is given a
TCP port nobody listens on: what works, works over ROS 2."""
import subprocess
import sys
import time

import pytest
from agent_tools import REPO, AgentProcess, AttachedClient, seconds_until_ended_while_frozen, sent_started_and_watched
from agent_tools import run_ended as ended
from json_line_node import JsonLineNode
from ros2_fixtures import ROS2_PYTHON
from test_standalone_on_ros2 import RECORDER, long_drive_exported, turtlebot_sim_on_ros2
from waiting import eventually

from rockly_desktop.runtime.agent.protocol import AGENT_SILENT_SECONDS

ZERO = {"linear": [0.0, 0.0, 0.0], "angular": [0.0, 0.0, 0.0]}
NO_TCP = ("--port", "1")  # nothing listens there: a call that works went over ROS 2


@pytest.fixture(scope="module")
def robot(tmp_path_factory, ros2_settings):
    """``(settings, the "long" program's standalone export, wire recorder)``: the TurtleBot simulated on ROS 2;
    "long" drives at 0.1 m/s for 120 s (long enough for every case here)."""
    folder = tmp_path_factory.mktemp("agent-over-ros2")
    exported, _source = long_drive_exported(folder)
    on_the_domain = ["--domain", str(ros2_settings.domain_id), "--discovery", "localhost"]
    simulator = turtlebot_sim_on_ros2(on_the_domain)
    wire = JsonLineNode([ROS2_PYTHON, "-c", RECORDER], ros2_settings.environment(), "the wire recorder")
    yield ros2_settings, exported, wire
    wire.stop()
    simulator.terminate()
    simulator.wait(30)
    simulator.stdout.close()
    simulator.stderr.close()


@pytest.fixture
def agent(robot, tmp_path):
    settings, _, _ = robot
    agent = AgentProcess(tmp_path / "library", "--domain", settings.domain_id, "--discovery", "localhost",
                         backend="ros2")
    yield agent
    agent.stop()


def robot_command(settings, *args, language="en") -> list:
    """``rockly robot --via ros --domain N ARGS`` (with a TCP port nobody listens on)."""
    return [sys.executable, "-m", "rockly_desktop", "robot", "--via", "ros", "--domain", str(settings.domain_id),
            *NO_TCP, "--language", language, *map(str, args)]


def run_robot(settings, *args, language="en") -> subprocess.CompletedProcess:
    return subprocess.run(robot_command(settings, *args, language=language), capture_output=True, text=True,
                          timeout=120, cwd=REPO, env=settings.environment())


def attached(settings, *options) -> AttachedClient:
    """``rockly robot --via ros --domain N attach [--watch-only]`` as a process."""
    return AttachedClient(robot_command(settings, "attach", *options), settings.environment())


def zeros(wire) -> int:
    return sum(1 for line in list(wire.lines) if line == ZERO)


def driving(wire, since: int) -> bool:
    """Whether the recorder heard the program drive after its first ``since`` lines (the module's earlier runs
    drove too)."""
    return any(line["linear"][0] == 0.1 for line in list(wire.lines)[since:])


def started(settings, program, *send_options) -> AttachedClient:
    """Send the program as "long", start it and attach a watcher (not the editor) once it drives."""
    return sent_started_and_watched(lambda *args: run_robot(settings, *args),
                                    lambda *options: attached(settings, *options), program, "long", *send_options)


def test_send_list_start_attach_and_stop_over_ros2(robot, agent):
    settings, program, wire = robot
    since = len(wire.lines)
    watcher = started(settings, program)
    try:
        listed = run_robot(settings, "list")
        assert listed.returncode == 0, listed.stderr
        assert listed.stdout.startswith("long  turtlebot ") and "running: long" in listed.stdout
        # without --via: the domain given and an agent on it mean ROS 2
        auto = subprocess.run([sys.executable, "-m", "rockly_desktop", "robot", "--domain", str(settings.domain_id),
                               *NO_TCP, "list"], capture_output=True, text=True, timeout=120, cwd=REPO,
                              env=settings.environment())
        assert auto.returncode == 0 and auto.stdout == listed.stdout, auto.stderr
        eventually(lambda: driving(wire, since), 60)
        before = zeros(wire)
        stopped = run_robot(settings, "stop")
        assert stopped.stdout == "the program was stopped (the robot stops safely)\n", stopped.stderr
        eventually(lambda: zeros(wire) > before, 30)  # the safe stop's zero velocity, on the wire
        end = watcher.wait_for(ended)  # events arrive over ROS 2
        watcher.process.wait(60)
    finally:
        watcher.end()
    finished = watcher.wait_for(lambda line: line.get("event") == "finished")
    assert finished["outcome"] == "stopped" and end["status"] == 130
    assert watcher.process.returncode == 0  # the attached process ends with the run
    deleted = run_robot(settings, "delete", "long")
    assert deleted.stdout == "'long' was deleted from the robot\n", deleted.stderr
    assert run_robot(settings, "list").stdout == "no programs on the robot yet\n"


def test_a_lost_editor_over_ros2_stops_the_robot_within_the_time_to_decide(robot, agent):
    settings, program, wire = robot
    since = len(wire.lines)
    watcher = started(settings, program, "--decide-seconds", "1")
    editor = attached(settings)
    try:
        assert editor.first["controller"] is True
        eventually(lambda: driving(wire, since), 60)
        before = zeros(wire)
        editor.process.kill()  # the window's side is gone: its heartbeats end
        killed = time.monotonic()
        eventually(lambda: zeros(wire) > before, 30)
        # the product's promise: the robot stops within the chosen time (1 s), with room for a loaded machine
        assert time.monotonic() - killed < 1.0 + 4.0
        end = watcher.wait_for(ended)
    finally:
        editor.end()
        watcher.end()
    assert end["stopped_for_lost_editor"] is True
    assert watcher.seen(lambda line: line.get("state") == "editor_lost")


def test_no_agent_on_the_domain_is_said(robot):
    settings, _, _ = robot
    told = run_robot(settings, "--namespace", "/nobody_here", "list", language="de")
    assert told.returncode == 1
    assert told.stderr.startswith("rockly robot: kein Rockly-Agent antwortet im ROS-2-Namensraum /nobody_here in "
                                  f"Domäne {settings.domain_id}"), told.stderr


def test_the_agent_killed_mid_run_is_heard_lost_and_the_robot_stops(robot, agent):
    """A topic has no closed connection: a client hears the agent lost as its publisher gone from the graph (the
    killed agent's helper leaves it); the run's own process stops the robot without the agent."""
    settings, program, wire = robot
    since = len(wire.lines)
    watcher = started(settings, program)
    try:
        eventually(lambda: driving(wire, since), 60)
        before = zeros(wire)
        agent.process.kill()
        agent.process.wait(10)
        watcher.process.wait(60)  # the attached client ends: it lost the agent
        eventually(lambda: zeros(wire) > before, 30)
    finally:
        watcher.end()
    assert watcher.process.returncode == 0 and not watcher.seen(ended)


def test_a_frozen_agent_is_heard_lost_over_ros2_and_its_run_goes_on(robot, agent):
    """SIGSTOP leaves the agent's publisher in the graph (its ROS 2 helper lives on): the attached client hears the
    agent fall silent and ends as for a lost publisher; the run's own process goes on driving, and the agent, woken,
    still runs it (a keep-going program)."""
    settings, program, wire = robot
    since = len(wire.lines)
    watcher = started(settings, program, "--keep-going")
    try:
        eventually(lambda: driving(wire, since), 60)

        def drives_on():  # the run drives on without the agent
            moving = len(wire.lines)
            eventually(lambda: driving(wire, moving), 30)
        took = seconds_until_ended_while_frozen(agent.process, watcher.process, drives_on)
    finally:
        watcher.end()
    assert watcher.process.returncode == 0 and not watcher.seen(ended)
    # the product's promise: a few seconds, with room for a loaded machine
    assert took < AGENT_SILENT_SECONDS + 10
    listed = run_robot(settings, "list")
    assert listed.returncode == 0 and "running: long" in listed.stdout, listed.stderr
    stopped = run_robot(settings, "stop")
    assert stopped.returncode == 0, stopped.stderr
