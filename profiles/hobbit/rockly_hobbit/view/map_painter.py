"""The map half of the view: the cached room, then the trail, the navigation goal, HOBBIT, and the chips
that say how it moves, where it is and the simulation time."""
import math

from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QColor, QFontMetricsF, QPainterPath, QPen

from rockly_desktop.sdk_view import chip, decimal, round_pen, with_alpha

from .animation import wrap_pi
from .drawing import rounded, star
from .layout import map_transform
from .palette import GOAL, INK, INK_SOFT, MAP_BORDER, MOTION_COLOURS, TRAIL
from .robot import paint_robot
from .snapshot import num, point, trail

TRAIL_AGES = 10   # the trail is drawn in this many steps from faint (old) to strong (new)


def paint_map(p, layout, scene, room, dpr):
    """Everything inside ``layout.map``; ``room`` is the view's RoomPixmap, ``dpr`` its device pixel ratio."""
    rect = layout.map
    if rect.width() < 4 or rect.height() < 4:
        return
    transform = map_transform(rect, scene.shown)
    scale = transform.m11()
    p.drawPixmap(rect.topLeft(), room.get(rect, transform, scene.shown, dpr, layout.radius))
    p.save()
    p.setClipPath(rounded(rect, layout.radius))
    p.setTransform(transform)
    _paint_trail(p, scene.snapshot, scale)
    goal = point(scene.snapshot.get("nav_goal"))
    if goal is not None:
        _paint_goal_ground(p, scene, goal)
    paint_robot(p, scene, scale)
    p.resetTransform()
    if goal is not None:
        _paint_flag(p, transform.map(QPointF(*goal)), scale, scene.phase)
    _paint_chips(p, scene, rect, layout.u)
    p.restore()
    p.setPen(QPen(MAP_BORDER, max(1.0, 1.5 * layout.u)))
    p.setBrush(Qt.BrushStyle.NoBrush)
    p.drawRoundedRect(rect, layout.radius, layout.radius)


def _trail_dots(points, spacing):
    """Evenly spaced dots along the polyline ``points``."""
    dots, carry = [points[0]], 0.0
    for (ax, ay), (bx, by) in zip(points, points[1:], strict=False):
        length = math.hypot(bx - ax, by - ay)
        if length == 0:
            continue
        d = spacing - carry
        while d <= length:
            dots.append((ax + (bx - ax) * d / length, ay + (by - ay) * d / length))
            d += spacing
        carry = length - (d - spacing)
    return dots


def _paint_trail(p, snapshot, scale):
    """Where HOBBIT drove: dots about 9 pixels apart, older ones fainter and smaller."""
    points = trail(snapshot)
    if len(points) < 2:
        return
    dots = _trail_dots(points, max(0.07, 9.0 / scale))
    radius = max(0.024, 2.2 / scale)
    p.setPen(Qt.PenStyle.NoPen)
    n = len(dots)
    for age in range(TRAIL_AGES):
        lo, hi = n * age // TRAIL_AGES, n * (age + 1) // TRAIL_AGES
        if lo >= hi:
            continue
        t = hi / n
        r = radius * (0.65 + 0.35 * t)
        path = QPainterPath()   # dots of similar age as one path: one draw call, not hundreds
        path.setFillRule(Qt.FillRule.WindingFill)
        for x, y in dots[lo:hi]:
            path.addEllipse(QPointF(x, y), r, r)
        p.setBrush(with_alpha(TRAIL, 0.12 + 0.78 * t))
        p.drawPath(path)


def _paint_goal_ground(p, scene, goal):
    """A target on the floor at the goal, and a dashed line to it while HOBBIT navigates there (map metres)."""
    gx, gy = goal
    if scene.snapshot.get("motion") == "navigating":
        pen = round_pen(with_alpha(GOAL, 0.65), 2.0)
        pen.setCosmetic(True)
        pen.setDashPattern([4, 4])
        p.setPen(pen)
        p.drawLine(QPointF(scene.shown["x"], scene.shown["y"]), QPointF(gx, gy))
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(QColor(0, 0, 0, 28))
    p.drawEllipse(QPointF(gx + 0.02, gy - 0.03), 0.22, 0.22)
    for radius, color in ((0.21, GOAL), (0.15, QColor("#FFFFFF")), (0.09, GOAL), (0.035, QColor("#FFFFFF"))):
        p.setBrush(color)
        p.drawEllipse(QPointF(gx, gy), radius, radius)


