"""Running programs in the window on the built-in simulator: run, step, breakpoints, stop, errors."""
import pytest
from page_tools import call_page, run_js
from program_builder import block, number, stack, text, workspace
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QApplication, QMessageBox
from window_tools import click_stop, completed

from rockly_desktop.ui.docks.tablet import TabletDialog


def load(qtbot, window, *blocks, variables=None):
    ws = workspace(*blocks)
    if variables:
        ws["variables"] = [{"name": name, "id": name} for name in variables]
    call_page(qtbot, window.editor, "load", {"workspace": ws})
    return ws


def finished(qtbot, window, timeout=20000):
    with qtbot.waitSignal(window.runs.sig_finished, timeout=timeout) as blocker:
        pass
    return blocker.args[0]


def highlighted(qtbot, window):
    return run_js(qtbot, window.editor, "Blockly.getMainWorkspace().getAllBlocks(false)"
                                        ".filter(b => b.getSvgRoot().classList.contains('blocklyHighlighted'))"
                                        ".map(b => b.id)")


def current_block(window):
    """The block the running program is at (as the program's thread last said; None before it started)."""
    thread = window.runs.thread
    return thread.runner.hooks.current_block if thread is not None else None


def tablet_dialogs(window):
    return [dialog for dialog in window.findChildren(TabletDialog) if dialog.isVisible()]


def test_run_moves_the_simulated_robot_and_reports_the_end(qtbot, window):
    load(qtbot, window, stack(block("hobbit_emo", {"emotion": "HAPPY"}, id="emo"),
                              block("hobbit_head", {"head_position": "up_left"}, id="head"),
                              block("hobbit_move", {"direction": "+"}, {"speed": number(0.5)}, id="drive"),
                              block("text_print", inputs={"TEXT": text("done")}, id="print")))
    with qtbot.waitSignal(window.runs.sig_finished, timeout=20000) as blocker:
        assert window.runs.run()
        assert window.run_toolbar.stop_action.isEnabled() and not window.run_toolbar.run_action.isEnabled()
    assert blocker.args[0].outcome == "finished"
    snapshot = window.robot().snapshot()
    assert (snapshot["emotion"], snapshot["head"]) == ("HAPPY", "up_left")
    assert snapshot["x"] == pytest.approx(0.5, abs=0.03)
    assert window.console.lines()[-2:] == ["done", "Program finished"]
    assert window.run_toolbar.run_action.isEnabled() and not window.run_toolbar.stop_action.isEnabled()


def test_variables_read_as_people_write_them_and_go_with_their_program(qtbot, window):
    load(qtbot, window, stack(
        block("variables_set", {"VAR": {"id": "name"}}, {"VALUE": text("Mia")}),
        block("variables_set", {"VAR": {"id": "things"}},
              {"VALUE": block("lists_create_with", inputs={"ADD0": number(1), "ADD1": text("cup")},
                              extraState={"itemCount": 2})})), variables=["name", "things"])
    with qtbot.waitSignal(window.runs.sig_finished, timeout=20000):
        window.runs.run()
    qtbot.waitUntil(lambda: window.variables.values().get("name") == "“Mia”", timeout=5000)
    assert window.variables.values()["things"] == "[1, “cup”]"
    window.files.new(ask=False)
    assert window.variables.values() == {} and window.variables.table.rowCount() == 0


def test_stepping_highlights_each_block_exactly_and_shows_variables(qtbot, window):
    load(qtbot, window, stack(block("variables_set", {"VAR": {"id": "score"}}, {"VALUE": number(7)}, id="set"),
                              block("hobbit_emo", {"emotion": "SAD"}, id="emo")), variables=["score"])
    window.runs.step()
    qtbot.waitUntil(lambda: window.runs.state == "paused", timeout=10000)
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == ["set"], timeout=5000)
    assert window.variables.values() == {"score": "–"}
    window.runs.step()
    qtbot.waitUntil(lambda: window.runs.state == "paused" and highlighted(qtbot, window) == ["emo"], timeout=10000)
    assert window.variables.values() == {"score": "7"}
    assert window.run_toolbar.continue_action.isEnabled()
    with qtbot.waitSignal(window.runs.sig_finished, timeout=10000):
        window.runs.resume()
    assert window.robot().snapshot()["emotion"] == "SAD"
    assert highlighted(qtbot, window) == []


