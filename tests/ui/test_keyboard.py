"""The window from the keyboard alone: a program built, run and stopped with keys, Tab through every
dock, a name on every control in Qt's accessibility tree, the keys on the Help page.

Keys go where a keyboard sends them: to the widget that has the focus (``QApplication.focusWidget()``),
which is the web view's inner widget while the block editor has the keyboard; Chromium gets them from
there as it gets a real keyboard's, offscreen too.
"""
import sys

import pytest
from page_tools import run_js
from program_builder import number, rockly_document
from PySide6.QtCore import Qt
from PySide6.QtGui import QAccessible
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QApplication, QDockWidget, QTabBar, QToolButton, QWidget

from rockly_desktop.bridge.channel import PageChannel
from rockly_desktop.settings.app_settings import AppSettings
from rockly_desktop.ui.help_dialogs import shortcuts_html
from rockly_desktop.ui.preferences.preferences import PreferencesDialog
from rockly_desktop.ui.texts import tr

K = Qt.Key
CTRL = Qt.KeyboardModifier.ControlModifier
SHIFT = Qt.KeyboardModifier.ShiftModifier


def press(qtbot, window, key, modifier=Qt.KeyboardModifier.NoModifier):
    """One key where the person's keyboard is now; the focus is never lost."""
    focused = QApplication.focusWidget()
    assert focused is not None, "the keyboard went nowhere"
    QTest.keyClick(focused, key, modifier)
    assert QApplication.focusWidget() is not None, "the keyboard went nowhere"


def focused_block(qtbot, window):
    return run_js(qtbot, window.editor, "(() => { const n = Blockly.getFocusManager().getFocusedNode();"
                                        " return n && n.type ? n.type : null; })()")


def workspace_focused(qtbot, window):
    return run_js(qtbot, window.editor, "Blockly.getFocusManager().getFocusedTree() === Blockly.getMainWorkspace()")


def focused_category(qtbot, window):
    return run_js(qtbot, window.editor, "(() => { const n = Blockly.getFocusManager().getFocusedNode();"
                                        " return n && n.getName ? n.getName() : null; })()")


def active(window):
    window.activateWindow()
    return QApplication.activeWindow() is window


def take_block(qtbot, window, category_downs, block_downs, block_type):
    """T, down to the category, right into its blocks, down to the block, Enter takes it, Enter puts it down."""
    press(qtbot, window, K.Key_T)
    qtbot.waitUntil(lambda: focused_category(qtbot, window) is not None, timeout=5000)
    for _ in range(category_downs):
        press(qtbot, window, K.Key_Down)
    press(qtbot, window, K.Key_Right)
    for _ in range(block_downs):
        press(qtbot, window, K.Key_Down)
    qtbot.waitUntil(lambda: focused_block(qtbot, window) == block_type, timeout=5000)
    press(qtbot, window, K.Key_Enter)
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, "Blockly.getMainWorkspace().getAllBlocks(false)"
                                                         f".some(b => b.type === {block_type!r})"), timeout=5000)
    press(qtbot, window, K.Key_Enter)


def test_a_program_is_built_run_and_stopped_with_keys_only(qtbot, driver):
    window = driver.open_window(simulator_speed=1.0)
    qtbot.waitUntil(lambda: active(window), timeout=5000)
    press(qtbot, window, K.Key_2, CTRL)  # to the program's blocks (a fresh window starts there too)
    qtbot.waitUntil(lambda: window.editor.focusProxy() is QApplication.focusWidget(), timeout=5000)
    qtbot.waitUntil(lambda: workspace_focused(qtbot, window), timeout=5000)
    take_block(qtbot, window, 0, 0, "hobbit_move")  # Drive: drive forward 1 m
    take_block(qtbot, window, 0, 1, "hobbit_turn")  # under the drive (the selected block): turn left 90°
    take_block(qtbot, window, 1, 1, "hobbit_emo")  # Head: show happy, under the turn
    program = "robot.drive(1, 'forward')\nrobot.turn(90, 'left')\nrobot.show_emotion('HAPPY')\n"
    qtbot.waitUntil(lambda: window.editor.python == program, timeout=5000)

    press(qtbot, window, K.Key_F5)
    qtbot.waitUntil(lambda: window.robot().snapshot()["motion"] == "moving", timeout=10000)
    assert window.runs.state == "running"
    with qtbot.waitSignal(window.runs.sig_finished, timeout=5000) as blocker:
        press(qtbot, window, K.Key_Escape)
    assert blocker.args[0].outcome == "stopped"
    snapshot = window.robot().snapshot()
    assert snapshot["linear"] == 0 and snapshot["angular"] == 0 and snapshot["motion"] == "idle"


