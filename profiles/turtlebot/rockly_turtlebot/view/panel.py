"""The panel beside (or below) the map: a radar of the laser, the speeds, and the battery.

In a column (``layout.vertical``) the three cards are stacked; in a band the radar stands on
the left and the speeds and the battery on the right. Heights come from the fonts, so the
texts never overlap at any size.
"""
import math

from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QFontMetricsF, QPen

from rockly_desktop.sdk import AHEAD_HALF_WIDTH
from rockly_desktop.sdk_view import card, decimal, sized_font, with_alpha

from . import model
from .palette import (
    BAR_BG,
    BATTERY_EMPTY,
    BATTERY_LOW,
    BATTERY_OK,
    DRIVE,
    INK,
    INK_SOFT,
    PLATE,
    RADAR_BG,
    RADAR_RING,
    TURN,
    distance_colour,
)
from .scan import paint_radar_hits

RADAR_RINGS = (0.5, 1.0, 2.0, 3.5)    # metres; the radar's scale is the square root of the distance
MAX_LINEAR, MAX_ANGULAR = 0.22, 2.84


class Fonts:
    def __init__(self, base, u):
        self.title = sized_font(base, 12 * u, True)
        self.small = sized_font(base, 11 * u)
        self.big = sized_font(base, 16 * u, True)
        self.title_h = QFontMetricsF(self.title).height()
        self.small_h = QFontMetricsF(self.small).height()
        self.big_h = QFontMetricsF(self.big).height()


def panel_cards(layout, fonts):
    """The three cards' rects: laser, speed, battery."""
    u, panel, gap = layout.u, layout.panel, layout.gap
    pad = max(4.0, 7.0 * u)
    bar = max(4.0, 6.0 * u)
    speed_h = 2 * pad + fonts.title_h + 2 * (fonts.small_h + bar + pad)
    battery_h = 2 * pad + max(fonts.title_h, 16.0 * u)
    if layout.vertical:
        inner = panel.adjusted(0, gap, -gap, -gap)
        laser_h = max(30.0, inner.height() - speed_h - battery_h - 2 * gap)
        laser = QRectF(inner.left(), inner.top(), inner.width(), laser_h)
        speed = QRectF(inner.left(), laser.bottom() + gap, inner.width(), speed_h)
        battery = QRectF(inner.left(), speed.bottom() + gap, inner.width(), battery_h)
    else:
        inner = panel.adjusted(gap, 0, -gap, -gap)
        laser_w = min(inner.width() * 0.45, inner.height())
        laser = QRectF(inner.left(), inner.top(), laser_w, inner.height())
        right = QRectF(laser.right() + gap, inner.top(), inner.right() - laser.right() - gap, inner.height())
        spare = max(0.0, right.height() - speed_h - battery_h - gap)
        speed = QRectF(right.left(), right.top(), right.width(), speed_h + spare / 2)
        battery = QRectF(right.left(), speed.bottom() + gap, right.width(),
                         max(0.0, right.bottom() - speed.bottom() - gap))
    return laser, speed, battery, pad


def paint_panel(p, layout, snapshot, scan, texts, base_font):
    """``scan`` is the snapshot's view.scan.Scan."""
    fonts = Fonts(base_font, layout.u)
    laser, speed, battery, pad = panel_cards(layout, fonts)
    for rect in (laser, speed, battery):
        if rect.height() > 8 and rect.width() > 8:
            card(p, rect, layout.radius)
    _paint_laser(p, laser.adjusted(pad, pad, -pad, -pad), snapshot, scan, texts, fonts)
    _paint_speed(p, speed.adjusted(pad, pad, -pad, -pad), snapshot, texts, fonts, layout.u)
    _paint_battery(p, battery.adjusted(pad, 0, -pad, 0), snapshot, texts, fonts, layout.u)


