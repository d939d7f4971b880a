"""Showing text a profile, a program, a recording or a robot supplies exactly as written.

A QLabel or a tool tip renders a text that looks like HTML (a tag near its start) as rich text,
with images, links and styles; a menu, a group box or a check box turns ``&`` into a shortcut.
Such text reaches the window only through these helpers.
"""
import html

from PySide6.QtCore import Qt
from PySide6.QtWidgets import QLabel


def plain_label(text: str = "", parent=None, **properties) -> QLabel:
    """A QLabel that shows ``text`` (and every text set later) as plain text."""
    label = QLabel(text, parent, **properties)
    label.setTextFormat(Qt.TextFormat.PlainText)
    return label


def tooltip_text(text: str) -> str:
    """A tool tip showing ``text`` as written (a tool tip has no text format of its own)."""
    return f"<p style='white-space:pre-wrap'>{html.escape(str(text))}</p>" if text else ""


def mnemonic_free(text: str) -> str:
    """``text`` for a menu, a group box's title or a check box: each ``&`` shown, none a shortcut."""
    return str(text).replace("&", "&&")
