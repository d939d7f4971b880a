"""Real ROS 1 for tests: a rosmaster on a free port, the ROS-level simulator as a process."""
import os
import socket
import subprocess
import sys
import time
import xmlrpc.client
from pathlib import Path

from waiting import eventually

from rockly_desktop.robot.ros1.connection import RosConnection, ask_master, master_answers
from rockly_desktop.robot.sim.served_simulator import PUT_BACK_SERVICE

REPO = Path(__file__).resolve().parents[1]


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def ros_environment(master_uri: str, home: Path) -> dict:
    """Environment for a ROS process of this test run: its own master, home and logs."""
    home.mkdir(parents=True, exist_ok=True)
    return dict(os.environ, ROS_MASTER_URI=master_uri, ROS_IP="127.0.0.1", ROS_HOME=str(home),
                ROS_LOG_DIR=str(home / "log"), PYTHONUNBUFFERED="1")


def publishers_reach(master_uri: str, topic: str, subscriber: str) -> bool:
    """True when every publisher of ``topic`` the master lists (but ``subscriber``) has a connection up to the node
    ``subscriber``, as the publisher's own bus info says (``getBusInfo``); a listed node that refuses (killed)
    publishes nothing. Only the publisher's side tells: rospy counts a subscriber's connection before it has
    connected, and what is published before the publisher has the connection is lost to that subscriber."""
    for node in dict(ask_master(master_uri, "getSystemState")[0]).get(topic, []):
        if node == subscriber:
            continue
        try:
            bus = ask_master(ask_master(master_uri, "lookupNode", node), "getBusInfo")
        except ConnectionRefusedError:
            continue
        except (OSError, xmlrpc.client.Error):  # slow to answer: ask again
            return False
        if not any(entry[1] == subscriber and entry[2] == "o" and entry[4] == topic for entry in bus):
            return False
    return True


def connected_subscription(ros_robot, topic: str, msg_type: str):
    """This process's shared subscription to ``topic``, once every publisher the master lists has connected it.

    rospy connects a subscriber to a publisher in a thread of its own: a message sent before
    that connection is up is lost to this subscriber."""
    import rospy

    entry = ros_robot.graph.topic(topic, msg_type)
    eventually(lambda: publishers_reach(ros_robot.connection.master_uri, topic, rospy.get_name()))
    return entry


def put_back_simulator(master_uri: str, timeout: float = 30.0):
    """Put the ROS-level simulator on ``master_uri`` back as it started: a call to its /rockly_sim/reset
    (std_srvs/Trigger) from this process's node."""
    RosConnection.get(master_uri)  # this process as a node on that master
    import rospy
    from std_srvs.srv import Trigger

    rospy.wait_for_service(PUT_BACK_SERVICE, timeout)
    answer = rospy.ServiceProxy(PUT_BACK_SERVICE, Trigger)()
    assert answer.success, answer.message


def feed_hears(robot, topics: dict):
    """Return once ``robot``'s state feed records every topic of ``topics`` ({topic: type}) from every publisher.

    The feed subscribes to what it finds on the graph once a second: a message sent before
    would not reach the panels."""
    for topic, msg_type in topics.items():
        feed = robot.graph.topic(topic, msg_type).raw_callbacks  # of the subscription the feed shares
        eventually(lambda callbacks=feed: callbacks)             # the feed records it
        connected_subscription(robot, topic, msg_type)


def messages_received(master_uri: str, topic: str) -> int:
    """How many messages on ``topic`` the nodes subscribed to it have received (each node's bus statistics)."""
    _publishers, subscribers, _services = ask_master(master_uri, "getSystemState")
    received = 0
    for node in dict(subscribers).get(topic, []):
        _code, _message, (_published, subscribed, _served) = xmlrpc.client.ServerProxy(
            ask_master(master_uri, "lookupNode", node)).getBusStats("/rockly_test")
        received += sum(messages for name, connections in subscribed if name == topic
                        for _id, _bytes, messages, *_rest in connections)
    return received


def publishes(master_uri: str, topic: str) -> bool:
    """Whether the master lists a publisher of ``topic``."""
    return bool(dict(ask_master(master_uri, "getSystemState")[0]).get(topic))


class RosMaster:
    """A rosmaster process on a free port; ``stop()`` kills it, ``start()`` brings it back on the same port."""

    def __init__(self, home: Path):
        self.port = free_port()
        self.uri = f"http://127.0.0.1:{self.port}"
        self.home = home
        self.process = None

    def start(self, timeout: float = 15.0):
        self.process = subprocess.Popen(["rosmaster", "--core", "-p", str(self.port)],
                                        env=ros_environment(self.uri, self.home),
                                        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        eventually(lambda: self.process.poll() is not None or master_answers(self.uri) is not None, timeout)
        if self.process.poll() is not None:
            raise RuntimeError("rosmaster did not start")
        return self

    def stop(self):
        if self.process is not None and self.process.poll() is None:
            self.process.kill()
            self.process.wait(10)


def hobbit_on_own_master(folder: Path) -> tuple:
    """``(master, simulator)``: a rosmaster of its own (its home in ``folder``) and ``rockly sim hobbit --ros``
    on it, up; the caller stops both."""
    master = RosMaster(folder / "ros").start()
    return master, RocklyProcess(["sim", "hobbit", "--ros", "--no-window", "--master", master.uri], master,
                                 ready_line="on ROS")


class RocklyProcess:
    """A ``rockly`` command running as its own process (a ROS node)."""

    def __init__(self, args, master: RosMaster, ready_line: str = None, timeout: float = 60.0):
        self.process = subprocess.Popen([sys.executable, "-m", "rockly_desktop", *map(str, args)], cwd=REPO,
                                        env=ros_environment(master.uri, master.home), text=True,
                                        stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        if ready_line:
            deadline = time.monotonic() + timeout
            for line in self.process.stdout:
                if ready_line in line:
                    break
                if time.monotonic() > deadline:
                    break
            else:
                raise RuntimeError(f"'{ready_line}' never came: {self.process.stderr.read()}")

    def stop(self):
        if self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(10)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait(10)
