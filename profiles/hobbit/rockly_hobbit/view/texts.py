"""The view's words in each language, and setting them: fonts by pixel size, lines wrapped to a width."""
from PySide6.QtGui import QFont, QTextLayout, QTextOption

MIN_TEXT_PX = 11

TEXTS = {
    "en": {
        "emotions": {"HAPPY": "happy", "VHAPPY": "very happy", "LTIRED": "a bit tired", "VTIRED": "very tired",
                     "CONCERNED": "worried", "SAD": "sad", "WONDERING": "wondering", "NEUTRAL": "calm",
                     "SLEEPING": "asleep"},
        "motion": {"idle": "standing", "moving": "driving", "turning": "turning", "navigating": "driving to the flag"},
        "waiting": "Waiting for your answer", "yes": "Yes", "no": "No", "ok": "OK", "type": "Type here…",
        "tablet_off": "tablet is off",
        "arm": "Arm", "gripper": "Gripper", "head": "Head", "turntable": "Turntable",
        "open": "open", "closed": "closed", "out": "out", "stored": "stored",
    },
    "de": {
        "emotions": {"HAPPY": "fröhlich", "VHAPPY": "sehr fröhlich", "LTIRED": "etwas müde", "VTIRED": "sehr müde",
                     "CONCERNED": "besorgt", "SAD": "traurig", "WONDERING": "verwundert", "NEUTRAL": "ruhig",
                     "SLEEPING": "schläft"},
        "motion": {"idle": "steht", "moving": "fährt", "turning": "dreht sich", "navigating": "fährt zur Fahne"},
        "waiting": "Wartet auf deine Antwort", "yes": "Ja", "no": "Nein", "ok": "OK", "type": "Hier tippen…",
        "tablet_off": "Tablet ist aus",
        "arm": "Arm", "gripper": "Greifer", "head": "Kopf", "turntable": "Drehteller",
        "open": "offen", "closed": "zu", "out": "draußen", "stored": "eingefahren",
    },
}


def decimal(value, places, language):
    """``value`` with ``places`` decimals, with a decimal comma in German (as the state panels write it)."""
    text = f"{value:.{places}f}"
    return text.replace(".", ",") if language == "de" else text


def sized_font(base, px, bold=False):
    """``base`` at ``px`` pixels (never below MIN_TEXT_PX)."""
    font = QFont(base)
    font.setPixelSize(max(MIN_TEXT_PX, int(round(px))))
    font.setBold(bold)
    return font


_WRAP_CACHE = {}


def wrap_lines(text, font, width):
    """``text`` broken into lines no wider than ``width`` pixels (at words, else anywhere)."""
    key = (text, font.toString(), round(width, 1))
    if key not in _WRAP_CACHE:
        if len(_WRAP_CACHE) > 256:
            _WRAP_CACHE.clear()
        _WRAP_CACHE[key] = _layout_lines(text, font, width)
    return list(_WRAP_CACHE[key])


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
