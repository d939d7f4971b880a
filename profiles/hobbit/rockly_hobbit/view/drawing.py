"""HOBBIT's own painting helpers, shared by the map and the panel: arcs and wedges, rounded clips, a star.

(Pens, colours with alpha, cards and chips come from the SDK: ``rockly_desktop.sdk_view``.)"""
import math

from PySide6.QtCore import QPointF, Qt
from PySide6.QtGui import QPainterPath, QPolygonF


def arc(cx, cy, r, start_deg, end_deg, steps=24, y_down=True):
    """Points on a circle from ``start_deg`` to ``end_deg`` (counter-clockwise as seen)."""
    sign = -1.0 if y_down else 1.0
    return [QPointF(cx + r * math.cos(math.radians(a)), cy + sign * r * math.sin(math.radians(a)))
            for a in (start_deg + (end_deg - start_deg) * i / steps for i in range(steps + 1))]


def wedge(cx, cy, r, start_deg, end_deg, steps):
    """A closed pie slice around (cx, cy), y up (map and robot frames)."""
    path = QPainterPath(QPointF(cx, cy))
    for point in arc(cx, cy, r, start_deg, end_deg, steps, y_down=False):
        path.lineTo(point)
    path.closeSubpath()
    return path


def rounded(rect, radius):
    """``rect`` with round corners, as a path (to clip to)."""
    path = QPainterPath()
    path.addRoundedRect(rect, radius, radius)
    return path


def star(p, center, radius, colour):
    """A four-pointed star in screen pixels (y down)."""
    points = []
    for k in range(8):
        r = radius if k % 2 == 0 else radius * 0.38
        a = math.radians(90 + k * 45)
        points.append(QPointF(center.x() + r * math.cos(a), center.y() - r * math.sin(a)))
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(colour)
    p.drawPolygon(QPolygonF(points))