def test_a_breakpoint_set_from_the_block_menu_pauses_there_and_is_saved(qtbot, window, tmp_path):
    load(qtbot, window, stack(block("hobbit_head", {"head_position": "up_center"}, id="first"),
                              block("hobbit_head", {"head_position": "down_center"}, id="second")))
    with qtbot.waitSignal(window.editor.sig_breakpoints, timeout=5000):
        run_js(qtbot, window.editor, "Blockly.ContextMenuRegistry.registry.getItem('rocklyBreakpoint')"
                                     ".callback({block: Blockly.getMainWorkspace().getBlockById('second')})")
    assert window.document.breakpoints == ["second"]
    assert run_js(qtbot, window.editor, "Blockly.getMainWorkspace().getBlockById('second').getSvgRoot()"
                                        ".classList.contains('rocklyBreakpoint')")
    window.runs.run()
    qtbot.waitUntil(lambda: window.runs.state == "paused", timeout=10000)
    assert window.robot().snapshot()["head"] == "up_center"
    assert highlighted(qtbot, window) == ["second"]
    with qtbot.waitSignal(window.runs.sig_finished, timeout=10000):
        window.runs.resume()
    assert window.robot().snapshot()["head"] == "down_center"
    path = tmp_path / "with-breakpoint.rockly"
    assert completed(qtbot, window.files.save_as, str(path))
    assert '"breakpoints": [\n  "second"\n ]' in path.read_text()


def test_an_error_marks_its_block_with_a_plain_message_and_the_traceback_one_click_away(qtbot, window):
    load(qtbot, window, stack(block("variables_set", {"VAR": {"id": "x"}}, {"VALUE": block(
        "math_arithmetic", {"OP": "DIVIDE"}, {"A": number(1), "B": number(0)})}, id="divide"),
        block("hobbit_sos", id="never")), variables=["x"])
    window.runs.run()
    result = finished(qtbot, window)
    assert (result.outcome, result.block_id) == ("error", "divide")
    boxes = [box for box in window.findChildren(QMessageBox) if box.objectName() == "run_error_box" and box.isVisible()]
    assert boxes and boxes[0].text() == "Dividing by zero is not possible."
    assert "ZeroDivisionError" in boxes[0].detailedText()
    marked = ("Blockly.getMainWorkspace().getBlockById('divide')"
              ".getSvgRoot().classList.contains('rocklyError')")
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, marked), timeout=5000)
    assert window.console.lines()[-1] == "Dividing by zero is not possible."
    assert window.robot().snapshot()["notices"] == []


def test_an_error_mark_is_not_the_running_glow_and_goes_when_its_block_is_edited(qtbot, window):
    load(qtbot, window, block("variables_set", {"VAR": {"id": "x"}}, {"VALUE": block(
        "math_arithmetic", {"OP": "DIVIDE"}, {"A": number(1), "B": number(0)})}, id="divide"), variables=["x"])
    window.runs.run()
    assert finished(qtbot, window).outcome == "error"
    marks = ("(() => { const b = Blockly.getMainWorkspace().getBlockById('divide'); const root = b.getSvgRoot();"
             " return [root.classList.contains('rocklyError'), b.isSelected ? b.isSelected() : false,"
             " b.hasIcon(Blockly.icons.IconType.WARNING)]; })()")
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, marks)[0], timeout=5000)
    assert run_js(qtbot, window.editor, marks) == [True, False, True]  # red, not the selection's yellow

    run_js(qtbot, window.editor, "Blockly.getMainWorkspace().getBlockById('divide').setFieldValue("
                                 "Blockly.getMainWorkspace().getVariableMap().createVariable('y').getId(), 'VAR')")

    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, marks) == [False, False, False], timeout=5000)


