"""The Console dock: what the program prints and what the robot reports, with times."""
import time

from PySide6.QtGui import QColor, QFontDatabase, QTextCharFormat
from PySide6.QtWidgets import QDockWidget, QPlainTextEdit

_COLOURS = {"output": "#202020", "robot": "#2e7d32", "info": "#1f5fa8", "error": "#c62828"}
MAX_LINES = 5000


class ConsoleDock(QDockWidget):
    """A read-only log; ``append(text, kind)`` with kind output | robot | info | error."""

    def __init__(self, title: str, parent=None):
        super().__init__(title, parent)
        self.setObjectName("console_dock")
        self.view = QPlainTextEdit(self)
        self.view.setReadOnly(True)
        self.view.setMaximumBlockCount(MAX_LINES)
        self.view.setFont(QFontDatabase.systemFont(QFontDatabase.SystemFont.FixedFont))
        self.setWidget(self.view)

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

    def lines(self) -> list:
        """The console's lines without their time stamps."""
        return [line[10:] for line in self.view.toPlainText().splitlines()]
