"""The Teacher tab of a profile the teacher set no limits for shows (and keeps) the strictest ones set."""
import pytest
from profile_copies import copy_profile
from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QLabel

from rockly_desktop.core.paths import shared_toolboxes_dir
from rockly_desktop.profiles.profile import load_profile
from rockly_desktop.robot.wrappers.limits import Limits
from rockly_desktop.settings.teacher import TeacherSettings
from rockly_desktop.ui.preferences.preferences import PreferencesDialog


@pytest.mark.parametrize(("language", "start"), [("en", "No limits of its own were set for this robot"),
                                                 ("de", "Für diesen Roboter wurden keine eigenen Grenzen")])
def test_a_copied_profile_shows_the_strictest_limits_and_ok_keeps_them_as_its_own(qtbot, tmp_path, language, start):
    copy = load_profile(copy_profile(tmp_path / "hobbit_copy", "hobbit_copy").root, shared_toolboxes_dir())
    teacher = TeacherSettings(QSettings(str(tmp_path / "teacher.ini"), QSettings.Format.IniFormat))
    teacher.set_pin("2468")
    teacher.set_limits("hobbit", max_speed=0.15, max_turn=40, switched_off={"arm"})
    dialog = PreferencesDialog(language, None, copy, teacher)
    qtbot.addWidget(dialog)
    tab = dialog.teacher_tab
    tab.pin.setText("2468")
    tab.unlock()
    assert tab.unlocked
    said = tab.findChild(QLabel, "teacher_default_limits")
    assert said is not None and said.text().startswith(start)
    assert (tab.max_speed.value(), tab.max_turn.value()) == (0.15, 40)
    assert not tab.capability_boxes["arm"].isChecked() and tab.capability_boxes["navigation"].isChecked()
    tab.apply()
    assert teacher.has_own_limits("hobbit_copy")
    assert teacher.limits("hobbit_copy") == Limits(0.15, 40, frozenset({"arm"}))


def test_a_profile_with_its_own_limits_says_nothing_of_others(qtbot, tmp_path, hobbit):
    teacher = TeacherSettings(QSettings(str(tmp_path / "teacher.ini"), QSettings.Format.IniFormat))
    teacher.set_pin("2468")
    teacher.set_limits("hobbit", max_speed=0.15)
    teacher.set_limits("turtlebot", max_speed=0.05)
    dialog = PreferencesDialog("en", None, hobbit, teacher)
    qtbot.addWidget(dialog)
    dialog.teacher_tab.pin.setText("2468")
    dialog.teacher_tab.unlock()
    assert dialog.teacher_tab.findChild(QLabel, "teacher_default_limits") is None
    assert dialog.teacher_tab.max_speed.value() == 0.15
