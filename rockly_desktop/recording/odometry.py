"""The robot's recorded path from its odometry (``/odom``): what a real robot's replay draws in plan.

A recording of a real robot has no simulator snapshots; its ``nav_msgs/Odometry`` messages say
where the robot was. ``RecordedPath`` holds their poses (x, y in metres, heading in radians)
and gives the path up to a moment, the pose then, and the bounds of the whole run (so the
plan's scale stays put while the scrubber moves).
"""
import bisect
import math

from rockly_desktop.core.state_store import field_value
from rockly_desktop.recording.topics import RecordedTopics

ODOMETRY = "/odom"


def pose_of(message) -> tuple:
    """(x, y, heading) of an Odometry message dict, or None when it has no pose."""
    try:
        x = float(field_value(message, "pose.pose.position.x"))
        y = float(field_value(message, "pose.pose.position.y"))
        q = {axis: float(field_value(message, f"pose.pose.orientation.{axis}")) for axis in "xyzw"}
    except (KeyError, TypeError, ValueError):
        return None
    heading = math.atan2(2 * (q["w"] * q["z"] + q["x"] * q["y"]), 1 - 2 * (q["y"] ** 2 + q["z"] ** 2))
    return x, y, heading


class RecordedPath:
    """The poses on ``topic`` (``/odom``) of ``topics`` (a ``RecordedTopics``), in time order."""

    def __init__(self, topics: RecordedTopics, topic: str = ODOMETRY):
        self.times, self.poses = [], []
        for stamp, message in zip(topics.times(topic), topics.messages(topic)):
            pose = pose_of(message) if message is not None else None
            if pose is not None:
                self.times.append(stamp)
                self.poses.append(pose)

    def __bool__(self):
        return bool(self.poses)

    def until(self, seconds: float) -> list:
        """The poses up to ``seconds`` (the last one is where the robot was then)."""
        return self.poses[:bisect.bisect_right(self.times, seconds)]

    def bounds(self) -> tuple:
        """(min x, min y, max x, max y) of the whole path."""
        xs = [pose[0] for pose in self.poses]
        ys = [pose[1] for pose in self.poses]
        return min(xs), min(ys), max(xs), max(ys)
