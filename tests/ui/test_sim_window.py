"""The window of `rockly sim PROFILE --ros`, in-process: real widgets offscreen, the real
simulated HOBBIT in a SimWorld; tablet questions come from a worker thread, as ROS's
service threads ask them. (The same window on a real master: tests/robot/ros1/test_sim_window_on_ros.py.)"""
import threading

import pytest
from background import Background
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QPushButton

from rockly_desktop.core.errors import RobotCommandError, RobotTimeout
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.sim.answer_list import AnswerList
from rockly_desktop.robot.sim.sim_world import SimWorld
from rockly_desktop.ui.docks.sim_window import UNANSWERED, SimulatorWindow
from rockly_desktop.ui.docks.tablet import TabletDialog


@pytest.fixture
def sim(qtbot, hobbit):
    """The window on a running simulated HOBBIT whose tablet is ``lines`` then the window."""
    window = SimulatorWindow(hobbit, "en")
    qtbot.addWidget(window)
    lines = []
    world = SimWorld()
    tablet = AnswerList([], lines.append, then=window.tablet)
    simulator = hobbit.load_object("simulator")(world, tablet=tablet, speed=20)
    simulator.start()
    window.show_simulator(simulator, "http://127.0.0.1:11311")
    window.show()
    yield window, world, simulator, tablet, lines
    simulator.shutdown()


def ask(world, kind, text, timeout=60):
    """Call /MMUI in a thread (never the GUI thread), as the ROS service thread does."""
    params = [{"name": "type", "value": kind}, {"name": "text", "value": text},
              {"name": "Timeout", "value": str(timeout)}]

    def call():
        assert threading.current_thread() is not threading.main_thread()
        response = world.call_service("/MMUI", {"params": params}, Interrupt())
        return [p["value"] for p in response["params"]]

    return Background(call)


def open_dialogs(window):
    return [dialog for dialog in window.findChildren(TabletDialog) if dialog.isVisible()]


def button(dialog, label):
    return next(b for b in dialog.findChildren(QPushButton) if b.text() == label)


def test_the_window_shows_the_simulated_robot_live_and_names_robot_and_master(qtbot, sim):
    window, world, simulator, _tablet, _lines = sim
    assert type(window.centralWidget()).__name__ == "HobbitSimView"
    assert "HOBBIT" in window.windowTitle() and "http://127.0.0.1:11311" in window.windowTitle()
    world.publish("/DiscreteMotionCmd", "std_msgs/String", {"data": "Move 0.5"})
    qtbot.waitUntil(lambda: simulator.snapshot()["x"] == pytest.approx(0.5, abs=0.01), timeout=5000)
    qtbot.waitUntil(lambda: window.view.snapshot()["x"] == pytest.approx(0.5, abs=0.01), timeout=2000)


def test_a_question_opens_the_apps_tablet_dialog_and_the_persons_answer_goes_back(qtbot, sim):
    window, world, _simulator, _tablet, lines = sim
    call = ask(world, "D_YES_NO", "Tea?")
    qtbot.waitUntil(lambda: bool(open_dialogs(window)), timeout=5000)
    dialog = open_dialogs(window)[0]
    assert dialog.label.text() == "Tea?" and not dialog.isModal() and dialog.parent() is window
    qtbot.waitUntil(lambda: window.view.snapshot()["tablet"] == {"kind": "D_YES_NO", "text": "Tea?"},
                    timeout=2000)  # HOBBIT's own tablet in the view shows it too
    qtbot.mouseClick(button(dialog, "Yes"), Qt.MouseButton.LeftButton)
    assert call.join().result == ["yes"]
    assert lines == ["tablet  yes_no: 'Tea?'", "asking in the window", "answer  'yes'"]

    call = ask(world, "D_NAME", "Your name?")
    qtbot.waitUntil(lambda: bool(open_dialogs(window)), timeout=5000)
    dialog = open_dialogs(window)[0]
    qtbot.keyClicks(dialog.entry, "Ada Lovelace")
    qtbot.mouseClick(button(dialog, "OK"), Qt.MouseButton.LeftButton)
    assert call.join().result == ["Ada Lovelace"]


def test_answers_from_the_command_line_come_first_then_the_window_asks(qtbot, hobbit):
    window = SimulatorWindow(hobbit, "en")
    qtbot.addWidget(window)
    world = SimWorld()
    simulator = hobbit.load_object("simulator")(world, tablet=AnswerList(["no", "Bob"], lambda _line: None,
                                                                          then=window.tablet))
    simulator.start()
    try:
        window.show_simulator(simulator, "http://127.0.0.1:11311")
        window.show()
        assert ask(world, "D_OK", "Hello").join().result == [""]        # confirmed while answers are left
        assert ask(world, "D_YES_NO", "Tea?").join().result == ["no"]
        assert ask(world, "D_NAME", "Name?").join().result == ["Bob"]
        assert open_dialogs(window) == []
        call = ask(world, "D_YES_NO", "More tea?")
        qtbot.waitUntil(lambda: bool(open_dialogs(window)), timeout=5000)
        open_dialogs(window)[0]._answer("yes")
        assert call.join().result == ["yes"]
    finally:
        simulator.shutdown()


def test_the_questions_timeout_applies_and_its_dialog_closes(qtbot, sim):
    window, world, _simulator, _tablet, _lines = sim
    call = ask(world, "D_YES_NO", "Quick?", timeout=0.5)
    qtbot.waitUntil(lambda: bool(open_dialogs(window)), timeout=5000)
    assert isinstance(call.join().error, RobotTimeout)
    qtbot.waitUntil(lambda: open_dialogs(window) == [], timeout=5000)


def test_closing_a_question_without_answering_fails_the_call_instead_of_answering_no(qtbot, sim):
    window, world, _simulator, _tablet, _lines = sim
    call = ask(world, "D_YES_NO", "Tea?")
    qtbot.waitUntil(lambda: bool(open_dialogs(window)), timeout=5000)
    qtbot.keyClick(open_dialogs(window)[0], Qt.Key.Key_Escape)
    error = call.join().error
    assert isinstance(error, RobotCommandError) and str(UNANSWERED) in str(error)


def test_sos_and_volume_notices_show_in_the_window(qtbot, sim):
    window, world, _simulator, _tablet, _lines = sim
    ask(world, "F_CALLSOS", "").join()
    qtbot.waitUntil(lambda: "SOS call started" in window.statusBar().currentMessage(), timeout=5000)
    ask(world, "F_LOUDER", "").join()
    qtbot.waitUntil(lambda: "volume 60 %" in window.statusBar().currentMessage(), timeout=5000)
    qtbot.waitUntil(lambda: "volume 60 %" in window.view.snapshot()["notices"], timeout=2000)


def test_a_profile_without_a_view_still_gets_a_window_for_its_tablet(qtbot, hobbit, monkeypatch):
    monkeypatch.delitem(hobbit.manifest, "simulator_view")
    window = SimulatorWindow(hobbit, "de")
    qtbot.addWidget(window)
    assert "Simulatoransicht" in window.centralWidget().text()
    window.show_simulator(object(), "http://example:11311")
    assert window.windowTitle() == "HOBBIT (simuliert) auf ROS — http://example:11311"


def test_closing_the_window_says_so(qtbot, sim):
    window = sim[0]
    with qtbot.waitSignal(window.sig_closed, timeout=1000):
        window.close()
