"""Motions a robot makes at its own speed, which a teacher's speed limit cannot slow down.

A base driver may drive a distance (``Move 2``) at its own fixed speed, and move_base drives a
navigation goal at its planner's speed: no velocity in these messages can be clamped.
A manifest lists such names under ``own_speed`` with the speeds they go at; while a teacher's
limit is below those speeds they are refused (a profile's own commands then drive with velocity
commands, ``RobotCommands.allowed_speed``). The profile's safe-stop messages always pass.
"""
from dataclasses import dataclass

from rockly_desktop.robot.wrappers.capability_coverage import Covered


@dataclass(frozen=True)
class OwnSpeed:
    """What a manifest's ``own_speed`` says: ``speed`` (m/s) and ``turn`` (°/s) these motions go at
    (None: not said, so any limit is lower), the ROS names that start them, and the ``stops``:
    ``(topic, message)`` pairs of the safe stop, which only ever halt the robot."""

    speed: float = None
    turn: float = None
    topics: frozenset = frozenset()
    services: frozenset = frozenset()
    actions: frozenset = frozenset()
    stops: tuple = ()

    @classmethod
    def from_manifest(cls, own_speed: dict, safe_stop: list):
        """The ``own_speed`` entry of a manifest (None or {} for none) and its ``safe_stop`` list."""
        own_speed = own_speed or {}
        stops = tuple((step["publish"]["topic"], step["publish"].get("message") or {})
                      for step in safe_stop if isinstance(step, dict) and "publish" in step)
        return cls(own_speed.get("speed"), own_speed.get("turn"), frozenset(own_speed.get("topics", ())),
                   frozenset(own_speed.get("services", ())), frozenset(own_speed.get("actions", ())), stops)

    def covered(self, label) -> Covered:
        """These names as a part a ``Coverage`` knows by ``label``."""
        return Covered(label, self.topics, self.services, self.actions)

    def too_fast_for(self, limits) -> bool:
        """True when a teacher's ``limits`` (``max_speed`` m/s, ``max_turn`` °/s) are below these motions' speeds."""
        def lower(limit, own):
            return limit is not None and (own is None or limit < own)
        return lower(limits.max_speed, self.speed) or lower(limits.max_turn, self.turn)
