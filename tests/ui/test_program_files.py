"""Programs on disk through the window: open, save, round trip, bad files, import, export."""
import json
import os
import stat
import threading

import pytest
from page_tools import add_block_as_user
from program_builder import block, number, rockly_document, stack, text
from PySide6.QtWidgets import QFileDialog, QMessageBox
from window_tools import completed, error_boxes, state

from rockly_desktop.core.program import load_program
from rockly_desktop.settings.app_settings import AppSettings

PICK_UP = stack(block("hobbit_arm_gripper", {"movement": "OpenGripper"}),
                block("hobbit_arm_move", {"movement": "MoveToPreGraspFloor"}),
                block("hobbit_arm_gripper", {"movement": "CloseGripper"}))


@pytest.fixture
def pick_up_file(tmp_path):
    path = tmp_path / "pick-up.rockly"
    path.write_text(rockly_document([PICK_UP]), encoding="utf-8")
    return path


def wait_for_code(qtbot, window, expected):
    qtbot.waitUntil(lambda: window.code_dock.view.toPlainText() == expected, timeout=10000)


def open_program(qtbot, window, path, importing=False):
    """Open (or import) ``path`` and wait until the window has taken it over."""
    assert completed(qtbot, window.files.import_xml if importing else window.files.open, str(path))


def test_open_shows_blocks_and_their_python(qtbot, window, pick_up_file):
    open_program(qtbot, window, pick_up_file)
    wait_for_code(qtbot, window, "robot.gripper('open')\nrobot.move_arm('floor')\nrobot.gripper('close')\n")
    assert window.windowTitle().startswith("pick-up.rockly")
    assert not window.isWindowModified()


def test_an_edit_marks_the_program_modified_and_save_clears_it(qtbot, window, pick_up_file):
    open_program(qtbot, window, pick_up_file)
    wait_for_code(qtbot, window, "robot.gripper('open')\nrobot.move_arm('floor')\nrobot.gripper('close')\n")
    add_block_as_user(qtbot, window.editor, "hobbit_sos")
    qtbot.waitUntil(window.isWindowModified, timeout=5000)
    assert completed(qtbot, window.files.save)
    assert not window.isWindowModified()
    saved = load_program(pick_up_file)
    assert saved.profile_id == "hobbit"
    assert {b["type"] for b in saved.workspace["blocks"]["blocks"]} == {"hobbit_arm_gripper", "hobbit_sos"}


def test_save_and_open_round_trip_keeps_every_character(qtbot, driver, tmp_path):
    nasty = "say \"hi\"\nit's \\ '''\"\"\" 🤖 Grüße"
    source = tmp_path / "source.rockly"
    source.write_text(rockly_document([block("hobbit_show_info", inputs={"text": text(nasty)}, x=10, y=10)]),
                      encoding="utf-8")
    window = driver.open_window()
    open_program(qtbot, window, source)
    qtbot.waitUntil(lambda: "show_info" in window.code_dock.view.toPlainText(), timeout=10000)
    target = tmp_path / "copy.rockly"
    assert completed(qtbot, window.files.save_as, str(target))
    first = state(qtbot, window)

    reopened = driver.open_window()
    open_program(qtbot, reopened, target)
    qtbot.waitUntil(lambda: "show_info" in reopened.code_dock.view.toPlainText(), timeout=10000)
    assert state(qtbot, reopened) == first
    assert load_program(target).workspace["blocks"]["blocks"][0]["inputs"]["text"]["block"]["fields"]["TEXT"] == nasty


