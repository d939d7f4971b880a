"""The agent's calls over ROS 1 (``rockly agent --backend ros1``'s topics in ``/rockly_agent``), against ``rockly sim
hobbit --ros`` on a master of the test's own: ``rockly robot --via ros`` processes send, list, start, attach and
stop; the editor's process killed mid-run stops the robot (a zero velocity on the wire, seen by an independent
rospy node) or lets the run finish, as the program says; a client of another version, or no agent in the
graph, is told plainly. Every client is given a TCP port nobody listens on: what works, works over ROS."""
import subprocess
import sys
import time

import pytest
from agent_tools import (
    REPO,
    AttachedClient,
    hobbit_on_ros_with_wire,
    put_back_on_own_master,
    ros1_agent,
    seconds_until_ended_while_frozen,
    sent_started_and_watched,
    zero_velocities,
)
from agent_tools import run_ended as ended
from program_builder import block, number, rockly_document, stack
from ros_helpers import ros_environment
from standalone_tools import export_standalone
from waiting import eventually

from rockly_desktop.runtime.agent.protocol import AGENT_SILENT_SECONDS, DEFAULT_NAMESPACE
from rockly_desktop.runtime.agent.robot_keys import RobotKey, RobotKeys, ros_address

NO_TCP = ("--port", "1")  # nothing listens there: a call that works went over ROS


@pytest.fixture(scope="module")
def robot(tmp_path_factory):
    """``(master, programs, wire recorder)``: HOBBIT simulated on ROS; ``programs``: "far" drives 50 m (long
    enough for every case here), "short" drives, waits 4 s and drives back."""
    folder = tmp_path_factory.mktemp("agent-over-ros")
    far, short = folder / "far.rockly", folder / "short.rockly"
    far.write_text(rockly_document([block("hobbit_move", {"direction": "+"}, {"speed": number(50)}, id="far")]))
    short.write_text(rockly_document([stack(
        block("hobbit_move", {"direction": "+"}, {"speed": number(1)}, id="go"),
        block("hobbit_wait", inputs={"seconds": number(4)}, id="linger"),
        block("hobbit_move", {"direction": "-"}, {"speed": number(1)}, id="back"))]))
    programs = {path.stem: export_standalone(path, folder / f"{path.stem}.py", "--language", "en")
                for path in (far, short)}
    with hobbit_on_ros_with_wire(folder) as (master, wire):
        yield master, programs, wire


@pytest.fixture
def agent(robot, tmp_path):
    """The agent, on a simulator put back where it started: the drives of the tests before (whose number and length
    depend on their order and the machine's load) would otherwise have taken HOBBIT into a wall."""
    put_back_on_own_master(robot[0])
    with ros1_agent(tmp_path / "library", robot[0]) as agent:
        yield agent


def robot_command(master, *args, language="en") -> list:
    """``rockly robot --via ros --master MASTER ARGS`` (with a TCP port nobody listens on)."""
    return [sys.executable, "-m", "rockly_desktop", "robot", "--via", "ros", "--master", master.uri, *NO_TCP,
            "--language", language, *map(str, args)]


def run_robot(master, *args, language="en") -> subprocess.CompletedProcess:
    return subprocess.run(robot_command(master, *args, language=language), capture_output=True, text=True,
                          timeout=120, cwd=REPO, env=ros_environment(master.uri, master.home))


def attached(master, *options) -> AttachedClient:
    """``rockly robot --via ros attach [--watch-only]`` as a process."""
    return AttachedClient(robot_command(master, "attach", *options), ros_environment(master.uri, master.home))


def started(master, programs, name, *send_options) -> AttachedClient:
    """Send program ``name``, start it and attach a watcher (not the editor) once it drives."""
    return sent_started_and_watched(lambda *args: run_robot(master, *args), lambda *options: attached(master, *options),
                                    programs[name], name, *send_options)


