"""The topics the robot's agent is reached on over ROS 2: JSON objects, each in a ``std_msgs/msg/String``, in the
agent's namespace (default ``/rockly_agent``), as over ROS 1 (``robot/ros1/agent_topics.py``):

    NAMESPACE/to_agent     clients -> agent
    NAMESPACE/from_agent   agent -> clients

Both reliable, volatile and deep (``QOS``): every request, answer and event arrives, in order, and a client
joining later is not handed what others were told. They are carried by this process's ROS 2 helper
(``Ros2Helper``: Rockly's process never imports rclpy), beside a link's commands but apart from them (its
``send``: neither takes the other's failures). Where ROS 1 names a master, ROS 2 names the graph: a domain id
(or a connection's settings, ``Ros2Settings.from_connection``). What the messages mean is the runtime's
(``runtime.agent.ros_transport``), which reaches this module through the robot-link registry.
"""
import json
import threading
import time

from rockly_desktop.core.errors import RobotCommandError
from rockly_desktop.robot.link import RobotUnavailable
from rockly_desktop.robot.ros2.client import Ros2Helper
from rockly_desktop.robot.ros2.environment import Ros2Settings

TYPE = "std_msgs/msg/String"
QOS = {"reliability": "reliable", "durability": "volatile", "depth": 1000}
ASK_SECONDS = 10.0  # a helper's answer about the graph, on a loaded machine


def topics(namespace: str) -> tuple:
    """``(to_agent, from_agent)`` topic names in ``namespace``."""
    namespace = "/" + namespace.strip("/")
    return namespace + "/to_agent", namespace + "/from_agent"


def _settings(where) -> Ros2Settings:
    if isinstance(where, dict):
        return Ros2Settings.from_connection(where)
    return Ros2Settings(None if where in (None, "") else int(where))


def _helper(where=None) -> Ros2Helper:
    """The helper on the graph ``where`` names: the process's own when it is on that domain (a window's or a robot
    menu's link's, never ended for another), else one started with ``where``'s settings."""
    settings = None if where is None else _settings(where)
    helper = Ros2Helper.running()
    if helper is not None and (settings is None or _domain(settings) == _domain(helper.settings)):
        return helper
    return Ros2Helper.get(settings or Ros2Settings())


def _domain(settings: Ros2Settings) -> str:
    return settings.environment().get("ROS_DOMAIN_ID") or "0"


def _ask(helper: Ros2Helper, op: str, *args):
    """The helper's answer to ``op``; RobotCommandError when it fails or does not come within ASK_SECONDS."""
    answered, outcome = threading.Event(), []

    def then(ok, value):
        outcome.append((ok, value))
        answered.set()
    helper.send(op, *args, then=then)
    if not answered.wait(ASK_SECONDS) or helper.lost:
        raise helper.lost_error() if helper.lost else RobotCommandError(f"the ROS 2 helper did not answer '{op}'")
    ok, value = outcome[0]
    if not ok:
        raise RobotCommandError(f"the ROS 2 helper could not do '{op}': {value}")
    return value


def agent_in_graph(where, namespace: str) -> bool:
    """True when the ROS 2 graph ``where`` names lists an agent in ``namespace`` (a subscriber of its ``to_agent``
    topic on another node); a fresh helper looks until it had DISCOVERY_SECONDS to discover it."""
    try:
        helper = _helper(where)
        while True:
            if _ask(helper, "ends", topics(namespace)[0])[1]:
                return True
            if not helper.discovery_left():
                return False
            time.sleep(0.1)
    except (RobotCommandError, RobotUnavailable, ValueError):
        return False


def master_at_hand():
    """The domain id of this process's ROS 2 helper when it has one (e.g. the window connected to a ROS 2 robot)."""
    helper = Ros2Helper.running()
    return _domain(helper.settings) if helper is not None else None


def node_name(where=None) -> tuple:
    """``(this process's helper's node name, the graph as a person reads it: a LocalText)``, the helper started
    on ``where`` when it is the first; a RobotUnavailable when it cannot be."""
    try:
        helper = _helper(where)
    except ValueError as error:  # a domain id out of range
        raise RobotUnavailable(str(error)) from None
    return f"rockly_{helper.process.pid}", helper.settings.describe()


class Topics:
    """One side's ends of the agent's topics in ``namespace``: ``incoming`` (``to_agent`` for the agent,
    ``from_agent`` for a client) calls ``on_message(dict)`` for every JSON object that comes (on the helper's
    reader thread, in the order sent); ``publish`` sends on the other. Make it after ``node_name``."""

    def __init__(self, namespace: str, agent_side: bool, on_message):
        to_agent, from_agent = topics(namespace)
        self._incoming, self._outgoing = (to_agent, from_agent) if agent_side else (from_agent, to_agent)
        self._on_message = on_message
        self._helper = helper = _helper()
        self._sid = helper.new_id()
        for topic in (self._incoming, self._outgoing):
            _ask(helper, "keep_qos", topic, QOS)
        helper.on("msg", self._sid, self._take)
        _ask(helper, "subscribe", self._sid, self._incoming, TYPE)
        # the publisher now, not at the first message: the other side sees this one in the graph from the start
        helper.send("publish_first", self._outgoing, TYPE, None)

    def publish(self, message: dict) -> bool:
        """Send ``message``; False when it cannot be (the helper is gone)."""
        try:
            self._helper.send("publish", self._outgoing, TYPE, {"data": json.dumps(message, ensure_ascii=False)})
            return True
        except RobotCommandError:
            return False

    def _ends(self, topic: str) -> tuple:
        try:
            return _ask(self._helper, "ends", topic)
        except RobotCommandError:
            return 0, 0

    def connected(self) -> bool:
        """True while both topics are connected to the other side (to some agent, or some client)."""
        return bool(self._ends(self._outgoing)[1] and self._ends(self._incoming)[0])

    def heard_from(self) -> bool:
        """True while the incoming topic has a publisher on another node."""
        return bool(self._ends(self._incoming)[0])

    def close(self):
        self._helper.off("msg", self._sid)
        try:
            self._helper.send("unsubscribe", self._sid)
        except RobotCommandError:
            pass  # the helper is gone, and its subscription with it

    def _take(self, message):
        try:
            received = json.loads(message.get("data", ""))
        except (ValueError, AttributeError):
            return
        if isinstance(received, dict):
            self._on_message(received)