def _paint_flag(p, base, scale, phase):
    """A waving flag on a pole standing at ``base`` (widget pixels), upright whatever the map's scale."""
    pole = max(24.0, 0.62 * scale)
    top = QPointF(base.x(), base.y() - pole)
    p.setPen(round_pen(QColor("#4A4F66"), max(2.0, 0.028 * scale)))
    p.drawLine(base, top)
    fw, fh = pole * 0.62, pole * 0.4
    wave = math.sin(phase * 4.0) * fh * 0.12
    flag = QPainterPath(top)
    flag.cubicTo(QPointF(top.x() + fw * 0.35, top.y() - wave), QPointF(top.x() + fw * 0.65, top.y() + wave),
                 QPointF(top.x() + fw, top.y() + fh * 0.5))
    flag.cubicTo(QPointF(top.x() + fw * 0.65, top.y() + fh * 0.5 + wave),
                 QPointF(top.x() + fw * 0.35, top.y() + fh - wave), QPointF(top.x(), top.y() + fh))
    flag.closeSubpath()
    p.setPen(QPen(QColor("#C81E45"), max(1.0, 0.01 * scale)))
    p.setBrush(GOAL)
    p.drawPath(flag)
    star(p, QPointF(top.x() + fw * 0.38, top.y() + fh * 0.5), fh * 0.24, QColor("#FFE066"))
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(QColor("#FFD23F"))
    p.drawEllipse(top, max(2.5, 0.03 * scale), max(2.5, 0.03 * scale))


def _motion_label(snapshot, texts, language):
    """"driving  0.30 m/s", "turning  29°/s", "standing"..."""
    motion = str(snapshot.get("motion") or "idle")
    label = texts["motion"].get(motion, motion)
    linear, angular = num(snapshot.get("linear")), num(snapshot.get("angular"))
    if abs(linear) > 0.005:
        label += f"  {decimal(abs(linear), 2, language)} m/s"
    elif abs(angular) > 0.01:
        label += f"  {abs(math.degrees(angular)):.0f}°/s"
    return motion, label


def _paint_chips(p, scene, rect, u):
    """How HOBBIT moves (bottom left), where it is (bottom right) and the time (top right), where they fit."""
    font, small = scene.font(12 * u, True), scene.font(11 * u)
    fm, fm_small = QFontMetricsF(font), QFontMetricsF(small)
    pad = max(4.0, 6.0 * u)
    motion, label = _motion_label(scene.snapshot, scene.texts, scene.language)
    dot = fm.height() * 0.55
    chip_h = fm.height() + pad
    chip_w = min(rect.width() - 2 * pad, fm.horizontalAdvance(label) + dot + 3 * pad + 4)
    box = QRectF(rect.left() + pad, rect.bottom() - pad - chip_h, chip_w, chip_h)
    chip(p, box)
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(QColor(MOTION_COLOURS.get(motion, MOTION_COLOURS["idle"])))
    p.drawEllipse(QPointF(box.left() + pad + dot / 2, box.center().y()), dot / 2, dot / 2)
    p.setPen(INK)
    p.setFont(font)
    text_rect = box.adjusted(pad * 2 + dot, 0, -pad, 0)
    p.drawText(text_rect, Qt.AlignmentFlag.AlignVCenter | Qt.AlignmentFlag.AlignLeft,
               fm.elidedText(label, Qt.TextElideMode.ElideRight, text_rect.width()))
    # where exactly, for the grown-ups: the latest snapshot's pose, not the eased one
    target = scene.target
    language = scene.language
    where = (f"x {decimal(target['x'], 2, language)}  y {decimal(target['y'], 2, language)} m  "
             f"θ {decimal(math.degrees(wrap_pi(target['theta'])), 0, language)}°")
    where_w = fm_small.horizontalAdvance(where) + 2 * pad
    if box.right() + pad + where_w <= rect.right() - pad:
        _text_chip(p, QRectF(rect.right() - pad - where_w, rect.bottom() - pad - chip_h, where_w, chip_h), where, small)
    clock = f"t {decimal(num(scene.snapshot.get('time')), 1, language)} s"
    clock_w = fm_small.horizontalAdvance(clock) + 2 * pad
    if rect.width() > 3 * clock_w:
        _text_chip(p, QRectF(rect.right() - pad - clock_w, rect.top() + pad, clock_w, fm_small.height() + pad),
                   clock, small)


def _text_chip(p, box, text, font):
    chip(p, box)
    p.setPen(INK_SOFT)
    p.setFont(font)
    p.drawText(box, Qt.AlignmentFlag.AlignCenter, text)
