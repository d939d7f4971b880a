"""The room under the robot: lawn and garden, wooden floor, furniture, walls with door and window, metre grid.

It changes only with the map's size and visible area, so it is drawn once into a pixmap and reused.
"""
import math

from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QColor, QPainter, QPixmap, QPolygonF, QTransform

from rockly_desktop.sdk_view import cosmetic_pen, round_pen

from ..world import WORLD
from .drawing import arc, rounded
from .furniture import paint_furniture
from .geometry import DOOR, ROOM, WALL, WINDOW
from .palette import GRID, LAWN, SEAM, WALL_EDGE, WALL_FILL, WOOD

PLANK = 0.2   # metres


class RoomPixmap:
    """The room drawn for one map size and visible area, kept until either changes."""

    def __init__(self):
        self._key, self._pixmap = None, None

    def get(self, rect, transform, shown, dpr, radius):
        """The room for the map at ``rect`` (widget pixels) seen through ``transform``, clipped to round corners."""
        key = (int(rect.width()), int(rect.height()), round(shown["bx0"], 3), round(shown["by0"], 3),
               round(shown["bx1"], 3), round(shown["by1"], 3), dpr)
        if self._key != key:
            self._key, self._pixmap = key, _draw(rect, transform, shown, dpr, radius)
        return self._pixmap


def _draw(rect, transform, shown, dpr, radius):
    pixmap = QPixmap(max(1, int(math.ceil(rect.width() * dpr))), max(1, int(math.ceil(rect.height() * dpr))))
    pixmap.setDevicePixelRatio(dpr)
    pixmap.fill(Qt.GlobalColor.transparent)
    p = QPainter(pixmap)
    p.setRenderHint(QPainter.RenderHint.Antialiasing)
    local = QRectF(0, 0, rect.width(), rect.height())
    p.setClipPath(rounded(local, radius))
    p.fillRect(local, LAWN)
    p.setTransform(transform * QTransform.fromTranslate(-rect.left(), -rect.top()))
    _paint_garden(p, shown)
    _paint_floor(p)
    paint_furniture(p)
    _paint_walls(p)
    _paint_grid(p, shown)
    _paint_origin(p, transform.m11())
    p.end()
    return pixmap


def _paint_garden(p, shown):
    """Grass tufts and little flowers on the lawn around the house, the same wherever the view is."""
    x0, y0, x1, y1 = ROOM
    step = 0.55
    tuft = round_pen(QColor("#9CD18A"), 0.022)
    petals = (QColor("#FFFFFF"), QColor("#FFD166"), QColor("#FF9EC4"), QColor("#B9A5FF"))
    for ix in range(math.floor(shown["bx0"] / step) - 1, math.ceil(shown["bx1"] / step) + 2):
        for iy in range(math.floor(shown["by0"] / step) - 1, math.ceil(shown["by1"] / step) + 2):
            h = ((ix * 73856093) ^ (iy * 19349663)) & 0xFFFF
            x = (ix + (h % 97) / 97.0) * step
            y = (iy + ((h >> 7) % 89) / 89.0) * step
            if x0 - WALL - 0.08 < x < x1 + WALL + 0.08 and y0 - WALL - 0.08 < y < y1 + WALL + 0.08:
                continue
            if h % 5 == 0:
                p.setPen(Qt.PenStyle.NoPen)
                p.setBrush(petals[(h >> 3) % len(petals)])
                for k in range(5):
                    a = math.radians(k * 72 + h % 60)
                    p.drawEllipse(QPointF(x + 0.035 * math.cos(a), y + 0.035 * math.sin(a)), 0.028, 0.028)
                p.setBrush(QColor("#FFB020"))
                p.drawEllipse(QPointF(x, y), 0.022, 0.022)
            else:
                p.setPen(tuft)
                for dx, lean in ((-0.03, -0.03), (0.0, 0.0), (0.03, 0.03)):
                    p.drawLine(QPointF(x + dx, y), QPointF(x + dx + lean, y + 0.07 - abs(dx)))


