"""The SDK's drawing helpers for a profile's simulator view: the one Rockly module besides
``rockly_desktop.sdk`` that profile code imports, and the only part of the SDK that uses Qt.

A view paints with a QPainter in its ``paintEvent``; these are the small pieces every view
needs: colours with alpha, pens, a card and a chip to put text on, fonts by pixel size,
numbers written as the language writes them, and text wrapped to a width. (Reading the
snapshot without trusting it is Qt-free: ``with_defaults``, ``as_number``... in the SDK.)
"""
from PySide6.QtCore import QLocale, Qt
from PySide6.QtGui import QColor, QFont, QPen, QTextLayout, QTextOption

MIN_TEXT_PX = 10          # smaller text is not read by a child at a glance
CARD = QColor("#FFFFFF")
_SHADOW = QColor(60, 70, 120, 28)
_CHIP_EDGE, _CHIP_FILL = QColor(60, 70, 120, 40), QColor(255, 255, 255, 225)
_WRAP_CACHE_SIZE = 256


def with_alpha(colour, alpha: float) -> QColor:
    """``colour`` with its alpha set to ``alpha`` (0..1, clamped)."""
    faded = QColor(colour)
    faded.setAlphaF(max(0.0, min(1.0, alpha)))
    return faded


def round_pen(colour, width: float, round_joins: bool = False) -> QPen:
    """A pen with round caps (and round joins), ``width`` in the painter's units."""
    pen = QPen(colour, width)
    pen.setCapStyle(Qt.PenCapStyle.RoundCap)
    if round_joins:
        pen.setJoinStyle(Qt.PenJoinStyle.RoundJoin)
    return pen


def cosmetic_pen(colour, width: float, round_caps: bool = False) -> QPen:
    """A pen ``width`` pixels wide whatever the painter's scale (and with round caps)."""
    pen = QPen(colour, width)
    pen.setCosmetic(True)
    if round_caps:
        pen.setCapStyle(Qt.PenCapStyle.RoundCap)
    return pen


def card(painter, rect, radius: float, accent=None, fill=CARD):
    """A card (white unless ``fill``) with a soft shadow, outlined in ``accent`` if given."""
    painter.setPen(Qt.PenStyle.NoPen)
    painter.setBrush(_SHADOW)
    painter.drawRoundedRect(rect.translated(0, 2), radius, radius)
    painter.setBrush(fill)
    if accent is not None:
        painter.setPen(QPen(accent, 2.5))
    painter.drawRoundedRect(rect, radius, radius)


def chip(painter, rect):
    """A translucent white pill for a short label over a map."""
    painter.setPen(QPen(_CHIP_EDGE, 1))
    painter.setBrush(_CHIP_FILL)
    painter.drawRoundedRect(rect, rect.height() / 2, rect.height() / 2)


def sized_font(base: QFont, px: float, bold: bool = False, min_px: int = MIN_TEXT_PX) -> QFont:
    """``base`` at ``px`` pixels, never below ``min_px``."""
    font = QFont(base)
    font.setPixelSize(max(min_px, int(round(px))))
    font.setBold(bold)
    return font


def decimal(value: float, places: int, language: str, sign: bool = False) -> str:
    """``value`` with ``places`` decimals (and a sign), with ``language``'s decimal point (1,60 in German);
    a value that rounds to zero has no sign ("0°", not "-0°" or "+0°")."""
    text = f"{value:{'+' if sign else ''}.{places}f}"
    if not text.strip("+-0."):
        text = text.lstrip("+-")
    return text.replace(".", QLocale(language).decimalPoint())


_wrapped = {}


def wrap_lines(text: str, font: QFont, width: float) -> list:
    """``text`` broken into lines no wider than ``width`` pixels: at words, else anywhere; its own
    line breaks kept, trailing empty lines dropped."""
    key = (text, font.toString(), round(width, 1))
    if key not in _wrapped:
        if len(_wrapped) > _WRAP_CACHE_SIZE:
            _wrapped.clear()
        _wrapped[key] = _layout_lines(text, font, width)
    return list(_wrapped[key])


def _layout_lines(text, font, width):
    option = QTextOption()
    option.setWrapMode(QTextOption.WrapMode.WrapAtWordBoundaryOrAnywhere)
    lines = []
    for paragraph in text.split("\n"):
        if not paragraph.strip():
            lines.append("")
            continue
        layout = QTextLayout(paragraph, font)
        layout.setTextOption(option)
        layout.beginLayout()
        while True:
            line = layout.createLine()
            if not line.isValid():
                break
            line.setLineWidth(max(1.0, width))
            lines.append(paragraph[line.textStart():line.textStart() + line.textLength()].rstrip())
        layout.endLayout()
    while lines and not lines[-1]:
        lines.pop()
    return lines
