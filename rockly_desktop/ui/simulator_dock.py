"""The Simulator dock: the profile's own view of its simulated robot, refreshed at 30 Hz."""
from PySide6.QtCore import Qt, QTimer
from PySide6.QtWidgets import QDockWidget, QLabel

REFRESH_MS = 33


class SimulatorDock(QDockWidget):
    """Shows ``view`` (a QWidget with ``set_snapshot(dict)``) fed from ``robot.snapshot()``."""

    def __init__(self, title: str, parent=None):
        super().__init__(title, parent)
        self.setObjectName("simulator_dock")
        self.view = None
        self.robot = None
        self._timer = QTimer(self)
        self._timer.setInterval(REFRESH_MS)
        self._timer.timeout.connect(self.refresh)

    def show_robot(self, robot, view, note: str = "—"):
        """Show ``robot``'s simulation in ``view``; without a view, show ``note`` instead."""
        self.robot = robot
        self.view = view
        old = self.widget()
        if old is not None:
            old.deleteLater()
        if view is None:
            label = QLabel(note, self)
            label.setWordWrap(True)
            label.setAlignment(Qt.AlignmentFlag.AlignCenter)
            self.setWidget(label)
            self._timer.stop()
            return
        self.setWidget(view)
        self.refresh()
        self._timer.start()

    def refresh(self):
        """Give the view the robot's current state."""
        if self.robot is not None and self.view is not None:
            self.view.set_snapshot(self.robot.snapshot())

    def stop(self):
        """Stop refreshing (the robot is going away, or a replay shows a recorded state)."""
        self._timer.stop()

    def resume(self):
        """Show the robot as it is again, refreshed as before ``stop``."""
        if self.robot is not None and self.view is not None:
            self.refresh()
            self._timer.start()
