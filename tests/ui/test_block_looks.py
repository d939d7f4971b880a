"""What a block and the window say and show (real QtWebEngine + Blockly): a block's badge when a STOP ended it,
a badge's text whole inside its frame, Blockly's own words in German, one word for where a program runs."""
import pytest
from page_tools import call_page, run_js
from program_builder import block, number, stack, workspace
from PySide6.QtCore import QPoint, QRect, QSize, Qt
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QApplication, QDockWidget, QLabel, QMessageBox, QTabBar

from rockly_desktop.ui.preferences.preferences import PreferencesDialog


def badge_look(qtbot, window, block_id):
    """The badge on ``block_id``: its text, its state class, its frame's fill and how far its text runs past its
    frame's right edge inside (negative: room to spare), or None."""
    return run_js(qtbot, window.editor, f"""(() => {{
        const root = Blockly.getMainWorkspace().getBlockById('{block_id}').getSvgRoot();
        const badge = root.querySelector(':scope > .rocklyBadge');
        if (!badge) return null;
        const text = badge.querySelector('.rocklyBadgeText'), shape = badge.querySelector('.rocklyBadgeShape');
        const textBox = text.getBoundingClientRect(), shapeBox = shape.getBoundingClientRect();
        return {{text: text.textContent, classes: [...badge.classList], fill: getComputedStyle(shape).fill,
                 overrun: textBox.right - (shapeBox.right - 2)}};
    }})()""")


def test_a_block_ended_by_stop_says_stopped_in_its_own_colour_and_its_running_badge_is_whole(qtbot, driver):
    window = driver.open_window(simulator_speed=1.0)
    call_page(qtbot, window.editor, "load", {"workspace": workspace(
        block("hobbit_arm_move", {"movement": "MoveToCandle"}, id="arm"))})
    window.runs.run()
    qtbot.waitUntil(lambda: (badge_look(qtbot, window, "arm") or {}).get("text") == "running…", timeout=10000)
    running = badge_look(qtbot, window, "arm")
    assert running["overrun"] <= 0, running  # the whole word inside its frame
    with qtbot.waitSignal(window.runs.sig_finished, timeout=20000) as blocker:
        qtbot.keyClick(QApplication.activeWindow() or window, Qt.Key.Key_Escape)
    assert blocker.args[0].outcome == "stopped"
    qtbot.waitUntil(lambda: "running" not in badge_look(qtbot, window, "arm")["text"], timeout=20000)
    stopped = badge_look(qtbot, window, "arm")
    assert stopped["text"].startswith("■ stopped "), stopped
    assert "rocklyBadge-stopped" in stopped["classes"]
    failed_fill = run_js(qtbot, window.editor, """(() => {
        const probe = document.createElementNS('http://www.w3.org/2000/svg', 'g');
        probe.setAttribute('class', 'rocklyBadge rocklyBadge-failed');
        probe.innerHTML = '<rect class="rocklyBadgeShape"/>';
        document.querySelector('.blocklySvg').appendChild(probe);
        const fill = getComputedStyle(probe.firstChild).fill;
        probe.remove();
        return fill; })()""")
    plain = "rgb(236, 239, 241)"
    assert stopped["fill"] not in (failed_fill, running["fill"], plain)  # its own: not failed's, running's or plain


def menu_texts(qtbot, window, target: str) -> list:
    """The items of the context menu Blockly opens on ``target`` (a page expression: a block or the workspace);
    opened again should the page close it before it was read (a focus the window's start gives the blocks late)."""
    items = []

    def opened():
        run_js(qtbot, window.editor, f"""(() => {{
            const ws = Blockly.getMainWorkspace(), target = {target};
            const box = (target.getSvgRoot ? target.getSvgRoot() : ws.getParentSvg()).getBoundingClientRect();
            target.showContextMenu(new PointerEvent('contextmenu', {{clientX: box.left + 10, clientY: box.top + 10}}));
            return true; }})()""")
        items[:] = run_js(qtbot, window.editor, "[...document.querySelectorAll('.blocklyContextMenu "
                                                ".blocklyMenuItemContent')].map(item => item.textContent)")
        return bool(items)

    qtbot.waitUntil(opened, timeout=5000)
    run_js(qtbot, window.editor, "Blockly.ContextMenu.hide() || true")
    return items


