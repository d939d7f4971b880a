"""The agent on the robot (``rockly agent --backend ros1``), against what runs on the laptop today, in one run:

  - stop on the wire: a STOP request (``AgentClient.stop()``) -> the zero Twist of the robot's safe stop
    received by a separate plain rospy node, while the program drives under the agent (aim <= 50 ms);
    baseline: the same stop of the same program run in this process (the laptop's run, as benchmarks/ros1.py);
  - attach: a new (paired) client connecting, saying hello and attaching to a running program until the run's
    state is in hand (aim <= 1 s); baseline: one bare TLS request/answer with the same agent (connect and the
    TLS handshake, its greeting, a line, a line);
  - both again over ROS 1 (the agent's topics, ``AgentClient(via="ros")``), each with its ratio to the TCP figure
    of the same run;
  - both over TCP and over ROS 2 with ``rockly agent --backend ros2`` driving ``rockly sim turtlebot --ros2``
    (``_agent_ros2.py``), the ROS 2 figures each with its ratio to that agent's TCP figure of the same run.

A real rosmaster on a free port, a ROS 2 domain of the run's own; the agents, the simulator and the echo nodes are
processes of their own. Each agent pairs this process first (its key in a config folder of the run's own).

    python benchmarks/agent.py
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

from _agent_ros2 import ros2_figures
from _paths import REPO  # its set-up: Rockly and the tests' helpers importable
from _stop_on_the_wire import DRIVE_AND_WAIT, stop_latencies
from _twist_echo import TwistEcho
from agent_tools import pair_with_agent
from ros_helpers import RosMaster, ros_environment

from rockly_desktop.runtime.agent.protocol import DEFAULT_NAMESPACE
from rockly_desktop.runtime.agent.robot_keys import ros_address

STOP_TRIALS = 10
ATTACH_TRIALS = 20

ECHO_NODE = r'''
import time, rospy
from geometry_msgs.msg import Twist
rospy.init_node("rockly_bench_agent_echo", disable_signals=True)
def on_twist(m):
    kind = "zero" if m.linear.x == 0 and m.angular.z == 0 else "move"
    print(kind, repr(time.time()), flush=True)
rospy.Subscriber("/cmd_vel", Twist, on_twist, queue_size=1000)
print("ready", flush=True)
rospy.spin()
'''


def median_ms(values):
    return statistics.median(values) * 1000


def report(name, measured, baseline, baseline_name, aim):
    ratio = statistics.median(measured) / statistics.median(baseline)
    print(f"{name}: median {median_ms(measured):.1f} ms (max {max(measured) * 1000:.1f} ms, aim <= {aim}), "
          f"{baseline_name} median {median_ms(baseline):.1f} ms, ratio {ratio:.2f}")


def standalone_program(profile) -> str:
    from rockly_desktop.robot.wrappers.limits import Limits
    from rockly_desktop.runtime.standalone_file import standalone_text

    return standalone_text("bench-drive.rockly", profile, {"code": DRIVE_AND_WAIT, "variables": {}}, {}, Limits(), "en")


def agent_process(master, home, library):
    process = subprocess.Popen([sys.executable, "-m", "rockly_desktop", "agent", "--backend", "ros1", "--master",
                                master.uri, "--host", "127.0.0.1", "--port", "0", "--library", str(library)],
                               cwd=REPO, env=ros_environment(master.uri, home), stdout=subprocess.PIPE, text=True)
    ready = process.stdout.readline()
    port = int(ready.split("127.0.0.1:")[1].split(",")[0])
    pair_with_agent(port, library, [ros_address("ros1", master.uri, DEFAULT_NAMESPACE)], name="benchmark")
    return process, port


def main():
    from rockly_desktop.profiles.registry import ProfileRegistry

    home = Path(tempfile.mkdtemp(prefix="rockly-bench-agent-"))
    os.environ["XDG_CONFIG_HOME"] = str(home / "config")  # the pairings' keys: not the user's
    master = RosMaster(home).start()
    os.environ.update(ros_environment(master.uri, home))
    echo = TwistEcho("/usr/bin/python3", ECHO_NODE, ros_environment(master.uri, home))
    agent, port = agent_process(master, home, home / "library")
    hobbit = ProfileRegistry.discover().get("hobbit")
    try:
        agent_stops, attaches, bare, ros_stops, ros_attaches = agent_figures(port, master, hobbit, echo)
        local = local_stops(hobbit, master, echo)
    finally:
        agent.terminate()
        agent.wait(30)
        echo.process.kill()
        master.stop()
    report("STOP -> zero Twist on the wire, program under the agent", agent_stops, local,
           "the same run on the laptop", "50 ms")
    report("attach to a running program (connect, hello, attach)", attaches, bare,
           "a bare TLS request to the agent", "1000 ms")
    report("over ROS 1: STOP -> zero Twist on the wire, program under the agent", ros_stops, agent_stops,
           "the same over TCP", "50 ms")
    report("over ROS 1: attach to a running program (connect, hello, attach)", ros_attaches, attaches,
           "the same over TCP", "1000 ms")
    tcp2_stops, tcp2_attaches, ros2_stops, ros2_attaches = ros2_figures(stop_times, attach_times)
    report("over ROS 2: STOP -> zero Twist on the wire, program under the agent", ros2_stops, tcp2_stops,
           "the same over TCP (ROS 2 robot)", "50 ms")
    report("over ROS 2: attach to a running program (connect, hello, attach)", ros2_attaches, tcp2_attaches,
           "the same over TCP (ROS 2 robot)", "1000 ms")
    print("(one loaded machine shared with other work: figures vary between runs)")


def agent_figures(port, master, hobbit, echo):
    """STOP and attach times over TCP, then over ROS 1, with the same agent and program."""
    from rockly_desktop.runtime.agent.client import AgentClient

    events = []
    client = AgentClient("127.0.0.1", port, on_event=events.append)
    try:
        client.send("drive", standalone_program(hobbit))
        client.attach()
        stops = stop_times(client, events, echo)
        attaches, bare = attach_times(client, lambda: AgentClient("127.0.0.1", port), lambda: bare_request(port))
    finally:
        client.close()
    events = []
    client = AgentClient(via="ros", master=master.uri, on_event=events.append)
    try:
        client.attach()
        ros_stops = stop_times(client, events, echo)
        ros_attaches, _ = attach_times(client, lambda: AgentClient(via="ros", master=master.uri), lambda: None)
    finally:
        client.close()
    return stops, attaches, bare, ros_stops, ros_attaches


def stop_times(client, events, echo):
    """STOP -> zero Twist times of the program started and stopped through ``client`` (attached: ``events``)."""
    stops = []
    for _ in range(STOP_TRIALS):
        events.clear()
        begun = time.time()
        client.start("drive")
        echo.wait_for("move", begun, 60)
        time.sleep(0.1)  # the run is in its wait
        requested = time.time()
        client.stop()
        stops.append(echo.wait_for("zero", requested) - requested)
        while not any(event.get("state") == "ended" for event in list(events)):
            time.sleep(0.01)
    return stops


def bare_request(port):
    from agent_wire import tls_connection

    connection, _ = tls_connection(port)
    with connection:
        connection.sendall(json.dumps({"op": "list", "id": 1}).encode() + b"\n")
        connection.makefile("rb").readline()


def attach_times(client, new_client, baseline):
    """Attach times of clients ``new_client()`` with the program running, and ``baseline()``'s times."""
    client.start("drive")
    attaches, bare = [], []
    try:
        for _ in range(ATTACH_TRIALS):
            started = time.perf_counter()
            watcher = new_client()
            state = watcher.attach(control=False)
            attaches.append(time.perf_counter() - started)
            assert state["run"] is not None
            watcher.close()
            started = time.perf_counter()
            baseline()
            bare.append(time.perf_counter() - started)
    finally:
        client.stop()
        while client.programs()["run"] is not None:  # ended: the next figures start their own runs
            time.sleep(0.01)
    return attaches, bare


def local_stops(hobbit, master, echo):
    """The baseline: the same program run in this process on a RosRobot, stopped the same way."""
    from rockly_desktop.robot.ros1.link import RosRobot

    robot = RosRobot(hobbit, master.uri)
    arrivals = []
    watching = threading.Event()

    def follow():
        index = len(echo.seen)  # the agent's trials' zeros are not this baseline's
        while not watching.is_set():
            for kind, when in echo.seen[index:]:
                if kind == "zero":
                    arrivals.append(when)
            index = len(echo.seen)
            time.sleep(0.0005)
    follower = threading.Thread(target=follow, daemon=True)
    follower.start()
    try:
        return stop_latencies(hobbit, robot, arrivals, STOP_TRIALS)
    finally:
        watching.set()
        robot.shutdown()


if __name__ == "__main__":
    main()
