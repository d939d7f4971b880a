"""The block maker's dialog as a person meets it (issue 29, items 13 and 14): it fits a 1280×800 screen with
its buttons, Enter in the preview block's field only ends the typing, and the Python follows what was typed."""
import json
import os
import subprocess
import sys

import pytest
from page_tools import run_js
from PySide6.QtCore import QPoint, Qt
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QDialog
from test_block_maker import drawn_preview, make_mmui_block, open_maker
from window_tools import one_screen_platform

FITTED_MAKER = """
import json, sys
from PySide6.QtWidgets import QApplication
app = QApplication([])
from rockly_desktop.profiles.registry import ProfileRegistry
from rockly_desktop.ui.blockmaker.maker_dialog import BlockMakerDialog
from rockly_desktop.ui.blockmaker.offers import known_offers
profile = ProfileRegistry.discover().get("hobbit")
maker = BlockMakerDialog(profile, sys.argv[1], known_offers(profile))
maker.choose_named("/MMUI")  # the fields table shown: the maker at its fullest
maker.show()
for _ in range(20):
    app.processEvents()
def rect(widget):
    corner = widget.mapToGlobal(widget.rect().topLeft())
    return [corner.x(), corner.y(), widget.width(), widget.height()]
buttons = [maker.save_button, maker.try_button, maker.buttons.button(maker.buttons.StandardButton.Close)]
print(json.dumps({"area": maker.screen().availableGeometry().getRect(), "frame": maker.frameGeometry().getRect(),
                  "buttons": [rect(button) for button in buttons], "shown": [b.isVisible() for b in buttons]}))
"""


def inside(inner, outer) -> bool:
    x, y, w, h = inner
    ox, oy, ow, oh = outer
    return ox <= x and oy <= y and x + w <= ox + ow and y + h <= oy + oh


@pytest.mark.parametrize("size", [(1280, 800), (1920, 1080)])
@pytest.mark.parametrize("language", ["en", "de"])
def test_the_maker_with_its_frame_and_buttons_fits_the_screen(tmp_path, size, language):
    script = tmp_path / "maker.py"
    script.write_text(FITTED_MAKER)
    env = dict(os.environ, QT_QPA_PLATFORM=one_screen_platform(tmp_path, *size), QTWEBENGINE_DISABLE_SANDBOX="1",
               XDG_CONFIG_HOME=str(tmp_path / "config"), XDG_DATA_HOME=str(tmp_path / "data"))
    done = subprocess.run([sys.executable, str(script), language], env=env, timeout=120, capture_output=True,
                          text=True, check=True)
    shown = json.loads(done.stdout.strip().splitlines()[-1])
    assert inside(shown["frame"], shown["area"]), shown
    assert all(shown["shown"]) and all(inside(button, shown["area"]) for button in shown["buttons"]), shown


def preview_field_centre(qtbot, maker, input_name: str) -> QPoint:
    """Where the preview page draws the field of the shadow block in ``input_name`` (in the view's pixels)."""
    x, y = run_js(qtbot, maker.preview, f"""(() => {{
        const block = Blockly.getMainWorkspace().getTopBlocks(false)[0];
        const shadow = block.getInput({input_name!r}).connection.targetBlock();
        const box = shadow.inputList[0].fieldRow.find((field) => field.EDITABLE).getSvgRoot().getBoundingClientRect();
        return [box.left + box.width / 2, box.top + box.height / 2]; }})()""")
    return QPoint(round(x), round(y))


def type_into_preview_field(qtbot, maker, input_name: str, text: str):
    """Click the preview block's field as a person does, type ``text`` over it and press Enter."""
    page = maker.preview.focusProxy()
    spot = preview_field_centre(qtbot, maker, input_name)
    QTest.mouseMove(page, spot)
    QTest.mousePress(page, Qt.MouseButton.LeftButton, pos=spot)
    QTest.mouseRelease(page, Qt.MouseButton.LeftButton, pos=spot)
    qtbot.waitUntil(lambda: run_js(qtbot, maker.preview, "Blockly.WidgetDiv.isVisible()"), timeout=5000)
    QTest.keyClick(page, Qt.Key.Key_A, Qt.KeyboardModifier.ControlModifier)
    QTest.keyClicks(page, text)
    QTest.keyClick(page, Qt.Key.Key_Return)


