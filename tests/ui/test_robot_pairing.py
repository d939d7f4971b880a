"""Pairing in Programs on the robot… (issue 30), against a real agent in its own process, the dialog driven by
keys and clicks where a person types and clicks: the right code pairs (as a teacher on a fresh agent; a kiosk as a
student: test_kiosk_pairing) and then sending and starting work; a wrong code is said and the code typed stays; a
revoked key is said and Forget deletes it, after which a new code pairs again; a teacher makes a code another
laptop pairs with."""
import dataclasses
import os
import re
import socket
import stat
import subprocess
import sys

import pytest
from agent_tools import REPO, AgentProcess
from page_tools import call_page
from program_builder import workspace
from PySide6.QtCore import Qt, QTimer
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QInputDialog, QLineEdit
from screenshots import screenshot
from test_attach_window import exported, greet_and_drive  # noqa: F401 (fixture)

from rockly_desktop.runtime.agent.client import AgentClient
from rockly_desktop.runtime.agent.robot_keys import RobotKeys, tcp_address
from rockly_desktop.ui.agent.robot_programs_dialog import RobotProgramsDialog

SHOTS = "/work/notes/shots"
CODE = re.compile(r"\b[2-9A-Z]{3}-[2-9A-Z]{3}\b")


def code_from_the_robot(library, *options) -> str:
    """The code ``rockly agent pair`` prints on the robot (as its admin runs it there)."""
    return robot_says_pair(library, *options)[0]


def robot_says_pair(library, *options) -> tuple:
    """``(code, the certificate's fingerprint)`` as ``rockly agent pair`` prints them on the robot."""
    done = subprocess.run([sys.executable, "-m", "rockly_desktop", "agent", "--library", str(library), "pair",
                           *options], capture_output=True, text=True, cwd=REPO, timeout=120)
    assert done.returncode == 0, done.stderr
    return CODE.search(done.stdout).group(0), done.stdout.split("certificate: ")[1].split(" (")[0]


@pytest.fixture
def agent(tmp_path):
    """A fresh agent (nobody paired) with slow simulated time."""
    robot = AgentProcess(tmp_path / "library", "--speed", 0.05, paired=False)
    yield robot
    robot.stop()


@pytest.fixture
def programs_dialog(qtbot, window):
    """Makes the window's Programs on the robot… dialog for an agent's port; its calls' threads end after."""
    made = []

    def make(port, language="en", **options):
        dialog = RobotProgramsDialog(window.attached, language, window, host="127.0.0.1", port=port,
                                     document=window.document, limits=lambda: window.settings.teacher.limits("hobbit"),
                                     **options)
        qtbot.addWidget(dialog)
        made.append(dialog)
        dialog.show()
        return dialog

    yield make
    for dialog in made:
        dialog.close()
        dialog.calls.wait(30)
        dialog.pairing.calls.wait(30)


def type_code_and_pair(qtbot, dialog, code: str):
    """Type ``code`` where the dialog asks for it and click Pair, as a person does."""
    qtbot.waitUntil(lambda: dialog.pairing.isVisible() and dialog.pairing.pairing_needed, timeout=20000)
    field = dialog.pairing.code
    field.selectAll()
    QTest.keyClicks(field, code)
    QTest.mouseClick(dialog.pairing.pair_button, Qt.MouseButton.LeftButton)


def whole(qtbot, label):
    """Wait until ``label`` shows its wrapped text whole (as high as the text needs: the dialog grew for it)."""
    qtbot.waitUntil(lambda: label.height() >= label.heightForWidth(label.width()), timeout=5000)


def asked_to_pair(dialog) -> bool:
    return dialog.pairing.isVisible() and dialog.pairing.pairing_needed and dialog.pairing.reason.text() != ""


