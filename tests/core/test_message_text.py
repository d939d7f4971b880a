"""How the Topic monitor writes values: exact numbers, quoted strings, bytes by size, list summaries."""
from rockly_desktop.core.message_text import TEXT_LIMIT, summary, value_kind, value_text


def items(count):
    return f"{count} items"


def test_kinds():
    assert [value_kind(v) for v in ({}, [], (), 3, 2.5, True, "x", None, b"")] == [
        "dict", "list", "list", "number", "number", "leaf", "leaf", "leaf", "leaf"]


def test_values_are_shown_exactly():
    assert value_text(1.945) == "1.945" and value_text(0.1 + 0.2) == "0.3" and value_text(2.0) == "2.0"
    assert value_text(1e300) == "1e+300" and value_text(float("nan")) == "nan" and value_text(3) == "3"
    assert value_text(True) == "True" and value_text(None) == "None"
    assert value_text('say "hi"\n') == '"say \\"hi\\"\\n"'
    assert value_text("ä") == '"ä"'


def test_long_values_are_clipped_and_bytes_shown_by_size():
    assert value_text("x" * 500) == '"' + "x" * (TEXT_LIMIT - 1) + "…"
    assert value_text(bytes(range(3))) == "<3 bytes> 00 01 02"
    assert value_text(bytes(20)) == "<20 bytes> " + " ".join(["00"] * 16) + " …"


def test_summaries_of_dicts_and_lists():
    assert summary({"a": 1}, items) == ""
    assert summary([], items) == "[]"
    assert summary([1.0, 2.5, 3], items) == "[1.0, 2.5, 3]"
    assert summary([{"name": "a"}, {"name": "b"}], items) == "2 items"
    assert summary([0.0] * 36, items) == "(36) [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, …]"
    assert summary(["x" * 40, "y" * 40], items) == '(2) ["' + "x" * 40 + '", …]'
