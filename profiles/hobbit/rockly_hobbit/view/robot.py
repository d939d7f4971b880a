"""HOBBIT seen from above, in map metres: base and bumper, body and tray, turntable, arm with gripper,
the head's view cone and the head itself, plus hints of how it moves and an SOS halo.

The SOS halo and the shadow are drawn unrotated, the rest in the robot frame (x forward):
the front is where the yellow bumper is.
"""
import math

from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QBrush, QColor, QLinearGradient, QPen, QPolygonF, QRadialGradient

from rockly_desktop.sdk_view import round_pen, with_alpha

from .animation import lerp
from .drawing import arc, wedge
from .geometry import BASE_RADIUS, HEAD_CENTER, HEAD_RADIUS, SHOULDER, TURNTABLE, TURNTABLE_RADIUS
from .palette import (
    ARM,
    ARM_EDGE,
    BASE_COLOR,
    BASE_EDGE,
    BODY,
    BODY_EDGE,
    BUMPER,
    GRIPPER,
    HEAD,
    SOS,
    VIEW_CONE,
    VIEW_CONE_EDGE,
    VISOR,
)
from .snapshot import num

ROBOT_MIN_PX = 44      # HOBBIT's base is drawn at least this wide (up to 1.6x its real size)


def paint_robot(p, scene, scale):
    """HOBBIT where the eased pose says; ``scale`` is pixels per metre."""
    s = scene.shown
    x, y, theta = s["x"], s["y"], s["theta"]
    # on a small map HOBBIT is drawn up to 1.6x its size, so a child can still see it
    grow = max(1.0, min(1.6, ROBOT_MIN_PX / (2 * BASE_RADIUS * scale)))
    p.save()
    p.translate(x, y)
    p.scale(grow, grow)
    scale *= grow
    p.setPen(Qt.PenStyle.NoPen)
    if scene.sos:
        pulse = 0.5 + 0.5 * math.sin(scene.phase * 6.0)
        p.setBrush(with_alpha(SOS, 0.18 + 0.22 * pulse))
        p.drawEllipse(QPointF(0, 0), BASE_RADIUS + 0.16 + 0.06 * pulse, BASE_RADIUS + 0.16 + 0.06 * pulse)
    p.setBrush(QColor(20, 30, 60, 55))
    p.drawEllipse(QPointF(0.035, -0.05), BASE_RADIUS + 0.01, BASE_RADIUS + 0.01)
    p.rotate(math.degrees(theta))
    _paint_motion_hints(p, scene.snapshot, scale)
    line = max(0.012, 1.4 / scale)
    # base, bumper and a chevron
    _disc(p, QPointF(0, 0), BASE_RADIUS, BASE_COLOR, BASE_EDGE, line)
    p.setPen(round_pen(BUMPER, 0.045))
    p.setBrush(Qt.BrushStyle.NoBrush)
    p.drawPolyline(QPolygonF(arc(0, 0, BASE_RADIUS - 0.03, -55, 55, 20, y_down=False)))
    p.setPen(QPen(QColor("#E0A100"), line * 0.8))
    p.setBrush(BUMPER)
    p.drawPolygon(QPolygonF([QPointF(0.235, 0), QPointF(0.155, 0.06), QPointF(0.155, -0.06)]))
    # body column with the tray on its back
    p.setPen(QPen(BODY_EDGE, line))
    p.setBrush(BODY)
    p.drawRoundedRect(QRectF(-0.235, -0.16, 0.345, 0.32), 0.07, 0.07)
    p.setPen(QPen(QColor("#B98A5C"), line * 0.8))
    p.setBrush(QColor("#F1D3A8"))
    p.drawRoundedRect(QRectF(-0.215, -0.125, 0.105, 0.25), 0.03, 0.03)
    _paint_turntable(p, s, line)
    if scene.emotion != "SLEEPING":
        _paint_view_cone(p, s, grow)
    _paint_arm(p, s, line, theta)
    _paint_head(p, s, line, scene.emotion == "SLEEPING")
    p.restore()


