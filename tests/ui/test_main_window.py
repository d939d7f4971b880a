"""The main window as a person meets it: toolbox, Code dock, status, languages, memory, profiles."""
import gc
import shutil

from page_tools import toolbox_names
from program_builder import block, number, rockly_document
from PySide6.QtCore import QCoreApplication
from PySide6.QtWidgets import QLabel, QMessageBox
from window_tools import WindowDriver, error_boxes, state

import rockly_desktop.app as app
from rockly_desktop.ui.preferences.preferences import PreferencesDialog

REPO_HOBBIT = __import__("pathlib").Path(__file__).resolve().parents[2] / "profiles" / "hobbit"


def menu_titles(window) -> list:
    return [action.text() for action in window.menuBar().actions()]


def test_python_collects_garbage_again_once_the_editor_is_ready(qtbot, driver, monkeypatch):
    # The start's own objects are not collected among while it runs; afterwards collecting goes on as before.
    enabled_while_reading = []
    read_profiles = app._read_profiles
    monkeypatch.setattr(app, "_read_profiles", lambda *args: enabled_while_reading.append(gc.isenabled())
                        or read_profiles(*args))
    window = app.build_main_window(driver.settings_path)
    driver.windows.append(window)
    assert enabled_while_reading == [False]
    assert gc.isenabled() and gc.get_freeze_count() > 0
    window.show()
    with qtbot.waitSignal(window.editor.sig_ready, timeout=30000):
        window.start()
    assert gc.isenabled() and gc.get_freeze_count() == 0


def test_a_window_started_before_it_shows_opens_its_program_and_asks_once_it_is_shown(qtbot, tmp_path, monkeypatch):
    # run_gui's order: the program goes to the page first; what the start found is asked in the shown window.
    extra = tmp_path / "profiles"
    shutil.copytree(REPO_HOBBIT, extra / "broken", ignore=shutil.ignore_patterns("__pycache__"))
    manifest = extra / "broken" / "profile.yaml"
    manifest.write_text(manifest.read_text().replace("id: hobbit", "id: broken").replace("blocks.yaml", "no.yaml"))
    program = tmp_path / "drive.rockly"
    program.write_text(rockly_document([block("hobbit_move", {"direction": "+"}, {"speed": number(2)})]))
    window_shown_when_asked = []
    monkeypatch.setattr(QMessageBox, "open", lambda box: window_shown_when_asked.append(box.parent().isVisible())
                        or QMessageBox.show(box))
    driver = WindowDriver(qtbot, tmp_path / "settings.ini", [extra])
    try:
        window = app.build_main_window(driver.settings_path, [extra])
        driver.windows.append(window)
        with qtbot.waitSignal(window.editor.sig_ready, timeout=30000):
            window.start(str(program))
            window.show()
        assert window.editor.python == "robot.drive(2, 'forward')\n"
        qtbot.waitUntil(lambda: window_shown_when_asked == [True], timeout=5000)
    finally:
        driver.close_all()


def test_window_shows_hobbit_toolbox_code_dock_and_robot(qtbot, window):
    assert toolbox_names(qtbot, window.editor)[:4] == ["Drive", "Head", "Arm", "Tablet"]
    assert window.code_dock.isVisible() and window.code_dock.windowTitle() == "Python code"
    assert window.profile_label.text() == "Robot: HOBBIT"
    assert menu_titles(window) == ["&File", "&Edit", "&Robot", "&View", "&Tools", "&Settings", "&Help"]


def toolbar_labels(window) -> list:
    return [label.text().strip() for label in window.run_toolbar.findChildren(QLabel)]


def test_the_robot_menu_and_the_run_on_box_have_distinct_names_in_both_languages(qtbot, window):
    for language, menu, box in (("en", "&Robot", "Run on:"), ("de", "&Roboter", "Läuft auf:")):
        if language == "de":
            with qtbot.waitSignal(window.editor.sig_ready, timeout=30000):
                window.set_language("de")
        assert menu in menu_titles(window) and box in toolbar_labels(window)
        assert not any(label.startswith(menu.strip("&")) for label in toolbar_labels(window))
        assert window.run_toolbar.backend.toolTip()