def test_enter_in_the_preview_blocks_field_ends_the_typing_and_keeps_the_maker_open(qtbot, window):
    maker = open_maker(qtbot, window)
    make_mmui_block(qtbot, maker)
    qtbot.waitUntil(lambda: (drawn_preview(qtbot, maker) or {}).get("text", "").startswith("ask"), timeout=10000)
    assert maker.save_button.isEnabled()   # Enter pressed Save and closed the maker before
    type_into_preview_field(qtbot, maker, "sessionid", "42")
    qtbot.waitUntil(lambda: not run_js(qtbot, maker.preview, "Blockly.WidgetDiv.isVisible()"), timeout=5000)
    qtbot.waitUntil(lambda: "'sessionID': '42'" in maker.python.toPlainText(), timeout=5000)
    assert maker.isVisible() and QDialog.result(maker) == 0   # ("result" is the maker's "It gives" box)
    assert "made_say" not in window.editor.known_block_types   # nothing saved


def test_the_python_shown_uses_the_value_typed_into_the_preview_block(qtbot, window):
    maker = open_maker(qtbot, window)
    make_mmui_block(qtbot, maker)
    qtbot.waitUntil(lambda: (drawn_preview(qtbot, maker) or {}).get("text", "").startswith("ask"), timeout=10000)
    assert "'sessionID': '7'" in maker.python.toPlainText()
    type_into_preview_field(qtbot, maker, "sessionid", "99")
    qtbot.waitUntil(lambda: "'sessionID': '99'" in maker.python.toPlainText(), timeout=5000)
    assert "'requestText': 'hello'" in maker.python.toPlainText()
    maker.sentence["en"].setText("ask %1 now to say %2")   # a change to the block draws it anew with its defaults
    qtbot.waitUntil(lambda: "now" in drawn_preview(qtbot, maker)["text"], timeout=10000)
    assert "'sessionID': '7'" in maker.python.toPlainText()


def tried(qtbot, maker) -> list:
    """Press Try it as a person does and wait for the maker's report of how the try ended."""
    QTest.mouseClick(maker.try_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: maker.try_report.isVisible() and "…" not in maker.try_report.toPlainText(),
                    timeout=30000)
    return maker.try_report.toPlainText().splitlines()


def test_try_it_shows_in_the_maker_what_was_sent_the_robots_answer_and_the_result(qtbot, window):
    maker = open_maker(qtbot, window)
    make_mmui_block(qtbot, maker, block_id="made_try")
    qtbot.waitUntil(lambda: (drawn_preview(qtbot, maker) or {}).get("text", "").startswith("ask"), timeout=10000)
    type_into_preview_field(qtbot, maker, "sessionid", "12")
    qtbot.waitUntil(lambda: "'sessionID': '12'" in maker.python.toPlainText(), timeout=5000)
    report = tried(qtbot, maker)
    assert report[0].startswith("Called the service /MMUI with: ") and '"sessionID": "12"' in report[0], report
    assert report[1:] == ['The robot answered: {"params": []}', "Done: the block worked."]
    assert window.robot().snapshot()["tablet"] == {"kind": "D_PLAIN", "text": "made by hand"}


@pytest.mark.parametrize("language, refused", [
    ("en", "The robot could not do this: The simulated HOBBIT does not know the emotion 'happy'. It knows: "),
    ("de", "Das konnte der Roboter nicht tun: Der simulierte HOBBIT kennt das Gefühl 'happy' nicht. Er kennt: ")])
def test_an_emotion_the_simulator_does_not_know_is_a_refusal_shown_in_the_maker(qtbot, request, language, refused):
    window = request.getfixturevalue("window" if language == "en" else "german_window")
    maker = open_maker(qtbot, window)
    assert maker.choose_named("/head/emo")
    maker.fields.set_use("data", "input", "happy")
    maker.sentence["en"].setText("eyes show %1")
    maker.sentence["de"].setText("Augen zeigen %1")
    qtbot.waitUntil(lambda: (drawn_preview(qtbot, maker) or {}).get("text", "").startswith(
        "eyes" if language == "en" else "Augen"), timeout=10000)
    report = tried(qtbot, maker)
    sent = "Sent on the topic" if language == "en" else "Auf dem Topic"
    assert report[0].startswith(sent) and '{"data": "happy"}' in report[0], report
    assert report[1].startswith(refused), report
    assert len(report) == 2, report   # the refusal is the whole story: no second line about the run
    assert window.robot().snapshot()["emotion"] == "NEUTRAL"


def test_trying_moves_the_maker_off_the_simulator_view(qtbot, window):
    maker = open_maker(qtbot, window)
    make_mmui_block(qtbot, maker)
    dock = window.simulator_dock
    seen = dock.rect().translated(dock.mapToGlobal(QPoint(0, 0)))
    assert maker.frameGeometry().intersects(seen)   # as it opens: over the simulator
    tried(qtbot, maker)
    assert not maker.frameGeometry().intersects(seen), (maker.frameGeometry(), seen)
    assert maker.save_button.isVisible() and maker.try_report.isVisible()
