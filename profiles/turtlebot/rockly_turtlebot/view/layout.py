"""Where things go for one widget size: the map and the panel side by side or stacked, and the map's scale.

All in widget pixels. ``u`` is the size unit: 1 at 640 x 480, so paddings, fonts and lines grow with the view.
"""
from PySide6.QtCore import QRectF
from PySide6.QtGui import QTransform

MARGIN = 0.16   # metres shown around the room (its walls are drawn there)


class Layout:
    """The map's and the panel's rects; ``vertical``: the panel is a column at the right, else a band below."""

    def __init__(self, map_rect, panel_rect, vertical, u):
        self.map, self.panel, self.vertical, self.u = map_rect, panel_rect, vertical, u
        self.radius = max(6.0, 10.0 * u)
        self.gap = max(4.0, 6.0 * u)


def visible_area(room):
    x0, y0, x1, y1 = room
    return x0 - MARGIN, y0 - MARGIN, x1 + MARGIN, y1 + MARGIN


def layout_for(width, height):
    """The map fills what the panel leaves (the room is centred in it); the panel is a column on a wide
    view, a band below on a tall one."""
    w, h = max(1, width), max(1, height)
    u = max(0.5, min(2.5, min(w / 640.0, h / 480.0)))
    gap = max(4.0, 6.0 * u)
    if w >= 1.05 * h:
        pw = max(min(130.0, 0.45 * w), min(0.3 * w, 380.0))
        return Layout(QRectF(gap, gap, w - pw - gap, h - 2 * gap), QRectF(w - pw, 0, pw, h), True, u)
    ph = max(120.0, min(0.55 * w, 0.5 * h, 300.0))
    return Layout(QRectF(gap, gap, w - 2 * gap, h - ph - gap), QRectF(0, h - ph, w, ph), False, u)


def map_transform(rect, room):
    """Map metres (y up) to the pixels of ``rect``, fitting the room and its walls, centred."""
    x0, y0, x1, y1 = visible_area(room)
    scale = max(1e-3, min(rect.width() / (x1 - x0), rect.height() / (y1 - y0)))
    cx, cy = rect.center().x(), rect.center().y()
    mx, my = (x0 + x1) / 2, (y0 + y1) / 2
    return QTransform(scale, 0, 0, -scale, cx - scale * mx, cy + scale * my)
