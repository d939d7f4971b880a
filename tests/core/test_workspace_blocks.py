"""Which block types a program uses (Blockly JSON and first-Rockly XML), and renaming old fields."""
import xml.etree.ElementTree as ElementTree
from collections import Counter
from pathlib import Path

import pytest
import yaml

from rockly_desktop.core.errors import ProgramFileError
from rockly_desktop.core.workspace_blocks import (
    block_types_in_workspace,
    block_types_in_xml,
    blocks_in_file_order,
    parse_blockly_xml,
    rename_legacy_fields,
    untyped_block_number,
    untyped_xml_block_number,
    xml_to_text,
)

REPO = Path(__file__).resolve().parents[2]
BLOCKLY_NS = "https://developers.google.com/blockly/xml"

# The gripper alias as HOBBIT's profile.yaml declares it (checked against the file below).
GRIPPER_ALIAS = {"hobbit_arm_gripper": {"gripper_position": {
    "field": "movement", "values": {"open": "OpenGripper", "close": "CloseGripper"}}}}


def number(value):
    return {"type": "math_number", "fields": {"NUM": value}}


def test_empty_workspaces_have_no_blocks():
    assert block_types_in_workspace({}) == Counter()
    assert block_types_in_workspace({"blocks": {"languageVersion": 0, "blocks": []}}) == Counter()
    assert block_types_in_workspace({"variables": [{"name": "x", "id": "1"}]}) == Counter()


def test_counts_blocks_in_next_chains_nested_inputs_and_shadows():
    condition = {"type": "logic_compare", "fields": {"OP": "EQ"},
                 "inputs": {"A": {"shadow": number(1), "block": {"type": "math_arithmetic",
                                                                   "inputs": {"A": {"shadow": number(2)},
                                                                              "B": {"shadow": number(3)}}}},
                            "B": {"block": {"type": "hobbit_yes_no",
                                            "inputs": {"text": {"shadow": {"type": "text",
                                                                           "fields": {"TEXT": "?"}}}}}}}}
    body = {"type": "hobbit_head", "fields": {"head_position": "up_left"},
            "next": {"block": {"type": "hobbit_emo", "fields": {"emotion": "HAPPY"},
                               "next": {"block": {"type": "hobbit_head",
                                                  "fields": {"head_position": "center_center"}}}}}}
    if_block = {"type": "controls_if", "inputs": {"IF0": {"block": condition}, "DO0": {"block": body}},
                "next": {"block": {"type": "hobbit_move", "fields": {"direction": "+"},
                                   "inputs": {"speed": {"shadow": number(1)}}}}}
    loose = {"type": "hobbit_stop", "x": 300, "y": 10}
    workspace = {"blocks": {"languageVersion": 0, "blocks": [if_block, loose]}}

    assert block_types_in_workspace(workspace) == Counter({
        "controls_if": 1, "logic_compare": 1, "math_arithmetic": 1, "math_number": 4, "hobbit_yes_no": 1,
        "text": 1, "hobbit_head": 2, "hobbit_emo": 1, "hobbit_move": 1, "hobbit_stop": 1,
    })


def test_shadow_and_block_in_the_same_input_are_both_counted():
    block = {"type": "hobbit_wait", "inputs": {"seconds": {"shadow": number(1), "block": {"type": "math_random_int"}}}}
    counts = block_types_in_workspace({"blocks": {"blocks": [block]}})
    assert counts == Counter({"hobbit_wait": 1, "math_number": 1, "math_random_int": 1})


def test_a_very_long_chain_does_not_hit_the_recursion_limit():
    chain = None
    for _ in range(5000):
        chain = {"type": "hobbit_stop", **({"next": {"block": chain}} if chain else {})}
    assert block_types_in_workspace({"blocks": {"blocks": [chain]}}) == Counter({"hobbit_stop": 5000})


