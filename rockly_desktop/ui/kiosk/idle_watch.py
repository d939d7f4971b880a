"""Noticing that nobody has touched Rockly for a while: event filters on the application's windows
and a clock.

Not a filter on the QApplication: PySide 6.11 makes a Python wrapper for each object such a filter
is shown an event for, which sets a property on it, whose event comes back to the filter while the
wrapper is half made (a crash as soon as the editor page runs). Every input event reaches its
top-level QWindow first, and the filter is only ever shown those few windows.

Nor a Python slot on a watched window's ``destroyed``: a QWindow goes when its widget is deleted,
and a slot called then needs a wrapper for a half-destroyed object (a crash once ``stop()`` has let
go of the watch's own wrappers). A window gone is seen by ``shiboken6.isValid`` instead.
"""
import time

import shiboken6
from PySide6.QtCore import QEvent, QObject, QTimer, Signal
from PySide6.QtGui import QGuiApplication

CHECK_MS = 1000
_INPUT = frozenset({
    QEvent.Type.KeyPress, QEvent.Type.MouseButtonPress, QEvent.Type.MouseButtonDblClick, QEvent.Type.MouseMove,
    QEvent.Type.Wheel, QEvent.Type.TouchBegin, QEvent.Type.TouchUpdate, QEvent.Type.TabletPress,
})


class IdleWatch(QObject):
    """Emits ``sig_idle`` (once a second, until ``rest()``) when there has been no key, mouse or touch
    input for ``seconds`` in ``window`` (a top-level widget) or any window of the application that
    had the focus since (its dialogs). After ``rest()`` it waits for input again
    before it counts, so a stand nobody visits is not started over and over.

    The clock is this module's ``time.monotonic`` (a test puts a fake ``time`` in its place).
    """

    sig_idle = Signal()

    def __init__(self, seconds: float, window, parent=None):
        super().__init__(parent)
        self.seconds = seconds
        self._last_input = time.monotonic()
        self._armed = True
        self._watched = []
        window.winId()  # its QWindow exists from now on
        self._watch(window.windowHandle())
        QGuiApplication.instance().focusWindowChanged.connect(self._watch)
        self._timer = QTimer(self)
        self._timer.setInterval(CHECK_MS)
        self._timer.timeout.connect(self.check)
        self._timer.start()

    def _watch(self, window):
        self._watched = [watched for watched in self._watched if shiboken6.isValid(watched)]
        if window is not None and window not in self._watched:
            self._watched.append(window)
            window.installEventFilter(self)

    def eventFilter(self, watched, event):
        """Every key, mouse or touch event in a watched window counts as someone being there."""
        if event.type() in _INPUT:
            self.touched()
        return False

    def touched(self):
        """Someone is there: count from now."""
        self._last_input = time.monotonic()
        self._armed = True

    def rest(self):
        """The idle time was dealt with: wait for input before counting again."""
        self._armed = False

    def check(self):
        """Emit ``sig_idle`` when the idle time has passed (the timer calls this every second)."""
        if self._armed and time.monotonic() - self._last_input >= self.seconds:
            self.sig_idle.emit()

    def stop(self):
        """Stop watching."""
        if not self._timer.isActive():
            return
        self._timer.stop()
        QGuiApplication.instance().focusWindowChanged.disconnect(self._watch)
        for window in self._watched:
            if shiboken6.isValid(window):
                window.removeEventFilter(self)
        self._watched.clear()
