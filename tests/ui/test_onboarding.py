"""A first visit: File → Examples, the empty canvas's hint, programs opening at their start, Help's pages."""
from pathlib import Path

import pytest
from page_tools import START_IN_VIEW, add_block_as_user, call_page, run_js
from program_builder import block, number, stack, workspace
from PySide6.QtGui import QAction
from PySide6.QtWidgets import QTextBrowser
from window_tools import completed, state

from rockly_desktop.core.paths import examples_dir
from rockly_desktop.ui.files import program_files
from rockly_desktop.ui.files.examples_menu import example_programs, readable_name
from rockly_desktop.ui.help_dialogs import HelpPage, action_shortcuts
from rockly_desktop.ui.texts import tr

HINT_SHOWN = "(() => { const hint = document.getElementById('emptyHint'); return hint && !hint.hidden; })()"
HINT_TEXT = "document.getElementById('emptyHint').textContent"


def _examples_menu_actions(window):
    window.examples_menu.fill()
    return [(action.text(), action.data()) for action in window.examples_menu.actions()]


def test_the_examples_menu_lists_every_example_of_the_robot_by_a_readable_name(window):
    shipped = sorted((examples_dir() / "hobbit").glob("*.rockly"))

    listed = _examples_menu_actions(window)

    assert sorted(path for _name, path in listed) == [str(path) for path in shipped]
    assert ("Drive a square", str(examples_dir() / "hobbit" / "drive-a-square.rockly")) in listed


def test_shared_examples_follow_the_robots_own(tmp_path):
    (tmp_path / "hobbit").mkdir()
    for name in ("hobbit/b_second.rockly", "hobbit/a-first.rockly", "for-everyone.rockly", "notes.txt"):
        (tmp_path / name).write_text("{}")

    assert [name for name, _path in example_programs("hobbit", tmp_path)] == ["A first", "B second", "For everyone"]
    assert example_programs("turtlebot", tmp_path) == [("For everyone", tmp_path / "for-everyone.rockly")]


def test_a_german_window_lists_the_german_examples_and_english_ones_where_none_are_translated():
    german = [name for name, _path in example_programs("hobbit", language="de")]
    assert german == ["Arm mit Fortschritt", "Aufräumen", "Fahre ein Quadrat"]
    assert [path.parent.parent.name for _name, path in example_programs("turtlebot", language="de")] == ["de"]
    assert example_programs("hobbit", language="fr") == example_programs("hobbit")
    assert readable_name(Path("avoid-obstacles.rockly")) == "Avoid obstacles"


def test_an_example_opens_as_an_untitled_copy_and_saving_never_touches_the_shipped_file(
        qtbot, window, tmp_path, monkeypatch):
    example = examples_dir() / "hobbit" / "drive-a-square.rockly"
    shipped = example.read_bytes()
    asked = []

    def choose_place(_parent, _title, suggestion, _filter):
        asked.append(suggestion)
        return str(tmp_path / "mine.rockly")
    monkeypatch.setattr(window.files.file_dialogs, "save_file", choose_place)

    assert completed(qtbot, window.files.open_copy, str(example), "Drive a square")
    assert (window.document.path, window.document.modified) == (None, False)
    assert "Drive a square" in window.statusBar().currentMessage()
    assert [b["type"] for b in _blocks(state(qtbot, window)["workspace"])] == ["hobbit_emo"]
    assert str(example) not in window.settings.recent_files

    assert completed(qtbot, window.files.save)

    assert len(asked) == 1 and Path(asked[0]).parent != example.parent
    assert window.document.path == str(tmp_path / "mine.rockly")
    assert (tmp_path / "mine.rockly").is_file()
    assert example.read_bytes() == shipped


def test_choosing_an_example_asks_to_save_changes_first(qtbot, window, answer_prompts):
    asked = answer_prompts(program_files.QMessageBox.StandardButton.Cancel)
    add_block_as_user(qtbot, window.editor, "hobbit_sos")
    qtbot.waitUntil(lambda: window.document.modified, timeout=5000)
    window.examples_menu.fill()
    menu = [action for action in window.examples_menu.actions() if action.data()]

    menu[0].trigger()

    assert len(asked) == 1 and window.document.modified  # cancelled: the program stays
    assert [b["type"] for b in _blocks(state(qtbot, window)["workspace"])] == ["hobbit_sos"]


