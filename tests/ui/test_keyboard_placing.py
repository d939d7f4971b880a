"""Placing blocks with Blockly's keys in the real window (keys go to the focused widget, as a keyboard's do):
a block taken from the flyout goes below the selected block, and on stage the block being placed or moved stays
in sight, and so does the program."""
import pytest
from page_tools import call_page, run_js
from program_builder import block, stack, workspace
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QApplication
from screenshots import screenshot
from test_flyout_blocks import frames_passed
from test_keyboard import K, active, focused_block, focused_category, press

FOCUSED_ID = "(() => { const n = Blockly.getFocusManager().getFocusedNode(); return n && n.id; })()"
PROGRAM = """Blockly.getMainWorkspace().getTopBlocks(true).map((top) => {
  const ids = []; for (let b = top; b; b = b.getNextBlock()) ids.push(b.type === 'hobbit_emo' ? b.id : b.type);
  return ids; })"""


def window_with_program(qtbot, driver, *ids, stage=False, select=True):
    """A window at 1280x800 (on stage if asked) with a stack of ``ids``, the keyboard in it, on its first block
    if ``select``."""
    window = driver.open_window()
    window.resize(1280, 800)
    qtbot.waitUntil(lambda: active(window) and window.width() == 1280, timeout=5000)
    if stage:
        window.stage.set_active(True)
        qtbot.waitUntil(lambda: run_js(qtbot, window.editor, "RocklyStage.active()"), timeout=5000)
    blocks = [block("hobbit_emo", id=block_id) for block_id in ids]
    blocks[0].update(x=0, y=0)
    call_page(qtbot, window.editor, "load", {"workspace": workspace(stack(*blocks)), "breakpoints": []})
    press(qtbot, window, K.Key_2, Qt.KeyboardModifier.ControlModifier)   # the keyboard into the program's blocks
    qtbot.waitUntil(lambda: window.editor.focusProxy() is QApplication.focusWidget(), timeout=5000)
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, "Blockly.getFocusManager().getFocusedTree()"
                                                         " === Blockly.getMainWorkspace()"), timeout=5000)
    if not select:
        return window
    press(qtbot, window, K.Key_Down)                                       # from the workspace to its first block
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, FOCUSED_ID) == ids[0], timeout=5000)
    return window


def take_first_drive_block(qtbot, window):
    """T into the toolbox, right into Drive's blocks, Enter takes the first one."""
    press(qtbot, window, K.Key_T)
    qtbot.waitUntil(lambda: focused_category(qtbot, window) is not None, timeout=5000)
    press(qtbot, window, K.Key_Right)
    qtbot.waitUntil(lambda: focused_block(qtbot, window) == "hobbit_move", timeout=5000)
    press(qtbot, window, K.Key_Enter)
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, "Blockly.getMainWorkspace().isDragging()"), timeout=5000)


@pytest.mark.parametrize("downs", [0, 1, 2], ids=["first", "second", "third"])
def test_a_block_taken_from_the_flyout_goes_below_the_selected_block(qtbot, driver, downs):
    program = ["first", "second", "third"]
    window = window_with_program(qtbot, driver, *program)
    for _ in range(downs):
        press(qtbot, window, K.Key_Down)
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, FOCUSED_ID) == program[downs], timeout=5000)
    take_first_drive_block(qtbot, window)
    press(qtbot, window, K.Key_Enter)                                       # put it down where it is offered
    qtbot.waitUntil(lambda: not run_js(qtbot, window.editor, "Blockly.getMainWorkspace().isDragging()"),
                    timeout=5000)
    program.insert(downs + 1, "hobbit_move")
    assert run_js(qtbot, window.editor, PROGRAM) == [program]


IN_SIGHT = """(() => { const ws = Blockly.getMainWorkspace();
  const box = (block) => { const r = block.getSvgRoot().getBoundingClientRect();
    return [r.left, r.top, r.right, r.bottom]; };
  const moving = ws.getAllBlocks(false).find((block) => block.isDragging());
  return {view: [ws.getMetricsManager().getAbsoluteMetrics().left, 0, innerWidth, innerHeight],
          moving: moving && box(moving), program: box(ws.getBlockById('first'))}; })()"""


def inside(box, view) -> bool:
    return view[0] <= box[0] and view[1] <= box[1] and box[2] <= view[2] and box[3] <= view[3]


@pytest.mark.parametrize("selected", [False, True], ids=["nothing selected", "a block selected"])
def test_on_stage_a_block_taken_and_moved_with_the_keys_stays_in_sight_and_so_does_the_program(
        qtbot, driver, selected):
    window = window_with_program(qtbot, driver, "first", "second", stage=True, select=selected)
    take_first_drive_block(qtbot, window)
    for step in range(4):
        frames_passed(qtbot, window.editor)
        shown = run_js(qtbot, window.editor, IN_SIGHT)
        assert inside(shown["moving"], shown["view"]) and shown["program"][0] >= shown["view"][0], (step, shown)
        screenshot(window.editor, f"keys-stage-{'selected' if selected else 'nothing'}-{step}")
        press(qtbot, window, K.Key_Left)
    press(qtbot, window, K.Key_Escape)


def overlap(a, b) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


@pytest.mark.parametrize("stage", [False, True], ids=["normal", "stage"])
def test_a_block_taken_with_nothing_selected_starts_in_sight_below_the_program_not_over_it(qtbot, driver, stage):
    window = window_with_program(qtbot, driver, "first", "second", stage=stage, select=False)
    take_first_drive_block(qtbot, window)
    frames_passed(qtbot, window.editor)
    shown = run_js(qtbot, window.editor, IN_SIGHT)
    assert inside(shown["moving"], shown["view"]) and not overlap(shown["moving"], shown["program"]), shown
    assert shown["moving"][1] >= shown["program"][3], shown
    screenshot(window.editor, f"keys-nothing-selected-{'stage' if stage else 'normal'}")
    press(qtbot, window, K.Key_Escape)
