"""Layout at common screen sizes: the first window fits the screen's available area with its frame,
the simulator's own panels stay on screen in the normal layout and on stage, and on stage the blocks
have room that the flyout and the zoom controls leave free."""
import json
import os
import subprocess
import sys

import pytest
from page_tools import run_js
from window_tools import one_screen_platform

from rockly_desktop.core.paths import examples_dir

SIZES = [(1280, 800), (1366, 768), (1920, 1080)]

FIRST_WINDOW = """
import json, sys
from PySide6.QtWidgets import QApplication
app = QApplication([])
from rockly_desktop.app import build_main_window
window = build_main_window(sys.argv[1])
window.show()
app.processEvents()
area, frame = window.screen().availableGeometry(), window.frameGeometry()
print(json.dumps({"area": area.getRect(), "frame": frame.getRect(), "status_bar": window.statusBar().isVisible()}))
window.document.modified = False
window.close()
"""


def inside(inner, outer) -> bool:
    """Whether the rect (x, y, w, h) ``inner`` lies inside ``outer``."""
    x, y, w, h = inner
    ox, oy, ow, oh = outer
    return ox <= x and oy <= y and x + w <= ox + ow and y + h <= oy + oh


@pytest.mark.parametrize("size", SIZES)
def test_the_first_window_with_its_frame_fits_the_screens_available_area(tmp_path, size):
    width, height = size
    script = tmp_path / "first_window.py"
    script.write_text(FIRST_WINDOW)
    env = dict(os.environ, QT_QPA_PLATFORM=one_screen_platform(tmp_path, *size), QTWEBENGINE_DISABLE_SANDBOX="1")
    done = subprocess.run([sys.executable, str(script), str(tmp_path / "settings.ini")], env=env, timeout=120,
                          capture_output=True, text=True, check=True)
    shown = json.loads(done.stdout.strip().splitlines()[-1])
    assert shown["area"] == [0, 0, width, height]
    assert inside(shown["frame"], shown["area"]), shown
    assert shown["frame"][2] >= min(width, 1280) - 40 and shown["frame"][3] >= min(height, 800) - 60, shown  # not tiny


def test_the_first_window_fits_the_test_screen_too(window):
    frame, area = window.frameGeometry(), window.screen().availableGeometry()
    assert area.contains(frame), (frame, area)


def laid_out(qtbot, window, width, height):
    window.resize(width, height)
    qtbot.waitUntil(lambda: (window.width(), window.height()) == (width, height), timeout=3000)


@pytest.mark.parametrize("stage", [False, True], ids=["normal", "stage"])
@pytest.mark.parametrize("size", SIZES, ids=["1280x800", "1366x768", "1920x1080"])
def test_the_simulators_arm_gripper_and_head_stay_on_screen(qtbot, window, size, stage):
    if stage:
        on_stage(qtbot, window, size)
    else:
        laid_out(qtbot, window, *size)
    view = window.simulator_dock.widget()

    def listed():
        return [label for label, _values in view.panel_texts()["details"]][:3]

    qtbot.waitUntil(lambda: view.isVisible() and listed() == ["Arm", "Gripper", "Head"], timeout=3000)


def on_stage(qtbot, window, size):
    """``window`` at ``size``, on stage with the given sizes applied and the page told."""
    laid_out(qtbot, window, *size)
    window.stage.set_active(True)
    qtbot.waitUntil(lambda: window.simulator_dock.width() > window.editor.width(), timeout=3000)
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, "document.body.classList.contains('rocklyStage')"),
                    timeout=5000)
    page_settled(qtbot, window)


PAGE_WIDTHS = """(() => { const metrics = Blockly.getMainWorkspace().getMetricsManager();
  return [innerWidth, metrics.getAbsoluteMetrics().left + metrics.getViewMetrics().width]; })()"""


def page_settled(qtbot, window):
    """Wait until the page has the editor's width and Blockly has seen it: the page's resize comes
    from Chromium a little after Qt's, and Blockly takes it from the page's resize event later still."""
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, PAGE_WIDTHS) == [window.editor.width()] * 2, timeout=5000)


STAGE_BOXES = """(() => {
  const ws = Blockly.getMainWorkspace();
  const box = (element) => { const r = element.getBoundingClientRect();
    return r.width && r.height ? [r.left, r.top, r.right, r.bottom] : null; };
  const shown = (element) => element && getComputedStyle(element).display !== 'none' ? box(element) : null;
  const onScreen = (b) => b && b[2] > 0 && b[0] < innerWidth && b[3] > 0 && b[1] < innerHeight;
  const flyout = ws.getFlyout();
  const left = ws.getMetricsManager().getAbsoluteMetrics().left;
  return {
    page: [innerWidth, innerHeight], toolbox: left,
    flyout: flyout.isVisible() ? [left, 0, left + flyout.getWidth(), innerHeight] : null,
    controls: [...document.querySelectorAll('.blocklyZoom, .blocklyTrash')].map(shown).filter(Boolean),
    blocks: ws.getTopBlocks(false).map((b) => box(b.getSvgRoot())).filter(onScreen),
  };
})()"""

OPEN_FIRST_CATEGORY = """(() => { const toolbox = Blockly.getMainWorkspace().getToolbox();
  toolbox.setSelectedItem(toolbox.getToolboxItems().find((item) => item.getName)); return true; })()"""


def overlap(a, b) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


@pytest.mark.parametrize("size", SIZES, ids=["1280x800", "1366x768", "1920x1080"])
def test_on_stage_the_blocks_have_room_and_nothing_covers_them(qtbot, driver, size):
    window = driver.open_window(str(examples_dir() / "hobbit" / "tidy-up.rockly"))
    on_stage(qtbot, window, size)
    boxes = run_js(qtbot, window.editor, STAGE_BOXES)
    assert boxes["page"][0] - boxes["toolbox"] >= 480, boxes        # the blocks' own area, right of the toolbox
    assert boxes["blocks"] and boxes["controls"] == [], boxes         # no zoom buttons or trashcan over them
    run_js(qtbot, window.editor, OPEN_FIRST_CATEGORY)

    def clear_of_the_flyout():
        shown = run_js(qtbot, window.editor, STAGE_BOXES)
        return bool(shown["flyout"] and shown["blocks"]) and not any(
            overlap(block, shown["flyout"]) for block in shown["blocks"])

    qtbot.waitUntil(clear_of_the_flyout, timeout=3000)   # (its blocks at the workspace's scale: test_flyout_blocks)
    run_js(qtbot, window.editor, "Blockly.getMainWorkspace().getToolbox().clearSelection(), true")
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, STAGE_BOXES)["blocks"] and min(
        block[0] for block in run_js(qtbot, window.editor, STAGE_BOXES)["blocks"]) < boxes["toolbox"] + 60,
        timeout=3000)                                                     # and back where it was once it closes
