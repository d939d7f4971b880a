"""Every ROS name a part of a robot is reached by, for a teacher's limits to refuse them all.

A manifest names an action (``arm``); a program can still reach its server by the action's
own topics and services: on ROS 1 by publishing its ``...ActionGoal`` on ``arm/goal``, on
ROS 2 by calling ``arm/_action/send_goal``. ``Coverage`` answers
for each ROS name which covered part it reaches, the action's topics and services included.
Cancelling is left out (``ACTION/cancel``, ``ACTION/_action/cancel_goal``): it only ever stops a
part, and a teacher's limits never keep a robot from stopping.
"""
from dataclasses import dataclass

# The names actionlib (ROS 1) and ROS 2 actions put under an action's name, cancelling left out.
ACTION_TOPICS = ("goal", "status", "feedback", "result", "_action/feedback", "_action/status")
ACTION_SERVICES = ("_action/send_goal", "_action/get_result")


@dataclass(frozen=True)
class Covered:
    """A part of a robot and the ROS names its manifest says it uses."""

    label: object
    topics: frozenset = frozenset()
    services: frozenset = frozenset()
    actions: frozenset = frozenset()


class Coverage:
    """Which ``Covered`` part (its ``label``) a topic, service or action name reaches.

    ``normalise(name, kind)`` makes the parts' names comparable (the limits' resolution of a ROS
    name as the robot's middleware resolves it); ``reached_by`` is asked with a name resolved alike.
    """

    def __init__(self, parts, normalise):
        self._names = {}  # (kind, name) -> label
        for part in parts:
            for kind in ("topics", "services", "actions"):
                for name in getattr(part, kind):
                    self._names[(kind, normalise(name, kind))] = part.label
            for action in part.actions:
                base = normalise(action, "actions")
                for topic in ACTION_TOPICS:
                    self._names[("topics", normalise(f"{base}/{topic}", "topics"))] = part.label
                for service in ACTION_SERVICES:
                    self._names[("services", normalise(f"{base}/{service}", "services"))] = part.label

    def __bool__(self):
        return bool(self._names)

    def reached_by(self, kind: str, resolved: str):
        """The label of the part the ``resolved`` name reaches as a ``kind`` ('topics', 'services',
        'actions'), or None."""
        return self._names.get((kind, resolved))
