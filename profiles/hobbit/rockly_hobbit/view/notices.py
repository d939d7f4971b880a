"""Notices as chips under the tablet: an SOS red with a "!" badge, older ones faded, each in up to
two lines so a German notice is read whole (only a very long one is shortened)."""
from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QColor, QFontMetricsF

from rockly_desktop.sdk_view import card, round_pen, wrap_lines

from .palette import INK, SOS
from .snapshot import is_sos

LEFT = Qt.AlignmentFlag.AlignVCenter | Qt.AlignmentFlag.AlignLeft
MAX_LINES = 2


def _font(scene, text, u, newest):
    return scene.font(12 * u, bold=is_sos(text) or newest)


def _pad(u):
    return max(5.0, 7.0 * u)


def _text_inset(scene, text, u, newest):
    """Pixels of a chip ``text`` is not written in (its badge or bar and paddings)."""
    pad = _pad(u)
    if is_sos(text):
        badge = QFontMetricsF(_font(scene, text, u, newest)).height() * 0.85
        return pad * 2.6 + badge
    return pad * 2.2 + max(3.0, 4 * u)


def notice_lines(scene, text, width, u, newest):
    """The lines ``text`` is written in on a chip ``width`` pixels wide (the last one elided if needed)."""
    font = _font(scene, text, u, newest)
    available = max(1.0, width - _text_inset(scene, text, u, newest))
    lines = wrap_lines(text, font, available) or [""]
    if len(lines) > MAX_LINES:
        rest = " ".join(lines[MAX_LINES - 1:])
        lines = lines[:MAX_LINES - 1] + [QFontMetricsF(font).elidedText(rest, Qt.TextElideMode.ElideRight, available)]
    return lines


def notice_height(scene, text, width, u, newest):
    """How tall the chip for ``text`` is."""
    fm = QFontMetricsF(_font(scene, text, u, newest))
    lines = len(notice_lines(scene, text, width, u, newest))
    return fm.height() + (lines - 1) * fm.lineSpacing() + max(6.0, 8.0 * u)


def paint_notice(p, scene, rect, text, u, newest):
    """One notice as a chip in ``rect``."""
    sos = is_sos(text)
    font = _font(scene, text, u, newest)
    fm = QFontMetricsF(font)
    radius = min(rect.height() * 0.35, (fm.height() + max(6.0, 8.0 * u)) * 0.35)
    pad = _pad(u)
    p.save()
    if not newest and not sos:
        p.setOpacity(0.78)
    if sos:
        p.setPen(Qt.PenStyle.NoPen)
        p.setBrush(SOS)
        p.drawRoundedRect(rect, radius, radius)
        badge = fm.height() * 0.85
        center = QPointF(rect.left() + pad + badge / 2, rect.center().y())
        p.setBrush(QColor("#FFFFFF"))
        p.drawEllipse(center, badge / 2, badge / 2)
        p.setPen(round_pen(SOS, max(2.0, badge * 0.14)))
        p.drawLine(QPointF(center.x(), center.y() - badge * 0.24), QPointF(center.x(), center.y() + badge * 0.05))
        p.drawPoint(QPointF(center.x(), center.y() + badge * 0.24))
        p.setPen(QColor("#FFFFFF"))
    else:
        card(p, rect, radius)
        p.setPen(Qt.PenStyle.NoPen)
        p.setBrush(QColor("#8C5CF0"))
        p.drawRoundedRect(QRectF(rect.left() + pad * 0.6, rect.top() + rect.height() * 0.25, max(3.0, 4 * u),
                                 rect.height() * 0.5), 2, 2)
        p.setPen(INK)
    left = rect.left() + _text_inset(scene, text, u, newest) - pad
    lines = notice_lines(scene, text, rect.width(), u, newest)
    top = rect.center().y() - (fm.height() + (len(lines) - 1) * fm.lineSpacing()) / 2
    p.setFont(font)
    for index, line in enumerate(lines):
        p.drawText(QRectF(left, top + index * fm.lineSpacing(), rect.right() - pad - left, fm.height()), LEFT, line)
    p.restore()
