"""Noticing that nobody has touched Rockly for a while: an application-wide event filter and a clock."""
import time

from PySide6.QtCore import QEvent, QObject, QTimer, Signal
from PySide6.QtWidgets import QApplication

CHECK_MS = 1000
_INPUT = frozenset({
    QEvent.Type.KeyPress, QEvent.Type.MouseButtonPress, QEvent.Type.MouseButtonDblClick, QEvent.Type.MouseMove,
    QEvent.Type.Wheel, QEvent.Type.TouchBegin, QEvent.Type.TouchUpdate, QEvent.Type.TabletPress,
})


class IdleWatch(QObject):
    """Emits ``sig_idle`` (once a second, until ``rest()``) when there has been no key, mouse or touch
    input anywhere in the application for ``seconds``. After ``rest()`` it waits for input again
    before it counts, so a stand nobody visits is not started over and over.

    The clock is this module's ``time.monotonic`` (a test puts a fake ``time`` in its place).
    """

    sig_idle = Signal()

    def __init__(self, seconds: float, parent=None):
        super().__init__(parent)
        self.seconds = seconds
        self._last_input = time.monotonic()
        self._armed = True
        QApplication.instance().installEventFilter(self)
        self._timer = QTimer(self)
        self._timer.setInterval(CHECK_MS)
        self._timer.timeout.connect(self.check)
        self._timer.start()

    def eventFilter(self, watched, event):
        """Every key, mouse or touch event anywhere counts as someone being there."""
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
        self._timer.stop()
        QApplication.instance().removeEventFilter(self)
