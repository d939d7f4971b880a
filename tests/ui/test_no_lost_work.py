"""No lost work: the window keeps a copy of unsaved changes, and the next start after a crash offers it."""
import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest
from page_tools import add_block_as_user
from program_builder import block, rockly_document, stack, workspace
from PySide6.QtWidgets import QMessageBox, QPushButton
from recovery_tools import REPO, LiveProcess, left_by_killed_process
from window_tools import completed

from rockly_desktop.core import paths
from rockly_desktop.core.program import Program
from rockly_desktop.core.recovery import read_recovery
from rockly_desktop.settings.app_settings import AppSettings

SOS_AND_EMO = Program("hobbit", workspace(stack(block("hobbit_sos", id="s"), block("hobbit_emo", {"emotion": "SAD"}))),
                      ["s"])


@pytest.fixture
def sos_file(tmp_path):
    path = tmp_path / "sos.rockly"
    path.write_text(rockly_document([block("hobbit_sos")]), encoding="utf-8")
    return path


def recovery_files() -> list:
    folder = paths.recovery_dir()
    return sorted(folder.glob("*.rockly")) if folder.exists() else []


def block_types(program) -> set:
    found = set()

    def walk(item):
        found.add(item["type"])
        if "next" in item:
            walk(item["next"]["block"])

    for top in program.workspace["blocks"]["blocks"]:
        walk(top)
    return found


def recovery_box(window):
    boxes = [box for box in window.findChildren(QMessageBox) if box.objectName() == "recovery_box" and box.isVisible()]
    return boxes[0] if boxes else None


def answer_recovery(qtbot, window, button: str):
    qtbot.waitUntil(lambda: recovery_box(window) is not None, timeout=10000)
    recovery_box(window).findChild(QPushButton, button).click()


def open_and_change(qtbot, window, path):
    assert completed(qtbot, window.files.open, str(path))
    add_block_as_user(qtbot, window.editor, "hobbit_emo")
    qtbot.waitUntil(window.isWindowModified, timeout=5000)


# --- keeping a copy -------------------------------------------------------------------------


def test_an_edit_is_copied_to_a_recovery_file_and_saving_removes_it(qtbot, window, sos_file):
    assert completed(qtbot, window.files.open, str(sos_file))
    assert recovery_files() == []  # a program without unsaved changes needs no copy
    add_block_as_user(qtbot, window.editor, "hobbit_emo")
    qtbot.waitUntil(lambda: bool(recovery_files()), timeout=10000)
    [path] = recovery_files()
    recovery = read_recovery(path)
    assert recovery.program_path == str(sos_file)
    assert block_types(recovery.program) == {"hobbit_sos", "hobbit_emo"}
    assert completed(qtbot, window.files.save)
    assert recovery_files() == []


def test_a_run_copies_the_unsaved_program_before_it_starts(qtbot, window, sos_file):
    assert completed(qtbot, window.files.open, str(sos_file))
    copies_at_start = []
    window.runs.sig_state_changed.connect(
        lambda state: state == "starting" and copies_at_start.append([read_recovery(p) for p in recovery_files()]))
    # Run at once when the edit arrives: well before the few seconds autosave waits.
    window.editor.sig_changed.connect(lambda _w, _p, origin: origin == "user" and window.runs.run())
    with qtbot.waitSignal(window.runs.sig_finished, timeout=30000):
        add_block_as_user(qtbot, window.editor, "hobbit_emo")
    [[recovery]] = copies_at_start
    assert block_types(recovery.program) == {"hobbit_sos", "hobbit_emo"}


def test_closing_without_saving_removes_the_copy(qtbot, window, sos_file, answer_prompts):
    open_and_change(qtbot, window, sos_file)
    window.autosave.flush()
    assert len(recovery_files()) == 1
    answer_prompts(QMessageBox.StandardButton.Discard)
    assert window.close()
    assert list(paths.recovery_dir().iterdir()) == []


def test_opening_another_program_after_discarding_the_changes_removes_the_copy(qtbot, window, sos_file, tmp_path,
                                                                               answer_prompts):
    other = tmp_path / "other.rockly"
    other.write_text(rockly_document([block("hobbit_emo")]), encoding="utf-8")
    open_and_change(qtbot, window, sos_file)
    window.autosave.flush()
    answer_prompts(QMessageBox.StandardButton.Discard)
    assert completed(qtbot, window.files.open, str(other))
    assert recovery_files() == []


# --- offering it at the next start ----------------------------------------------------------


