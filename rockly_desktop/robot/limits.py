"""A teacher's limits, enforced on the backend every command of a run goes through.

``LimitedBackend`` wraps the run's RobotBackend: velocity commands on the topics a
profile declares as its drive interface (``geometry_msgs/Twist`` or ``TwistStamped``) are clamped to the
maximum speeds (anything else there under a speed limit, another type or a speed that is no
number, is refused: ``robot/velocity_messages.py``), and topics, services and actions of a
switched-off capability are refused with a RobotCommandError, an action's own topics and services
included (``robot/capability_coverage.py``). Profiles need no code for it: the names come from
their manifest. Reading (subscribe, latest, waits) and cancelling always pass. A motion at
the robot's own speed (a base driver's "drive 0.5 m", a navigation goal) is no velocity the
wrapper can clamp: the manifest lists those names (``own_speed``, ``robot/own_speed.py``) and they
are refused under a lower limit; the profile asks ``allowed_speed`` (through
``RobotCommands.allowed_speed``) and drives such motions with velocity commands instead.
"""
import math
from dataclasses import dataclass

from rockly_desktop.core.app_texts import app_local_text, app_text
from rockly_desktop.core.errors import RobotCommandError
from rockly_desktop.robot.capability_coverage import Coverage, Covered
from rockly_desktop.robot.interface import RobotBackend
from rockly_desktop.robot.own_speed import OwnSpeed
from rockly_desktop.robot.velocity_messages import velocity_problem
from rockly_desktop.robot.wrapped_backend import WrappedBackend


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
        self._velocity_topics = {_ros_name(topic) for topic in velocity_topics}
        self._blocked = Coverage([Covered(capability.name, capability.topics, capability.services, capability.actions)
                                  for capability in capabilities], _ros_name)
        own_speed = own_speed or OwnSpeed()
        self._own_speed = Coverage([own_speed.covered(True)] if own_speed.too_fast_for(limits) else [], _ros_name)
        self._stops = [(_ros_name(topic), message) for topic, message in own_speed.stops]
        self._language = language
        self.note = note
        self._noted = set()

    def _refuse(self, kind: str, name: str, message=None):
        capability = self._blocked.reached_by(kind, name)
        if capability is not None:
            raise RobotCommandError(app_local_text("limit_switched_off", name=capability))
        if self._own_speed.reached_by(kind, name) and (_ros_name(name), message) not in self._stops:
            raise RobotCommandError(app_local_text("limit_own_speed", name=str(name)))

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

    def publish(self, topic: str, msg_type: str, message: dict) -> None:
        """Publish, refused for a switched-off capability, velocities clamped on drive topics (where,
        under a speed limit, anything but a Twist or TwistStamped of numbers is refused)."""
        self._refuse("topics", topic, message)
        if _ros_name(topic) in self._velocity_topics and self._speed_limited:
            problem = velocity_problem(msg_type, message)
            if problem is not None:
                key, values = problem
                raise RobotCommandError(app_local_text(key, topic=str(topic), **values))
            message = self._clamped(message)
        self._inner.publish(topic, msg_type, message)

    def call_service(self, name: str, srv_type: str, request: dict, timeout: float) -> dict:
        """Call a service, refused for a switched-off capability."""
        self._refuse("services", name)
        return self._inner.call_service(name, srv_type, request, timeout)

    def send_goal(self, action: str, action_type: str, goal: dict, feedback=None):
        """Send an action goal, refused for a switched-off capability."""
        self._refuse("actions", action)
        return self._inner.send_goal(action, action_type, goal, feedback)