def _title(p, rect, text, fonts):
    p.setFont(fonts.title)
    p.setPen(INK_SOFT)
    p.drawText(QRectF(rect.left(), rect.top(), rect.width(), fonts.title_h),
               Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignVCenter, text)
    return rect.top() + fonts.title_h


def _paint_laser(p, rect, snapshot, scan, texts, fonts):
    """A round radar (ahead is up) with every hit as a dot, and the distance straight ahead in big."""
    if rect.height() < fonts.title_h:
        return
    top = _title(p, rect, texts["laser"], fonts)
    far = scan.far
    ahead = scan.nearest_ahead()
    text_h = fonts.big_h
    size = max(0.0, min(rect.width(), rect.bottom() - top - text_h - 4))
    if size >= 30:
        top += max(0.0, (rect.bottom() - top - text_h - 4 - size) / 2)   # radar and number centred in the card
        _paint_radar(p, QPointF(rect.center().x(), top + 2 + size / 2), size / 2, scan, far)
        text_top = top + 4 + size
    else:
        text_top = top
    p.setFont(fonts.big if ahead is not None else fonts.small)
    p.setPen(distance_colour(ahead).darker(140) if ahead is not None else INK_SOFT)
    label = ahead_label(scan, texts)
    text_rect = QRectF(rect.left(), text_top, rect.width(), text_h)
    p.drawText(text_rect, Qt.AlignmentFlag.AlignCenter,
               p.fontMetrics().elidedText(label, Qt.TextElideMode.ElideRight, int(rect.width())))


def ahead_label(scan, texts):
    """"ahead 1.21 m" (what the robot's commands and the Robot state panel call ahead), or "nothing in sight"."""
    ahead = scan.nearest_ahead()
    return f"{texts['ahead']} {decimal(ahead, 2, texts['language'])} m" if ahead is not None else texts["nothing"]


def speed_rows(snapshot, texts):
    """(label, value, fastest, text, colour) of driving (m/s) and turning (°/s, as people read it; the
    robot's own unit is rad/s)."""
    language = texts["language"]
    linear, angular = model.num(snapshot.get("linear")), math.degrees(model.num(snapshot.get("angular")))
    return ((texts["driving"], linear, MAX_LINEAR, f"{decimal(linear, 2, language, sign=True)} m/s", DRIVE),
            (texts["turning"], angular, math.degrees(MAX_ANGULAR), f"{decimal(angular, 0, language, sign=True)} °/s",
             TURN))


def _radar_point(centre, radius, angle, distance, far):
    r = radius * math.sqrt(min(1.0, distance / far))
    return QPointF(centre.x() + r * math.cos(angle), centre.y() - r * math.sin(angle))


def _paint_radar(p, centre, radius, scan, far):
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(RADAR_BG)
    p.drawEllipse(centre, radius, radius)
    p.setBrush(Qt.BrushStyle.NoBrush)
    p.setPen(QPen(RADAR_RING, 1.0))
    for metres in RADAR_RINGS:
        ring = radius * math.sqrt(min(1.0, metres / far))
        p.drawEllipse(centre, ring, ring)
    # the sector the robot calls "ahead"
    p.setPen(QPen(with_alpha(RADAR_RING, 0.6), 1.0))
    for side in (-1, 1):
        p.drawLine(centre, _radar_point(centre, radius, math.pi / 2 + side * AHEAD_HALF_WIDTH, far, far))
    paint_radar_hits(p, scan, centre, radius, max(2.0, radius / 30))
    body = max(3.0, radius * math.sqrt(model.RADIUS / far))
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(PLATE)
    p.drawEllipse(centre, body, body)
    p.setBrush(with_alpha(Qt.GlobalColor.white, 0.9))
    p.drawPolygon([QPointF(centre.x(), centre.y() - body * 0.8),
                   QPointF(centre.x() - body * 0.5, centre.y() + body * 0.4),
                   QPointF(centre.x() + body * 0.5, centre.y() + body * 0.4)])


