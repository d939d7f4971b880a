"""Blocks the editor page would choke on are refused first, naming the block and what is wrong."""
import xml.etree.ElementTree as ElementTree

import pytest
from program_builder import block, stack, workspace

from rockly_desktop.core.workspace_checks import MAX_EXTRA_ITEMS, workspace_problem, xml_problem

BAD_BLOCKS = [
    ("a field holding a list", block("text", {"TEXT": ["a"]}), "block 2 (text): its field TEXT holds list"),
    ("a field holding an object", block("text", {"TEXT": {"x": 1}}), "its field TEXT holds an object"),
    ("a number as id", block("text", id=5), "block 2 (text): its id is int, not text"),
    ("fields as a list", block("text", fields=None) | {"fields": []}, "its fields are not an object"),
    ("inputs as a list", block("text_print") | {"inputs": []}, "its inputs are not an object"),
    ("an input holding text", block("text_print") | {"inputs": {"TEXT": "hello"}}, "its input TEXT does not hold"),
    ("next as a list", block("hobbit_stop") | {"next": [1]}, "its next is not an object"),
    ("a position in words", block("hobbit_stop", x="left"), "its position x is not a number"),
    ("a join of 100 million texts", block("text_join", extraState={"itemCount": 100_000_000}),
     "block 2 (text_join): its saved state itemCount asks for 100,000,000"),
    ("a million parameters", block("procedures_defnoreturn", extraState={"params": [{"name": "p"}] * 1_000_000}),
     "its saved state params lists 1,000,000 items"),
]


@pytest.mark.parametrize("bad, problem", [case[1:] for case in BAD_BLOCKS], ids=[case[0] for case in BAD_BLOCKS])
def test_a_bad_block_is_named_with_its_number_type_and_problem(bad, problem):
    program = workspace(stack(block("hobbit_stop"), bad))

    assert problem in workspace_problem(program)


def test_good_programs_pass():
    program = workspace(stack(
        block("text_join", extraState={"itemCount": 3}),
        block("controls_if", extraState={"elseIfCount": 2, "hasElse": True}),
        block("variables_set", {"VAR": {"id": "v1"}}),
    ), block("math_number", {"NUM": 1e300}, x=10.5, y=-3))

    assert workspace_problem(program) is None


def test_top_level_entries_that_are_not_blocks_are_named():
    assert workspace_problem({"blocks": {"blocks": [block("hobbit_stop"), "stop"]}}) == (
        "top-level block 2 is not a block (an object)")


def test_xml_mutations_asking_for_too_many_inputs_are_refused():
    root = ElementTree.fromstring('<xml><block type="hobbit_stop"></block><block type="text_join">'
                                  f'<mutation items="{MAX_EXTRA_ITEMS + 1}"></mutation></block></xml>')

    assert xml_problem(root) == "block 2 (text_join): its mutation items asks for 1001 (at most 1,000)"


def test_xml_mutations_of_a_usual_size_pass():
    root = ElementTree.fromstring('<xml><block type="controls_if"><mutation elseif="2" else="1"/></block></xml>')

    assert xml_problem(root) is None
