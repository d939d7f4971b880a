"""The timeline bar under the workspace: a scrubber over a recorded run, play at 0.25×–4×, markers.

The bar knows only times: it says ``sig_moment(seconds)`` when the person drags, plays or
clicks a marker, and ``sig_closed`` when they close it. What a moment shows is the
replay's business (``ui/replay/replay.py``).
"""
import math
import time

from PySide6.QtCore import QRectF, Qt, QTimer, Signal
from PySide6.QtGui import QColor, QPainter
from PySide6.QtWidgets import QComboBox, QHBoxLayout, QLabel, QSlider, QStyle, QToolButton, QVBoxLayout, QWidget

from rockly_desktop.ui.plain_text import tooltip_text
from rockly_desktop.ui.texts import tr

SPEEDS = (0.25, 0.5, 1.0, 2.0, 4.0)
PLAY_MS = 33
_COLOURS = {"error": "#d32f2f", "pause": "#f9a825", "breakpoint": "#1565c0", "bump": "#6a1b9a", "goal": "#2e7d32"}
_CLICK_PIXELS = 6


class MarkerStrip(QWidget):
    """Coloured ticks at the markers' times; a click near one says ``sig_jump(time)``."""

    sig_jump = Signal(float)

    def __init__(self, language, parent=None):
        super().__init__(parent)
        self.setFixedHeight(10)
        self.setMouseTracking(True)
        self.markers = []
        self.duration = 0.0
        self._language = language

    def _x(self, seconds: float) -> float:
        margin = 8  # about where the slider's groove begins and ends
        return margin + (self.width() - 2 * margin) * (seconds / self.duration if self.duration else 0.0)

    def nearest(self, x: float):
        """The marker drawn nearest ``x`` (within a few pixels), or None."""
        close = [(abs(self._x(marker.time) - x), marker) for marker in self.markers]
        close = [item for item in close if item[0] <= _CLICK_PIXELS]
        return min(close, key=lambda item: item[0])[1] if close else None

    def paintEvent(self, _event):
        """Qt override: one tick per marker."""
        painter = QPainter(self)
        for marker in self.markers:
            painter.fillRect(QRectF(self._x(marker.time) - 1.5, 0, 3, self.height()), QColor(_COLOURS[marker.kind]))

    def mouseMoveEvent(self, event):
        """Qt override: the marker under the pointer as a tooltip."""
        marker = self.nearest(event.position().x())
        language = self._language.code
        self.setToolTip(tooltip_text(tr(f"marker_{marker.kind}", language, text=marker.text)) if marker else "")

    def mousePressEvent(self, event):
        """Qt override: jump to the marker clicked."""
        marker = self.nearest(event.position().x())
        if marker is not None:
            self.sig_jump.emit(marker.time)