def test_block_without_a_type_is_counted_under_a_readable_name():
    counts = block_types_in_workspace({"blocks": {"blocks": [{"id": "a"}, {"type": ""}, {"type": ["x"]}]}})
    assert counts == Counter({"(block without a type)": 3})


def test_blocks_are_numbered_in_the_order_the_file_has_them():
    program = {"blocks": {"blocks": [
        {"type": "a", "inputs": {"X": {"shadow": {"type": "b"},
                                       "block": {"type": "c", "next": {"block": {"type": "d"}}}},
                                 "Y": {"block": {"type": "e"}}},
         "next": {"block": {"type": "f"}}},
        {"next": {"block": {"type": "h"}}, "type": "g"},
        "not a block",
        {"type": "i"},
    ]}}
    assert [block["type"] for block in blocks_in_file_order(program)] == list("abcdefghi")


def test_the_first_block_without_a_type_is_named_by_its_number():
    assert untyped_block_number({"blocks": {"blocks": [{"type": "a", "next": {"block": {"type": "b"}}}]}}) is None
    assert untyped_block_number({}) is None
    for untyped in ({}, {"type": ""}, {"type": None}, {"type": ["x"]}):
        program = {"blocks": {"blocks": [{"type": "a", "inputs": {"X": {"block": {"type": "b"}}},
                                          "next": {"block": {**untyped, "next": {"block": {}}}}}]}}
        assert untyped_block_number(program) == 3
    assert untyped_xml_block_number(parse_blockly_xml('<xml><block type="a"><value name="V"><shadow type="b"/></value>'
                                                      '<next><block><field name="f">x</field></block></next>'
                                                      '</block></xml>')) == 3
    assert untyped_xml_block_number(parse_blockly_xml('<xml><block type="a"/></xml>')) is None


@pytest.mark.parametrize("workspace", [
    {"blocks": []},
    {"blocks": "hobbit_move"},
    {"blocks": {"blocks": {"type": "hobbit_move"}}},
    {"blocks": {"blocks": ["hobbit_move", 3, None]}},
    {"blocks": {"blocks": [{"type": "hobbit_move", "inputs": ["speed"], "next": "hobbit_stop"}]}},
    {"blocks": {"blocks": [{"type": "hobbit_move", "inputs": {"speed": "1", "x": None}, "next": {"block": 5}}]}},
], ids=["blocks a list", "blocks a string", "top blocks a mapping", "junk items", "inputs a list", "junk connections"])
def test_malformed_workspace_from_a_hand_edited_file_does_not_crash(workspace):
    counts = block_types_in_workspace(workspace)
    assert set(counts) <= {"hobbit_move"}


# --- first-Rockly XML -------------------------------------------------------------------------

FIRST_ROCKLY_XML = """<xml{ns}>
  <variables><variable type="" id="v1">answer</variable></variables>
  <block type="hobbit_arm_gripper" id="g1" x="38" y="63">
    <field name="gripper_position">open</field>
    <next>
      <block type="controls_if" id="if1">
        <value name="IF0">
          <block type="hobbit_yes_no" id="yn">
            <field name="yes_no">D_YES</field>
            <value name="text"><shadow type="text" id="t1"><field name="TEXT">Shall I close it?</field></shadow></value>
          </block>
        </value>
        <statement name="DO0">
          <block type="hobbit_arm_gripper" id="g2">
            <field name="gripper_position">close</field>
            <next>
              <block type="hobbit_move" id="m1">
                <field name="direction">+</field>
                <value name="speed"><shadow type="math_number" id="n1"><field name="NUM">1</field></shadow></value>
              </block>
            </next>
          </block>
        </statement>
      </block>
    </next>
  </block>
</xml>
"""
EXPECTED_XML_TYPES = Counter({"hobbit_arm_gripper": 2, "controls_if": 1, "hobbit_yes_no": 1, "text": 1,
                              "hobbit_move": 1, "math_number": 1})


@pytest.fixture(params=["", f' xmlns="{BLOCKLY_NS}"'], ids=["no namespace", "blockly namespace"])
def first_rockly_xml(request):
    return FIRST_ROCKLY_XML.format(ns=request.param)