def raised_docks(window):
    return [dock for dock in window.findChildren(QDockWidget)
            if dock.isVisible() and not dock.visibleRegion().isEmpty()]


def dock_of(widget):
    while widget is not None and not isinstance(widget, QDockWidget):
        widget = widget.parentWidget()
    return widget


def tab_round(qtbot, window, key, modifier=Qt.KeyboardModifier.NoModifier):
    """Press ``key`` until the focus comes back where it started: the widgets it visited, in order, from there."""
    start = QApplication.focusWidget()
    visited = [start]
    for _ in range(60):
        press(qtbot, window, key, modifier)
        if QApplication.focusWidget() is start:
            return visited
        visited.append(QApplication.focusWidget())
    raise AssertionError(f"Tab never came back: {[type(w).__name__ for w in visited]}")


def test_tab_and_shift_tab_go_round_every_control_of_every_dock_and_never_lose_focus(qtbot, window):
    window.resize(1280, 800)  # the toolbar's width: on the tests' small screen the first window is narrower
    qtbot.waitUntil(lambda: active(window), timeout=5000)
    forward = tab_round(qtbot, window, K.Key_Tab)
    backward = tab_round(qtbot, window, K.Key_Backtab, SHIFT)
    assert backward == forward[:1] + forward[:0:-1]
    docks_reached = {dock_of(widget) for widget in forward} - {None}
    assert set(raised_docks(window)) <= docks_reached
    toolbar = window.run_toolbar
    assert {toolbar.widgetForAction(toolbar.run_action), toolbar.speed, toolbar.backend} <= set(forward)
    assert window.editor.focusProxy() in forward
    # the panels behind the raised ones: their tab bar takes the keyboard, the arrow keys bring them up
    reached_behind = set()
    for bar in [w for w in forward if isinstance(w, QTabBar)]:
        for _ in range(bar.count()):
            bar.setFocus()
            press(qtbot, window, K.Key_Right)
            reached_behind |= {dock_of(widget) for widget in tab_round(qtbot, window, K.Key_Tab)}
    assert {dock for dock in window.findChildren(QDockWidget) if not dock.isHidden()} <= reached_behind | docks_reached


def focusable_controls(window):
    """The window's controls that can take the keyboard now: shown, in sight, enabled, with a focus policy."""
    return [widget for widget in window.findChildren(QWidget)
            if widget.focusPolicy() != Qt.FocusPolicy.NoFocus and widget.isVisible() and widget.isEnabled()
            and not widget.visibleRegion().isEmpty() and widget.window() is window]


def names_of_focusable_controls(window):
    names = {}
    for widget in focusable_controls(window):
        interface = QAccessible.queryAccessibleInterface(widget)
        assert interface is not None, widget
        names[widget] = interface.text(QAccessible.Text.Name)
    return names


@pytest.mark.parametrize("language", ["en", "de"])
def test_every_control_that_takes_the_keyboard_has_a_name_in_the_accessibility_tree(qtbot, window, language):
    qtbot.waitUntil(lambda: window.simulator_dock.view is not None, timeout=10000)
    if language == "de":
        window.set_language("de")
        qtbot.waitUntil(lambda: window.language == "de" and window.editor.is_ready, timeout=15000)
        qtbot.waitUntil(lambda: window.simulator_dock.view is not None, timeout=10000)
    for dock in window.findChildren(QDockWidget):  # every panel in turn, and its controls
        dock.show()
        dock.raise_()
        names = names_of_focusable_controls(window)
        unnamed = [type(widget).__name__ for widget, name in names.items() if not name.strip()]
        assert not unnamed, f"no name in the accessibility tree: {unnamed}"
    names = names_of_focusable_controls(window)
    toolbar = window.run_toolbar
    assert names[toolbar.speed] == tr("speed", language)
    assert names[window.editor.focusProxy()] == tr("a11y_block_editor", language)
    assert names[window.code_dock.view].startswith(tr("code_dock", language))


def test_the_help_page_lists_the_jump_keys_and_the_block_editors_keys_in_both_languages(qtbot, window):
    for language in ("en", "de"):
        page = shortcuts_html(window, language)
        for key in ("keys_t", "keys_arrows", "keys_tab", "editor_keys_title"):
            assert tr(key, language) in page
    page = shortcuts_html(window, "en")
    assert "Go to the Toolbox" in page and "Ctrl+1" in page
    window.set_language("de")
    qtbot.waitUntil(lambda: window.language == "de", timeout=15000)
    assert "Zur Blockauswahl" in shortcuts_html(window, "de")