def test_switching_to_german_translates_window_and_blocks_and_keeps_the_program(qtbot, window, tmp_path):
    path = tmp_path / "p.rockly"
    path.write_text(rockly_document([block("hobbit_move", {"direction": "+"}, {"speed": number(2)})]))
    with qtbot.waitSignal(window.document.sig_changed):
        window.files.open(str(path))
    qtbot.waitUntil(lambda: window.code_dock.view.toPlainText() == "robot.drive(2, 'forward')\n")
    before = state(qtbot, window)["workspace"]

    with qtbot.waitSignal(window.editor.sig_ready, timeout=30000):
        window.set_language("de")
    qtbot.waitUntil(lambda: state(qtbot, window)["workspace"] == before, timeout=10000)
    assert toolbox_names(qtbot, window.editor)[:4] == ["Fahren", "Kopf", "Arm", "Tablet"]
    assert menu_titles(window) == ["&Datei", "&Bearbeiten", "&Roboter", "&Ansicht", "&Werkzeuge", "&Einstellungen",
                                   "&Hilfe"]
    assert window.code_dock.windowTitle() == "Python-Code"
    assert window.profile_label.text() == "Roboter: HOBBIT"
    assert not window.isWindowModified()
    assert window.settings.language == "de"


def test_preferences_dialog_offers_english_and_german(qtbot):
    dialog = PreferencesDialog("de")
    qtbot.addWidget(dialog)
    assert dialog.windowTitle() == "Einstellungen"
    assert [dialog.language_box.itemText(i) for i in range(dialog.language_box.count())] == ["English", "Deutsch"]
    assert dialog.language == "de"
    dialog.language_box.setCurrentIndex(0)
    assert dialog.language == "en"


def test_language_layout_and_last_file_are_remembered(qtbot, driver, tmp_path):
    path = tmp_path / "remember-me.rockly"
    path.write_text(rockly_document([block("hobbit_sos")]))
    first = driver.open_window()
    with qtbot.waitSignal(first.document.sig_changed):
        first.files.open(str(path))
    with qtbot.waitSignal(first.editor.sig_ready, timeout=30000):
        first.set_language("de")
    first.resize(760, 580)
    first.code_dock.hide()
    first.close()

    second = WindowDriver(qtbot, driver.settings_path)
    try:
        window = second.open_window()
        qtbot.waitUntil(lambda: window.document.path == str(path), timeout=10000)
        assert window.language == "de"
        assert (window.width(), window.height()) == (760, 580)
        assert not window.code_dock.isVisible()
        assert window.settings.recent_files[0] == str(path)
        qtbot.waitUntil(lambda: window.code_dock.view.toPlainText() == "robot.call_sos()\n", timeout=10000)
    finally:
        second.close_all()


def test_a_remembered_file_that_is_gone_does_not_stop_the_start(qtbot, driver, tmp_path):
    gone = tmp_path / "deleted.rockly"
    gone.write_text(rockly_document([block("hobbit_sos")]))
    window = driver.open_window(str(gone))
    qtbot.waitUntil(lambda: window.document.path == str(gone), timeout=10000)
    window.close()
    gone.unlink()
    again = driver.open_window()
    qtbot.waitUntil(lambda: bool(error_boxes(again)), timeout=10000)
    assert "does not exist" in error_boxes(again)[0]
    assert again.document.path is None and state(qtbot, again)["python"] == ""


def test_a_broken_profile_is_reported_and_the_app_still_starts(qtbot, tmp_path):
    extra = tmp_path / "profiles"
    broken = extra / "broken"
    shutil.copytree(REPO_HOBBIT, broken, ignore=shutil.ignore_patterns("__pycache__"))
    manifest = broken / "profile.yaml"
    manifest.write_text(manifest.read_text().replace("id: hobbit", "id: broken")
                        .replace("blocks: blocks.yaml", "blocks: nowhere.yaml"))
    driver = WindowDriver(qtbot, tmp_path / "settings.ini", [extra])
    try:
        window = driver.open_window()
        boxes = [box for box in window.findChildren(QMessageBox) if box.objectName() == "profile_errors_box"]
        assert len(boxes) == 1
        assert str(manifest) in boxes[0].text() and "blocks" in boxes[0].text() and "nowhere.yaml" in boxes[0].text()
        assert toolbox_names(qtbot, window.editor)[0] == "Drive"
        assert "hobbit" in window.registry.profiles and "broken" not in window.registry.profiles
    finally:
        driver.close_all()


def test_closing_with_unsaved_changes_asks_first(qtbot, window, answer_prompts):
    window.document.mark_modified()
    asked = answer_prompts(QMessageBox.StandardButton.Cancel)
    assert not window.close()
    assert window.isVisible() and asked
    answer_prompts(QMessageBox.StandardButton.Discard)
    assert window.close()
    QCoreApplication.processEvents()

