"""The robot's own limits set from the window (issue 30): a laptop paired as a teacher reads them in Preferences →
Teacher, types new ones and sets them on the robot; the robot's agent (its own process, on a ROS 1 master with the
simulated HOBBIT) then holds a stranger's program (``limits: {}``, 3 m/s in its code) to them, as an independent
rospy node sees on /cmd_vel. A laptop paired as a student is refused and changes nothing. Preferences is the
window's own (Edit → Preferences), the PIN typed."""
import json
import os
import re

import pytest
from agent_tools import AgentProcess, hobbit_on_ros_with_wire
from program_builder import block, number, rockly_document
from PySide6.QtCore import QPoint, Qt
from PySide6.QtTest import QTest
from ros_helpers import ros_environment
from standalone_tools import export_standalone
from test_robot_pairing import SHOTS, code_from_the_robot
from waiting import eventually

from rockly_desktop.runtime.agent.client import AgentClient
from rockly_desktop.ui.preferences.preferences import PreferencesDialog

FAST = ("ros.publish_message('/cmd_vel', 'geometry_msgs/Twist', {'linear': {'x': 3.0}, 'angular': {'z': 2.0}})\n"
        "ros.wait(0.5)\n")


@pytest.fixture(scope="module")
def robot(tmp_path_factory):
    """``(master, a stranger's standalone text, wire recorder of /cmd_vel)``."""
    folder = tmp_path_factory.mktemp("robot-limits-window")
    source = folder / "wait.rockly"
    source.write_text(rockly_document([block("hobbit_wait", inputs={"seconds": number(1)})]))
    exported = export_standalone(source, folder / "wait.py", "--language", "en").read_text()
    stranger = re.sub(r'RUN_CODE = """.*?"""', lambda _: f'RUN_CODE = """{FAST}"""', exported, flags=re.S)
    assert "'limits': {" in stranger and "3.0" in stranger
    with hobbit_on_ros_with_wire(folder) as (master, wire):
        yield master, stranger, wire


@pytest.fixture
def agent(robot, tmp_path):
    """The robot's agent on the test's master (nobody paired yet), its limits in ``agent.limits_file`` (none)."""
    master = robot[0]
    limits_file = tmp_path / "robot-limits.json"
    process = AgentProcess(tmp_path / "library", "--master", master.uri, "--robot-limits", limits_file,
                           backend="ros1", env=ros_environment(master.uri, master.home), paired=False)
    process.limits_file = limits_file
    yield process
    process.stop()


def paired(agent, *options):
    """Pair this laptop (the window's keys) with ``agent``, with a code ``rockly agent pair OPTIONS`` printed."""
    client = AgentClient("127.0.0.1", agent.port)
    try:
        return client.pair(code_from_the_robot(agent.library, *options))
    finally:
        client.close()


@pytest.fixture
def teacher_tab(qtbot, window, monkeypatch):
    """Opens the window's Preferences (Edit → Preferences, shown without waiting in it) on its Teacher tab for the
    agent at a port (the address the Programs dialog last reached), and unlocks it with a new PIN typed twice."""
    opened = []
    monkeypatch.setattr(PreferencesDialog, "exec", lambda dialog: opened.append(dialog) or dialog.show() or 0)

    def open_tab(port, language="en"):
        window.settings.agent_address = f"127.0.0.1:{port}"
        window.set_language(language)
        qtbot.waitUntil(lambda: window.language == language, timeout=15000)
        window.show_preferences()
        dialog = opened[-1]
        tabs = dialog.tabs
        QTest.mouseClick(tabs.tabBar(), Qt.MouseButton.LeftButton,
                         pos=tabs.tabBar().tabRect(tabs.indexOf(dialog.teacher_tab)).center())
        assert tabs.currentWidget() is dialog.teacher_tab
        QTest.keyClicks(dialog.teacher_tab.pin, "4711")
        QTest.keyClicks(dialog.teacher_tab.pin_again, "4711")
        QTest.mouseClick(dialog.teacher_tab.unlock_button, Qt.MouseButton.LeftButton)
        assert dialog.teacher_tab.unlocked
        return dialog, dialog.teacher_tab.robot_limits_box

    yield open_tab
    for dialog in opened:
        dialog.reject()
        dialog.teacher_tab.robot_limits_box._robot.calls.wait(30)


