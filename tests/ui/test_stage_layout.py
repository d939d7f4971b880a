"""The stage layout (View → Stage, F11) and bottom tabs that keep their size."""
import pytest
from page_tools import START_IN_VIEW, run_js
from PySide6.QtCore import Qt
from PySide6.QtTest import QTest
from window_tools import WindowDriver

from rockly_desktop.app import build_main_window
from rockly_desktop.core.paths import examples_dir


def simulator_area(window) -> int:
    view = window.simulator_dock.widget()
    return view.width() * view.height() if view is not None and view.isVisible() else 0


def staged(window, width, height) -> bool:
    """The simulator has its stage size: most of the width, the blocks keeping theirs (at least 45 % of the area)."""
    return simulator_area(window) >= width * height * 0.45 and window.simulator_dock.width() > window.editor.width()


def laid_out(qtbot, window, width, height):
    window.resize(width, height)
    qtbot.waitUntil(lambda: (window.width(), window.height()) == (width, height), timeout=3000)


@pytest.mark.parametrize("size", [(1280, 800), (1920, 1080)])
def test_on_stage_the_simulator_is_large_and_the_blocks_keep_their_room(qtbot, window, size):
    width, height = size
    laid_out(qtbot, window, width, height)
    assert simulator_area(window) < width * height // 2            # the usual layout: a small simulator
    stage = window.stage.action
    assert stage.isCheckable() and stage.shortcut().toString() == "F11"
    assert stage in window.menuBar().actions()[3].menu().actions()    # View → Stage
    stage.trigger()
    qtbot.waitUntil(lambda: staged(window, width, height), timeout=3000)
    assert window.editor.width() >= 590                               # the blocks keep room for the flyout
    assert not window.code_dock.isVisible() and not window.variables.isVisible()
    assert window.console.isVisible() and window.console.height() < height // 6     # a strip under the blocks
    assert window.editor.width() >= width // 3                        # the blocks beside it
    assert window.simulator_dock.x() > window.editor.x()


def test_leaving_the_stage_puts_back_the_layout_from_before(qtbot, window):
    laid_out(qtbot, window, 1280, 800)
    window.variables.raise_()
    qtbot.waitUntil(lambda: window.variables.isVisible(), timeout=3000)
    before = (window.simulator_dock.width(), window.simulator_dock.height())
    window.stage.set_active(True)
    qtbot.waitUntil(lambda: staged(window, 1280, 800), timeout=3000)
    window.stage.set_active(False)
    qtbot.waitUntil(lambda: window.variables.isVisible(), timeout=3000)
    assert not window.stage.action.isChecked() and not window.stage.active
    qtbot.waitUntil(lambda: (window.simulator_dock.width(), window.simulator_dock.height()) == before, timeout=3000)


def test_the_stage_is_remembered_across_windows(qtbot, driver):
    first = driver.open_window()
    laid_out(qtbot, first, 1280, 800)
    first.code_dock.raise_()
    first.stage.action.trigger()
    qtbot.waitUntil(lambda: staged(first, 1280, 800), timeout=3000)
    first.close()

    again = WindowDriver(qtbot, driver.settings_path)
    try:
        window = again.open_window()
        assert window.stage.active and window.stage.action.isChecked()
        laid_out(qtbot, window, 1280, 800)      # (the offscreen screen is smaller: restoring fits the window into it)
        qtbot.waitUntil(lambda: staged(window, 1280, 800), timeout=3000)
        assert not window.code_dock.isVisible()
        window.stage.action.trigger()                                      # off: the layout from before the stage
        qtbot.waitUntil(lambda: window.code_dock.isVisible(), timeout=3000)
        assert simulator_area(window) < 1280 * 800 // 2
        window.close()
        third = again.open_window()
        assert not third.stage.active and third.code_dock.isVisible()
    finally:
        again.close_all()


def near(height: int, wanted: int) -> bool:
    return abs(height - wanted) <= 3