class ReplayBar(QWidget):
    """Scrubber, play/pause, speed and time of a recording (hidden until ``show_timeline``)."""

    sig_moment = Signal(float)
    sig_closed = Signal()

    def __init__(self, language, parent=None):
        """``language``: the window's ``CurrentLanguage``, read whenever the bar speaks."""
        super().__init__(parent)
        self.setObjectName("replay_bar")
        self._language = language
        self.duration = 0.0
        self._note = ""
        self.markers = MarkerStrip(language, self)
        self.markers.sig_jump.connect(self.jump_to)
        self.slider = QSlider(Qt.Orientation.Horizontal, self)
        self.slider.setObjectName("replay_slider")
        self.slider.valueChanged.connect(self._on_slider)
        self.play_button = QToolButton(self)
        self.play_button.setObjectName("replay_play")
        self.play_button.clicked.connect(self.toggle_play)
        self.speed = QComboBox(self)
        self.speed.setObjectName("replay_speed")
        for speed in SPEEDS:
            self.speed.addItem(f"{speed:g}×", speed)
        self.speed.setCurrentIndex(SPEEDS.index(1.0))
        self.time_label = QLabel(self)
        self.close_button = QToolButton(self)
        self.close_button.setObjectName("replay_close")
        self.close_button.setText("×")
        self.close_button.clicked.connect(self.close_timeline)
        track = QVBoxLayout()
        track.setSpacing(0)
        track.addWidget(self.markers)
        track.addWidget(self.slider)
        row = QHBoxLayout(self)
        row.setContentsMargins(6, 2, 6, 2)
        for widget in (self.play_button, self.speed):
            row.addWidget(widget)
        row.addLayout(track, 1)
        row.addWidget(self.time_label)
        row.addWidget(self.close_button)
        self._timer = QTimer(self)
        self._timer.setInterval(PLAY_MS)
        self._timer.timeout.connect(self._advance)
        self._played_at = None
        self._exact = None  # the time last jumped to, finer than the slider's milliseconds
        self.retitle()
        self.hide()

    @property
    def language(self) -> str:
        """The language the bar speaks: the window's, now."""
        return self._language.code

    def retitle(self):
        """Say everything in the current language (after it changed; the note is the replay's: ``set_note``)."""
        language = self.language
        self.speed.setToolTip(tr("replay_speed", language))
        self.close_button.setToolTip(tr("replay_close", language))
        self._show_play_state()
        self._show_time()

    def set_note(self, note: str, details: str = ""):
        """``note`` follows the time, ``details`` (what the note stands for) is its tooltip."""
        self._note = note
        self.time_label.setToolTip(details)
        self._show_time()

    @property
    def position(self) -> float:
        """The scrubber's time, in seconds from the recording's start: exactly the time jumped to (a
        marker's events may be a fraction of the slider's millisecond apart), else the slider's."""
        if self._exact is not None and _slider_value(self._exact) == self.slider.value():
            return self._exact
        return self.slider.value() / 1000

    def show_timeline(self, duration: float, markers, note: str = "", details: str = ""):
        """Show the bar for a recording ``duration`` s long with its ``markers``; the scrubber at its end;
        ``note`` follows the time, ``details`` (what the note stands for) is its tooltip."""
        self.pause()
        self.duration = max(0.0, duration)
        self.markers.duration, self.markers.markers = self.duration, list(markers)
        self.markers.update()
        self.slider.blockSignals(True)  # opening shows the end; nothing is replayed until the person moves
        self.slider.setRange(0, math.ceil(self.duration * 1000))
        self.slider.setValue(self.slider.maximum())
        self.slider.blockSignals(False)
        self.set_note(note, details)
        self.show()

    def jump_to(self, seconds: float):
        """Move the scrubber to ``seconds`` (and show that moment)."""
        self._exact = seconds
        if self.slider.value() == _slider_value(seconds):  # the same millisecond: no valueChanged comes
            self._on_slider(self.slider.value())
        else:
            self.slider.setValue(_slider_value(seconds))

    @property
    def playing(self) -> bool:
        """True while the bar plays the recording."""
        return self._timer.isActive()

    def _at_end(self) -> bool:
        # the slider's last millisecond may lie past the end, the end between two of its milliseconds
        return self.position >= self.duration

    def toggle_play(self):
        """Play from the scrubber (from the start when at the end), or pause."""
        if self._timer.isActive():
            self.pause()
            return
        if self._at_end():
            self.jump_to(0.0)
        self._played_at = time.monotonic()
        self._timer.start()
        self._show_play_state()

    def pause(self):
        """Stop playing."""
        self._timer.stop()
        self._show_play_state()

    def close_timeline(self):
        """Hide the bar; the window goes back to showing the robot as it is."""
        self.pause()
        self.hide()
        self.sig_closed.emit()

    def _advance(self):
        now = time.monotonic()
        step = (now - self._played_at) * self.speed.currentData()
        self._played_at = now
        self.jump_to(min(self.duration, self.position + step))
        if self._at_end():
            self.pause()

    def _on_slider(self, _value):
        self._show_time()
        self.sig_moment.emit(self.position)

    def _show_time(self):
        text = tr("replay_time", self.language, now=self.position, total=self.duration)
        self.time_label.setText(f"{text} {self._note}".strip())

    def _show_play_state(self):
        # the style's icons: the fonts here may have no ⏸ (nor ▶), and a missing glyph shows as a box
        icon = QStyle.StandardPixmap.SP_MediaPause if self._timer.isActive() else QStyle.StandardPixmap.SP_MediaPlay
        self.play_button.setIcon(self.style().standardIcon(icon))
        self.play_button.setToolTip(tr("replay_pause" if self._timer.isActive() else "replay_play", self.language))


def under(widget: QWidget, bar: ReplayBar) -> QWidget:
    """``widget`` with ``bar`` below it, as one widget (the window's central widget)."""
    holder = QWidget(widget.parentWidget())
    column = QVBoxLayout(holder)
    column.setContentsMargins(0, 0, 0, 0)
    column.setSpacing(0)
    column.addWidget(widget, 1)
    column.addWidget(bar)
    return holder


def _slider_value(seconds: float) -> int:
    """The slider's value (milliseconds) for ``seconds``."""
    return int(round(seconds * 1000))
