"""A kiosk's challenge of the day: the lesson a teacher chose (a kiosk setting) shown in the Lessons dock
for every visitor, afresh: the last visitor's step, results and progress are gone, and nothing of a
visitor's progress is written to the settings."""
import pytest
from PySide6.QtCore import QSettings, Qt
from test_kiosk import clock, folders, open_kiosk  # noqa: F401 (fixtures)
from test_lessons_dock import CHECK_MS, PROGRAMS, lesson_item, open_program

from rockly_desktop.settings.app_settings import AppSettings


@pytest.fixture
def challenge(driver):
    settings = AppSettings(driver.settings_path)
    settings.kiosk.challenge = "hobbit-smile"
    settings.sync()


def test_every_visitor_gets_the_challenge_of_the_day_afresh(qtbot, driver, challenge, open_kiosk, clock):  # noqa: F811
    window, kiosk = open_kiosk()
    dock = window.lessons_dock
    qtbot.waitUntil(dock.isVisible, timeout=15000)
    assert window.simulator_dock.isVisible()  # the stage's big simulator stays
    assert dock.title.text() == "Challenge of the day: Make HOBBIT smile"
    assert dock.step_heading.text().startswith("Step 1 of ")

    open_program(qtbot, window, PROGRAMS / "hobbit-smile" / "solution.rockly")
    qtbot.mouseClick(dock.next_button, Qt.MouseButton.LeftButton)
    qtbot.mouseClick(dock.check_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.lessons.last_result is not None, timeout=CHECK_MS)
    assert window.lessons.last_result.passed and dock.results.isVisible()
    assert lesson_item(dock, "hobbit-smile").text(0).startswith("✓ ")
    window.settings.sync()
    assert QSettings(str(driver.settings_path), QSettings.Format.IniFormat).value("lessons/passed") is None

    clock.now += 1000  # nobody touched it: the next visitor
    with qtbot.waitSignal(kiosk.idle.sig_idle, timeout=3000):
        pass
    qtbot.waitUntil(lambda: lesson_item(dock, "hobbit-smile").text(0).startswith("○ "), timeout=15000)
    assert dock.isVisible() and dock.title.text() == "Challenge of the day: Make HOBBIT smile"
    assert dock.step_heading.text().startswith("Step 1 of ") and not dock.results.isVisible()
    assert dock.verdict.text() == ""


def test_the_teacher_chooses_the_challenge_in_the_kiosk_tab(qtbot, window):
    from rockly_desktop.ui.preferences.preferences import PreferencesDialog

    window.settings.teacher.set_pin("4711")
    lessons = window.lessons.library.for_robot(window.profile.id)
    dialog = PreferencesDialog("de", window, window.profile, window.settings.teacher, kiosk=window.settings.kiosk,
                               pin_given=True, challenges=[(lesson.id, lesson.title("de")) for lesson in lessons])
    box = dialog.kiosk_tab.challenge
    assert box.currentText() == "Keine" and box.isEnabled()
    box.setCurrentIndex(box.findText(lessons[0].title("de")))
    dialog.kiosk_tab.apply()
    assert window.settings.kiosk.challenge == lessons[0].id
    dialog.deleteLater()