def test_switching_bottom_tabs_keeps_the_simulator_and_each_tab_its_size(qtbot, window):
    laid_out(qtbot, window, 1600, 1000)
    qtbot.waitUntil(lambda: window.console.height() < 1000 // 4, timeout=3000)   # the console is a strip
    simulator, strip = window.simulator_dock.size(), window.console.height()
    window.plot_dock.raise_()
    qtbot.waitUntil(lambda: window.plot_dock.height() >= 1000 // 4, timeout=3000)   # the plot gets room
    assert window.simulator_dock.size() == simulator                      # beside the bottom tabs, untouched
    window.monitor_dock.raise_()
    qtbot.waitUntil(lambda: window.monitor_dock.height() >= 1000 // 4, timeout=3000)
    window.console.raise_()
    qtbot.waitUntil(lambda: near(window.console.height(), strip), timeout=3000)   # its own strip again
    assert window.simulator_dock.size() == simulator


def test_a_quick_round_of_bottom_tabs_brings_the_console_strip_back(qtbot, window):
    laid_out(qtbot, window, 1600, 1000)
    qtbot.waitUntil(lambda: window.console.height() < 1000 // 4, timeout=3000)
    simulator, strip = window.simulator_dock.size(), window.console.height()
    for dock in (window.plot_dock, window.monitor_dock, window.console):    # raised before any is laid out
        dock.raise_()
    qtbot.waitUntil(lambda: near(window.console.height(), strip), timeout=3000)
    assert window.simulator_dock.size() == simulator


def test_a_bottom_tab_the_person_resized_gets_that_height_back(qtbot, window):
    laid_out(qtbot, window, 1600, 1000)
    qtbot.waitUntil(lambda: window.console.height() < 1000 // 4, timeout=3000)
    strip = window.console.height()
    window.resizeDocks([window.console], [260], Qt.Orientation.Vertical)   # the person drags it taller
    qtbot.waitUntil(lambda: window.console.height() > strip + 30, timeout=3000)
    taller = window.console.height()
    window.plot_dock.raise_()
    qtbot.waitUntil(lambda: window.plot_dock.height() >= 1000 // 4, timeout=3000)
    window.console.raise_()
    qtbot.waitUntil(lambda: near(window.console.height(), taller), timeout=3000)


def test_the_width_the_person_gives_the_simulator_on_stage_is_remembered(qtbot, driver):
    first = driver.open_window()
    laid_out(qtbot, first, 1280, 800)
    first.stage.set_active(True)
    qtbot.waitUntil(lambda: staged(first, 1280, 800), timeout=3000)
    first.resizeDocks([first.simulator_dock], [900], Qt.Orientation.Horizontal)     # dragged wider
    qtbot.waitUntil(lambda: abs(first.simulator_dock.width() - 900) <= 2, timeout=3000)
    first.close()

    again = WindowDriver(qtbot, driver.settings_path)
    try:
        window = again.open_window()
        laid_out(qtbot, window, 1600, 1000)                                     # a bigger window: the same share
        qtbot.waitUntil(lambda: abs(window.simulator_dock.width() - 900 * 1600 / 1280) <= 4, timeout=3000)
    finally:
        again.close_all()


def _start_in_view(qtbot, window) -> bool:
    where = run_js(qtbot, window.editor, START_IN_VIEW)
    left, top, right, bottom = where["view"]
    block_left, block_top, _right, _bottom = where["block"]
    return left <= block_left < right and top <= block_top < bottom


def test_going_on_stage_right_after_start_keeps_the_programs_start_in_view(qtbot, driver):
    # The program opens as the window starts, before the page has its final size (as `rockly PROGRAM` does).
    window = build_main_window(driver.settings_path)
    driver.windows.append(window)
    window.resize(1280, 800)
    window.show()
    with qtbot.waitSignal(window.editor.sig_ready, timeout=30000):
        window.start(str(examples_dir() / "hobbit" / "drive-a-square.rockly"))
    window.stage.set_active(True)
    qtbot.waitUntil(lambda: staged(window, 1280, 800), timeout=3000)
    qtbot.waitUntil(lambda: _start_in_view(qtbot, window), timeout=3000)


def simulator_size(window):
    return window.simulator_dock.width(), window.simulator_dock.height()


def test_f11_maximises_a_window_that_is_not_and_leaving_gives_back_its_size_and_the_simulators(qtbot, window):
    window.showNormal()
    window.resize(760, 560)  # (smaller than the offscreen screen, so that maximising shows)
    qtbot.waitUntil(lambda: (window.width(), window.height()) == (760, 560), timeout=3000)
    simulator_before = simulator_size(window)
    QTest.keyClick(window, Qt.Key.Key_F11)
    qtbot.waitUntil(lambda: window.isMaximized() and window.stage.active, timeout=3000)
    qtbot.waitUntil(lambda: window.width() > 760 and not window.code_dock.isVisible(), timeout=3000)
    QTest.keyClick(window, Qt.Key.Key_F11)
    qtbot.waitUntil(lambda: not window.isMaximized() and (window.width(), window.height()) == (760, 560),
                    timeout=3000)
    qtbot.waitUntil(lambda: simulator_size(window) == simulator_before, timeout=3000)


def test_leaving_the_stage_on_a_maximised_window_keeps_it_maximised_and_gives_the_simulator_its_size(qtbot, window):
    window.showMaximized()
    qtbot.waitUntil(window.isMaximized, timeout=3000)
    qtbot.waitUntil(lambda: window.simulator_dock.width() > 0, timeout=3000)
    simulator_before = simulator_size(window)
    window.stage.set_active(True)
    qtbot.waitUntil(lambda: not window.code_dock.isVisible(), timeout=3000)
    window.stage.set_active(False)
    assert window.isMaximized()
    qtbot.waitUntil(lambda: simulator_size(window) == simulator_before, timeout=3000)


def workspace_scale(qtbot, window) -> float:
    return run_js(qtbot, window.editor, "Blockly.getMainWorkspace().scale")


def test_on_stage_the_blocks_are_drawn_larger_and_back_at_desk_size_after_the_start_in_view(qtbot, driver):
    window = driver.open_window(str(examples_dir() / "hobbit" / "drive-a-square.rockly"))
    laid_out(qtbot, window, 1920, 1080)
    desk = workspace_scale(qtbot, window)
    window.stage.set_active(True)
    qtbot.waitUntil(lambda: workspace_scale(qtbot, window) >= desk * 1.4, timeout=3000)
    qtbot.waitUntil(lambda: _start_in_view(qtbot, window), timeout=3000)
    window.stage.set_active(False)
    qtbot.waitUntil(lambda: abs(workspace_scale(qtbot, window) - desk) < 1e-6, timeout=3000)
    qtbot.waitUntil(lambda: _start_in_view(qtbot, window), timeout=3000)
