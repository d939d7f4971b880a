"""core/deep_json: the same answers as ``json`` where ``json`` copes, any depth where it does not,
and only numbers the editor page's JSON.parse accepts too."""
import json

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rockly_desktop.core import deep_json
from rockly_desktop.core.deep_json import _dumps_iteratively, _loads_iteratively

JSON_VALUES = st.recursive(
    st.none() | st.booleans() | st.integers() | st.floats(allow_nan=False, allow_infinity=False) | st.text(),
    lambda children: st.lists(children, max_size=4) | st.dictionaries(st.text(max_size=8), children, max_size=4),
    max_leaves=30,
)


@settings(max_examples=300, deadline=None)
@given(JSON_VALUES)
def test_the_iterative_codec_agrees_with_json(value):
    for ascii_only in (True, False):
        text = json.dumps(value, ensure_ascii=ascii_only)
        assert _dumps_iteratively(value, ascii_only) == text
        assert _loads_iteratively(text) == json.loads(text)


def outcome(loads, text):
    try:
        return "read", loads(text)
    except ValueError:
        return "refused", None


@settings(max_examples=500, deadline=None)
@given(st.text(alphabet='[]{}",:0123456789.eE-+ \\truefalsnIiNy', max_size=40) | st.text(max_size=40))
def test_any_text_is_read_as_json_reads_it_or_refused_with_a_value_error(text):
    fast, iterative = outcome(deep_json.loads, text), outcome(_loads_iteratively, text)
    assert fast == iterative
    plain = outcome(json.loads, text)
    if plain != fast:  # only numbers JSON.parse would not take are refused beyond what json refuses
        assert fast[0] == "refused" and any(word in text for word in ("NaN", "Infinity", "e", "E"))


def deep_stack(count):
    block = {"type": "hobbit_stop"}
    for _ in range(count - 1):
        block = {"type": "hobbit_stop", "next": {"block": block}}
    return block


def test_a_stack_far_deeper_than_pythons_recursion_limit_round_trips():
    document = {"workspace": deep_stack(20_000)}

    text = deep_json.dumps(document, indent=1)

    assert deep_json.dumps(deep_json.loads(text)) == deep_json.dumps(document)  # == itself would recurse
    assert len(text) < 1_000_000  # written compact: indentation would grow with the square of the depth


def test_a_shallow_document_keeps_its_indentation():
    assert deep_json.dumps({"a": [1]}, indent=1) == '{\n "a": [\n  1\n ]\n}'


@pytest.mark.parametrize("text", ["NaN", "[Infinity]", '{"x": -Infinity}', "1e400", "[-1e999]"])
def test_numbers_the_page_cannot_read_are_refused(text):
    with pytest.raises(ValueError):
        deep_json.loads(text)
    with pytest.raises(ValueError):
        deep_json.loads("[" * 2000 + text + "]" * 2000)  # the iterative path too


def test_writing_a_number_json_has_no_word_for_is_refused():
    with pytest.raises(ValueError):
        deep_json.dumps({"x": float("nan")})


def test_nesting_past_the_bound_is_refused_clearly():
    with pytest.raises(deep_json.TooDeep, match="nested too deeply"):
        deep_json.loads("[" * (deep_json.MAX_DEPTH + 1) + "]" * (deep_json.MAX_DEPTH + 1))


def test_broken_deep_text_names_where_it_breaks():
    text = "[" * 3000 + "1,,"
    with pytest.raises(json.JSONDecodeError) as caught:
        deep_json.loads(text)
    assert caught.value.pos == 3002
