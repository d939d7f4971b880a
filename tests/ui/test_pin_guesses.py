"""The teacher's PIN cannot be guessed by script: wrong PINs cost a wait that grows, holds in a new
dialog and after a restart, and is told in plain words; the settings file is readable by its owner only."""
import os
import stat
from pathlib import Path

import pytest
from fake_time import FakeTime
from PySide6.QtCore import QSettings
from screenshots import screenshot

from rockly_desktop.settings import teacher as teacher_settings
from rockly_desktop.settings.app_settings import AppSettings
from rockly_desktop.ui.kiosk.kiosk import LeaveDialog
from rockly_desktop.ui.preferences.preferences import PreferencesDialog

PIN = "2580"
_dialogs = []  # kept until the test ends (a dialog's tab dies with it)


@pytest.fixture
def clock(monkeypatch):
    fake = FakeTime()
    fake.now = 1_800_000_000.0  # a wall-clock time: the wait is kept as one in the settings file
    monkeypatch.setattr(teacher_settings, "time", fake)
    return fake


@pytest.fixture(autouse=True)
def forget_dialogs():
    yield
    _dialogs.clear()


@pytest.fixture
def settings_path(tmp_path):
    path = tmp_path / "settings.ini"
    settings = AppSettings(path)
    settings.teacher.set_pin(PIN)
    settings.sync()
    return path


def teacher_tab(qtbot, settings_path, hobbit, language="en"):
    """The Teacher tab of a new Preferences dialog over a fresh read of the settings file (as after a restart)."""
    dialog = PreferencesDialog(language, None, hobbit, AppSettings(settings_path).teacher)
    qtbot.addWidget(dialog)
    _dialogs.append(dialog)
    return dialog.teacher_tab


def guess(tab, pin):
    tab.pin.setText(pin)
    tab.unlock()
    return tab.problem.text()


def test_after_three_wrong_pins_even_the_right_one_waits_also_in_a_new_dialog_after_a_restart(
        qtbot, clock, settings_path, hobbit):
    tab = teacher_tab(qtbot, settings_path, hobbit)
    assert guess(tab, "0000") == "Wrong PIN."
    assert guess(tab, "0001") == "Wrong PIN."
    assert guess(tab, "0002") == "Wrong PIN. Too many wrong PINs: the next PIN is taken in 5 seconds."
    assert guess(tab, PIN) == "Too many wrong PINs: the next PIN is taken in 5 seconds."
    assert not tab.unlocked

    clock.now += 3
    tab = teacher_tab(qtbot, settings_path, hobbit, "de")  # closed, Rockly restarted, opened again
    assert tab.problem.text() == "Zu viele falsche PINs: Die nächste PIN wird in 2 Sekunden angenommen."
    assert "Zu viele" in guess(tab, PIN) and not tab.unlocked

    clock.now += 2
    assert guess(tab, "0003") == "Falsche PIN. Zu viele falsche PINs: Die nächste PIN wird in 10 Sekunden angenommen."
    clock.now += 10
    tab = teacher_tab(qtbot, settings_path, hobbit)
    assert tab.problem.text() == ""
    guess(tab, PIN)
    assert tab.unlocked
    assert AppSettings(settings_path).teacher.pin_wait() == 0  # the right PIN forgives the wrong ones
    assert guess(teacher_tab(qtbot, settings_path, hobbit), "0004") == "Wrong PIN."


def test_the_wait_doubles_up_to_a_quarter_of_an_hour_so_a_four_digit_pin_takes_months(clock, settings_path):
    teacher = AppSettings(settings_path).teacher
    waits = []
    for number in range(14):
        answer = teacher.try_pin(f"{number:04d}")
        assert not answer.right and not answer.refused
        waits.append(answer.wait)
        clock.now += answer.wait
    assert waits == [0, 0, 5, 10, 20, 40, 80, 160, 320, 640, 900, 900, 900, 900]
    assert sum(teacher_settings.wait_after(n) for n in range(1, 10_001)) > 90 * 24 * 3600
    assert teacher.try_pin(PIN).right


