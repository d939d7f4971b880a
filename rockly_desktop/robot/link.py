"""What every robot link offers: the built-in simulator, a robot over ROS 1, and any later backend.

A link is the robot a window or ``rockly run`` works with for a whole session: it makes a
backend for each run, follows the robot's graph into a state store (for the panels, the
topic monitor and the plot), says how healthy it is, and stops the robot safely. Which
links there are, and how each is named, set up and reached, is ``robot/links.py``'s
registry.
"""
from dataclasses import dataclass, field
from typing import Protocol

from rockly_desktop.core.catalogue import LocalText
from rockly_desktop.core.errors import RocklyError
from rockly_desktop.core.state_store import StateStore
from rockly_desktop.robot.interrupt import Interrupt


class RobotUnavailable(RocklyError):
    """A robot link cannot be used: its software is not installed, or the robot does not answer.

    ``reason`` names the case for a window that says it in its own language (the window's
    texts ``ros_REASON`` and ``ros_REASON_hint``); ``values`` are what the message names.
    """

    def __init__(self, message: str, reason: str = None, **values):
        super().__init__(message)
        self.reason = reason
        self.values = values


@dataclass(frozen=True)
class LinkWarning:
    """Something the person should know about a link that works (e.g. the robot may not reach
    this computer back). ``message`` is English; a window says ``ros_REASON`` under the title
    ``ros_TITLE`` with ``values`` filled in."""

    reason: str
    title: str
    message: str
    values: dict = field(default_factory=dict)

    def __str__(self):
        return self.message


@dataclass(frozen=True)
class LinkStatus:
    """How the connection to a robot is: ``state`` connected | connecting | lost, ``where`` it
    goes (e.g. the ROS master's URI, or a catalogue text: a ROS 2 domain) and the last round trip
    in seconds (None: not measured)."""

    state: str
    where: "str | LocalText"
    round_trip: float = None


class RobotLink(Protocol):
    """The robot a session runs programs on. Made by the registry (``links.open_link``)."""

    kind: str  # the registry's key for this link, e.g. "sim" or "ros1"
    ros_version: "str | None"  # 'ros1', 'ros2': what of a profile's ``ros_versions`` its robot wants; None: either
    profile: object  # the robot profile it serves
    state: StateStore  # what the robot's topics, services and actions last said

    @classmethod
    def unavailable(cls) -> "RobotUnavailable | None":
        """Why this kind of link cannot be used on this computer (naming the set-up step), or None.
        Cheap: it must not start anything."""

    @classmethod
    def open(cls, profile, connection: dict = None, *, tablet=None, speed: float = 1.0,
             timeout: float = 5.0) -> "RobotLink":
        """A link to ``profile``'s robot with the ``connection`` settings the registry declares for
        this kind; a simulator answers tablet questions on ``tablet`` and runs ``speed`` times real
        time; reaching a robot gives up after ``timeout`` seconds. Raises RobotUnavailable."""

    def backend(self, interrupt: Interrupt):
        """A backend for one run (``robot/interface.py``) whose waits end when ``interrupt`` stops."""

    def follow_graph(self):
        """Start filling ``state`` from the robot's whole graph (for the panels); idempotent."""

    def graph_topics(self) -> list:
        """(topic, type, publisher count) of the robot's graph; the count is the others' (not Rockly's own)."""

    def graph_services(self) -> list:
        """(service, type as ``pkg/Type``) of the robot's graph, not Rockly's own; a type not known is "".
        Read from what ``follow_graph`` last learnt: never waits (the window's thread calls it)."""

    def graph_actions(self) -> list:
        """(action, type as ``pkg/NameAction``) of the robot's action servers; never waits, as ``graph_services``."""

    def graph_parameters(self) -> list:
        """The names of the robot's parameters as ``ros.get_param`` takes them (ROS 1: the parameter
        server's; ROS 2: ``node:param``); never waits, as ``graph_services``."""

    def interface_definition(self, kind: str, name: str, type_name: str):
        """The definition (a ``core.ros_definitions.LearntDefinition``) of ``type_name``, the type of the
        topic, service or action ``name`` (``kind``), as the robot says it, for a type Rockly has no file
        for. Waits on the robot, bounded in time: never on the window's thread. Raises DefinitionNotLearnt
        saying why (and what to do) when the robot does not say it."""

    @classmethod
    def read_definition(cls, profile, connection: dict, kind: str, name: str, type_name: str):
        """``interface_definition`` asked without a link: nothing that commands the robot is made, so
        nothing stops it afterwards (``rockly blocks make`` learning a type while another client drives
        the robot). Waits on the robot, bounded in time; RobotUnavailable when it does not answer,
        DefinitionNotLearnt as ``interface_definition``."""

    def want_parameters(self, wanted: bool):
        """Whether ``graph_parameters`` is wanted (the block maker is open): asking every node for its
        parameters costs the robot, so a followed graph lists them only while someone wishes them."""

    def own_publishers(self) -> dict:
        """{topic: how many publishers Rockly itself has on it} (not in ``graph_topics``' counts), so the
        Topic monitor counts them too."""

    def health(self) -> list:
        """``robot.health.HealthItem``s: the link itself, then the topics, services and action servers."""

    def status(self) -> "LinkStatus | None":
        """How the connection to the robot is; None for a robot in this process (nothing to lose)."""

    def warnings(self) -> list:
        """LinkWarnings to tell the person once the link is made (may be empty)."""

    def snapshot(self) -> "dict | None":
        """The simulated robot's state for the simulator view; None for a real robot."""

    def recording_encoder(self):
        """``encoder(msg_type, message) -> (schema text, bytes)`` writing the robot's topics in their
        ROS encoding into a recording (``recording/``), or None: the topics are recorded as JSON. The
        encoder names its encodings: ``message_encoding`` ('ros1', 'cdr'), ``schema_encoding``
        ('ros1msg', 'ros2msg') and ``schema_name(msg_type)`` (``pkg/Type``, ``pkg/msg/Type``)."""

    def reset(self):
        """Put the simulated robot back as it started; NotImplementedError for a real robot."""

    def safe_stop(self) -> list:
        """Do the profile's safe stop now; returns what failed."""

    def shutdown(self):
        """Stop the robot safely and end what the link started."""