def test_the_right_code_pairs_the_window_as_a_teacher_and_then_send_and_start_work(qtbot, window, agent,
                                                                                 programs_dialog):
    call_page(qtbot, window.editor, "load", {"workspace": workspace(greet_and_drive())})
    dialog = programs_dialog(agent.port)
    qtbot.waitUntil(lambda: asked_to_pair(dialog), timeout=20000)
    assert not dialog.pairing.forget_button.isVisible()  # no key to forget yet
    code, fingerprint = robot_says_pair(agent.library)
    type_code_and_pair(qtbot, dialog, code)
    qtbot.waitUntil(lambda: dialog.pairing.about.isVisible(), timeout=20000)
    about = dialog.pairing.about.text()
    assert about.endswith(f"this computer is a teacher there.\nCertificate: {fingerprint}"), about  # as the robot says
    key = RobotKeys().get(tcp_address("127.0.0.1", agent.port))
    assert key is not None and key.role == "teacher" and len(key.fingerprint) == 64
    assert stat.S_IMODE(os.stat(RobotKeys().path).st_mode) == 0o600
    assert dialog.pairing.another_button.isVisible() and dialog.pairing.forget_button.isVisible()
    qtbot.waitUntil(dialog.send_button.isEnabled, timeout=20000)   # once the dialog has asked the robot again
    QTest.mouseClick(dialog.send_button, Qt.MouseButton.LeftButton)   # an unsaved program: the name is asked
    qtbot.waitUntil(lambda: dialog.findChild(QInputDialog) is not None
                    and dialog.findChild(QInputDialog).isVisible(), timeout=5000)
    asked = dialog.findChild(QInputDialog)
    QTest.keyClicks(asked.findChild(QLineEdit), "greeting")
    QTest.keyClick(asked.findChild(QLineEdit), Qt.Key.Key_Return)
    qtbot.waitUntil(lambda: dialog.programs.count() == 1, timeout=20000)
    row = dialog.programs.visualItemRect(dialog.programs.item(0)).center()
    QTest.mouseClick(dialog.programs.viewport(), Qt.MouseButton.LeftButton, pos=row)
    qtbot.waitUntil(dialog.start_button.isEnabled, timeout=20000)
    QTest.mouseClick(dialog.start_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: dialog.running.text().startswith("Running on the robot now: greeting"), timeout=30000)
    qtbot.waitUntil(dialog.stop_button.isEnabled, timeout=20000)
    QTest.mouseClick(dialog.stop_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: dialog.running.text() == "Nothing runs on the robot now.", timeout=60000)


@pytest.mark.parametrize("language, reason", [
    ("en", "This computer is not paired with this robot yet"),
    ("de", "Dieser Rechner ist noch nicht mit diesem Roboter gekoppelt")])
def test_the_dialog_says_in_plain_words_that_this_computer_must_pair_first(qtbot, window, agent, programs_dialog,
                                                                          language, reason):
    dialog = programs_dialog(agent.port, language)
    qtbot.waitUntil(lambda: asked_to_pair(dialog), timeout=20000)
    assert dialog.pairing.reason.text().startswith(reason)
    assert "rockly agent pair" in dialog.pairing.how.text()
    assert dialog.status.text() == ""   # said once, in the panel
    assert not dialog.programs.isVisible() and not dialog.pairing.pair_button.isEnabled()   # no code typed yet
    for label in (dialog.pairing.reason, dialog.pairing.how):
        whole(qtbot, label)
    screenshot(dialog, f"pairing_needed_{language}")
    dialog.grab().save(os.path.join(SHOTS, f"pairing_needed_{language}.png"))


def test_a_wrong_code_is_said_and_the_code_typed_stays_and_the_right_one_then_pairs(qtbot, window, agent,
                                                                                  programs_dialog):
    right = code_from_the_robot(agent.library)
    wrong = "222-222" if right != "222-222" else "333-333"
    dialog = programs_dialog(agent.port)
    type_code_and_pair(qtbot, dialog, wrong)
    qtbot.waitUntil(lambda: dialog.pairing.problem.text() not in ("", "Asking the robot…"), timeout=20000)
    assert "code" in dialog.pairing.problem.text().lower()
    whole(qtbot, dialog.pairing.problem)
    dialog.grab().save(os.path.join(SHOTS, "pairing_wrong_code_en.png"))
    assert dialog.pairing.code.text() == wrong and dialog.pairing.pair_button.isEnabled()
    assert dialog.pairing.pairing_needed and RobotKeys().all() == []
    type_code_and_pair(qtbot, dialog, right)
    qtbot.waitUntil(lambda: dialog.pairing.about.isVisible(), timeout=20000)
    assert RobotKeys().get(tcp_address("127.0.0.1", agent.port)) is not None


