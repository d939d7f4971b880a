"""The Code dock: the Python generated from the blocks, live, read-only, coloured."""
from PySide6.QtGui import QFontDatabase
from PySide6.QtWidgets import QDockWidget, QPlainTextEdit

from rockly_desktop.ui.docks.python_highlighter import PythonHighlighter


class CodeView(QPlainTextEdit):
    """Read-only Python with syntax colouring that keeps its scroll position on updates."""

    def __init__(self, parent=None):
        super().__init__(parent)
        self.setReadOnly(True)
        self.setLineWrapMode(QPlainTextEdit.LineWrapMode.NoWrap)
        font = QFontDatabase.systemFont(QFontDatabase.SystemFont.FixedFont)
        font.setPointSize(max(font.pointSize(), 11))
        self.setFont(font)
        self.highlighter = PythonHighlighter(self.document())

    def set_code(self, code: str):
        """Show ``code``, keeping the scroll position if the text changed."""
        if code == self.toPlainText():
            return
        scroll = self.verticalScrollBar().value()
        self.setPlainText(code)
        self.verticalScrollBar().setValue(scroll)


class CodeDock(QDockWidget):
    """Dock holding the CodeView."""

    def __init__(self, title: str, parent=None):
        super().__init__(title, parent)
        self.view = CodeView(self)
        self.setWidget(self.view)
