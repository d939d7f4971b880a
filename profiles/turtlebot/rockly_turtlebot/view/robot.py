"""The TurtleBot seen from above (a TurtleBot3 Burger: round plate, two wheels, the laser on top), its trail,
and a burst where it bumped into something.

Drawn in map metres; the robot frame has x forward, where the green arrow points.
"""
import math

from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QPen, QPolygonF

from rockly_desktop.sdk_view import cosmetic_pen, round_pen, with_alpha

from . import model
from .palette import (
    BUMP,
    BUMP_GLOW,
    FRONT,
    LIDAR,
    LIDAR_EDGE,
    LIDAR_WINDOW,
    PLATE,
    PLATE_EDGE,
    PLATE_RING,
    SHADOW,
    TRAIL,
    TREAD,
    WHEEL,
)

MIN_PX = 34          # the robot is drawn at least this wide (up to 1.8x its real size) on small maps
LIDAR_SPIN = 150.0   # degrees per simulated second, for the turret's window


def grow_for(scale, radius):
    """How much bigger than life the robot is drawn at ``scale`` pixels per metre."""
    return max(1.0, min(1.8, MIN_PX / (2 * radius * scale)))


def paint_trail(p, snapshot, u):
    """Where the robot drove: a line that fades from old to new."""
    points = model.trail(snapshot)
    if len(points) < 2:
        return
    pieces = 8
    size = math.ceil(len(points) / pieces)
    for k in range(pieces):
        part = points[max(0, k * size - 1):(k + 1) * size]
        if len(part) < 2:
            continue
        pen = cosmetic_pen(with_alpha(TRAIL, 0.15 + 0.55 * (k + 1) / pieces), max(1.5, 2.5 * u), round_caps=True)
        pen.setDashPattern([1.0, 1.6])
        p.setPen(pen)
        p.drawPolyline(QPolygonF([QPointF(x, y) for x, y in part]))


def paint_robot(p, snapshot, scan, scale):
    """The robot at the snapshot's pose; ``scan`` (a view.scan.Scan) says where a bump touches."""
    x, y, theta = model.pose(snapshot)
    radius = model.num(snapshot.get("radius"), model.RADIUS, 0.02, 1.0)
    grow = grow_for(scale, radius)
    r = radius * grow
    line = 1.3 / scale
    p.save()
    p.translate(x, y)
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(SHADOW)
    p.drawEllipse(QPointF(0.25 * r, -0.3 * r), r * 1.02, r * 1.02)
    p.rotate(math.degrees(theta))
    # wheels stick out a little at both sides
    for side in (-1, 1):
        wheel = QRectF(-0.33 * r, side * 0.80 * r - 0.13 * r, 0.66 * r, 0.26 * r)
        p.setPen(Qt.PenStyle.NoPen)
        p.setBrush(WHEEL)
        p.drawRoundedRect(wheel, 0.06 * r, 0.06 * r)
        p.setPen(QPen(TREAD, line * 1.2))
        for k in range(-2, 3):
            p.drawLine(QPointF(k * 0.12 * r, wheel.top() + 0.04 * r), QPointF(k * 0.12 * r, wheel.bottom() - 0.04 * r))
    # the plate, with its ring of mounting holes
    p.setPen(QPen(PLATE_EDGE, line * 1.5))
    p.setBrush(PLATE)
    p.drawEllipse(QPointF(0, 0), 0.78 * r, 0.9 * r)
    p.setPen(QPen(PLATE_RING, line))
    p.setBrush(Qt.BrushStyle.NoBrush)
    p.drawEllipse(QPointF(0, 0), 0.62 * r, 0.72 * r)
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(PLATE_RING)
    for k in range(12):
        a = math.radians(k * 30 + 15)
        p.drawEllipse(QPointF(0.7 * r * math.cos(a), 0.81 * r * math.sin(a)), 0.035 * r, 0.035 * r)
    # which way is forward
    p.setBrush(FRONT)
    p.setPen(QPen(FRONT.darker(140), line))
    p.drawPolygon(QPolygonF([QPointF(0.98 * r, 0), QPointF(0.62 * r, 0.26 * r), QPointF(0.62 * r, -0.26 * r)]))
    _paint_lidar(p, snapshot, r, line)
    p.restore()
    if snapshot.get("bumped") is True:
        _paint_bump(p, x, y, theta + (scan.closest_angle() or 0.0), r)


def _paint_lidar(p, snapshot, r, line):
    """The laser's turret, its window turning with the simulated time."""
    centre = QPointF(-0.12 * r, 0)
    p.setPen(QPen(LIDAR_EDGE, line))
    p.setBrush(LIDAR)
    p.drawEllipse(centre, 0.38 * r, 0.38 * r)
    p.setBrush(LIDAR_EDGE)
    p.drawEllipse(centre, 0.2 * r, 0.2 * r)
    angle = math.radians(model.num(snapshot.get("time")) * LIDAR_SPIN % 360)
    p.setPen(round_pen(LIDAR_WINDOW, 0.14 * r, round_joins=True))
    tip = QPointF(centre.x() + 0.3 * r * math.cos(angle), centre.y() + 0.3 * r * math.sin(angle))
    p.drawLine(centre, tip)


def _paint_bump(p, x, y, direction, r):
    """A yellow-and-red burst on the robot's edge in the map ``direction`` of what it touches."""
    cx, cy = x + r * math.cos(direction), y + r * math.sin(direction)
    points = []
    for k in range(16):
        a = 2 * math.pi * k / 16
        length = (0.55 if k % 2 == 0 else 0.28) * r
        points.append(QPointF(cx + length * math.cos(a), cy + length * math.sin(a)))
    p.setPen(QPen(BUMP, 1.5 / max(1.0, r * 100)))
    p.setBrush(BUMP_GLOW)
    p.drawPolygon(QPolygonF(points))
    p.setBrush(BUMP)
    p.setPen(Qt.PenStyle.NoPen)
    p.drawEllipse(QPointF(cx, cy), 0.13 * r, 0.13 * r)
