"""Small painting helpers shared by the map and the panel: pens, arcs and wedges, cards, chips, buttons, a star."""
import math

from PySide6.QtCore import QPointF, Qt
from PySide6.QtGui import QColor, QPainterPath, QPen, QPolygonF

from .palette import CARD


def with_alpha(color, alpha):
    c = QColor(color)
    c.setAlphaF(max(0.0, min(1.0, alpha)))
    return c


def round_pen(color, width, round_joins=False):
    """A pen with round caps (and joins)."""
    pen = QPen(color, width)
    pen.setCapStyle(Qt.PenCapStyle.RoundCap)
    if round_joins:
        pen.setJoinStyle(Qt.PenJoinStyle.RoundJoin)
    return pen


def cosmetic_pen(color, width):
    """A pen ``width`` pixels wide whatever the painter's scale."""
    pen = QPen(color, width)
    pen.setCosmetic(True)
    return pen


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


def card(p, rect, radius, accent=None):
    """A white card with a soft shadow, outlined in ``accent`` if given."""
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(QColor(60, 70, 120, 28))
    p.drawRoundedRect(rect.translated(0, 2), radius, radius)
    p.setBrush(CARD)
    if accent is not None:
        p.setPen(QPen(accent, 2.5))
    p.drawRoundedRect(rect, radius, radius)


def chip(p, rect):
    """A translucent white pill for a short label over the map."""
    p.setPen(QPen(QColor(60, 70, 120, 40), 1))
    p.setBrush(QColor(255, 255, 255, 225))
    p.drawRoundedRect(rect, rect.height() / 2, rect.height() / 2)


def button(p, rect, colour, label, fm):
    """A round button in ``colour`` with a white ``label`` (in the painter's current font, measured by ``fm``)."""
    radius = rect.height() / 2
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(colour.darker(125))
    p.drawRoundedRect(rect.translated(0, 2), radius, radius)
    p.setBrush(colour)
    p.drawRoundedRect(rect, radius, radius)
    p.setPen(QColor("#FFFFFF"))
    p.drawText(rect, Qt.AlignmentFlag.AlignCenter, fm.elidedText(label, Qt.TextElideMode.ElideRight, rect.width() - 6))


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
