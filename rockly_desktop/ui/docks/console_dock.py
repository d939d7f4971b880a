"""The Console dock: what the program prints and what the robot reports, with times.

During a replay it shows, in a view of its own, what the recorded program had printed up to
the moment (``show_recorded``), the last line in sight; ``show_live`` goes back to the log.
"""
import time

from PySide6.QtGui import QColor, QFontDatabase, QTextCharFormat
from PySide6.QtWidgets import QDockWidget, QPlainTextEdit, QStackedWidget

_COLOURS = {"output": "#202020", "robot": "#2e7d32", "info": "#1f5fa8", "error": "#c62828"}
MAX_LINES = 5000


class ConsoleDock(QDockWidget):
    """A read-only log; ``append(text, kind)`` with kind output | robot | info | error."""

    def __init__(self, title: str, parent=None):
        super().__init__(title, parent)
        self.view = QPlainTextEdit(self)
        self.view.setReadOnly(True)
        self.view.setMaximumBlockCount(MAX_LINES)
        self.view.setFont(QFontDatabase.systemFont(QFontDatabase.SystemFont.FixedFont))
        self.replay_view = QPlainTextEdit(self)
        self.replay_view.setObjectName("console_replay")
        self.replay_view.setReadOnly(True)
        self.replay_view.setFont(self.view.font())
        self.replay_view.setMaximumBlockCount(MAX_LINES)
        self._recorded = (None, 0)  # the replay's lines and how many of them are shown
        self._stack = QStackedWidget(self)
        self._stack.addWidget(self.view)
        self._stack.addWidget(self.replay_view)
        self.setWidget(self._stack)

    def append(self, text: str, kind: str = "output"):
        """Add one line, stamped with the time of day."""
        self.append_lines([text], kind)

    def append_lines(self, lines, kind: str = "output"):
        """Add several lines at once (one redraw), each stamped with the time of day."""
        lines = list(lines)[-MAX_LINES:]
        if not lines:
            return
        text_format = QTextCharFormat()
        text_format.setForeground(QColor(_COLOURS.get(kind, _COLOURS["output"])))
        cursor = self.view.textCursor()
        cursor.movePosition(cursor.MoveOperation.End)
        stamp = time.strftime("%H:%M:%S")
        # One insert for the whole batch: each line break becomes a line of its own.
        text = "\n".join(f"{stamp}  {line}" for line in lines)
        cursor.insertText(text if self.view.document().isEmpty() else "\n" + text, text_format)
        self.view.setTextCursor(cursor)
        self.view.ensureCursorVisible()

    def clear(self):
        """Empty the log and go back to it (the kiosk's next visitor starts with a blank console)."""
        self.view.clear()
        self.show_live()

    def lines(self) -> list:
        """The console's lines without their time stamps."""
        return [line[10:] for line in self.view.toPlainText().splitlines()]

    def show_recorded(self, lines: list, count: int):
        """Show the first ``count`` of ``lines`` (a replay's output; the last MAX_LINES of them), the last in
        sight. Moving on in the same ``lines`` only adds the lines that came since."""
        shown_lines, shown = self._recorded
        if lines is shown_lines and shown <= count and shown:
            if count > shown:
                self.replay_view.appendPlainText("\n".join(lines[max(shown, count - MAX_LINES):count]))
        else:
            self.replay_view.setPlainText("\n".join(lines[max(0, count - MAX_LINES):count]))
        self._recorded = (lines, count)
        self.replay_view.moveCursor(self.replay_view.textCursor().MoveOperation.End)
        self.replay_view.ensureCursorVisible()
        self._stack.setCurrentWidget(self.replay_view)

    def show_live(self):
        """Show the log again (the replay closed)."""
        self._recorded = (None, 0)
        self._stack.setCurrentWidget(self.view)

    def recorded_lines(self) -> list:
        """The lines the replay view shows."""
        return self.replay_view.toPlainText().splitlines() if self._stack.currentWidget() is self.replay_view else []
