"""Teacher settings in a real window: toolbox levels on the real page, the PIN gate, remembered choices."""
from page_tools import call_page, run_js, toolbox_names
from program_builder import block, rockly_document, workspace
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QDialog
from window_tools import state

from rockly_desktop.settings.app_settings import AppSettings
from rockly_desktop.ui.preferences.preferences import PreferencesDialog

STARTER = {"hobbit_move", "hobbit_turn", "hobbit_stop", "hobbit_head", "hobbit_emo", "hobbit_show_info",
           "hobbit_wait", "controls_repeat_ext"}


def toolbox_blocks(qtbot, view) -> set:
    """The block types the page's toolbox offers (from what it was given, category by category)."""
    return set(run_js(qtbot, view, """Blockly.getMainWorkspace().getToolbox().getToolboxItems()
        .filter(item => item.getContents && Array.isArray(item.getContents()))
        .flatMap(item => item.getContents().map(entry => entry.type))"""))


def teacher_settings(driver):
    return AppSettings(driver.settings_path).teacher


def test_the_starter_level_gives_the_page_only_its_blocks_and_a_program_beyond_it_opens(qtbot, driver, tmp_path):
    teacher = teacher_settings(driver)
    teacher.set_level("hobbit", "starter")
    path = tmp_path / "arm.rockly"
    path.write_text(rockly_document([block("hobbit_arm_gripper", {"movement": "OpenGripper"})]))
    window = driver.open_window(str(path))
    assert toolbox_blocks(qtbot, window.editor) == STARTER
    assert toolbox_names(qtbot, window.editor) == ["Drive", "Head", "Tablet", "Time", "Loops"]
    qtbot.waitUntil(lambda: "robot.gripper" in state(qtbot, window)["python"], timeout=10000)


def accept_with(monkeypatch, act):
    """Make the Preferences dialog's exec do ``act(dialog)`` and then press OK."""
    def fake_exec(dialog):
        act(dialog)
        return QDialog.DialogCode.Accepted
    monkeypatch.setattr(PreferencesDialog, "exec", fake_exec)


def test_a_level_chosen_in_preferences_reloads_the_toolbox_and_keeps_the_program(qtbot, window, monkeypatch):
    full = toolbox_blocks(qtbot, window.editor)
    assert "hobbit_arm_gripper" in full and "ROS_publisher" in full
    run_js(qtbot, window.editor,
           "Blockly.serialization.blocks.append({type: 'hobbit_sos'}, Blockly.getMainWorkspace()).id")
    qtbot.waitUntil(lambda: "robot.call_sos()" in window.editor.python, timeout=10000)

    def choose_starter(dialog):
        tab = dialog.teacher_tab
        tab.pin.setText("2468")
        tab.pin_again.setText("2468")
        tab.unlock()
        assert tab.unlocked
        tab.level_box.setCurrentIndex(tab.level_box.findData("starter"))
        tab.max_speed.setValue(0.25)
        tab.capability_boxes["arm"].setChecked(False)
    accept_with(monkeypatch, choose_starter)
    window.show_preferences()
    qtbot.waitUntil(lambda: toolbox_blocks(qtbot, window.editor) == STARTER, timeout=10000)
    assert "robot.call_sos()" in state(qtbot, window)["python"]
    teacher = window.settings.teacher
    assert teacher.level("hobbit") == "starter"
    assert teacher.limits("hobbit").max_speed == 0.25 and teacher.switched_off("hobbit") == ["arm"]

    def choose_full(dialog):
        dialog.teacher_tab.pin.setText("2468")
        dialog.teacher_tab.unlock()
        dialog.teacher_tab.level_box.setCurrentIndex(dialog.teacher_tab.level_box.findData("full"))
    accept_with(monkeypatch, choose_full)
    window.show_preferences()
    expected = full - {"hobbit_arm_gripper", "hobbit_arm_move", "hobbit_arm_turntable", "hobbit_arm_joints"}
    qtbot.waitUntil(lambda: toolbox_blocks(qtbot, window.editor) == expected, timeout=10000)


def test_a_wrong_pin_leaves_the_tab_locked_and_the_settings_as_they_were(qtbot, driver, registry):
    teacher = teacher_settings(driver)
    teacher.set_pin("1357")
    dialog = PreferencesDialog("de", None, registry.get("hobbit"), teacher)
    qtbot.addWidget(dialog)
    tab = dialog.teacher_tab
    assert dialog.tabs.tabText(1) == "Lehrkraft" and tab.pin_again is None
    tab.pin.setText("1111")
    tab.unlock()
    assert not tab.unlocked and tab.problem.text() == "Falsche PIN." and tab.pin.text() == ""
    tab.level_box.setCurrentIndex(tab.level_box.findData("starter"))  # not reachable by hand, nor kept
    assert tab.apply() is False and teacher.level("hobbit") is None
    tab.pin.setText("1357")
    tab.unlock()
    assert tab.unlocked


def test_the_first_pin_must_be_long_enough_and_typed_twice_and_is_kept_only_hashed(qtbot, driver, registry):
    teacher = teacher_settings(driver)
    dialog = PreferencesDialog("en", None, registry.get("turtlebot"), teacher)
    qtbot.addWidget(dialog)
    tab = dialog.teacher_tab
    tab.pin.setText("12")
    tab.pin_again.setText("12")
    tab.unlock()
    assert not tab.unlocked and tab.problem.text() == "The PIN needs at least 4 characters."
    tab.pin.setText("123456")
    tab.pin_again.setText("123465")
    tab.unlock()
    assert not tab.unlocked and tab.problem.text() == "The two PINs differ."
    tab.pin_again.setText("123456")
    tab.unlock()
    assert tab.unlocked and not tab.capability_boxes
    teacher._store.sync()
    stored = driver.settings_path.read_text(encoding="utf-8")
    assert "123456" not in stored and "pbkdf2_sha256" in stored
    assert not teacher.try_pin("123457").right and teacher.try_pin("123456").right


def test_enter_in_the_pin_field_unlocks_and_does_not_close_the_dialog(qtbot, driver, registry):
    teacher = teacher_settings(driver)
    teacher.set_pin("9876")
    dialog = PreferencesDialog("en", None, registry.get("hobbit"), teacher)
    qtbot.addWidget(dialog)
    dialog.show()
    dialog.tabs.setCurrentIndex(1)
    tab = dialog.teacher_tab
    tab.pin.setFocus()
    qtbot.keyClicks(tab.pin, "9876")
    qtbot.keyClick(tab.pin, Qt.Key.Key_Return)
    assert tab.unlocked and dialog.isVisible() and dialog.result() == 0


def test_a_run_in_the_window_keeps_the_teachers_limits(qtbot, driver):
    teacher = teacher_settings(driver)
    teacher.set_limits("hobbit", switched_off=["arm"])
    window = driver.open_window()
    call_page(qtbot, window.editor, "load", {"workspace": workspace(
        block("hobbit_arm_gripper", {"movement": "OpenGripper"}, id="grip"))})
    with qtbot.waitSignal(window.runs.sig_finished, timeout=20000) as blocker:
        assert window.runs.run()
    result = blocker.args[0]
    assert (result.outcome, result.block_id) == ("error", "grip")
    assert result.message == "The robot could not do this: the teacher switched off “Arm and gripper” for this robot"
    assert window.robot().snapshot()["gripper"] == "closed"
