"""Syntax colouring for Python in the Code dock."""
import keyword
import re

from PySide6.QtGui import QColor, QFont, QSyntaxHighlighter, QTextCharFormat


def _format(colour: str, bold: bool = False, italic: bool = False) -> QTextCharFormat:
    text_format = QTextCharFormat()
    text_format.setForeground(QColor(colour))
    if bold:
        text_format.setFontWeight(QFont.Weight.Bold)
    text_format.setFontItalic(italic)
    return text_format


_RULES = (
    (re.compile(rf"\b(?:{'|'.join(keyword.kwlist)})\b"), _format("#8e44ad", bold=True)),
    (re.compile(r"\b(?:True|False|None)\b"), _format("#c0392b", bold=True)),
    (re.compile(r"\b\d+(?:\.\d*)?(?:[eE][-+]?\d+)?\b"), _format("#d35400")),
    (re.compile(r"\brobot\b"), _format("#2e7d32", bold=True)),
    (re.compile(r"\b[A-Za-z_]\w*(?=\()"), _format("#1f5fa8")),
)
_STRING = re.compile(r"'(?:[^'\\\n]|\\.)*'|\"(?:[^\"\\\n]|\\.)*\"")
_COMMENT = re.compile(r"#[^\n]*")
STRING_FORMAT = _format("#b7791f")
COMMENT_FORMAT = _format("#7f8c8d", italic=True)


class PythonHighlighter(QSyntaxHighlighter):
    """Colours keywords, constants, numbers, calls, strings and comments, line by line.

    Rockly's generator writes every string on one line (newlines escaped), so a line-based
    highlighter is exact for generated code.
    """

    def highlightBlock(self, text: str):
        """Qt override: colour one line."""
        for pattern, text_format in _RULES:
            for match in pattern.finditer(text):
                self.setFormat(match.start(), match.end() - match.start(), text_format)
        strings = [(m.start(), m.end()) for m in _STRING.finditer(text)]
        for start, end in strings:
            self.setFormat(start, end - start, STRING_FORMAT)
        for match in _COMMENT.finditer(text):
            if not any(start < match.start() < end for start, end in strings):
                self.setFormat(match.start(), len(text) - match.start(), COMMENT_FORMAT)
                break
