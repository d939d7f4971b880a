"""Numbers read as people type them, per language (the Qt side's one reader; the page's reads the same)."""
import pytest

from rockly_desktop.core.numbers import number_text, read_number

READ = [("de", "2,5", 2.5), ("de", "-0,25", -0.25), ("de", "1.000", 1000), ("de", "1.000,5", 1000.5),
        ("de", ",5", 0.5), ("de", "3", 3), ("de", " 7 ", 7), ("en", "2.5", 2.5), ("en", "1,000", 1000),
        ("en", "1,000.5", 1000.5), ("en", "-.5", -0.5), ("en", "1e3", 1000.0), ("en", "\u22124", -4)]
"""(language, typed, the number read): shared with the page's reader's test."""

REFUSED = [("en", "2,5"), ("en", "1,5000"), ("en", "1,00"), ("en", "12,34,567"), ("de", "2.5"), ("de", "1,000,5"),
           ("en", ""), ("en", "-"), ("en", "."), ("en", "e3"), ("en", "abc"), ("en", "2.5.1")]
"""(language, typed): texts that are no number, or could be read two ways."""


@pytest.mark.parametrize(("language", "typed", "number"), READ)
def test_a_number_is_read_as_its_language_writes_it(language, typed, number):
    value = read_number(typed, language)
    assert value == number and type(value) is type(number)


@pytest.mark.parametrize(("language", "typed"), REFUSED)
def test_a_comma_that_is_no_mark_of_the_language_is_refused_not_dropped(language, typed):
    with pytest.raises(ValueError):
        read_number(typed, language)


@pytest.mark.parametrize(("language", "number", "text"), [
    ("de", 2.5, "2,5"), ("en", 2.5, "2.5"), ("de", 1000.0, "1000"), ("de", -0.125, "-0,125"), ("en", 12000, "12000")])
def test_a_number_is_written_back_as_it_is_read(language, number, text):
    assert number_text(number, language) == text
    assert read_number(text, language) == number
