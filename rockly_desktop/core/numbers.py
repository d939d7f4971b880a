"""Numbers written as a language writes them: its decimal mark and digit grouping ("0,15 m/s" in German).

Every text Rockly fills in from a catalogue goes through ``number_format(language)``, so a
``{speed:g}`` or ``{now:.1f}`` in a text is written the reader's way, and so do the state panels
(the simulator views use ``sdk_view.decimal``, which asks Qt). Only the marks change: the digits
are what the format spec says.
"""
import functools
import re
import string

# language -> (decimal mark, digit group mark); a language not named writes 1,234.5 (English).
_MARKS = {"de": (",", ".")}
_ENGLISH_MARKS = (".", ",")


def number_marks(language: str) -> tuple:
    """(decimal mark, digit group mark) of ``language`` ("de", or a locale name like "de_AT")."""
    return _MARKS.get(str(language).split("_")[0].split("-")[0], _ENGLISH_MARKS)


class LocalNumbers(string.Formatter):
    """``str.format`` whose numbers use a language's decimal mark and group mark; a number that
    rounds to zero has no minus ("0,0", not "-0,0")."""

    def __init__(self, language: str):
        super().__init__()
        point, group = number_marks(language)
        self._marks = None if (point, group) == _ENGLISH_MARKS else str.maketrans({".": point, ",": group})

    def format_field(self, value, format_spec):
        """``string.Formatter`` override: a number's text with this language's marks."""
        text = super().format_field(value, format_spec)
        if not isinstance(value, (int, float)) or isinstance(value, bool):
            return text
        if text.startswith("-") and not text.strip("-0.,"):
            text = text[1:]
        return text.translate(self._marks) if self._marks else text


@functools.lru_cache(maxsize=None)
def number_format(language: str) -> LocalNumbers:
    """The formatter for ``language`` (made once): ``number_format("de").format("{:.2f}", 0.15)`` is "0,15"."""
    return LocalNumbers(language)


def _number_pattern(point: str, group: str):
    """A number as a person types it with these marks: digits grouped in threes by ``group`` or not grouped at
    all, an optional decimal part after ``point`` and an exponent (``1e-3``)."""
    point, group = re.escape(point), re.escape(group)
    return re.compile(rf"[+-]?(?={point}?\d)(?:\d{{1,3}}(?:{group}\d{{3}})+|\d+)?(?:{point}\d+)?(?:e[+-]?\d+)?",
                      re.IGNORECASE)


_PATTERNS = {marks: _number_pattern(*marks) for marks in (_ENGLISH_MARKS, *_MARKS.values())}


def read_number(text: str, language: str):
    """The number a person typed in ``language``: "2,5" in German is 2.5; in English "1,000" is 1000 and "2,5",
    whose comma is neither a decimal mark nor a group of three, is refused. A group mark only counts between
    groups of three digits, so a number is never read as another. Raises ValueError for a text that is no
    number (or one that could be read two ways); a whole number typed without a decimal part is an int."""
    point, group = number_marks(language)
    typed = str(text).strip().replace("\u2212", "-").replace(" ", "").replace("\u202f", "")
    if not _PATTERNS[(point, group)].fullmatch(typed):
        raise ValueError(f"not a number in {language}: {text!r}")
    plain = typed.replace(group, "").replace(point, ".")
    return float(plain) if "." in plain or "e" in plain.lower() else int(plain)


def number_text(value, language: str) -> str:
    """``value`` as a person types it in ``language``, read back by ``read_number`` as the same number: "2,5" in
    German, never grouped (1000.0 is "1000")."""
    if isinstance(value, float) and value.is_integer():
        value = int(value)
    return number_format(language).format("{}", value)
