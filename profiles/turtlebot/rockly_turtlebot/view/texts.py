"""The view's words in each language, and fonts by pixel size."""
from PySide6.QtGui import QFont

MIN_TEXT_PX = 10

TEXTS = {
    "en": {"language": "en", "laser": "Laser", "ahead": "ahead", "nothing": "nothing in sight", "speed": "Speed",
           "driving": "driving", "turning": "turning", "battery": "Battery", "bumped": "Bump!",
           "bumps": "bumps", "standing": "standing still"},
    "de": {"language": "de", "laser": "Laser", "ahead": "vorne", "nothing": "nichts in Sicht", "speed": "Tempo",
           "driving": "fahren", "turning": "drehen", "battery": "Akku", "bumped": "Rums!",
           "bumps": "Stöße", "standing": "steht still"},
}


def decimal(value, places, language, sign=False):
    """``value`` with ``places`` decimals, with a decimal comma in German."""
    text = f"{value:{'+' if sign else ''}.{places}f}"
    return text.replace(".", ",") if language == "de" else text


def sized_font(base, px, bold=False):
    """``base`` at ``px`` pixels (never below MIN_TEXT_PX)."""
    font = QFont(base)
    font.setPixelSize(max(MIN_TEXT_PX, int(round(px))))
    font.setBold(bold)
    return font
