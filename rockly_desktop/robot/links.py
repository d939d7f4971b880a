"""The registry of robot links: every kind of robot Rockly runs programs on, in one place.

Each entry is data (its name in the window, its connection settings, its ``rockly sim``
option) plus the import path of its link class (``robot/link.py``'s ``RobotLink``), which
is imported only when that kind is used: a missing ROS stack costs nothing at start-up.
The command line (``--backend``, ``rockly sim --ros``), the run toolbar's robot box and
the connection dialog all read it. A new backend is one module and one entry here (and its
window texts in ``ui/texts.py``).
"""
import importlib
import os
from dataclasses import dataclass

from rockly_desktop.core.ros_distributions import DISTRIBUTIONS
from rockly_desktop.robot.link import RobotUnavailable


@dataclass(frozen=True)
class ConnectionSetting:
    """One thing a person tells Rockly to reach a robot, remembered per profile.

    ``label`` and ``hint`` are window text keys (``ui/texts.py``); the default is the first
    of the ``environment`` variables that is set, else ``default``; ``example`` is a long
    typical value (the field is made wide enough for it). ``choices`` ((value, text key)
    pairs; no key: the value is a name, the same in every language, e.g. Jazzy) make it a
    choice among those values (e.g. ROS 2's discovery range) instead of a typed text; a
    choice's ``hint`` is its tooltip. ``option`` is its ``rockly run`` and ``rockly sim``
    option, with ``help`` (English, as the whole command line).
    """

    name: str
    label: str
    environment: tuple = ()
    default: str = ""
    hint: str = None
    example: str = ""
    choices: tuple = ()
    option: str = None
    help: str = ""

    def default_value(self) -> str:
        """The value to offer when none is remembered: from this computer's environment (a choice's
        value in any case, e.g. LOCALHOST for localhost; one that is no choice, e.g. a ROS 1
        ROS_DISTRO, is not offered), else ``default``."""
        value = next((os.environ[name] for name in self.environment if os.environ.get(name)), self.default)
        if not self.choices:
            return value
        return next((choice for choice, _text in self.choices if choice.lower() == value.lower()), self.default)


@dataclass(frozen=True)
class LinkKind:
    """One kind of robot link: ``kind`` is its key (``--backend KIND``), ``link`` its class as
    ``module:Class``, ``name`` the window text key of its name in the robot box, ``title`` its
    name on the command line (English, as the whole command line).

    ``simulated``: the profile's simulator in this process (shown in the Simulator dock, can be
    put back). ``settings`` are asked for in the connection dialog, whose explanation is the
    text ``explanation``; they are remembered under ``settings_group/PROFILE/NAME``.
    ``sim_option`` (e.g. ``--ros``) makes ``rockly sim`` serve the simulator on this link's
    middleware through ``sim_server`` (``module:callable``, see ``serve_simulator``).
    ``recording_encoder`` (``module:callable``, see ``recording_encoder``) encodes the robot's topics
    in a recording of a run on this link; None: they are recorded as JSON. ``agent_topics`` (a module, see
    ``agent_topics``) carries the robot's agent's messages on this link's middleware; None: the agent is reached
    over TCP only; ``agent_texts`` are its texts (cannot reach the middleware, no agent in the graph, the agent
    offers its calls there), and ``agent_beside`` names the connection setting (a URL) whose host the agent runs on.
    """

    kind: str
    link: str
    name: str
    title: str
    simulated: bool = False
    settings: tuple = ()
    settings_group: str = None
    explanation: str = None
    sim_option: str = None
    sim_server: str = None
    recording_encoder: str = None
    agent_topics: str = None
    agent_texts: tuple = ()
    agent_beside: str = None

    def link_class(self):
        """The link class (imported now, on first use)."""
        return _load(self.link)


ROS1_SETTINGS = (
    ConnectionSetting("master", "connect_master", ("ROS_MASTER_URI",), "http://localhost:11311",
                      example="http://192.168.100.100:11311", option="--master",
                      help="ROS master URI for ROS 1 (default: $ROS_MASTER_URI)"),
    ConnectionSetting("host", "connect_host", ("ROS_IP", "ROS_HOSTNAME"), hint="connect_host_hint"),
)

ROS2_SETTINGS = (
    ConnectionSetting("domain_id", "connect_domain", ("ROS_DOMAIN_ID",), "0", hint="connect_domain_hint",
                      example="232", option="--domain",
                      help="ROS 2 domain id, 0 to 232 (default: $ROS_DOMAIN_ID or 0)"),
    ConnectionSetting("discovery", "connect_discovery", ("ROS_AUTOMATIC_DISCOVERY_RANGE",), "subnet",
                      choices=tuple((value, f"connect_discovery_{value}")
                                    for value in ("localhost", "subnet", "off", "system_default")),
                      option="--discovery", help="ROS 2 discovery range: localhost, subnet, off or system_default "
                                                 "(default: $ROS_AUTOMATIC_DISCOVERY_RANGE or subnet)"),
    ConnectionSetting("peers", "connect_peers", ("ROS_STATIC_PEERS",), hint="connect_peers_hint",
                      example="192.168.100.100; robot.local", option="--peers",
                      help="ROS 2 static peers beyond the discovery range, e.g. '192.168.1.30;robot.local' "
                           "(default: $ROS_STATIC_PEERS)"),
    ConnectionSetting("ros_distribution", "connect_distribution", ("ROS_DISTRO",), "auto",
                      hint="connect_distribution_hint",
                      choices=(("auto", "connect_distribution_auto"),
                               *((name, None) for name in DISTRIBUTIONS)),
                      option="--ros-distro",
                      help="the robot's ROS 2 distribution, where types differ (a Jazzy robot's TwistStamped "
                           f"/cmd_vel): auto (the robot's graph says), {', '.join(DISTRIBUTIONS)} "
                           "(default: $ROS_DISTRO or auto)"),
)

