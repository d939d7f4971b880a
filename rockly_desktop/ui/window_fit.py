"""The first window fits its screen: the window's frame (title bar and borders) included, inside the
screen's available area (without panels and docks), so the status bar and its health light show
without maximising.

Before the window is shown its frame is not known: the window is sized with room for a usual frame,
and once the window manager has framed it (the window is shown, then activated) it is moved and
shrunk by whatever still sticks out.
"""
from PySide6.QtCore import QEvent, QObject, QPoint, QRect, QSize
from PySide6.QtGui import QGuiApplication
from PySide6.QtWidgets import QStyle

WANTED = QSize(1280, 800)
BORDER = 4  # px: room for a frame's side and bottom borders before the real frame is known


def fit_first_window(window, wanted: QSize = WANTED):
    """Size ``window`` to ``wanted`` or less, so that with its frame it fits its screen's available
    area, and keep it fitting once it is shown and framed (see the module's docstring)."""
    area = _available(window)
    title = window.style().pixelMetric(QStyle.PixelMetric.PM_TitleBarHeight)
    frame = QSize(2 * BORDER, title + 2 * BORDER)
    size = wanted.boundedTo(area.size() - frame)
    window.resize(size)
    spare = area.size() - size - frame
    window.move(area.topLeft() + QPoint(spare.width() // 2, spare.height() // 2))  # the frame's corner
    window.installEventFilter(_KeepInside(window, size))


class _KeepInside(QObject):
    """Moves and shrinks the window into the available area when it is shown and when first activated
    (then the window manager has framed it), while it still has the ``size`` it was given here; leaves
    it alone after that, when it was sized otherwise (a remembered geometry) and when maximised or full screen."""

    def __init__(self, window, size: QSize):
        super().__init__(window)
        self._window = window
        self._size = size

    def eventFilter(self, watched, event):
        """Qt override: fit on Show and on the first WindowActivate."""
        if watched is self._window and event.type() in (QEvent.Type.Show, QEvent.Type.WindowActivate):
            if self._window.size() == self._size:
                keep_inside(self._window)
                self._size = self._window.size()
            if event.type() == QEvent.Type.WindowActivate:
                self._window.removeEventFilter(self)
                self.deleteLater()
        return False


def keep_inside(window):
    """Move and shrink ``window`` so that its frame is inside its screen's available area."""
    if window.isMaximized() or window.isFullScreen() or window.isMinimized():
        return
    area, frame, inner = _available(window), window.frameGeometry(), window.geometry()
    extra = QSize(frame.width() - inner.width(), frame.height() - inner.height())
    size = inner.size().boundedTo(area.size() - extra)
    if size != inner.size():
        window.resize(size)
    fitted = QRect(frame.topLeft(), size + extra)
    left = min(max(fitted.left(), area.left()), area.right() + 1 - fitted.width())
    top = min(max(fitted.top(), area.top()), area.bottom() + 1 - fitted.height())
    if (left, top) != (frame.left(), frame.top()):
        window.move(left, top)  # move() places the frame's top-left corner


def _available(window) -> QRect:
    screen = window.screen() or QGuiApplication.primaryScreen()
    return screen.availableGeometry()