def type_into(box, text: str):
    """Type ``text`` into a spin box in place of what it shows, and leave it with Tab."""
    box.setFocus()
    box.lineEdit().selectAll()
    QTest.keyClicks(box.lineEdit(), text)
    QTest.keyClick(box.lineEdit(), Qt.Key.Key_Tab)


def speeds_on_the_wire(wire) -> list:
    import struct
    return [(twist[0], twist[5]) for twist in (struct.unpack("<6d", raw) for _type, raw in wire.on("/cmd_vel"))]


def test_a_teacher_sets_the_robots_limits_in_the_teacher_tab_and_a_run_on_the_robot_keeps_them(
        qtbot, window, robot, agent, teacher_tab):
    master, stranger, wire = robot
    assert paired(agent).role == "teacher"   # the first laptop on a fresh agent
    dialog, box = teacher_tab(agent.port)
    qtbot.waitUntil(lambda: box.status.text() == "These are the limits the robot keeps now.", timeout=20000)
    qtbot.waitUntil(lambda: box.values.isVisible() and box.capability_boxes["arm"].height() > 0)   # laid out
    assert box.max_speed.value() == 0 and box.max_turn.value() == 0   # "no limit": the robot has none yet
    assert box.max_speed.text() == "no limit"
    type_into(box.max_speed, "0.2")
    type_into(box.max_turn, "30")
    arm = box.capability_boxes["arm"]
    QTest.mouseClick(arm, Qt.MouseButton.LeftButton, pos=QPoint(arm.height() // 2, arm.height() // 2))  # its tick
    assert not arm.isChecked()   # the arm switched off
    assert box.status.text() == "Changed here, not yet on the robot: click Set on the robot."
    dialog.grab().save(os.path.join(SHOTS, "teacher_tab_robot_limits_en.png"))
    QTest.mouseClick(box.keep_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: box.status.text() == "The robot keeps these limits now; its next run holds to them.",
                    timeout=20000)
    assert json.loads(agent.limits_file.read_text()) == {"max_speed": 0.2, "max_turn": 30.0, "switched_off": ["arm"]}
    seen_before = len(wire.on("/cmd_vel"))
    client = AgentClient("127.0.0.1", agent.port)   # the same laptop's key
    try:
        client.send("fast", stranger)
        client.start("fast")
        eventually(lambda: client.programs()["run"] is None, 60)
    finally:
        client.close()
    eventually(lambda: len(wire.on("/cmd_vel")) > seen_before, 30)
    speeds = speeds_on_the_wire(wire)[seen_before:]
    assert any(linear > 0 for linear, _ in speeds), speeds   # it drove, held to the robot's limit
    assert all(abs(linear) <= 0.2 + 1e-9 and abs(angular) <= 0.5236 + 1e-3 for linear, angular in speeds), speeds


def test_a_student_is_refused_and_the_robots_limits_stay(qtbot, window, agent, teacher_tab):
    agent.limits_file.write_text('{"max_speed": 0.3, "max_turn": null, "switched_off": []}\n')
    assert paired(agent, "--role", "student").role == "student"
    dialog, box = teacher_tab(agent.port, "de")
    qtbot.waitUntil(lambda: box.status.text() not in ("", "Ich frage den Roboter…") and box.read_button.isEnabled(),
                    timeout=20000)
    assert "Lehrkraft" in box.status.text(), box.status.text()
    assert not box.keep_button.isEnabled() and not box.values.isVisible()   # nothing shown it did not say
    dialog.grab().save(os.path.join(SHOTS, "teacher_tab_robot_limits_student_de.png"))
    assert json.loads(agent.limits_file.read_text())["max_speed"] == 0.3
    client = AgentClient("127.0.0.1", agent.port)
    try:
        with pytest.raises(Exception) as refused:
            client.robot_limits({"max_speed": None, "max_turn": None, "switched_off": []})
        assert refused.value.key == "agent_teacher_only"
    finally:
        client.close()
    assert json.loads(agent.limits_file.read_text())["max_speed"] == 0.3
