"""Replaying a recorded run in the window (real QtWebEngine + Blockly): every run is recorded, its
timeline shows under the workspace, and a moment lights the block and shows the values of then."""
import json
from pathlib import Path

import pytest
from page_tools import call_page, run_js
from program_builder import block, number, stack, workspace
from PySide6.QtCore import QPoint, Qt
from PySide6.QtWidgets import QMessageBox

from rockly_desktop.recording import channels
from rockly_desktop.recording.library import recordings_in


def highlighted(qtbot, window):
    return run_js(qtbot, window.editor, "Blockly.getMainWorkspace().getAllBlocks(false)"
                                        ".filter(b => b.getSvgRoot().classList.contains('blocklyHighlighted'))"
                                        ".map(b => b.id)")


def run_to_the_end(qtbot, window, *blocks, variables=()):
    ws = workspace(*blocks)
    ws["variables"] = [{"name": name, "id": name} for name in variables]
    call_page(qtbot, window.editor, "load", {"workspace": ws})
    with qtbot.waitSignal(window.runs.sig_finished, timeout=20000) as blocker:
        assert window.runs.run()
    return blocker.args[0]


def test_a_run_is_recorded_and_its_timeline_replays_block_values_and_robot(qtbot, driver):
    window = driver.open_window(simulator_speed=2.0)  # the drive lasts about a second: snapshots on the way
    result = run_to_the_end(qtbot, window, stack(
        block("variables_set", {"VAR": {"id": "laps"}}, {"VALUE": number(1)}, id="one"),
        block("hobbit_move", {"direction": "+"}, {"speed": number(1)}, id="drive"),
        block("variables_set", {"VAR": {"id": "laps"}}, {"VALUE": number(2)}, id="two"),
        block("hobbit_emo", {"emotion": "HAPPY"}, id="smile")), variables=["laps"])
    assert result.outcome == "finished"
    assert recordings_in(window.settings.recordings_folder) == [window.runs.last_recording]
    bar = window.replay_bar
    qtbot.waitUntil(bar.isVisible, timeout=5000)
    assert highlighted(qtbot, window) == []  # nothing is replayed until the person moves the scrubber
    recording = window.replay.moments.recording
    final_x = window.robot().snapshot()["x"]
    on_the_way = next(entry for entry in recording.on(channels.SIMULATOR) if 0.05 < entry.data["x"] < final_x - 0.05)

    bar.jump_to(on_the_way.time + 0.001)  # the scrubber counts whole milliseconds
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == ["drive"], timeout=5000)
    assert window.variables.values() == {"laps": "1"}
    assert window.simulator_dock.view._snapshot["x"] == on_the_way.data["x"]  # where the robot was then
    bar.jump_to(bar.duration)
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == ["smile"], timeout=5000)
    assert window.variables.values() == {"laps": "2"}

    bar.close_timeline()
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == [], timeout=5000)


def test_an_error_is_a_marker_and_a_file_that_is_no_recording_changes_nothing(qtbot, window, tmp_path):
    result = run_to_the_end(qtbot, window, stack(block("hobbit_head", {"head_position": "up_left"}, id="look"),
                                                 block("text_print", inputs={"TEXT": block(
                                                     "math_arithmetic", {"OP": "DIVIDE"},
                                                     {"A": number(1), "B": number(0)})}, id="divide")))
    assert result.outcome == "error"
    qtbot.waitUntil(window.replay_bar.isVisible, timeout=5000)
    assert [marker.kind for marker in window.replay_bar.markers.markers] == ["error"]
    shown = window.replay.moments

    not_a_recording = tmp_path / "photo.mcap"
    not_a_recording.write_bytes(b"\x89PNG not a recording")
    window.replay.open(not_a_recording)
    qtbot.waitUntil(lambda: window.findChild(QMessageBox, "recording_unreadable_box") is not None, timeout=5000)
    box = window.findChild(QMessageBox, "recording_unreadable_box")
    assert "photo.mcap is not an MCAP recording" in box.text()
    box.close()
    assert window.replay.moments is shown and window.replay_bar.isVisible()


def badge(qtbot, window, block_id):
    """The text of the badge on ``block_id`` itself (not on a block nested in it), or None."""
    return run_js(qtbot, window.editor, f"(Blockly.getMainWorkspace().getBlockById('{block_id}').getSvgRoot()"
                                        ".querySelector(':scope > .rocklyBadge > .rocklyBadgeText')"
                                        " || {textContent: null}).textContent")