def _disc(p, centre, radius, fill, edge, width):
    """A filled circle outlined ``width`` wide."""
    p.setPen(QPen(edge, width))
    p.setBrush(fill)
    p.drawEllipse(centre, radius, radius)


def _paint_motion_hints(p, snapshot, scale):
    """Speed lines behind a driving robot, a curved arrow around a turning one."""
    linear, angular = num(snapshot.get("linear")), num(snapshot.get("angular"))
    p.setPen(round_pen(with_alpha(BASE_EDGE, 0.55), max(0.02, 2.0 / scale)))
    p.setBrush(Qt.BrushStyle.NoBrush)
    if abs(linear) > 0.02:
        back = -1.0 if linear > 0 else 1.0
        for dy, length in ((-0.14, 0.12), (0.0, 0.18), (0.14, 0.12)):
            start = back * (BASE_RADIUS + 0.06)
            p.drawLine(QPointF(start, dy), QPointF(start + back * length, dy))
    if abs(angular) > 0.05:
        points = arc(0, 0, BASE_RADIUS + 0.09, 120, 240, 16, y_down=False)
        if angular < 0:
            points = points[::-1]
        p.drawPolyline(QPolygonF(points))
        end, before = points[-1], points[-3]
        dx, dy = end.x() - before.x(), end.y() - before.y()
        norm = math.hypot(dx, dy) or 1.0
        dx, dy = dx / norm * 0.07, dy / norm * 0.07
        p.drawLine(end, QPointF(end.x() - dx - dy * 0.8, end.y() - dy + dx * 0.8))
        p.drawLine(end, QPointF(end.x() - dx + dy * 0.8, end.y() - dy - dx * 0.8))


def _paint_turntable(p, s, line):
    """The turntable slides out in front of the base and turns; a pink dot shows its angle."""
    out = s["tt_out"]
    if out < 0.02:
        return
    cx = lerp(0.18, TURNTABLE[0], out)
    radius = TURNTABLE_RADIUS * (0.6 + 0.4 * out)
    p.save()
    p.setOpacity(min(1.0, out * 1.5))
    p.translate(cx, TURNTABLE[1])
    _disc(p, QPointF(0, 0), radius, QColor("#C9BDF5"), QColor("#6E5BB8"), line)
    p.rotate(s["tt_angle"])
    p.setPen(QPen(QColor("#8C7AD6"), line * 0.8))
    for k in range(6):
        a = math.radians(k * 60)
        p.drawLine(QPointF(0, 0), QPointF(math.cos(a) * radius * 0.85, math.sin(a) * radius * 0.85))
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(QColor("#FF5D8F"))
    p.drawEllipse(QPointF(radius * 0.55, 0), radius * 0.22, radius * 0.22)
    p.setBrush(QColor("#FFFFFF"))
    p.drawEllipse(QPointF(0, 0), radius * 0.16, radius * 0.16)
    p.restore()


def _paint_arm(p, s, line, theta):
    """Shoulder, elbow and tip with a shadow that shows how high the arm is, then the gripper or a raised cap."""
    shoulder, elbow, tip = QPointF(*SHOULDER), QPointF(s["ex"], s["ey"]), QPointF(s["tx"], s["ty"])
    # the shadow falls down-right on screen, farther the higher the arm
    off = 0.015 + 0.06 * s["height"]
    sx = off * (math.cos(-theta) * 0.6 - math.sin(-theta) * -0.8)
    sy = off * (math.sin(-theta) * 0.6 + math.cos(-theta) * -0.8)
    p.setPen(round_pen(QColor(20, 30, 60, 45), 0.06, round_joins=True))
    p.setBrush(Qt.BrushStyle.NoBrush)
    p.drawPolyline(QPolygonF([shoulder + QPointF(sx, sy), elbow + QPointF(sx, sy), tip + QPointF(sx, sy)]))
    for width, color in ((0.062, ARM_EDGE), (0.045, ARM)):
        p.setPen(round_pen(color, width, round_joins=True))
        p.drawPolyline(QPolygonF([shoulder, elbow, tip]))
    _disc(p, elbow, 0.032, QColor("#FFC27A"), ARM_EDGE, line)
    _disc(p, shoulder, 0.04, QColor("#9AA3BA"), ARM_EDGE, line)
    up = s["up"]
    if 1.0 - up > 0.05:
        _paint_gripper(p, s, elbow, tip, line, 1.0 - up)
    if up > 0.05:
        # arm straight up ("candle"): a round cap with an arrow pointing at the sky
        r = 0.06 * up
        _disc(p, tip, r, ARM, ARM_EDGE, line)
        p.setPen(Qt.PenStyle.NoPen)
        p.setBrush(QColor("#FFFFFF"))
        p.drawEllipse(tip, r * 0.55, r * 0.55)
        p.setBrush(ARM_EDGE)
        p.drawEllipse(tip, r * 0.25, r * 0.25)


