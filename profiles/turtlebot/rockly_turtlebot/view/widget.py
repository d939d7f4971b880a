"""TurtleBotSimView, the QWidget: takes snapshots and paints the map (with the painters) and the panel."""
import math

from PySide6.QtCore import QPointF, QRectF, QSize, Qt
from PySide6.QtGui import QFontMetricsF, QPainter, QPainterPath, QPen
from PySide6.QtWidgets import QWidget

from rockly_desktop.sdk_view import chip, decimal, sized_font

from . import model
from .layout import layout_for, map_transform
from .palette import BUMP, INK, MAP_BORDER, PANEL_BG
from .panel import ahead_label, paint_panel, speed_rows
from .robot import paint_robot, paint_trail
from .room import RoomPixmap
from .scan import Scan, paint_scan
from .texts import TEXTS

DEFAULT_SNAPSHOT = model.DEFAULT_SNAPSHOT


class TurtleBotSimView(QWidget):
    """A simulated TurtleBot seen from above, with its laser scan, speeds and battery."""

    def __init__(self, parent=None, language="en"):
        super().__init__(parent)
        self._language = language if language in TEXTS else "en"
        self._snapshot = dict(DEFAULT_SNAPSHOT)
        self._scan = Scan(self._snapshot)
        self._room = RoomPixmap()
        self.setAttribute(Qt.WidgetAttribute.WA_OpaquePaintEvent)
        self.setMinimumSize(200, 150)

    # --- public -------------------------------------------------------------------------

    @property
    def language(self):
        """'en' or 'de': the language of the few texts shown."""
        return self._language

    @language.setter
    def language(self, language):
        self._language = language if language in TEXTS else "en"
        self.update()

    def snapshot(self):
        """The latest snapshot given (with defaults for what it left out)."""
        return dict(self._snapshot)

    def set_snapshot(self, snapshot):
        """Show ``snapshot`` (a dict as ``SimTurtleBot.snapshot()`` returns; missing keys keep their defaults)."""
        self._snapshot = model.merged(snapshot)
        self._scan = Scan(self._snapshot)
        self.update()

    def map_rect(self):
        """Where the room is drawn, in widget pixels."""
        return self._layout().map.toAlignedRect()

    def map_to_widget(self, x, y):
        """Widget pixel position of the map point (x, y) metres, for the current size."""
        return map_transform(self._layout().map, model.room(self._snapshot)).map(QPointF(x, y))

    def panel_texts(self):
        """What the panel says now (for tests and screen readers): ``ahead``, ``driving``, ``turning``."""
        texts = TEXTS[self._language]
        driving, turning = speed_rows(self._snapshot, texts)
        return {"ahead": ahead_label(self._scan, texts), "driving": driving[3], "turning": turning[3]}

    def sizeHint(self):
        return QSize(640, 480)

    def minimumSizeHint(self):
        return QSize(320, 240)

    # --- painting -----------------------------------------------------------------------

    def _layout(self):
        return layout_for(self.width(), self.height())

    def paintEvent(self, event):
        if self.width() < 10 or self.height() < 10:
            return
        painter = QPainter(self)
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        painter.setRenderHint(QPainter.RenderHint.TextAntialiasing)
        layout = self._layout()
        painter.fillRect(event.rect(), PANEL_BG)
        self._paint_map(painter, layout)
        paint_panel(painter, layout, self._snapshot, self._scan, TEXTS[self._language], self.font())
        painter.end()

    def _paint_map(self, p, layout):
        rect, snapshot = layout.map, self._snapshot
        if rect.width() < 4 or rect.height() < 4:
            return
        room = model.room(snapshot)
        transform = map_transform(rect, room)
        p.drawPixmap(rect.topLeft(), self._room.get(rect, transform, room, model.boxes(snapshot),
                                                    self.devicePixelRatioF(), layout.radius))
        p.save()
        clip = QPainterPath()
        clip.addRoundedRect(rect, layout.radius, layout.radius)
        p.setClipPath(clip)
        p.setTransform(transform)
        paint_trail(p, snapshot, layout.u)
        paint_scan(p, self._scan, layout.u)
        paint_robot(p, snapshot, self._scan, transform.m11())
        p.resetTransform()
        self._paint_chips(p, layout, transform)
        p.restore()
        p.setPen(QPen(MAP_BORDER, max(1.0, 1.5 * layout.u)))
        p.setBrush(Qt.BrushStyle.NoBrush)
        p.drawRoundedRect(rect, layout.radius, layout.radius)

    def _paint_chips(self, p, layout, transform):
        """The simulated time (top right), the pose (bottom right) and 'Bump!' beside a robot that touches something."""
        u, rect, snapshot, texts = layout.u, layout.map, self._snapshot, TEXTS[self._language]
        font = sized_font(self.font(), 11 * u)
        fm = QFontMetricsF(font)
        p.setFont(font)
        pad, h, margin = 7 * u, fm.height() + 5 * u, 6 * u
        x, y, theta = model.pose(snapshot)
        language = self._language
        clock = f"t {decimal(model.num(snapshot.get('time')), 1, language)} s"
        heading = decimal(math.degrees(theta), 0, language)
        where = f"x {decimal(x, 2, language)}  y {decimal(y, 2, language)} m  θ {heading}°"
        for text, top in ((clock, rect.top() + margin), (where, rect.bottom() - margin - h)):
            width = fm.horizontalAdvance(text) + 2 * pad
            if width > rect.width() - 2 * margin:
                continue
            box = QRectF(rect.right() - margin - width, top, width, h)
            chip(p, box)
            p.setPen(INK)
            p.drawText(box, Qt.AlignmentFlag.AlignCenter, text)
        if snapshot.get("bumped") is True:
            bold = sized_font(self.font(), 12 * u, True)
            p.setFont(bold)
            text = texts["bumped"]
            width = QFontMetricsF(bold).horizontalAdvance(text) + 2 * pad
            at = transform.map(QPointF(x, y))
            box = QRectF(at.x() - width / 2, at.y() - 30 * u - h, width, h)
            box.moveLeft(max(rect.left() + margin, min(box.left(), rect.right() - margin - width)))
            box.moveTop(max(rect.top() + margin, box.top()))
            chip(p, box)
            p.setPen(BUMP)
            p.drawText(box, Qt.AlignmentFlag.AlignCenter, text)
