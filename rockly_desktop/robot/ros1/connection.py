"""The one ROS 1 node of a Rockly process, and whether its master is reachable.

rospy allows ``init_node`` once per process, so the node is started on first use with
the master chosen then (``ROS_MASTER_URI``, ``ROS_IP``/``ROS_HOSTNAME`` are read at that
moment). A watchdog asks the master for its pid twice a second; waits in the backend
fail within ~2 s of the master vanishing (nothing listens at its address any more), or
once it has not answered for SILENT_SECONDS (a hung master, a cut network): a master that
only answers late, as on a loaded computer, is not lost. When it is back (or another
master answers there, even between two looks), the node registers its endpoints with it
again and the status returns to connected.
"""
import logging
import os
import socket
import threading
import time
import xmlrpc.client

from rockly_desktop.core.app_texts import app_text
from rockly_desktop.robot.link import RobotUnavailable

log = logging.getLogger(__name__)

CONNECTED, CONNECTING, LOST = "connected", "connecting", "lost"
WATCH_SECONDS = 0.5
PROBE_TIMEOUT = 1.0
SILENT_SECONDS = 10.0  # a master or robot node that answers no look for this long is lost (a late one is not)
NODE_NAME = "rockly"


class _QuickTransport(xmlrpc.client.Transport):
    """XML-RPC that gives up after PROBE_TIMEOUT instead of hanging on a lost network."""

    def make_connection(self, host):
        connection = super().make_connection(host)
        connection.timeout = PROBE_TIMEOUT
        return connection


def ask_master(master_uri: str, method: str, *args):
    """Call the master's XML-RPC ``method`` (caller id filled in), giving up after PROBE_TIMEOUT.

    Returns the value, or raises OSError / xmlrpc.client.Error when the master does not answer.
    """
    code, message, value = getattr(xmlrpc.client.ServerProxy(master_uri, transport=_QuickTransport()), method)(
        "/rockly", *args)
    if code != 1:
        raise xmlrpc.client.Fault(code, message)
    return value


def master_pid(master_uri: str) -> tuple:
    """The master's pid and the round-trip time of asking it (seconds); ``(None, seconds waited)`` when it did not
    answer within PROBE_TIMEOUT (late: it may be busy), ``(None, None)`` when it refused or failed."""
    started = time.monotonic()
    try:
        pid = ask_master(master_uri, "getPid")
    except TimeoutError:
        return None, time.monotonic() - started
    except (OSError, xmlrpc.client.Error):
        return None, None
    return pid, time.monotonic() - started


def master_answers(master_uri: str) -> float:
    """The master's round-trip time in seconds, or None when it does not answer."""
    pid, round_trip = master_pid(master_uri)
    return None if pid is None else round_trip


def address_problem(environment):
    """Why other nodes could not reach this computer at the address ROS is told to give them
    (``ROS_IP``), as (kind, address) with kind 'ipv6' or 'not_local'; None when it is fine.
    rospy starts either way, and the robot's nodes then never get this computer's commands."""
    address = environment.get("ROS_IP")
    if not address:
        return None
    if ":" in address and environment.get("ROS_IPV6") != "on":
        return "ipv6", address
    try:
        with socket.socket(socket.AF_INET6 if ":" in address else socket.AF_INET, socket.SOCK_STREAM) as probe:
            probe.bind((address, 0))
    except OSError:
        return "not_local", address
    return None


def address_problem_text(problem, language: str = "en") -> str:
    """An address problem (kind, address) in plain words in ``language`` (the catalogue's ``address_KIND``)."""
    kind, address = problem
    return app_text(f"address_{kind}", language, address=address)


class RosUnavailable(RobotUnavailable):
    """rospy is not installed here, or the master cannot be reached.

    ``reason`` is 'no_master', 'no_rospy', 'other_master' or 'no_ros_tools' (see RobotUnavailable).
    """


