"""The agent's ``robot_limits`` (issue 30: the robot keeps its own limits, and a paired teacher sets them from the
window): the agent in a process of its own on 127.0.0.1, clients paired with codes ``rockly agent pair`` printed.
A teacher reads and sets the robot's limits file; a student, a laptop never paired and a stranger speaking the wire
protocol are refused and change nothing; ill-typed limits are refused; a file the agent may not write is said."""
import json
import re
import subprocess
import sys

import pytest
from agent_tools import REPO, AgentProcess

from rockly_desktop.runtime.agent.client import AgentClient, AgentError
from rockly_desktop.runtime.agent.robot_keys import RobotKeys

CODE = re.compile(r"\b[2-9A-Z]{3}-[2-9A-Z]{3}\b")
NONE = {"max_speed": None, "max_turn": None, "switched_off": []}


def code_from_the_robot(library, *options) -> str:
    done = subprocess.run([sys.executable, "-m", "rockly_desktop", "agent", "--library", str(library), "pair",
                           *options], capture_output=True, text=True, cwd=REPO, timeout=120)
    assert done.returncode == 0, done.stderr
    return CODE.search(done.stdout).group(0)


def paired_clients(agent, library, folder) -> list:
    """A teacher's and a student's client of ``agent``, each laptop with keys of its own in ``folder``, paired with
    codes ``rockly agent pair`` printed, then connected anew (a connection proves its key in its hello)."""
    for role in ("teacher", "student"):
        client = AgentClient("127.0.0.1", agent.port, keys=RobotKeys(folder / f"{role}.json"))
        try:
            assert client.pair(code_from_the_robot(library, "--role", role)).role == role
        finally:
            client.close()
    return [AgentClient("127.0.0.1", agent.port, keys=RobotKeys(folder / f"{role}.json"))
            for role in ("teacher", "student")]


@pytest.fixture
def robot(tmp_path):
    """``(agent, its limits file, a teacher's client, a student's client)``."""
    limits_file = tmp_path / "limits" / "robot-limits.json"
    agent = AgentProcess(tmp_path / "library", "--robot-limits", limits_file, paired=False)
    clients = []
    try:
        clients = paired_clients(agent, tmp_path / "library", tmp_path)
        yield agent, limits_file, *clients
    finally:
        for client in clients:
            client.close()
        agent.stop()


def test_a_teacher_reads_and_sets_the_robots_own_limits(robot):
    agent, limits_file, teacher, student = robot
    assert teacher.robot_limits() == NONE   # no file: the robot limits nothing itself
    kept = teacher.robot_limits({"max_speed": 0.25, "max_turn": 40, "switched_off": ["arm"]})
    assert kept == {"max_speed": 0.25, "max_turn": 40.0, "switched_off": ["arm"]}
    assert json.loads(limits_file.read_text()) == kept   # the file every run on the robot reads
    shown = subprocess.run([sys.executable, "-m", "rockly_desktop", "agent", "--robot-limits", str(limits_file),
                            "limits"], capture_output=True, text=True, cwd=REPO, timeout=120)
    assert "highest speed 0.25 m/s" in shown.stdout and "switched off: arm" in shown.stdout
    assert teacher.robot_limits(NONE) == NONE


def test_a_student_is_refused_and_the_limits_stay(robot):
    agent, limits_file, teacher, student = robot
    teacher.robot_limits({"max_speed": 0.2, "max_turn": None, "switched_off": []})
    for asking in (lambda: student.robot_limits(), lambda: student.robot_limits(NONE)):
        with pytest.raises(AgentError) as refused:
            asking()
        assert refused.value.key == "agent_teacher_only"
    assert json.loads(limits_file.read_text())["max_speed"] == 0.2


def test_a_laptop_never_paired_is_refused(robot, tmp_path):
    agent, limits_file, teacher, student = robot
    stranger = AgentClient("127.0.0.1", agent.port, keys=RobotKeys(tmp_path / "nobody.json"))
    try:
        with pytest.raises(AgentError) as refused:
            stranger.robot_limits(NONE)
        assert refused.value.key == "agent_not_paired"
    finally:
        stranger.close()
    assert not limits_file.exists()


@pytest.mark.parametrize("wanted", [{"max_speed": -1}, {"max_speed": "fast"}, {"max_turn": float("inf")},
                                    {"switched_off": "arm"}, {"switched_off": [1]}, {"speed": 3.0}, [], "none"])
def test_ill_typed_limits_are_refused_and_change_nothing(robot, wanted):
    agent, limits_file, teacher, student = robot
    teacher.robot_limits({"max_speed": 0.2, "max_turn": None, "switched_off": []})
    with pytest.raises(AgentError) as refused:
        teacher.robot_limits(wanted)
    assert refused.value.key == "agent_bad_request"
    assert json.loads(limits_file.read_text())["max_speed"] == 0.2


def test_a_limits_file_the_agent_may_not_write_is_said(tmp_path):
    (tmp_path / "not-a-folder").write_text("")   # no user, root neither, writes a file under a file
    agent = AgentProcess(tmp_path / "library", "--robot-limits", tmp_path / "not-a-folder" / "robot-limits.json",
                         paired=False)
    clients = []
    try:
        clients = paired_clients(agent, tmp_path / "library", tmp_path)
        with pytest.raises(AgentError) as refused:
            clients[0].robot_limits(NONE)
        assert refused.value.key == "agent_limits_cannot_write"
        assert refused.value.message.startswith("the robot's limits cannot be kept: ")
    finally:
        for client in clients:
            client.close()
        agent.stop()
