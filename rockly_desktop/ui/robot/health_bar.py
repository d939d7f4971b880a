"""The connection health light in the status bar: one coloured dot and a word a child can read.

Hovering shows every part (the link, the robot's topics with rate and age, its services
and action servers). It asks the robot for its health twice a second.
"""
from PySide6.QtCore import QTimer, Signal
from PySide6.QtWidgets import QLabel

from rockly_desktop.robot.health import overall
from rockly_desktop.ui.texts import said_in, tr

COLOURS = {"green": "#2e7d32", "amber": "#f9a825", "red": "#c62828"}
SYMBOLS = {"green": "✔", "amber": "!", "red": "✖"}
REFRESH_MS = 500


class HealthBar(QLabel):
    """Shows ``robot.health()`` (a list of HealthItems) as one traffic light with details on hover.

    It is the window's one source of the link's health: each look is also given to ``sig_refreshed``
    (the robot, its items), from which the status bar says the link's state."""

    sig_refreshed = Signal(object, list)

    def __init__(self, language, parent=None):
        """``language``: the window's ``CurrentLanguage``, read at each look."""
        super().__init__(parent)
        self.setObjectName("health_bar")
        self._language = language
        self.robot = None
        self.level = None
        self.items = []
        self._timer = QTimer(self)
        self._timer.setInterval(REFRESH_MS)
        self._timer.timeout.connect(self.refresh)

    def show_robot(self, robot):
        """Follow ``robot``'s health."""
        self.robot = robot
        self.refresh()
        self._timer.start()

    def refresh(self):
        """Ask the robot and redraw."""
        if self.robot is None:
            return
        self.items = self.robot.health()
        self.level = overall(self.items)
        colour, language = COLOURS[self.level], self._language.code
        summary = tr("health_" + self.level, language)
        self.setText(f"<span style='color:{colour}; font-size:16px'>●</span> {summary}")
        rows = "".join(f"<tr><td style='color:{COLOURS[item.level]}'>{SYMBOLS[item.level]}</td>"
                       f"<td>{_escape(said_in(item.name, language))}</td>"
                       f"<td>{_escape(said_in(item.detail, language))}</td></tr>" for item in self.items)
        self.setToolTip(f"<b>{tr('health_title', language)}</b><table>{rows}</table>")
        self.sig_refreshed.emit(self.robot, self.items)

    def stop(self):
        """Stop asking (the robot is going away)."""
        self._timer.stop()


def _escape(text: str) -> str:
    return str(text).replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
