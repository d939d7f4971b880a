"""Small painting helpers: pens, a colour with alpha, cards and chips."""
from PySide6.QtCore import Qt
from PySide6.QtGui import QColor, QPen

from .palette import CARD


def with_alpha(colour, alpha):
    c = QColor(colour)
    c.setAlphaF(max(0.0, min(1.0, alpha)))
    return c


def round_pen(colour, width):
    """A pen with round caps and joins, ``width`` in the painter's units."""
    pen = QPen(colour, width)
    pen.setCapStyle(Qt.PenCapStyle.RoundCap)
    pen.setJoinStyle(Qt.PenJoinStyle.RoundJoin)
    return pen


def cosmetic_pen(colour, width, round_caps=False):
    """A pen ``width`` pixels wide whatever the painter's scale."""
    pen = QPen(colour, width)
    pen.setCosmetic(True)
    if round_caps:
        pen.setCapStyle(Qt.PenCapStyle.RoundCap)
    return pen


def card(p, rect, radius):
    """A white card with a soft shadow."""
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(QColor(50, 60, 100, 26))
    p.drawRoundedRect(rect.translated(0, 2), radius, radius)
    p.setBrush(CARD)
    p.drawRoundedRect(rect, radius, radius)


def chip(p, rect):
    """A translucent white pill for a short label over the map."""
    p.setPen(QPen(QColor(50, 60, 100, 40), 1))
    p.setBrush(QColor(255, 255, 255, 225))
    p.drawRoundedRect(rect, rect.height() / 2, rect.height() / 2)
