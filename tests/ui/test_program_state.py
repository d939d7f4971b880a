"""What a run leaves on screen belongs to its program and robot (real window, real simulators): New,
Open, an example and a robot switch end the replay and clear the Variables; a recording shows only
on the robot, and in the simulated world, it was recorded with."""
import sys
from pathlib import Path

import pytest
from page_tools import call_page
from program_builder import block, number, rockly_document, stack, workspace
from PySide6.QtWidgets import QMessageBox
from window_tools import completed, opened_recording

from rockly_desktop.recording import channels
from rockly_desktop.recording.reading import read_recording
from rockly_desktop.recording.recorder import Recorder
from rockly_desktop.robot.links import link_kind
from rockly_desktop.ui.robot.connection_dialog import ConnectionDialog

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "turtlebot" / "avoid-obstacles.rockly"


def run_hobbit_counting_laps(qtbot, window):
    """Run a HOBBIT program with a variable ``laps`` to its end; its replay is then on screen."""
    ws = workspace(stack(block("variables_set", {"VAR": {"id": "laps"}}, {"VALUE": number(3)}, id="laps"),
                         block("hobbit_move", {"direction": "+"}, {"speed": number(0.5)}, id="drive")))
    ws["variables"] = [{"name": "laps", "id": "laps"}]
    call_page(qtbot, window.editor, "load", {"workspace": ws})
    with qtbot.waitSignal(window.runs.sig_finished, timeout=20000) as blocker:
        assert window.runs.run()
    assert blocker.args[0].outcome == "finished"
    qtbot.waitUntil(window.replay_bar.isVisible, timeout=5000)
    window.replay_bar.jump_to(window.replay_bar.duration)
    assert window.variables.values() == {"laps": "3"}
    window.document.modified = False  # nothing to ask about: the commands go straight on


def open_other(qtbot, window, tmp_path):
    path = tmp_path / "other.rockly"
    path.write_text(rockly_document([block("hobbit_sos")]))
    assert completed(qtbot, window.files.open, str(path))


def choose_the_turtlebot(qtbot, window):
    window.choose_profile("turtlebot")
    qtbot.waitUntil(lambda: window.profile.id == "turtlebot" and window.editor.is_ready, timeout=30000)


REPLACEMENTS = {
    "new": lambda qtbot, window, tmp_path: window.files.new(ask=False),
    "open": open_other,
    "example": lambda qtbot, window, _path: completed(qtbot, window.files.open_copy, str(EXAMPLE), "Avoid obstacles"),
    "robot": lambda qtbot, window, tmp_path: choose_the_turtlebot(qtbot, window),
}


@pytest.mark.parametrize("replace", list(REPLACEMENTS))
def test_new_open_an_example_and_a_robot_switch_end_the_replay_and_clear_the_variables(qtbot, window, tmp_path,
                                                                                      replace):
    run_hobbit_counting_laps(qtbot, window)
    REPLACEMENTS[replace](qtbot, window, tmp_path)
    qtbot.waitUntil(lambda: not window.replay_bar.isVisible(), timeout=5000)
    assert window.variables.values() == {} and window.variables.table.rowCount() == 0
    window.replay_bar.sig_moment.emit(window.replay_bar.duration)  # a stray moment of the old timeline
    assert window.variables.values() == {}
    live, view = window.robot().snapshot(), window.simulator_dock.view  # the view shows the robot as it is
    qtbot.waitUntil(lambda: (view._snapshot["x"], view._snapshot["y"]) == (live["x"], live["y"]), timeout=5000)


def test_running_on_a_robot_over_ros_instead_ends_the_replay_and_clears_the_variables(qtbot, window, ros_master,
                                                                                     hobbit_on_ros, monkeypatch):
    run_hobbit_counting_laps(qtbot, window)
    window.settings.remember_link_connection(link_kind("ros1"), "hobbit", {"master": ros_master.uri,
                                                                            "host": "127.0.0.1"})
    monkeypatch.setattr(ConnectionDialog, "exec", lambda dialog: 1)
    window.run_toolbar.backend.setCurrentIndex(window.run_toolbar.backend.findData("ros1"))
    assert window.robots.kind == "ros1"
    qtbot.waitUntil(lambda: not window.replay_bar.isVisible(), timeout=5000)
    assert window.variables.values() == {}


def test_a_recording_of_hobbit_is_not_replayed_onto_the_turtlebot(qtbot, window):
    run_hobbit_counting_laps(qtbot, window)
    path = window.runs.last_recording
    metadata = read_recording(path).metadata
    assert metadata["profile"] == "hobbit" and metadata["world"] == window.robots.world_id()
    choose_the_turtlebot(qtbot, window)
    turtlebot = window.robot().snapshot()

    assert not opened_recording(qtbot, window, path)

    boxes = [box for box in window.findChildren(QMessageBox)
             if box.objectName() == "recording_other_robot_box" and box.isVisible()]
    assert boxes and boxes[0].text() == ("This recording is of a run on HOBBIT. A replay shows only on the robot it "
                                         "was recorded with, not on TurtleBot: choose HOBBIT in the Robot menu first.")
    assert not window.replay_bar.isVisible() and window.variables.values() == {}
    assert (window.robot().snapshot()["x"], window.robot().snapshot()["y"]) == (turtlebot["x"], turtlebot["y"])


def recording_in_world(path, world: str):
    recorder = Recorder(path)
    recorder.start({"program": "p.rockly", "profile": "hobbit", "robot": "sim", "world": world})
    recorder.note(channels.RUN, {"event": "start"})
    recorder.note(channels.RUN, {"event": "end", "outcome": "finished"})
    recorder.close()
    return path


def test_a_recording_from_another_simulated_world_is_not_shown(qtbot, window, tmp_path):
    here = window.robots.world_id()
    assert here is not None
    assert not opened_recording(qtbot, window, recording_in_world(tmp_path / "elsewhere.mcap", "another-house"))
    boxes = [box for box in window.findChildren(QMessageBox)
             if box.objectName() == "recording_other_robot_box" and box.isVisible()]
    assert boxes and "another simulated world" in boxes[0].text() and not window.replay_bar.isVisible()
    assert opened_recording(qtbot, window, recording_in_world(tmp_path / "here.mcap", here))
    assert window.replay_bar.isVisible()


def test_a_worlds_fingerprint_is_its_geometry():
    from profile_copies import HOBBIT_DIR, SHARED_TOOLBOXES

    from rockly_desktop.profiles.profile import load_profile

    load_profile(HOBBIT_DIR, SHARED_TOOLBOXES).load_object("simulator")
    load_profile(HOBBIT_DIR.parent / "turtlebot", SHARED_TOOLBOXES).load_object("simulator")
    house = sys.modules["rockly_hobbit.world"].WORLD
    arena = sys.modules["rockly_turtlebot.arena"]
    assert arena.Arena().fingerprint() == arena.Arena().fingerprint() != house.fingerprint()
    assert arena.Arena(boxes=arena.BOXES[:1]).fingerprint() != arena.Arena().fingerprint()
