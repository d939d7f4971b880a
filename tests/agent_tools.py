"""The robot's agent (``rockly agent``) as a process of its own, and ``rockly robot`` as a user runs it."""
import json
import signal
import struct
import subprocess
import sys
import threading
import time
from contextlib import contextmanager
from pathlib import Path

from ros_helpers import hobbit_on_own_master, ros_environment
from waiting import eventually
from wire_recorder import WireRecorder

from rockly_desktop.runtime.agent.pairings import Pairings, agent_folder
from rockly_desktop.runtime.agent.protocol import AGENT_SILENT_SECONDS, DEFAULT_NAMESPACE
from rockly_desktop.runtime.agent.robot_keys import RobotKeys, ros_address

REPO = Path(__file__).resolve().parents[1]


class AgentProcess:
    """``rockly agent --backend BACKEND`` on a free localhost port, its programs in ``library``; on ROS 1 (its
    ``--master`` among ``options``), returns once the master lists the agent's own node on its topics.

    With ``paired`` (the default) this test's laptop is paired with it first, as a teacher (the first laptop on a
    fresh agent): its key is in the test's robot keys (``RobotKeys()``, the test's config folder) for
    ``tcp:127.0.0.1:PORT``, and for the agent's ROS address where it has one; ``self.key`` is that key."""

    def __init__(self, library: Path, *options, backend="sim", env=None, paired=True):
        self.library = Path(library)
        self.process = subprocess.Popen(
            [sys.executable, "-m", "rockly_desktop", "agent", "--backend", backend, "--host", "127.0.0.1",
             "--port", "0", "--library", str(library), "--language", "en", *map(str, options)],
            cwd=REPO, env=env, text=True, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        ready = self.process.stdout.readline()
        assert "listening on" in ready, ready + self.process.stderr.read()
        self.port = int(ready.split("listening on 127.0.0.1:")[1].split(",")[0])
        if backend == "ros1":  # it says it listens on TCP before its node is up: a ROS client then finds no agent
            self._wait_on_ros1(str(options[options.index("--master") + 1]))
        self.key = self.pair(_ros_addresses(options)) if paired else None

    def new_code(self, role: str = None) -> str:
        """A one-time pairing code of this agent, made as ``rockly agent pair`` makes it (in the agent's folder)."""
        return Pairings(agent_folder(self.library)).new_code(role).shown

    def pair(self, also_for=(), role: str = None, keys: RobotKeys = None):
        """Pair a laptop (its keys: ``keys``, else the test's) as ``role``; returns its RobotKey."""
        return pair_with_agent(self.port, self.library, also_for, role, keys)

    def _wait_on_ros1(self, master_uri: str):
        """Return once the master lists this agent's node (``rockly_PID_...``) as a subscriber of its requests."""
        from rockly_desktop.robot.ros1.agent_topics import topics
        from rockly_desktop.robot.ros1.connection import ask_master

        def listed():
            subscribers = dict(ask_master(master_uri, "getSystemState")[1]).get(topics(DEFAULT_NAMESPACE)[0], [])
            return self.process.poll() is not None or any(
                node.startswith(f"/rockly_{self.process.pid}_") for node in subscribers)
        eventually(listed, 60)
        assert self.process.poll() is None, self.process.stderr.read()

    def robot(self, *args, language="en", timeout=120, env=None) -> subprocess.CompletedProcess:
        """``rockly robot --port PORT ARGS`` run to its end."""
        return subprocess.run(self.robot_command(*args, language=language), capture_output=True, text=True,
                              timeout=timeout, cwd=REPO, env=env)

    def robot_command(self, *args, language="en") -> list:
        return [sys.executable, "-m", "rockly_desktop", "robot", "--host", "127.0.0.1", "--port", str(self.port),
                "--language", language, *map(str, args)]

    def stop(self):
        """End the agent as systemd does (SIGTERM); kill it only if it does not end."""
        if self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(60)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait(10)
        self.process.stdout.close()
        self.process.stderr.close()


def pair_with_agent(port: int, library: Path, also_for=(), role: str = None, keys: RobotKeys = None,
                    name: str = "test laptop"):
    """Pair a laptop (its keys: ``keys``, else this process's ``RobotKeys()``) with the agent on 127.0.0.1:``port``
    whose programs are in ``library``, as ``role``, also for the addresses ``also_for``; returns its RobotKey."""
    from rockly_desktop.runtime.agent.client import AgentClient

    client = AgentClient("127.0.0.1", port, keys=keys)
    try:
        return client.pair(Pairings(agent_folder(library)).new_code(role).shown, name, also_for)
    finally:
        client.close()


def _ros_addresses(options) -> list:
    """The ROS addresses of an agent started with ``options`` (``--master URI``, ``--domain N``)."""
    options = [str(option) for option in options]
    if "--domain" in options:
        return [ros_address("ros2", int(options[options.index("--domain") + 1]), DEFAULT_NAMESPACE)]
    if "--master" in options:
        return [ros_address("ros1", options[options.index("--master") + 1], DEFAULT_NAMESPACE)]
    return []


@contextmanager
def hobbit_on_ros_with_wire(folder: Path):
    """``(master, wire recorder of /cmd_vel)``: HOBBIT simulated on a rosmaster of its own (its home in ``folder``),
    all stopped after."""
    master, simulator = hobbit_on_own_master(folder)
    wire = WireRecorder(master, ["/cmd_vel"])
    try:
        yield master, wire
    finally:
        wire.stop()
        simulator.stop()
        master.stop()


PUT_BACK = """
import sys
sys.path.insert(0, "tests")
from ros_helpers import put_back_simulator
put_back_simulator(sys.argv[1])
"""


def put_back_on_own_master(master):
    """Put the simulator on ``master`` (a RosMaster of a test's own) back where it started, from a process of its own:
    this process's one ROS node may be on another master."""
    done = subprocess.run([sys.executable, "-c", PUT_BACK, master.uri], cwd=REPO, capture_output=True, text=True,
                          timeout=120, env=ros_environment(master.uri, master.home))
    assert done.returncode == 0, done.stderr


@contextmanager
def ros1_agent(library: Path, master):
    """``rockly agent --backend ros1`` on ``master`` (tests' RosMaster), its programs in ``library``; stopped after."""
    agent = AgentProcess(library, "--master", master.uri, backend="ros1", env=ros_environment(master.uri, master.home))
    try:
        yield agent
    finally:
        agent.stop()


def zero_velocities(wire) -> int:
    """How many zero Twists the wire recorder has seen on /cmd_vel."""
    return sum(1 for _type, raw in wire.on("/cmd_vel") if struct.unpack("<6d", raw) == (0.0,) * 6)


@contextmanager
def installed_agent(bin_folder: Path, library: Path, *options, env: dict):
    """``rockly-agent --backend ... OPTIONS`` of an installed environment (its ``bin_folder``) on a free localhost
    port, run from / with ``env``; yields ``robot(*args)``: the stdout of that environment's ``rockly-robot``, which
    must succeed. Afterwards the agent is ended with SIGTERM and must exit cleanly."""
    agent = subprocess.Popen([str(bin_folder / "rockly-agent"), "--host", "127.0.0.1", "--port", "0", "--library",
                              str(library), *map(str, options)], cwd="/", env=env, text=True,
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        ready = agent.stdout.readline()
        assert "listening on 127.0.0.1:" in ready, agent.stderr.read()
        port = ready.split("127.0.0.1:")[1].split(",")[0]

        def robot(*args):
            result = subprocess.run([str(bin_folder / "rockly-robot"), "--host", "127.0.0.1", "--port", port,
                                     *map(str, args)], cwd="/", env=env, capture_output=True, text=True, timeout=120)
            assert result.returncode == 0, result.stderr
            return result.stdout
        made = subprocess.run([str(bin_folder / "rockly-agent"), "--library", str(library), "pair"], cwd="/", env=env,
                              capture_output=True, text=True, timeout=120)
        assert made.returncode == 0, made.stderr
        assert "paired" in robot("pair", made.stdout.split("code: ")[1].split(" ")[0]).lower()
        yield robot
    finally:
        agent.terminate()
        agent.communicate(timeout=60)
    assert agent.returncode == 0


class AttachedClient:
    """``rockly robot ... attach [--watch-only]`` (``command``) as a process; ``lines``: the JSON lines it printed."""

    def __init__(self, command: list, env: dict):
        self.lines = []
        self.process = subprocess.Popen(command, cwd=REPO, text=True, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                        env=env)
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()
        eventually(lambda: self.lines or self.process.poll() is not None, 60)
        assert self.lines, self.process.stderr.read()

    def _read(self):
        for line in self.process.stdout:
            self.lines.append(json.loads(line))

    @property
    def first(self) -> dict:
        return self.lines[0]

    def seen(self, wanted) -> list:
        return [line for line in list(self.lines) if wanted(line)]

    def wait_for(self, wanted, timeout=60) -> dict:
        try:
            eventually(lambda: self.seen(wanted) or not self._reader.is_alive(), timeout)  # or all it said was read
            assert self.seen(wanted)
        except AssertionError:
            raise AssertionError(f"not seen (waited up to {timeout} s); exit status {self.process.poll()}; "
                                 f"lines: {self.lines}") from None
        return self.seen(wanted)[0]

    def end(self):
        if self.process.poll() is None:
            self.process.kill()
        self.process.wait(30)
        self._reader.join(10)
        self.process.stdout.close()
        self.process.stderr.close()


def run_ended(line) -> bool:
    """An attached client's line saying the run ended."""
    return line.get("event") == "run" and line.get("state") == "ended"


def sent_started_and_watched(run_robot, attach, program, name, *send_options) -> AttachedClient:
    """Send ``program`` as ``name`` with ``run_robot(*args)``, start it and ``attach("--watch-only")`` a watcher
    (not the editor), checking what each step says."""
    sent = run_robot("send", program, "--name", name, *send_options)
    assert sent.returncode == 0 and sent.stdout == f"'{name}' is on the robot now\n", sent.stderr
    begun = run_robot("start", name)
    assert begun.returncode == 0 and begun.stdout == f"'{name}' started on the robot\n", begun.stderr
    watcher = attach("--watch-only")
    assert watcher.first["event"] == "attached" and watcher.first["controller"] is False
    assert watcher.first["run"]["program"] == name
    return watcher


def seconds_until_ended_while_frozen(agent: subprocess.Popen, client: subprocess.Popen, meanwhile=lambda: None):
    """Freeze ``agent`` (SIGSTOP) until ``client`` ends (it should hear the agent lost), run ``meanwhile()``, and let
    the agent go on (SIGCONT, whatever happened); the seconds the client took."""
    agent.send_signal(signal.SIGSTOP)
    frozen = time.monotonic()
    try:
        client.wait(AGENT_SILENT_SECONDS + 30)
        took = time.monotonic() - frozen
        meanwhile()
    finally:
        agent.send_signal(signal.SIGCONT)
    return took
