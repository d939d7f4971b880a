"""The window in German: Qt's own buttons, run errors, the ROS connection failure, state panels, toolbox texts."""
from page_tools import call_page, run_js
from program_builder import block, number, stack, text, workspace
from PySide6.QtCore import QTimer
from PySide6.QtWidgets import QMessageBox
from window_tools import modal_dialog

from rockly_desktop.core.state_store import StateStore
from rockly_desktop.robot.links import link_kind
from rockly_desktop.robot.ros1.connection import RosUnavailable
from rockly_desktop.settings.app_settings import AppSettings
from rockly_desktop.ui.docks.state_panels import StatePanels, number_format
from rockly_desktop.ui.message_boxes import plain_message_box, title_width
from rockly_desktop.ui.qt_language import translations_folder, use_language
from rockly_desktop.ui.robot.connection_dialog import ConnectionDialog
from rockly_desktop.ui.texts import robot_problem, tr

SAVE_BUTTONS = QMessageBox.StandardButton.Save | QMessageBox.StandardButton.Discard | QMessageBox.StandardButton.Cancel


def button_texts(box) -> list:
    return sorted(button.text() for button in box.buttons())


def new_box_buttons(qtbot) -> list:
    box = plain_message_box(None, QMessageBox.Icon.Warning, "t", "x", SAVE_BUTTONS)
    qtbot.addWidget(box)
    box.setDetailedText("details")
    return button_texts(box)


def answer_save_prompt(window) -> list:
    """Ask the window's real 'save changes?' question, note its buttons and cancel it."""
    seen = []

    def cancel():
        box = modal_dialog()
        seen.extend(button_texts(box))
        box.button(QMessageBox.StandardButton.Cancel).click()

    window.document.mark_modified()
    QTimer.singleShot(0, cancel)
    outcomes = []
    window.files.maybe_save(then=outcomes.append)
    assert outcomes == [False]
    return seen


# --- Qt's own texts ---------------------------------------------------------------------------


def test_qts_translations_ship_with_pyside6():
    from pathlib import Path

    assert (Path(translations_folder()) / "qtbase_de.qm").is_file()


def test_qts_buttons_are_german_in_a_window_started_in_german(qtbot, german_window):
    assert answer_save_prompt(german_window) == ["Abbrechen", "Speichern", "Verwerfen"]
    assert "Details einblenden..." in new_box_buttons(qtbot)


def test_qts_buttons_follow_a_language_switch(qtbot, window):
    assert answer_save_prompt(window) == ["Cancel", "Discard", "Save"]
    with qtbot.waitSignal(window.editor.sig_ready, timeout=30000):
        window.set_language("de")
    assert answer_save_prompt(window) == ["Abbrechen", "Speichern", "Verwerfen"]
    with qtbot.waitSignal(window.editor.sig_ready, timeout=30000):
        window.set_language("en")
    assert answer_save_prompt(window) == ["Cancel", "Discard", "Save"]
    assert "Show Details..." in new_box_buttons(qtbot)


def test_english_needs_no_translation_file(qtbot):
    assert use_language("de") and use_language("en")
    assert new_box_buttons(qtbot) == ["Cancel", "Discard", "Save", "Show Details..."]


# --- one owner ---------------------------------------------------------------------------------


def spoken(window) -> set:
    """The languages the window and its helpers would speak in now."""
    return {window.language, window.settings.language, window.replay.language, window.replay_bar.language}


def test_the_window_and_its_helpers_speak_the_one_language_its_settings_own(qtbot, driver, window):
    """No copy to fall behind: another Rockly on the same settings file switching to German leaves this
    window and its helpers English; this window's own switch moves them all, the health light included."""
    other = AppSettings(driver.settings_path)
    other.language = "de"
    other.sync()
    window.settings.sync()
    assert spoken(window) == {"en"}
    with qtbot.waitSignal(window.editor.sig_ready, timeout=30000):
        window.set_language("de")
    assert spoken(window) == {"de"}
    qtbot.waitUntil(lambda: tr("health_title", "de") in window.health.toolTip(), timeout=5000)


# --- a run's error ----------------------------------------------------------------------------


