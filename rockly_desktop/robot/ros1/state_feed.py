"""Filling a StateStore from a ROS 1 graph: every topic, decoded to dicts, and the graph itself.

A thread asks the master once a second which topics exist (with their types and
publisher counts: the others' and Rockly's own apart), which services (with their types, asked of
each server once), actions and parameters (only while ``want_parameters`` wishes them), and subscribes
to new topics through the shared RosGraph; rospy's
callback threads then record every message, undecoded (the store decodes what is read).
Widgets read the store, never rospy.
"""
import logging
import threading

from rockly_desktop.robot.followed_topics import FollowedTopics
from rockly_desktop.robot.parameter_wish import ParameterWish
from rockly_desktop.robot.ros1.agent_topics import topics as agent_topics
from rockly_desktop.robot.ros1.connection import ask_master
from rockly_desktop.robot.ros1.graph_offers import ServiceTypes, graph_actions, parameter_names

log = logging.getLogger(__name__)

POLL_SECONDS = 1.0
ROS_OWN_SERVICES = ("/get_loggers", "/set_logger_level")  # every rospy node's, no robot's


def rockly_agents(subscriber_list) -> set:
    """The nodes of Rockly agents among the master's ``[(topic, [node, ...]), ...]`` subscribers: those that
    listen on an agent's requests topic (``NAMESPACE/to_agent``, ``agent_topics``)."""
    requests = "/" + agent_topics("agent")[0].rsplit("/", 1)[1]  # "/to_agent", whatever the namespace
    return {node for topic, nodes in subscriber_list if topic.endswith(requests) for node in nodes}


class RosStateFeed:
    """Keeps ``store`` filled from the graph of ``ros_graph``'s master until ``stop()``."""

    def __init__(self, ros_graph, store):
        self._ros_graph = ros_graph
        self._followed = FollowedTopics(store, lambda topic, msg_type: ros_graph.topic(topic, msg_type).raw_callbacks)
        self._topics = []
        self._own = {}
        self._services = set()
        self._typed_services = []
        self._actions = []
        self._parameters = ParameterWish()
        self._stopped = threading.Event()
        self._thread = threading.Thread(target=self._poll, name="rockly-ros-graph", daemon=True)
        self._thread.start()

    def graph_topics(self) -> list:
        """(topic, type, publisher count) of every topic the master knows, as of the last poll; the count
        is the others' (Rockly's own, this window's and its agents', are ``own_publishers``)."""
        return list(self._topics)

    def own_publishers(self) -> dict:
        """{topic: Rockly's publishers} for each topic this process's node or a Rockly agent's publishes (what a
        program runs on the robot sends), as of the last poll."""
        return dict(self._own)

    def services(self) -> set:
        """Names of the services the master knows, as of the last poll."""
        return set(self._services)

    def graph_services(self) -> list:
        """(service, type) of the master's services, as of the last poll (a type its server did not say: "")."""
        return list(self._typed_services)

    def graph_actions(self) -> list:
        """(action, type) of the actionlib servers in the graph, as of the last poll."""
        return list(self._actions)

    def graph_parameters(self) -> list:
        """Names on the parameter server (not ROS's own), as of the last poll."""
        return list(self._parameters.names)

    def want_parameters(self, wanted: bool):
        """Ask for the parameter names from now on (``wanted``), or no more (and forget them)."""
        self._parameters.want(wanted)

    def stop(self):
        """Stop watching the graph (subscriptions stay with the shared RosGraph)."""
        self._stopped.set()

    def _poll(self):
        import rospy

        uri = self._ros_graph.connection.master_uri
        service_types = ServiceTypes(uri)
        while not self._stopped.is_set():
            if not self._ros_graph.connection.lost:
                try:
                    types = dict(ask_master(uri, "getTopicTypes"))
                    publisher_list, subscriber_list, services = ask_master(uri, "getSystemState")
                    publishers = dict(publisher_list)
                    me = rospy.get_name()
                    rocklys = {me} | rockly_agents(subscriber_list)
                    self._services = {name for name, _nodes in services}
                    self._own = {topic: len(rocklys.intersection(nodes)) for topic, nodes in publishers.items()
                                 if rocklys.intersection(nodes)}
                    self._topics = sorted((topic, msg_type, len([node for node in publishers.get(topic, [])
                                                                 if node not in rocklys]))
                                          for topic, msg_type in types.items())
                    for topic, msg_type in types.items():
                        self._followed.follow(topic, msg_type)
                    self._actions = graph_actions(types)
                    if self._parameters.wanted.is_set():
                        names = parameter_names(uri)
                        self._parameters.keep(names)  # unless unwished meanwhile
                    self._typed_services = service_types.typed(
                        name for name, nodes in services if me not in nodes and not name.endswith(ROS_OWN_SERVICES))
                except Exception as error:
                    log.debug("reading the ROS graph failed: %s", error)
            self._stopped.wait(POLL_SECONDS)
