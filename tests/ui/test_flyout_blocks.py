"""Blocks from the toolbox's flyouts, with real input: a block dragged out with the mouse lands where it is
dropped (on stage too, where the program makes way for the flyout), and every flyout draws its blocks at the
workspace's scale."""
import pytest
from page_tools import call_page, run_js
from program_builder import block, stack, workspace
from PySide6.QtCore import QPoint, Qt
from PySide6.QtTest import QTest
from screenshots import screenshot

CATEGORY_AT = """(() => { const toolbox = Blockly.getMainWorkspace().getToolbox();
  const item = toolbox.getToolboxItems().find((i) => i.getName && i.getName() === %r);
  const r = item.getDiv().getBoundingClientRect(); return [r.left + r.width / 2, r.top + r.height / 2]; })()"""
FIRST_FLYOUT_BLOCK = """(() => { const flyout = Blockly.getMainWorkspace().getFlyout();
  if (!flyout.isVisible()) return null;
  const b = flyout.getWorkspace().getTopBlocks(true)[0]; const r = b.getSvgRoot().getBoundingClientRect();
  return {type: b.type, at: [r.left, r.top]}; })()"""
LAST_OF_PROGRAM = """(() => { let b = Blockly.getMainWorkspace().getBlockById(%r);
  while (b.getNextBlock()) b = b.getNextBlock();
  const r = b.getSvgRoot().getBoundingClientRect(); return {id: b.id, left: r.left, bottom: r.bottom}; })()"""
DRAGGED = """(() => { const b = Blockly.getMainWorkspace().getAllBlocks(false).find((b) => b.isDragging());
  if (!b) return null; const r = b.getSvgRoot().getBoundingClientRect(); return [r.left, r.top]; })()"""
FLYOUT_OPEN = "Blockly.getMainWorkspace().getFlyout().isVisible()"
TWO_FRAMES = ("(window.rocklyFrames = 0, requestAnimationFrame(() => requestAnimationFrame("
              "() => { window.rocklyFrames = 2; })), true)")
GRAB = 12  # px right of and below the flyout block's corner, where the mouse takes it
FOLLOWED = 1.5  # px: a dragged block this near to where the mouse holds it has followed the mouse


def frames_passed(qtbot, view):
    """Wait until the page has drawn two frames from now: what it asked to do on the next frame is done."""
    run_js(qtbot, view, TWO_FRAMES)
    qtbot.waitUntil(lambda: run_js(qtbot, view, "window.rocklyFrames") == 2, timeout=5000)


def click_category(qtbot, window, name: str):
    x, y = run_js(qtbot, window.editor, CATEGORY_AT % name)
    QTest.mouseClick(window.editor.focusProxy(), Qt.MouseButton.LeftButton, pos=QPoint(int(x), int(y)))
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, FLYOUT_OPEN), timeout=5000)
    frames_passed(qtbot, window.editor)


def editor_with_program(qtbot, driver, stage: bool):
    window = driver.open_window()
    window.resize(1280, 800)
    qtbot.waitUntil(lambda: window.width() == 1280, timeout=3000)
    if stage:
        window.stage.set_active(True)
        qtbot.waitUntil(lambda: run_js(qtbot, window.editor, "RocklyStage.active()"), timeout=5000)
    call_page(qtbot, window.editor, "load", {"workspace": workspace(stack(block("hobbit_emo", x=0, y=0),
                                                                         block("hobbit_emo"))), "breakpoints": []})
    return window


def mouse_to(page, start, end, steps=8):
    for step in range(1, steps + 1):
        QTest.mouseMove(page, QPoint(round(start[0] + (end[0] - start[0]) * step / steps),
                                     round(start[1] + (end[1] - start[1]) * step / steps)))


def block_follows(qtbot, view, mouse):
    """Wait until the block being dragged has its corner GRAB px above and left of ``mouse``: the page took the move."""
    def followed():
        dragged = run_js(qtbot, view, DRAGGED)
        return dragged is not None and all(abs(dragged[i] + GRAB - mouse[i]) <= FOLLOWED for i in (0, 1))
    qtbot.waitUntil(followed, timeout=5000)


def drag_to(qtbot, view, page, start, aim, steps=8):
    """Move the mouse from ``start`` towards where ``aim()`` says, as a hand does: a step at a time, each one
    followed by the dragged block before the next; where the target moved meanwhile, on to where it is now.
    Returns where the mouse ends."""
    mouse = start
    for _attempt in range(3):
        target = aim()
        if target == mouse:
            return mouse
        for step in range(1, steps + 1):
            mouse = (round(start[0] + (target[0] - start[0]) * step / steps),
                     round(start[1] + (target[1] - start[1]) * step / steps))
            QTest.mouseMove(page, QPoint(*mouse))
            block_follows(qtbot, view, mouse)
        start = mouse
        frames_passed(qtbot, view)
    assert aim() == mouse, "the program kept moving while the block was dragged to it"
    return mouse


