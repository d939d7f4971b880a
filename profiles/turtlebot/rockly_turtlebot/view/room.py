"""The room under the robot: a floor of foam tiles, low walls and colourful boxes, drawn once per size.

It changes only with the map's size, the room and the boxes, so it is kept as a pixmap.
"""
import math

from PySide6.QtCore import QLineF, QRectF, Qt
from PySide6.QtGui import QPainter, QPainterPath, QPixmap, QTransform

from rockly_desktop.sdk_view import cosmetic_pen, with_alpha

from .palette import BOX_COLOURS, OUTSIDE, SHADOW, TILE_SEAM, TILES, WALL, WALL_TOP

TILE = 0.5     # metres
WALL_THICKNESS = 0.07


class RoomPixmap:
    """The room drawn for one map rect, room and set of boxes, kept until any of them changes."""

    def __init__(self):
        self._key, self._pixmap = None, None

    def get(self, rect, transform, room, boxes, dpr, radius):
        key = (round(rect.width(), 1), round(rect.height(), 1), room, tuple(boxes), dpr, radius)
        if self._key != key:
            self._key, self._pixmap = key, _draw(rect, transform, room, boxes, dpr, radius)
        return self._pixmap


def _draw(rect, transform, room, boxes, dpr, radius):
    pixmap = QPixmap(max(1, math.ceil(rect.width() * dpr)), max(1, math.ceil(rect.height() * dpr)))
    pixmap.setDevicePixelRatio(dpr)
    pixmap.fill(Qt.GlobalColor.transparent)
    p = QPainter(pixmap)
    p.setRenderHint(QPainter.RenderHint.Antialiasing)
    local = QRectF(0, 0, rect.width(), rect.height())
    clip = QPainterPath()
    clip.addRoundedRect(local, radius, radius)
    p.setClipPath(clip)
    p.fillRect(local, OUTSIDE)
    p.setTransform(transform * QTransform.fromTranslate(-rect.left(), -rect.top()))
    _paint_floor(p, room)
    _paint_walls(p, room)
    for index, box in enumerate(boxes):
        paint_box(p, box, index)
    p.end()
    return pixmap


def _paint_floor(p, room):
    x0, y0, x1, y1 = room
    p.setPen(Qt.PenStyle.NoPen)
    ix0, iy0 = math.floor(x0 / TILE), math.floor(y0 / TILE)
    for ix in range(ix0, math.ceil(x1 / TILE)):
        for iy in range(iy0, math.ceil(y1 / TILE)):
            left, bottom = max(x0, ix * TILE), max(y0, iy * TILE)
            right, top = min(x1, (ix + 1) * TILE), min(y1, (iy + 1) * TILE)
            p.setBrush(TILES[(ix + iy) % 2])
            p.drawRect(QRectF(left, bottom, right - left, top - bottom))
    p.setPen(cosmetic_pen(TILE_SEAM, 1.0))
    for ix in range(ix0 + 1, math.ceil(x1 / TILE)):
        if x0 < ix * TILE < x1:
            p.drawLine(QLineF(ix * TILE, y0, ix * TILE, y1))
    for iy in range(iy0 + 1, math.ceil(y1 / TILE)):
        if y0 < iy * TILE < y1:
            p.drawLine(QLineF(x0, iy * TILE, x1, iy * TILE))


def _paint_walls(p, room):
    x0, y0, x1, y1 = room
    t = WALL_THICKNESS
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(with_alpha(SHADOW, 0.6))
    outer = QPainterPath()
    outer.addRect(QRectF(x0 - t, y0 - t, x1 - x0 + 2 * t, y1 - y0 + 2 * t))
    inner = QPainterPath()
    inner.addRect(QRectF(x0, y0, x1 - x0, y1 - y0))
    shadow = QPainterPath()
    shadow.addRect(QRectF(x0, y1 - 0.035, x1 - x0, 0.035))
    shadow.addRect(QRectF(x0, y0, 0.035, y1 - y0))
    p.drawPath(shadow)
    p.setBrush(WALL)
    p.drawPath(outer.subtracted(inner))
    p.setPen(cosmetic_pen(WALL_TOP, 1.5))
    p.setBrush(Qt.BrushStyle.NoBrush)
    p.drawRect(QRectF(x0 - t / 2, y0 - t / 2, x1 - x0 + t, y1 - y0 + t))


def paint_box(p, box, index):
    """A toy crate seen from above: shadow, coloured body, a lighter lid and two strips of tape."""
    x0, y0, x1, y1 = box
    fill, edge = BOX_COLOURS[index % len(BOX_COLOURS)]
    w, h = x1 - x0, y1 - y0
    corner = min(w, h) * 0.12
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(SHADOW)
    p.drawRoundedRect(QRectF(x0 + 0.03, y0 - 0.035, w, h), corner, corner)
    p.setBrush(with_alpha(edge, 1.0))
    p.drawRoundedRect(QRectF(x0, y0, w, h), corner, corner)
    inset = min(w, h) * 0.1
    lid = QRectF(x0 + inset, y0 + inset, w - 2 * inset, h - 2 * inset)
    p.setBrush(with_alpha(fill, 1.0))
    p.drawRoundedRect(lid, corner * 0.6, corner * 0.6)
    p.setBrush(with_alpha(Qt.GlobalColor.white, 0.28))
    strip = min(w, h) * 0.12
    if w >= h:
        p.drawRect(QRectF(lid.center().x() - strip / 2, lid.top(), strip, lid.height()))
    else:
        p.drawRect(QRectF(lid.left(), lid.center().y() - strip / 2, lid.width(), strip))
    p.setBrush(with_alpha(Qt.GlobalColor.white, 0.35))
    p.drawEllipse(QRectF(lid.left() + inset * 0.5, lid.bottom() - inset * 1.5, inset, inset))
