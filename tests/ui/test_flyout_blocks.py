"""Blocks in the toolbox's flyouts: every flyout draws its blocks at the workspace's scale, on stage too."""
import pytest
from page_tools import call_page, run_js
from program_builder import block, stack, workspace


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
  return {scale: ws.scale, text: Math.min(...heights(ws)), flyouts: sizes}; })()"""


@pytest.mark.parametrize("stage", [False, True], ids=["normal", "stage"])
@pytest.mark.parametrize("profile", ["hobbit", "turtlebot"])
def test_every_flyout_draws_its_blocks_at_the_workspaces_scale(qtbot, driver, profile, stage):
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
