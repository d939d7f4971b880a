"""Where a tablet question's window goes: beside the simulator view, never over the robot it asks for."""
from PySide6.QtCore import QPoint, QRect, QSize
from PySide6.QtWidgets import QWidget

GAP = 12  # px between the window and the view it keeps clear of


def global_rect(widget: QWidget):
    """``widget``'s rectangle in screen coordinates, or None while it is not shown."""
    if widget is None or not widget.isVisible():
        return None
    return QRect(widget.mapToGlobal(QPoint(0, 0)), widget.size())


def place_clear_of(size: QSize, avoid: QRect, near: QRect, bounds: QRect) -> QPoint:
    """The top-left corner for a window of ``size`` that does not intersect ``avoid``: left of it, below,
    above or right of it (the first that lies in ``bounds``), centred on ``near`` (the parent window) along
    that side. Where none fits, the spot that covers the least of ``avoid``."""
    width, height = size.width(), size.height()
    centre = near.center()
    # x and y are clamped to ``bounds`` along the side; the side's own coordinate is not
    across_x = min(max(centre.x() - width // 2, bounds.left()), bounds.right() - width + 1)
    across_y = min(max(centre.y() - height // 2, bounds.top()), bounds.bottom() - height + 1)
    spots = [QPoint(avoid.left() - GAP - width, across_y), QPoint(across_x, avoid.bottom() + 1 + GAP),
             QPoint(across_x, avoid.top() - GAP - height), QPoint(avoid.right() + 1 + GAP, across_y)]
    for spot in spots:
        rect = QRect(spot, size)
        if bounds.contains(rect) and not rect.intersects(avoid):
            return spot
    inside = [QPoint(min(max(spot.x(), bounds.left()), bounds.right() - width + 1),
                     min(max(spot.y(), bounds.top()), bounds.bottom() - height + 1)) for spot in spots]
    return min(inside, key=lambda spot: _area(QRect(spot, size).intersected(avoid)))


def _area(rect: QRect) -> int:
    return max(0, rect.width()) * max(0, rect.height())
