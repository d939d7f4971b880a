"""Numbers typed into Rockly's own widgets, key by key, read the way the window's language writes them: in German
"0,25" is 0.25; in English "0,25" (no group of three) is refused and the box keeps its number, never 25 or 2."""
import pytest
from PySide6.QtCore import QSettings, Qt
from PySide6.QtTest import QTest
from screenshots import screenshot

from rockly_desktop.settings.teacher import TeacherSettings
from rockly_desktop.ui.preferences.preferences import PreferencesDialog
from rockly_desktop.ui.qt_language import use_language
from rockly_desktop.ui.run.run_toolbar import RunToolbar


def preferences(qtbot, tmp_path, hobbit, language):
    """The Preferences with the Teacher tab unlocked, in ``language`` (Qt's number formats too, as the window sets
    them), HOBBIT's speed limit 0.15 m/s."""
    use_language(language)
    teacher = TeacherSettings(QSettings(str(tmp_path / "teacher.ini"), QSettings.Format.IniFormat))
    teacher.set_pin("2468")
    teacher.set_limits("hobbit", max_speed=0.15)
    dialog = PreferencesDialog(language, None, hobbit, teacher)
    qtbot.addWidget(dialog)
    dialog.teacher_tab.pin.setText("2468")
    dialog.teacher_tab.unlock()
    return teacher, dialog


def type_limit(tab, keys):
    box = tab.max_speed
    tab.window().tabs.setCurrentWidget(tab)
    tab.window().show()
    box.setFocus()
    box.lineEdit().selectAll()
    QTest.keyClicks(box, keys)
    QTest.keyClick(box, Qt.Key.Key_Return)  # the box takes (or refuses) what was typed


@pytest.mark.parametrize(("language", "keys", "shown", "kept"), [
    ("de", "0,25", "0,25 m/s", 0.25), ("de", "0.25", "0,15 m/s", 0.15),
    ("en", "0.25", "0.25 m/s", 0.25), ("en", "0,25", "0.15 m/s", 0.15), ("en", "2,5", "0.15 m/s", 0.15)])
def test_the_teacher_speed_limit_is_read_as_the_language_writes_it(qtbot, tmp_path, hobbit, language, keys, shown,
                                                                    kept):
    teacher, dialog = preferences(qtbot, tmp_path, hobbit, language)
    tab = dialog.teacher_tab
    type_limit(tab, keys)
    assert tab.max_speed.text() == shown
    screenshot(dialog, f"preferences-speed-limit-{language}-{keys}")
    tab.apply()
    assert teacher.limits("hobbit").max_speed == kept


@pytest.mark.parametrize(("language", "tip"), [("de", "Zeitlupe: bei jedem Block 0,4 s warten"),
                                               ("en", "Slow motion: wait 0.4 s at every block")])
def test_the_speed_slider_says_its_wait_as_the_language_writes_numbers(qtbot, language, tip):
    toolbar = RunToolbar(language)
    qtbot.addWidget(toolbar)
    toolbar.show()
    toolbar.speed.setFocus()
    QTest.keyClick(toolbar.speed, Qt.Key.Key_Left)
    QTest.keyClick(toolbar.speed, Qt.Key.Key_Left)
    assert toolbar.delay == pytest.approx(0.4)
    assert toolbar.speed.toolTip() == tip
