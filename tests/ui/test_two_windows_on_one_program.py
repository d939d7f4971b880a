"""Two writers on one program file: a window never writes over a change another window or program
made since it opened or saved the file; it asks (save as another file, overwrite, reload)."""
import os
import subprocess
import sys

import pytest
from page_tools import add_block_as_user, block_types_on_page
from program_builder import block, rockly_document
from PySide6.QtCore import QCoreApplication, QEvent
from window_tools import completed

from rockly_desktop.core.program import load_program
from rockly_desktop.core.recovery import RecoverySession, read_recovery
from rockly_desktop.ui.files.disk_changes import CANCEL, OVERWRITE, RELOAD, SAVE_AS

QUESTION = "“square.rockly” was changed by another window or program since you opened or saved it here."


@pytest.fixture
def program_file(tmp_path):
    path = tmp_path / "square.rockly"
    path.write_text(rockly_document([block("hobbit_sos")]), encoding="utf-8")
    return path


class FakeSaveDialog:
    """Stands in for the window's file dialogs: Save As picks ``path``."""

    def __init__(self, path):
        self.path = str(path)

    def save_file(self, *_args):
        return self.path


def saved_types(path) -> set:
    return {entry["type"] for entry in load_program(path).workspace["blocks"]["blocks"]}


def edited(qtbot, window, block_type):
    add_block_as_user(qtbot, window.editor, block_type)
    qtbot.waitUntil(lambda: window.document.modified, timeout=5000)
    return window


def write_from_another_process(path, top_blocks):
    """Another program writes the file (in place, as a plain editor does)."""
    subprocess.run([sys.executable, "-c", "import sys; open(sys.argv[1], 'w', encoding='utf-8').write(sys.argv[2])",
                    str(path), rockly_document(top_blocks)], check=True)


def test_the_second_save_of_two_windows_asks_and_save_as_keeps_both(qtbot, driver, program_file, tmp_path,
                                                                    answer_prompts):
    first = edited(qtbot, driver.open_window(str(program_file)), "hobbit_emo")
    second = edited(qtbot, driver.open_window(str(program_file)), "hobbit_head")
    assert completed(qtbot, second.files.save)
    assert saved_types(program_file) == {"hobbit_sos", "hobbit_head"}

    asked = answer_prompts(SAVE_AS)
    kept = tmp_path / "square-mine.rockly"
    first.files.file_dialogs = FakeSaveDialog(kept)
    assert completed(qtbot, first.files.save)
    assert asked == [QUESTION]
    assert saved_types(program_file) == {"hobbit_sos", "hobbit_head"}  # the second window's, untouched
    assert saved_types(kept) == {"hobbit_sos", "hobbit_emo"}            # the first window's, all of it
    assert first.document.path == str(kept) and not first.document.modified

    assert completed(qtbot, second.files.save)  # the second window's file is still as it knew it
    assert asked == [QUESTION]


def test_overwrite_writes_this_windows_program_and_cancel_writes_nothing(qtbot, window, program_file, answer_prompts):
    assert completed(qtbot, window.files.open, str(program_file))
    edited(qtbot, window, "hobbit_emo")
    write_from_another_process(program_file, [block("hobbit_head")])

    asked = answer_prompts(CANCEL)
    assert completed(qtbot, window.files.save) is False
    assert saved_types(program_file) == {"hobbit_head"} and window.document.modified

    answer_prompts(OVERWRITE)
    assert completed(qtbot, window.files.save)
    assert saved_types(program_file) == {"hobbit_sos", "hobbit_emo"} and not window.document.modified
    assert asked == [QUESTION, QUESTION]


def test_reload_shows_the_file_as_another_program_left_it(qtbot, window, program_file, answer_prompts):
    assert completed(qtbot, window.files.open, str(program_file))
    edited(qtbot, window, "hobbit_emo")
    write_from_another_process(program_file, [block("hobbit_head")])
    answer_prompts(RELOAD)
    assert completed(qtbot, window.files.save) is False  # nothing of the window's was saved
    qtbot.waitUntil(lambda: block_types_on_page(qtbot, window.editor) == ["hobbit_head"], timeout=10000)
    assert not window.document.modified and saved_types(program_file) == {"hobbit_head"}


def test_a_file_touched_or_rewritten_with_the_same_text_is_no_change(qtbot, window, program_file, answer_prompts):
    assert completed(qtbot, window.files.open, str(program_file))
    edited(qtbot, window, "hobbit_emo")
    same = program_file.read_bytes()
    program_file.unlink()
    program_file.write_bytes(same)  # another inode and time, the same program
    os.utime(program_file, ns=(1, 1))
    asked = answer_prompts(CANCEL)
    assert completed(qtbot, window.files.save)
    assert asked == [] and saved_types(program_file) == {"hobbit_sos", "hobbit_emo"}


def activate(window):
    QCoreApplication.sendEvent(window, QEvent(QEvent.Type.WindowActivate))


def test_back_at_the_front_an_unchanged_window_reloads_and_a_changed_one_asks_once(qtbot, window, program_file,
                                                                                  answer_prompts, monkeypatch):
    assert completed(qtbot, window.files.open, str(program_file))
    checks, check = [], window.files.follow_disk
    monkeypatch.setattr(window.files, "follow_disk", lambda: (checks.append(True), check()))
    asked = answer_prompts(CANCEL)
    write_from_another_process(program_file, [block("hobbit_head")])
    activate(window)
    qtbot.waitUntil(lambda: block_types_on_page(qtbot, window.editor) == ["hobbit_head"], timeout=10000)
    assert not window.document.modified and asked == []
    assert "changed on disk" in window.statusBar().currentMessage()

    edited(qtbot, window, "hobbit_emo")
    write_from_another_process(program_file, [block("hobbit_sos")])
    activate(window)
    qtbot.waitUntil(lambda: asked == [QUESTION], timeout=10000)
    checked = len(checks)
    activate(window)
    qtbot.waitUntil(lambda: len(checks) > checked, timeout=10000)  # the activation's check has run
    assert asked == [QUESTION] and window.document.modified  # asked once; the program stays as it is
    assert sorted(block_types_on_page(qtbot, window.editor)) == ["hobbit_emo", "hobbit_head"]
    assert completed(qtbot, window.files.save) is False  # Save asks again: Cancel
    assert asked == [QUESTION, QUESTION] and saved_types(program_file) == {"hobbit_sos"}


def test_a_restored_program_asks_before_writing_over_a_file_changed_since_the_crash(qtbot, window, program_file,
                                                                                   tmp_path, answer_prompts):
    assert completed(qtbot, window.files.open, str(program_file))
    edited(qtbot, window, "hobbit_emo")
    session = RecoverySession(tmp_path / "recovery")   # what the crashed window's autosave kept
    window.autosave.session, old_session = session, window.autosave.session
    window.autosave.flush()
    assert session.path.exists()
    window.autosave.session = old_session
    recovery = read_recovery(session.path)
    assert recovery.file_stamp == window.document.disk_stamp

    window.document.modified = False
    write_from_another_process(program_file, [block("hobbit_head")])  # after the crash, before the restore
    assert completed(qtbot, window.files.restore, recovery)
    assert sorted(block_types_on_page(qtbot, window.editor)) == ["hobbit_emo", "hobbit_sos"]
    asked = answer_prompts(CANCEL)
    assert completed(qtbot, window.files.save) is False
    assert asked == [QUESTION] and saved_types(program_file) == {"hobbit_head"}
    session.close()