def _planks(row):
    """(left x, length, index) of the planks in floor row ``row``, staggered from row to row."""
    x = ROOM[0] - (row * 0.73) % 1.6
    k = 0
    while x < ROOM[2]:
        length = 1.1 + ((row * 7 + k * 3) % 5) * 0.18
        yield x, length, k
        x += length
        k += 1


def _paint_floor(p):
    x0, y0, x1, y1 = ROOM
    rows = int(round((y1 - y0) / PLANK))
    p.setPen(Qt.PenStyle.NoPen)
    for row in range(rows):
        y = y0 + row * PLANK
        for x, length, k in _planks(row):
            left, right = max(x, x0), min(x + length, x1)
            if right > left:
                p.setBrush(WOOD[(row * 3 + k) % len(WOOD)])
                p.drawRect(QRectF(left, y, right - left, PLANK))
    p.setPen(cosmetic_pen(SEAM, 1.0))
    for row in range(1, rows):
        y = y0 + row * PLANK
        p.drawLine(QPointF(x0, y), QPointF(x1, y))
    for row in range(rows):
        y = y0 + row * PLANK
        for x, length, _ in _planks(row):
            if x0 < x + length < x1:
                p.drawLine(QPointF(x + length, y), QPointF(x + length, y + PLANK))


def _paint_walls(p):
    x0, y0, x1, y1 = ROOM
    t = WALL
    edge = cosmetic_pen(WALL_EDGE, 1.2)
    pieces = [QRectF(bx0, by0, bx1 - bx0, by1 - by0) for bx0, by0, bx1, by1 in
              (wall.bounds for wall in WORLD.obstacles if wall.kind == "wall")]
    p.setPen(edge)
    p.setBrush(WALL_FILL)
    for piece in pieces:
        p.drawRect(piece)
    # window in the top wall
    p.setBrush(QColor("#BFE6FF"))
    p.drawRect(QRectF(WINDOW[0], y1 + t * 0.25, WINDOW[1] - WINDOW[0], t * 0.5))
    p.setPen(cosmetic_pen(QColor("#FFFFFF"), 1.5))
    mid = (WINDOW[0] + WINDOW[1]) / 2
    p.drawLine(QPointF(mid, y1 + t * 0.3), QPointF(mid, y1 + t * 0.7))
    # door, swung open into the room
    width = DOOR[1] - DOOR[0]
    swing = cosmetic_pen(QColor(110, 100, 170, 110), 1.2)
    swing.setDashPattern([3, 3])
    p.setPen(swing)
    p.setBrush(Qt.BrushStyle.NoBrush)
    p.drawPolyline(QPolygonF(arc(DOOR[0], y0, width, 0, 90, 16, y_down=False)))
    p.setPen(edge)
    p.setBrush(QColor("#C79466"))
    p.drawRect(QRectF(DOOR[0] - 0.02, y0, 0.05, width))


def _paint_grid(p, shown):
    """A line every metre across the visible area."""
    p.setPen(cosmetic_pen(GRID, 1.0))
    for x in range(math.ceil(shown["bx0"]), math.floor(shown["bx1"]) + 1):
        p.drawLine(QPointF(x, shown["by0"] - 1), QPointF(x, shown["by1"] + 1))
    for y in range(math.ceil(shown["by0"]), math.floor(shown["by1"]) + 1):
        p.drawLine(QPointF(shown["bx0"] - 1, y), QPointF(shown["bx1"] + 1, y))


def _paint_origin(p, scale):
    """Small x (red) and y (green) arrows at the map origin, for whoever wants coordinates."""
    length, head = 0.38, 0.07
    for (dx, dy), colour in (((1, 0), QColor(230, 70, 70, 150)), ((0, 1), QColor(40, 170, 90, 150))):
        p.setPen(round_pen(colour, max(0.018, 2.0 / scale)))
        end = QPointF(dx * length, dy * length)
        p.drawLine(QPointF(0, 0), end)
        p.drawLine(end, QPointF(end.x() - dx * head - dy * head * 0.6, end.y() - dy * head - dx * head * 0.6))
        p.drawLine(end, QPointF(end.x() - dx * head + dy * head * 0.6, end.y() - dy * head + dx * head * 0.6))
