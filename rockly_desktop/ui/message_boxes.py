"""Message boxes whose text is shown as typed (Qt would render a text containing a tag as HTML), whole
(wrapped, never cut) and in a window wide enough for its whole title (a short text made a narrow box,
and the window manager cut its title: "Etwas ist s…fgegangen").

The title's width is the minimum width of the box's button row, not of its text: a minimum width on
the text label replaces the label's own size hint, so QMessageBox saw a label narrower than its
text, did not wrap it and cut it mid-word (a bump's message ended "bumped in"). With the row holding the width,
QMessageBox measures the text as it is and wraps it when it is wider than its limits.
"""
from PySide6.QtCore import Qt
from PySide6.QtGui import QFont, QFontMetrics
from PySide6.QtWidgets import QDialogButtonBox, QMessageBox

TITLE_BAR_EXTRA = 160   # pixels of a title bar that are not its text: icon, buttons, margins


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
    margins = box.layout().contentsMargins()
    # a widget's minimum width holds however often QMessageBox lays itself out anew (a spacer would not)
    box.findChild(QDialogButtonBox).setMinimumWidth(title_width(title, box.font()) - margins.left() - margins.right())
    return box
