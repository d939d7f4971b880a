"""What a robot backend offers: ROS-shaped topics, services and actions, by ROS names.

Messages are plain dicts shaped like the ROS message (``{"linear": {"x": 0.2}}`` for a
``geometry_msgs/Twist``); missing fields take the message type's defaults. The
simulator and the ROS 1 backend implement the same interface, so a profile's commands
run unchanged on both.
"""
from abc import ABC, abstractmethod
from dataclasses import dataclass, field
from enum import Enum


class GoalStatus(Enum):
    """How an action goal ended (actionlib's terminal states, simplified)."""

    SUCCEEDED = "succeeded"
    ABORTED = "aborted"
    PREEMPTED = "preempted"
    REJECTED = "rejected"


@dataclass(frozen=True)
class GoalOutcome:
    """The end of an action goal: its status, the result message and the server's reason (actionlib's status text)."""

    status: GoalStatus
    result: dict = field(default_factory=dict)
    text: str = ""


class GoalHandle(ABC):
    """A goal that was sent to an action server."""

    @abstractmethod
    def done(self) -> bool:
        """True once the goal has ended (its outcome is known); does not wait."""

    @abstractmethod
    def wait(self, timeout: float) -> GoalOutcome:
        """Wait (interruptibly) for the goal to end; raise RobotTimeout after ``timeout`` s."""

    @abstractmethod
    def cancel(self) -> None:
        """Ask the action server to stop working on this goal."""


class RobotBackend(ABC):
    """The robot as a program sees it. Every wait is interruptible by a stop request.

    ``interrupt`` is the Interrupt its waits watch (set by implementations); a command in
    the middle of a motion asks ``pause_requested()`` and, after halting, ``hold()``.
    """

    interrupt = None

    def pause_requested(self) -> bool:
        """True when the person pressed Pause: a long motion should halt now."""
        return bool(self.interrupt is not None and self.interrupt.pause_requested)

    def hold(self) -> None:
        """Wait, after halting a motion for a pause, until the program may go on (stop raises)."""
        if self.interrupt is not None:
            self.interrupt.hold()

    def resolve_name(self, name: str, kind: str = "topics") -> str:
        """The topic, service or action (``kind``: 'topics', 'services', 'actions') a command given
        ``name`` reaches, as this backend's middleware resolves it; RobotCommandError for a name it
        would refuse. A backend on a ROS middleware asks it (substitutions, ``~``, namespace, remappings).

        This default suits a robot whose names are matched exactly, as the simulator's world does:
        a command reaches ``/cmd_vel`` only by that very name, so the name with one leading slash
        (``cmd_vel/`` is ``/cmd_vel`` too) names at least everything it can reach.
        """
        return "/" + str(name).strip("/")

    def watch(self, waited: float) -> None:
        """Raise (RobotConnectionLost) when the robot cannot serve a wait that has lasted ``waited`` seconds: its
        master or helper is gone, or a node it listens to. A wait made elsewhere (the program's own process, whose
        waits are its own) asks this now and then; this backend's own waits watch the same by themselves. A robot
        in this process (the simulator) has nothing to lose."""
        return None

    @abstractmethod
    def publish(self, topic: str, msg_type: str, message: dict) -> None:
        """Publish ``message`` (a dict shaped like ``msg_type``) on ``topic``."""

    @abstractmethod
    def subscribe(self, topic: str, msg_type: str, callback):
        """Call ``callback(message dict)`` for every message on ``topic``; returns a function that unsubscribes."""

    @abstractmethod
    def wait_until(self, predicate, timeout: float) -> bool:
        """Wait until ``predicate()`` is true (True) or ``timeout`` passes (False); a stop raises."""

    @abstractmethod
    def latest(self, topic: str, msg_type: str):
        """The last message seen on ``topic`` as a dict, or None if none arrived yet."""

    @abstractmethod
    def wait_for_message(self, topic: str, msg_type: str, timeout: float) -> dict:
        """Wait for the next message on ``topic``; raise RobotTimeout after ``timeout`` s."""

    @abstractmethod
    def call_service(self, name: str, srv_type: str, request: dict, timeout: float) -> dict:
        """Call a service and return its response as a dict; raise RobotTimeout or RobotCommandError."""

    @abstractmethod
    def send_goal(self, action: str, action_type: str, goal: dict, feedback=None) -> GoalHandle:
        """Send a goal to an action server; ``feedback(dict)`` is called for each feedback."""

    @abstractmethod
    def cancel_all_goals(self, action: str) -> None:
        """Cancel every active goal on the action server ``action``, whoever sent it (actionlib's cancel_all_goals)."""

    @abstractmethod
    def get_param(self, name: str, default=None):
        """A ROS parameter's value, or ``default`` when it is not set."""

    @abstractmethod
    def set_param(self, name: str, value) -> None:
        """Set a ROS parameter."""

    @abstractmethod
    def sleep(self, seconds: float) -> None:
        """Wait ``seconds``; returns early only by raising when the program is stopped."""
