"""The Simulator dock: the profile's own view of its simulated robot, refreshed at 30 Hz.

A replay of a real robot's run puts its plan view here for a while (``show_recorded_view``;
the dock shows even where a real robot hides it), ``show_live_view`` puts the live one back.
"""
from PySide6.QtCore import Qt, QTimer
from PySide6.QtWidgets import QDockWidget

from rockly_desktop.ui.plain_text import plain_label

REFRESH_MS = 33


class SimulatorDock(QDockWidget):
    """Shows ``view`` (a QWidget with ``set_snapshot(dict)``) fed from ``robot.snapshot()``."""

    def __init__(self, title: str, parent=None):
        super().__init__(title, parent)
        self.view = None
        self.robot = None
        self._timer = QTimer(self)
        self._timer.setInterval(REFRESH_MS)
        self._timer.timeout.connect(self.refresh)
        self._live = None  # (the live widget, whether the dock was hidden) while a recorded view is shown
        self._own_title = None  # the dock's title while a note is added to it

    def say_not_the_robot(self, note: str):
        """Put ``note`` in the dock's title (the window is attached to a real robot's run: this simulated robot
        is not that robot); "" gives the dock its own title back."""
        if note:
            if self._own_title is None:
                self._own_title = self.windowTitle()
            self.setWindowTitle(f"{self._own_title} — {note}")
        elif self._own_title is not None:
            self.setWindowTitle(self._own_title)
            self._own_title = None

    def show_robot(self, robot, view, note: str = "—"):
        """Show ``robot``'s simulation in ``view``; without a view, show ``note`` instead."""
        if self._live is not None:  # the robot changed during a replay: its recorded view goes too
            self._live[0].deleteLater()
            self._live = None
        self.robot = robot
        self.view = view
        old = self.widget()
        if old is not None:
            old.deleteLater()
        if view is None:
            label = plain_label(note, self)
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

    def show_recorded_view(self, widget):
        """Show ``widget`` (a replay's plan view) instead of the live view, the dock shown."""
        self.stop()
        if self._live is None:
            self._live = (self.widget(), self.isHidden())
            self._live[0].hide()
        else:
            self.widget().deleteLater()
        self.setWidget(widget)
        self.show()

    def show_live_view(self):
        """Put the live view back as it was before ``show_recorded_view`` (nothing if none was shown)."""
        if self._live is None:
            return
        live, hidden = self._live
        self._live = None
        self.widget().deleteLater()
        self.setWidget(live)
        live.show()
        self.setHidden(hidden)
        self.resume()
