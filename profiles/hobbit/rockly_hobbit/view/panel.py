"""The side panel: the eyes card with the mood's name, battery and volume, the tablet, notices (``notices``)
and the details card (``details``)."""
import math

from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QColor, QFontMetricsF, QPen, QPolygonF

from rockly_desktop.sdk_view import card, round_pen, with_alpha

from .details import paint_details
from .drawing import arc
from .eyes import paint_eyes
from .layout import panel_sections
from .notices import paint_notice
from .palette import EMOTION_ACCENT, INK
from .snapshot import num
from .tablet import paint_tablet

LEFT = Qt.AlignmentFlag.AlignVCenter | Qt.AlignmentFlag.AlignLeft


def paint_panel(p, layout, scene):
    sections = panel_sections(layout, scene)
    u = layout.u
    accent = QColor(EMOTION_ACCENT[scene.emotion])
    card(p, sections["card"], layout.radius, accent)
    paint_eyes(p, scene, sections["face"])
    _paint_mood(p, scene, sections["label"], accent, u)
    _paint_status(p, scene, sections["status"], u)
    if sections["tablet"] is not None:
        p.save()
        p.setClipRect(sections["tablet"].adjusted(-4, -4, 4, 4))
        paint_tablet(p, scene, sections["tablet"], layout)
        p.restore()
    for index, (rect, notice) in enumerate(sections["notices"]):
        paint_notice(p, scene, rect, notice, u, index == 0)
    if sections["details"] is not None:
        paint_details(p, scene, sections["details"], u)


def _paint_mood(p, scene, label, accent, u):
    """The emotion's name under the eyes, after a dot in its accent colour, centred."""
    font = scene.font(13 * u, True)
    fm = QFontMetricsF(font)
    text = scene.texts["emotions"][scene.emotion]
    dot = fm.height() * 0.5
    text_w = min(fm.horizontalAdvance(text), label.width() - dot - 16)
    left = label.center().x() - (text_w + dot + 6) / 2
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(accent)
    p.drawEllipse(QPointF(left + dot / 2, label.center().y()), dot / 2, dot / 2)
    p.setPen(INK)
    p.setFont(font)
    p.drawText(QRectF(left + dot + 6, label.top(), text_w + 2, label.height()), LEFT,
               fm.elidedText(text, Qt.TextElideMode.ElideRight, text_w + 1))


def _battery_colour(battery):
    if battery >= 50:
        return QColor("#2FBF71")
    if battery >= 20:
        return QColor("#FFB020")
    return QColor("#F04444")


def _paint_status(p, scene, rect, u):
    """Battery (blinking when nearly empty) and, where there is room, the volume."""
    snap = scene.snapshot
    battery = num(snap.get("battery"), 100.0, 0.0, 100.0)
    volume = num(snap.get("volume"), 50.0, 0.0, 100.0)
    card(p, rect, max(8.0, 10.0 * u))
    font = scene.font(13 * u, True)
    fm = QFontMetricsF(font)
    pad = max(5.0, 8.0 * u)
    icon_h = min(rect.height() * 0.5, 16 * u + 4)
    icon_w = icon_h * 1.9
    show_volume = rect.width() >= 2 * (icon_w + fm.horizontalAdvance("100%") + 2.5 * pad) - pad
    half = rect.width() / 2 if show_volume else rect.width()
    body = QRectF(rect.left() + pad, rect.center().y() - icon_h / 2, icon_w, icon_h)
    colour = _battery_colour(battery)
    blink = 1.0
    if battery < 15 and scene.animate:
        blink = 0.45 + 0.55 * (0.5 + 0.5 * math.sin(scene.phase * 5.0))
    p.setPen(QPen(INK, max(1.5, 2.0 * u)))
    p.setBrush(QColor("#FFFFFF"))
    p.drawRoundedRect(body, icon_h * 0.22, icon_h * 0.22)
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(INK)
    nub = QRectF(body.right() + 1, body.center().y() - icon_h * 0.2, icon_h * 0.16, icon_h * 0.4)
    p.drawRoundedRect(nub, 1.5, 1.5)
    inset = max(2.5, 3.0 * u)
    fill = body.adjusted(inset, inset, -inset, -inset)
    fill.setWidth(max(0.0, fill.width() * battery / 100.0))
    if fill.width() > 0.5:
        p.setBrush(with_alpha(colour, blink))
        p.drawRoundedRect(fill, 2, 2)
    p.setPen(colour.darker(135) if battery < 50 else INK)
    p.setFont(font)
    p.drawText(QRectF(body.right() + pad * 0.9, rect.top(), half - icon_w - 1.9 * pad, rect.height()), LEFT,
               f"{battery:.0f}%")
    if show_volume:
        _paint_volume(p, rect, half, icon_h, pad, u, volume, font)


def _paint_volume(p, rect, half, h, pad, u, volume, font):
    """In the right ``half`` of ``rect``: a loudspeaker with up to three waves (crossed out when muted),
    and the percentage."""
    left = rect.left() + half + pad * 0.5
    cy = rect.center().y()
    speaker = QPolygonF([QPointF(left, cy - h * 0.2), QPointF(left + h * 0.3, cy - h * 0.2),
                         QPointF(left + h * 0.65, cy - h * 0.5), QPointF(left + h * 0.65, cy + h * 0.5),
                         QPointF(left + h * 0.3, cy + h * 0.2), QPointF(left, cy + h * 0.2)])
    p.setPen(QPen(INK, 1.2))
    p.setBrush(INK)
    p.drawPolygon(speaker)
    waves = 0 if volume <= 0 else 1 if volume < 34 else 2 if volume < 67 else 3
    p.setPen(round_pen(INK, max(1.5, 1.8 * u)))
    p.setBrush(Qt.BrushStyle.NoBrush)
    for k in range(waves):
        p.drawPolyline(QPolygonF(arc(left + h * 0.6, cy, h * (0.3 + 0.22 * k), -45, 45, 10)))
    if waves == 0:
        x = left + h * 0.9
        p.drawLine(QPointF(x, cy - h * 0.2), QPointF(x + h * 0.4, cy + h * 0.2))
        p.drawLine(QPointF(x, cy + h * 0.2), QPointF(x + h * 0.4, cy - h * 0.2))
    p.setPen(INK)
    p.setFont(font)
    p.drawText(QRectF(left + h * 1.45 + pad * 0.4, rect.top(), half - h * 1.45 - pad, rect.height()), LEFT,
               f"{volume:.0f}%")
