"""Filling a StateStore from the ROS 2 graph: every topic's messages, and the graph itself.

A thread asks the helper once a second for the graph (topics with their types and publisher
counts, services, action servers), every PARAMETER_POLL_SECONDS for the nodes' parameters (each
node's answer bounded by PARAMETER_ANSWER_SECONDS) but only while ``want_parameters`` wishes them (every
node's ``list_parameters`` is a service call: only the block maker needs them), and subscribes to new topics
through the shared Ros2Graph;
the helper's messages are recorded as they come. Widgets read the store, never the helper.
"""
import logging
import threading
import time

from rockly_desktop.robot.followed_topics import FollowedTopics
from rockly_desktop.robot.parameter_wish import ParameterWish

log = logging.getLogger(__name__)

POLL_SECONDS = 1.0
PARAMETER_POLL_SECONDS = 3.0
PARAMETER_ANSWER_SECONDS = 1.0
# ROS 2's own chatter, not the robot's
IGNORED_TOPICS = {"/parameter_events", "/rosout"}


class Ros2StateFeed:
    """Keeps ``store`` filled from the graph of ``ros_graph``'s helper until ``stop()``."""

    def __init__(self, ros_graph, store):
        self._ros_graph = ros_graph
        self._followed = FollowedTopics(store, lambda topic, msg_type: ros_graph.topic(topic, msg_type).raw_callbacks)
        self._graph = {"topics": [], "own": {}, "services": [], "actions": []}
        self._parameters = ParameterWish()
        self._stopped = threading.Event()
        self._thread = threading.Thread(target=self._poll, name="rockly-ros2-graph", daemon=True)
        self._thread.start()

    def graph_topics(self) -> list:
        """(topic, type as ``pkg/Type``, publisher count) of every topic of the graph, as of the last poll."""
        return sorted((topic, short_type(types[0]), count) for topic, types, count in self._graph["topics"]
                      if types and topic not in IGNORED_TOPICS)

    def own_publishers(self) -> dict:
        """{topic: publishers of Rockly's own node on it} (not in ``graph_topics``), as of the last poll."""
        return dict(self._graph.get("own", {}))

    def services(self) -> set:
        """Names of the graph's services, as of the last poll."""
        return set(self._graph["services"])

    def actions(self) -> set:
        """Names of the graph's action servers, as of the last poll."""
        return set(self._graph["actions"])

    def graph_services(self) -> list:
        """(service, ``pkg/Type``) of the graph's services (not actions' parts, nor nodes' parameter services)."""
        return [tuple(entry) for entry in self._graph.get("typed_services", [])]

    def graph_actions(self) -> list:
        """(action, ``pkg/NameAction``) of the graph's action servers, as of the last poll."""
        return [tuple(entry) for entry in self._graph.get("typed_actions", [])]

    def graph_parameters(self) -> list:
        """``node:param`` of the graph's nodes' parameters, as of the last parameter poll."""
        return list(self._parameters.names)

    def want_parameters(self, wanted: bool):
        """Ask for the parameter names from now on (``wanted``), or no more (and forget them)."""
        self._parameters.want(wanted)

    def stop(self):
        """Stop watching the graph (subscriptions stay with the shared Ros2Graph)."""
        self._stopped.set()

    def _poll(self):
        helper = self._ros_graph.helper
        parameters_asked = 0.0
        while not self._stopped.is_set() and not helper.lost:
            try:
                self._graph = helper.call("graph", timeout=5.0)
                for topic, msg_type, count in self.graph_topics():
                    if count:
                        self._followed.follow(topic, msg_type)
                if not self._parameters.wanted.is_set():
                    parameters_asked = 0.0  # asked at once when wished again
                elif time.monotonic() - parameters_asked >= PARAMETER_POLL_SECONDS:
                    parameters_asked = time.monotonic()
                    names = helper.call("parameters", PARAMETER_ANSWER_SECONDS, timeout=PARAMETER_ANSWER_SECONDS + 5.0)
                    self._parameters.keep(names)  # unless unwished meanwhile
            except Exception as error:
                log.debug("reading the ROS 2 graph failed: %s", error)
            self._stopped.wait(POLL_SECONDS)


def short_type(msg_type: str) -> str:
    """``pkg/msg/Type`` as Rockly's panels name types (``pkg/Type``, as on ROS 1)."""
    parts = msg_type.split("/")
    return f"{parts[0]}/{parts[-1]}"
