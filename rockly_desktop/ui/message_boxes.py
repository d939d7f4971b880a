"""Message boxes whose text is shown as typed: Qt would render a text containing a tag as HTML."""
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QMessageBox


def plain_message_box(parent, icon, title: str, text: str, buttons=QMessageBox.StandardButton.Ok) -> QMessageBox:
    """A QMessageBox showing ``text`` (and any informative or detailed text) as plain text."""
    box = QMessageBox(icon, title, text, buttons, parent)
    box.setTextFormat(Qt.TextFormat.PlainText)
    return box
