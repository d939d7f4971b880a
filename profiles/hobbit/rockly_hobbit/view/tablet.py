"""HOBBIT's tablet in the panel: its text at the biggest size that fits, and the answer it waits for.

A waiting tablet (yes/no, OK, a name) glows and shows a "waiting for your answer" caption with
its buttons or input field; in a small panel the caption goes first, then the buttons.
"""
import math

from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QBrush, QColor, QFontMetricsF, QLinearGradient, QPen, QPolygonF

from rockly_desktop.sdk_view import with_alpha, wrap_lines

from .drawing import button
from .palette import HINT, INK
from .snapshot import WAITING_KINDS
from .texts import MIN_TEXT_PX


def _metrics(width, u):
    """(bezel, inner padding, text width) of a tablet ``width`` pixels wide."""
    bezel = max(5.0, 7.0 * u)
    inner_pad = max(5.0, 8.0 * u)
    return bezel, inner_pad, width - 2 * (bezel + inner_pad)


def _gap(u):
    return max(4.0, 6.0 * u)


def _button_height(scene, u):
    return QFontMetricsF(scene.font(13 * u, True)).height() + max(6.0, 8.0 * u)


def _caption_lines(scene, font, width):
    """The "waiting for your answer ..." caption in at most two lines beside the hourglass."""
    icon = QFontMetricsF(font).height() * 0.8
    return wrap_lines(scene.texts["waiting"] + " ...", font, width - icon - 4)[:2]


def _hint_height(scene, kind, text_w, u):
    if kind not in WAITING_KINDS:
        return 0.0
    small = scene.font(11 * u, True)
    lines = len(_caption_lines(scene, small, text_w))
    return lines * QFontMetricsF(small).lineSpacing() + _gap(u) + _button_height(scene, u) + _gap(u)


def tablet_height(scene, width, u):
    """How tall the tablet wants to be at ``width`` pixels to show all its text."""
    bezel, inner_pad, text_w = _metrics(width, u)
    if scene.tablet is None:
        return QFontMetricsF(scene.font(11 * u)).height() + 2 * (bezel + inner_pad)
    kind, text = scene.tablet
    font = scene.font(15 * u, True)
    lines = max(1, len(wrap_lines(text, font, text_w)))
    text_h = lines * QFontMetricsF(font).lineSpacing()
    return text_h + _hint_height(scene, kind, text_w, u) + 2 * (bezel + inner_pad)


