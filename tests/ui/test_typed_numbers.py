"""Numbers typed into a block's number field, key by key, the way the window's language writes them: in German
"2,5" is 2.5 and shows 2,5; in English "2,5" is refused (Blockly's own field read it as 25). The Python and the
saved file keep 2.5 in both."""
import json

import pytest
from number_cases import READ, REFUSED
from page_tools import call_page, run_js
from program_builder import block, number, rockly_document
from PySide6.QtCore import QPoint, Qt
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QApplication
from screenshots import screenshot
from window_tools import completed

from rockly_desktop.settings.app_settings import AppSettings

FIELD = "Blockly.getMainWorkspace().getBlockById('metres').getField('NUM')"
WORKSPACE_FOCUSED = "Blockly.getFocusManager().getFocusedTree() === Blockly.getMainWorkspace()"
OPEN_EDITOR = f"""(() => {{
    const field = {FIELD};
    if (!field.isBeingEdited_) {{
      Blockly.getFocusManager().focusNode(field.isFullBlockField() ? field.getSourceBlock() : field);
      field.showEditor();
    }}
    return document.activeElement.className === 'blocklyHtmlInput';
}})()"""


@pytest.fixture
def program(tmp_path):
    """A program that drives 1 m forward, its distance in a number block of its own (id ``metres``)."""
    path = tmp_path / "drive.rockly"
    drive = block("hobbit_move", {"direction": "+"}, {"speed": {**number(1), "id": "metres"}}, x=40, y=40)
    path.write_text(rockly_document([drive]), encoding="utf-8")
    return path


def window_in(driver, language, program, size=(1280, 800)):
    """A window in ``language`` of ``size`` with ``program`` open, its page at the editor's width."""
    settings = AppSettings(driver.settings_path)
    settings.language = language
    settings.sync()
    window = driver.open_window(program)
    window.resize(*size)
    qtbot = driver.qtbot
    qtbot.waitUntil(lambda: window.editor.python.startswith("robot.drive("), timeout=10000)
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, "window.innerWidth") == window.editor.width(), timeout=5000)
    return window


def type_into_field(qtbot, window, keys):
    """The keyboard to the blocks (Ctrl+2), the number field's editor open, ``keys`` typed where the keyboard is
    (the page's focus proxy)."""
    qtbot.waitUntil(lambda: window.activateWindow() or QApplication.activeWindow() is window, timeout=5000)
    QTest.keyClick(QApplication.focusWidget(), Qt.Key.Key_2, Qt.KeyboardModifier.ControlModifier)
    qtbot.waitUntil(lambda: QApplication.focusWidget() is window.editor.focusProxy(), timeout=5000)
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, WORKSPACE_FOCUSED), timeout=5000)
    call_page(qtbot, window.editor, "clearMarks")  # answered after every call the window sent before (focusing)
    # As Blockly's own Tab to a field does: the keyboard's focus on the field (on its block, for a block that is
    # all field), then its editor.
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, OPEN_EDITOR), timeout=10000)
    QTest.keyClicks(QApplication.focusWidget(), keys)
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, "document.activeElement.value") == keys, timeout=5000)


def press_enter(qtbot, window):
    QTest.keyClick(QApplication.focusWidget(), Qt.Key.Key_Return)
    qtbot.waitUntil(lambda: not run_js(qtbot, window.editor, f"{FIELD}.isBeingEdited_"), timeout=5000)


def note_drawn(qtbot, window) -> bool:
    """True once the window's picture shows the refusal's background (rockly.css) inside its note's corner."""
    left, top = run_js(qtbot, window.editor, "(() => { const r = document.querySelector('.rocklyNumberRefused')"
                                             ".getBoundingClientRect(); return [r.left + 3, r.top + 3]; })()")
    corner = window.editor.mapTo(window, QPoint(round(left), round(top)))
    return window.grab().toImage().pixelColor(corner).name() == "#fff3e0"


def saved_number(qtbot, window, path):
    assert completed(qtbot, window.files.save_as, str(path))
    saved = json.loads(path.read_text(encoding="utf-8"))
    return saved["workspace"]["blocks"]["blocks"][0]["inputs"]["speed"]["block"]["fields"]["NUM"]


@pytest.mark.parametrize("size", [(1280, 800), (1920, 1080)])
def test_german_2_comma_5_is_two_and_a_half_metres_and_shows_so(qtbot, driver, program, tmp_path, size):
    window = window_in(driver, "de", program, size)
    type_into_field(qtbot, window, "2,5")
    press_enter(qtbot, window)
    assert run_js(qtbot, window.editor, f"{FIELD}.getValue()") == 2.5
    assert run_js(qtbot, window.editor, f"{FIELD}.getText()") == "2,5"
    qtbot.waitUntil(lambda: window.editor.python == "robot.drive(2.5, 'forward')\n", timeout=5000)
    assert saved_number(qtbot, window, tmp_path / "saved.rockly") == 2.5
    screenshot(window, f"german-block-2-comma-5-{size[0]}")


def test_german_field_editor_starts_from_the_number_written_with_a_comma(qtbot, driver, program, tmp_path):
    program.write_text(program.read_text(encoding="utf-8").replace('"NUM": 1', '"NUM": 0.25'), encoding="utf-8")
    window = window_in(driver, "de", program)
    assert run_js(qtbot, window.editor, f"{FIELD}.getText()") == "0,25"
    run_js(qtbot, window.editor, f"{FIELD}.showEditor()")
    assert run_js(qtbot, window.editor, "document.activeElement.value") == "0,25"


@pytest.mark.parametrize("size", [(1280, 800), (1920, 1080)])
def test_english_2_comma_5_is_refused_and_the_field_keeps_its_number(qtbot, driver, program, tmp_path, size):
    window = window_in(driver, "en", program, size)
    type_into_field(qtbot, window, "2,5")
    note = "(document.querySelector('.rocklyNumberRefused') || {}).textContent"
    assert run_js(qtbot, window.editor, note) == "Not a number. Write decimals with a point, like 2.5."
    qtbot.waitUntil(lambda: note_drawn(qtbot, window), timeout=5000)  # the page draws it a frame later
    screenshot(window, f"english-2-comma-5-refused-{size[0]}")
    press_enter(qtbot, window)
    assert run_js(qtbot, window.editor, f"{FIELD}.getValue()") == 1
    assert run_js(qtbot, window.editor, "document.querySelector('.rocklyNumberRefused')") is None
    assert window.editor.python == "robot.drive(1, 'forward')\n"
    assert saved_number(qtbot, window, tmp_path / "saved.rockly") == 1


def test_english_1_comma_000_is_a_thousand(qtbot, driver, program, tmp_path):
    window = window_in(driver, "en", program)
    type_into_field(qtbot, window, "1,000")
    press_enter(qtbot, window)
    qtbot.waitUntil(lambda: window.editor.python == "robot.drive(1000, 'forward')\n", timeout=5000)
    assert saved_number(qtbot, window, tmp_path / "saved.rockly") == 1000


def test_the_page_reads_numbers_as_the_qt_side_does(qtbot, driver, program):
    """Both readers, one table (tests/number_cases.py)."""
    window = window_in(driver, "en", program)
    for language, typed, wanted in READ + [(language, typed, None) for language, typed in REFUSED]:
        read = run_js(qtbot, window.editor, f"(RocklyNumbers.setLanguage({language!r}),"
                                            f" RocklyNumbers.read({json.dumps(typed)}))")
        assert read == wanted, (language, typed)
