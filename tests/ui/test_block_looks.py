"""What a block says and shows in a run (real QtWebEngine + Blockly): its badge when a STOP ended it, and
a badge's text whole inside its frame."""
from page_tools import call_page, run_js
from program_builder import block, workspace
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QApplication


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
    with qtbot.waitSignal(window.runs.sig_finished, timeout=5000) as blocker:
        qtbot.keyClick(QApplication.activeWindow() or window, Qt.Key.Key_Escape)
    assert blocker.args[0].outcome == "stopped"
    qtbot.waitUntil(lambda: "running" not in badge_look(qtbot, window, "arm")["text"], timeout=5000)
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
    assert stopped["fill"] not in (failed_fill, running["fill"], "rgb(236, 239, 241)")  # not failed's, running's or plain