LOOK = ("(() => { const ws = Blockly.getMainWorkspace();"
        " const text = document.querySelector('.blocklyBlockCanvas .blocklyText');"
        " return {theme: ws.getTheme().name, contrast: document.getElementById('workspace').classList"
        ".contains('rocklyHighContrast'), size: text ? parseFloat(getComputedStyle(text).fontSize) : null,"
        " toolbox: getComputedStyle(document.querySelector('.blocklyToolbox')).backgroundColor,"
        " width: ws.getTopBlocks(false)[0].getHeightWidth().width,"
        " number: getComputedStyle(document.querySelector('.blocklyShadow .blocklyText')).fill}; })()")


def test_high_contrast_and_larger_text_from_preferences_stay_through_a_language_switch(qtbot, window, monkeypatch):
    load_program = "robot.drive(1, 'forward')\n"
    qtbot.waitUntil(lambda: active(window), timeout=5000)
    press(qtbot, window, K.Key_2, CTRL)
    qtbot.waitUntil(lambda: workspace_focused(qtbot, window), timeout=5000)
    take_block(qtbot, window, 0, 0, "hobbit_move")
    qtbot.waitUntil(lambda: window.editor.python == load_program, timeout=5000)
    before = run_js(qtbot, window.editor, LOOK)
    assert not before["contrast"]

    def choose(dialog):
        dialog.contrast_box.setChecked(True)
        dialog.large_text_box.setChecked(True)
        return True
    monkeypatch.setattr(PreferencesDialog, "exec", choose)
    window.show_preferences()
    def in_the_new_look():  # the class first, then every field measured again: wait for both
        now = run_js(qtbot, window.editor, LOOK)
        return bool(now["contrast"]) and now["size"] > before["size"] * 1.2 and now["width"] > before["width"] * 1.2
    qtbot.waitUntil(in_the_new_look, timeout=5000)
    after = run_js(qtbot, window.editor, LOOK)
    assert after["size"] > before["size"] * 1.2
    assert after["toolbox"] == "rgb(0, 0, 0)" != before["toolbox"]
    assert after["width"] > before["width"] * 1.2  # the fields measured again: larger text never overlaps
    assert after["number"] == "rgb(0, 0, 0)" != before["number"]
    assert window.settings.block_look == {"highContrast": True, "largeText": True}

    window.set_language("de")  # a new page: the look goes with it
    qtbot.waitUntil(lambda: window.language == "de" and window.editor.is_ready, timeout=15000)
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, LOOK)["contrast"], timeout=5000)
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, LOOK)["size"] == after["size"], timeout=5000)


@pytest.mark.parametrize("look", [{"highContrast": True, "largeText": True},
                                  {"highContrast": False, "largeText": False}], ids=["contrast-and-large", "plain"])
def test_a_window_starts_in_the_remembered_look_without_measuring_its_blocks_again(qtbot, driver, tmp_path,
                                                                                   monkeypatch, look):
    # The look goes with the page's setup: a setLook after the start-up program measured its blocks again.
    AppSettings(driver.settings_path).block_look = look
    program = tmp_path / "drive.rockly"
    program.write_text(rockly_document([{"type": "hobbit_move", "fields": {"direction": "+"}, "x": 10, "y": 10,
                                                "inputs": {"speed": {"shadow": number(1)}}}]))
    calls = []
    original_call = PageChannel.call
    monkeypatch.setattr(PageChannel, "call", lambda self, name, *args, **kwargs: calls.append(name)
                        or original_call(self, name, *args, **kwargs))
    window = driver.open_window(program)
    shown = run_js(qtbot, window.editor, LOOK)
    assert shown["contrast"] == look["highContrast"]
    assert shown["theme"] == "rockly" + "-contrast" * look["highContrast"] + "-large" * look["largeText"]
    assert "setLook" not in calls, calls


