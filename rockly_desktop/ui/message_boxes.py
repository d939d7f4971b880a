"""Message boxes whose text is shown as typed (Qt would render a text containing a tag as HTML) and
whose window is wide enough for its whole title (a short text made a narrow box, and the window
manager cut its title: "Etwas ist s…fgegangen")."""
from PySide6.QtCore import Qt
from PySide6.QtGui import QFont, QFontMetrics
from PySide6.QtWidgets import QMessageBox

TITLE_BAR_EXTRA = 160   # pixels of a title bar that are not its text: icon, buttons, margins
ICON_COLUMN = 60        # pixels of a message box left of its text: the icon and the margins


def title_width(title: str, font: QFont) -> int:
    """How wide a window must be to show ``title`` in its title bar (drawn bold, often a bit bigger)."""
    bold = QFont(font)
    bold.setBold(True)
    bold.setPointSizeF(font.pointSizeF() * 1.15 if font.pointSizeF() > 0 else 11.0)
    return QFontMetrics(bold).horizontalAdvance(title) + TITLE_BAR_EXTRA


def plain_message_box(parent, icon, title: str, text: str, buttons=QMessageBox.StandardButton.Ok) -> QMessageBox:
    """A QMessageBox showing ``text`` (and any informative or detailed text) as plain text."""
    box = QMessageBox(icon, title, text, buttons, parent)
    box.setTextFormat(Qt.TextFormat.PlainText)
    # the text's minimum width holds however often QMessageBox lays itself out anew (a spacer would not)
    box.setStyleSheet(f"QLabel#qt_msgbox_label {{ min-width: {title_width(title, box.font()) - ICON_COLUMN}px; }}")
    return box
