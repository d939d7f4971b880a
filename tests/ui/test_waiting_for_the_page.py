"""The window never waits for the page in a nested event loop: Run, save and close carry on
when the page has answered, and nothing is lost or started twice meanwhile."""

import pytest
from page_tools import add_block_as_user, call_page
from program_builder import block, rockly_document, stack, text, workspace
from PySide6.QtWidgets import QMessageBox
from window_tools import completed, error_boxes

from rockly_desktop.core.program import load_program


@pytest.fixture
def sos_file(tmp_path):
    path = tmp_path / "sos.rockly"
    path.write_text(rockly_document([block("hobbit_sos")]), encoding="utf-8")
    return path


def open_and_change(qtbot, window, path):
    """Open ``path`` and add a block the way a person does: the program is then modified."""
    assert completed(qtbot, window.files.open, str(path))
    add_block_as_user(qtbot, window.editor, "hobbit_emo")
    qtbot.waitUntil(window.isWindowModified, timeout=5000)


def saved_types(path) -> set:
    return {b["type"] for b in load_program(path).workspace["blocks"]["blocks"]}


def page_answered_everything_before(qtbot, window):
    """The page answers in order: once this call is answered, every earlier one has been."""
    call_page(qtbot, window.editor, "getState")


def test_clicking_run_twice_fast_starts_exactly_one_run(qtbot, window):
    call_page(qtbot, window.editor, "load", {"workspace": workspace(block("text_print", inputs={"TEXT": text("hi")}))})
    states = []
    window.runs.sig_state_changed.connect(states.append)
    with qtbot.waitSignal(window.runs.sig_finished, timeout=20000):
        window.run_toolbar.run_action.trigger()
        assert window.runs.state == "starting" and not window.run_toolbar.run_action.isEnabled()
        window.run_toolbar.run_action.trigger()
        assert window.runs.run() is False
    page_answered_everything_before(qtbot, window)
    assert states == ["starting", "running", "idle"]
    assert window.console.lines().count("Program started") == 1 and window.console.lines().count("hi") == 1
    assert window.runs.thread is None


def test_closing_the_window_while_a_run_starts_starts_nothing_and_stops_the_robot(qtbot, window):
    call_page(qtbot, window.editor, "load", {"workspace": workspace(block("hobbit_sos"))})
    robot = window.robot()
    window.runs.run()
    assert window.runs.state == "starting"
    assert window.close()
    assert window.runs.state == "idle" and window.runs.thread is None
    page_answered_everything_before(qtbot, window)  # the run code has come by now, too late to start
    assert window.runs.state == "idle" and window.runs.thread is None
    assert "Program started" not in window.console.lines()
    snapshot = robot.snapshot()
    assert snapshot["linear"] == 0 and snapshot["motion"] == "idle"
    assert not robot.simulator._thread.is_alive()  # this window's simulator's clock (not another test's)


def test_saving_then_closing_at_once_saves_the_file_before_the_window_closes(qtbot, window, sos_file, answer_prompts):
    open_and_change(qtbot, window, sos_file)
    asked = answer_prompts(QMessageBox.StandardButton.Cancel)
    window.files.save()
    assert window.files.saving
    assert not window.close()  # not yet: the page has still to give the program
    qtbot.waitUntil(lambda: not window.isVisible(), timeout=10000)
    assert asked == []  # the save under way was waited for, not asked about again
    assert saved_types(sos_file) == {"hobbit_sos", "hobbit_emo"}


def test_save_changes_then_save_closes_once_the_file_is_written(qtbot, window, sos_file, answer_prompts):
    open_and_change(qtbot, window, sos_file)
    asked = answer_prompts(QMessageBox.StandardButton.Save)
    assert not window.close()
    assert asked and "sos.rockly" in asked[0]
    qtbot.waitUntil(lambda: not window.isVisible(), timeout=10000)
    assert saved_types(sos_file) == {"hobbit_sos", "hobbit_emo"}
    assert window.runs.thread is None


def test_save_changes_then_save_opens_the_next_program_after_the_save(
        qtbot, window, sos_file, tmp_path, answer_prompts):
    other = tmp_path / "other.rockly"
    other.write_text(rockly_document([stack(block("hobbit_head", {"head_position": "up_left"}))]), encoding="utf-8")
    open_and_change(qtbot, window, sos_file)
    answer_prompts(QMessageBox.StandardButton.Save)
    assert completed(qtbot, window.files.open, str(other))
    assert saved_types(sos_file) == {"hobbit_sos", "hobbit_emo"}
    assert window.document.path == str(other) and not window.isWindowModified()
    qtbot.waitUntil(lambda: "'up_left'" in window.code_dock.view.toPlainText(), timeout=10000)


def test_a_page_reloaded_while_run_waits_for_the_code_leaves_the_run_idle_with_a_message(qtbot, window, registry):
    call_page(qtbot, window.editor, "load", {"workspace": workspace(block("hobbit_sos"))})
    window.runs.run()
    with qtbot.waitSignal(window.editor.sig_ready, timeout=30000):
        window.activate_profile(registry.get("turtlebot"))  # a new page: the old one never answers
    qtbot.waitUntil(lambda: window.runs.state == "idle", timeout=5000)
    assert window.runs.thread is None and window.run_toolbar.run_action.isEnabled()
    assert window.console.lines()[-1].startswith("The program was not started: the block editor did not give its code")


def test_a_page_reloaded_while_a_save_waits_fails_the_save_with_a_message(qtbot, window, sos_file, registry):
    open_and_change(qtbot, window, sos_file)
    before = sos_file.read_bytes()
    outcomes = []
    window.files.save(then=outcomes.append)
    window.activate_profile(registry.get("turtlebot"))
    qtbot.waitUntil(lambda: outcomes == [False], timeout=5000)
    assert not window.files.saving and window.isWindowModified()
    assert "reloaded" in error_boxes(window)[0]
    assert sos_file.read_bytes() == before