def test_first_rockly_xml_parses_with_and_without_namespace(first_rockly_xml):
    root = parse_blockly_xml(first_rockly_xml, "old.xml")
    assert root.tag.rsplit("}", 1)[-1] == "xml"
    assert block_types_in_xml(root) == EXPECTED_XML_TYPES


def test_xml_block_count_ignores_fields_values_and_variables():
    root = parse_blockly_xml('<xml><variables><variable>block</variable></variables>'
                             '<block type="a"><field name="block">shadow</field>'
                             '<value name="V"><block type="b"/></value>'
                             '</block><block/></xml>')
    assert block_types_in_xml(root) == Counter({"a": 1, "b": 1, "(block without a type)": 1})


def test_empty_xml_document_has_no_blocks():
    assert block_types_in_xml(parse_blockly_xml("<xml/>")) == Counter()
    assert block_types_in_xml(parse_blockly_xml(f'<xml xmlns="{BLOCKLY_NS}"></xml>')) == Counter()


@pytest.mark.parametrize("text", ["", "   \n\t"], ids=["empty", "whitespace"])
def test_empty_xml_text_says_the_file_is_empty(text):
    with pytest.raises(ProgramFileError) as caught:
        parse_blockly_xml(text, "empty.xml")
    assert caught.value.problem == "the file is empty"
    assert caught.value.path == "empty.xml"


@pytest.mark.parametrize("text", [
    '<xml><block type="a"></xml>',
    '<xml><block type="a">',
    "not xml at all",
    '{"format": "rockly-program"}',
], ids=["mismatched tag", "truncated", "plain text", "json"])
def test_broken_xml_says_it_is_not_valid_blockly_xml(text):
    with pytest.raises(ProgramFileError) as caught:
        parse_blockly_xml(text, "broken.xml")
    assert caught.value.problem.startswith("this is not valid Blockly XML (")
    assert "line 1" in caught.value.problem
    assert caught.value.path == "broken.xml"


@pytest.mark.parametrize("text, top", [
    ("<html><body>hi</body></html>", "html"),
    ('<?xml version="1.0"?><svg xmlns="http://www.w3.org/2000/svg"/>', "svg"),
    (f'<block xmlns="{BLOCKLY_NS}" type="hobbit_stop"/>', "block"),
], ids=["html", "svg", "bare block"])
def test_xml_whose_top_element_is_not_xml_is_refused_naming_the_element(text, top):
    with pytest.raises(ProgramFileError) as caught:
        parse_blockly_xml(text, "other.xml")
    assert caught.value.problem == f"this is not a Blockly program (the top element is <{top}>, not <xml>)"


# --- old field names ----------------------------------------------------------------------


def gripper_fields(root):
    return [(element.get("id"), [(field.get("name"), field.text) for field in element
                                 if field.tag.rsplit("}", 1)[-1] == "field"])
            for element in root.iter() if element.get("type") == "hobbit_arm_gripper"]


def test_hobbit_profile_declares_the_gripper_alias_used_here():
    manifest = yaml.safe_load((REPO / "profiles" / "hobbit" / "profile.yaml").read_text(encoding="utf-8"))
    assert manifest["legacy_fields"] == GRIPPER_ALIAS


def test_old_gripper_field_becomes_movement_with_new_values(first_rockly_xml):
    root = parse_blockly_xml(first_rockly_xml)

    changed = rename_legacy_fields(root, GRIPPER_ALIAS)

    assert changed == 2
    assert gripper_fields(root) == [("g1", [("movement", "OpenGripper")]), ("g2", [("movement", "CloseGripper")])]
    assert block_types_in_xml(root) == EXPECTED_XML_TYPES