def test_a_run_error_is_explained_in_german_naming_the_variable(qtbot, german_window):
    window = german_window
    ws = workspace(stack(
        block("variables_set", {"VAR": {"id": "name"}}, {"VALUE": text("Anna")}, id="set"),
        block("text_print", inputs={"TEXT": block("math_arithmetic", {"OP": "ADD"}, {
            "A": block("variables_get", {"VAR": {"id": "name"}}), "B": number(7)})}, id="print"),
        block("hobbit_sos", id="never")))
    ws["variables"] = [{"name": "name", "id": "name"}]
    call_page(qtbot, window.editor, "load", {"workspace": ws})
    with qtbot.waitSignal(window.runs.sig_finished, timeout=20000) as blocker:
        window.runs.run()
    result = blocker.args[0]
    expected = ("Ein Text und eine Zahl können nicht addiert werden („name“ ist 'Anna'); "
                "verbinde sie mit „erstelle Text aus“.")
    assert (result.outcome, result.block_id, result.message) == ("error", "print", expected)
    boxes = [box for box in window.findChildren(QMessageBox) if box.objectName() == "run_error_box" and box.isVisible()]
    assert boxes and boxes[0].text() == expected
    assert boxes[0].windowTitle() == "Etwas ist schiefgegangen"
    assert boxes[0].width() >= title_width("Etwas ist schiefgegangen", boxes[0].font())   # the whole title shows
    assert "Details einblenden..." in button_texts(boxes[0])
    assert "TypeError: can only concatenate str" in boxes[0].detailedText()  # the Python, for the adults
    assert window.console.lines()[-1] == expected
    marked = ("Blockly.getMainWorkspace().getBlockById('print')"
              ".getSvgRoot().classList.contains('rocklyError')")
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, marked), timeout=5000)


GERMAN_DISTANCE_ERROR = "Das konnte der Roboter nicht tun: Die Strecke muss eine Zahl sein, nicht 'ten'"


def run_the_distance_ten(qtbot, window):
    """Run a HOBBIT drive whose distance is the text 'ten'; the run's result."""
    ws = workspace(stack(
        block("variables_set", {"VAR": {"id": "d"}}, {"VALUE": text("ten")}, id="set"),
        block("hobbit_move", {"direction": "+"}, {"speed": block("variables_get", {"VAR": {"id": "d"}})}, id="drive")))
    ws["variables"] = [{"name": "Strecke", "id": "d"}]
    call_page(qtbot, window.editor, "load", {"workspace": ws})
    with qtbot.waitSignal(window.runs.sig_finished, timeout=20000) as blocker:
        window.runs.run()
    return blocker.args[0]


def test_a_profiles_command_error_is_all_german_in_a_german_window(qtbot, german_window):
    result = run_the_distance_ten(qtbot, german_window)
    assert (result.outcome, result.block_id, result.message) == ("error", "drive", GERMAN_DISTANCE_ERROR)
    boxes = [box for box in german_window.findChildren(QMessageBox)
             if box.objectName() == "run_error_box" and box.isVisible()]
    marked = "Der Block, den HOBBIT gerade ausgeführt hat, ist rot markiert."
    assert boxes and (boxes[0].windowTitle(), boxes[0].text()) == (  # what the robot says, not "Etwas ist schief…"
        "Nachricht von HOBBIT", f"{GERMAN_DISTANCE_ERROR}\n\n{marked}")


# --- the ROS connection -----------------------------------------------------------------------


def test_an_unreachable_master_is_explained_in_german_with_a_next_step(qtbot, german_window, monkeypatch):
    window = german_window
    window.settings.remember_link_connection(link_kind("ros1"), "hobbit", {"master": "http://127.0.0.1:9"})
    monkeypatch.setattr(ConnectionDialog, "exec", lambda dialog: 1)
    shown = []
    monkeypatch.setattr(QMessageBox, "exec",
                        lambda box: shown.append((box.windowTitle(), box.text(), box.informativeText())))
    backend = window.run_toolbar.backend
    backend.setCurrentIndex(backend.findData("ros1"))
    assert window.robots.kind == "sim"
    title, problem, next_step = shown[0]
    assert title == "Keine Verbindung zum Roboter"
    # Either nothing answers there, or this process's one ROS node already uses another test's master.
    if problem.startswith("Unter"):
        assert (problem, next_step) == ("Unter http://127.0.0.1:9 antwortet kein ROS-Master.",
                                        "Läuft dort roscore? Stimmt die Adresse?")
    else:
        assert problem.startswith("Rockly ist schon mit dem ROS-Master unter ") and "http://127.0.0.1:9" in problem
        assert next_step == "Starte Rockly neu, um einen anderen ROS-Master zu nutzen."


