"""A robot over ROS 2 as a robot link (``robot/link.py``): a real robot (or a ROS-2-level simulator)
through this process's helper process (``client``).

A helper that is lost (it died, or hung and was ended) is replaced at once by the spare the link
keeps started, which sends the profile's safe stop (in the types the robot's graph taught); the
run that was going fails saying why, the next run goes through the new helper, and the health
light says what happened. Nothing of this waits on the window's thread.
"""
import logging
import threading
import time
from dataclasses import dataclass

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.message_arrays import as_shown
from rockly_desktop.core.state_store import StateStore
from rockly_desktop.robot import link_parts, links
from rockly_desktop.robot.health import AMBER, GREEN, RED, HealthItem, server_health, topic_health
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
from rockly_desktop.robot.wrappers.ros_versions import base_types

log = logging.getLogger(__name__)

REPLACED_SHOWN_SECONDS = 60.0  # the health light says amber this long after a helper was replaced
RETRY_SECONDS = 2.0  # a replacement that could not start is tried again after this


class Ros2Connection:
    """The link's state as the window shows it, in the ROS 1 connection's shape (``status``,
    ``lost``, ``round_trip``, ``master_uri``); ROS 2 has no master, so ``master_uri`` is the
    link's description ('ROS 2, domain 7, localhost'; 'ROS 2 Jazzy, …' with a declared distribution)."""

    def __init__(self, link, settings, ros_distribution: str = None):
        self._link = link
        self.master_uri = app_local_text("ros2_link_where", ros=ros2_name(ros_distribution), where=settings.describe())

    @property
    def lost(self) -> bool:
        """True while the link has no live helper (it is being replaced)."""
        return self._link.helper.lost

    @property
    def status(self) -> str:
        """connected | lost."""
        return "lost" if self.lost else "connected"

    @property
    def round_trip(self):
        """Seconds to the helper and back, as last measured (by the helper's own thread), or None."""
        return self._link.helper.round_trip


@dataclass(frozen=True)
class Replacement:
    """A lost helper replaced: when (``time.time()``), why (``reason``, a catalogue text) and what of
    the safe stop the new helper sent failed (empty: it was sent)."""

    at: float
    reason: object
    failures: tuple


