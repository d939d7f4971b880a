"""A program's values as people read them in the Variables dock: a text in quotes as the language
writes them (“Mia”, „Mia“), true/false in the blocks' words, numbers without float noise, lists
in brackets; no Python quotes or None. Long values are shortened with "…".
"""
import math

MAX_TEXT = 200          # characters of a text shown
MAX_ITEMS = 20          # items of a list or message shown
MAX_DEPTH = 3           # lists in lists shown this deep
NO_VALUE = "–"          # a variable that has no value yet
_QUOTES = {"de": ("„", "“")}
_TRUTH = {"en": ("true", "false"), "de": ("wahr", "falsch")}   # the logic blocks' own words


def value_text(value, language: str) -> str:
    """``value`` as the Variables dock shows it in ``language`` ('de' German, anything else English)."""
    return _text(value, language, 0)


def _text(value, language, depth):
    if value is None:
        return NO_VALUE
    if isinstance(value, bool):
        true, false = _TRUTH.get(language, _TRUTH["en"])
        return true if value else false
    if isinstance(value, str):
        opening, closing = _QUOTES.get(language, ("“", "”"))
        shown = value if len(value) <= MAX_TEXT else value[:MAX_TEXT] + "…"
        return f"{opening}{shown}{closing}"
    if isinstance(value, float):
        return _number(value)
    if isinstance(value, int):
        return str(value)
    if isinstance(value, (list, tuple, dict)):
        return _collection(value, language, depth)
    shown = str(value)
    return shown if len(shown) <= MAX_TEXT else shown[:MAX_TEXT] + "…"


def _collection(value, language, depth):
    """[a, b] for a list, {key: a} for a message; deeper than MAX_DEPTH only "…" inside."""
    brackets = "{}" if isinstance(value, dict) else "[]"
    if depth >= MAX_DEPTH and value:
        return brackets[0] + "…" + brackets[1]
    if isinstance(value, dict):
        texts = [f"{key}: {_text(item, language, depth + 1)}" for key, item in list(value.items())[:MAX_ITEMS]]
    else:
        texts = [_text(item, language, depth + 1) for item in value[:MAX_ITEMS]]
    return brackets[0] + ", ".join(texts + (["…"] if len(value) > MAX_ITEMS else [])) + brackets[1]


def _number(value):
    if math.isinf(value):
        return "∞" if value > 0 else "-∞"
    if math.isnan(value):
        return "NaN"
    return format(value, ".12g")