def test_an_empty_canvas_says_where_blocks_go_until_there_is_a_block(qtbot, window):
    assert run_js(qtbot, window.editor, HINT_SHOWN)
    assert run_js(qtbot, window.editor, HINT_TEXT).startswith("Drag blocks from the categories on the left")
    toolbox = "Blockly.getMainWorkspace().getToolbox()"
    run_js(qtbot, window.editor, f"{toolbox}.selectItemByPosition(0)")  # a category's blocks cover the canvas
    qtbot.waitUntil(lambda: not run_js(qtbot, window.editor, HINT_SHOWN), timeout=5000)
    run_js(qtbot, window.editor, f"{toolbox}.clearSelection()")
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, HINT_SHOWN), timeout=5000)

    add_block_as_user(qtbot, window.editor, "hobbit_sos")
    qtbot.waitUntil(lambda: not run_js(qtbot, window.editor, HINT_SHOWN), timeout=5000)

    window.files.new(ask=False)
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, HINT_SHOWN), timeout=5000)
    call_page(qtbot, window.editor, "load", {"workspace": workspace(block("hobbit_sos"))})
    assert not run_js(qtbot, window.editor, HINT_SHOWN)


def test_the_hint_speaks_german_in_german(qtbot, german_window):
    assert run_js(qtbot, german_window.editor, HINT_SHOWN)
    assert run_js(qtbot, german_window.editor, HINT_TEXT).startswith("Zieh Blöcke aus den Kategorien links")


@pytest.mark.parametrize("example", ["drive-a-square", "arm-with-progress", "tidy-up"])
def test_an_opened_program_shows_its_top_left_block(qtbot, driver, example):
    window = driver.open_window()
    window.resize(1280, 800)
    assert completed(qtbot, window.files.open, str(examples_dir() / "hobbit" / f"{example}.rockly"))

    where = run_js(qtbot, window.editor, START_IN_VIEW)

    left, top, right, bottom = where["view"]
    block_left, block_top, _right, _bottom = where["block"]
    assert left <= block_left < right and top <= block_top < bottom, where


def test_a_program_far_from_the_origin_opens_at_its_start(qtbot, window):
    far = stack(block("hobbit_sos", x=3000, y=-2000), block("hobbit_wait", inputs={"seconds": number(1)}))
    call_page(qtbot, window.editor, "load", {"workspace": workspace(far, block("hobbit_stop", x=3600, y=900))})

    where = run_js(qtbot, window.editor, START_IN_VIEW)

    left, top, right, bottom = where["view"]
    assert left <= where["block"][0] < right and top <= where["block"][1] < bottom, where


def test_an_imported_first_rockly_program_opens_at_its_start(qtbot, window, tmp_path):
    path = tmp_path / "old.xml"
    path.write_text('<xml xmlns="https://developers.google.com/blockly/xml">'
                    '<block type="hobbit_sos" x="-2500" y="1800"><next><block type="hobbit_stop"/></next></block>'
                    '<block type="hobbit_stop" x="900" y="3000"/></xml>')
    assert completed(qtbot, window.files.import_xml, str(path))

    where = run_js(qtbot, window.editor, START_IN_VIEW)

    left, top, right, bottom = where["view"]
    assert left <= where["block"][0] < right and top <= where["block"][1] < bottom, where


def test_first_steps_is_a_page_inside_the_app_naming_the_real_commands(qtbot, window):
    window.findChild(QAction, "action_first_steps").trigger()
    page = window.findChild(HelpPage, "first_steps_dialog")
    qtbot.waitUntil(page.isVisible)

    text = page.findChild(QTextBrowser).toPlainText()

    assert "First steps with Rockly" in text
    assert "Click Run (F5)" in text and "STOP (Esc)" in text and "Put back (Ctrl+R)" in text
    assert "File → Examples opens" in text


def test_first_steps_in_german(qtbot, german_window):
    german_window.findChild(QAction, "action_first_steps").trigger()
    page = german_window.findChild(HelpPage, "first_steps_dialog")

    text = page.findChild(QTextBrowser).toPlainText()

    assert "Erste Schritte mit Rockly" in text and "Klick auf Start (F5)" in text
    assert page.windowTitle() == tr("first_steps_title", "de")


def test_keyboard_shortcuts_are_those_of_the_windows_actions(qtbot, window):
    window.findChild(QAction, "action_keyboard_shortcuts").trigger()
    page = window.findChild(HelpPage, "shortcuts_dialog")
    text = page.findChild(QTextBrowser).toPlainText()

    rows = dict(action_shortcuts(window))

    assert rows["Save"] == "Ctrl+S" and rows["Run"] == "F5" and rows["STOP"] == "Esc"
    assert rows["Put back"] == "Ctrl+R" and rows["Export Python"] == "Ctrl+E"
    for command, keys in rows.items():
        assert command in text and keys in text
    window.findChild(QAction, "action_save").setShortcut("Ctrl+Shift+K")  # whatever the actions say is listed
    assert dict(action_shortcuts(window))["Save"] == "Ctrl+Shift+K"


def _blocks(ws) -> list:
    return ws.get("blocks", {}).get("blocks", [])
