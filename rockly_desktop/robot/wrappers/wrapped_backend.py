"""A RobotBackend around another, for what changes a run's commands on their way (a teacher's
limits, the robot's ROS version, a recording): every call passes through unless a subclass
changes it, and so do a backend's own extras (``connect_publisher``, ``allowed_speed``...)."""
from rockly_desktop.robot.interface import RobotBackend


class WrappedBackend(RobotBackend):
    """Passes every call to ``inner``; a subclass overrides only what it changes."""

    def __init__(self, inner: RobotBackend):
        self._inner = inner
        self.interrupt = inner.interrupt

    def __getattr__(self, name):
        if name == "_inner":  # not set yet (a copy being made): no endless lookup
            raise AttributeError(name)
        return getattr(self._inner, name)

    def resolve_name(self, name: str, kind: str = "topics") -> str:
        """``name`` as the inner backend's middleware resolves it."""
        return self._inner.resolve_name(name, kind)

    def watch(self, waited: float) -> None:
        """Raise when the inner backend's robot cannot serve a wait that has lasted ``waited`` s."""
        self._inner.watch(waited)

    def publish(self, topic: str, msg_type: str, message: dict) -> None:
        """Publish on ``topic``."""
        self._inner.publish(topic, msg_type, message)

    def subscribe(self, topic: str, msg_type: str, callback):
        """Subscribe to ``topic``; returns the unsubscribe function."""
        return self._inner.subscribe(topic, msg_type, callback)

    def wait_until(self, predicate, timeout: float) -> bool:
        """Wait until ``predicate()`` is true or ``timeout`` passes."""
        return self._inner.wait_until(predicate, timeout)

    def latest(self, topic: str, msg_type: str):
        """The last message on ``topic``."""
        return self._inner.latest(topic, msg_type)

    def wait_for_message(self, topic: str, msg_type: str, timeout: float) -> dict:
        """Wait for the next message on ``topic``."""
        return self._inner.wait_for_message(topic, msg_type, timeout)

    def call_service(self, name: str, srv_type: str, request: dict, timeout: float) -> dict:
        """Call a service."""
        return self._inner.call_service(name, srv_type, request, timeout)

    def send_goal(self, action: str, action_type: str, goal: dict, feedback=None):
        """Send an action goal."""
        return self._inner.send_goal(action, action_type, goal, feedback)

    def cancel_all_goals(self, action: str) -> None:
        """Cancel every goal of ``action``."""
        self._inner.cancel_all_goals(action)

    def get_param(self, name: str, default=None):
        """A parameter, or ``default``."""
        return self._inner.get_param(name, default)

    def set_param(self, name: str, value) -> None:
        """Set a parameter."""
        self._inner.set_param(name, value)

    def sleep(self, seconds: float) -> None:
        """Wait ``seconds`` (pausable, stoppable)."""
        self._inner.sleep(seconds)
