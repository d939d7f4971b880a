"""HOBBIT and its room in metres: the room's walls, the robot's parts, its arm poses and where its head looks.

Map frame: x to the right, y up, theta counter-clockwise from +x.
Robot frame: x forward, y to the robot's left.
"""
import math

from ..world import WORLD

ROOM = WORLD.area              # x0, y0, x1, y1 of the room's inside
WALL = 0.14
DOOR = (2.3, 3.2)              # gap in the bottom wall, x from..to (drawn: the door swung open)
WINDOW = (2.7, 4.5)            # glass in the top wall, x from..to

BASE_RADIUS = WORLD.radius
HEAD_CENTER = (0.03, 0.0)
HEAD_RADIUS = 0.11
SHOULDER = (0.03, -0.19)
TURNTABLE = (0.40, 0.0)
TURNTABLE_RADIUS = 0.12

# Arm poses seen from above, in the robot frame:
# elbow, tip, how straight up the arm points (0..1), height of the tip over the floor (0..1).
ARM_POSES = {
    "home": ((-0.13, -0.23), (0.06, -0.24), 0.0, 0.5),
    "candle": ((0.04, -0.21), (0.05, -0.21), 1.0, 1.0),
    "floor": ((0.25, -0.29), (0.57, -0.31), 0.0, 0.0),
    "table": ((0.24, -0.25), (0.54, -0.17), 0.0, 0.8),
    "tray": ((0.07, -0.15), (-0.15, -0.05), 0.0, 0.6),
    "learning": ((0.22, -0.22), (0.35, -0.08), 0.0, 0.5),
    "joints": ((0.17, -0.34), (0.34, -0.44), 0.0, 0.5),
}

# Head positions: pan (degrees, + = robot's left), view length (m), cone opacity,
# cone half-width (degrees), tilt (-1 up .. +1 down; used by the eyes' gaze).
HEAD_LOOKS = {
    "center_center": (0.0, 1.8, 0.42, 22.0, 0.0),
    "up_center": (0.0, 2.8, 0.22, 20.0, -1.0),
    "down_center": (0.0, 0.85, 0.60, 27.0, 1.0),
    "center_right": (-50.0, 1.8, 0.42, 22.0, 0.0),
    "center_left": (50.0, 1.8, 0.42, 22.0, 0.0),
    "up_right": (-50.0, 2.8, 0.22, 20.0, -1.0),
    "up_left": (50.0, 2.8, 0.22, 20.0, -1.0),
    "down_right": (-50.0, 0.85, 0.60, 27.0, 1.0),
    "down_left": (50.0, 0.85, 0.60, 27.0, 1.0),
    "littledown_center": (0.0, 1.3, 0.50, 24.0, 0.5),
    "search_table": (0.0, 1.5, 0.38, 38.0, 0.6),
    # to_grasp and to_turntable point at the gripper and the turntable (see head_look)
}


def head_look(head, tip):
    """(pan degrees, length, opacity, half-width degrees, tilt) for a head position name; ``tip`` is the arm's."""
    hx, hy = HEAD_CENTER
    if head == "to_grasp":
        dx, dy = tip[0] - hx, tip[1] - hy
        return math.degrees(math.atan2(dy, dx)), math.hypot(dx, dy) + 0.18, 0.6, 18.0, 1.0
    if head == "to_turntable":
        dx, dy = TURNTABLE[0] - hx, TURNTABLE[1] - hy
        return math.degrees(math.atan2(dy, dx)), math.hypot(dx, dy) + 0.2, 0.6, 24.0, 1.0
    return HEAD_LOOKS.get(head, HEAD_LOOKS["center_center"])