def test_each_connection_problem_has_both_languages_and_a_next_step():
    cases = [RosUnavailable("no ROS master answers at http://robot:11311", "no_master", master="http://robot:11311"),
             RosUnavailable("ROS 1 (rospy) is not installed", "no_rospy"),
             RosUnavailable("genpy missing", "no_ros_tools"),
             RosUnavailable("already connected", "other_master", current="http://a:11311", wanted="http://b:11311")]
    for error in cases:
        english, german = robot_problem(error, "en"), robot_problem(error, "de")
        assert all(english) and all(german) and english != german, error.reason
    assert robot_problem(cases[0], "en") == ("No ROS master answers at http://robot:11311.",
                                             "Is roscore running on that computer? Is the address right?")
    assert robot_problem(ValueError("something else"), "de") == ("something else", "")


# --- state panels -----------------------------------------------------------------------------


def test_state_panels_write_numbers_the_german_way(qtbot, hobbit):
    panels = StatePanels(hobbit.state_panels, "de")
    qtbot.addWidget(panels)
    store = StateStore()
    panels.set_store(store)
    store.record("/odom", "nav_msgs/Odometry", {"pose": {"pose": {"position": {"x": 1.6, "y": -0.5},
                                                                     "orientation": {"x": 0, "y": 0,
                                                                                     "z": 0.7071068, "w": 0.7071068}}},
                                                "twist": {"twist": {"linear": {"x": 0.3}, "angular": {"z": 0.25}}}})
    store.record("/battery_state", "sensor_msgs/BatteryState", {"percentage": 0.42})
    store.record("/DiscreteMotionState", "std_msgs/String", {"data": "Idle"})
    store.record("/head/move", "std_msgs/String", {"data": "center_center"})
    panels.refresh()
    values = panels.values()
    assert (values["Position x"], values["Position y"], values["Richtung"]) == ("1,60 m", "-0,50 m", "90°")
    assert (values["Tempo"], values["Drehen"], values["Ladung"]) == ("0,30 m/s", "14 °/s", "42 %")
    assert (values["Bewegung"], values["Blick"]) == ("steht", "geradeaus")  # the robot's values, named for people


def test_numbers_follow_the_language_and_the_rest_of_a_format_stays():
    assert number_format("de").format("{:,.1f} m.a.x {}", 12345.67, "v1.2") == "12.345,7 m.a.x v1.2"
    assert number_format("en").format("{:,.1f} m.a.x {}", 12345.67, "v1.2") == "12,345.7 m.a.x v1.2"
    assert number_format("de").format("{}", 0.5) == "0,5"
    assert number_format("de").format("{}", True) == "True"


def test_panels_follow_a_run_in_german(qtbot, german_window):
    window = german_window
    call_page(qtbot, window.editor, "load", {"workspace": workspace(
        block("hobbit_move", {"direction": "+"}, {"speed": number(0.5)}))})
    with qtbot.waitSignal(window.runs.sig_finished, timeout=20000):
        window.runs.run()
    panels = window.state_dock.widget()
    qtbot.waitUntil(lambda: panels.values()["Position x"] == "0,50 m", timeout=3000)


# --- toolbox texts ----------------------------------------------------------------------------


def flyout_texts(qtbot, window, category: str) -> list:
    return run_js(qtbot, window.editor, f"""(() => {{
        const toolbox = Blockly.getMainWorkspace().getToolbox();
        toolbox.setSelectedItem(toolbox.getToolboxItems().find(i => i.getName && i.getName() === {category!r}));
        return toolbox.getFlyout().getWorkspace().getTopBlocks(true)
            .map(b => b.getInputTargetBlock('text')).filter(t => t).map(t => t.getFieldValue('TEXT')); }})()""")


def test_the_tablet_blocks_default_texts_are_german(qtbot, german_window):
    assert flyout_texts(qtbot, german_window, "Tablet") == ["Hallo!", "Bereit?", "Wollen wir spielen?", "Wie heißt du?"]