class Ros2Robot(link_parts.ReadsFollowedGraph):
    """A robot on ROS 2, through this process's one helper (started on first use, replaced when lost,
    ended by ``shutdown``).

    ``settings`` (Ros2Settings) are the domain id, discovery range and static peers;
    ``ros_distribution`` the robot's declared ROS 2 distribution (None: its graph says which types
    it wants, ``robot/wrappers/ros_versions.py``). Raises Ros2Unavailable when ROS 2 is not set up (naming
    ``make ros2``) or its helper does not start.
    """

    kind = "ros2"
    ros_version = "ros2"

    def __init__(self, profile, settings: Ros2Settings = None, ros_distribution: str = None):
        self.profile = profile
        self.settings = settings or Ros2Settings()
        self.ros_distribution = ros_distribution
        self.state = StateStore(decode=as_shown)  # the helper's compact arrays: small ones as lists
        self._following = link_parts.GraphFollowing(self._new_feed)
        self._shut = threading.Event()
        self.replaced = None  # the last Replacement of a lost helper
        self._replacing = None  # why the helper being replaced was lost (a catalogue text); None: not replacing
        self._not_replaced = None  # why no new helper started, while that is so
        self._attached = threading.Event()  # clear while a lost helper is replaced: runs wait for the new one
        self._replacer = None  # the thread replacing a lost helper
        self._attach(Ros2Helper.get(self.settings, spare=True), match=True)
        self._attached.set()
        self.connection = Ros2Connection(self, self.settings, ros_distribution)
        interface = profile.ros_interface
        types = base_types(interface)
        streamed = {name: types[name] for name in interface.get("streams", []) if name in types}
        # the topics whose interface package ROS 2's environment lacks, by package (said by the health light)
        self._unreadable = dict(self.helper.call("missing", streamed, timeout=10.0))

    def _attach(self, helper, match: bool):
        """Work through ``helper``: its last act, should Rockly die, is the profile's safe stop (its
        publishers are made now, and matched when ``match``; one of a type ROS 2 lacks fails when the
        stop is done, saying so, as on ROS 1); a new graph over it; told when it is lost."""
        profile = self.profile
        unknown = helper.call("configure", dict(profile.ros_interface.get("qos") or {}), list(profile.safe_stop),
                              match, timeout=10.0)
        graph = Ros2Graph(helper)
        graph.published.update(action["publish"]["topic"] for action in profile.safe_stop
                               if "publish" in action and action["publish"]["topic"] not in unknown)
        graph.service_watchers.append(self.state.record)
        self.helper, self.graph = helper, graph
        helper.on_lost(self._lost)

    def _lost(self, helper):
        """``helper`` is lost (on its reader thread): replace it on a thread of its own."""
        if helper is not self.helper or self._shut.is_set():
            return
        self._attached.clear()
        self._replacing = app_local_text("ros2_helper_ended", reason=helper.exit_reason
                                         or app_local_text("ros2_pipe_closed"))
        self._replacer = threading.Thread(target=self._replace, name="ros2-helper-replace", daemon=True)
        self._replacer.start()

    def _replace(self):
        """Take the spare (or start a helper) until one works, send the safe stop through it before any
        run's command, follow the graph again if it was followed."""
        reason = self._replacing
        followed = self._following.stop()
        while True:
            try:
                self._attach(Ros2Helper.get(self.settings, spare=True), match=False)
                break
            except Exception as error:  # no helper starts now (ROS 2 broken?): said by the health light, tried again
                log.warning("the ROS 2 helper could not be replaced: %s", error)
                self._not_replaced = str(error)
                if self._shut.wait(RETRY_SECONDS):
                    return
        self._not_replaced = None
        failures = self.safe_stop()
        self.replaced = Replacement(time.time(), reason, tuple(failures))
        self._replacing = None
        self._attached.set()
        log.warning("the ROS 2 helper was replaced (%s); safe stop failures: %s", reason, failures or "none")
        if followed and not self._shut.is_set():
            self.follow_graph()

    def graph_for_run(self, interrupt: Interrupt) -> Ros2Graph:
        """The graph a run works through: a helper being replaced is waited for (a stop ends the wait),
        except by the replacement's own safe stop."""
        if threading.current_thread() is not self._replacer:
            while not self._attached.wait(0.01) and not self._shut.is_set():
                interrupt.check()
        return self.graph

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

    def _new_feed(self):
        """A state feed filling ``state`` from the graph the link works through now."""
        from rockly_desktop.robot.ros2.state_feed import Ros2StateFeed

        return Ros2StateFeed(self.graph, self.state)

    def follow_graph(self):
        """Start filling ``state`` from every topic of the graph (for the panels); idempotent."""
        return self._following.follow()

    def interface_definition(self, kind: str, name: str, type_name: str):
        """The definition of the type of the topic, service or action ``name`` (``robot.link``): from Rockly's
        ROS 2 environment, else (a topic) as its publisher's node describes it (``live_definitions``)."""
        from rockly_desktop.robot.ros2.live_definitions import interface_definition

        return interface_definition(self.helper, kind, name, type_name)

    @classmethod
    def read_definition(cls, profile, connection: dict, kind: str, name: str, type_name: str):
        """``interface_definition`` through a helper of its own that is never told the profile's safe stop
        (``robot.link``): it publishes nothing, so its end stops nothing; the process's helper is left alone."""
        from rockly_desktop.robot.ros2.live_definitions import interface_definition

        helper = Ros2Helper(Ros2Settings.from_connection(connection))
        try:
            return interface_definition(helper, kind, name, type_name)
        finally:
            helper.close()

    def backend(self, interrupt: Interrupt):
        """A backend whose waits end when ``interrupt`` is stopped or the helper is gone; made at once,
        it works through the helper of its first command (one being replaced is waited for)."""
        return Ros2Backend(self.graph_for_run, interrupt)

    def snapshot(self):
        """A real robot has no simulator view."""
        return None

    def recording_encoder(self):
        """The robot's messages as ROS 2 writes them (CDR; ``ros2msg`` schemas from ROS 2's ``.msg`` files)."""
        return links.recording_encoder(self.kind, self.profile)

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

    def health(self) -> list:
        """HealthItems: the link (domain, discovery range; a helper lost or replaced lately), the
        robot's topics, services and action servers. Asks the helper nothing (the window's thread)."""
        interface = self.profile.ros_interface
        where = self.settings.describe()
        replacing, not_replaced = self._replacing, self._not_replaced
        if not_replaced is not None:
            return [HealthItem("ROS 2", RED, app_local_text("health_ros2_lost", where=where, error=app_local_text(
                "health_ros2_not_replaced", reason=replacing, error=not_replaced)))]
        if replacing is not None:
            return [HealthItem("ROS 2", RED, app_local_text("health_ros2_replacing", where=where, error=replacing))]
        if self.helper.lost:  # ended by Rockly (the link is going away): nothing replaces it
            return [HealthItem("ROS 2", RED, app_local_text("health_ros2_lost", where=where,
                                                            error=self.helper.lost_error().message))]
        replaced = self.replaced
        if replaced is not None and time.time() - replaced.at < REPLACED_SHOWN_SECONDS:
            values = {"where": where, "time": time.strftime("%H:%M:%S", time.localtime(replaced.at)),
                      "reason": replaced.reason}
            link = HealthItem("ROS 2", AMBER, app_local_text("health_ros2_replaced_unsafe", **values,
                                                             failures="; ".join(replaced.failures))
                              if replaced.failures else app_local_text("health_ros2_replaced", **values))
        else:
            link = HealthItem("ROS 2", GREEN, app_local_text("health_ros2", where=where,
                                                             distro=self.helper.info.get("distro", "ROS 2"),
                                                             ms=round((self.connection.round_trip or 0) * 1000, 1)))
        feed = self.follow_graph()
        return [link] + topic_health(interface, self.state.topics(), self._unreadable) + server_health(
            interface, lambda kind, name: f"/{name.strip('/')}" in (
                feed.services() if kind == "services" else feed.actions()))

    def safe_stop(self) -> list:
        """Do the profile's safe stop now (whatever the program's last commands did); returns what failed."""
        self.helper.drop_failures()
        return link_parts.safe_stop(self)

    def shutdown(self):
        """Stop the robot safely, stop following the graph and end the helper (its last act is the
        safe stop too): no process is left when the window closes or ``rockly run`` ends."""
        self._shut.set()
        replacer = self._replacer
        if replacer is not None:
            replacer.join(timeout=10.0)  # the helper it takes is then ended below
        self._following.stop()
        if not self.helper.lost:
            self.safe_stop()
            self.graph.close()
        Ros2Helper.end(self.helper)