def test_a_revoked_key_is_said_forget_deletes_it_and_a_new_code_pairs_again(qtbot, window, agent, programs_dialog):
    client = AgentClient("127.0.0.1", agent.port)
    try:
        client.pair(code_from_the_robot(agent.library), name="old laptop")
    finally:
        client.close()
    revoked = subprocess.run([sys.executable, "-m", "rockly_desktop", "agent", "--library", str(agent.library),
                              "revoke", "old laptop"], capture_output=True, text=True, cwd=REPO, timeout=120)
    assert revoked.returncode == 0, revoked.stderr
    dialog = programs_dialog(agent.port)
    qtbot.waitUntil(lambda: asked_to_pair(dialog) and dialog.pairing.forget_button.isVisible(), timeout=20000)
    assert dialog.programs.count() == 0
    QTest.mouseClick(dialog.pairing.forget_button, Qt.MouseButton.LeftButton)
    assert RobotKeys().get(tcp_address("127.0.0.1", agent.port)) is None
    type_code_and_pair(qtbot, dialog, code_from_the_robot(agent.library))
    qtbot.waitUntil(lambda: dialog.pairing.about.isVisible(), timeout=20000)
    assert RobotKeys().get(tcp_address("127.0.0.1", agent.port)) is not None


@pytest.mark.parametrize("language", ["en", "de"])
def test_a_teacher_makes_a_code_another_laptop_pairs_with(qtbot, window, agent, programs_dialog, tmp_path, language):
    dialog = programs_dialog(agent.port, language)
    type_code_and_pair(qtbot, dialog, code_from_the_robot(agent.library))
    qtbot.waitUntil(lambda: dialog.pairing.about.isVisible(), timeout=20000)
    QTest.mouseClick(dialog.pairing.another_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: dialog.pairing.other_code.isVisible(), timeout=20000)
    code = dialog.pairing.other_code.text()
    assert CODE.fullmatch(code)
    for label in (dialog.pairing.about, dialog.pairing.other_code_hint):
        whole(qtbot, label)
    dialog.grab().save(os.path.join(SHOTS, f"pairing_paired_{language}.png"))
    other = AgentClient("127.0.0.1", agent.port, keys=RobotKeys(tmp_path / "other-laptop.json"))
    try:
        key = other.pair(code, name="other laptop")
    finally:
        other.close()
    assert key.role == "student"   # the role chosen first


def test_a_certificate_other_than_the_one_paired_with_is_said_and_forget_lets_the_laptop_pair_anew(
        qtbot, window, agent, programs_dialog):
    client = AgentClient("127.0.0.1", agent.port)
    try:
        key = client.pair(code_from_the_robot(agent.library))
    finally:
        client.close()
    RobotKeys().save(dataclasses.replace(key, fingerprint="0" * 64))   # as if the robot's agent were another one
    dialog = programs_dialog(agent.port)
    qtbot.waitUntil(lambda: asked_to_pair(dialog) and dialog.pairing.forget_button.isVisible(), timeout=20000)
    assert "compare the fingerprint 'rockly agent pair' shows there" in dialog.pairing.reason.text()
    assert dialog.programs.count() == 0 and not dialog.programs.isVisible()
    QTest.mouseClick(dialog.pairing.forget_button, Qt.MouseButton.LeftButton)
    assert RobotKeys().all() == []
    type_code_and_pair(qtbot, dialog, code_from_the_robot(agent.library))
    qtbot.waitUntil(lambda: dialog.pairing.about.isVisible(), timeout=20000)
    assert RobotKeys().get(tcp_address("127.0.0.1", agent.port)).fingerprint == key.fingerprint


def test_pairing_with_an_agent_that_never_answers_leaves_the_window_responsive(qtbot, window, agent,
                                                                               programs_dialog):
    dialog = programs_dialog(agent.port)
    qtbot.waitUntil(lambda: asked_to_pair(dialog), timeout=20000)
    silent = socket.socket()   # takes the connection and never answers: the pairing waits for the agent
    silent.bind(("127.0.0.1", 0))
    silent.listen(0)
    dialog.port.setValue(silent.getsockname()[1])
    ticks = []
    timer = QTimer()
    timer.timeout.connect(lambda: ticks.append(1))
    timer.start(10)
    try:
        type_code_and_pair(qtbot, dialog, "K7Q-M2X")
        assert dialog.pairing.problem.text() == "Asking the robot…" and not dialog.pairing.pair_button.isEnabled()
        qtbot.waitUntil(lambda: len(ticks) >= 20, timeout=3000)   # the window's event loop goes on meanwhile
        assert dialog.pairing.calls.busy and dialog.pairing.code.text() == "K7Q-M2X"
    finally:
        timer.stop()
        silent.close()   # the waiting connection is reset: the pairing ends
    qtbot.waitUntil(lambda: not dialog.pairing.calls.busy, timeout=30000)
    assert dialog.pairing.problem.text() not in ("", "Asking the robot…")   # why it did not pair, said
    assert dialog.pairing.code.text() == "K7Q-M2X" and dialog.pairing.pair_button.isEnabled()
    assert RobotKeys().all() == []
