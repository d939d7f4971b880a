"""A kiosk and the robot (issue 30): Programs on the robot… (where pairing is) opens only with the teacher's PIN,
and a kiosk laptop pairs as a student even with a code that would make it a teacher, so a visitor can neither
pair others nor change the robot's limits. The real kiosk window, the PIN typed, the agent in its own process."""
# ruff: noqa: F811 (the kiosk fixtures come from test_kiosk)
import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QAction
from PySide6.QtTest import QTest
from test_kiosk import PIN, clock, folders, open_kiosk  # noqa: F401 (fixtures)
from test_robot_pairing import agent, code_from_the_robot, type_code_and_pair  # noqa: F401 (fixture)

from rockly_desktop.runtime.agent.client import AgentClient, AgentError
from rockly_desktop.runtime.agent.robot_keys import RobotKeys, tcp_address
from rockly_desktop.ui.agent.robot_programs_dialog import RobotProgramsDialog


def test_a_kiosk_pairs_behind_the_teachers_pin_and_as_a_student(qtbot, open_kiosk, agent):
    window, kiosk = open_kiosk()
    window.settings.agent_address = f"127.0.0.1:{agent.port}"
    window.findChild(QAction, "action_robot_programs").trigger()
    gate = kiosk.teacher_dialog
    assert gate is not None and gate.isVisible() and window.findChild(RobotProgramsDialog) is None
    QTest.keyClicks(gate.pin, PIN)
    QTest.keyClick(gate.pin, Qt.Key.Key_Return)
    qtbot.waitUntil(lambda: window.findChild(RobotProgramsDialog) is not None, timeout=10000)
    dialog = window.findChild(RobotProgramsDialog)
    try:
        qtbot.waitUntil(lambda: dialog.pairing.isVisible() and dialog.pairing.pairing_needed, timeout=20000)
        type_code_and_pair(qtbot, dialog, code_from_the_robot(agent.library))   # a fresh agent's first: a teacher's
        qtbot.waitUntil(lambda: dialog.pairing.about.isVisible(), timeout=20000)
        assert "this computer is a student there" in dialog.pairing.about.text()
        assert not dialog.pairing.another_button.isVisible()
    finally:
        dialog.close()
        dialog.calls.wait(30)
        dialog.pairing.calls.wait(30)
    assert RobotKeys().get(tcp_address("127.0.0.1", agent.port)).role == "student"
    client = AgentClient("127.0.0.1", agent.port)   # the kiosk laptop's key: a student's
    try:
        for teachers_only in (lambda: client.pairing_code("student"), lambda: client.robot_limits()):
            with pytest.raises(AgentError) as refused:
                teachers_only()
            assert refused.value.key == "agent_teacher_only"
    finally:
        client.close()