def test_send_list_start_attach_and_stop_over_ros(robot, agent):
    master, programs, wire = robot
    before = zero_velocities(wire)
    watcher = started(master, programs, "far")
    try:
        listed = run_robot(master, "list")
        assert listed.returncode == 0, listed.stderr
        assert listed.stdout.startswith("far  hobbit 1.0.0  came 20") and "running: far" in listed.stdout
        # without --via: the master given and an agent in its graph mean ROS
        auto = subprocess.run([sys.executable, "-m", "rockly_desktop", "robot", "--master", master.uri, *NO_TCP,
                               "list"], capture_output=True, text=True, timeout=120, cwd=REPO,
                              env=ros_environment(master.uri, master.home))
        assert auto.returncode == 0 and auto.stdout == listed.stdout, auto.stderr
        eventually(lambda: (watcher.first["run"]["block"] == "far"
                            or watcher.seen(lambda line: line.get("id") == "far")), 60)
        stopped = run_robot(master, "stop")
        assert stopped.stdout == "the program was stopped (the robot stops safely)\n", stopped.stderr
        eventually(lambda: zero_velocities(wire) > before, 30)
        end = watcher.wait_for(ended)  # events arrive over ROS
        watcher.process.wait(60)
    finally:
        watcher.end()
    finished = watcher.wait_for(lambda line: line.get("event") == "finished")
    assert finished["outcome"] == "stopped" and end["status"] == 130
    assert watcher.process.returncode == 0  # the attached process ends with the run
    deleted = run_robot(master, "delete", "far")
    assert deleted.stdout == "'far' was deleted from the robot\n", deleted.stderr
    assert run_robot(master, "list").stdout == "no programs on the robot yet\n"


def test_a_lost_editor_over_ros_stops_the_robot_within_the_time_to_decide(robot, agent):
    master, programs, wire = robot
    watcher = started(master, programs, "far", "--decide-seconds", "1")
    editor = attached(master)
    try:
        assert editor.first["controller"] is True
        before = zero_velocities(wire)
        editor.process.kill()  # the window's side is gone: its heartbeats end
        killed = time.monotonic()
        eventually(lambda: zero_velocities(wire) > before, 30)
        # the product's promise: the robot stops within the chosen time (1 s), with room for a loaded machine
        assert time.monotonic() - killed < 1.0 + 4.0
        end = watcher.wait_for(ended)
    finally:
        editor.end()
        watcher.end()
    assert end["stopped_for_lost_editor"] is True
    assert watcher.seen(lambda line: line.get("state") == "editor_lost")


def test_a_frozen_agent_is_heard_lost_over_ros_and_its_run_goes_on(robot, agent):
    """SIGSTOP leaves the agent's publisher at the master for ever: the attached client hears the agent fall silent
    and ends as for a lost publisher; the agent, woken, still runs the program (a keep-going one)."""
    master, programs, _ = robot
    watcher = started(master, programs, "far", "--keep-going")
    try:
        took = seconds_until_ended_while_frozen(agent.process, watcher.process)
    finally:
        watcher.end()
    assert watcher.process.returncode == 0 and not watcher.seen(ended)
    # the product's promise: a few seconds, with room for a loaded machine
    assert took < AGENT_SILENT_SECONDS + 10
    listed = run_robot(master, "list")
    assert listed.returncode == 0 and "running: far" in listed.stdout, listed.stderr
    assert run_robot(master, "stop").returncode == 0


def test_a_lost_editor_over_ros_lets_a_keep_going_program_finish(robot, agent):
    master, programs, _ = robot
    watcher = started(master, programs, "short", "--keep-going", "--decide-seconds", "0.5")
    editor = attached(master)
    try:
        run = editor.first["run"]
        assert editor.first["controller"] is True and run is not None and run["state"] != "ended", watcher.lines
        editor.process.kill()
        end = watcher.wait_for(ended, 120)
    finally:
        editor.end()
        watcher.end()
    assert end["status"] == 0 and end["stopped_for_lost_editor"] is False, watcher.lines
    assert watcher.seen(lambda line: line.get("id") == "back")  # it went on past the time to decide
    assert watcher.seen(lambda line: line.get("event") == "finished")[0]["outcome"] == "finished"


