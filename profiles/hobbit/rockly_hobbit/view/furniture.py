"""The furniture in the room, in map metres: rug, sofa, table with chairs, bookshelf, two plants and a ball.

Where each piece stands and how big it is comes from the house's data (``world.yaml``, what the
simulated HOBBIT bumps into); only the rug, which it drives over, is the view's own. Each piece
is drawn twice, first as a soft shadow offset down-right, then for real.
"""
import math

from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QColor, QPen

from rockly_desktop.sdk_view import cosmetic_pen

from ..world import WORLD
from .drawing import wedge

SHADOW = QColor(40, 30, 20, 40)
SHADOW_OFFSET = (0.035, -0.05)
OUTLINE = QColor(0, 0, 0, 60)


def paint_furniture(p):
    _paint_rug(p)
    for piece in (_sofa, _table, _shelf, _plant, _second_plant, _ball):
        p.save()
        p.translate(*SHADOW_OFFSET)
        piece(p, True)
        p.restore()
        piece(p, False)


def _box(obstacle_id):
    """(x0, y0, x1, y1) of a piece of furniture in the house's data."""
    return WORLD.obstacle(obstacle_id).bounds


def _centre(obstacle_id):
    x0, y0, x1, y1 = _box(obstacle_id)
    return (x0 + x1) / 2, (y0 + y1) / 2


def _silhouette(p, is_shadow, colour):
    """Pen and brush for a piece's outer shape: outlined ``colour``, or plain shadow on the shadow pass."""
    p.setPen(Qt.PenStyle.NoPen if is_shadow else cosmetic_pen(OUTLINE, 1.0))
    p.setBrush(SHADOW if is_shadow else QColor(colour))


def _paint_rug(p):
    """The rug in front of the sofa, with a dotted border."""
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(QColor("#CDEBDF"))
    p.drawRoundedRect(QRectF(0.2, 0.45, 1.8, 0.95), 0.3, 0.3)
    dots = QPen(QColor("#FFFFFF"), 0.035)
    dots.setDashPattern([0.4, 1.6])
    dots.setCapStyle(Qt.PenCapStyle.RoundCap)
    p.setPen(dots)
    p.setBrush(Qt.BrushStyle.NoBrush)
    p.drawRoundedRect(QRectF(0.3, 0.55, 1.6, 0.75), 0.22, 0.22)


def _cushion(p, x, y, degrees, colour):
    p.setBrush(QColor(colour))
    p.save()
    p.translate(x, y)
    p.rotate(degrees)
    p.drawRoundedRect(QRectF(-0.13, -0.1, 0.26, 0.2), 0.06, 0.06)
    p.restore()


def _sofa(p, is_shadow):
    x0, y0, x1, y1 = _box("sofa")
    w, h = x1 - x0, y1 - y0
    _silhouette(p, is_shadow, "#F2857A")
    p.drawRoundedRect(QRectF(x0, y0, w, h), 0.12, 0.12)
    if is_shadow:
        return
    p.setBrush(QColor("#DD6C62"))
    p.drawRoundedRect(QRectF(x0, y1 - 0.25, w, 0.25), 0.1, 0.1)    # the back
    p.drawRoundedRect(QRectF(x0, y0, 0.24, h), 0.1, 0.1)           # the arms
    p.drawRoundedRect(QRectF(x1 - 0.24, y0, 0.24, h), 0.1, 0.1)
    p.setBrush(QColor("#F8A196"))
    seat = (w - 0.6) / 2
    p.drawRoundedRect(QRectF(x0 + 0.28, y0 + 0.06, seat, h - 0.32), 0.08, 0.08)
    p.drawRoundedRect(QRectF(x0 + 0.32 + seat, y0 + 0.06, seat, h - 0.32), 0.08, 0.08)
    _cushion(p, x0 + 0.45, y1 - 0.4, -12, "#FFD166")
    _cushion(p, x1 - 0.44, y1 - 0.4, 10, "#8FD3F0")