class RosConnection:
    """The process's ROS node and its master's health (``status``: connected | connecting | lost)."""

    _instance = None
    _instance_lock = threading.Lock()

    def __init__(self, master_uri: str, host: str = None):
        self.master_uri = master_uri
        self.host = host
        self.status = CONNECTING
        self.round_trip = None
        self.address_problem = None  # (kind, address) when the robot could not reach this computer
        self._master_pid = None
        self._answered_at = None  # when the master last answered a look
        self._stopped = threading.Event()
        self._watchdog = None

    @classmethod
    def get(cls, master_uri: str = None, host: str = None, timeout: float = 5.0) -> "RosConnection":
        """The process's connection, started (once) with ``master_uri``; RosUnavailable if it cannot be."""
        with cls._instance_lock:
            if cls._instance is None:
                master_uri = master_uri or os.environ.get("ROS_MASTER_URI", "http://localhost:11311")
                connection = cls(master_uri, host)
                connection._start(timeout)
                cls._instance = connection
            elif master_uri and master_uri != cls._instance.master_uri:
                raise RosUnavailable(f"this Rockly is already connected to {cls._instance.master_uri}; "
                                     f"restart it to use {master_uri}", "other_master",
                                     current=cls._instance.master_uri, wanted=master_uri)
            return cls._instance

    def _start(self, timeout: float):
        try:
            import rospy
        except ImportError as error:
            raise RosUnavailable(f"ROS 1 (rospy) is not installed on this computer ({error})", "no_rospy") from None
        os.environ["ROS_MASTER_URI"] = self.master_uri
        if self.host:
            os.environ["ROS_IP" if self.host.replace(".", "").isdigit() else "ROS_HOSTNAME"] = self.host
        self.address_problem = address_problem(os.environ)
        if self.address_problem:
            log.warning("%s", address_problem_text(self.address_problem))
        if not self._wait_for_master(timeout):
            raise RosUnavailable(f"no ROS master answers at {self.master_uri}", "no_master", master=self.master_uri)
        rospy.init_node(NODE_NAME, anonymous=True, disable_signals=True)
        self.status = CONNECTED
        self._watchdog = threading.Thread(target=self._watch, name="rockly-ros-watchdog", daemon=True)
        self._watchdog.start()

    def _wait_for_master(self, timeout: float) -> bool:
        deadline = time.monotonic() + timeout
        while True:
            self._master_pid, self.round_trip = master_pid(self.master_uri)
            if self._master_pid is not None:
                self._answered_at = time.monotonic()
                return True
            if time.monotonic() >= deadline:
                return False
            time.sleep(0.1)

    def _watch(self):
        while not self._stopped.wait(WATCH_SECONDS):
            self._look()

    def _look(self):
        """Ask the master once: note whether it answers, and tell a new master of this node. A late answer keeps the
        status until the master has been silent for SILENT_SECONDS."""
        pid, waited = master_pid(self.master_uri)
        now = time.monotonic()
        if pid is None and waited is not None and self._answered_at is not None \
                and now - self._answered_at < SILENT_SECONDS:
            return
        self.round_trip = None if pid is None else waited
        if pid is not None:
            self._answered_at = now
        status = CONNECTED if pid is not None else LOST
        if status != self.status:
            log.warning("ROS master %s: %s", self.master_uri, status)
        # A master restarted between two looks (another pid) knows nothing of this node either.
        if status == CONNECTED and (self.status != CONNECTED or pid != self._master_pid):
            _register_again()
            self._master_pid = pid
        self.status = status

    @property
    def lost(self) -> bool:
        """True while the master does not answer."""
        return self.status == LOST

    def shutdown(self, reason: str):
        """End this process's node for good: the master forgets its publishers, subscribers
        and services (rospy cannot start a node again in the same process)."""
        import rospy

        self._stopped.set()
        rospy.signal_shutdown(reason)


def _register_again():
    """Tell a restarted master about this node's publishers, subscribers and services.

    rospy registers each endpoint once, when it is made; a master that comes back empty
    would otherwise never connect this node to anyone again.
    """
    from rospy.impl.registration import (
        Registration,
        RegManager,
        get_registration_listeners,
        get_service_manager,
        get_topic_manager,
    )

    topics, services = get_topic_manager(), get_service_manager()
    managers = [listener for listener in get_registration_listeners().listeners if isinstance(listener, RegManager)]
    for manager in managers:
        for topic, msg_type in topics.get_publications():
            manager.reg_added(topic, msg_type, Registration.PUB)
        for topic, msg_type in topics.get_subscriptions():
            manager.reg_added(topic, msg_type, Registration.SUB)
        for name, uri in services.get_services():
            manager.reg_added(name, uri, Registration.SRV)
