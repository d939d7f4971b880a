"""A program the page has just built is serialized once: for the `changed` report, which the
field check reuses (the start-up program's first frame waits for every serialization)."""
import pytest
from page_tools import call_page, run_js
from program_builder import block, number, stack, workspace

# Counts the page's serializations and Python generations made after Blockly has built a program.
COUNT_AFTER_BUILDING = """(() => {
    const counts = window.rocklyTestCounts = {workspaces: 0, blocks: 0, python: 0};
    const count = (owner, name, key) => {
        const original = owner[name];
        owner[name] = function (...args) { counts[key] += 1; return original.apply(this, args); };
    };
    const resetAfter = (owner, name) => {
        const original = owner[name];
        owner[name] = function (...args) {
            const result = original.apply(this, args);
            counts.workspaces = counts.blocks = counts.python = 0;
            return result;
        };
    };
    count(Blockly.serialization.workspaces, 'save', 'workspaces');
    count(Blockly.serialization.blocks, 'save', 'blocks');
    count(python.pythonGenerator, 'workspaceToCode', 'python');
    resetAfter(Blockly.serialization.workspaces, 'load');
    resetAfter(Blockly.Xml, 'domToWorkspace');
    return true;
})()"""

MOVE = {"type": "hobbit_move", "fields": {"direction": "+"}, "inputs": {"speed": {"shadow": number(2)}}}
PROGRAM = workspace(stack(block("hobbit_emo", {"emotion": "FURIOUS"}), MOVE, block("hobbit_sos")))
XML = ('<xml xmlns="https://developers.google.com/blockly/xml">'
       '<block type="hobbit_sos" x="10" y="10"><next><block type="hobbit_emo"><field name="emotion">FURIOUS</field>'
       '</block></next></block><block type="hobbit_stop" x="10" y="200"></block></xml>')


@pytest.mark.parametrize(("call", "args"), [("load", {"workspace": PROGRAM}), ("importXml", {"xml": XML})],
                         ids=["json", "xml"])
def test_a_loaded_program_is_serialized_and_generated_once(qtbot, editor, call, args):
    run_js(qtbot, editor, COUNT_AFTER_BUILDING)
    with qtbot.waitSignal(editor.sig_changed, timeout=15000):
        result = call_page(qtbot, editor, call, args)
    assert [(entry["field"], entry["requested"]) for entry in result["replacedFields"]] == [("emotion", "FURIOUS")]
    assert run_js(qtbot, editor, "window.rocklyTestCounts") == {"workspaces": 1, "blocks": 0, "python": 1}
