"""The furniture in the room, in map metres: rug, sofa, table with chairs, bookshelf, two plants and a ball.

Each piece is drawn twice, first as a soft shadow offset down-right, then for real.
"""
import math

from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QColor, QPen

from rockly_desktop.sdk_view import cosmetic_pen

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
    _silhouette(p, is_shadow, "#F2857A")
    p.drawRoundedRect(QRectF(0.1, 1.6, 2.0, 0.82), 0.12, 0.12)
    if is_shadow:
        return
    p.setBrush(QColor("#DD6C62"))
    p.drawRoundedRect(QRectF(0.1, 2.17, 2.0, 0.25), 0.1, 0.1)
    p.drawRoundedRect(QRectF(0.1, 1.6, 0.24, 0.82), 0.1, 0.1)
    p.drawRoundedRect(QRectF(1.86, 1.6, 0.24, 0.82), 0.1, 0.1)
    p.setBrush(QColor("#F8A196"))
    p.drawRoundedRect(QRectF(0.38, 1.66, 0.7, 0.5), 0.08, 0.08)
    p.drawRoundedRect(QRectF(1.12, 1.66, 0.7, 0.5), 0.08, 0.08)
    _cushion(p, 0.55, 2.02, -12, "#FFD166")
    _cushion(p, 1.66, 2.02, 10, "#8FD3F0")


def _table(p, is_shadow):
    for cx in (3.4, 4.0):   # chairs tucked in on the wall side
        _silhouette(p, is_shadow, "#7DC4E4")
        p.drawRoundedRect(QRectF(cx - 0.2, 1.55, 0.4, 0.45), 0.08, 0.08)
        if not is_shadow:
            p.setBrush(QColor("#5AA8CC"))
            p.drawRoundedRect(QRectF(cx - 0.2, 1.9, 0.4, 0.1), 0.04, 0.04)
    _silhouette(p, is_shadow, "#C98A57")
    p.drawRoundedRect(QRectF(3.1, 0.75, 1.2, 0.9), 0.08, 0.08)
    if is_shadow:
        return
    p.setBrush(QColor("#D9A06D"))
    p.drawRoundedRect(QRectF(3.16, 0.81, 1.08, 0.78), 0.06, 0.06)
    # a fruit bowl
    p.setBrush(QColor("#FFFFFF"))
    p.drawEllipse(QPointF(3.7, 1.2), 0.17, 0.17)
    p.setPen(Qt.PenStyle.NoPen)
    for (dx, dy), colour in (((-0.06, 0.04), "#FF5D5D"), ((0.06, 0.05), "#FFB020"), ((0.0, -0.06), "#6CCB5F")):
        p.setBrush(QColor(colour))
        p.drawEllipse(QPointF(3.7 + dx, 1.2 + dy), 0.055, 0.055)


def _shelf(p, is_shadow):
    """A bookshelf against the right wall, with books of varied colour, thickness and depth."""
    _silhouette(p, is_shadow, "#A8764E")
    p.drawRect(QRectF(4.58, -2.0, 0.42, 1.5))
    if is_shadow:
        return
    p.setBrush(QColor("#C79466"))
    p.drawRect(QRectF(4.62, -1.96, 0.34, 1.42))
    p.setPen(Qt.PenStyle.NoPen)
    colours = ("#FF6B6B", "#4D8DFF", "#FFD166", "#2EC4B6", "#B084F5", "#FF9F43", "#6CCB5F")
    y = -1.93
    k = 0
    while y < -0.6:
        h = 0.06 + (k * 5 % 4) * 0.02
        p.setBrush(QColor(colours[k % len(colours)]))
        depth = 0.24 + (k % 3) * 0.03
        p.drawRect(QRectF(4.95 - depth, y, depth, h))
        y += h + 0.012
        k += 1


def _plant(p, is_shadow, at=(-0.62, 2.1)):
    """A potted plant seen from above: seven leaves around the pot."""
    x, y = at
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
    _plant(p, is_shadow, at=(4.65, 2.1))


def _ball(p, is_shadow, at=(-0.55, -2.05)):
    """A beach ball: six coloured slices."""
    x, y = at
    p.setPen(Qt.PenStyle.NoPen)
    if is_shadow:
        p.setBrush(SHADOW)
        p.drawEllipse(QPointF(x, y), 0.14, 0.14)
        return
    for k, colour in enumerate(("#FF5D5D", "#FFFFFF", "#4D8DFF", "#FFFFFF", "#FFD166", "#FFFFFF")):
        p.setBrush(QColor(colour))
        p.drawPath(wedge(x, y, 0.14, k * 60, (k + 1) * 60, 6))
