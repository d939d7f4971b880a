"""The views' drawing helpers (rockly_desktop/sdk_view.py), as profile views use them."""
import pytest
from PySide6.QtCore import QRectF
from PySide6.QtGui import QColor, QFont, QImage, QPainter

from rockly_desktop import sdk_view


@pytest.mark.parametrize("value, places, language, sign, text", [
    (1.6, 2, "en", False, "1.60"), (1.6, 2, "de", False, "1,60"), (-0.25, 1, "de", True, "-0,2"),
    (0.25, 2, "en", True, "+0.25"), (3.0, 0, "de", False, "3"),
    (-0.3, 0, "en", False, "0"), (-0.001, 2, "de", True, "0,00"), (-0.6, 0, "en", False, "-1"),
])
def test_numbers_are_written_as_the_language_writes_them(value, places, language, sign, text):
    assert sdk_view.decimal(value, places, language, sign) == text


def test_fonts_never_get_smaller_than_readable(qapp):
    base = QFont()
    assert sdk_view.sized_font(base, 3).pixelSize() == sdk_view.MIN_TEXT_PX
    assert sdk_view.sized_font(base, 3, min_px=11).pixelSize() == 11
    big = sdk_view.sized_font(base, 23.6, bold=True)
    assert (big.pixelSize(), big.bold()) == (24, True)


def test_text_is_wrapped_at_words_keeping_its_own_line_breaks(qapp):
    font = sdk_view.sized_font(QFont(), 14)
    lines = sdk_view.wrap_lines("one two three four five six seven\n\nlast\n\n", font, 80)
    assert len(lines) > 3 and lines[-1] == "last" and "" in lines
    assert " ".join(line for line in lines if line) == "one two three four five six seven last"
    assert sdk_view.wrap_lines("x" * 200, font, 50)[0] != "x" * 200   # a word too long breaks anywhere


def test_colours_and_pens():
    assert sdk_view.with_alpha(QColor("#FF0000"), 1.7).alphaF() == 1.0
    assert sdk_view.with_alpha("#FF0000", -1).alpha() == 0
    assert sdk_view.cosmetic_pen(QColor("red"), 2).isCosmetic()
    assert not sdk_view.round_pen(QColor("red"), 0.1).isCosmetic()


def test_cards_and_chips_paint_white_shapes(qapp):
    image = QImage(200, 100, QImage.Format.Format_ARGB32)
    image.fill(QColor("#000000"))
    painter = QPainter(image)
    sdk_view.card(painter, QRectF(10, 10, 80, 60), 8, accent=QColor("red"))
    sdk_view.chip(painter, QRectF(110, 30, 80, 30))
    painter.end()
    assert QColor(image.pixel(50, 40)) == QColor("#FFFFFF")
    assert QColor(image.pixel(150, 45)).lightness() > 200
