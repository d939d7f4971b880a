"""Numbers read as people type them, per language (the Qt side's one reader; the page's reads the same)."""
import pytest
from number_cases import READ, REFUSED

from rockly_desktop.core.numbers import number_text, read_number


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
