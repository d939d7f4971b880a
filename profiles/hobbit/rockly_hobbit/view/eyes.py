"""HOBBIT's eyes in the panel: one face per emotion, looking where the head turns, blinking now and then."""
import math

from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import (
    QBrush,
    QColor,
    QLinearGradient,
    QPainterPath,
    QPainterPathStroker,
    QPolygonF,
    QRadialGradient,
)

from rockly_desktop.sdk_view import round_pen, with_alpha

from .drawing import arc, rounded, star
from .palette import FACE_BG, FACE_BG_SLEEP, IRIS, IRIS_DARK, LID_EDGE

WHITE = QColor("#FFFFFF")
BLINKING = ("NEUTRAL", "CONCERNED", "WONDERING", "LTIRED", "SAD")
BLINK_EVERY = 3.7   # seconds
BLINK_TAKES = 0.18


def paint_eyes(p, scene, face):
    """The face in ``face`` (widget pixels) for ``scene.emotion``."""
    emotion, phase, shown = scene.emotion, scene.phase, scene.shown
    sleeping = emotion == "SLEEPING"
    radius = min(face.height() * 0.22, face.width() * 0.1)
    gradient = QLinearGradient(face.topLeft(), face.bottomLeft())
    base = FACE_BG_SLEEP if sleeping else FACE_BG
    gradient.setColorAt(0, base.lighter(118))
    gradient.setColorAt(1, base)
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(QBrush(gradient))
    p.drawRoundedRect(face, radius, radius)
    p.save()
    p.setClipPath(rounded(face, radius))
    e = min(face.width() * 0.135, face.height() * 0.28)
    cy = face.center().y() + face.height() * 0.07
    look_x = max(-1.0, min(1.0, shown["pan"] / math.radians(50))) * 0.35
    look_y = shown["tilt"] * 0.3
    blink = 0.0
    if scene.animate and emotion in BLINKING:
        t = phase % BLINK_EVERY
        if t < BLINK_TAKES:
            blink = 1.0 - abs(t - BLINK_TAKES / 2) / (BLINK_TAKES / 2)
    for side in (-1, 1):
        c = QPointF(face.center().x() + side * face.width() * 0.23, cy)
        if emotion in ("HAPPY", "VHAPPY"):
            _happy_eye(p, c, e, side, emotion == "VHAPPY")
        elif sleeping:
            _sleeping_eye(p, c, e)
        else:
            _open_eye(p, c, e, side, emotion, look_x, look_y, blink)
    if emotion == "WONDERING":
        p.setFont(scene.font(int(e * 1.05), True))
        p.setPen(QColor("#FFD84D"))
        p.drawText(QRectF(face.right() - face.width() * 0.13, face.top() + face.height() * 0.05,
                          face.width() * 0.12, e * 1.3), Qt.AlignmentFlag.AlignCenter, "?")
    if sleeping:
        _paint_floating_z(p, scene, face, e, cy)
    p.restore()


def _paint_floating_z(p, scene, face, e, cy):
    rise = (scene.phase * 0.35) % 1.0 if scene.animate else 0.3
    for k, (size, dx) in enumerate(((0.7, 0.0), (1.0, 0.5))):
        t = (rise + k * 0.5) % 1.0
        p.setFont(scene.font(int(e * size), True))
        p.setPen(with_alpha(QColor("#C9D3FF"), 0.25 + 0.75 * math.sin(math.pi * t) if scene.animate else 1.0))
        x = face.right() - face.width() * (0.24 - 0.14 * dx) + t * e * 0.2
        y = cy - e * (0.5 + 0.6 * k) - t * e * 0.35
        p.drawText(QPointF(x, y), "z" if k == 0 else "Z")


def _happy_eye(p, c, e, side, very):
    """A smiling arc; very happy adds a blush and a sparkle."""
    r = e * (1.2 if very else 1.1)
    center_y = c.y() + e * (0.55 if very else 0.5)
    p.setPen(round_pen(WHITE, e * (0.38 if very else 0.33)))
    p.setBrush(Qt.BrushStyle.NoBrush)
    p.drawPolyline(QPolygonF(arc(c.x(), center_y, r, 12 if very else 25, 168 if very else 155, 24)))
    if very:
        p.setPen(Qt.PenStyle.NoPen)
        p.setBrush(QColor(255, 120, 160, 185))
        p.drawEllipse(QPointF(c.x() + side * e * 0.35, c.y() + e * 0.95), e * 0.48, e * 0.24)
        star(p, QPointF(c.x() + side * e * 1.25, c.y() - e * 0.75), e * 0.28, QColor("#FFE066"))


def _sleeping_eye(p, c, e):
    """A closed lid with three lashes."""
    colour = QColor("#AFC0F2")
    p.setPen(round_pen(colour, e * 0.2))
    p.setBrush(Qt.BrushStyle.NoBrush)
    center_y = c.y() - e * 0.25
    p.drawPolyline(QPolygonF(arc(c.x(), center_y, e * 0.8, 200, 340, 24)))
    p.setPen(round_pen(colour, e * 0.1))
    for a in (230, 270, 310):
        rad = math.radians(a)
        inner = QPointF(c.x() + e * 0.8 * math.cos(rad), center_y - e * 0.8 * math.sin(rad))
        outer = QPointF(c.x() + e * 1.08 * math.cos(rad), center_y - e * 1.08 * math.sin(rad))
        p.drawLine(inner, outer)