@pytest.mark.parametrize("stage", [False, True], ids=["normal", "stage"])
def test_a_block_dragged_from_the_flyout_lands_where_it_is_dropped_and_snaps_on(qtbot, driver, stage):
    window = editor_with_program(qtbot, driver, stage)
    page, view = window.editor.focusProxy(), window.editor
    first = run_js(qtbot, view, "Blockly.getMainWorkspace().getTopBlocks(true)[0].id")
    click_category(qtbot, window, "Drive")
    taken = run_js(qtbot, view, FIRST_FLYOUT_BLOCK)
    press = (round(taken["at"][0] + GRAB), round(taken["at"][1] + GRAB))
    QTest.mousePress(page, Qt.MouseButton.LeftButton, pos=QPoint(*press))
    mouse_to(page, press, (press[0] + 40, press[1] + 40))                 # the drag starts: the flyout closes
    qtbot.waitUntil(lambda: run_js(qtbot, view, DRAGGED) is not None and not run_js(qtbot, view, FLYOUT_OPEN),
                    timeout=5000)
    block_follows(qtbot, view, (press[0] + 40, press[1] + 40))
    frames_passed(qtbot, view)
    screenshot(window.editor, f"drop-{'stage' if stage else 'normal'}-dragging")

    def below_the_program():  # where the person sees the program's last block now, and just below it
        last = run_js(qtbot, view, LAST_OF_PROGRAM % first)
        return round(last["left"] + GRAB), round(last["bottom"] + GRAB)
    target = drag_to(qtbot, view, page, (press[0] + 40, press[1] + 40), below_the_program)
    last_id = run_js(qtbot, view, LAST_OF_PROGRAM % first)["id"]
    QTest.mouseRelease(page, Qt.MouseButton.LeftButton, pos=QPoint(*target))
    qtbot.waitUntil(lambda: run_js(qtbot, view, DRAGGED) is None, timeout=5000)   # Blockly's drag has ended
    after = run_js(qtbot, view, f"(() => {{ const next = Blockly.getMainWorkspace().getBlockById({last_id!r})"
                                ".getNextBlock(); return next && next.type; })()")
    assert after == taken["type"]
    frames_passed(qtbot, view)
    screenshot(window.editor, f"drop-{'stage' if stage else 'normal'}-dropped")


# Every category's flyout in turn: its scale and its smallest text, beside the workspace's.
FLYOUT_SIZES = """(() => { const ws = Blockly.getMainWorkspace(); const toolbox = ws.getToolbox();
  const heights = (on) => [...on.getCanvas().querySelectorAll('.blocklyText')]
      .map((text) => text.getBoundingClientRect().height).filter((height) => height > 0);
  const sizes = [];
  for (const item of toolbox.getToolboxItems().filter((i) => i.getName)) {
    toolbox.setSelectedItem(item);
    sizes.push({category: item.getName(), scale: ws.getFlyout().getWorkspace().scale,
                text: Math.min(...heights(ws.getFlyout().getWorkspace()))});
  }
  toolbox.clearSelection();
  const desk = (RocklyStage.active() && RocklyStage.deskScale()) || ws.scale;  // on stage the program is drawn larger
  return {scale: desk, text: Math.min(...heights(ws)) * desk / ws.scale, flyouts: sizes}; })()"""


@pytest.mark.parametrize("stage", [False, True], ids=["normal", "stage"])
@pytest.mark.parametrize("profile", ["hobbit", "turtlebot"])
def test_every_flyout_draws_its_blocks_at_the_desks_scale(qtbot, driver, profile, stage):
    window = editor_with_program(qtbot, driver, stage)
    if profile != window.profile.id:
        window.document.modified = False
        window.choose_profile(profile)
        qtbot.waitUntil(lambda: window.profile.id == profile and window.editor.is_ready, timeout=15000)
    call_page(qtbot, window.editor, "load", {"workspace": workspace(block("text_print", x=0, y=0)), "breakpoints": []})
    sizes = run_js(qtbot, window.editor, FLYOUT_SIZES)
    assert len(sizes["flyouts"]) >= 8, sizes
    small = [flyout for flyout in sizes["flyouts"]
             if flyout["scale"] != sizes["scale"] or flyout["text"] < sizes["text"] - 0.5]
    assert small == [], sizes


PROGRAM_AND_FLYOUT = """(() => { const ws = Blockly.getMainWorkspace();
  const r = ws.getBlockById(%r).getSvgRoot().getBoundingClientRect();
  return {program: r.left, flyout: ws.getMetricsManager().getAbsoluteMetrics().left + ws.getFlyout().getWidth()};
  })()"""


def test_on_stage_the_program_follows_a_narrower_flyout_back_to_its_edge(qtbot, driver):
    window = editor_with_program(qtbot, driver, stage=True)
    first = run_js(qtbot, window.editor, "Blockly.getMainWorkspace().getTopBlocks(true)[0].id")
    click_category(qtbot, window, "Drive")
    wide = run_js(qtbot, window.editor, PROGRAM_AND_FLYOUT % first)
    click_category(qtbot, window, "Head")
    narrow = run_js(qtbot, window.editor, PROGRAM_AND_FLYOUT % first)
    assert narrow["flyout"] < wide["flyout"] - 100, (wide, narrow)
    assert 0 <= narrow["program"] - narrow["flyout"] <= 40, (wide, narrow)   # beside Head's flyout, not Drive's
