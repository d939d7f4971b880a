"""The simulator's tablet question in the window: its window never covers the robot, and closing it answers
"no answer" (said in the console) and the program goes on."""
import pytest
from page_tools import call_page
from program_builder import block, stack, text, workspace

from rockly_desktop.ui.docks.tablet import TabletDialog
from rockly_desktop.ui.docks.tablet_placement import global_rect


def tablet_dialogs(window):
    return [dialog for dialog in window.findChildren(TabletDialog) if dialog.isVisible()]


def ask_for_a_name(qtbot, window):
    """Run 'print(ask for a text), print("after")' and wait for the question's window."""
    program = stack(block("text_print", inputs={"TEXT": block("hobbit_user_input", inputs={"text": text("Name?")})}),
                    block("text_print", inputs={"TEXT": text("after")}))
    call_page(qtbot, window.editor, "load", {"workspace": workspace(program)})
    assert window.runs.run()
    qtbot.waitUntil(lambda: bool(tablet_dialogs(window)), timeout=10000)
    return tablet_dialogs(window)[0]


@pytest.mark.parametrize("on_stage", [False, True], ids=["desk", "stage"])
@pytest.mark.parametrize("size", [(1280, 800), (1920, 1080)], ids=["1280x800", "1920x1080"])
def test_the_tablet_question_never_covers_the_simulator_view(qtbot, window, size, on_stage):
    window.resize(*size)
    qtbot.waitUntil(lambda: (window.width(), window.height()) == size, timeout=3000)
    window.stage.set_active(on_stage)
    qtbot.waitUntil(lambda: window.simulator_dock.isVisible(), timeout=3000)
    dialog = ask_for_a_name(qtbot, window)
    simulator = global_rect(window.simulator_dock)
    assert not dialog.frameGeometry().intersects(simulator), (dialog.frameGeometry(), simulator)
    assert dialog.frameGeometry().intersects(window.frameGeometry())  # beside the robot, still in the window
    with qtbot.waitSignal(window.runs.sig_finished, timeout=10000):
        dialog.entry.setText("Ada")
        dialog._answer("Ada")


def test_closing_the_tablet_question_answers_no_answer_and_the_program_goes_on(qtbot, window):
    dialog = ask_for_a_name(qtbot, window)
    with qtbot.waitSignal(window.runs.sig_finished, timeout=10000) as finished:
        dialog.close()  # what the window's × does
    assert finished.args[0].outcome == "finished"
    lines = window.console.lines()
    said = lines.index("HOBBIT's tablet: no answer (the window was closed)")
    assert lines[said + 1:said + 3] == ["", "after"]  # the answer '' printed, then the rest of the program