BAD_FILES = {
    "broken.rockly": (b'{"format": "rockly-program", "version": 1, "profile": "hobbit", "workspace": {"blo',
                      "broken JSON"),
    "empty.rockly": (b"", "empty"),
    "foreign.rockly": (b'{"name": "my-package", "version": "1.0.0"}', "not a Rockly program"),
    "list.rockly": (b"[1, 2, 3]", "not a Rockly program"),
    "newer.rockly": (b'{"format": "rockly-program", "version": 99, "profile": "hobbit", "workspace": {}}',
                     "newer Rockly"),
    "binary.rockly": (b"\x89PNG\r\n\x1a\n\x00\x00\xff\xfe", "not text"),
    "no-profile.rockly": (b'{"format": "rockly-program", "version": 1, "workspace": {}}', "robot profile"),
    "page.xml": (b"<html><body>hello</body></html>", "not a Blockly program"),
    "cut.xml": (b'<xml xmlns="https://developers.google.com/blockly/xml"><block type="hobbit_sos"',
                "not valid Blockly XML"),
    "untyped.rockly": (rockly_document([stack(block("hobbit_sos"), {"fields": {"emotion": "HAPPY"}})]).encode(),
                       "the file is broken: block 2 has no type"),
    "untyped.xml": (b'<xml><block type="hobbit_sos"><next><block><field name="emotion">HAPPY</field></block></next>'
                    b'</block></xml>', "the file is broken: block 2 has no type"),
}


@pytest.mark.parametrize("name", sorted(BAD_FILES))
def test_a_bad_file_is_explained_and_changes_nothing(qtbot, window, pick_up_file, tmp_path, name):
    open_program(qtbot, window, pick_up_file)
    wait_for_code(qtbot, window, "robot.gripper('open')\nrobot.move_arm('floor')\nrobot.gripper('close')\n")
    before = state(qtbot, window)
    content, expected_words = BAD_FILES[name]
    bad = tmp_path / name
    bad.write_bytes(content)

    assert not completed(qtbot, window.files.open, str(bad))
    messages = error_boxes(window)
    assert len(messages) == 1 and expected_words in messages[0] and name in messages[0]
    assert state(qtbot, window) == before
    assert window.document.path == str(pick_up_file)
    assert bad.read_bytes() == content


def test_missing_file_is_explained(qtbot, window, tmp_path):
    assert not completed(qtbot, window.files.open, str(tmp_path / "gone.rockly"))
    assert "does not exist" in error_boxes(window)[0]


def test_unknown_blocks_are_named_with_their_missing_profile(qtbot, window, tmp_path):
    path = tmp_path / "turtle.rockly"
    path.write_text(rockly_document([block("turtle_drive"), block("turtle_scan"), block("hobbit_sos")],
                                    profile="turtle"))
    before = state(qtbot, window)
    window.files.open(str(path))
    qtbot.waitUntil(lambda: bool(error_boxes(window)), timeout=10000)
    assert state(qtbot, window) == before and window.document.path is None
    message = error_boxes(window)[0]
    assert "turtle_drive" in message and "turtle_scan" in message and "hobbit_sos" not in message
    assert "'turtle'" in message and "not installed" in message


def test_unknown_blocks_in_an_installed_profile_are_named(qtbot, window, tmp_path):
    path = tmp_path / "future.rockly"
    path.write_text(rockly_document([block("hobbit_dance")]))
    window.files.open(str(path))
    qtbot.waitUntil(lambda: bool(error_boxes(window)), timeout=10000)
    assert "hobbit_dance" in error_boxes(window)[0] and "'hobbit' does not provide them" in error_boxes(window)[0]


FIRST_ROCKLY_XML = """<xml xmlns="https://developers.google.com/blockly/xml">
  <variables><variable id="v1">name</variable></variables>
  <block type="hobbit_emo" x="20" y="20"><field name="emotion">HAPPY</field>
    <next><block type="hobbit_arm_gripper"><field name="gripper_position">close</field>
    <next><block type="variables_set"><field name="VAR" id="v1">name</field>
      <value name="VALUE"><block type="hobbit_user_input"><value name="text">
        <block type="text"><field name="TEXT">What's your name?</field></block></value></block></value>
    <next><block type="hobbit_move"><field name="direction">-</field>
      <value name="speed"><block type="math_number"><field name="NUM">2</field></block></value>
    </block></next></block></next></block></next></block>
</xml>"""


