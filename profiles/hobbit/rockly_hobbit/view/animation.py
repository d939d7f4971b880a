"""Easing: the drawn values a snapshot asks for, and the values shown now gliding toward them.

Everything the map draws from (pose, arm, gripper, turntable, head, visible area) is a float
here, so one easing step serves them all; angles take the short way round.
"""
import math

from .geometry import ARM_POSES, ROOM, WALL, head_look
from .snapshot import num, point

EASE_SECONDS = 0.07      # time constant of the easing toward the latest snapshot
SLOW_EASE = {            # things that would look abrupt if they followed as quickly
    "grip": 0.12, "tt_out": 0.3, "pan": 0.15, "look_len": 0.15, "look_alpha": 0.15, "look_width": 0.15,
    "tilt": 0.15, "bx0": 0.3, "by0": 0.3, "bx1": 0.3, "by1": 0.3,
}
TELEPORT_METRES = 2.0    # farther jumps are drawn at once, not glided
FRAME_MS = 16            # while something moves
AMBIENT_MS = 66          # blinking, floating z, pulsing hints

ANGLE_KEYS = {"theta", "pan"}
DEGREE_KEYS = {"tt_angle"}


def wrap_pi(angle):
    return (angle + math.pi) % (2 * math.pi) - math.pi


def _wrap_180(degrees):
    return (degrees + 180.0) % 360.0 - 180.0


def lerp(a, b, t):
    return a + (b - a) * t


def _smooth(t):
    return t * t * (3 - 2 * t)


def _arm_pose(snapshot):
    """(elbow, tip, up, height) of the arm, between two poses while it moves."""
    pose = ARM_POSES.get(snapshot.get("arm"), ARM_POSES["home"])
    goal = ARM_POSES.get(snapshot.get("arm_target"))
    if goal is None or goal is pose:
        return pose
    k = _smooth(num(snapshot.get("arm_progress"), 0.0, 0.0, 1.0))
    return ((lerp(pose[0][0], goal[0][0], k), lerp(pose[0][1], goal[0][1], k)),
            (lerp(pose[1][0], goal[1][0], k), lerp(pose[1][1], goal[1][1], k)),
            lerp(pose[2], goal[2], k), lerp(pose[3], goal[3], k))


def targets(snapshot):
    """The drawn quantities a snapshot asks for, as floats the view can ease toward."""
    get = snapshot.get
    values = {"x": num(get("x")), "y": num(get("y")), "theta": num(get("theta"))}
    pose = _arm_pose(snapshot)
    (values["ex"], values["ey"]), (values["tx"], values["ty"]), values["up"], values["height"] = pose
    values["grip"] = 1.0 if get("gripper") == "open" else 0.0
    values["tt_out"] = 1.0 if get("turntable") == "out" else 0.0
    values["tt_angle"] = num(get("turntable_angle"))
    look = head_look(get("head"), pose[1])
    pan, values["look_len"], values["look_alpha"], values["look_width"], values["tilt"] = look
    values["pan"] = math.radians(pan)
    # visible area: the room with its walls, grown to keep the robot and its goal in sight
    margin = WALL + 0.3
    x0, y0, x1, y1 = ROOM[0] - margin, ROOM[1] - margin, ROOM[2] + margin, ROOM[3] + margin
    for spot in ((values["x"], values["y"]), point(get("nav_goal"))):
        if spot is not None:
            x0, y0 = min(x0, spot[0] - 0.8), min(y0, spot[1] - 0.8)
            x1, y1 = max(x1, spot[0] + 0.8), max(y1, spot[1] + 0.8)
    values.update(bx0=x0, by0=y0, bx1=x1, by1=y1)
    return values


class Easing:
    """The values drawn now (``shown``) and those the latest snapshot asks for (``target``)."""

    def __init__(self, snapshot):
        self.target = targets(snapshot)
        self.shown = dict(self.target)
        self.settled = True

    def aim(self, snapshot):
        """Head for ``snapshot``'s values; return how far (metres) the drawn robot is from its new place."""
        self.target = targets(snapshot)
        return math.hypot(self.target["x"] - self.shown["x"], self.target["y"] - self.shown["y"])

    def arrive(self):
        """Show the target at once."""
        self.shown = dict(self.target)

    def moving(self, keys):
        return any(self.shown[key] != self.target[key] for key in keys)

    def step(self, dt):
        """Move the shown values ``dt`` seconds' worth toward the targets; True (and settled) when all arrived."""
        settled = True
        for key, target in self.target.items():
            k = 1.0 - math.exp(-dt / SLOW_EASE.get(key, EASE_SECONDS))
            shown = self.shown.get(key, target)
            if key in ANGLE_KEYS:
                diff, eps = wrap_pi(target - shown), 1e-3
            elif key in DEGREE_KEYS:
                diff, eps = _wrap_180(target - shown), 0.05
            else:
                diff, eps = target - shown, 1e-3
            if abs(diff) <= eps:
                self.shown[key] = target
            else:
                self.shown[key] = shown + diff * k
                settled = False
        self.settled = settled
        return settled
