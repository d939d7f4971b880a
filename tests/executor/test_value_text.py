"""Values as people read them in the Variables dock (rockly_desktop/executor/value_text.py)."""
import math

import pytest

from rockly_desktop.executor.value_text import MAX_ITEMS, value_text


@pytest.mark.parametrize("value, language, text", [
    ("Mia", "en", "“Mia”"), ("Mia", "de", "„Mia“"), (None, "en", "–"), (True, "en", "true"), (False, "de", "falsch"),
    (7, "en", "7"), (3.5, "de", "3.5"), (0.1 + 0.2, "en", "0.3"), (7.0, "en", "7"), (math.inf, "en", "∞"),
    ([1, "cup", [True]], "en", "[1, “cup”, [true]]"), ({"x": 1.5, "name": "a"}, "en", "{x: 1.5, name: “a”}"),
    ((), "en", "[]"),
])
def test_values_are_written_as_people_read_them(value, language, text):
    assert value_text(value, language) == text


def test_long_values_are_shortened():
    assert value_text(list(range(100)), "en").endswith(f"{MAX_ITEMS - 1}, …]")
    assert value_text("x" * 1000, "en") == "“" + "x" * 200 + "…”"
    looped = []
    looped.append(looped)
    assert value_text(looped, "en") == "[[[[…]]]]"
