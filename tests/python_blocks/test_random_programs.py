"""Random block programs, built from the toolbox's blocks (HOBBIT's commands, loops, conditions, variables,
logic, math, text and lists), go blocks → Python → blocks → Python through the real editor page unchanged; a
Python block is allowed only where the level offers every block (Full)."""
import json

from block_round_trip import round_trip
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from program_builder import block, number, rockly_document, stack, text

from rockly_desktop.lessons.check import level_blocks
from rockly_desktop.python_blocks.workspace import PYTHON_BLOCK

VARIABLES = ("speed", "name")
numbers = st.one_of(st.integers(-1000, 1000), st.floats(-100, 100, allow_nan=False).map(lambda x: round(x, 3)))
words = st.text(st.characters(codec="utf-8", exclude_categories=("Cs",)), max_size=12)


def get(name):
    return block("variables_get", {"VAR": {"id": name}})


def two(block_type, operators, inner):
    return st.tuples(st.sampled_from(operators), inner, inner).map(
        lambda parts: block(block_type, {"OP": parts[0]}, {"A": parts[1], "B": parts[2]}))


def joined(block_type, inner):
    # one text alone is written as that text: it comes back as a text block, not a join of one
    return st.lists(inner, min_size=2, max_size=4).map(lambda items: block(
        block_type, inputs={f"ADD{index}": item for index, item in enumerate(items)},
        extraState={"itemCount": len(items)}))


def number_values(depth: int = 2):
    leaves = st.one_of(numbers.map(number), st.sampled_from(VARIABLES).map(get))
    if depth == 0:
        return leaves
    inner = number_values(depth - 1)
    return st.one_of(leaves, two("math_arithmetic", ["ADD", "MINUS", "MULTIPLY", "DIVIDE", "POWER"], inner))


def text_values(depth: int = 1):
    leaves = st.one_of(words.map(text), st.sampled_from(VARIABLES).map(get))
    if depth == 0:
        return leaves
    return st.one_of(leaves, joined("text_join", st.one_of(text_values(depth - 1), number_values(1))))


def boolean_values(depth: int = 2):
    leaves = st.one_of(st.booleans().map(lambda flag: block("logic_boolean", {"BOOL": "TRUE" if flag else "FALSE"})),
                       two("logic_compare", ["EQ", "NEQ", "LT", "GTE"], number_values(1)))
    if depth == 0:
        return leaves
    inner = boolean_values(depth - 1)
    return st.one_of(leaves, two("logic_operation", ["AND", "OR"], inner),
                     inner.map(lambda value: block("logic_negate", inputs={"BOOL": value})))


def any_values():
    return st.one_of(number_values(), text_values(), boolean_values(1),
                     joined("lists_create_with", st.one_of(number_values(1), text_values(0))))


def statements(depth: int = 2):
    simple = st.one_of(
        st.tuples(number_values(), st.sampled_from(["+", "-"])).map(
            lambda parts: block("hobbit_move", {"direction": parts[1]}, {"speed": parts[0]})),
        text_values().map(lambda value: block("hobbit_show_info", inputs={"text": value})),
        st.sampled_from(["HAPPY", "VHAPPY", "CONCERNED"]).map(
            lambda emotion: block("hobbit_emo", {"emotion": emotion})),
        st.tuples(st.sampled_from(VARIABLES), any_values()).map(
            lambda parts: block("variables_set", {"VAR": {"id": parts[0]}}, {"VALUE": parts[1]})),
        st.tuples(st.sampled_from(VARIABLES), number_values(1)).map(
            lambda parts: block("math_change", {"VAR": {"id": parts[0]}}, {"DELTA": parts[1]})),
    )
    if depth == 0:
        return simple
    body = st.lists(statements(depth - 1), min_size=1, max_size=3).map(lambda blocks: stack(*blocks))
    return st.one_of(
        simple,
        st.tuples(st.integers(0, 20), body).map(
            lambda parts: block("controls_repeat_ext", inputs={"TIMES": number(parts[0]), "DO": parts[1]})),
        st.tuples(boolean_values(1), body, st.none() | body).map(lambda parts: block(
            "controls_if", inputs={"IF0": parts[0], "DO0": parts[1], **({"ELSE": parts[2]} if parts[2] else {})},
            **({"extraState": {"hasElse": True}} if parts[2] else {}))),
        # `while not x` is also "repeat until x": a negation under "while" comes back as "until"
        st.tuples(st.sampled_from(["WHILE", "UNTIL"]), boolean_values(1), body).filter(
            lambda parts: parts[0] == "UNTIL" or parts[1]["type"] != "logic_negate").map(lambda parts: block(
                "controls_whileUntil", {"MODE": parts[0]}, {"BOOL": parts[1], "DO": parts[2]})),
    )


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                  HealthCheck.function_scoped_fixture])
@given(program=st.lists(statements(), min_size=1, max_size=6))
def test_random_block_programs_round_trip(program, headless_editor, registry, tmp_path_factory):
    folder = tmp_path_factory.mktemp("random")
    path = folder / "random.rockly"
    document = json.loads(rockly_document([stack(*program)]))
    document["workspace"]["variables"] = [{"name": name, "id": name} for name in VARIABLES]
    path.write_text(json.dumps(document))
    conversion, python, python_again, tree, tree_again = round_trip(headless_editor, registry, path, folder)
    assert python_again == python, (python, python_again)
    assert conversion.lossless, conversion.kept_python
    assert tree_again == tree


def test_a_python_block_is_beyond_every_level_but_full(registry):
    hobbit = registry.get("hobbit")
    assert level_blocks(hobbit, "full") is None  # every block
    for level in ("starter", "explorer"):
        assert PYTHON_BLOCK not in level_blocks(hobbit, level)
