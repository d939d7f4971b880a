"""Strangers on the robot's ROS 1 master against the agent's topics (``rockly agent --backend ros1``, HOBBIT
simulated): a plain rospy node (``ros1_agent_stranger.py``, no Rockly code) that publishes requests in clear,
replays what a paired laptop sent, forges a paired laptop's name or box, and listens to everything. The laptop is
``rockly robot --via ros`` with a config folder of its own, paired over ROS with a code from ``rockly agent pair``.
Every client is given a TCP port nobody listens on: what works, works over ROS."""
import base64
import collections
import json
import re
import subprocess
import sys
from pathlib import Path

import pytest
from agent_tools import REPO, AgentProcess, AttachedClient, hobbit_on_ros_with_wire, put_back_on_own_master
from json_line_node import JsonLineNode
from program_builder import block, number, rockly_document
from ros_helpers import ros_environment
from standalone_tools import export_standalone
from waiting import eventually

from rockly_desktop.runtime.agent.robot_keys import RobotKeys

STRANGER = Path(__file__).parent / "ros1_agent_stranger.py"
NAMESPACE = "/rockly_agent"


@pytest.fixture(scope="module")
def robot(tmp_path_factory):
    """``(master, {"far": its standalone export, source}, wire recorder)``: HOBBIT simulated on a master of its
    own; "far" drives 50 m (long enough for every case here)."""
    folder = tmp_path_factory.mktemp("agent-strangers")
    far = folder / "far.rockly"
    far.write_text(rockly_document([block("hobbit_move", {"direction": "+"}, {"speed": number(50)}, id="far")]))
    with hobbit_on_ros_with_wire(folder) as (master, wire):
        yield master, export_standalone(far, folder / "far.py", "--language", "en"), wire


class Laptop:
    """``rockly robot --via ros`` on ``master`` with a config folder (its robot keys) of its own."""

    def __init__(self, master, config: Path):
        self.master = master
        self.env = dict(ros_environment(master.uri, master.home), XDG_CONFIG_HOME=str(config))

    def command(self, *args) -> list:
        return [sys.executable, "-m", "rockly_desktop", "robot", "--via", "ros", "--master", self.master.uri,
                "--port", "1", "--language", "en", *map(str, args)]

    def run(self, *args) -> subprocess.CompletedProcess:
        return subprocess.run(self.command(*args), capture_output=True, text=True, timeout=120, cwd=REPO,
                              env=self.env)

    def ok(self, *args) -> str:
        done = self.run(*args)
        assert done.returncode == 0, done.stderr
        return done.stdout

    def attached(self, *options) -> AttachedClient:
        return AttachedClient(self.command("attach", *options), self.env)

    def pair(self, library: Path) -> str:
        """Pair over ROS with a code ``rockly agent pair`` shows on the robot; the code."""
        shown = subprocess.run([sys.executable, "-m", "rockly_desktop", "agent", "--library", str(library), "pair"],
                               capture_output=True, text=True, timeout=60, cwd=REPO, env=self.env)
        code = re.search(r"code: (\S+) ", shown.stdout).group(1)
        assert "over ROS" in self.ok("pair", code)
        return code


class Stranger(JsonLineNode):
    """The stranger node: ``heard(topic)`` what it heard there, ``publish(*messages)`` on ``to_agent``, and
    ``handled()``: return once the agent has handled everything it published (it answered a clear hello sent
    after them: the agent handles one publisher's messages in order)."""

    def __init__(self, env):
        super().__init__([sys.executable, STRANGER, NAMESPACE], env, "the stranger")
        self._marks = 0

    def heard(self, topic: str) -> list:
        return [line["message"] for line in list(self.lines) if line["topic"] == topic]

    def publish(self, *messages):
        self.process.stdin.write(json.dumps(list(messages)) + "\n")
        self.process.stdin.flush()

    def handled(self):
        self._marks += 1
        mark = f"mark-{self._marks}"
        self.publish({"op": "hello", "id": mark, "from": "stranger-mark", "format": 1})
        eventually(lambda: any(message.get("reply") == mark for message in self.heard("from_agent")), 60)

    def answers_to(self, name: str) -> list:
        return [message for message in self.heard("from_agent") if message.get("to") == name]

    def sealed(self, topic: str) -> list:
        return [message for message in self.heard(topic) if "box" in message and "client" in message]


@pytest.fixture
def scene(robot, tmp_path):
    """``(laptop, stranger, agent, program, wire)``: a fresh agent, a laptop paired with it over ROS, and a
    stranger on the master that heard all of it."""
    master, program, wire = robot
    put_back_on_own_master(master)
    laptop = Laptop(master, tmp_path / "laptop")
    agent = AgentProcess(tmp_path / "library", "--master", master.uri, backend="ros1", env=laptop.env)
    stranger = Stranger(laptop.env)
    try:
        laptop.code = laptop.pair(tmp_path / "library")
        yield laptop, stranger, agent, program, wire
    finally:
        stranger.stop()
        agent.stop()


