"""Strangers on a robot's ROS graph against the agent's topics, the same checks on ROS 1 and ROS 2
(tests/robot/ros1/test_agent_ros_strangers.py, tests/robot/ros2/test_agent_ros2_strangers.py): a plain node of that
middleware (``ros1_agent_stranger.py``, ``ros2_agent_stranger.py``, no Rockly code) publishes requests in clear,
replays what a paired laptop sent, forges a paired laptop's name or box, and listens to everything. The laptop is
``rockly robot --via ros`` with a config folder of its own, paired over ROS with a code from ``rockly agent pair``;
it is given a TCP port nobody listens on: what works, works over ROS."""
import base64
import collections
import json
import re
import subprocess
import sys
from pathlib import Path

from agent_tools import REPO, AttachedClient
from json_line_node import JsonLineNode
from waiting import eventually

from rockly_desktop.runtime.agent.protocol import FORMAT
from rockly_desktop.runtime.agent.robot_keys import RobotKeys

NAMESPACE = "/rockly_agent"


class Laptop:
    """``rockly robot --via ros GRAPH...`` (``graph``: ``--master URI`` or ``--domain N``) with ``env`` and the
    config folder ``config`` (its robot keys)."""

    def __init__(self, graph: list, env: dict, config: Path):
        self.graph = [str(part) for part in graph]
        self.config = config
        self.env = dict(env, XDG_CONFIG_HOME=str(config))
        self.code = None

    def command(self, *args) -> list:
        return [sys.executable, "-m", "rockly_desktop", "robot", "--via", "ros", *self.graph, "--port", "1",
                "--language", "en", *map(str, args)]

    def run(self, *args) -> subprocess.CompletedProcess:
        return subprocess.run(self.command(*args), capture_output=True, text=True, timeout=120, cwd=REPO,
                              env=self.env)

    def ok(self, *args) -> str:
        done = self.run(*args)
        assert done.returncode == 0, done.stderr
        return done.stdout

    def attached(self, *options) -> AttachedClient:
        return AttachedClient(self.command("attach", *options), self.env)

    def pair(self, library: Path):
        """Pair over ROS with a code ``rockly agent pair`` shows on the robot (kept in ``self.code``)."""
        shown = subprocess.run([sys.executable, "-m", "rockly_desktop", "agent", "--library", str(library), "pair"],
                               capture_output=True, text=True, timeout=60, cwd=REPO, env=self.env)
        self.code = re.search(r"code: (\S+) ", shown.stdout).group(1)
        assert "over ROS" in self.ok("pair", self.code)

    def key(self) -> bytes:
        (key,) = RobotKeys(self.config / "rockly" / "robot-keys.json").all()
        return key.key


class Stranger(JsonLineNode):
    """The stranger node (``command``): ``heard(topic)`` what it heard there, ``publish(*messages)`` on
    ``to_agent``, and ``handled()``: return once the agent has handled everything it published (it answered a clear
    hello sent after them: the agent handles one publisher's messages in order)."""

    def __init__(self, command: list, env: dict):
        super().__init__([*command, NAMESPACE], env, "the stranger")
        self._marks = 0

    def heard(self, topic: str) -> list:
        return [line["message"] for line in list(self.lines) if line["topic"] == topic]

    def publish(self, *messages):
        self.process.stdin.write(json.dumps(list(messages)) + "\n")
        self.process.stdin.flush()

    def handled(self):
        self._marks += 1
        mark = f"mark-{self._marks}"
        self.publish({"op": "hello", "id": mark, "from": "stranger-mark", "format": FORMAT})
        eventually(lambda: any(message.get("reply") == mark for message in self.heard("from_agent")), 60)

    def answers_to(self, name: str) -> list:
        return [message for message in self.heard("from_agent") if message.get("to") == name]

    def sealed(self, topic: str) -> list:
        return [message for message in self.heard(topic) if "box" in message and "client" in message]


def requests_in_clear_are_refused_and_nothing_runs(laptop: Laptop, stranger: Stranger, folder: Path):
    ran = folder / "ran"
    standalone = f"open({str(ran)!r}, 'w').write('the stranger was here')\n"
    stranger.publish({"op": "send", "id": 1, "from": "evil", "name": "innocent", "standalone": standalone},
                     {"op": "start", "id": 2, "from": "evil", "name": "innocent"},
                     {"op": "list", "id": 3, "from": "evil"}, {"op": "stop", "id": 4, "from": "evil"})
    stranger.handled()
    answers = stranger.answers_to("evil")
    assert [answer["reply"] for answer in answers] == [1, 2, 3, 4]
    assert {(answer["ok"], answer["error"]) for answer in answers} == {(False, "agent_not_paired")}
    assert laptop.ok("list") == "no programs on the robot yet\n" and not ran.exists()


