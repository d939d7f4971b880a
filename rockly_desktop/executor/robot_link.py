"""The robot a program runs against: the profile's built-in simulator, or a robot over ROS 1."""
from rockly_desktop.core.state_store import StateStore
from rockly_desktop.executor.health import GREEN, RED, HealthItem, server_health, topic_health
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.safe_stop import run_safe_stop
from rockly_desktop.robot.sim_world import SimBackend, SimWorld


class SimulatedRobot:
    """A profile's simulator running in this process for the whole session.

    ``tablet`` answers the robot's tablet dialogs (a window, or the CLI's --answer list).
    """

    name = "simulator"

    def __init__(self, profile, tablet=None, speed: float = 1.0):
        self.profile = profile
        self.world = SimWorld()
        self.state = StateStore()
        self.world.tap(self.state.record)
        self.simulator = profile.create("simulator", self.world, tablet=tablet, speed=speed)
        self.simulator.start()

    def backend(self, interrupt: Interrupt):
        """A backend whose waits end when ``interrupt`` is stopped."""
        return SimBackend(self.world, interrupt)

    def snapshot(self) -> dict:
        """The simulated robot's state, for the simulator view."""
        return self.simulator.snapshot()

    def graph_topics(self) -> list:
        """(topic, type, publisher count) of the simulated robot's topics."""
        return [(topic, msg_type, 1) for topic, msg_type in self.world.topics()]

    def health(self) -> list:
        """HealthItems of the simulated robot (its interface as the manifest declares it)."""
        interface = self.profile.ros_interface
        link = HealthItem("simulator", GREEN, "the built-in simulator is running")

        def has_server(kind, name):
            return self.world.has_service(name) if kind == "services" else self.world.has_action(name)

        return [link] + topic_health(interface, self.state.topics()) + server_health(interface, has_server)

    def safe_stop(self) -> list:
        """Do the profile's safe stop now; returns what failed."""
        return run_safe_stop(self.profile.safe_stop, self.backend(Interrupt()))

    def reset(self):
        """Put the simulated robot back as it started (its profile's ``reset()``)."""
        self.simulator.reset()

    def shutdown(self):
        """Stop the simulator's threads."""
        self.safe_stop()
        self.simulator.shutdown()


class RosRobot:
    """A real robot (or a ROS-level simulator) on ROS 1, through this process's one node.

    Raises RosUnavailable when rospy is missing or the master does not answer.
    """

    name = "ros1"

    def __init__(self, profile, master_uri: str = None):
        from rockly_desktop.robot.ros1.connection import RosConnection, RosUnavailable

        self.profile = profile
        self.connection = RosConnection.get(master_uri)  # RosUnavailable without rospy or a master
        try:
            from rockly_desktop.robot.ros1.backend import RosGraph
            from rockly_desktop.robot.ros1.message_classes import MessageTypes
        except ImportError as error:
            raise RosUnavailable(f"the ROS 1 message tools (genpy, actionlib) are not installed ({error})",
                                 "no_ros_tools") from None
        self.graph = RosGraph(self.connection, MessageTypes(profile.message_folders))
        safe_backend = self.backend(Interrupt())
        for action in profile.safe_stop:  # connected now, so a stop never waits for them
            if "publish" in action:
                safe_backend.connect_publisher(action["publish"]["topic"], action["publish"]["type"])
        from rockly_desktop.robot.ros1.message_values import from_message

        self.state = StateStore(decode=from_message)
        self.graph.service_watchers.append(self.state.record)  # this node's calls, e.g. the tablet's questions
        self._feed = None

    def follow_graph(self):
        """Start filling ``state`` from every topic of the graph (for the panels); idempotent."""
        if self._feed is None:
            from rockly_desktop.robot.ros1.state_feed import RosStateFeed

            self._feed = RosStateFeed(self.graph, self.state)
        return self._feed

    def backend(self, interrupt: Interrupt):
        """A backend whose waits end when ``interrupt`` is stopped or the master is lost."""
        from rockly_desktop.robot.ros1.backend import Ros1Backend

        return Ros1Backend(self.graph, interrupt)

    def snapshot(self):
        """A real robot has no simulator view."""
        return None

    def graph_topics(self) -> list:
        """(topic, type, publisher count) of the ROS graph (once ``follow_graph`` runs)."""
        return self._feed.graph_topics() if self._feed is not None else []

    def health(self) -> list:
        """HealthItems: the master (with its round trip), the robot's topics, services and action servers."""
        interface = self.profile.ros_interface
        connection = self.connection
        if connection.lost:
            return [HealthItem("ROS master", RED, f"{connection.master_uri} does not answer")]
        link = HealthItem("ROS master", GREEN, f"{connection.master_uri}, round trip "
                          f"{(connection.round_trip or 0) * 1000:.1f} ms")
        feed = self.follow_graph()
        publishers = {topic: count for topic, _type, count in feed.graph_topics()}
        return [link] + topic_health(interface, self.state.topics()) + server_health(
            interface, lambda kind, name: name in feed.services() if kind == "services"
            else publishers.get(f"/{name.strip('/')}/status", 0) > 0)

    def safe_stop(self) -> list:
        """Do the profile's safe stop now; returns what failed."""
        return run_safe_stop(self.profile.safe_stop, self.backend(Interrupt()))

    def shutdown(self):
        """Stop the robot safely and stop following the graph; the node stays up."""
        if self._feed is not None:
            self._feed.stop()
            self._feed = None
        self.safe_stop()