def test_blocks_that_talk_to_the_robot_get_badges_live_and_in_the_replay_not_at_the_starter_level(qtbot, window):
    info = block("hobbit_show_info", inputs={"text": block("text", {"TEXT": "Hello"})}, id="info")
    result = run_to_the_end(qtbot, window, stack(block("hobbit_head", {"head_position": "up_left"}, id="look"), info))
    assert result.outcome == "finished"
    qtbot.waitUntil(lambda: (badge(qtbot, window, "info") or "").startswith("✓"), timeout=5000)
    assert badge(qtbot, window, "look") is None  # a publish has no outcome to show
    assert not window.document.modified
    state = call_page(qtbot, window.editor, "getState")
    assert "rockly_badge" not in str(state["workspace"])  # a badge never reaches the program

    window.replay_bar.jump_to(0.0)  # before the call: no badge then
    qtbot.waitUntil(lambda: badge(qtbot, window, "info") is None, timeout=5000)
    window.replay_bar.jump_to(window.replay_bar.duration)
    qtbot.waitUntil(lambda: (badge(qtbot, window, "info") or "").startswith("✓"), timeout=5000)

    window.settings.teacher.set_level("hobbit", "starter")
    run_to_the_end(qtbot, window, stack(info))
    qtbot.waitUntil(lambda: badge(qtbot, window, "info") is None, timeout=5000)
    window.replay_bar.jump_to(0.0)
    window.replay_bar.jump_to(window.replay_bar.duration)
    assert badge(qtbot, window, "info") is None


def glowing(image) -> bool:
    """Whether a grab of the editor shows a highlighted block's yellow glow (a few dozen pixels of it)."""
    found = 0
    for y in range(0, image.height(), 3):
        for x in range(0, image.width(), 3):
            colour = image.pixelColor(x, y)
            found += colour.red() > 230 and 150 < colour.green() < 215 and colour.blue() < 60
    return found > 30


def shot(widget, name):
    """Save ``widget`` as /tmp/replay_shots/NAME.png (to look at)."""
    folder = Path("/tmp/replay_shots")
    folder.mkdir(exist_ok=True)
    assert widget.grab().save(str(folder / f"{name}.png"))


def test_the_console_and_the_plot_follow_the_replay(qtbot, driver):
    window = driver.open_window(simulator_speed=2.0)
    window.plot_dock.raise_()
    window.plot_panel().add_curve("/odom", "pose.pose.position.x")
    say = [block("text_print", inputs={"TEXT": block("text", {"TEXT": f"lap {lap}"})}, id=f"say{lap}")
           for lap in (1, 2)]
    result = run_to_the_end(qtbot, window, stack(
        say[0], block("hobbit_move", {"direction": "+"}, {"speed": number(1)}, id="drive"), say[1]))
    assert result.outcome == "finished"
    qtbot.waitUntil(window.replay_bar.isVisible, timeout=5000)
    printed = window.replay.moments.recording.on(channels.OUTPUT)
    assert [entry.data["text"] for entry in printed] == ["lap 1", "lap 2"]
    odom_x = window.replay.topics.series("/odom", "pose.pose.position.x")
    assert len(odom_x[0]) > 2 and odom_x[1][-1] > odom_x[1][0]  # it drove forward

    middle = (printed[0].time + printed[1].time) / 2
    page_before = window.editor.grab().toImage()
    window.replay_bar.jump_to(middle)
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == ["drive"], timeout=5000)
    qtbot.waitUntil(lambda: glowing(window.editor.grab().toImage()) and window.editor.grab().toImage() != page_before,
                    timeout=5000)  # the page has painted the glow where it is now
    lines = window.console.recorded_lines()
    assert len(lines) == 1 and lines[0].endswith("lap 1")  # what had been printed by then
    plot = window.plot_panel()
    assert plot.replaying and abs(plot.cursor.value() - window.replay_bar.position) < 1e-9
    times, values = plot.curve_item("/odom", "pose.pose.position.x").getData()
    assert list(times) == odom_x[0] and list(values) == odom_x[1]  # the whole recorded series
    shot(window, "replay_plot")
    window.console.raise_()
    shot(window, "replay_console")

    window.replay_bar.jump_to(window.replay_bar.duration)
    qtbot.waitUntil(lambda: len(window.console.recorded_lines()) == 2, timeout=5000)
    window.replay_bar.jump_to(0.0)  # back before anything was printed
    assert window.console.recorded_lines() == [] and window.console.replay_view.isVisible()
    window.replay_bar.close_timeline()
    assert not plot.replaying and plot.cursor is None
    assert window.console.recorded_lines() == [] and window.console.lines()[-1] != ""


HOVER_SCRIPT = """(() => {
  clearInterval(window.rocklyHovering);
  const path = Blockly.getMainWorkspace().getBlockById(%s).pathObject.svgPath;
  const point = () => {
    const box = path.getBoundingClientRect();
    const at = {bubbles: true, clientX: box.left + 6, clientY: box.bottom - 6, pointerType: 'mouse'};
    path.dispatchEvent(new PointerEvent('pointerout', at));
    setTimeout(() => {
      path.dispatchEvent(new PointerEvent('pointerover', at));
      path.dispatchEvent(new PointerEvent('pointermove', at));
    }, 20);
  };
  point();
  // Blockly shows a tooltip 750 ms after the pointer rests, unless a gesture blocks tooltips then: again.
  window.rocklyHovering = setInterval(() => Blockly.Tooltip.isVisible() ? clearInterval(window.rocklyHovering)
                                                                        : point(), 1500);
  return true;
})()"""