def a_client_from_before_pairing_is_told_to_update_and_pair(stranger: Stranger):
    """What a Rockly of protocol format 1 (before pairing; its ``RosLine`` at git 5b5bd36^) says over ROS: a
    heartbeat with an id until the agent answers it (its line's handshake), then its hello. Before, the agent left
    that heartbeat unanswered, and the old laptop said no agent was there."""
    old = "/rockly_old_laptop/4242-0a1b2c3d"
    stranger.publish({"op": "heartbeat", "id": old, "from": old})
    stranger.handled()
    assert [answer["reply"] for answer in stranger.answers_to(old)] == [old]
    stranger.publish({"op": "hello", "id": 1, "from": old, "format": 1, "rockly": "0.0.9", "language": "de",
                      "client": "rockly (old@laptop)"})
    stranger.handled()
    told = [answer for answer in stranger.answers_to(old) if answer["reply"] == 1]
    assert [(answer["ok"], answer["error"]) for answer in told] == [(False, "agent_client_before_pairing")]
    assert told[0]["message"].startswith("dieses Rockly (0.0.9) ist älter als der Agent des Roboters (Rockly ")
    assert "aktualisiere Rockly auf diesem Laptop und kopple ihn dann mit dem Roboter" in told[0]["message"]


def a_listener_reads_nothing(laptop: Laptop, stranger: Stranger, program: Path, block_type: str):
    """The stranger, there from the pairing on, heard sealed boxes and nothing readable: no code, no key, no
    program's name or blocks, no list, no event."""
    laptop.ok("send", program, "--name", "secret-square")
    assert "secret-square" in laptop.ok("list")
    laptop.ok("start", "secret-square")
    watcher = laptop.attached()
    try:
        laptop.ok("stop")
        watcher.wait_for(lambda line: line.get("event") == "run" and line.get("state") == "ended")  # events came
    finally:
        watcher.end()
    heard = json.dumps(stranger.heard("to_agent") + stranger.heard("from_agent"))
    key = laptop.key()
    secrets = ["secret-square", laptop.code, laptop.code.replace("-", ""), block_type, '"event"', '"programs"',
               base64.b64encode(key).decode(), key.hex()]
    assert [secret for secret in secrets if secret in heard] == []
    assert len(stranger.sealed("to_agent")) > 5 and len(stranger.sealed("from_agent")) > 5  # it did hear them


def _start_and_stop_far(laptop: Laptop) -> int:
    """Start "far", wait until it runs, stop it, wait until it ended; how many commands (lines) that took."""
    commands = []

    def command(*words):
        commands.append(words)
        return laptop.ok(*words)
    command("start", "far")
    eventually(lambda: "running: far" in command("list"), 60)
    command("stop")
    eventually(lambda: "running" not in command("list"), 60)
    return len(commands)


def a_start_and_a_stop_the_stranger_heard(laptop: Laptop, stranger: Stranger) -> list:
    """The boxes of a start and a stop of "far", each command on a line of its own, once the stranger heard every
    line of one such round (a short-lived command may be done before a stranger's subscription found it)."""
    for _ in range(5):
        heard_before = {message["line"] for message in stranger.sealed("to_agent")}
        commands = _start_and_stop_far(laptop)
        recorded = stranger.sealed("to_agent")
        if len({message["line"] for message in recorded} - heard_before) == commands:
            return recorded
    raise AssertionError("the stranger never heard every line of a start and a stop")


def recorded_boxes_of_a_start_and_a_stop_are_ignored(laptop: Laptop, stranger: Stranger, program: Path):
    laptop.ok("send", program, "--name", "far")
    recorded = a_start_and_a_stop_the_stranger_heard(laptop, stranger)
    stranger.publish(*recorded)  # the start among them
    stranger.handled()
    assert "running" not in laptop.ok("list")
    laptop.ok("start", "far")
    eventually(lambda: "running: far" in laptop.ok("list"), 60)
    stranger.publish(*recorded)  # the stop among them
    stranger.handled()
    assert "running: far" in laptop.ok("list")
    laptop.ok("stop")


def the_editors_box(stranger: Stranger) -> dict:
    """A box the attached editor sent, as the stranger heard it: the line that beats (every 0.2 s) sends most."""
    def most_sent():
        return collections.Counter(message["line"] for message in stranger.sealed("to_agent")).most_common(1)
    eventually(lambda: most_sent() and most_sent()[0][1] >= 10, 30)
    return next(message for message in stranger.sealed("to_agent") if message["line"] == most_sent()[0][0])


def a_forged_name_or_box_leaves_the_editor_in_control(laptop: Laptop, stranger: Stranger, program: Path):
    laptop.ok("send", program, "--name", "far", "--keep-going")
    laptop.ok("start", "far")
    editor = laptop.attached()
    try:
        assert editor.first["controller"] is True
        theirs = the_editors_box(stranger)
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
