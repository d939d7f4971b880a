"""Names and types that differ between ROS versions: a profile's ``ros_versions``, resolved per robot.

A profile declares its interface once in ``ros_interface`` (the types of ROS 1 and of ROS 2 before
any change) and, in ``ros_versions``, only what differs: ``{/cmd_vel: {jazzy: geometry_msgs/TwistStamped}}``
(a ROS 2 distribution counts from that one on; ``ros1`` and ``ros2`` name a whole version).

Which type a robot wants is not asked of anyone: on ROS 2 the robot's graph says it (the type its
``/cmd_vel`` subscriber has); only when the graph lists no type for the name does the declared
distribution (a link's ``ros_distribution``) or the version decide. The built-in simulator takes
either type; declared with a distribution it gets what such a robot would.

``VersionedBackend`` wraps a run's backend: a message written for the interface's own type (a
Twist dict) is sent as the type the robot wants (a TwistStamped with a header stamp and frame), so
profile commands, the safe stop and a teacher's limits are written once.
"""
import time
import weakref

from rockly_desktop.core.ros_distributions import DISTRIBUTIONS, VERSIONS
from rockly_desktop.robot.interface import RobotBackend
from rockly_desktop.robot.wrappers.wrapped_backend import WrappedBackend

FRAME_ID = "base_link"   # the frame a stamped velocity command is given in: the robot's own
ROS1, ROS2 = VERSIONS  # the version keys of a profile's ros_versions, and a link's ros_version
RECHECK_SECONDS = 0.5    # while the graph lists no type for a name, look again at most this often

# a stamped type -> (the type it stamps, its field holding that)
STAMPED = {
    "geometry_msgs/TwistStamped": ("geometry_msgs/Twist", "twist"),
    "geometry_msgs/AccelStamped": ("geometry_msgs/Accel", "accel"),
    "geometry_msgs/PoseStamped": ("geometry_msgs/Pose", "pose"),
    "geometry_msgs/PointStamped": ("geometry_msgs/Point", "point"),
    "geometry_msgs/Vector3Stamped": ("geometry_msgs/Vector3", "vector"),
    "geometry_msgs/WrenchStamped": ("geometry_msgs/Wrench", "wrench"),
}


def short_type(type_name: str) -> str:
    """``pkg/msg/Type`` as ``pkg/Type`` (the short form is how profiles write types)."""
    parts = str(type_name).split("/")
    return f"{parts[0]}/{parts[-1]}" if len(parts) == 3 else str(type_name)


def ros_name(name) -> str:
    """A ROS name with one leading slash."""
    return "/" + str(name).strip("/")


def declared_type(base: str, variants: dict, version: str, distribution: str = None) -> str:
    """The type ``variants`` declare for a robot on ``version`` ('ros1', 'ros2'; None: either) and ``distribution``.

    A distribution key counts from that distribution on (``jazzy`` also for kilted); one newer
    than Rockly knows counts as the newest. Without a matching key: ``ros2`` for ROS 2, ``ros1``
    for ROS 1, else ``base`` (the ros_interface type). A simulator with a distribution is ROS 2.
    """
    if version == ROS1:
        return variants.get(ROS1, base)
    if distribution:
        known = DISTRIBUTIONS.index(distribution) if distribution in DISTRIBUTIONS else len(DISTRIBUTIONS) - 1
        for key in reversed(DISTRIBUTIONS[:known + 1]):
            if key in variants:
                return variants[key]
        return variants.get(ROS2, base)
    return variants.get(ROS2, base) if version == ROS2 else base


def robot_type(base: str, variants: dict, version: str, distribution: str = None, graph_types=None) -> str:
    """The type the robot wants for a name: what its graph lists (``graph_types``; None: no graph),
    a declared type other than ``base`` first; without any listed, ``declared_type``."""
    listed = {short_type(type_name) for type_name in graph_types or ()}
    candidates = [type_name for type_name in dict.fromkeys([*variants.values(), base]) if type_name in listed]
    if candidates:
        return candidates[0]
    return declared_type(base, variants, version, distribution)


def base_types(ros_interface: dict) -> dict:
    """{ROS name: type} of everything ``ros_interface`` declares (topics, services, actions)."""
    types = {}
    for part in ("subscribes", "publishes", "services", "actions"):
        types.update({ros_name(name): type_name for name, type_name in (ros_interface.get(part) or {}).items()})
    return types


def converted(message, from_type: str, to_type: str):
    """``message`` (a dict of ``from_type``) as ``to_type``: a plain message wrapped into its stamped
    type (header stamped now, frame FRAME_ID) or a stamped one unwrapped; unchanged otherwise."""
    from_type, to_type = short_type(from_type), short_type(to_type)
    if from_type == to_type or not isinstance(message, dict):
        return message
    if STAMPED.get(to_type, (None,))[0] == from_type:
        now = time.time()
        stamp = {"secs": int(now), "nsecs": int((now % 1) * 1e9)}
        return {"header": {"stamp": stamp, "frame_id": FRAME_ID}, STAMPED[to_type][1]: message}
    if STAMPED.get(from_type, (None,))[0] == to_type:
        return dict(message.get(STAMPED[from_type][1]) or {})
    return message


