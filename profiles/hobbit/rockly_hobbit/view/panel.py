"""The side panel: the eyes card with the mood's name, battery and volume, the tablet, notices and the details card."""
import math

from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QColor, QFontMetricsF, QPen, QPolygonF

from rockly_desktop.sdk_view import card, round_pen, with_alpha

from .drawing import arc
from .eyes import paint_eyes
from .layout import panel_sections
from .palette import ARM, EMOTION_ACCENT, INK, INK_SOFT, SOS
from .snapshot import is_sos, num
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
        _paint_notice(p, scene, rect, notice, u, index == 0)
    if sections["details"] is not None:
        _paint_details(p, scene, sections["details"], u)


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


def _paint_notice(p, scene, rect, text, u, newest):
    """One notice as a chip: red with a "!" badge for an SOS, older ones faded."""
    sos = is_sos(text)
    radius = rect.height() * 0.35
    font = scene.font(12 * u, bold=sos or newest)
    fm = QFontMetricsF(font)
    pad = max(5.0, 7.0 * u)
    p.save()
    if not newest and not sos:
        p.setOpacity(0.78)
    if sos:
        p.setPen(Qt.PenStyle.NoPen)
        p.setBrush(SOS)
        p.drawRoundedRect(rect, radius, radius)
        badge = rect.height() * 0.62
        center = QPointF(rect.left() + pad + badge / 2, rect.center().y())
        p.setBrush(QColor("#FFFFFF"))
        p.drawEllipse(center, badge / 2, badge / 2)
        p.setPen(round_pen(SOS, max(2.0, badge * 0.14)))
        p.drawLine(QPointF(center.x(), center.y() - badge * 0.24), QPointF(center.x(), center.y() + badge * 0.05))
        p.drawPoint(QPointF(center.x(), center.y() + badge * 0.24))
        text_rect = rect.adjusted(pad * 1.6 + badge, 0, -pad, 0)
        p.setPen(QColor("#FFFFFF"))
    else:
        card(p, rect, radius)
        p.setPen(Qt.PenStyle.NoPen)
        p.setBrush(QColor("#8C5CF0"))
        p.drawRoundedRect(QRectF(rect.left() + pad * 0.6, rect.top() + rect.height() * 0.25, max(3.0, 4 * u),
                                 rect.height() * 0.5), 2, 2)
        text_rect = rect.adjusted(pad * 1.2 + max(3.0, 4 * u), 0, -pad, 0)
        p.setPen(INK)
    p.setFont(font)
    p.drawText(text_rect, LEFT, fm.elidedText(text, Qt.TextElideMode.ElideRight, text_rect.width()))
    p.restore()


def _detail_rows(scene):
    """(label, value, progress or None) for the arm, gripper, head and turntable."""
    snap, texts = scene.snapshot, scene.texts
    arm, target = str(snap.get("arm") or "home"), snap.get("arm_target")
    progress = num(snap.get("arm_progress"), 0.0, 0.0, 1.0) if target else None
    turntable = (f"{texts['out']} {num(snap.get('turntable_angle')):.0f}°" if snap.get("turntable") == "out"
                 else texts["stored"])
    return [(texts["arm"], f"{arm} → {target}" if target else arm, progress),
            (texts["gripper"], texts["open"] if snap.get("gripper") == "open" else texts["closed"], None),
            (texts["head"], str(snap.get("head") or "center_center"), None),
            (texts["turntable"], turntable, None)]


def _paint_details(p, scene, rect, u):
    """A card listing what the arm, gripper, head and turntable do; a bar shows a moving arm's progress."""
    card(p, rect, max(8.0, 10.0 * u))
    font, bold = scene.font(12 * u), scene.font(12 * u, True)
    fm, fm_bold = QFontMetricsF(font), QFontMetricsF(bold)
    pad = max(5.0, 7.0 * u)
    rows = _detail_rows(scene)
    label_w = max(fm.horizontalAdvance(row[0]) for row in rows) + pad
    y = rect.top() + pad
    for label, value, progress in rows:
        line = QRectF(rect.left() + pad, y, rect.width() - 2 * pad, fm.height())
        p.setFont(font)
        p.setPen(INK_SOFT)
        p.drawText(line, LEFT, fm.elidedText(label, Qt.TextElideMode.ElideRight, line.width() * 0.45))
        value_rect = line.adjusted(min(label_w, line.width() * 0.45), 0, 0, 0)
        if progress is not None:
            bar = QRectF(value_rect.left(), line.bottom() - 1, value_rect.width(), 3)
            p.setPen(Qt.PenStyle.NoPen)
            p.setBrush(QColor("#E3E6F3"))
            p.drawRoundedRect(bar, 1.5, 1.5)
            bar.setWidth(bar.width() * progress)
            p.setBrush(ARM)
            p.drawRoundedRect(bar, 1.5, 1.5)
        p.setFont(bold)
        p.setPen(INK)
        p.drawText(value_rect, Qt.AlignmentFlag.AlignVCenter | Qt.AlignmentFlag.AlignRight,
                   fm_bold.elidedText(value, Qt.TextElideMode.ElideRight, value_rect.width()))
        y += fm.lineSpacing()