def _paint_speed(p, rect, snapshot, texts, fonts, u):
    """Two bars from the middle: how fast it drives and turns (``speed_rows``); left of the middle is
    backward/right."""
    if rect.height() < fonts.title_h:
        return
    top = _title(p, rect, texts["speed"], fonts)
    rows = speed_rows(snapshot, texts)
    bar_h = max(4.0, 6.0 * u)
    row_h = fonts.small_h + bar_h + max(4.0, 8.0 * u)
    top += max(0.0, (rect.bottom() - top - 2 * row_h) / 2)      # the two rows centred in the card
    p.setFont(fonts.small)
    fm = p.fontMetrics()
    for k, (label, value, top_speed, number, colour) in enumerate(rows):
        y = top + k * row_h + 2
        if y + fonts.small_h + bar_h > rect.bottom() + 2:
            break
        text_rect = QRectF(rect.left(), y, rect.width(), fonts.small_h)
        p.setPen(INK)
        p.drawText(text_rect, Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter, number)
        room = rect.width() - fm.horizontalAdvance(number) - 6
        if room > 12:
            p.setPen(INK_SOFT)
            p.drawText(text_rect, Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignVCenter,
                       fm.elidedText(label, Qt.TextElideMode.ElideRight, int(room)))
        bar = QRectF(rect.left(), text_rect.bottom() + 2, rect.width(), bar_h)
        p.setPen(Qt.PenStyle.NoPen)
        p.setBrush(BAR_BG)
        p.drawRoundedRect(bar, bar_h / 2, bar_h / 2)
        share = max(-1.0, min(1.0, value / top_speed))
        middle = bar.center().x()
        filled = QRectF(min(middle, middle + share * bar.width() / 2), bar.top(), abs(share) * bar.width() / 2, bar_h)
        p.setBrush(colour)
        p.drawRoundedRect(filled, bar_h / 2, bar_h / 2)
        p.setBrush(INK_SOFT)
        p.drawRect(QRectF(middle - 0.5, bar.top() - 1, 1.0, bar_h + 2))


def _paint_battery(p, rect, snapshot, texts, fonts, u):
    """A battery that empties from the right and turns orange then red, with percent and volts."""
    if rect.height() < 10:
        return
    level = model.num(snapshot.get("battery"), 100.0, 0.0, 100.0)
    volts = model.num(snapshot.get("voltage"), math.nan)
    colour = BATTERY_OK if level > 30 else BATTERY_LOW if level > 10 else BATTERY_EMPTY
    h = min(rect.height() - 6, max(12.0, 16.0 * u))
    body = QRectF(rect.left(), rect.center().y() - h / 2, h * 1.9, h)
    line = max(1.2, 1.5 * u)
    p.setPen(QPen(INK, line))
    p.setBrush(Qt.BrushStyle.NoBrush)
    p.drawRoundedRect(body, h * 0.18, h * 0.18)
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(INK)
    p.drawRoundedRect(QRectF(body.right(), body.center().y() - h * 0.2, h * 0.15, h * 0.4), 1, 1)
    inner = body.adjusted(line + 1.5, line + 1.5, -line - 1.5, -line - 1.5)
    p.setBrush(colour)
    p.drawRoundedRect(QRectF(inner.left(), inner.top(), inner.width() * level / 100, inner.height()), 1.5, 1.5)
    p.setFont(fonts.title)
    text = f"{level:.0f} %" + (f"   {decimal(volts, 1, texts['language'])} V" if math.isfinite(volts) else "")
    text_rect = QRectF(body.right() + h * 0.15 + 6 * u, rect.top(), rect.right() - body.right() - h * 0.15 - 6 * u,
                       rect.height())
    p.setPen(INK)
    p.drawText(text_rect, Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignVCenter,
               p.fontMetrics().elidedText(text, Qt.TextElideMode.ElideRight, int(max(1.0, text_rect.width()))))
