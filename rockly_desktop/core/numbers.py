"""Numbers written as a language writes them: its decimal mark and digit grouping ("0,15 m/s" in German).

Every text Rockly fills in from a catalogue goes through ``number_format(language)``, so a
``{speed:g}`` or ``{now:.1f}`` in a text is written the reader's way, and so do the state panels
(the simulator views use ``sdk_view.decimal``, which asks Qt). Only the marks change: the digits
are what the format spec says.
"""
import functools
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

