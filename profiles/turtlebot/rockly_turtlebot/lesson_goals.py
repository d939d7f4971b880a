"""What lessons can ask of the TurtleBot beyond the generic goals: following a wall with its laser.

Named in profile.yaml's ``lesson_goals``.
"""
import math

from rockly_desktop.sdk import LessonField, LessonGoal, Verdict, nearest_in_scan, profile_texts

TEXTS = profile_texts(__file__)
SIDES = {"left": math.pi / 2, "right": -math.pi / 2}


class FollowsWall(LessonGoal):
    """Counts the metres driven while the laser sees something beside the robot, nearer than ``gap``."""

    kind = "follows_wall"
    fields = (LessonField("side", "choice", True, "Which side the wall is on.", tuple(SIDES)),
              LessonField("metres", "positive", True, "How far the robot must drive along it."),
              LessonField("gap", "positive", False,
                          "The most metres from the robot's centre to the wall (default 0.4)."))
    meaning = "The robot drives `metres` with a wall on that side, never farther than `gap` from it."

    def __init__(self, spec, context):
        super().__init__(spec, context)
        self.along = 0.0
        self._last = None

    def see(self, moment):
        snapshot = moment.snapshot
        here = (moment.x, moment.y)
        scan = {"ranges": snapshot.get("scan") or [], "angle_min": 0.0,
                "angle_increment": 2 * math.pi / max(1, len(snapshot.get("scan") or [])),
                "range_min": snapshot.get("range_min", 0.0), "range_max": snapshot.get("range_max", math.inf)}
        try:
            beside = nearest_in_scan(scan, SIDES[self.spec["side"]])
        except (KeyError, TypeError, ValueError):
            beside = math.inf
        if self._last is not None and beside <= float(self.spec.get("gap", 0.4)):
            self.along += math.dist(self._last, here)
            if self.along >= float(self.spec["metres"]):
                self.met(moment)
        self._last = here

    def verdict(self, end):
        passed = self.met_at is not None
        key = "lesson_follows_wall_passed" if passed else "lesson_follows_wall_failed"
        return Verdict(passed, TEXTS(key, along=self.along, metres=float(self.spec["metres"])))


GOALS = [FollowsWall]