ROS1_ENCODER = "rockly_desktop.robot.ros1.recording_codec:profile_encoder"
ROS2_ENCODER = "rockly_desktop.robot.ros2.recording_codec:profile_encoder"

LINKS = {entry.kind: entry for entry in (
    # the simulator's ROS-shaped messages are recorded as ROS 1 writes them: a run on it reads like one on the robot
    LinkKind("sim", "rockly_desktop.robot.sim.link:SimulatedRobot", "backend_simulator", "the built-in simulator",
             simulated=True, recording_encoder=ROS1_ENCODER),
    LinkKind("ros1", "rockly_desktop.robot.ros1.link:RosRobot", "backend_ros1", "a robot over ROS 1",
             settings=ROS1_SETTINGS,
             settings_group="ros", explanation="connect_explanation",
             sim_option="--ros", sim_server="rockly_desktop.robot.ros1.sim_bridge:serve_simulator",
             recording_encoder=ROS1_ENCODER, agent_topics="rockly_desktop.robot.ros1.agent_topics",
             agent_texts=("agent_no_ros", "agent_not_in_graph", "agent_ready_ros"), agent_beside="master"),
    LinkKind("ros2", "rockly_desktop.robot.ros2.link:Ros2Robot", "backend_ros2", "a robot over ROS 2",
             settings=ROS2_SETTINGS, settings_group="ros2", explanation="connect_explanation_ros2",
             sim_option="--ros2", sim_server="rockly_desktop.robot.ros2.sim_bridge:serve_simulator",
             recording_encoder=ROS2_ENCODER, agent_topics="rockly_desktop.robot.ros2.agent_topics",
             agent_texts=("agent_no_ros2", "agent_not_in_graph_ros2", "agent_ready_ros2")),
)}
DEFAULT_KIND = "sim"


class UnknownRobotLink(RobotUnavailable):
    """A kind of robot link that is not in the registry."""

    def __init__(self, kind: str):
        known = ", ".join(LINKS)
        super().__init__(f"there is no robot link '{kind}' (Rockly knows: {known})", "unknown_link",
                         kind=kind, known=known)


def link_kinds() -> list:
    """Every LinkKind, in the order the robot box lists them (the simulator first)."""
    return list(LINKS.values())


def link_kind(kind: str) -> LinkKind:
    """The LinkKind ``kind``; UnknownRobotLink (naming the known ones) if there is none."""
    try:
        return LINKS[kind]
    except KeyError:
        raise UnknownRobotLink(kind) from None


def check_available(kind: str):
    """Raise RobotUnavailable (naming the set-up step) when ``kind`` cannot be used on this computer."""
    problem = link_kind(kind).link_class().unavailable()
    if problem is not None:
        raise problem


def open_link(kind: str, profile, connection: dict = None, **options):
    """A link of ``kind`` to ``profile``'s robot (``RobotLink.open``'s ``options``); RobotUnavailable
    when it cannot be used here or the robot does not answer."""
    check_available(kind)
    return link_kind(kind).link_class().open(profile, connection or {}, **options)


def read_definition(kind: str, profile, connection: dict, interface_kind: str, name: str, type_name: str):
    """The definition of ``type_name`` as ``kind``'s robot says it (``RobotLink.read_definition``), asked
    read-only: no link is opened, so neither is the safe stop done that ends every link (it would stop a
    program another client runs on the robot). RobotUnavailable when it cannot be used here."""
    check_available(kind)
    return link_kind(kind).link_class().read_definition(profile, connection or {}, interface_kind, name, type_name)


def serve_simulator(kind: str, profile, connection: dict = None, speed: float = 1.0, tablet=None):
    """``profile``'s simulator served on ``kind``'s middleware until its ``shutdown()``.

    Returns the server: ``simulator`` (the profile's), ``where`` (what the window names, e.g. the
    master's URI) and ``shutdown()``. RobotUnavailable when ``kind`` cannot serve one here.
    """
    entry = link_kind(kind)
    if entry.sim_server is None:
        raise RobotUnavailable(f"the robot link '{kind}' cannot serve a simulator", "no_sim_server", kind=kind)
    check_available(kind)
    return _load(entry.sim_server)(profile, connection or {}, speed=speed, tablet=tablet)


def recording_encoder(kind: str, profile, msg_types=()):
    """The encoder of ``kind``'s entry for a recording of ``profile``'s robot (``RobotLink.recording_encoder``),
    the message classes of ``msg_types`` made now; None when the entry names none or its middleware's
    tools are not installed here (e.g. genpy): the robot's topics are then recorded as JSON."""
    target = link_kind(kind).recording_encoder
    if target is None:
        return None
    try:
        make = _load(target)
    except ImportError:
        return None
    return make(profile, msg_types)


def agent_topics(kind: str):
    """The module of ``kind``'s entry that carries the robot's agent's messages on its middleware
    (``robot/ros1/agent_topics.py`` is the example), imported now; None when the entry names none."""
    target = link_kind(kind).agent_topics
    return importlib.import_module(target) if target is not None else None


def agent_graph_kinds() -> list:
    """The kinds whose middleware carries the robot's agent's messages (their entries name ``agent_topics``)."""
    return [entry.kind for entry in LINKS.values() if entry.agent_topics]


def _load(target: str):
    module, _, name = target.partition(":")
    return getattr(importlib.import_module(module), name)
