"""The agent's figures on ROS 2, for benchmarks/agent.py: ``rockly agent --backend ros2`` and ``rockly sim turtlebot
--ros2`` on a domain of this run's own (localhost), a plain rclpy node echoing /cmd_vel; STOP -> zero Twist on the
wire and attach, over TCP and over the agent's ROS 2 topics (``AgentClient(via="ros", domain=N)``) with the same
agent and program, so each ROS 2 figure has its ratio to TCP's of the same run."""
import os
import subprocess
import sys
import tempfile
from pathlib import Path

from _paths import REPO
from _twist_echo import TwistEcho
from agent_tools import pair_with_agent

from rockly_desktop.runtime.agent.protocol import DEFAULT_NAMESPACE
from rockly_desktop.runtime.agent.robot_keys import ros_address

ROS2_PYTHON = REPO / ".venv-ros2" / "bin" / "python"
DRIVE = "robot.drive_for(0.1, 120)\n"  # drives until stopped (each trial stops it)

ECHO_NODE = r'''
import time, rclpy
from geometry_msgs.msg import Twist
rclpy.init()
node = rclpy.create_node("rockly_bench_agent_echo")
def on_twist(m):
    kind = "zero" if m.linear.x == 0 and m.angular.z == 0 else "move"
    print(kind, repr(time.time()), flush=True)
node.create_subscription(Twist, "/cmd_vel", on_twist, 1000)
print("ready", flush=True)
rclpy.spin(node)
'''


def _started(command, env, ready_text):
    process = subprocess.Popen([sys.executable, "-m", "rockly_desktop", *command], cwd=REPO, env=env,
                               stdout=subprocess.PIPE, text=True)
    for line in process.stdout:
        if ready_text in line:
            return process, line
    raise RuntimeError(f"'{' '.join(command)}' did not start")


def _end(process):
    process.terminate()
    try:
        process.wait(30)
    except subprocess.TimeoutExpired:
        process.kill()
        process.wait(10)


def ros2_figures(stop_times, attach_times):
    """``(TCP stops, TCP attaches, ROS 2 stops, ROS 2 attaches)`` in seconds, with benchmarks/agent.py's
    ``stop_times`` and ``attach_times``."""
    from rockly_desktop.profiles.registry import ProfileRegistry
    from rockly_desktop.robot.ros2.environment import Ros2Settings
    from rockly_desktop.robot.wrappers.limits import Limits
    from rockly_desktop.runtime.agent.client import AgentClient
    from rockly_desktop.runtime.standalone_file import standalone_text

    domain = 150 + os.getpid() % 80
    settings = Ros2Settings(domain, "localhost")
    env = settings.environment()
    os.environ.update(env)
    on_the_domain = ["--domain", str(domain), "--discovery", "localhost"]
    library = Path(tempfile.mkdtemp(prefix="rockly-bench-agent-ros2-"))
    turtlebot = ProfileRegistry.discover().get("turtlebot")
    program = standalone_text("bench-drive.rockly", turtlebot, {"code": DRIVE, "variables": {}}, {}, Limits(), "en")
    simulator, _ = _started(["sim", "turtlebot", "--ros2", "--no-window", *on_the_domain], env, "is up on ROS")
    echo = TwistEcho(ROS2_PYTHON, ECHO_NODE, env)
    agent, ready = _started(["agent", "--backend", "ros2", *on_the_domain, "--host", "127.0.0.1", "--port", "0",
                             "--library", str(library)], env, "listening on")
    port = int(ready.split("127.0.0.1:")[1].split(",")[0])
    try:
        pair_with_agent(port, library, [ros_address("ros2", domain, DEFAULT_NAMESPACE)], name="benchmark")
        events = []
        client = AgentClient("127.0.0.1", port, on_event=events.append)
        try:
            client.send("drive", program)
            client.attach()
            tcp_stops = stop_times(client, events, echo)
            tcp_attaches, _ = attach_times(client, lambda: AgentClient("127.0.0.1", port), lambda: None)
        finally:
            client.close()
        events = []
        client = AgentClient(via="ros", domain=domain, on_event=events.append)
        try:
            client.attach()
            ros_stops = stop_times(client, events, echo)
            ros_attaches, _ = attach_times(client, lambda: AgentClient(via="ros", domain=domain), lambda: None)
        finally:
            client.close()
    finally:
        _end(agent)
        echo.process.kill()
        echo.process.wait(10)
        _end(simulator)
    return tcp_stops, tcp_attaches, ros_stops, ros_attaches
