"""HobbitSimView, the QWidget: takes snapshots, runs the animation clock, and hands each paint to the painters."""
from PySide6.QtCore import QElapsedTimer, QPointF, QSize, Qt, QTimer
from PySide6.QtGui import QPainter
from PySide6.QtWidgets import QWidget

from .animation import AMBIENT_MS, FRAME_MS, TELEPORT_METRES, Easing
from .details import detail_lines
from .layout import layout_for, map_transform, panel_sections
from .map_painter import paint_map
from .notices import notice_lines
from .palette import PANEL_BG
from .panel import paint_panel
from .room import RoomPixmap
from .scene import Scene
from .snapshot import DEFAULT_SNAPSHOT, merged, sos_active
from .tablet import tablet_words
from .texts import TEXTS


class HobbitSimView(QWidget):
    """A simulated HOBBIT seen from above, with its eyes, battery, tablet and notices."""

    def __init__(self, parent=None, language="en"):
        super().__init__(parent)
        self._language = language if language in TEXTS else "en"
        self._snapshot = dict(DEFAULT_SNAPSHOT)
        self._easing = Easing(self._snapshot)
        self._animate = True
        self._clock = QElapsedTimer()
        self._clock.start()
        self._last_tick = 0.0
        self._timer = QTimer(self)
        self._timer.setTimerType(Qt.TimerType.PreciseTimer)
        self._timer.timeout.connect(self._tick)
        self._room = RoomPixmap()
        self._text_cache = {}
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
        self._text_cache.clear()
        self.update()

    def snapshot(self):
        """The latest snapshot given (a copy)."""
        return dict(self._snapshot)

    def set_snapshot(self, snapshot):
        """Show ``snapshot`` (a dict as ``SimHobbit.snapshot()`` returns; missing keys keep their defaults)."""
        self._snapshot = merged(snapshot)
        jump = self._easing.aim(self._snapshot)
        if not self._animate or not self.isVisible() or jump > TELEPORT_METRES:
            self._easing.arrive()
            self.update()
            return
        # the panel shows the news now; the room follows on the next animation frame
        if self._easing.settled:
            self._last_tick = self._now() - FRAME_MS / 1000.0
        self._easing.settled = False
        self._run_timer(FRAME_MS)
        self.update(self._layout().panel.toAlignedRect())

    def set_animation_enabled(self, enabled):
        """False: draw each snapshot exactly, nothing moves by itself (tests, screenshots)."""
        self._animate = bool(enabled)
        if not self._animate:
            self._timer.stop()
            self._easing.arrive()
        elif self.isVisible():
            self._easing.settled = False
            self._last_tick = self._now()
            self._run_timer(FRAME_MS)
        self.update()

    def animation_enabled(self):
        return self._animate

    def displayed_pose(self):
        """(x, y, theta) as drawn right now; trails the latest snapshot while easing toward it."""
        shown = self._easing.shown
        return shown["x"], shown["y"], shown["theta"]

    def eyes_rect(self):
        """Where HOBBIT's eyes are drawn, in widget pixels."""
        return panel_sections(self._layout(), self._scene())["face"].toAlignedRect()

    def map_rect(self):
        """Where the room is drawn, in widget pixels."""
        return self._layout().map.toAlignedRect()

    def map_to_widget(self, x, y):
        """Widget pixel position of the map point (x, y) metres, for the current size."""
        return map_transform(self._layout().map, self._easing.shown).map(QPointF(x, y))

    def panel_texts(self):
        """The panel's words as drawn now, whole lines (for tests and screen readers): ``tablet`` (the
        question's lines and, when waiting, the caption), ``notices`` (each one's lines) and ``details``
        ((label, value lines) per row; empty when the card has no room)."""
        layout, scene = self._layout(), self._scene()
        sections = panel_sections(layout, scene)
        tablet = sections["tablet"]
        notices = [notice_lines(scene, text, rect.width(), layout.u, index == 0)
                   for index, (rect, text) in enumerate(sections["notices"])]
        details = sections["details"]
        return {
            "tablet": tablet_words(scene, tablet.width(), tablet.height(), layout.u) if tablet is not None else [],
            "notices": notices,
            "details": [(label, [value for value in values if value])
                        for label, values, _progress in detail_lines(scene, details.width(), layout.u)]
            if details is not None else [],
        }

    def sizeHint(self):
        return QSize(640, 480)

    def minimumSizeHint(self):
        return QSize(320, 240)

    # --- animation ----------------------------------------------------------------------

    def showEvent(self, event):
        super().showEvent(event)
        if self._animate:
            self._last_tick = self._now()
            self._run_timer(FRAME_MS if not self._easing.settled else AMBIENT_MS)

    def hideEvent(self, event):
        super().hideEvent(event)
        self._timer.stop()

    def _now(self):
        """Seconds on the view's own clock."""
        return self._clock.elapsed() / 1000.0

    def _run_timer(self, interval):
        """Tick every ``interval`` ms; a running timer is not restarted (that would starve it)."""
        if not self._timer.isActive():
            self._timer.start(interval)
        elif self._timer.interval() != interval:
            self._timer.setInterval(interval)

    def _tick(self):
        now = self._now()
        dt = min(0.1, max(0.0, now - self._last_tick))
        self._last_tick = now
        easing = self._easing
        if not easing.settled:
            gaze_moving = easing.moving(("pan", "tilt"))
            easing.step(dt)
            self._run_timer(AMBIENT_MS if easing.settled else FRAME_MS)
            layout = self._layout()
            self.update(layout.map.adjusted(-2, -2, 2, 2).toAlignedRect())
            if gaze_moving:   # the eyes in the panel look where the head turns
                self.update(layout.panel.toAlignedRect())
            return
        # settled: only the gentle ambient motions need drawing
        if self._snapshot.get("nav_goal") is not None or sos_active(self._snapshot):
            self.update()
        else:
            self.update(self._layout().panel.toAlignedRect())

    # --- painting -----------------------------------------------------------------------

    def _layout(self):
        return layout_for(self.width(), self.height())

    def _scene(self):
        """What this paint draws; the phase is 0 when animation is off (nothing moves by itself)."""
        return Scene(self._snapshot, self._easing.shown, self._easing.target, self._language, self.font(),
                     self._animate, self._now() if self._animate else 0.0, self._text_cache)

    def paintEvent(self, event):
        if self.width() < 10 or self.height() < 10:
            return
        painter = QPainter(self)
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        painter.setRenderHint(QPainter.RenderHint.TextAntialiasing)
        painter.setRenderHint(QPainter.RenderHint.SmoothPixmapTransform)
        layout, scene = self._layout(), self._scene()
        dirty = event.rect()
        painter.fillRect(dirty, PANEL_BG)
        if dirty.intersects(layout.map.adjusted(-2, -2, 2, 2).toAlignedRect()):
            paint_map(painter, layout, scene, self._room, self.devicePixelRatioF())
        if dirty.intersects(layout.panel.toAlignedRect()):
            paint_panel(painter, layout, scene)
        painter.end()