OTHER_VERSION = """
import sys
import rockly_desktop.runtime.agent.client as client
client.FORMAT, client.__version__ = client.FORMAT + 1, "9.0.0"
from rockly_desktop.runtime.agent.commands import robot_main
sys.exit(robot_main(sys.argv[1:]))
"""


@pytest.mark.parametrize("language, expected", [
    ("en", "rockly robot: the robot's agent (Rockly 0.1.0) and this Rockly (9.0.0) do not speak the same language"),
    ("de", "rockly robot: der Agent des Roboters (Rockly 0.1.0) und dieses Rockly (9.0.0) sprechen nicht dieselbe "
           "Sprache"),
])
def test_a_client_of_another_version_is_told_over_ros(robot, agent, language, expected):
    master, _, _ = robot
    told = subprocess.run([sys.executable, "-c", OTHER_VERSION, "--via", "ros", "--master", master.uri, *NO_TCP,
                           "--language", language, "list"], capture_output=True, text=True, timeout=120, cwd=REPO,
                          env=ros_environment(master.uri, master.home))
    assert told.returncode == 1 and told.stderr.startswith(expected), told.stderr


def test_no_agent_in_the_graph_is_said(robot):
    master, _, _ = robot
    told = run_robot(master, "--namespace", "/nobody_here", "list", language="de")
    assert told.returncode == 1
    assert told.stderr == (f"rockly robot: kein Rockly-Agent antwortet im ROS-1-Namensraum /nobody_here bei "
                           f"{master.uri} (läuft 'rockly agent --backend ros1' auf dem Roboter, mit diesem Master?)\n")


def test_an_editor_gone_silent_over_ros_leaves_control_to_the_next(robot, agent):
    """A topic has no closed connection: the agent forgets a client it no longer hears (5 s), so a window that
    comes after the killed editor controls the run."""
    master, programs, _ = robot
    watcher = started(master, programs, "far", "--keep-going")
    editor = attached(master)
    assert editor.first["controller"] is True
    editor.process.kill()
    editor.end()

    def next_window_controls():
        try:
            window = attached(master)
        except AssertionError:  # no answer this time: each look before left a killed client at the master
            return False
        window.end()
        return window.first["controller"]
    try:
        eventually(next_window_controls, 60, interval=0.5)
        assert run_robot(master, "stop").returncode == 0
        watcher.wait_for(ended)
    finally:
        watcher.end()


def test_over_ros_an_unpaired_or_forged_client_is_refused(robot, agent, tmp_path):
    """A node on the master that is not paired sends ``list`` and ``send``: each is refused; one with a key the
    agent never gave, in the teacher's id, is not answered at all (its boxes do not open: docs/decisions/036);
    nothing is kept."""
    master, programs, _ = robot
    stranger_config = tmp_path / "stranger-config"
    env = dict(ros_environment(master.uri, master.home), XDG_CONFIG_HOME=str(stranger_config))

    def as_stranger(*args):
        return subprocess.run(robot_command(master, *args), capture_output=True, text=True, timeout=120, cwd=REPO,
                              env=env)
    for args in (("list",), ("send", programs["far"], "--name", "innocent")):
        refused = as_stranger(*args)
        assert refused.returncode == 1 and "is not paired with the robot's agent" in refused.stderr, refused.stderr
    RobotKeys(stranger_config / "rockly" / "robot-keys.json").save(RobotKey(
        ros_address("ros1", master.uri, DEFAULT_NAMESPACE), agent.key.agent, agent.key.client, b"x" * 32, "teacher",
        ""))  # the teacher's id, a key of its own making
    forged = as_stranger("send", programs["far"], "--name", "innocent")
    assert forged.returncode == 1 and "did not answer within 10 s" in forged.stderr, forged.stderr
    listed = run_robot(master, "list")
    assert listed.returncode == 0 and "innocent" not in listed.stdout and "no programs" in listed.stdout, listed.stderr