def stamped_part(message, msg_type: str):
    """The part of a stamped message the stamp is on (a TwistStamped's ``twist``), else the message."""
    field = STAMPED.get(short_type(msg_type), (None, None))[1]
    return message.get(field) if field and isinstance(message, dict) else message


class LearntTypes:
    """What a robot's graph said about the types it wants, shared by the backends of one link."""

    def __init__(self):
        self.resolved = {}   # ROS name -> (type, whether that is final)
        self.checked = {}    # ROS name -> when the graph was last asked


class VersionedBackend(WrappedBackend):
    """A RobotBackend sending each message as the type the robot wants (see the module's docstring).

    ``versions`` is the profile's ``ros_versions`` and ``ros_interface`` its interface;
    ``ros_version`` the link's (``RobotLink.ros_version``: 'ros1', 'ros2'; None: either, a simulator), its
    graph the inner backend's ``topic_types(name)`` where it has one; ``distribution`` the
    robot's declared ROS 2 distribution (None: not declared). ``learnt`` keeps what the graph
    said (a link's, shared by its runs and its safe stop); ``recheck`` False uses a type learnt
    before as it is, asking the graph only for a name never asked about (the safe stop: its zero
    velocity must not wait for a graph query).
    """

    def __init__(self, inner: RobotBackend, versions: dict, ros_interface: dict, distribution: str = None,
                 learnt: LearntTypes = None, recheck: bool = True, ros_version: str = None):
        super().__init__(inner)
        self._variants = {ros_name(name): dict(entry) for name, entry in (versions or {}).items()}
        self._base = base_types(ros_interface or {})
        self.ros_version = ros_version
        self.distribution = distribution
        learnt = learnt or LearntTypes()
        self._resolved, self._checked = learnt.resolved, learnt.checked
        self._recheck = recheck

    def type_for(self, name: str, msg_type: str = None) -> str:
        """The type the robot wants on ``name`` (``msg_type``, or the interface's, where nothing differs)."""
        key = ros_name(name)
        if key not in self._variants:
            return msg_type or self._base.get(key)
        known = self._resolved.get(key)
        if known is not None and (known[1] or not self._recheck
                                  or time.monotonic() - self._checked.get(key, 0) < RECHECK_SECONDS):
            return known[0]
        graph = getattr(self._inner, "topic_types", None)
        listed = graph(key) if graph is not None else None
        self._checked[key] = time.monotonic()
        base = self._base.get(key, msg_type)
        wanted = robot_type(base, self._variants[key], self.ros_version, self.distribution, listed)
        # a varied type the graph lists is the robot's; the usual one may be Rockly's own publisher
        # (or the robot not discovered yet), so it is looked at again
        self._resolved[key] = (wanted, bool(listed) and wanted != base)
        return wanted

    def interface(self) -> dict:
        """{ROS name: type} of the profile's interface as this robot wants it."""
        return {**self._base, **{name: self.type_for(name) for name in self._variants}}

    def publish(self, topic: str, msg_type: str, message: dict) -> None:
        """Publish ``message`` as the type the robot wants on ``topic`` (converted where it can be)."""
        wanted = self.type_for(topic, msg_type)
        if wanted and short_type(wanted) != short_type(msg_type):
            changed = converted(message, msg_type, wanted)
            if changed is not message:  # a type it cannot be converted to is left to the robot to refuse
                message, msg_type = changed, wanted
        self._inner.publish(topic, msg_type, message)

    def call_service(self, name: str, srv_type: str, request: dict, timeout: float) -> dict:
        """Call a service with the type the robot has for it."""
        return self._inner.call_service(name, self.type_for(name, srv_type), request, timeout)

    def send_goal(self, action: str, action_type: str, goal: dict, feedback=None):
        """Send an action goal with the type the robot has for it."""
        return self._inner.send_goal(action, self.type_for(action, action_type), goal, feedback)


_LEARNT = weakref.WeakKeyDictionary()  # link -> LearntTypes


def link_backend(link, interrupt, stopping: bool = False):
    """``link.backend(interrupt)`` sending what its profile declares per ROS version as its robot wants it
    (on ``link.ros_version``; ``link.ros_distribution``, where a link has one, is the robot's
    declared ROS 2 distribution). The link's backends share what its graph said; ``stopping`` (the safe stop)
    uses that as it is."""
    learnt = _LEARNT.setdefault(link, LearntTypes())
    return versioned_backend(link.profile, link.backend(interrupt), getattr(link, "ros_distribution", None),
                             learnt, recheck=not stopping, ros_version=link.ros_version)


def versioned_backend(profile, backend, distribution: str = None, learnt: LearntTypes = None,
                      recheck: bool = True, ros_version: str = None):
    """``backend`` sending what ``profile`` declares per ROS version as the robot on ``ros_version`` wants it (see
    VersionedBackend); ``backend`` itself when the profile declares nothing per version (or it is
    versioned already)."""
    versions = getattr(profile, "ros_versions", None)  # a stand-in profile (tests, tools) may have none
    if not versions or isinstance(backend, VersionedBackend):
        return backend
    return VersionedBackend(backend, versions, profile.ros_interface, distribution, learnt, recheck, ros_version)