def test_a_clock_put_back_does_not_make_the_wait_endless(clock, settings_path):
    teacher = AppSettings(settings_path).teacher
    for number in range(3):
        teacher.try_pin(f"{number:04d}")
    clock.now -= 365 * 24 * 3600
    assert teacher.pin_wait() == teacher_settings.MAX_WAIT_SECONDS
    clock.now += teacher_settings.MAX_WAIT_SECONDS
    assert teacher.try_pin(PIN).right


def test_the_kiosks_pin_prompt_waits_too(qtbot, clock, settings_path):
    def dialog():
        made = LeaveDialog(AppSettings(settings_path).teacher, "en")
        qtbot.addWidget(made)
        made.open()
        return made

    leave = dialog()
    for wrong in ("1111", "2222", "3333"):
        leave.pin.setText(wrong)
        leave.accept()
    assert leave.problem.text().endswith("taken in 5 seconds.")
    leave.close()
    leave = dialog()
    assert leave.problem.text() == "Too many wrong PINs: the next PIN is taken in 5 seconds."
    leave.pin.setText(PIN)
    leave.accept()
    assert leave.isVisible() and leave.result() == 0
    clock.now += 5
    leave.pin.setText(PIN)
    leave.accept()
    assert not leave.isVisible() and leave.result() == 1


def mode(path) -> int:
    return stat.S_IMODE(os.stat(path).st_mode)


def test_the_settings_file_is_private_and_stays_so_after_saves(tmp_path, monkeypatch):
    made_by_rockly = tmp_path / "new" / "settings.ini"
    settings = AppSettings(made_by_rockly)
    settings.teacher.set_pin(PIN)
    settings.language = "de"
    settings.sync()
    assert mode(made_by_rockly) == 0o600 and mode(made_by_rockly.parent) == 0o700

    old = tmp_path / "old.ini"  # left world-readable by an earlier Rockly
    old.write_text("[General]\nlanguage=en\n")
    os.chmod(old, 0o644)
    settings = AppSettings(old)
    assert mode(old) == 0o600 and settings.language == "en"
    settings.teacher.set_pin(PIN)
    settings.sync()
    assert mode(old) == 0o600 and "pbkdf2" in old.read_text()


def test_rockly_s_own_settings_folder_is_made_private():
    # Qt reads where user settings live once per process: the folder is asked of Qt, not set here
    folder = Path(QSettings("Rockly", "Rockly").fileName()).parent
    assert folder.name == "Rockly"
    folder.mkdir(parents=True, exist_ok=True)
    os.chmod(folder, 0o755)
    settings = AppSettings()
    file = settings._store.fileName()
    assert file.startswith(str(folder)), file
    settings.language = "de"
    settings.sync()
    assert mode(folder) == 0o700 and mode(file) == 0o600


@pytest.mark.parametrize("language, wait", [("en", "5 min 20 s."), ("de", "5 Min. 20 Sek. angenommen.")])
def test_the_kiosks_pin_prompt_shows_a_long_wait_whole_in_minutes_and_seconds(qtbot, clock, settings_path, language,
                                                                             wait):
    teacher = AppSettings(settings_path).teacher
    for number in range(8):  # earlier visitors' guesses, each after its wait
        clock.now += teacher.try_pin(f"{number:04d}").wait
    leave = LeaveDialog(teacher, language)
    qtbot.addWidget(leave)
    leave.open()
    qtbot.waitUntil(leave.isVisible)
    leave.pin.setText("9999")
    leave.accept()   # the ninth wrong PIN: 320 s to wait, said under a text one line longer than before
    problem = leave.problem
    screenshot(leave, f"pin_lockout_{language}")
    assert problem.text().endswith(wait)
    qtbot.waitUntil(lambda: problem.height() >= problem.heightForWidth(problem.width()))
    assert problem.geometry().bottom() < leave.height() and problem.isVisible()