def _table(p, is_shadow):
    for chair in ("chair_left", "chair_right"):   # chairs tucked in on the wall side
        cx0, cy0, cx1, cy1 = _box(chair)
        _silhouette(p, is_shadow, "#7DC4E4")
        p.drawRoundedRect(QRectF(cx0, cy0, cx1 - cx0, cy1 - cy0), 0.08, 0.08)
        if not is_shadow:
            p.setBrush(QColor("#5AA8CC"))
            p.drawRoundedRect(QRectF(cx0, cy1 - 0.1, cx1 - cx0, 0.1), 0.04, 0.04)
    x0, y0, x1, y1 = _box("table")
    _silhouette(p, is_shadow, "#C98A57")
    p.drawRoundedRect(QRectF(x0, y0, x1 - x0, y1 - y0), 0.08, 0.08)
    if is_shadow:
        return
    p.setBrush(QColor("#D9A06D"))
    p.drawRoundedRect(QRectF(x0 + 0.06, y0 + 0.06, x1 - x0 - 0.12, y1 - y0 - 0.12), 0.06, 0.06)
    # a fruit bowl
    bx, by = _centre("table")
    p.setBrush(QColor("#FFFFFF"))
    p.drawEllipse(QPointF(bx, by), 0.17, 0.17)
    p.setPen(Qt.PenStyle.NoPen)
    for (dx, dy), colour in (((-0.06, 0.04), "#FF5D5D"), ((0.06, 0.05), "#FFB020"), ((0.0, -0.06), "#6CCB5F")):
        p.setBrush(QColor(colour))
        p.drawEllipse(QPointF(bx + dx, by + dy), 0.055, 0.055)


def _shelf(p, is_shadow):
    """A bookshelf against the right wall, with books of varied colour, thickness and depth."""
    x0, y0, x1, y1 = _box("shelf")
    _silhouette(p, is_shadow, "#A8764E")
    p.drawRect(QRectF(x0, y0, x1 - x0, y1 - y0))
    if is_shadow:
        return
    p.setBrush(QColor("#C79466"))
    p.drawRect(QRectF(x0 + 0.04, y0 + 0.04, x1 - x0 - 0.08, y1 - y0 - 0.08))
    p.setPen(Qt.PenStyle.NoPen)
    colours = ("#FF6B6B", "#4D8DFF", "#FFD166", "#2EC4B6", "#B084F5", "#FF9F43", "#6CCB5F")
    y = y0 + 0.07
    k = 0
    while y < y1 - 0.1:
        h = 0.06 + (k * 5 % 4) * 0.02
        p.setBrush(QColor(colours[k % len(colours)]))
        depth = 0.24 + (k % 3) * 0.03
        p.drawRect(QRectF(x1 - 0.05 - depth, y, depth, h))
        y += h + 0.012
        k += 1


def _plant(p, is_shadow, obstacle_id="plant"):
    """A potted plant seen from above: seven leaves around the pot."""
    x, y = _centre(obstacle_id)
    p.setPen(Qt.PenStyle.NoPen)
    if is_shadow:
        p.setBrush(SHADOW)
        p.drawEllipse(QPointF(x, y), 0.3, 0.3)
        return
    p.setBrush(QColor("#E07A4F"))
    p.drawEllipse(QPointF(x, y), 0.17, 0.17)
    for k in range(7):
        a = math.radians(k * 360 / 7 + 10)
        p.setBrush(QColor("#4CB862") if k % 2 else QColor("#6FD07B"))
        p.save()
        p.translate(x + math.cos(a) * 0.13, y + math.sin(a) * 0.13)
        p.rotate(math.degrees(a))
        p.drawEllipse(QPointF(0, 0), 0.17, 0.075)
        p.restore()
    p.setBrush(QColor("#3A9E50"))
    p.drawEllipse(QPointF(x, y), 0.06, 0.06)


def _second_plant(p, is_shadow):
    _plant(p, is_shadow, "second_plant")


def _ball(p, is_shadow):
    """A beach ball: six coloured slices."""
    x, y = _centre("ball")
    p.setPen(Qt.PenStyle.NoPen)
    if is_shadow:
        p.setBrush(SHADOW)
        p.drawEllipse(QPointF(x, y), 0.14, 0.14)
        return
    for k, colour in enumerate(("#FF5D5D", "#FFFFFF", "#4D8DFF", "#FFFFFF", "#FFD166", "#FFFFFF")):
        p.setBrush(QColor(colour))
        p.drawPath(wedge(x, y, 0.14, k * 60, (k + 1) * 60, 6))