def test_blocklys_menus_and_the_repeat_block_speak_german_without_stray_gaps(qtbot, german_window):
    window = german_window
    call_page(qtbot, window.editor, "load", {"workspace": workspace(
        block("controls_repeat_ext", inputs={"TIMES": number(4)}, id="repeat"))})
    workspace_menu = menu_texts(qtbot, window, "ws")
    block_menu = menu_texts(qtbot, window, "ws.getBlockById('repeat')")
    assert "Rückgängig Strg + Z" in workspace_menu and "Wiederholen Strg + Y" in workspace_menu
    assert any(item.startswith("2 Bausteine löschen") and item.endswith(" Entf") for item in block_menu), block_menu
    english = ("Control", "Delete", "Shift", "Escape")
    assert not [item for item in workspace_menu + block_menu if any(word in item for word in english)]
    words = run_js(qtbot, window.editor, "[...Blockly.getMainWorkspace().getBlockById('repeat').getSvgRoot()"
                                         ".querySelectorAll(':scope > g > .blocklyText, :scope > .blocklyText')]"
                                         ".map(text => text.textContent)")
    assert [word for word in words if word != "4"][:2] == ["wiederhole", "Mal:"], words  # no "-mal" after a gap


def test_the_teacher_tab_and_the_toolbar_use_one_word_for_where_a_program_runs(qtbot, german_window, registry):
    window = german_window
    label = next(widget.text().strip() for widget in window.run_toolbar.findChildren(QLabel)
                 if widget.text().strip().endswith(":"))
    dialog = PreferencesDialog("de", None, registry.get("hobbit"), window.settings.teacher)
    qtbot.addWidget(dialog)
    assert f"„{label.rstrip(':')}“" in dialog.teacher_tab.lock_robot.text()


def block_on_screen(qtbot, window, block_id) -> QRect:
    """Where the block ``block_id`` is on the screen (global pixels)."""
    box = run_js(qtbot, window.editor, f"(() => {{ const r = Blockly.getMainWorkspace().getBlockById('{block_id}')"
                                       ".getSvgRoot().getBoundingClientRect();"
                                       " return [r.left, r.top, r.width, r.height]; })()")
    zoom = window.editor.zoomFactor()
    left, top, width, height = (round(value * zoom) for value in box)
    return QRect(window.editor.mapToGlobal(QPoint(left, top)), QSize(width, height))


def beside(block: QRect, box: QRect) -> bool:
    """True when ``box`` does not cover ``block`` and stands next to it (within 40 pixels)."""
    return not block.intersects(box) and block.adjusted(-40, -40, 40, 40).intersects(box)


def run_error_box(window):
    boxes = [box for box in window.findChildren(QMessageBox) if box.objectName() == "run_error_box" and box.isVisible()]
    return boxes[0] if boxes else None


@pytest.mark.parametrize("size", [(1280, 800), (1920, 1080)])
def test_an_errors_message_stands_beside_its_block_and_the_block_stays_red_after_ok(qtbot, driver, size):
    window = driver.open_window()
    window.resize(*size)
    program = workspace(stack(block("variables_set", {"VAR": {"id": "x"}}, {"VALUE": block(
        "math_arithmetic", {"OP": "DIVIDE"}, {"A": number(1), "B": number(0)})}, id="divide")))
    program["variables"] = [{"name": "x", "id": "x"}]
    call_page(qtbot, window.editor, "load", {"workspace": program})
    window.runs.run()
    qtbot.waitUntil(lambda: run_error_box(window) is not None, timeout=20000)
    box = run_error_box(window)
    qtbot.waitUntil(window.replay_bar.isVisible, timeout=5000)  # (it takes room from the blocks when it comes)
    qtbot.waitUntil(lambda: beside(block_on_screen(qtbot, window, "divide"), box.frameGeometry()), timeout=5000)
    assert window.frameGeometry().contains(box.frameGeometry())  # beside the block, still on the window

    ok = box.button(QMessageBox.StandardButton.Ok)
    qtbot.mouseClick(ok, Qt.MouseButton.LeftButton, pos=ok.rect().center())
    qtbot.waitUntil(lambda: run_error_box(window) is None, timeout=5000)
    marked = block_on_screen(qtbot, window, "divide")
    page = window.editor.focusProxy()
    qtbot.mouseClick(page, Qt.MouseButton.LeftButton, pos=page.mapFromGlobal(marked.topLeft() + QPoint(12, 12)))
    outline = ("[...Blockly.getMainWorkspace().getBlockById('divide').getSvgRoot()"
               ".querySelectorAll(':scope > .blocklyPath')]"
               ".map(path => [getComputedStyle(path).stroke, getComputedStyle(path).filter])")
    selected = "Blockly.getMainWorkspace().getBlockById('divide').getSvgRoot().classList.contains('blocklySelected')"
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, selected), timeout=5000)  # the click selected it
    for stroke, glow in run_js(qtbot, window.editor, outline):
        assert stroke == "rgb(213, 0, 0)" and "SelectedGlow" not in glow, (stroke, glow)  # red, no yellow glow


