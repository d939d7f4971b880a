"""The "Programs on the robot" dialog says, at a click, how to put the agent on a robot, in the window's language."""
import pytest
from PySide6.QtCore import QObject, Signal

from rockly_desktop.ui.agent.robot_programs_dialog import RobotProgramsDialog


class NotAttached(QObject):
    """The window's AttachedRun as the dialog sees it before anything is attached."""

    sig_state_changed = Signal(str)


@pytest.mark.parametrize("language, button, first, last", [
    ("en", "How do I put the agent on my robot?", "The robot's computer needs Debian or Ubuntu with ROS 1 Noetic",
     "Every step in detail: 'docs/agent.md'."),
    ("de", "Wie bringe ich den Agenten auf meinen Roboter?", "Der Computer des Roboters braucht Debian oder Ubuntu",
     "Jeder Schritt genau: 'docs/agent.md'."),
])
def test_the_help_opens_with_the_steps_in_the_windows_language(qtbot, language, button, first, last):
    attached = NotAttached()
    dialog = RobotProgramsDialog(attached, language)
    qtbot.addWidget(dialog)
    dialog.show()
    assert dialog.help_button.text() == button and not dialog.help.isVisible()
    dialog.help_button.click()
    assert dialog.help.isVisible()
    assert dialog.help.height() >= dialog.help.heightForWidth(dialog.help.width())   # not clipped
    assert dialog.screen().availableGeometry().contains(dialog.frameGeometry())   # its buttons too
    steps = dialog.help.text()
    assert steps.startswith(first) and steps.endswith(last)
    assert "'~/rockly/bin/rockly-agent --backend ros1'" in steps and "11411" in steps
    assert "'docs/agent/rockly-agent.service'" in steps
    dialog.help_button.click()
    assert not dialog.help.isVisible()