def _open_eye(p, c, e, side, emotion, look_x, look_y, blink):
    """Sclera, iris, pupil and highlights under lids that tell the mood, then brows and a tear.

    ``side`` -1 is the eye on the left of the screen.
    """
    iris, pupil, gaze_x, gaze_y = 0.56, 0.3, look_x, look_y
    lid, slant, lower = 0.06, 0.0, 0.0
    size = e
    if emotion == "LTIRED":
        lid, gaze_y = 0.46, gaze_y + 0.2
    elif emotion == "VTIRED":
        lid, lower, gaze_y = 0.68, 0.16, gaze_y + 0.3
    elif emotion == "CONCERNED":
        pupil, gaze_y = 0.26, gaze_y - 0.15
    elif emotion == "SAD":
        lid, slant, gaze_y = 0.3, 0.42, gaze_y + 0.35
    elif emotion == "WONDERING":
        size, iris, pupil = e * 1.08, 0.7, 0.42
        gaze_x, gaze_y = gaze_x + 0.3, gaze_y - 0.3
    lid = max(lid, blink)
    gaze_x, gaze_y = max(-0.6, min(0.6, gaze_x)), max(-0.6, min(0.6, gaze_y))
    # the visible part of the eye: the ball minus the lids, so no white seams remain
    eye = QPainterPath()
    eye.addEllipse(c, size, size * 1.04)
    top, bottom = c.y() - size * 1.05, c.y() + size * 1.05
    visible = QPainterPath(eye)
    lid_lines = []
    if lid > 0.08:
        # "slant" lowers the lid's outer end (sad)
        a = QPointF(c.x() - side * size * 1.2, top + 2.1 * size * max(0.0, lid - slant * 0.5))
        b = QPointF(c.x() + side * size * 1.2, top + 2.1 * size * min(1.0, lid + slant * 0.5))
        cover = QPainterPath()
        cover.addPolygon(QPolygonF([QPointF(a.x(), top - 2), QPointF(b.x(), top - 2), b, a]))
        cover.closeSubpath()
        visible = visible.subtracted(cover)
        lid_lines.append((a, b))
    if lower > 0:
        y = bottom - 2.1 * size * lower
        cover = QPainterPath()
        cover.addRect(QRectF(c.x() - size * 1.2, y, size * 2.4, bottom - y + 2))
        visible = visible.subtracted(cover)
        lid_lines.append((QPointF(c.x() - size * 1.2, y), QPointF(c.x() + size * 1.2, y)))
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(WHITE)
    p.drawPath(visible)

    def disc(center, radius, brush):
        shape = QPainterPath()
        shape.addEllipse(center, radius, radius)
        p.setBrush(brush)
        p.drawPath(shape.intersected(visible))

    ic = QPointF(c.x() + gaze_x * size * 0.55, c.y() + gaze_y * size * 0.55)
    gradient = QRadialGradient(ic, size * iris)
    gradient.setColorAt(0, IRIS)
    gradient.setColorAt(1, IRIS_DARK)
    disc(ic, size * iris, QBrush(gradient))
    disc(ic, size * pupil, QColor("#0E1630"))
    disc(QPointF(ic.x() - size * iris * 0.35, ic.y() - size * iris * 0.38), size * 0.16, WHITE)
    disc(QPointF(ic.x() + size * iris * 0.35, ic.y() + size * iris * 0.35), size * 0.07, WHITE)
    stroker = QPainterPathStroker()
    stroker.setWidth(size * 0.12)
    p.setBrush(LID_EDGE)
    for a, b in lid_lines:
        line = QPainterPath(a)
        line.lineTo(b)
        p.drawPath(stroker.createStroke(line).intersected(eye))
    _brow(p, c, size, side, emotion)
    if emotion == "SAD" and side < 0:
        _tear(p, c, size)


# how the brows sit: (inner end, outer end, extra bend), in eye radii; WONDERING raises one
BROWS = {"CONCERNED": (-0.42, 0.12, 0.0), "SAD": (-0.3, 0.2, 0.0)}
WONDERING_BROWS = {1: (-0.45, -0.45, -0.22), -1: (0.05, 0.05, 0.0)}


def _brow(p, c, size, side, emotion):
    brow = WONDERING_BROWS[side] if emotion == "WONDERING" else BROWS.get(emotion)
    if brow is None:
        return
    inner_dy, outer_dy, bend = brow
    base_y = c.y() - size * 1.38
    inner = QPointF(c.x() - side * size * 0.75, base_y + inner_dy * size)
    outer = QPointF(c.x() + side * size * 0.75, base_y + outer_dy * size)
    control = QPointF(c.x(), (inner.y() + outer.y()) / 2 - size * (0.15 - bend))
    path = QPainterPath(inner)
    path.quadTo(control, outer)
    p.setPen(round_pen(QColor("#E6ECFF"), size * 0.24))
    p.setBrush(Qt.BrushStyle.NoBrush)
    p.drawPath(path)


def _tear(p, c, size):
    """A tear under the outer corner of an eye."""
    x, y, r = c.x() - size * 0.7, c.y() + size * 1.05, size * 0.2
    path = QPainterPath(QPointF(x, y - size * 0.32))
    path.cubicTo(QPointF(x + r * 0.25, y - size * 0.15), QPointF(x + r, y - size * 0.02), QPointF(x + r, y + r * 0.4))
    path.arcTo(QRectF(x - r, y - r * 0.6, 2 * r, 2 * r), 0, -180)
    path.cubicTo(QPointF(x - r, y - size * 0.02), QPointF(x - r * 0.25, y - size * 0.15), QPointF(x, y - size * 0.32))
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(QColor("#7CC8FF"))
    p.drawPath(path)