def test_the_control_that_has_the_keyboard_wears_a_thick_orange_ring_on_every_dock(qtbot, window):
    qtbot.waitUntil(lambda: active(window), timeout=5000)
    ring = "#ff6d00"
    stops = tab_round(qtbot, window, K.Key_Tab)
    for _ in stops:
        press(qtbot, window, K.Key_Tab)
        focused = QApplication.focusWidget()
        shown = window.editor if focused is window.editor.focusProxy() else focused
        image = shown.grab().toImage()
        middle_x, middle_y = shown.width() // 2, shown.height() // 2
        edges = [(middle_x, 1), (1, middle_y), (middle_x, shown.height() - 2), (shown.width() - 2, middle_y)]
        assert [image.pixelColor(x, y).name() for x, y in edges] == [ring] * 4, type(shown).__name__
    assert set(raised_docks(window)) <= {dock_of(widget) for widget in stops}
    # a click shows where it went by itself: no ring (as a browser's :focus-visible)
    QTest.mouseClick(window.console.view.viewport(), Qt.MouseButton.LeftButton)
    assert QApplication.focusWidget() is window.console.view
    assert window.console.view.grab().toImage().pixelColor(window.console.view.width() // 2, 1).name() != ring


def test_blocklys_keyboard_hints_speak_german_in_a_german_window(qtbot, german_window):
    hint = run_js(qtbot, german_window.editor, "Blockly.Msg.KEYBOARD_NAV_UNCONSTRAINED_MOVE_HINT")
    assert hint == tr("nav_hint_unconstrained_move", "de") != tr("nav_hint_unconstrained_move", "en")


def test_ctrl_and_a_digit_jump_to_the_toolbox_blocks_code_console_and_simulator(qtbot, window):
    qtbot.waitUntil(lambda: active(window), timeout=5000)
    window.console.hide()  # a closed panel opens when its key is pressed
    press(qtbot, window, K.Key_3, CTRL)
    assert QApplication.focusWidget() is window.code_dock.view
    press(qtbot, window, K.Key_4, CTRL)
    assert window.console.isVisible() and QApplication.focusWidget() is window.console.view
    press(qtbot, window, K.Key_5, CTRL)
    assert dock_of(QApplication.focusWidget()) is window.simulator_dock
    press(qtbot, window, K.Key_1, CTRL)
    qtbot.waitUntil(lambda: focused_category(qtbot, window) is not None, timeout=5000)
    assert QApplication.focusWidget() is window.editor.focusProxy()
    press(qtbot, window, K.Key_2, CTRL)
    qtbot.waitUntil(lambda: workspace_focused(qtbot, window), timeout=5000)


def test_a_closed_window_names_no_controls_any_more(qtbot, window, monkeypatch):
    """Nothing of a closed window reaches its controls' naming: the tabbed docks' visibility (as the window hides,
    and as its docks are destroyed) and the robot box's changes (as the robots shut down) come too late."""
    from rockly_desktop.ui import keyboard

    named = []
    monkeypatch.setattr(keyboard, "name_controls", lambda *args: named.append(args))
    window.document.modified = False
    window.close()
    window.robots.sig_robot_changed.emit()
    window.plot_dock.visibilityChanged.emit(True)
    assert named == []


def test_a_window_deleted_without_closing_says_nothing_of_its_deleted_controls(qtbot, driver, monkeypatch):
    """A window deleted unclosed (a kiosk that cannot start) still has its docks' signals while Qt destroys them."""
    from PySide6.QtCore import QCoreApplication, QEvent

    window = driver.open_window()
    driver.windows.remove(window)
    window.runs.shutdown()
    window.robots.shutdown()
    errors = []  # what a Qt slot raised
    monkeypatch.setattr(sys, "excepthook", lambda kind, error, trace: errors.append(error))
    window.deleteLater()
    QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)
    assert errors == []


def test_the_controls_are_named_once_the_editor_is_up_not_while_the_window_is_built(qtbot, driver, monkeypatch):
    # Naming every control made Python wrappers and enums for each while the editor waited for its program.
    from rockly_desktop.app import build_main_window
    from rockly_desktop.ui import keyboard

    named = []
    name_controls = keyboard.name_controls
    monkeypatch.setattr(keyboard, "name_controls", lambda *args: named.append(args) or name_controls(*args))
    window = build_main_window(driver.settings_path)
    driver.windows.append(window)
    window.show()
    assert named == []
    with qtbot.waitSignal(window.editor.sig_ready, timeout=30000):
        window.start()
    assert named  # (a robot shown or a tab switched later names them again)
    assert QAccessible.queryAccessibleInterface(window.run_toolbar.speed).text(QAccessible.Text.Name) \
        == tr("speed", "en")
    assert all(button.focusPolicy() == Qt.FocusPolicy.TabFocus
               for button in window.run_toolbar.findChildren(QToolButton) if button.defaultAction() is not None)
    qtbot.waitUntil(lambda: window.editor.hasFocus() or window.editor.focusProxy().hasFocus(), timeout=5000)


def test_a_window_whose_editor_cannot_start_still_names_its_controls(qtbot, driver, monkeypatch):
    from rockly_desktop.app import build_main_window
    from rockly_desktop.bridge.editor_view import EditorView

    setup = EditorView._setup
    monkeypatch.setattr(EditorView, "_setup", staticmethod(lambda *args, **kwargs: {**setup(*args, **kwargs),
                                                                                    "profile": None}))
    window = build_main_window(driver.settings_path)
    driver.windows.append(window)
    window.show()
    with qtbot.waitSignal(window.editor.sig_page_error, timeout=30000):
        window.start()
    qtbot.waitUntil(lambda: QAccessible.queryAccessibleInterface(window.run_toolbar.speed)
                    .text(QAccessible.Text.Name) == tr("speed", "en"), timeout=5000)
    assert not window.editor.is_ready
