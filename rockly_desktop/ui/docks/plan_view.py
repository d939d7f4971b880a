"""A plan view of a real robot's recorded run: its path from ``/odom`` so far and its pose then.

The replay shows it in the Simulator dock when a recording has no simulator snapshots. The
plan is north-up (x to the right, y up, as ROS's ``odom`` frame), scaled to the whole run's
path so that it stays put while the scrubber moves, with a grid and a scale bar.
"""
import math

from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QColor, QPainter, QPainterPath, QPen
from PySide6.QtWidgets import QWidget

from rockly_desktop.core.numbers import number_format
from rockly_desktop.ui.texts import tr

_MARGIN_M = 0.75     # room around the path, in metres
_ROBOT_RADIUS_M = 0.25
_TOP = 24            # pixels for the title line
_GRID_STEPS = (0.1, 0.25, 0.5, 1.0, 2.0, 5.0, 10.0, 25.0, 50.0, 100.0)
_PATH = QColor("#1f5fa8")
_ROBOT = QColor("#e65100")


class PlanView(QWidget):
    """Draws ``poses`` ((x, y, heading) up to the moment) inside ``bounds`` (min x, min y, max x, max y)."""

    def __init__(self, bounds: tuple, language: str, parent=None):
        super().__init__(parent)
        self.setObjectName("plan_view")
        self.setMinimumSize(200, 160)
        self.language = language
        low_x, low_y, high_x, high_y = bounds
        self.bounds = (low_x - _MARGIN_M, low_y - _MARGIN_M, high_x + _MARGIN_M, high_y + _MARGIN_M)
        self.poses = []

    def show_poses(self, poses: list):
        """Show the path up to a moment (``poses`` in time order; the last one is the robot then)."""
        self.poses = list(poses)
        self.update()

    def _scale(self) -> float:
        low_x, low_y, high_x, high_y = self.bounds
        return min(self.width() / (high_x - low_x), (self.height() - _TOP) / (high_y - low_y))

    def to_widget(self, x: float, y: float) -> QPointF:
        """Where the point (x, y) in metres is drawn (the plan centred below the title line)."""
        low_x, low_y, high_x, high_y = self.bounds
        scale = self._scale()
        left = (self.width() - (high_x - low_x) * scale) / 2
        top = _TOP + (self.height() - _TOP - (high_y - low_y) * scale) / 2
        return QPointF(left + (x - low_x) * scale, top + (high_y - y) * scale)

    def paintEvent(self, _event):
        """Qt override: grid, path, robot, scale bar and the pose in words."""
        painter = QPainter(self)
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        painter.fillRect(self.rect(), QColor("#fafafa"))
        step = self._grid(painter)
        if self.poses:
            self._path(painter)
            self._robot(painter, *self.poses[-1])
        self._legend(painter, step)

    def _grid(self, painter) -> float:
        scale = self._scale()
        step = next((s for s in _GRID_STEPS if s * scale >= 40), _GRID_STEPS[-1])
        corner = self.to_widget(self.bounds[0], self.bounds[3])  # where the plan's top left is drawn
        low_x = self.bounds[0] - corner.x() / scale  # the metres the whole widget shows
        high_x = low_x + self.width() / scale
        high_y = self.bounds[3] + (corner.y() - _TOP) / scale
        low_y = high_y - (self.height() - _TOP) / scale
        painter.setPen(QPen(QColor("#e0e0e0"), 1))
        x = math.ceil(low_x / step) * step
        while x <= high_x:
            painter.drawLine(self.to_widget(x, low_y), self.to_widget(x, high_y))
            x += step
        y = math.ceil(low_y / step) * step
        while y <= high_y:
            painter.drawLine(self.to_widget(low_x, y), self.to_widget(high_x, y))
            y += step
        painter.setPen(QPen(QColor("#9e9e9e"), 1, Qt.PenStyle.DashLine))  # the odometry's origin
        painter.drawLine(self.to_widget(0, low_y), self.to_widget(0, high_y))
        painter.drawLine(self.to_widget(low_x, 0), self.to_widget(high_x, 0))
        return step

    def _path(self, painter):
        path = QPainterPath(self.to_widget(*self.poses[0][:2]))
        for x, y, _heading in self.poses[1:]:
            path.lineTo(self.to_widget(x, y))
        painter.setPen(QPen(_PATH, 2.5))
        painter.drawPath(path)
        painter.setBrush(QColor("#9e9e9e"))
        painter.setPen(Qt.PenStyle.NoPen)
        painter.drawEllipse(self.to_widget(*self.poses[0][:2]), 4, 4)  # where the run began

    def _robot(self, painter, x, y, heading):
        centre = self.to_widget(x, y)
        radius = max(8.0, _ROBOT_RADIUS_M * self._scale())
        painter.setBrush(QColor(_ROBOT.red(), _ROBOT.green(), _ROBOT.blue(), 50))
        painter.setPen(QPen(_ROBOT, 2))
        painter.drawEllipse(centre, radius, radius)
        nose = QPointF(centre.x() + radius * 1.4 * math.cos(heading), centre.y() - radius * 1.4 * math.sin(heading))
        painter.setPen(QPen(_ROBOT, 3))
        painter.drawLine(centre, nose)

    def _legend(self, painter, step):
        painter.setPen(QColor("#333333"))
        if self.poses:
            x, y, heading = self.poses[-1]
            where = number_format(self.language).format(tr("plan_pose", self.language), x=x, y=y,
                                                        heading=math.degrees(heading))
        else:
            where = tr("plan_no_pose", self.language)
        painter.drawText(QRectF(6, 2, self.width() - 12, 20), Qt.AlignmentFlag.AlignVCenter,
                         f"{tr('plan_title', self.language)}   {where}")
        length = step * self._scale()
        bottom = self.height() - 8
        painter.setPen(QPen(QColor("#333333"), 2))
        painter.drawLine(QPointF(10, bottom), QPointF(10 + length, bottom))
        painter.drawText(QRectF(14 + length, bottom - 14, 80, 20), Qt.AlignmentFlag.AlignVCenter,
                         number_format(self.language).format("{:g} m", step))