def test_renaming_touches_no_other_block_or_field(first_rockly_xml):
    root = parse_blockly_xml(first_rockly_xml)
    rename_legacy_fields(root, GRIPPER_ALIAS)
    fields = {(element.get("id"), field.get("name"), field.text)
              for element in root.iter() for field in element if field.tag.rsplit("}", 1)[-1] == "field"}
    assert {("yn", "yes_no", "D_YES"), ("t1", "TEXT", "Shall I close it?"),
            ("m1", "direction", "+"), ("n1", "NUM", "1")} <= fields


def test_renaming_a_program_already_in_the_new_form_changes_nothing():
    text = '<xml><block type="hobbit_arm_gripper" id="g"><field name="movement">OpenGripper</field></block></xml>'
    root = parse_blockly_xml(text)
    assert rename_legacy_fields(root, GRIPPER_ALIAS) == 0
    assert gripper_fields(root) == [("g", [("movement", "OpenGripper")])]


def test_an_unknown_old_value_keeps_its_text_under_the_new_name():
    root = parse_blockly_xml('<xml><block type="hobbit_arm_gripper" id="g">'
                             '<field name="gripper_position">half</field></block></xml>')
    assert rename_legacy_fields(root, GRIPPER_ALIAS) == 1
    assert gripper_fields(root) == [("g", [("movement", "half")])]


def test_an_alias_without_values_only_renames_the_field():
    root = parse_blockly_xml('<xml><block type="old_block"><field name="SPEED">3</field></block></xml>')
    assert rename_legacy_fields(root, {"old_block": {"SPEED": {"field": "speed"}}}) == 1
    field = root.find("block/field")
    assert (field.get("name"), field.text) == ("speed", "3")


def test_a_field_of_a_nested_block_is_renamed_only_under_its_own_block_type():
    text = ('<xml><block type="hobbit_move"><field name="gripper_position">open</field>'
            '<next><block type="hobbit_arm_gripper"><field name="gripper_position">close</field></block></next>'
            '</block></xml>')
    root = parse_blockly_xml(text)
    assert rename_legacy_fields(root, GRIPPER_ALIAS) == 1
    move_field = root.find("block/field")
    gripper_field = root.find("block/next/block/field")
    assert (move_field.get("name"), move_field.text) == ("gripper_position", "open")
    assert (gripper_field.get("name"), gripper_field.text) == ("movement", "CloseGripper")


# --- back to text for the editor ------------------------------------------------------------


def test_xml_for_the_editor_has_no_namespace_prefixes_blockly_would_not_recognise(first_rockly_xml):
    root = parse_blockly_xml(first_rockly_xml)
    rename_legacy_fields(root, GRIPPER_ALIAS)

    text = xml_to_text(root)

    assert "ns0:" not in text
    assert text.startswith("<xml")
    reparsed = ElementTree.fromstring(text)
    assert [element.tag.rsplit("}", 1)[-1] for element in reparsed][:2] == ["variables", "block"]
    assert block_types_in_xml(reparsed) == EXPECTED_XML_TYPES
    assert '<field name="movement">OpenGripper</field>' in text
    assert gripper_fields(root) == gripper_fields(reparsed)


def test_xml_for_the_editor_keeps_the_blockly_namespace_when_it_had_one():
    root = parse_blockly_xml(f'<xml xmlns="{BLOCKLY_NS}"><block type="hobbit_stop"/></xml>')
    text = xml_to_text(root)
    assert text.startswith(f'<xml xmlns="{BLOCKLY_NS}">')
    assert ElementTree.fromstring(text).tag == f"{{{BLOCKLY_NS}}}xml"
    assert root.tag == f"{{{BLOCKLY_NS}}}xml", "serialising does not change the parsed tree"


def test_xml_text_with_quotes_and_unicode_survives():
    root = parse_blockly_xml('<xml><block type="text">'
                             '<field name="TEXT">Grüße "du" &amp; &lt;ich&gt; 😀</field></block></xml>')
    reparsed = ElementTree.fromstring(xml_to_text(root))
    assert reparsed.find("block/field").text == 'Grüße "du" & <ich> 😀'
