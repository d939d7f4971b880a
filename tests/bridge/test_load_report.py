"""The page says which field values of a program it could not keep, and refuses blocks without a type."""
import pytest
from page_tools import call_page
from program_builder import block, number, stack, text, workspace

# Texts that must come back exactly as written (no false report).
TRICKY_TEXTS = ["say \"hi\"\nit's \\ '''", "line\u2028separator\r\nand\ttab", "🤖 Grüße", "", "   ", "0x10", "1e5"]


def load(qtbot, editor, program, breakpoints=()):
    return call_page(qtbot, editor, "load", {"workspace": program, "breakpoints": list(breakpoints)})


def test_a_dropdown_value_the_block_does_not_offer_is_reported_with_what_it_became(qtbot, editor):
    result = load(qtbot, editor, workspace(stack(block("hobbit_emo", {"emotion": "FURIOUS"}), block("hobbit_sos"))))
    assert result["loaded"] is True
    [entry] = result["replacedFields"]
    assert entry["number"] == 1 and entry["type"] == "hobbit_emo" and entry["field"] == "emotion"
    assert entry["requested"] == "FURIOUS" and entry["now"] == "HAPPY"
    assert call_page(qtbot, editor, "getState")["workspace"]["blocks"]["blocks"][0]["fields"] == {"emotion": "HAPPY"}


def test_replaced_values_are_found_everywhere_and_numbered_in_file_order(qtbot, editor):
    # 1 controls_if, 2 hobbit_yes_no (in IF0), 3 its text, 4 hobbit_head (in DO0),
    # 5 hobbit_move (next), 6 its math_number shadow, 7 hobbit_stop (next)
    condition = block("hobbit_yes_no", {"yes_no": "D_MAYBE"}, {"text": text("Dance?")})
    program = workspace(stack(
        block("controls_if", inputs={"IF0": condition, "DO0": block("hobbit_head", {"head_position": "sideways"})}),
        {"type": "hobbit_move", "fields": {"direction": "+"}, "inputs": {"speed": {"shadow": number("fast")}}},
        block("hobbit_stop", {"brakes": "hard"}),
    ))
    result = load(qtbot, editor, program)
    found = [(entry["number"], entry["type"], entry["field"], entry["requested"],
              entry.get("now"), entry.get("missing"))
             for entry in result["replacedFields"]]
    assert found == [
        (2, "hobbit_yes_no", "yes_no", "D_MAYBE", "D_YES", None),
        (4, "hobbit_head", "head_position", "sideways", "center_center", None),
        (6, "math_number", "NUM", "fast", 0, None),
        (7, "hobbit_stop", "brakes", "hard", None, True),
    ]


def test_values_blockly_keeps_are_not_reported(qtbot, editor):
    texts = [block("hobbit_show_info", inputs={"text": text(value)}) for value in TRICKY_TEXTS]
    typed = block("ros_publish_message", {"message_type": "lab_msgs/Beep"},
                  {"topic": text("/beep"), "field:pitch": number(440)},
                  extraState={"type": "lab_msgs/Beep", "fields": [["pitch", "Number"]]})
    goal = block("ros_send_goal", {"action_type": "hobbit_msgs/ArmServerAction", "feedback": {"id": "fb"}},
                 {"action": text("hobbit_arm"), "field:command.data": text("MoveToCandle"),
                  "while_waiting": block("text_print", inputs={"TEXT": text("moving")})})
    program = {"variables": [{"name": "n", "id": "v1"}, {"name": "feedback", "id": "fb"}],
               "blocks": {"languageVersion": 0, "blocks": [stack(
        *texts, typed, block("text_print", inputs={"TEXT": goal}),
        block("variables_set", {"VAR": {"id": "v1"}}, {"VALUE": number("2.50")}),
        block("hobbit_move", {"direction": "-"}, {"speed": number(1e300)}),
        block("controls_if", inputs={"IF0": block("logic_boolean", {"BOOL": "FALSE"})}),
        block("hobbit_emo", {"emotion": "VHAPPY"}),
    )]}}
    result = load(qtbot, editor, program)
    assert result == {"loaded": True}


def test_a_bad_value_in_a_shadow_covered_by_a_block_is_reported_too(qtbot, editor):
    # Blockly keeps the hidden shadow's state (it comes back when the block is dragged out), with 0 for "fast".
    covered = {"type": "hobbit_move", "fields": {"direction": "+"},
               "inputs": {"speed": {"shadow": number("fast"), "block": number(3)}}}
    result = load(qtbot, editor, workspace(covered))
    replaced = [(entry["number"], entry["requested"], entry["now"]) for entry in result["replacedFields"]]
    assert replaced == [(2, "fast", 0)]
    saved = call_page(qtbot, editor, "getState")["workspace"]["blocks"]["blocks"][0]["inputs"]["speed"]
    assert saved["shadow"]["fields"]["NUM"] == 0 and saved["block"]["fields"]["NUM"] == 3


def test_xml_import_reports_replaced_values_too(qtbot, editor):
    xml = ('<xml xmlns="https://developers.google.com/blockly/xml">'
           '<block type="hobbit_sos" x="10" y="10"><next><block type="hobbit_emo"><field name="emotion">FURIOUS</field>'
           '</block></next></block>'
           '<block type="hobbit_move" x="10" y="200"><field name="direction">+</field><value name="speed">'
           '<shadow type="math_number"><field name="NUM">2</field></shadow></value></block></xml>')
    result = call_page(qtbot, editor, "importXml", {"xml": xml})
    assert result["loaded"] is True
    replaced = [(entry["number"], entry["field"], entry["requested"], entry["now"])
                for entry in result["replacedFields"]]
    assert replaced == [(2, "emotion", "FURIOUS", "HAPPY")]


@pytest.mark.parametrize("untyped", [{}, {"type": ""}, {"type": 7}])
def test_a_block_without_a_type_is_refused_by_number_before_the_workspace_changes(qtbot, editor, untyped):
    load(qtbot, editor, workspace(block("hobbit_stop")))
    broken = workspace(stack(block("hobbit_sos"), {**untyped, "next": {"block": block("hobbit_stop")}}))
    assert load(qtbot, editor, broken) == {"untypedBlock": 2}
    xml = '<xml><block type="hobbit_sos"><next><block><field name="x">1</field></block></next></block></xml>'
    assert call_page(qtbot, editor, "importXml", {"xml": xml}) == {"untypedBlock": 2}
    assert call_page(qtbot, editor, "getState")["python"] == "robot.stop()\n"
