"""HOBBIT's tablet in the panel: its text at the biggest size that fits, and the answer it waits for.

A waiting tablet (yes/no, OK, a name) glows and says to answer in the tablet window, with a
preview of the answers there (flat labels, not buttons: nothing in the view can be clicked).
The question is always shown whole: in a small panel the caption goes first, then the preview.
"""
import math

from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QBrush, QColor, QFontMetricsF, QLinearGradient, QPen, QPolygonF

from rockly_desktop.sdk_view import with_alpha, wrap_lines

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
    """The "answer in the tablet window" caption in at most two lines beside the hourglass."""
    icon = QFontMetricsF(font).height() * 0.8
    return wrap_lines(scene.texts["waiting"], font, width - icon - 4)[:2]


def _hint_height(scene, kind, text_w, u, caption=True, answers=True):
    """Pixels under the question for the caption and the answers' preview that are shown."""
    if kind not in WAITING_KINDS or not answers:
        return 0.0
    height = _button_height(scene, u) + _gap(u)
    if caption:
        small = scene.font(11 * u, True)
        height += len(_caption_lines(scene, small, text_w)) * QFontMetricsF(small).lineSpacing() + _gap(u)
    return height


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
    """(font, lines, whole) for ``text`` in width x height: the biggest size that fits; when even the
    smallest does not, the lines that fit, the last one elided (``whole`` is False)."""
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
    whole = len(lines) <= fit
    if not whole:
        rest = " ".join(lines[fit - 1:])
        lines = lines[:fit - 1] + [fm.elidedText(rest, Qt.TextElideMode.ElideRight, width)]
    if len(cache) > 64:
        cache.clear()
    cache[key] = (font, lines, whole)
    return font, lines, whole


def tablet_plan(scene, content, u):
    """What the tablet's screen ``content`` (a QRectF) shows: (font, question lines, caption?, answers?).

    The question comes first: when it does not fit whole, the caption goes, then the answers' preview.
    """
    kind, text = scene.tablet
    plans = ((True, True), (False, True), (False, False)) if kind in WAITING_KINDS else ((False, False),)
    for caption, answers in plans:
        hint_h = _hint_height(scene, kind, content.width(), u, caption, answers)
        if hint_h > content.height():
            continue
        font, lines, whole = _fitted_text(scene, text, content.width(), content.height() - hint_h, 15 * u)
        if whole:
            return font, lines, caption, answers
    font, lines, _whole = _fitted_text(scene, text, content.width(), content.height(), 15 * u)
    return font, lines, False, False


def tablet_words(scene, width, height, u):
    """The lines a tablet ``width`` x ``height`` pixels shows: the question's, then the caption's if shown."""
    if scene.tablet is None:
        return [scene.texts["tablet_off"]]
    bezel, inner_pad, _text_w = _metrics(width, u)
    content = QRectF(0, 0, width, height).adjusted(bezel + inner_pad, bezel + inner_pad,
                                                   -bezel - inner_pad, -bezel - inner_pad)
    _font, lines, caption, _answers = tablet_plan(scene, content, u)
    if caption:
        lines = lines + _caption_lines(scene, scene.font(11 * u, True), content.width())
    return lines


def paint_tablet(p, scene, rect, layout):
    u, radius = layout.u, layout.radius
    bezel, inner_pad, _text_w = _metrics(rect.width(), u)
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
    kind = scene.tablet[0]
    gradient = QLinearGradient(screen.topLeft(), screen.bottomLeft())
    gradient.setColorAt(0, QColor("#FFFFFF"))
    gradient.setColorAt(1, QColor("#EEF4FF"))
    p.setBrush(QBrush(gradient))
    p.drawRoundedRect(screen, screen_radius, screen_radius)
    content = screen.adjusted(inner_pad, inner_pad, -inner_pad, -inner_pad)
    font, lines, caption, answers = tablet_plan(scene, content, u)
    fm = QFontMetricsF(font)
    p.setFont(font)
    p.setPen(INK)
    for index, line in enumerate(lines):
        p.drawText(QRectF(content.left(), content.top() + index * fm.lineSpacing(), content.width(), fm.height()),
                   Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignVCenter, line)
    if answers:
        hint_h = _hint_height(scene, kind, content.width(), u, caption, answers)
        hint = QRectF(content.left(), content.bottom() - hint_h, content.width(), hint_h)
        _paint_answer_hint(p, scene, hint, kind, u, caption)


def _paint_answer_hint(p, scene, rect, kind, u, caption):
    """Where to answer (the tablet window) and a preview of the answers there: not buttons, as
    nothing here can be clicked."""
    texts = scene.texts
    gap = _gap(u)
    if caption:
        # hourglass + "answer in the tablet window"
        small = scene.font(11 * u, True)
        fm = QFontMetricsF(small)
        icon = fm.height() * 0.8
        top = rect.top() + gap
        _paint_hourglass(p, QRectF(rect.left(), top + (fm.height() - icon) / 2, icon * 0.7, icon))
        p.setPen(HINT)
        p.setFont(small)
        for i, line in enumerate(_caption_lines(scene, small, rect.width())):
            p.drawText(QRectF(rect.left() + icon, top + i * fm.lineSpacing(), rect.width() - icon, fm.height()),
                       Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignVCenter, line)
    answer_font = scene.font(13 * u, True)
    afm = QFontMetricsF(answer_font)
    row_h = _button_height(scene, u)
    row = QRectF(rect.left(), rect.bottom() - row_h - gap * 0.3, rect.width(), row_h)
    p.setFont(answer_font)
    if kind == "D_YES_NO":
        half = (row.width() - gap) / 2
        _answer_preview(p, QRectF(row.left(), row.top(), half, row_h), QColor("#1E9E5A"), texts["yes"], afm)
        _answer_preview(p, QRectF(row.left() + half + gap, row.top(), half, row_h), QColor("#D9363B"),
                        texts["no"], afm)
    elif kind == "D_OK":
        _answer_preview(p, row, QColor("#3B6FD1"), texts["ok"], afm)
    else:
        _paint_name_field(p, scene, row, u, gap)


def _answer_preview(p, rect, colour, label, fm):
    """An answer the tablet window offers, as a flat tinted label: no raised face, no shadow."""
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(with_alpha(colour, 0.12))
    p.drawRoundedRect(rect, 4, 4)
    p.setPen(colour)
    p.drawText(rect, Qt.AlignmentFlag.AlignCenter, fm.elidedText(label, Qt.TextElideMode.ElideRight, rect.width() - 6))


def _paint_name_field(p, scene, row, u, gap):
    """The tablet window's input field, previewed: a dashed outline with its "type here" placeholder."""
    height = row.height()
    pen = QPen(QColor("#8E9BC4"), max(1.2, 1.5 * u))
    pen.setStyle(Qt.PenStyle.DashLine)
    p.setPen(pen)
    p.setBrush(Qt.BrushStyle.NoBrush)
    p.drawRoundedRect(row, height * 0.3, height * 0.3)
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
