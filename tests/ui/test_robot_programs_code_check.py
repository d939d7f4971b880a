"""Programs on the robot… says, for the program chosen, whether its code is what its blocks make, as the robot's
agent checked it (``agent.source_match``, issue 30): a program whose code was changed beside its blocks is warned
of (an icon in the list and beside the sentence, the sentence in bold); an honest one is said to be what its
blocks make. The agent in its own process, the window paired with it, the programs chosen with clicks."""
import os

import pytest
from agent_tools import AgentProcess
from PySide6.QtCore import Qt
from PySide6.QtTest import QTest
from test_attach_window import exported  # noqa: F401 (fixture)
from test_robot_pairing import SHOTS
from waiting import eventually

from rockly_desktop.runtime.agent.client import AgentClient
from rockly_desktop.ui.agent.robot_programs_dialog import RobotProgramsDialog


@pytest.fixture
def robot(tmp_path, exported):  # noqa: F811
    """An agent keeping "honest" (as exported) and "changed" (code put in beside its blocks), both checked; this
    laptop paired with it."""
    agent = AgentProcess(tmp_path / "library", "--speed", 20)   # this laptop paired with it, as a teacher
    client = AgentClient("127.0.0.1", agent.port)
    try:
        standalone, source = exported
        changed = standalone.replace('RUN_CODE = """', 'RUN_CODE = """import os\nos.system("true")\n', 1)
        assert changed != standalone
        client.send("honest", standalone, source)
        client.send("changed", changed, source)
        eventually(lambda: {about["name"]: about["code"] for about in client.programs()["programs"]}
                   == {"honest": "same", "changed": "differs"}, 180)
    finally:
        client.close()
    yield agent
    agent.stop()


def choose(dialog, name: str):
    """Click program ``name`` in the dialog's list."""
    row = next(row for row in range(dialog.programs.count()) if dialog.programs.item(row).data(256) == name)
    QTest.mouseClick(dialog.programs.viewport(), Qt.MouseButton.LeftButton,
                     pos=dialog.programs.visualItemRect(dialog.programs.item(row)).center())
    assert dialog.chosen() == name


@pytest.mark.parametrize("language, differs, same", [
    ("en", "Its code is NOT what its blocks make (the code differs)", "Its code is what its blocks make"),
    ("de", "Sein Code ist NICHT das, was seine Blöcke ergeben (der Code anders)", "Sein Code ist das, was seine")])
def test_the_chosen_programs_code_is_said_and_a_changed_one_is_warned_of(qtbot, window, robot, language, differs,
                                                                        same):
    dialog = RobotProgramsDialog(window.attached, language, window, host="127.0.0.1", port=robot.port)
    qtbot.addWidget(dialog)
    dialog.show()
    try:
        qtbot.waitUntil(lambda: dialog.programs.count() == 2, timeout=20000)
        assert not dialog.code_state.isVisible()   # nothing chosen yet
        icons = {dialog.programs.item(row).data(256): not dialog.programs.item(row).icon().isNull()
                 for row in range(dialog.programs.count())}
        assert icons == {"honest": False, "changed": True}
        choose(dialog, "changed")
        assert dialog.code_state.text().startswith(differs), dialog.code_state.text()
        assert dialog.code_warning.isVisible() and dialog.code_state.font().bold()
        dialog.grab().save(os.path.join(SHOTS, f"robot_code_differs_{language}.png"))
        choose(dialog, "honest")
        assert dialog.code_state.text().startswith(same), dialog.code_state.text()
        assert not dialog.code_warning.isVisible() and not dialog.code_state.font().bold()
    finally:
        dialog.close()
        dialog.calls.wait(30)
