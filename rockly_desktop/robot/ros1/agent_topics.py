"""The topics the robot's agent is reached on over ROS 1: JSON objects, each in a ``std_msgs/String``, in the
agent's namespace (default ``/rockly_agent``):

    NAMESPACE/to_agent     clients -> agent
    NAMESPACE/from_agent   agent -> clients

Standard types only: a robot running Rockly's runtime from pip has no catkin build for a service type of our own
(docs/decisions/031). This module only carries the messages, on this process's one ROS 1 node
(``RosConnection``); what they mean is the runtime's (``runtime.agent.ros_transport``), which reaches this module
through the robot-link registry (``links.agent_topics``).
"""
import json
import xmlrpc.client

from rockly_desktop.robot.ros1.connection import RosConnection, ask_master

QUEUE = 1000  # messages a publisher holds for a slow subscriber


def topics(namespace: str) -> tuple:
    """``(to_agent, from_agent)`` topic names in ``namespace``."""
    namespace = "/" + namespace.strip("/")
    return namespace + "/to_agent", namespace + "/from_agent"


def agent_in_graph(master: str, namespace: str) -> bool:
    """True when the ROS 1 master at ``master`` lists an agent in ``namespace`` (a subscriber of its ``to_agent``
    topic); False when it does not, or does not answer."""
    try:
        subscribers = dict(ask_master(master, "getSystemState")[1])
    except (OSError, xmlrpc.client.Error):
        return False
    return bool(subscribers.get(topics(namespace)[0]))


def master_at_hand():
    """The master of this process's ROS 1 node when it has one (e.g. the window connected to a ROS 1 robot)."""
    connection = RosConnection._instance
    return connection.master_uri if connection is not None else None


def node_name(master: str = None) -> tuple:
    """``(this process's node name, its master's URI)``, the node started on ``master`` when it is the first;
    RosUnavailable (a RobotUnavailable) when it cannot be."""
    import rospy

    connection = RosConnection.get(master)
    return rospy.get_name(), connection.master_uri


class Topics:
    """One side's ends of the agent's topics in ``namespace``: ``incoming`` (``to_agent`` for the agent,
    ``from_agent`` for a client) calls ``on_message(dict)`` for every JSON object that comes (on rospy's thread,
    in the order sent); ``publish`` sends on the other. Make it after ``node_name`` (the process's node)."""

    def __init__(self, namespace: str, agent_side: bool, on_message):
        import rospy
        from std_msgs.msg import String

        to_agent, from_agent = topics(namespace)
        incoming, outgoing = (to_agent, from_agent) if agent_side else (from_agent, to_agent)
        self._String = String
        self._on_message = on_message
        self._out = rospy.Publisher(outgoing, String, queue_size=QUEUE, tcp_nodelay=True)
        self._in = rospy.Subscriber(incoming, String, self._take, tcp_nodelay=True)

    def publish(self, message: dict) -> bool:
        """Send ``message``; False when it cannot be (the node is shutting down)."""
        try:
            self._out.publish(self._String(json.dumps(message, ensure_ascii=False)))
            return True
        except Exception:  # rospy raises its own kinds (ROSException...) once the node shuts down
            return False

    def connected(self) -> bool:
        """True while both topics are connected to the other side (to some agent, or some client)."""
        return bool(self._out.get_num_connections() and self._in.get_num_connections())

    def heard_from(self) -> bool:
        """True while the incoming topic is connected to a publisher."""
        return bool(self._in.get_num_connections())

    def close(self):
        self._out.unregister()
        self._in.unregister()

    def _take(self, message):
        try:
            received = json.loads(message.data)
        except ValueError:
            return
        if isinstance(received, dict):
            self._on_message(received)
