"""In a kiosk, whatever reaches beyond the window's own program (other files, recordings, exports, the
robot's programs, attaching to them, the block maker) waits for the teacher's PIN, and First Steps tells
a visitor only what a visitor can do. Each test drives the real window (offscreen)."""
# ruff: noqa: F811 (the kiosk fixtures come from test_kiosk)
import pytest
from PySide6.QtCore import QTimer
from PySide6.QtGui import QAction
from PySide6.QtWidgets import QApplication
from screenshots import screenshot
from test_kiosk import PIN, clock, folders, open_kiosk  # noqa: F401 (fixtures)

from rockly_desktop.ui.help_dialogs import show_first_steps

TEACHERS_ACTIONS = ("action_open", "action_open_recording", "action_import_xml", "action_export_python",
                    "action_robot_programs", "action_make_block", "action_edit_made_block")


def other_windows(window, gate) -> list:
    """The windows on screen besides the kiosk and its PIN prompt (a modal one is closed: it would wait)."""
    modal = window.active_dialog()  # the window's dialogs are modal to it, not to Qt (decision 032)
    if modal is not None and modal is not gate:
        modal.reject()
    return [shown.objectName() or type(shown).__name__ for shown in QApplication.topLevelWidgets()
            if shown.isVisible() and shown not in (window, gate) and not shown.inherits("QMenu")]


def test_every_command_beyond_the_windows_program_asks_the_teachers_pin_in_a_kiosk(qtbot, open_kiosk):
    window, kiosk = open_kiosk()
    opened = {}
    for name in TEACHERS_ACTIONS:
        kiosk.teacher_dialog = None
        # a command that opens its own modal dialog (File → Open) waits in it: it is looked at and closed
        QTimer.singleShot(0, lambda name=name: opened.setdefault(name, other_windows(window, kiosk.teacher_dialog)))
        window.findChild(QAction, name).trigger()
        qtbot.waitUntil(lambda name=name: name in opened, timeout=10000)
        gate = kiosk.teacher_dialog
        assert gate is not None and gate.isVisible(), name
        assert window.active_dialog() is gate, name
        gate.reject()
    assert opened == {name: [] for name in TEACHERS_ACTIONS}


def test_attaching_to_a_run_on_the_robot_asks_the_teachers_pin_in_a_kiosk(qtbot, open_kiosk, monkeypatch):
    window, kiosk = open_kiosk()
    attached = []
    monkeypatch.setattr(window.agent_bar, "attach", lambda: attached.append(True))
    window.agent_bar.attach_button.click()
    assert kiosk.teacher_dialog is not None and kiosk.teacher_dialog.isVisible() and attached == []
    kiosk.teacher_dialog.pin.setText(PIN)
    kiosk.teacher_dialog.accept()
    assert attached == [True]


@pytest.mark.parametrize("language, robot_step", [("en", "Choose your robot in the Robot menu"),
                                                   ("de", "Wähle deinen Roboter im Menü Roboter")])
def test_first_steps_in_a_kiosk_names_only_what_a_visitor_can_do(qtbot, open_kiosk, language, robot_step):
    window, _kiosk = open_kiosk()
    window.set_language(language)
    qtbot.waitUntil(lambda: window.language == language, timeout=15000)
    page = show_first_steps(window, language)   # what Help → First Steps calls
    qtbot.waitUntil(lambda: page.isVisible())
    screenshot(page, f"first_steps_kiosk_{language}")
    text = page.browser.toPlainText()
    assert robot_step not in text   # the Robot menu asks for the teacher's PIN
    for named in ("Run (F5)", "STOP (Esc)") if language == "en" else ("Start (F5)", "STOPP (Esc)"):
        assert named in text
    page.close()
