"""What a child reads when a run ends with an error, in the real window on the built-in simulator:
a robot's own refusal (a bump, a part the teacher switched off) is what the robot says, whole and
wrapped, its block marked, no "Something went wrong" and no traceback; an error in the person's own
Python keeps its traceback behind Show Details, except in a kiosk."""
import pytest
from page_tools import run_js
from program_builder import block, number, rockly_document, stack
from PySide6.QtCore import QRect, Qt
from PySide6.QtWidgets import QLabel, QMessageBox
from test_running import finished, load

from rockly_desktop.app import build_main_window, start_kiosk
from rockly_desktop.settings.app_settings import AppSettings

SOFA = (block("hobbit_move", {"direction": "+"}, {"speed": number(1)}, id="ahead"),
        block("hobbit_turn", {"direction": "+"}, {"angle": number(90)}, id="left"),
        block("hobbit_move", {"direction": "+"}, {"speed": number(2)}, id="into_the_sofa"))
DIVIDE = block("variables_set", {"VAR": {"id": "x"}}, {"VALUE": block(
    "math_arithmetic", {"OP": "DIVIDE"}, {"A": number(1), "B": number(0)})}, id="divide")


def window_in(driver, language, switched_off=()):
    settings = AppSettings(driver.settings_path)
    settings.language = language
    if switched_off:
        settings.teacher.set_limits("hobbit", switched_off=switched_off)
    settings.sync()
    return driver.open_window()


def error_box(qtbot, window):
    def shown():
        return [box for box in window.findChildren(QMessageBox) if box.objectName() == "run_error_box"
                and box.isVisible()]

    qtbot.waitUntil(lambda: bool(shown()), timeout=5000)
    return shown()[0]


def text_is_whole(box) -> bool:
    """The box's text fits its label as the label draws it: no line is cut at the right or the bottom."""
    label = box.findChild(QLabel, "qt_msgbox_label")
    room = label.contentsRect()
    needed = label.fontMetrics().boundingRect(QRect(0, 0, room.width(), 100_000),
                                              int(Qt.TextFlag.TextWordWrap), label.text())
    return label.isVisible() and needed.width() <= room.width() and needed.height() <= room.height()


def has_show_details(box) -> bool:
    return bool(box.detailedText()) or any(button.text().replace("&", "").startswith(("Show Details", "Details"))
                                           for button in box.buttons())


def marked(qtbot, window, block_id):
    return run_js(qtbot, window.editor, f"Blockly.getMainWorkspace().getBlockById('{block_id}')"
                                        ".getSvgRoot().classList.contains('rocklyError')")


@pytest.mark.parametrize(("language", "title", "words"), [
    ("en", "Message from HOBBIT", "The robot could not do this: HOBBIT bumped into the sofa"),
    ("de", "Nachricht von HOBBIT", "Das konnte der Roboter nicht tun: HOBBIT ist gegen das Sofa gestoßen"),
])
def test_a_bump_is_what_the_robot_says_whole_with_its_block_marked_and_no_traceback(qtbot, driver, language, title,
                                                                                     words):
    window = window_in(driver, language)
    window.resize(1280, 800)
    load(qtbot, window, stack(*SOFA))
    window.runs.run()
    result = finished(qtbot, window, timeout=60000)
    assert (result.outcome, result.block_id, result.by_robot, result.details) == ("error", "into_the_sofa", True, None)
    assert window.robot().snapshot()["bumped"] == "sofa"
    box = error_box(qtbot, window)
    assert box.windowTitle() == title and box.icon() == QMessageBox.Icon.Information
    assert box.text().startswith(words) and "HOBBIT" in box.text().split("\n\n")[1]
    assert text_is_whole(box)
    assert not has_show_details(box)
    qtbot.waitUntil(lambda: marked(qtbot, window, "into_the_sofa"), timeout=5000)


@pytest.mark.parametrize("size", [(1280, 800), (480, 360)])
def test_a_long_german_refusal_is_whole_and_wrapped_at_any_window_size(qtbot, driver, size):
    window = window_in(driver, "de", switched_off=["arm"])
    window.resize(*size)
    load(qtbot, window, block("hobbit_arm_gripper", {"movement": "OpenGripper"}, id="grip"))
    window.runs.run()
    assert finished(qtbot, window).outcome == "error"
    box = error_box(qtbot, window)
    assert box.text().startswith("Das konnte der Roboter nicht tun: Die Lehrkraft hat „Arm und Greifer“ "
                                 "für diesen Roboter ausgeschaltet")
    assert box.findChild(QLabel, "qt_msgbox_label").wordWrap()
    assert text_is_whole(box)
    screen = box.screen().availableGeometry()
    assert box.width() <= screen.width() and box.height() <= screen.height()
    assert box.windowTitle() == "Nachricht von HOBBIT" and not has_show_details(box)


def test_an_error_in_the_persons_own_python_keeps_show_details(qtbot, driver):
    window = window_in(driver, "en")
    load(qtbot, window, DIVIDE, variables=["x"])
    window.runs.run()
    assert finished(qtbot, window).outcome == "error"
    box = error_box(qtbot, window)
    assert box.windowTitle() == "Something went wrong" and box.text() == "Dividing by zero is not possible."
    assert "ZeroDivisionError" in box.detailedText() and has_show_details(box)
    assert text_is_whole(box)


@pytest.fixture
def kiosk_window(qtbot, driver, tmp_path):
    """A kiosk window (PIN, chord and folders set) showing a start program; left at the end."""
    settings = AppSettings(driver.settings_path)
    settings.teacher.set_pin("4711")
    settings.kiosk.programs_folder, settings.kiosk.visitors_folder = tmp_path / "kiosk", tmp_path / "visitors"
    settings.kiosk.programs_folder.mkdir()
    settings.kiosk.quit_chord = "Ctrl+Alt+Shift+K"
    settings.sync()
    start = tmp_path / "start.rockly"
    start.write_text(rockly_document([block("hobbit_sos")]))
    window = build_main_window(driver.settings_path, kiosk=True)
    window.simulator_speed = 25.0
    driver.windows.append(window)
    kiosk = start_kiosk(window, start)
    with qtbot.waitSignal(window.editor.sig_ready, timeout=30000):
        window.start(start)
    yield window
    window.document.modified = False
    kiosk.leave()


def test_a_kiosk_shows_no_traceback(qtbot, kiosk_window):
    window = kiosk_window
    load(qtbot, window, DIVIDE, variables=["x"])
    window.runs.run()
    result = finished(qtbot, window)
    assert "ZeroDivisionError" in result.details  # the run knows it; the visitor is not shown it
    box = error_box(qtbot, window)
    assert box.text() == "Dividing by zero is not possible."
    assert not has_show_details(box)
