"""A robot over ROS 2 as a robot link (``robot/link.py``): a real robot (or a ROS-2-level simulator)
through this process's helper process (``client``)."""
import time

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.message_arrays import as_shown
from rockly_desktop.core.state_store import StateStore
from rockly_desktop.robot.health import GREEN, RED, HealthItem, server_health, topic_health
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.link import LinkStatus
from rockly_desktop.robot.ros2.backend import Ros2Backend, Ros2Graph
from rockly_desktop.robot.ros2.client import Ros2Helper
from rockly_desktop.robot.ros2.environment import (
    Ros2Settings,
    Ros2Unavailable,
    declared_distribution,
    ros2_name,
    ros2_python,
)
from rockly_desktop.robot.ros_versions import base_types, link_backend
from rockly_desktop.robot.safe_stop import run_safe_stop


class Ros2Connection:
    """The link's state as the window shows it, in the ROS 1 connection's shape (``status``,
    ``lost``, ``round_trip``, ``master_uri``); ROS 2 has no master, so ``master_uri`` is the
    link's description ('ROS 2, domain 7, localhost'; 'ROS 2 Jazzy, …' with a declared distribution)."""

    def __init__(self, helper, settings, ros_distribution: str = None):
        self._helper = helper
        self.master_uri = app_local_text("ros2_link_where", ros=ros2_name(ros_distribution), where=settings.describe())
        self.round_trip = None  # seconds to the helper and back, as of the last health look

    @property
    def lost(self) -> bool:
        """True once the helper process is gone."""
        return self._helper.lost

    @property
    def status(self) -> str:
        """connected | lost."""
        return "lost" if self._helper.lost else "connected"

    def measure(self):
        """Time a round trip to the helper (``round_trip``); a gone helper leaves it as it was."""
        started = time.perf_counter()
        try:
            self._helper.call("ping", timeout=2.0)
        except Exception:
            return
        self.round_trip = time.perf_counter() - started


class Ros2Robot:
    """A robot on ROS 2, through this process's one helper (started on first use, ended by ``shutdown``).

    ``settings`` (Ros2Settings) are the domain id, discovery range and static peers;
    ``ros_distribution`` the robot's declared ROS 2 distribution (None: its graph says which types
    it wants, ``robot/ros_versions.py``). Raises Ros2Unavailable when ROS 2 is not set up (naming
    ``make ros2``) or its helper does not start.
    """

    kind = "ros2"

    def __init__(self, profile, settings: Ros2Settings = None, ros_distribution: str = None):
        self.profile = profile
        self.settings = settings or Ros2Settings()
        self.ros_distribution = ros_distribution
        self.helper = Ros2Helper.get(self.settings)
        self.connection = Ros2Connection(self.helper, self.settings, ros_distribution)
        interface = profile.ros_interface
        # its last act, should Rockly die: the profile's safe stop (its publishers are made now; one
        # of a type ROS 2 lacks fails when the stop is done, saying so, as on ROS 1)
        unknown = self.helper.call("configure", dict(interface.get("qos") or {}), list(profile.safe_stop),
                                   timeout=10.0)
        self.graph = Ros2Graph(self.helper)
        self.graph.published.update(action["publish"]["topic"] for action in profile.safe_stop
                                    if "publish" in action and action["publish"]["topic"] not in unknown)
        self.state = StateStore(decode=as_shown)  # the helper's compact arrays: small ones as lists
        self.graph.service_watchers.append(self.state.record)
        self._feed = None
        types = base_types(interface)
        streamed = {name: types[name] for name in interface.get("streams", []) if name in types}
        # the topics whose interface package ROS 2's environment lacks, by package (said by the health light)
        self._unreadable = dict(self.helper.call("missing", streamed, timeout=10.0))

    @classmethod
    def unavailable(cls):
        """Ros2Unavailable ('no_ros2', naming ``make ros2``) when there is no ROS 2 Python here; starts nothing."""
        try:
            ros2_python()
        except Ros2Unavailable as problem:
            return problem
        return None

    @classmethod
    def open(cls, profile, connection: dict = None, *, tablet=None, speed: float = 1.0, timeout: float = 5.0):
        """The robot on ``connection``'s ``domain_id``, ``discovery`` range and static ``peers``
        (Ros2Settings.from_connection), of its declared ``ros_distribution``; the robot's own nodes
        answer its tablet, and ROS 2 has no master to wait for, so ``tablet``, ``speed`` and
        ``timeout`` are not used."""
        connection = connection or {}
        return cls(profile, Ros2Settings.from_connection(connection), declared_distribution(connection))

    def follow_graph(self):
        """Start filling ``state`` from every topic of the graph (for the panels); idempotent."""
        if self._feed is None:
            from rockly_desktop.robot.ros2.state_feed import Ros2StateFeed

            self._feed = Ros2StateFeed(self.graph, self.state)
        return self._feed

    def backend(self, interrupt: Interrupt):
        """A backend whose waits end when ``interrupt`` is stopped or the helper is gone."""
        return Ros2Backend(self.graph, interrupt)

    def snapshot(self):
        """A real robot has no simulator view."""
        return None

    def recording_encoder(self):
        """The robot's messages as ROS 2 writes them (CDR; ``ros2msg`` schemas from ROS 2's ``.msg`` files)."""
        from rockly_desktop.robot.ros2.recording_codec import Ros2Encoder

        return Ros2Encoder()

    def reset(self):
        """A real robot cannot be put back."""
        raise NotImplementedError("a real robot cannot be put back")

    def status(self) -> LinkStatus:
        """The helper's state (connected | lost), where the link goes ('ROS 2, domain 7, localhost')
        and the last round trip to the helper."""
        connection = self.connection
        return LinkStatus(connection.status, connection.master_uri, connection.round_trip)

    def warnings(self) -> list:
        """Nothing to warn about: ROS 2 needs no address of this computer."""
        return []

    def graph_topics(self) -> list:
        """(topic, type, publisher count) of the ROS 2 graph (once ``follow_graph`` runs)."""
        return self._feed.graph_topics() if self._feed is not None else []

    def health(self) -> list:
        """HealthItems: the link (domain, discovery range), the robot's topics, services and action servers."""
        interface = self.profile.ros_interface
        where = self.settings.describe()
        if self.helper.lost:
            return [HealthItem("ROS 2", RED, app_local_text("health_ros2_lost", where=where,
                                                            error=str(self.helper.lost_error())))]
        self.connection.measure()
        link = HealthItem("ROS 2", GREEN, app_local_text("health_ros2", where=where,
                                                         distro=self.helper.info.get("distro", "ROS 2"),
                                                         ms=round((self.connection.round_trip or 0) * 1000, 1)))
        feed = self.follow_graph()
        return [link] + topic_health(interface, self.state.topics(), self._unreadable) + server_health(
            interface, lambda kind, name: f"/{name.strip('/')}" in (
                feed.services() if kind == "services" else feed.actions()))

    def safe_stop(self) -> list:
        """Do the profile's safe stop now; returns what failed."""
        return run_safe_stop(self.profile.safe_stop, link_backend(self, Interrupt(), stopping=True))

    def shutdown(self):
        """Stop the robot safely, stop following the graph and end the helper (its last act is the
        safe stop too): no process is left when the window closes or ``rockly run`` ends."""
        if self._feed is not None:
            self._feed.stop()
            self._feed = None
        if not self.helper.lost:
            self.safe_stop()
            self.graph.close()
        Ros2Helper.end(self.helper)