def test_the_copy_a_killed_rockly_left_is_offered_and_restore_brings_the_program_back_unsaved(
        qtbot, driver, sos_file):
    left = left_by_killed_process(SOS_AND_EMO, str(sos_file))
    window = driver.open_window()
    qtbot.waitUntil(lambda: recovery_box(window) is not None, timeout=10000)
    box = recovery_box(window)
    assert box.windowTitle() == "Restore unsaved work?"
    assert "“sos.rockly” had changes that were not saved" in box.text()
    assert f"File: {sos_file}" in box.informativeText() and "Copy from: " in box.informativeText()
    answer_recovery(qtbot, window, "recovery_restore")
    qtbot.waitUntil(lambda: window.document.path == str(sos_file), timeout=10000)
    qtbot.waitUntil(lambda: "robot.show_emotion('SAD')" in window.code_dock.view.toPlainText(), timeout=10000)
    assert window.isWindowModified() and window.windowTitle().startswith("sos.rockly[*]")
    assert window.document.breakpoints == ["s"]
    # The window's own copy replaces the one it restored.
    assert recovery_files() == [window.autosave.session.path] and not left.exists()
    assert block_types(read_recovery(window.autosave.session.path).program) == {"hobbit_sos", "hobbit_emo"}


def test_discard_deletes_the_copy(qtbot, driver):
    left = left_by_killed_process(SOS_AND_EMO)
    window = driver.open_window()
    answer_recovery(qtbot, window, "recovery_discard")
    assert list(paths.recovery_dir().iterdir()) == [] and not left.exists()
    assert window.document.path is None and not window.isWindowModified()


def test_the_copy_of_a_rockly_still_running_is_not_offered(qtbot, driver):
    other = LiveProcess(SOS_AND_EMO)
    try:
        window = driver.open_window()  # an offer is made in start(), before the editor is ready
        assert recovery_box(window) is None and other.path.exists()
    finally:
        other.end()


def test_the_offer_in_german_for_a_program_never_saved(qtbot, driver):
    settings = AppSettings(driver.settings_path)
    settings.language = "de"
    settings.sync()
    left_by_killed_process(SOS_AND_EMO)
    window = driver.open_window()
    qtbot.waitUntil(lambda: recovery_box(window) is not None, timeout=10000)
    box = recovery_box(window)
    assert box.windowTitle() == "Ungespeicherte Arbeit wiederherstellen?"
    assert "Dein Programm „Unbenannt“ hatte ungespeicherte Änderungen" in box.text()
    assert "Datei: keine (das Programm wurde nie gespeichert)" in box.informativeText()
    assert "Kopie vom: " in box.informativeText()
    assert [button.text() for button in box.buttons()] == ["Wiederherstellen", "Verwerfen"]
    answer_recovery(qtbot, window, "recovery_restore")
    qtbot.waitUntil(lambda: "robot.show_emotion('SAD')" in window.code_dock.view.toPlainText(), timeout=10000)
    # the code may show before the load's answer marks the program as changed (it has no file to wait for)
    qtbot.waitUntil(window.isWindowModified, timeout=10000)
    assert window.document.path is None


# --- a real crash: kill -9 ------------------------------------------------------------------


def processes_in_group(group: int) -> list:
    """Ids of the processes (QtWebEngine's helpers too) in process group ``group``."""
    found = []
    for stat_file in Path("/proc").glob("[0-9]*/stat"):
        try:
            fields = stat_file.read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if int(fields[2]) == group:
            found.append(int(stat_file.parent.name))
    return found


def test_after_kill_9_the_next_start_offers_the_program_that_was_on_screen(qtbot, driver, tmp_path):
    # A value its block does not offer: the program opens changed (said in a message), so it has
    # unsaved changes the moment it is shown, with no one clicking anything.
    path = tmp_path / "furious.rockly"
    path.write_text(rockly_document([stack(block("hobbit_sos"), block("hobbit_emo", {"emotion": "FURIOUS"}))]),
                    encoding="utf-8")
    env = {**os.environ, "QT_QPA_PLATFORM": "offscreen", "QTWEBENGINE_DISABLE_SANDBOX": "1",
           "PYTHONPATH": str(REPO), "XDG_CACHE_HOME": str(tmp_path / "cache")}
    with open(tmp_path / "rockly.log", "w") as log:
        process = subprocess.Popen([sys.executable, "-m", "rockly_desktop", str(path)], env=env, cwd=REPO,
                                   stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    try:
        qtbot.waitUntil(lambda: bool(recovery_files()) or process.poll() is not None, timeout=60000)
        assert process.poll() is None, (tmp_path / "rockly.log").read_text()
        assert len(processes_in_group(process.pid)) > 1  # QtWebEngine's helpers are in the group too
        os.killpg(process.pid, signal.SIGKILL)
        assert process.wait(timeout=30) == -signal.SIGKILL
        qtbot.waitUntil(lambda: not processes_in_group(process.pid), timeout=10000)
    finally:
        if processes_in_group(process.pid):
            os.killpg(process.pid, signal.SIGKILL)
            process.wait(timeout=30)

    window = driver.open_window()
    qtbot.waitUntil(lambda: recovery_box(window) is not None, timeout=10000)
    assert "“furious.rockly” had changes" in recovery_box(window).text()
    answer_recovery(qtbot, window, "recovery_restore")
    qtbot.waitUntil(lambda: window.document.path == str(path), timeout=10000)
    qtbot.waitUntil(lambda: "robot.show_emotion('HAPPY')" in window.code_dock.view.toPlainText(), timeout=10000)
    assert window.isWindowModified()