def test_tablet_questions_appear_as_dialogs_with_the_exact_text(qtbot, window):
    question = 'Do you like "tea"?\nSay \'yes\' \\ 🍵'
    load(qtbot, window, block("controls_if", id="if", inputs={
        "IF0": block("hobbit_yes_no", {"yes_no": "D_YES"}, {"text": text(question)}),
        "DO0": block("hobbit_emo", {"emotion": "VHAPPY"})}))
    window.runs.run()
    qtbot.waitUntil(lambda: bool(tablet_dialogs(window)), timeout=10000)
    dialog = tablet_dialogs(window)[0]
    assert dialog.label.text() == question
    with qtbot.waitSignal(window.runs.sig_finished, timeout=10000):
        dialog._answer("yes")
    assert window.robot().snapshot()["emotion"] == "VHAPPY"


@pytest.mark.parametrize(("name", "program"), [
    ("sleep", block("hobbit_wait", inputs={"seconds": number(600)})),
    ("drive", block("hobbit_move", {"direction": "+"}, {"speed": number(100)})),
    ("arm", block("hobbit_arm_move", {"movement": "MoveToCandle"})),
    ("dialog", block("hobbit_show_info_confirm", inputs={"text": text("wait for me")})),
    ("tight loop", block("controls_whileUntil", {"MODE": "WHILE"}, {"BOOL": block("logic_boolean", {"BOOL": "TRUE"})})),
])
def test_stop_ends_the_run_anywhere_and_the_robot_stops(qtbot, driver, name, program):
    window = driver.open_window(simulator_speed=1.0)
    load(qtbot, window, program)
    window.runs.run()
    under_way = {"drive": lambda: window.robot().snapshot()["motion"] == "moving",
                 "arm": lambda: window.robot().snapshot()["arm_progress"] > 0,
                 "dialog": lambda: bool(tablet_dialogs(window))}
    # the program got into its wait / motion / dialog / loop (a wait or a loop starts as its block does)
    qtbot.waitUntil(under_way.get(name, lambda: current_block(window) is not None), timeout=10000)
    assert window.runs.state == "running", window.runs.last_result
    with qtbot.waitSignal(window.runs.sig_finished, timeout=5000) as blocker:
        qtbot.keyClick(QApplication.activeWindow() or window, Qt.Key.Key_Escape)  # Esc where the person is
    assert blocker.args[0].outcome == "stopped", blocker.args[0]
    snapshot = window.robot().snapshot()
    assert snapshot["linear"] == 0 and snapshot["angular"] == 0 and snapshot["motion"] == "idle"
    assert tablet_dialogs(window) == []
    assert window.console.lines()[-1] == "Program stopped"


def test_closing_the_window_stops_a_running_program(qtbot, driver):
    window = driver.open_window()
    load(qtbot, window, block("hobbit_move", {"direction": "+"}, {"speed": number(100)}))
    window.runs.run()
    qtbot.waitUntil(lambda: window.robot().snapshot()["motion"] == "moving", timeout=5000)
    robot = window.robot()
    window.document.modified = False
    assert window.close()
    assert window.runs.thread is None
    assert robot.snapshot()["linear"] == 0


