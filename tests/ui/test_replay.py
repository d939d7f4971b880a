"""Replaying a recorded run in the window (real QtWebEngine + Blockly): every run is recorded, its
timeline shows under the workspace, and a moment lights the block and shows the values of then."""
from page_tools import call_page, run_js
from program_builder import block, number, stack, workspace
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


def test_a_run_is_recorded_and_its_timeline_replays_block_values_and_robot(qtbot, window):
    window.simulator_speed = 10
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
    drive = next(entry for entry in recording.on(channels.BLOCKS) if entry.data["block"] == "drive")
    two = next(entry for entry in recording.on(channels.BLOCKS) if entry.data["block"] == "two")
    during = (drive.time + two.time) / 2

    bar.jump_to(during)
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == ["drive"], timeout=5000)
    assert window.variables.values() == {"laps": "1"}
    shown = window.simulator_dock.view._snapshot
    assert 0.0 < shown["x"] < window.robot().snapshot()["x"] - 0.05  # the robot on its way, not where it is now
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
    assert not window.replay.open(not_a_recording)
    qtbot.waitUntil(lambda: window.findChild(QMessageBox, "recording_unreadable_box") is not None, timeout=5000)
    box = window.findChild(QMessageBox, "recording_unreadable_box")
    assert "photo.mcap is not an MCAP recording" in box.text()
    box.close()
    assert window.replay.moments is shown and window.replay_bar.isVisible()