def _fitted_text(scene, text, width, height, max_px):
    """(font, lines) for ``text`` in width x height: the biggest size that fits, else elided."""
    cache = scene.text_cache
    key = (text, int(width), int(height), int(max_px), scene.language)
    if key in cache:
        return cache[key]
    size = int(max(MIN_TEXT_PX, max_px))
    while True:
        font = scene.font(size, bold=True)
        fm = QFontMetricsF(font)
        lines = wrap_lines(text, font, width)
        if len(lines) * fm.lineSpacing() <= height + 0.5 or size <= MIN_TEXT_PX:
            break
        size -= 1
    fit = max(1, int((height + 0.5) // fm.lineSpacing()))
    if len(lines) > fit:
        lines = lines[:fit]
        lines[-1] = fm.elidedText(lines[-1] + " …………", Qt.TextElideMode.ElideRight, width)
    if len(cache) > 64:
        cache.clear()
    cache[key] = (font, lines)
    return font, lines


def paint_tablet(p, scene, rect, layout):
    u, radius = layout.u, layout.radius
    bezel, inner_pad, text_w = _metrics(rect.width(), u)
    if scene.tablet is not None and scene.tablet[0] in WAITING_KINDS:
        glow = 0.35 + 0.35 * (0.5 + 0.5 * math.sin(scene.phase * 4.0)) if scene.animate else 0.6
        p.setPen(QPen(with_alpha(QColor("#FFC83D"), glow), max(3.0, 4.0 * u)))
        p.setBrush(Qt.BrushStyle.NoBrush)
        p.drawRoundedRect(rect.adjusted(1, 1, -1, -1), radius, radius)
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(QColor("#343B52"))
    p.drawRoundedRect(rect.adjusted(2, 2, -2, -2), radius, radius)
    screen = rect.adjusted(bezel, bezel, -bezel, -bezel)
    screen_radius = max(4.0, radius - bezel * 0.6)
    if scene.tablet is None:
        p.setBrush(QColor("#4A5270"))
        p.drawRoundedRect(screen, screen_radius, screen_radius)
        small = scene.font(11 * u)
        p.setPen(QColor("#AEB5CE"))
        p.setFont(small)
        p.drawText(screen, Qt.AlignmentFlag.AlignCenter,
                   QFontMetricsF(small).elidedText(scene.texts["tablet_off"], Qt.TextElideMode.ElideRight,
                                                   screen.width() - 4))
        return
    kind, text = scene.tablet
    gradient = QLinearGradient(screen.topLeft(), screen.bottomLeft())
    gradient.setColorAt(0, QColor("#FFFFFF"))
    gradient.setColorAt(1, QColor("#EEF4FF"))
    p.setBrush(QBrush(gradient))
    p.drawRoundedRect(screen, screen_radius, screen_radius)
    content = screen.adjusted(inner_pad, inner_pad, -inner_pad, -inner_pad)
    # in a small dock the hint shrinks to its buttons, then goes: the question comes first
    hint_h, caption = _hint_height(scene, kind, text_w, u), True
    one_line = QFontMetricsF(scene.font(MIN_TEXT_PX, True)).lineSpacing()
    if hint_h and content.height() < hint_h + one_line:
        hint_h, caption = _button_height(scene, u) + _gap(u), False
        if content.height() < hint_h + one_line:
            hint_h = 0.0
    text_box = QRectF(content.left(), content.top(), content.width(), max(0.0, content.height() - hint_h))
    font, lines = _fitted_text(scene, text, text_box.width(), text_box.height(), 15 * u)
    fm = QFontMetricsF(font)
    p.setFont(font)
    p.setPen(INK)
    y = text_box.top()
    for line in lines:
        if y + fm.height() > text_box.bottom() + fm.descent() + 1:
            break
        p.drawText(QRectF(text_box.left(), y, text_box.width(), fm.height()),
                   Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignVCenter, line)
        y += fm.lineSpacing()
    if kind in WAITING_KINDS and hint_h > 0:
        hint = QRectF(content.left(), content.bottom() - hint_h, content.width(), hint_h)
        _paint_answer_hint(p, scene, hint, kind, u, caption)


def _paint_answer_hint(p, scene, rect, kind, u, caption):
    texts = scene.texts
    gap = _gap(u)
    if caption:
        # hourglass + "waiting for your answer" with dots that come and go
        small = scene.font(11 * u, True)
        fm = QFontMetricsF(small)
        icon = fm.height() * 0.8
        top = rect.top() + gap
        _paint_hourglass(p, QRectF(rect.left(), top + (fm.height() - icon) / 2, icon * 0.7, icon))
        dots = int(scene.phase * 2.5) % 4 if scene.animate else 3
        lines = _caption_lines(scene, small, rect.width())
        if lines and lines[-1].endswith("..."):
            lines[-1] = lines[-1][:-3] + "." * dots
        p.setPen(HINT)
        p.setFont(small)
        for i, line in enumerate(lines):
            p.drawText(QRectF(rect.left() + icon, top + i * fm.lineSpacing(), rect.width() - icon, fm.height()),
                       Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignVCenter, line)
    button_font = scene.font(13 * u, True)
    bfm = QFontMetricsF(button_font)
    button_h = _button_height(scene, u)
    row = QRectF(rect.left(), rect.bottom() - button_h - gap * 0.3, rect.width(), button_h)
    p.setFont(button_font)
    if kind == "D_YES_NO":
        half = (row.width() - gap) / 2
        button(p, QRectF(row.left(), row.top(), half, button_h), QColor("#2FBF71"), texts["yes"], bfm)
        button(p, QRectF(row.left() + half + gap, row.top(), half, button_h), QColor("#FF5A5F"), texts["no"], bfm)
    elif kind == "D_OK":
        width = min(row.width(), max(bfm.horizontalAdvance(texts["ok"]) + 4 * gap, row.width() * 0.55))
        button(p, QRectF(row.center().x() - width / 2, row.top(), width, button_h), QColor("#4D8DFF"), texts["ok"], bfm)
    else:
        _paint_name_field(p, scene, row, u, gap)


def _paint_name_field(p, scene, row, u, gap):
    """An input field with a blinking caret and a "type here" placeholder."""
    height = row.height()
    p.setPen(QPen(QColor("#8E9BC4"), max(1.2, 1.5 * u)))
    p.setBrush(QColor("#FFFFFF"))
    p.drawRoundedRect(row, height * 0.3, height * 0.3)
    if int(scene.phase * 2) % 2 == 0 or not scene.animate:
        x = row.left() + gap
        p.setPen(QPen(HINT, 2))
        p.drawLine(QPointF(x, row.top() + height * 0.22), QPointF(x, row.bottom() - height * 0.22))
    font = scene.font(12 * u)
    p.setFont(font)
    p.setPen(QColor("#9AA1B9"))
    p.drawText(row.adjusted(gap + 5, 0, -gap, 0), Qt.AlignmentFlag.AlignVCenter | Qt.AlignmentFlag.AlignLeft,
               QFontMetricsF(font).elidedText(scene.texts["type"], Qt.TextElideMode.ElideRight,
                                              row.width() - 2 * gap - 5))


def _paint_hourglass(p, rect):
    p.setPen(QPen(HINT, 1.4))
    p.setBrush(QColor("#D9D0FF"))
    left, right, top, bottom = rect.left(), rect.right(), rect.top(), rect.bottom()
    cx, cy = rect.center().x(), rect.center().y()
    p.drawPolygon(QPolygonF([QPointF(left, top), QPointF(right, top), QPointF(cx + 1, cy),
                             QPointF(right, bottom), QPointF(left, bottom), QPointF(cx - 1, cy)]))