def test_import_of_a_first_rockly_xml_program(qtbot, window, tmp_path):
    path = tmp_path / "old.xml"
    path.write_text(FIRST_ROCKLY_XML, encoding="utf-8")
    open_program(qtbot, window, path, importing=True)
    wait_for_code(qtbot, window, "name = None\n\n\nrobot.show_emotion('HAPPY')\nrobot.gripper('close')\n"
                                 "name = robot.ask_text('What\\'s your name?')\nrobot.drive(2, 'backward')\n")
    assert window.document.path is None and window.isWindowModified()
    assert path.read_text(encoding="utf-8") == FIRST_ROCKLY_XML


def test_export_writes_the_generated_python(qtbot, window, pick_up_file, tmp_path):
    open_program(qtbot, window, pick_up_file)
    wait_for_code(qtbot, window, "robot.gripper('open')\nrobot.move_arm('floor')\nrobot.gripper('close')\n")
    target = tmp_path / "out.py"
    assert completed(qtbot, window.files.export_python, str(target))
    exported = target.read_text(encoding="utf-8")
    assert exported.endswith("robot.gripper('open')\nrobot.move_arm('floor')\nrobot.gripper('close')\n")
    assert exported.startswith("# Generated by Rockly")
    compile(exported, str(target), "exec")


def test_opening_a_program_clears_the_last_runs_variables(qtbot, window, pick_up_file):
    window.variables.show_values({"score": "7"})
    open_program(qtbot, window, pick_up_file)
    assert window.variables.values() == {} and window.variables.table.rowCount() == 0


def test_export_adds_py_to_a_name_chosen_without_a_suffix(qtbot, window, pick_up_file, tmp_path, monkeypatch):
    open_program(qtbot, window, pick_up_file)
    wait_for_code(qtbot, window, "robot.gripper('open')\nrobot.move_arm('floor')\nrobot.gripper('close')\n")
    monkeypatch.setattr(QFileDialog, "getSaveFileName", lambda *args: (str(tmp_path / "pick up"), ""))
    assert completed(qtbot, window.files.export_python)
    assert (tmp_path / "pick up.py").read_text(encoding="utf-8").startswith("# Generated by Rockly")
    assert not (tmp_path / "pick up").exists()


def test_save_into_a_read_only_folder_fails_clearly_and_keeps_the_old_file(qtbot, window, pick_up_file, tmp_path):
    open_program(qtbot, window, pick_up_file)
    wait_for_code(qtbot, window, "robot.gripper('open')\nrobot.move_arm('floor')\nrobot.gripper('close')\n")
    assert not completed(qtbot, window.files.save_as, str(tmp_path / "missing-folder" / "x.rockly"))
    assert "cannot write in this folder" in error_boxes(window)[0]
    assert window.document.path == str(pick_up_file)


def test_unsaved_changes_prompt_before_they_are_lost(qtbot, window, pick_up_file, answer_prompts):
    add_block_as_user(qtbot, window.editor, "hobbit_sos")
    qtbot.waitUntil(window.isWindowModified, timeout=5000)
    asked = answer_prompts(QMessageBox.StandardButton.Cancel)
    assert not completed(qtbot, window.files.open, str(pick_up_file))
    assert asked and "Untitled" in asked[0]
    assert "robot.call_sos()" in state(qtbot, window)["python"]
    answer_prompts(QMessageBox.StandardButton.Discard)
    open_program(qtbot, window, pick_up_file)
    wait_for_code(qtbot, window, "robot.gripper('open')\nrobot.move_arm('floor')\nrobot.gripper('close')\n")


def test_new_program_is_empty_and_unnamed(qtbot, window, pick_up_file):
    open_program(qtbot, window, pick_up_file)
    wait_for_code(qtbot, window, "robot.gripper('open')\nrobot.move_arm('floor')\nrobot.gripper('close')\n")
    window.files.new()
    wait_for_code(qtbot, window, "")
    assert window.document.path is None and window.windowTitle().startswith("Untitled")


