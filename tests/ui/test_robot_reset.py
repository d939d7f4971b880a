"""Putting the simulated robot back from the window: the toolbar button, the Robot menu, the preference."""
from program_builder import block, number, stack
from test_running import finished, load

from rockly_desktop.settings.app_settings import AppSettings
from rockly_desktop.ui.preferences.preferences import PreferencesDialog


def drive_away(qtbot, window, metres=0.5):
    load(qtbot, window, stack(block("hobbit_emo", {"emotion": "SAD"}, id="emo"),
                              block("hobbit_move", {"direction": "+"}, {"speed": number(metres)}, id="drive")))
    assert window.runs.run()
    return finished(qtbot, window)


def test_the_reset_button_puts_the_robot_back(qtbot, window):
    reset = window.run_toolbar.reset_action
    assert reset.isEnabled() and reset.shortcut().toString() == "Ctrl+R"
    assert reset in window.menuBar().actions()[2].menu().actions()     # the Robot menu has it too
    assert drive_away(qtbot, window).outcome == "finished"
    assert window.robot().snapshot()["x"] > 0.4
    reset.trigger()
    snapshot = window.robot().snapshot()
    assert (snapshot["x"], snapshot["y"], snapshot["theta"], snapshot["emotion"]) == (0.0, 0.0, 0.0, "NEUTRAL")
    assert window.statusBar().currentMessage() == "The robot is back where it started."


def test_reset_is_disabled_while_a_program_runs(qtbot, window):
    load(qtbot, window, stack(block("hobbit_move", {"direction": "+"}, {"speed": number(3)}, id="drive")))
    with qtbot.waitSignal(window.runs.sig_finished, timeout=20000):
        assert window.runs.run()
        qtbot.waitUntil(lambda: window.runs.state == "running", timeout=10000)
        assert not window.run_toolbar.reset_action.isEnabled()
        window.runs.stop()
    assert window.run_toolbar.reset_action.isEnabled()


def test_without_the_preference_runs_and_new_programs_leave_the_robot_where_it_is(qtbot, window):
    drive_away(qtbot, window, 0.3)
    drive_away(qtbot, window, 0.3)
    assert abs(window.robot().snapshot()["x"] - 0.6) < 0.03
    window.files.new(ask=False)
    assert abs(window.robot().snapshot()["x"] - 0.6) < 0.03    # a new program leaves the robot where it is


def test_with_the_preference_each_run_and_new_program_starts_from_the_start(qtbot, driver):
    settings = AppSettings(driver.settings_path)
    assert settings.reset_before_run is False
    settings.reset_before_run = True
    settings.sync()
    window = driver.open_window()
    drive_away(qtbot, window, 0.3)
    drive_away(qtbot, window, 0.3)
    assert abs(window.robot().snapshot()["x"] - 0.3) < 0.03
    window.files.new(ask=False)
    assert window.robot().snapshot()["x"] == 0.0


def test_the_preference_is_in_the_dialog_in_both_languages(qtbot):
    dialog = PreferencesDialog("de", reset_before_run=True)
    qtbot.addWidget(dialog)
    assert dialog.reset_box.text() == "Roboter vor jedem Start zurücksetzen" and dialog.reset_before_run
    english = PreferencesDialog("en")
    qtbot.addWidget(english)
    assert english.reset_box.text() == "Put the robot back before each Run" and not english.reset_before_run