ORANGE = "rgb(255, 109, 0)"  # the window's focus ring (ui/keyboard.py's #ff6d00)


def test_a_block_focused_in_the_flyout_wears_the_windows_orange_ring(qtbot, window):
    qtbot.waitUntil(lambda: activated(window), timeout=5000)
    QTest.keyClick(QApplication.focusWidget(), Qt.Key.Key_1, Qt.KeyboardModifier.ControlModifier)  # to the toolbox
    focused = ("(() => { const node = Blockly.getFocusManager().getFocusedNode();"
               " return node && node.getSvgRoot && node.workspace.isFlyout ? node.id : null; })()")
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, "Blockly.getFocusManager().getFocusedNode() !== null"),
                    timeout=5000)
    QTest.keyClick(QApplication.focusWidget(), Qt.Key.Key_Right)  # into the category's blocks
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, focused) is not None, timeout=5000)
    outlines = run_js(qtbot, window.editor, f"""[...Blockly.getMainWorkspace().getFlyout().getWorkspace()
        .getBlockById({focused}).getSvgRoot().querySelectorAll(':scope > .blocklyPath')]
        .map(path => getComputedStyle(path))
        .map(style => [style.stroke, parseFloat(style.strokeWidth), style.filter])""")
    for stroke, width, glow in outlines:  # its outline and the selection's drawn over it
        assert stroke == ORANGE and width >= 3 and "Glow" not in glow, outlines


def activated(window):
    window.activateWindow()
    return QApplication.activeWindow() is window


def ring_around(widget) -> list:
    """The colours at the middle of ``widget``'s four edges, as drawn."""
    image = widget.grab().toImage()
    middle_x, middle_y = widget.width() // 2, widget.height() // 2
    edges = [(middle_x, 1), (1, middle_y), (middle_x, widget.height() - 2), (widget.width() - 2, middle_y)]
    return [image.pixelColor(x, y).name() for x, y in edges]


def test_a_dialogs_control_that_has_the_keyboard_wears_the_orange_ring(qtbot, window):
    qtbot.waitUntil(lambda: activated(window), timeout=5000)
    dialog = PreferencesDialog("en", window, window.profile, window.settings.teacher)
    dialog.open()
    qtbot.waitUntil(lambda: QApplication.activeWindow() is dialog, timeout=5000)
    for _ in range(3):
        QTest.keyClick(QApplication.focusWidget() or dialog, Qt.Key.Key_Tab)
        focused = QApplication.focusWidget()
        assert focused.window() is dialog
        qtbot.waitUntil(lambda focused=focused: ring_around(focused) == ["#ff6d00"] * 4, timeout=5000)
    dialog.reject()


def group_of(window, widget) -> str:
    """What ``widget`` belongs to, as a person sees it: a dock's name, 'tabs of' the dock a tab bar shows, the
    toolbar, the blocks."""
    if isinstance(widget, QTabBar):
        return "tabs of " + widget.tabText(widget.currentIndex())
    node = widget
    while node is not None and not isinstance(node, QDockWidget):
        node = node.parentWidget()
    if node is not None:
        return node.windowTitle()
    return "blocks" if widget is window.editor.focusProxy() else "toolbar"


@pytest.mark.parametrize("size", [(1280, 800), (1920, 1080)])
def test_tab_goes_through_the_docks_in_visual_order_each_tab_bar_after_its_dock(qtbot, window, size):
    window.resize(*size)
    qtbot.waitUntil(lambda: activated(window), timeout=5000)
    window.editor.setFocus()
    groups = []
    for _ in range(40):
        QTest.keyClick(QApplication.focusWidget(), Qt.Key.Key_Tab)
        group = group_of(window, QApplication.focusWidget())
        if group == "blocks":
            break
        if not groups or groups[-1] != group:
            groups.append(group)
    # the right column top to bottom (the simulator; the code with its tabs), then the bottom row (the console
    # with its tabs), then round to the toolbar
    assert groups == ["Simulator", "Python code", "tabs of Python code", "Console", "tabs of Console", "toolbar"]