def test_a_large_program_opens(qtbot, window, tmp_path):
    blocks = [block("hobbit_move", {"direction": "+"}, {"speed": number(i)}) for i in range(300)]
    path = tmp_path / "large.rockly"
    path.write_text(rockly_document([stack(*blocks)]))
    open_program(qtbot, window, path)
    qtbot.waitUntil(lambda: window.code_dock.view.toPlainText().count("\n") == 300, timeout=15000)
    assert json.loads(path.read_text())["workspace"]["blocks"]["blocks"][0]["type"] == "hobbit_move"


def test_a_stack_of_600_blocks_tracks_edits_and_saves_them(qtbot, window, tmp_path):
    """Blockly's JSON nests a level per block: 600 in a stack is deeper than Python's json takes."""
    blocks = [block("hobbit_move", {"direction": "+"}, {"speed": number(i)}) for i in range(600)]
    path = tmp_path / "long.rockly"
    path.write_text(rockly_document([stack(*blocks)]))
    open_program(qtbot, window, path)
    qtbot.waitUntil(lambda: window.code_dock.view.toPlainText().count("\n") == 600, timeout=30000)

    add_block_as_user(qtbot, window.editor, "hobbit_sos")
    qtbot.waitUntil(window.isWindowModified, timeout=10000)
    assert completed(qtbot, window.files.save, timeout=30000)

    saved = load_program(path).workspace["blocks"]["blocks"]
    assert sorted(top["type"] for top in saved) == ["hobbit_move", "hobbit_sos"]
    assert not window.isWindowModified()


# --- opening with changes: said, never silent ---------------------------------------------


def changes_box(qtbot, window):
    """The warning shown when a program opened with changes (waits for it)."""
    def find():
        return [box for box in window.findChildren(QMessageBox)
                if box.objectName() == "opening_changes_box" and box.isVisible()]
    qtbot.waitUntil(lambda: bool(find()), timeout=10000)
    [box] = find()
    return box


def test_a_good_program_opens_without_a_warning(qtbot, window, pick_up_file):
    open_program(qtbot, window, pick_up_file)
    wait_for_code(qtbot, window, "robot.gripper('open')\nrobot.move_arm('floor')\nrobot.gripper('close')\n")
    # What must not come is a late edit from the page (sent 60 ms after a change): nothing
    # says none is coming, so this one wait stays, only long enough for it.
    qtbot.wait(200)
    assert error_boxes(window) == [] and not window.isWindowModified()


def test_a_value_its_block_does_not_offer_is_named_and_the_file_is_kept_until_saved(qtbot, window, tmp_path):
    path = tmp_path / "furious.rockly"
    path.write_text(rockly_document([stack(block("hobbit_sos"), block("hobbit_emo", {"emotion": "FURIOUS"}),
                                           block("hobbit_stop", {"brakes": "hard"}))]), encoding="utf-8")
    content = path.read_bytes()
    open_program(qtbot, window, path)
    box = changes_box(qtbot, window)
    assert "Block 2 (hobbit_emo), emotion: “FURIOUS” → “HAPPY”" in box.text()
    assert "Block 3 (hobbit_stop) has no field brakes: “hard” was left out" in box.text()
    assert "The file itself is unchanged" in box.informativeText()
    assert box.icon() == QMessageBox.Icon.Warning
    # The program opens as it is shown, marked changed: closing asks before anything is lost.
    wait_for_code(qtbot, window, "robot.call_sos()\nrobot.show_emotion('HAPPY')\nrobot.stop()\n")
    assert window.document.path == str(path) and window.isWindowModified()
    assert path.read_bytes() == content
    # Saving (after being told) writes what is shown.
    assert completed(qtbot, window.files.save)
    assert load_program(path).workspace["blocks"]["blocks"][0]["next"]["block"]["fields"] == {"emotion": "HAPPY"}


def test_an_imported_program_with_a_value_its_block_does_not_offer_is_named_too(qtbot, window, tmp_path):
    path = tmp_path / "old.xml"
    path.write_text('<xml><block type="hobbit_head"><field name="head_position">sideways</field></block></xml>')
    open_program(qtbot, window, path, importing=True)
    assert "Block 1 (hobbit_head), head_position: “sideways” → “center_center”" in changes_box(qtbot, window).text()


