"""Loose blocks: a value block lying alone on the canvas is not run, exported or shown as active;
loose statement stacks are all run, as in the first Rockly."""
from page_tools import call_page, print_value, run_js
from program_builder import block, number, stack, workspace

from rockly_desktop.profiles.opening import ProgramToOpen

DIVIDE_BY_ZERO = block("math_arithmetic", {"OP": "DIVIDE"}, {"A": number(1), "B": number(0)}, id="loose")
# Enabled, disabled as a loose block (Blockly's reason for orphans), drawn as disabled.
STATUS = """(() => {{ const b = Blockly.getMainWorkspace().getBlockById({id!r});
    return [b.isEnabled(), b.hasDisabledReason('ORPHANED_BLOCK'),
            b.getSvgRoot().classList.contains('blocklyDisabled')]; }})()"""


def test_a_loose_value_block_is_neither_exported_nor_run(headless_editor, hobbit):
    program = workspace(block("hobbit_sos", x=20, y=20), {**DIVIDE_BY_ZERO, "x": 400, "y": 20})

    exported = headless_editor.python_for(ProgramToOpen(path=None, profile=hobbit, workspace=program))
    run = headless_editor.call_and_wait("getRunCode")["code"]

    assert exported.strip() == "robot.call_sos()"
    assert "1 / 0" not in run and "robot.call_sos()" in run


def test_every_loose_statement_stack_is_generated_in_order(headless_editor, hobbit):
    program = workspace(stack(block("hobbit_sos", x=20, y=20), block("hobbit_stop")),
                       block("hobbit_wait", inputs={"seconds": number(2)}, x=20, y=400))

    code = headless_editor.python_for(ProgramToOpen(path=None, profile=hobbit, workspace=program))

    assert code.split() == ["robot.call_sos()", "robot.stop()", "robot.wait(2)"]


def test_a_loose_value_looks_disabled_and_comes_alive_when_snapped_in(qtbot, editor):
    call_page(qtbot, editor, "load", {"workspace": workspace(block("hobbit_sos"), DIVIDE_BY_ZERO)})
    assert run_js(qtbot, editor, STATUS.format(id="loose")) == [False, True, True]

    print_value(qtbot, editor, "loose")

    qtbot.waitUntil(lambda: run_js(qtbot, editor, STATUS.format(id="loose")) == [True, False, False], timeout=5000)
    state = call_page(qtbot, editor, "getState")
    assert "print(1 / 0)" in state["python"]
    assert "disabledReasons" not in str(state["workspace"])


def test_a_value_taken_out_of_its_block_is_disabled(qtbot, editor):
    call_page(qtbot, editor, "load", {"workspace": workspace(
        block("text_print", inputs={"TEXT": DIVIDE_BY_ZERO}, id="print"))})
    assert run_js(qtbot, editor, STATUS.format(id="loose")) == [True, False, False]

    run_js(qtbot, editor, "Blockly.getMainWorkspace().getBlockById('loose').unplug()")

    qtbot.waitUntil(lambda: run_js(qtbot, editor, STATUS.format(id="loose")) == [False, True, True], timeout=5000)
    assert "1 / 0" not in call_page(qtbot, editor, "getState")["python"]
