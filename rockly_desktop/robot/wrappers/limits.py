"""A teacher's limits, enforced on the backend every command of a run goes through.

``LimitedBackend`` wraps the run's RobotBackend: velocity commands on the topics a
profile declares as its drive interface (``geometry_msgs/Twist`` or ``TwistStamped``) are clamped to the
maximum speeds (anything else there under a speed limit, another type or a speed that is no
number, is refused: ``robot/wrappers/velocity_messages.py``), and topics, services and actions of a
switched-off capability are refused with a RobotCommandError, an action's own topics and services
included (``robot/wrappers/capability_coverage.py``). Profiles need no code for it: the names come from
their manifest. Names are compared as the robot's middleware resolves them (the backend's
``resolve_name``: ``{ns}cmd_vel``, ``~/...``, a namespace or a remapping may all reach
``/cmd_vel``), the program's and the manifest's alike; a name the middleware refuses is
refused here too. While a speed is limited, a Twist is held to the limit on whatever topic it
goes (a drive topic remapped where the manifest cannot know). Reading (subscribe, latest,
waits) and cancelling always pass. A motion at the robot's own speed (a base driver's "drive
0.5 m", a navigation goal) is no velocity the wrapper can clamp: the manifest lists those names
(``own_speed``, ``robot/wrappers/own_speed.py``) and they are refused under a lower limit; the profile
asks ``allowed_speed`` (through ``RobotCommands.allowed_speed``) and drives such motions with
velocity commands instead.
"""
import math
from dataclasses import dataclass

from rockly_desktop.core.app_texts import app_local_text, app_text
from rockly_desktop.core.errors import RobotCommandError
from rockly_desktop.robot.interface import RobotBackend
from rockly_desktop.robot.wrappers.capability_coverage import Coverage, Covered
from rockly_desktop.robot.wrappers.own_speed import OwnSpeed
from rockly_desktop.robot.wrappers.ros_versions import short_type
from rockly_desktop.robot.wrappers.velocity_messages import velocity_problem
from rockly_desktop.robot.wrappers.wrapped_backend import WrappedBackend

DRIVE_TYPES = frozenset({"geometry_msgs/Twist", "geometry_msgs/TwistStamped"})
MAX_NAMES = 4096  # resolved names a run keeps (a program may make names without end)


def _text(key: str, language: str, **values) -> str:
    return app_text(f"limit_{key}", language, **values)


@dataclass(frozen=True)
class Limits:
    """What a teacher allows: maximum speeds (None: no limit) and capabilities switched off.

    ``max_speed`` is in m/s, ``max_turn`` in degrees per second (as the teacher sets it).
    """

    max_speed: float = None
    max_turn: float = None
    switched_off: frozenset = frozenset()

    @property
    def is_open(self) -> bool:
        """True when nothing is limited."""
        return self.max_speed is None and self.max_turn is None and not self.switched_off

    def stricter(self, other: "Limits") -> "Limits":
        """The limits that hold both these and ``other``: the lower speeds, every capability either switches off."""
        def lower(mine, theirs):
            return theirs if mine is None else mine if theirs is None else min(mine, theirs)
        return Limits(lower(self.max_speed, other.max_speed), lower(self.max_turn, other.max_turn),
                      frozenset(self.switched_off | other.switched_off))


def limits_text(limits: Limits, capability_names, language: str = "en"):
    """One line saying which of ``limits`` apply (``capability_names``: the switched-off ones'
    names for people), in ``language``; None when nothing is limited."""
    parts = []
    if limits.max_speed is not None:
        parts.append(_text("limit_speed", language, speed=limits.max_speed))
    if limits.max_turn is not None:
        parts.append(_text("limit_turn", language, turn=limits.max_turn))
    if capability_names:
        parts.append(_text("limit_off", language, names=", ".join(capability_names)))
    return _text("limits_apply", language, limits="; ".join(parts)) if parts else None


@dataclass(frozen=True)
class Capability:
    """A part of a robot a teacher can switch off: its name for people and the ROS names it uses."""

    id: str
    name: str
    topics: frozenset = frozenset()
    services: frozenset = frozenset()
    actions: frozenset = frozenset()


def _ros_name(name) -> str:
    return "/" + str(name).strip("/")


def _clamp_vector(vector, limit: float):
    """``vector`` (a dict with x, y, z) with each part clamped to ±limit; and whether any was."""
    if not isinstance(vector, dict):
        return vector, False
    clamped, changed = dict(vector), False
    for axis in ("x", "y", "z"):
        value = vector.get(axis)
        if not isinstance(value, (int, float)) or isinstance(value, bool):
            continue
        if math.isnan(value):  # a NaN velocity is no velocity a teacher allowed
            clamped[axis], changed = 0.0, True
        elif abs(value) > limit:
            clamped[axis], changed = math.copysign(limit, value), True
    return clamped, changed