def test_a_program_for_a_profile_that_is_not_installed_says_so_before_it_is_saved_as_another(
        qtbot, window, pick_up_file):
    pepper = pick_up_file.with_name("pepper.rockly")
    pepper.write_text(pick_up_file.read_text().replace('"profile": "hobbit"', '"profile": "pepper"'))
    content = pepper.read_bytes()
    open_program(qtbot, window, pepper)
    text = changes_box(qtbot, window).text()
    assert "robot profile “pepper”, which is not installed here (installed: hobbit, turtlebot)" in text
    assert "It is shown with the blocks of HOBBIT; saving it makes it a program for HOBBIT." in text
    wait_for_code(qtbot, window, "robot.gripper('open')\nrobot.move_arm('floor')\nrobot.gripper('close')\n")
    assert window.isWindowModified() and pepper.read_bytes() == content
    assert completed(qtbot, window.files.save)
    assert load_program(pepper).profile_id == "hobbit"


def test_the_changes_are_named_in_german_too(qtbot, driver, tmp_path):
    settings = AppSettings(driver.settings_path)
    settings.language = "de"
    settings.sync()
    window = driver.open_window()
    path = tmp_path / "pepper.rockly"
    path.write_text(rockly_document([block("hobbit_emo", {"emotion": "FURIOUS"})], profile="pepper"))
    window.files.open(str(path))
    box = changes_box(qtbot, window)
    assert box.windowTitle() == "Das Programm wurde mit Änderungen geöffnet"
    assert ("Roboterprofil „pepper“ gemacht, das hier nicht installiert ist "
            "(installiert: hobbit, turtlebot)") in box.text()
    assert "Block 1 (hobbit_emo), emotion: „FURIOUS“ → „HAPPY“" in box.text()


def test_saving_through_a_symlink_keeps_the_link_and_updates_its_target(qtbot, window, pick_up_file, tmp_path):
    link = tmp_path / "shortcut.rockly"
    link.symlink_to(pick_up_file.name)
    open_program(qtbot, window, link)
    wait_for_code(qtbot, window, "robot.gripper('open')\nrobot.move_arm('floor')\nrobot.gripper('close')\n")
    add_block_as_user(qtbot, window.editor, "hobbit_sos")
    qtbot.waitUntil(window.isWindowModified, timeout=5000)
    assert completed(qtbot, window.files.save)
    assert link.is_symlink() and os.readlink(link) == pick_up_file.name
    assert "hobbit_sos" in {b["type"] for b in load_program(pick_up_file).workspace["blocks"]["blocks"]}


def test_export_into_a_fifo_writes_into_it(qtbot, window, pick_up_file, tmp_path):
    open_program(qtbot, window, pick_up_file)
    wait_for_code(qtbot, window, "robot.gripper('open')\nrobot.move_arm('floor')\nrobot.gripper('close')\n")
    fifo = tmp_path / "python.fifo"
    os.mkfifo(fifo)
    received = []
    reader = threading.Thread(target=lambda: received.append(fifo.read_text()), daemon=True)
    reader.start()
    assert completed(qtbot, window.files.export_python, str(fifo))
    reader.join(10)
    assert received and received[0].endswith("robot.gripper('close')\n")
    assert stat.S_ISFIFO(os.stat(fifo).st_mode)


def test_a_program_opened_at_start_with_changes_says_so_too(qtbot, driver, tmp_path):
    path = tmp_path / "furious.rockly"
    path.write_text(rockly_document([block("hobbit_emo", {"emotion": "FURIOUS"})]))
    window = driver.open_window(str(path))
    assert "Block 1 (hobbit_emo), emotion: “FURIOUS” → “HAPPY”" in changes_box(qtbot, window).text()
    qtbot.waitUntil(lambda: window.document.path == str(path), timeout=10000)
    assert window.isWindowModified()