def test_slow_motion_slider_delays_every_block(qtbot, window):
    # The program's waits (the delay too) run in its own process: what the window sees is each block in turn,
    # where at full speed three blocks pass between two of the window's looks.
    load(qtbot, window, stack(*(block("hobbit_emo", {"emotion": "NEUTRAL"}, id=f"emo{n}") for n in range(3))))
    window.run_toolbar.speed.setValue(window.run_toolbar.speed.maximum() - 1)
    assert window.run_toolbar.delay == pytest.approx(0.2)
    window.runs.run()
    seen = []

    def look():
        block_id = current_block(window)
        if block_id is not None and block_id not in seen:
            seen.append(block_id)
        return window.runs.state == "idle"
    qtbot.waitUntil(look, timeout=10000)
    assert window.runs.last_result.outcome == "finished"
    assert seen == ["emo0", "emo1", "emo2"]


def test_the_stop_button_works_while_the_tablet_waits_for_an_answer(qtbot, window):
    question = block("hobbit_user_input", inputs={"text": text("Name?")})
    load(qtbot, window, block("text_print", inputs={"TEXT": question}))
    window.runs.run()
    qtbot.waitUntil(lambda: bool(tablet_dialogs(window)), timeout=10000)
    stop_button = window.run_toolbar.widgetForAction(window.run_toolbar.stop_action)
    assert stop_button.isEnabled() and not tablet_dialogs(window)[0].isModal()
    with qtbot.waitSignal(window.runs.sig_finished, timeout=5000) as blocker:
        click_stop(window)  # as the window system delivers a click: a modal dialog would block it
    assert blocker.args[0].outcome == "stopped"
    qtbot.waitUntil(lambda: tablet_dialogs(window) == [], timeout=2000)


def test_pause_halts_a_drive_at_once_and_continue_drives_the_rest(qtbot, driver):
    window = driver.open_window(simulator_speed=2.0)
    load(qtbot, window, stack(block("hobbit_move", {"direction": "+"}, {"speed": number(1)}, id="drive"),
                              block("hobbit_emo", {"emotion": "HAPPY"}, id="after")))
    window.runs.run()
    qtbot.waitUntil(lambda: window.robot().snapshot()["x"] > 0.2, timeout=10000)
    window.runs.pause()
    qtbot.waitUntil(lambda: window.runs.state == "paused", timeout=5000)
    qtbot.waitUntil(lambda: window.robot().snapshot()["motion"] == "idle", timeout=5000)
    halted_at = window.robot().snapshot()["x"]
    assert 0.2 < halted_at < 0.95
    assert highlighted(qtbot, window) == ["drive"]
    paused_at = window.robot().snapshot()["time"]
    qtbot.waitUntil(lambda: window.robot().snapshot()["time"] > paused_at + 0.6, timeout=5000)  # simulated time runs
    assert window.robot().snapshot()["x"] == pytest.approx(halted_at, abs=0.005)  # and it stays put while paused
    with qtbot.waitSignal(window.runs.sig_finished, timeout=20000):
        window.runs.resume()
    final = window.robot().snapshot()
    assert final["x"] == pytest.approx(1.0, abs=0.02) and final["emotion"] == "HAPPY"


def test_run_on_an_empty_workspace_says_what_to_do(qtbot, window):
    assert window.runs.run()
    qtbot.waitUntil(lambda: window.runs.state == "idle", timeout=10000)
    assert window.runs.thread is None
    assert window.console.lines()[-1].startswith("There is nothing to run yet: drag blocks")


def test_loose_statement_stacks_all_run_and_a_loose_value_is_skipped(qtbot, window):
    load(qtbot, window,
         block("text_print", inputs={"TEXT": text("first stack")}, x=20, y=20),
         block("math_arithmetic", {"OP": "DIVIDE"}, {"A": number(1), "B": number(0)}, id="loose", x=400, y=20),
         stack(block("hobbit_emo", {"emotion": "HAPPY"}, x=20, y=300),
               block("text_print", inputs={"TEXT": text("second stack")})))

    window.runs.run()

    assert finished(qtbot, window).outcome == "finished"
    assert window.console.lines()[-3:] == ["first stack", "second stack", "Program finished"]
    assert window.robot().snapshot()["emotion"] == "HAPPY"
