"""Where things go for one widget size: map and panel side by side or stacked, the map's scale, the panel's parts.

All in widget pixels. ``u`` is the size unit: 1 at 640 x 480, so paddings, fonts and lines grow with the view.
"""
from PySide6.QtCore import QRectF
from PySide6.QtGui import QFontMetricsF, QTransform

from .details import details_height
from .notices import notice_height
from .tablet import tablet_height


class Layout:
    """The map's and the panel's rects; ``vertical``: the panel is a column at the right, else a band below."""

    def __init__(self, map_rect, panel_rect, vertical, u):
        self.map, self.panel, self.vertical, self.u = map_rect, panel_rect, vertical, u
        self.radius = max(8.0, 12.0 * u)     # corners of the map, the eyes card and the tablet


def layout_for(width, height):
    w, h = max(1, width), max(1, height)
    u = max(0.5, min(2.5, min(w / 640.0, h / 480.0)))
    gap = max(4.0, 6.0 * u)
    if w >= 1.05 * h:
        pw = max(130.0, min(0.31 * w, 560.0))
        return Layout(QRectF(gap, gap, w - pw - gap, h - 2 * gap), QRectF(w - pw, 0, pw, h), True, u)
    ph = max(120.0, min(0.36 * h, 320.0))
    return Layout(QRectF(gap, gap, w - 2 * gap, h - ph - gap), QRectF(0, h - ph, w, ph), False, u)


def map_transform(rect, shown):
    """Map metres (y up) to the pixels of ``rect``, fitting the visible area the eased values say."""
    bw, bh = max(0.1, shown["bx1"] - shown["bx0"]), max(0.1, shown["by1"] - shown["by0"])
    scale = max(1e-3, min(rect.width() / bw, rect.height() / bh))
    cx, cy = rect.center().x(), rect.center().y()
    mx, my = (shown["bx0"] + shown["bx1"]) / 2, (shown["by0"] + shown["by1"]) / 2
    return QTransform(scale, 0, 0, -scale, cx - scale * mx, cy + scale * my)


def panel_sections(layout, scene):
    """Rects of the panel's parts: card (of the eyes), face, label, status, tablet, notices [(rect, text)], details.

    tablet and details are None where they do not fit.
    """
    u, panel = layout.u, layout.panel
    pad = max(6.0, 8.0 * u)
    card_pad = max(5.0, 7.0 * u)
    label_h = QFontMetricsF(scene.font(13 * u, True)).height()
    status_h = max(24.0, 30.0 * u)
    sections = {}
    if layout.vertical:
        inner = panel.adjusted(0, pad, -pad, -pad)
        width = inner.width()
        face_h = min(width * 0.5, panel.height() * 0.3)
        card = QRectF(inner.left(), inner.top(), width, face_h + label_h + 2.5 * card_pad)
        top = card.bottom() + pad
        sections["status"] = QRectF(inner.left(), top, width, status_h)
        top += status_h + pad
        rest = QRectF(inner.left(), top, width, max(0.0, inner.bottom() - top))
    else:
        inner = panel.adjusted(pad, 0, -pad, -pad)
        room_h = max(40.0, inner.height() - status_h - pad)
        left_w = min(inner.width() * 0.44, (room_h - label_h - 2.5 * card_pad) * 2.0 + 2 * card_pad)
        face_h = min(room_h - label_h - 2.5 * card_pad, (left_w - 2 * card_pad) * 0.55)
        card = QRectF(inner.left(), inner.top(), left_w, face_h + label_h + 2.5 * card_pad)
        sections["status"] = QRectF(inner.left(), card.bottom() + pad, left_w, status_h)
        rest = QRectF(card.right() + pad, inner.top(), inner.right() - card.right() - pad, inner.height())
    sections["card"] = card
    face = QRectF(card.left() + card_pad, card.top() + card_pad, card.width() - 2 * card_pad, max(10.0, face_h))
    sections["face"] = face
    sections["label"] = QRectF(card.left(), face.bottom() + card_pad * 0.4, card.width(), label_h)
    # tablet first (it may be a question someone must answer), then what the arm, gripper, head and
    # turntable are doing (kept at the bottom in either layout: it never gives way to notices), then
    # the notices below the tablet in what is left, newest first
    notices = scene.notices[-3:][::-1]
    heights = [notice_height(scene, text, rest.width(), u, index == 0) for index, text in enumerate(notices)]
    tablet_h = min(rest.height(), tablet_height(scene, rest.width(), u))
    details_h = details_height(scene, rest.width(), u)
    room = rest.height() - tablet_h - (pad if tablet_h > 0 else 0)
    sections["details"] = None
    if room >= details_h:
        sections["details"] = QRectF(rest.left(), rest.bottom() - details_h, rest.width(), details_h)
        room -= details_h + pad
    n = _fitting(heights, room, pad)
    if notices and n == 0 and tablet_h > 0 and scene.snapshot.get("tablet") is None:
        # a tablet that is off gives way to the notices
        room += tablet_h + pad
        tablet_h, n = 0.0, _fitting(heights, room, pad)
    sections["tablet"] = QRectF(rest.left(), rest.top(), rest.width(), tablet_h) if tablet_h > 0 else None
    top = rest.top() + (tablet_h + pad if tablet_h > 0 else 0)
    sections["notices"] = []
    for text, height in zip(notices[:n], heights[:n], strict=True):
        sections["notices"].append((QRectF(rest.left(), top, rest.width(), height), text))
        top += height + pad * 0.5
    return sections


def _fitting(heights, room, pad):
    """How many of the chips ``heights`` (in order, ``pad`` / 2 apart) fit in ``room`` pixels."""
    count, used = 0, 0.0
    for height in heights:
        used += height + (pad * 0.5 if count else 0.0)
        if used > room:
            break
        count += 1
    return count
