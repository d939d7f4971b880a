"""The Preferences and Connect dialogs are as big as their content (nothing under their buttons); message
boxes are wide enough for their titles."""
import pytest
from PySide6.QtCore import QSettings
from PySide6.QtGui import QFontMetrics
from PySide6.QtWidgets import QDialogButtonBox, QMessageBox, QWidget

from rockly_desktop.robot.links import link_kind
from rockly_desktop.settings.teacher import TeacherSettings
from rockly_desktop.ui.message_boxes import plain_message_box, title_width
from rockly_desktop.ui.preferences.preferences import PreferencesDialog
from rockly_desktop.ui.robot.connection_dialog import ConnectionDialog


def _shown(qtbot, dialog):
    qtbot.addWidget(dialog)
    dialog.show()
    qtbot.waitExposed(dialog)
    return dialog


def _ends_with_its_buttons(dialog):
    """The buttons are the lowest thing, one layout margin above the dialog's bottom edge."""
    buttons = dialog.findChild(QDialogButtonBox)
    lowest = max(child.mapTo(dialog, child.rect().bottomLeft()).y()
                 for child in dialog.findChildren(QWidget) if child.isVisible())
    bottom = buttons.mapTo(dialog, buttons.rect().bottomLeft()).y()
    return lowest == bottom and dialog.height() - 1 - bottom == dialog.layout().contentsMargins().bottom()


@pytest.mark.parametrize("language", ["en", "de"])
def test_the_connect_dialog_is_as_big_as_its_content(qtbot, language):
    dialog = _shown(qtbot, ConnectionDialog(language, "HOBBIT", link_kind("ros1")))
    assert dialog.minimumSize() == dialog.maximumSize() == dialog.size()
    assert _ends_with_its_buttons(dialog)


@pytest.mark.parametrize("language", ["en", "de"])
def test_preferences_are_as_big_as_their_content_also_after_unlocking(qtbot, tmp_path, hobbit, language):
    teacher = TeacherSettings(QSettings(str(tmp_path / "teacher.ini"), QSettings.Format.IniFormat))
    dialog = _shown(qtbot, PreferencesDialog(language, None, hobbit, teacher))
    assert dialog.minimumSize() == dialog.maximumSize() == dialog.size()
    assert _ends_with_its_buttons(dialog)
    dialog.tabs.setCurrentWidget(dialog.teacher_tab)
    dialog.teacher_tab.pin.setText("2468")
    dialog.teacher_tab.pin_again.setText("2468")
    dialog.teacher_tab.unlock()
    assert dialog.teacher_tab.unlocked
    qtbot.waitUntil(lambda: dialog.size() == dialog.sizeHint(), timeout=3000)
    assert _ends_with_its_buttons(dialog)


def test_a_message_box_with_a_short_text_is_wide_enough_for_its_title(qtbot):
    title = "Etwas ist schiefgegangen"
    box = plain_message_box(None, QMessageBox.Icon.Warning, title, "Hoppla.")
    box.setDetailedText("Traceback")   # QMessageBox lays itself out anew
    _shown(qtbot, box)
    assert box.width() >= title_width(title, box.font()) > QFontMetrics(box.font()).horizontalAdvance(title)