class LimitedBackend(WrappedBackend):
    """A RobotBackend that keeps a run within a teacher's ``Limits``.

    ``velocity_topics`` are the Twist (or TwistStamped) topics clamped; ``capabilities`` the switched-off
    ones. ``note(text)`` is told once per run when a speed was clamped. Errors and notes
    are in ``language``.
    """

    def __init__(self, inner: RobotBackend, limits: Limits, velocity_topics=(), capabilities=(),
                 language: str = "en", note=None, own_speed: OwnSpeed = None):
        super().__init__(inner)
        self._limits = limits
        self._declared_velocity_topics = tuple(velocity_topics)
        self._declared_capabilities = [Covered(capability.name, capability.topics, capability.services,
                                               capability.actions) for capability in capabilities]
        self._declared_own_speed = own_speed or OwnSpeed()
        # The manifest's names resolved, on first use (resolving may ask the robot's middleware):
        self._velocity_topics = self._blocked = self._own_speed = self._stops = None
        self._resolved = {}  # (kind, name) -> resolved name
        self._language = language
        self.note = note
        self._noted = set()

    def resolved(self, name, kind: str = "topics") -> str:
        """``name`` as the robot's middleware resolves it (the backend's ``resolve_name``, asked once per
        name): the topic, service or action a command given ``name`` reaches. RobotCommandError when
        the middleware would refuse the name: what cannot be resolved is not sent."""
        key = (kind, str(name))
        found = self._resolved.get(key)
        if found is None:
            if len(self._resolved) >= MAX_NAMES:
                self._resolved.clear()
            found = self._resolved[key] = self._inner.resolve_name(key[1], kind)
        return found

    def _declared(self, name, kind: str) -> str:
        """A manifest's name as the profile's commands reach it (as written where the middleware refuses it)."""
        try:
            return self.resolved(name, kind)
        except RobotCommandError:
            return _ros_name(name)

    def _resolve_declared(self):
        if self._blocked is None:
            own_speed = self._declared_own_speed
            self._velocity_topics = {self._declared(topic, "topics") for topic in self._declared_velocity_topics}
            self._blocked = Coverage(self._declared_capabilities, self._declared)
            self._own_speed = Coverage([own_speed.covered(True)] if own_speed.too_fast_for(self._limits) else [],
                                       self._declared)
            self._stops = [(self._declared(topic, "topics"), message) for topic, message in own_speed.stops]

    def _refuse(self, kind: str, name: str, message=None) -> str:
        """``name`` resolved; RobotCommandError when it is refused, belongs to a switched-off capability or
        starts a motion at the robot's own speed above the limit (the safe stop's ``message`` passes)."""
        resolved = self.resolved(name, kind)
        self._resolve_declared()
        capability = self._blocked.reached_by(kind, resolved)
        if capability is not None:
            raise RobotCommandError(app_local_text("limit_switched_off", name=capability))
        if self._own_speed.reached_by(kind, resolved) and (resolved, message) not in self._stops:
            raise RobotCommandError(app_local_text("limit_own_speed", name=str(name)))
        return resolved

    @property
    def _speed_limited(self) -> bool:
        return self._limits.max_speed is not None or self._limits.max_turn is not None

    def _tell_once(self, key: str, **values):
        if key not in self._noted and self.note is not None:
            self._noted.add(key)
            self.note(_text(key, self._language, **values))

    def _clamped(self, message: dict) -> dict:
        message = dict(message or {})
        if isinstance(message.get("twist"), dict):  # a TwistStamped: its twist is clamped
            message["twist"] = self._clamped(message["twist"])
            return message
        if self._limits.max_speed is not None:
            message["linear"], changed = _clamp_vector(message.get("linear", {}), self._limits.max_speed)
            if changed:
                self._tell_once("speed_clamped", speed=self._limits.max_speed)
        if self._limits.max_turn is not None:
            message["angular"], changed = _clamp_vector(message.get("angular", {}),
                                                        math.radians(self._limits.max_turn))
            if changed:
                self._tell_once("turn_clamped", turn=self._limits.max_turn)
        return message

    def allowed_speed(self, own_speed: float, turning: bool = False) -> float:
        """``own_speed`` (m/s; turning: rad/s), or the teacher's maximum when that is lower (said once).

        Profiles ask it through ``RobotCommands.allowed_speed``; a backend wrapping this one must
        pass it on (a ``WrappedBackend`` does), or its runs would drive at the robot's own speed.
        """
        if turning and self._limits.max_turn is not None and math.radians(self._limits.max_turn) < own_speed:
            self._tell_once("turn_clamped", turn=self._limits.max_turn)
            return math.radians(self._limits.max_turn)
        if not turning and self._limits.max_speed is not None and self._limits.max_speed < own_speed:
            self._tell_once("speed_clamped", speed=self._limits.max_speed)
            return self._limits.max_speed
        return own_speed

    def _limited(self, resolved: str, topic, msg_type, message):
        """``message`` held to a speed limit: on a drive topic only a Twist (or TwistStamped) of numbers
        passes, clamped; elsewhere a Twist is clamped too (wherever a drive topic was remapped to)."""
        if not self._speed_limited:
            return message
        if resolved in self._velocity_topics or short_type(msg_type) in DRIVE_TYPES:
            problem = velocity_problem(msg_type, message)
            if problem is not None:
                key, values = problem
                raise RobotCommandError(app_local_text(key, topic=str(topic), **values))
            return self._clamped(message)
        return message

    def publish(self, topic: str, msg_type: str, message: dict) -> None:
        """Publish, refused for a switched-off capability, velocities held to the limit on drive topics
        and, under a speed limit, every Twist on any topic (where anything but a Twist or TwistStamped
        of numbers is refused on a drive topic)."""
        if not self._limits.is_open:
            message = self._limited(self._refuse("topics", topic, message), topic, msg_type, message)
        self._inner.publish(topic, msg_type, message)

    def call_service(self, name: str, srv_type: str, request: dict, timeout: float) -> dict:
        """Call a service, refused for a switched-off capability."""
        if not self._limits.is_open:
            self._refuse("services", name)
        return self._inner.call_service(name, srv_type, request, timeout)

    def send_goal(self, action: str, action_type: str, goal: dict, feedback=None):
        """Send an action goal, refused for a switched-off capability."""
        if not self._limits.is_open:
            self._refuse("actions", action)
        return self._inner.send_goal(action, action_type, goal, feedback)

