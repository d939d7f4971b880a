"""A robot over ROS 1 as a robot link (``robot/link.py``), through this process's one node."""
import importlib.util
import os

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.state_store import StateStore
from rockly_desktop.robot import link_parts, links
from rockly_desktop.robot.health import GREEN, RED, HealthItem, server_health, topic_health
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.link import LinkStatus, LinkWarning

SETUP_STEP = "run `make setup` in Rockly's folder (it installs Debian's ROS 1: python3-rospy and its tools)"


class RosRobot(link_parts.ReadsFollowedGraph):
    """A real robot (or a ROS-level simulator) on ROS 1, through this process's one node.

    ``master_uri`` and ``host`` (this computer's ROS_IP or ROS_HOSTNAME) are used when the node
    starts, the first time; it waits up to ``timeout`` s for the master.
    Raises RosUnavailable when rospy is missing or the master does not answer.
    """

    kind = "ros1"
    ros_version = "ros1"

    def __init__(self, profile, master_uri: str = None, host: str = None, timeout: float = 5.0):
        from rockly_desktop.robot.ros1.connection import RosConnection, RosUnavailable

        self.profile = profile
        self.connection = RosConnection.get(master_uri, host, timeout)  # RosUnavailable without rospy or a master
        try:
            from rockly_desktop.robot.ros1.backend import RosGraph
            from rockly_desktop.robot.ros1.message_classes import MessageTypes
        except ImportError as error:
            raise RosUnavailable(f"the ROS 1 message tools (genpy, actionlib) are not installed ({error}); "
                                 f"{SETUP_STEP}", "no_ros_tools") from None
        self.graph = RosGraph(self.connection, MessageTypes(profile.message_folders))
        safe_backend = self.backend(Interrupt())
        for action in profile.safe_stop:  # connected now, so a stop never waits for them
            if "publish" in action:
                safe_backend.connect_publisher(action["publish"]["topic"], action["publish"]["type"])
        from rockly_desktop.robot.ros1.message_values import shown_message

        self.state = StateStore(decode=shown_message)
        self.graph.service_watchers.append(self.state.record)  # this node's calls, e.g. the tablet's questions
        self._following = link_parts.GraphFollowing(self._new_feed)

    @classmethod
    def unavailable(cls):
        """RosUnavailable ('no_rospy', naming the set-up step) when rospy cannot be imported here."""
        if importlib.util.find_spec("rospy") is not None:
            return None
        from rockly_desktop.robot.ros1.connection import RosUnavailable

        return RosUnavailable(f"ROS 1 (rospy) is not installed on this computer: {SETUP_STEP}, "
                              "or use the built-in simulator", "no_rospy")

    @classmethod
    def open(cls, profile, connection: dict = None, *, tablet=None, speed: float = 1.0, timeout: float = 5.0):
        """The robot at ``connection``'s ``master`` (and this computer as ``host``); the robot's own
        nodes answer its tablet, so ``tablet`` and ``speed`` are not used."""
        connection = connection or {}
        return cls(profile, connection.get("master") or None, connection.get("host") or None, timeout)

    def _new_feed(self):
        """A state feed filling ``state`` from the graph the link works through now."""
        from rockly_desktop.robot.ros1.state_feed import RosStateFeed

        return RosStateFeed(self.graph, self.state)

    def follow_graph(self):
        """Start filling ``state`` from every topic of the graph (for the panels); idempotent."""
        return self._following.follow()

    def interface_definition(self, kind: str, name: str, type_name: str):
        """The definition of the type of the topic, service or action ``name`` (``robot.link``): a topic's as its
        publisher says it (``live_definitions``), else from its installed package; a topic's type no package
        here defines is learnt by this link's runs too, so they publish and hear it."""
        from rockly_desktop.core.errors import RobotCommandError
        from rockly_desktop.robot.ros1 import live_definitions

        learnt = live_definitions.interface_definition(self.connection.master_uri, kind, "/" + name.strip("/"),
                                                       type_name)
        if kind == "topic":
            try:
                self.graph.types.message_class(learnt.type_name)
            except RobotCommandError:
                self.graph.types.learn(learnt.type_name, learnt.full_text)
        return learnt

    @classmethod
    def read_definition(cls, profile, connection: dict, kind: str, name: str, type_name: str):
        """``interface_definition`` through the master at ``connection``'s ``master`` alone (``robot.link``):
        no node is started and nothing is published, so nothing stops the robot."""
        from rockly_desktop.robot.ros1 import live_definitions
        from rockly_desktop.robot.ros1.connection import RosUnavailable, master_answers

        master_uri = connection.get("master") or os.environ.get("ROS_MASTER_URI", "http://localhost:11311")
        if master_answers(master_uri) is None:
            raise RosUnavailable(f"no ROS master answers at {master_uri}", "no_master", master=master_uri)
        return live_definitions.interface_definition(master_uri, kind, "/" + name.strip("/"), type_name)

    def backend(self, interrupt: Interrupt):
        """A backend whose waits end when ``interrupt`` is stopped or the master is lost."""
        from rockly_desktop.robot.ros1.backend import Ros1Backend

        return Ros1Backend(self.graph, interrupt)

    def snapshot(self):
        """A real robot has no simulator view."""
        return None

    def recording_encoder(self):
        """The robot's messages as they came over the wire (ROS 1's own encoding)."""
        return links.recording_encoder(self.kind, self.profile)

    def reset(self):
        """A real robot cannot be put back."""
        raise NotImplementedError("a real robot cannot be put back")

    def status(self) -> LinkStatus:
        """The master's state (connected | connecting | lost), its URI and round trip."""
        connection = self.connection
        return LinkStatus(connection.status, connection.master_uri, connection.round_trip)

    def warnings(self) -> list:
        """A LinkWarning when the robot's nodes could not reach this computer at its ROS_IP."""
        if not self.connection.address_problem:
            return []
        from rockly_desktop.robot.ros1.connection import address_problem_text

        kind, address = self.connection.address_problem
        return [LinkWarning(f"address_{kind}", "address_title", address_problem_text(self.connection.address_problem),
                            {"address": address})]

    def health(self) -> list:
        """HealthItems: the master (with its round trip), the robot's topics, services and action servers."""
        interface = self.profile.ros_interface
        connection = self.connection
        if connection.lost:
            return [HealthItem("ROS master", RED, app_local_text("health_master_silent", uri=connection.master_uri))]
        link = HealthItem("ROS master", GREEN, app_local_text("health_master", uri=connection.master_uri,
                                                              ms=round((connection.round_trip or 0) * 1000, 1)))
        feed = self.follow_graph()
        publishers = {topic: count for topic, _type, count in feed.graph_topics()}
        return [link] + topic_health(interface, self.state.topics()) + server_health(
            interface, lambda kind, name: name in feed.services() if kind == "services"
            else publishers.get(f"/{name.strip('/')}/status", 0) > 0)

    def safe_stop(self) -> list:
        """Do the profile's safe stop now; returns what failed."""
        return link_parts.safe_stop(self)

    def shutdown(self):
        """Stop the robot safely and stop following the graph; the node stays up."""
        self._following.stop()
        self.safe_stop()