def hover(qtbot, window, block_id):
    """Point at ``block_id`` as a mouse would; the text of the tooltip Blockly shows then."""
    run_js(qtbot, window.editor, "Blockly.Tooltip.hide(), true")
    run_js(qtbot, window.editor, HOVER_SCRIPT % json.dumps(block_id))
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, "Blockly.Tooltip.isVisible()"), timeout=10000)
    return run_js(qtbot, window.editor, "Blockly.Tooltip.getDiv().innerText")


def test_an_expression_block_shows_its_last_value_on_hover_live_and_in_the_replay_not_at_the_starter_level(
        qtbot, window):
    sum_block = block("math_arithmetic", {"OP": "ADD"}, {"A": number(1), "B": block(
        "variables_get", {"VAR": {"id": "laps"}}, id="laps_now")}, id="sum")
    program = stack(block("variables_set", {"VAR": {"id": "laps"}}, {"VALUE": number(2)}, id="two"),
                    block("text_print", inputs={"TEXT": sum_block}, id="say"))
    assert run_to_the_end(qtbot, window, program, variables=["laps"]).outcome == "finished"
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, "RocklyValues.lastValue('sum')") == "3", timeout=5000)
    assert run_js(qtbot, window.editor, "RocklyValues.lastValue('laps_now')") == "2"
    text = hover(qtbot, window, "sum")
    assert text.splitlines()[-1] == "Last value: 3" and len(text.splitlines()) > 1  # below Blockly's own tooltip
    shot(window.editor, "value_on_hover")
    assert "__rockly__.value" not in call_page(qtbot, window.editor, "getState")["python"]  # exported Python is plain
    assert "value" not in str(call_page(qtbot, window.editor, "getState")["workspace"]).replace("VALUE", "")

    window.replay_bar.jump_to(0.0)  # before the sum was worked out
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, "RocklyValues.lastValue('sum')") is None, timeout=5000)
    assert hover(qtbot, window, "sum").splitlines()[-1] != "Last value: 3"
    window.replay_bar.jump_to(window.replay_bar.duration)
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, "RocklyValues.lastValue('sum')") == "3", timeout=5000)

    window.settings.teacher.set_level("hobbit", "starter")
    assert run_to_the_end(qtbot, window, program, variables=["laps"]).outcome == "finished"
    assert "__rockly__.value" not in call_page(qtbot, window.editor, "getRunCode", {"values": False})["code"]
    assert run_js(qtbot, window.editor, "RocklyValues.lastValue('sum')") is None
    assert "Last value" not in hover(qtbot, window, "sum")


def test_a_breakpoint_is_a_marker_of_its_own_and_a_click_on_it_jumps_there(qtbot, window):
    call_page(qtbot, window.editor, "load", {"workspace": workspace(stack(
        block("hobbit_head", {"head_position": "up_center"}, id="first"),
        block("hobbit_head", {"head_position": "down_center"}, id="second")))})
    call_page(qtbot, window.editor, "setBreakpoints", {"ids": ["second"]})
    window.runs.run()
    qtbot.waitUntil(lambda: window.runs.state == "paused", timeout=10000)
    with qtbot.waitSignal(window.runs.sig_finished, timeout=10000):
        window.runs.resume()
    bar = window.replay_bar
    qtbot.waitUntil(bar.isVisible, timeout=5000)
    marker = next(marker for marker in bar.markers.markers if marker.kind == "breakpoint")
    assert [m.kind for m in bar.markers.markers] == ["breakpoint"]
    strip = bar.markers
    qtbot.mouseClick(strip, Qt.MouseButton.LeftButton, pos=QPoint(round(strip._x(marker.time)), strip.height() // 2))
    assert bar.position == marker.time  # exactly: the breakpoint's block may have come a fraction of a ms before
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == ["second"], timeout=5000)



@pytest.mark.parametrize(("fixture", "mark"), [("window", "Replay"), ("german_window", "Wiederholung")])
def test_every_dock_showing_the_past_says_replay_until_the_timeline_closes(qtbot, request, fixture, mark):
    window = request.getfixturevalue(fixture)
    window.simulator_speed = 2.0
    window.plot_dock.raise_()
    window.plot_panel().add_curve("/odom", "pose.pose.position.x")
    assert run_to_the_end(qtbot, window, stack(
        block("text_print", inputs={"TEXT": block("text", {"TEXT": "go"})}),
        block("hobbit_move", {"direction": "+"}, {"speed": number(1)}))).outcome == "finished"
    qtbot.waitUntil(window.replay_bar.isVisible, timeout=5000)
    driven = [window.docks[key] for key in ("simulator_dock", "variables_dock", "console_dock", "plot_dock")]
    live_titles = [dock.windowTitle() for dock in driven]
    assert not any(mark in title for title in live_titles)
    window.replay_bar.jump_to(window.replay_bar.duration)  # the robot where it stopped, the line printed
    assert [dock.windowTitle() for dock in driven] == [f"{title} — {mark}" for title in live_titles]
    assert mark not in window.code_dock.windowTitle()  # the code is the program's, not a moment's
    shot(window, f"replay_marked_{fixture}")
    window.replay_bar.close_timeline()
    assert [dock.windowTitle() for dock in driven] == live_titles
