"""What the robot links (``robot/link.py``) share: the profile's safe stop, and following the robot's graph."""
import threading

from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.safe_stop import run_safe_stop
from rockly_desktop.robot.wrappers.ros_versions import link_backend


def safe_stop(link) -> list:
    """Do ``link``'s profile's safe stop now, through a backend of the link's that nothing interrupts
    and that sends in the types its robot's graph taught; returns what failed."""
    return run_safe_stop(link.profile.safe_stop, link_backend(link, Interrupt(), stopping=True))


class GraphFollowing:
    """A link's state feed (``graph_topics``, ``own_publishers``, ``services``, ``graph_services``,
    ``graph_actions``, ``graph_parameters``, ``want_parameters``, ``stop``), started by
    ``start()`` on the first ``follow`` and stopped by ``stop``; until then the robot's graph is empty.
    The wish for parameters outlives the feed: a feed started again (a new connection) is told it."""

    def __init__(self, start):
        self._start = start
        self._feed = None
        self._parameters_wanted = False
        self._lock = threading.Lock()

    def follow(self):
        """The feed, started now if it is not running; idempotent."""
        with self._lock:
            if self._feed is None:
                self._feed = self._start()
                self._feed.want_parameters(self._parameters_wanted)
            return self._feed

    def want_parameters(self, wanted: bool):
        """Ask the feed to list the robot's parameters (``wanted``) or to stop asking for them."""
        with self._lock:
            self._parameters_wanted = bool(wanted)
            feed = self._feed
        if feed is not None:
            feed.want_parameters(wanted)

    def stop(self) -> bool:
        """Stop the feed; returns whether it was running (to follow again on a new connection)."""
        with self._lock:
            feed, self._feed = self._feed, None
        if feed is not None:
            feed.stop()
        return feed is not None

    def graph_topics(self) -> list:
        """(topic, type, publisher count) of the robot's graph; empty while not followed."""
        feed = self._feed
        return feed.graph_topics() if feed is not None else []

    def own_publishers(self) -> dict:
        """{topic: Rockly's own publishers on it}; empty while not followed."""
        feed = self._feed
        return feed.own_publishers() if feed is not None else {}

    def graph_services(self) -> list:
        """(service, type) of the robot's graph; empty while not followed."""
        feed = self._feed
        return feed.graph_services() if feed is not None else []

    def graph_actions(self) -> list:
        """(action, type) of the robot's graph; empty while not followed."""
        feed = self._feed
        return feed.graph_actions() if feed is not None else []

    def graph_parameters(self) -> list:
        """The names of the robot's parameters; empty while not followed."""
        feed = self._feed
        return feed.graph_parameters() if feed is not None else []


class ReadsFollowedGraph:
    """The graph-reading half of a robot link whose ``_following`` is a GraphFollowing: what the last look
    at the robot's graph learnt (all empty until ``follow_graph`` runs); none of these waits."""

    def graph_topics(self) -> list:
        """(topic, type, publisher count) of the robot's graph."""
        return self._following.graph_topics()

    def graph_services(self) -> list:
        """(service, type) of the robot's graph, not Rockly's own."""
        return self._following.graph_services()

    def graph_actions(self) -> list:
        """(action, type) of the robot's graph's action servers."""
        return self._following.graph_actions()

    def graph_parameters(self) -> list:
        """The robot's graph's parameter names (listed only while ``want_parameters`` wishes them)."""
        return self._following.graph_parameters()

    def want_parameters(self, wanted: bool):
        """List the robot's parameters from now on (``wanted``), or stop asking every node for them."""
        self._following.want_parameters(wanted)

    def own_publishers(self) -> dict:
        """{topic: Rockly's own publishers on it} (not in ``graph_topics``)."""
        return self._following.own_publishers()