def _paint_gripper(p, s, elbow, tip, line, fingers):
    """Two fingers along the forearm, spread when open; ``fingers`` shrinks them as the arm points up."""
    dx, dy = tip.x() - elbow.x(), tip.y() - elbow.y()
    direction = math.atan2(dy, dx) if math.hypot(dx, dy) > 0.02 else 0.0
    spread = math.radians(7 + 26 * s["grip"])
    length = 0.075 * fingers
    p.setPen(round_pen(GRIPPER, 0.022))
    for side in (-1, 1):
        a = direction + side * spread
        mid = QPointF(tip.x() + math.cos(a) * length * 0.6, tip.y() + math.sin(a) * length * 0.6)
        end = QPointF(mid.x() + math.cos(direction) * length * 0.5, mid.y() + math.sin(direction) * length * 0.5)
        p.drawPolyline(QPolygonF([tip, mid, end]))
    _disc(p, tip, 0.028, QColor("#5B6584"), GRIPPER, line)


def _paint_view_cone(p, s, grow):
    """Where the head looks: a fading yellow cone, as long and wide as the head position says (in true metres)."""
    hx, hy = HEAD_CENTER
    length, half = s["look_len"] / grow, s["look_width"]
    pan = math.degrees(s["pan"])
    gradient = QRadialGradient(QPointF(hx, hy), length)
    gradient.setColorAt(0.0, with_alpha(VIEW_CONE, s["look_alpha"] + 0.25))
    gradient.setColorAt(0.55, with_alpha(VIEW_CONE, s["look_alpha"]))
    gradient.setColorAt(1.0, with_alpha(VIEW_CONE, 0.0))
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(QBrush(gradient))
    p.drawPath(wedge(hx, hy, length, pan - half, pan + half, 20))
    edge = QLinearGradient(QPointF(hx, hy), QPointF(hx + length * math.cos(math.radians(pan)),
                                                    hy + length * math.sin(math.radians(pan))))
    edge.setColorAt(0.0, with_alpha(VIEW_CONE_EDGE, 0.9))
    edge.setColorAt(1.0, with_alpha(VIEW_CONE_EDGE, 0.0))
    p.setPen(round_pen(QBrush(edge), 0.018 / grow))
    for a in (pan - half, pan + half):
        p.drawLine(QPointF(hx, hy), QPointF(hx + length * math.cos(math.radians(a)),
                                            hy + length * math.sin(math.radians(a))))


def _paint_head(p, s, line, sleeping):
    """The round head with a dark visor facing where it looks, and two lights that dim in sleep."""
    hx, hy = HEAD_CENTER
    pan = math.degrees(s["pan"])
    _disc(p, QPointF(hx, hy), HEAD_RADIUS, HEAD, BODY_EDGE, line)
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(VISOR)
    p.drawPath(wedge(hx, hy, HEAD_RADIUS * 0.86, pan - 58, pan + 58, 16))
    p.setBrush(QColor("#7FE3FF") if not sleeping else QColor("#4B5A8C"))
    for side in (-1, 1):
        a = math.radians(pan + side * 24)
        center = QPointF(hx + math.cos(a) * HEAD_RADIUS * 0.55, hy + math.sin(a) * HEAD_RADIUS * 0.55)
        p.drawEllipse(center, 0.018, 0.018)