def test_a_strangers_send_and_start_in_clear_are_refused_and_nothing_runs(scene, tmp_path):
    laptop, stranger, _, _, _ = scene
    ran = tmp_path / "ran"
    standalone = f"open({str(ran)!r}, 'w').write('the stranger was here')\n"
    stranger.publish({"op": "send", "id": 1, "from": "evil", "name": "innocent", "standalone": standalone},
                     {"op": "start", "id": 2, "from": "evil", "name": "innocent"},
                     {"op": "list", "id": 3, "from": "evil"}, {"op": "stop", "id": 4, "from": "evil"})
    stranger.handled()
    answers = stranger.answers_to("evil")
    assert [answer["reply"] for answer in answers] == [1, 2, 3, 4]
    assert {(answer["ok"], answer["error"]) for answer in answers} == {(False, "agent_not_paired")}
    assert laptop.ok("list") == "no programs on the robot yet\n" and not ran.exists()


def test_a_listener_reads_nothing_of_the_pairing_the_programs_or_the_run(scene, tmp_path):
    laptop, stranger, _, program, _ = scene
    laptop.ok("send", program, "--name", "secret-square")
    assert "secret-square" in laptop.ok("list")
    laptop.ok("start", "secret-square")
    watcher = laptop.attached()
    try:
        watcher.wait_for(lambda line: line.get("event") in ("block", "variables", "finished"))  # the run's events
        laptop.ok("stop")
        watcher.wait_for(lambda line: line.get("event") == "run" and line.get("state") == "ended")
    finally:
        watcher.end()
    (key,) = RobotKeys(tmp_path / "laptop" / "rockly" / "robot-keys.json").all()
    heard = json.dumps(stranger.heard("to_agent") + stranger.heard("from_agent"))
    secrets = ["secret-square", laptop.code, laptop.code.replace("-", ""), "hobbit_move", '"event"', '"programs"',
               base64.b64encode(key.key).decode(), key.key.hex()]
    assert [secret for secret in secrets if secret in heard] == []
    assert len(stranger.sealed("to_agent")) > 5 and len(stranger.sealed("from_agent")) > 5  # it did hear them


def test_recorded_boxes_of_a_start_and_a_stop_are_ignored(scene):
    laptop, stranger, _, program, wire = scene
    laptop.ok("send", program, "--name", "far")
    laptop.ok("start", "far")
    eventually(lambda: "running: far" in laptop.ok("list"), 60)
    laptop.ok("stop")
    eventually(lambda: "running" not in laptop.ok("list"), 60)
    recorded = stranger.sealed("to_agent")
    assert len({message["line"] for message in recorded}) >= 4  # send, start, list, stop: a line each
    stranger.publish(*recorded)  # the start among them
    stranger.handled()
    assert "running" not in laptop.ok("list")
    laptop.ok("start", "far")
    eventually(lambda: "running: far" in laptop.ok("list"), 60)
    stranger.publish(*recorded)  # the stop among them
    stranger.handled()
    assert "running: far" in laptop.ok("list")
    laptop.ok("stop")


def eventually_the_editors_box(stranger) -> dict:
    """A box the attached editor sent, as the stranger heard it: the line that beats (every 0.2 s) sends most."""
    def beating():
        lines = collections.Counter(message["line"] for message in stranger.sealed("to_agent"))
        return lines and lines.most_common(1)[0][1] >= 10
    eventually(beating, 30)
    line = collections.Counter(message["line"] for message in stranger.sealed("to_agent")).most_common(1)[0][0]
    return next(message for message in stranger.sealed("to_agent") if message["line"] == line)


def test_a_forged_name_or_box_leaves_the_editor_in_control(scene):
    laptop, stranger, _, program, _ = scene
    laptop.ok("send", program, "--name", "far", "--keep-going")
    laptop.ok("start", "far")
    editor = laptop.attached()
    try:
        assert editor.first["controller"] is True
        theirs = eventually_the_editors_box(stranger)
        client, line = theirs["client"], theirs["line"]
        stranger.publish({"op": "control", "id": 1, "what": "pause", "from": line},
                         {"op": "detach", "id": 2, "from": line}, {"op": "bye", "from": line},
                         {"client": client, "line": line, "box": "AAAA" * 20},
                         {"client": client, "line": line, "box": theirs["box"]})
        stranger.handled()
        second = laptop.attached("--watch-only")
        try:
            assert second.first["controlled_elsewhere"] is True and not second.first["run"]["paused"]
        finally:
            second.end()
        assert editor.process.poll() is None and not editor.seen(lambda event: event.get("event") == "paused")
    finally:
        editor.end()
    assert laptop.run("stop").returncode == 0
