"""The Lessons dock in the real window: the chosen robot's lessons by level, a lesson's steps, hints and the
marks on its blocks, its start program (after asking), the progress kept per user, and Check (off the
window's thread; a failed try opens the replay at the failing moment; the program is never changed)."""
import shutil
from pathlib import Path

import pytest
import yaml
from page_tools import run_js
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QMessageBox
from window_tools import state

from rockly_desktop.core.paths import user_data_dir
from rockly_desktop.settings.app_settings import AppSettings

ROOT = Path(__file__).resolve().parents[2]
PROGRAMS = ROOT / "tests" / "lessons" / "programs"
CHECK_MS = 60000


def show_lessons(qtbot, window):
    """Bring the Lessons dock to the front and wait for its list."""
    dock = window.lessons_dock
    dock.show()
    dock.raise_()
    qtbot.waitUntil(lambda: dock.lesson_list.topLevelItemCount() > 0 and dock.isVisible(), timeout=30000)
    return dock


def lesson_item(dock, lesson_id):
    for top in range(dock.lesson_list.topLevelItemCount()):
        heading = dock.lesson_list.topLevelItem(top)
        for index in range(heading.childCount()):
            item = heading.child(index)
            if item.data(0, Qt.ItemDataRole.UserRole).id == lesson_id:
                return item
    raise AssertionError(f"{lesson_id} is not listed")


def start_lesson(qtbot, dock, lesson_id):
    """Choose the lesson in the list and click "Start lesson", as a person does (after "All lessons" when a
    lesson is open)."""
    if dock.all_button.isVisible() and not dock.all_button.isChecked():
        qtbot.mouseClick(dock.all_button, Qt.MouseButton.LeftButton)
    item = lesson_item(dock, lesson_id)
    dock.lesson_list.scrollToItem(item)
    rect = dock.lesson_list.visualItemRect(item)
    qtbot.mouseClick(dock.lesson_list.viewport(), Qt.MouseButton.LeftButton, pos=rect.center())
    assert dock.lesson_list.currentItem() is item
    qtbot.mouseClick(dock.start_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: dock.lesson is not None and dock.lesson.id == lesson_id, timeout=15000)


def highlighted(qtbot, window) -> list:
    """The ids of the blocks glowing as the running (or replayed) one."""
    return run_js(qtbot, window.editor, "Blockly.getMainWorkspace().getAllBlocks(false)"
                                        ".filter(b => b.getSvgRoot().classList.contains('blocklyHighlighted'))"
                                        ".map(b => b.id)")


def marked_types(qtbot, window) -> list:
    """The types of the canvas blocks and toolbox categories the page marks as the step's."""
    return run_js(qtbot, window.editor, """(() => {
        const ws = Blockly.getMainWorkspace();
        const blocks = ws.getAllBlocks(false).filter(b => b.getSvgRoot().classList.contains('rocklyLesson'));
        const categories = ws.getToolbox().getToolboxItems()
            .filter(i => i.getDiv && i.getDiv() && i.getDiv().classList.contains('rocklyLesson'));
        return {blocks: blocks.map(b => b.type).sort(), categories: categories.length};
    })()""")


def flyout_marked(qtbot, window) -> list:
    """The types of the blocks the open drawer (flyout) shows marked as the step's."""
    return run_js(qtbot, window.editor, """(() => {
        const flyout = Blockly.getMainWorkspace().getFlyout();
        if (!flyout || !flyout.isVisible()) return [];
        return [...new Set(flyout.getWorkspace().getAllBlocks(false)
            .filter(b => b.getSvgRoot().classList.contains('rocklyLesson')).map(b => b.type))].sort();
    })()""")


def toolbox_types(qtbot, window) -> list:
    """Every block type the toolbox offers now."""
    return run_js(qtbot, window.editor, """(() => {
        const types = [];
        const walk = (items) => (items || []).forEach((item) => {
            if ((item.kind || '').toLowerCase() === 'block') types.push(item.type);
            walk(item.contents);
        });
        Blockly.getMainWorkspace().getToolbox().getToolboxItems().forEach((i) => i.getContents && walk(
            Array.isArray(i.getContents()) ? i.getContents() : []));
        return [...new Set(types)].sort();
    })()""")


def open_program(qtbot, window, path):
    outcomes = []
    window.files.open_copy(path, path.stem, then=outcomes.append)
    qtbot.waitUntil(lambda: bool(outcomes), timeout=15000)
    assert outcomes == [True]


def choose_robot(qtbot, window, profile_id):
    if window.profile.id != profile_id:
        window.document.modified = False
        with qtbot.waitSignal(window.editor.sig_ready, timeout=30000):
            window.choose_profile(profile_id)
        assert window.profile.id == profile_id


@pytest.fixture
def user_lesson():
    """A TurtleBot lesson of the user's with a start program and a step that allows three blocks only."""
    folder = user_data_dir() / "lessons" / "drive-once"
    folder.mkdir(parents=True, exist_ok=True)
    shutil.copy(PROGRAMS / "turtlebot-square" / "wrong.rockly", folder / "start.rockly")
    data = {"id": "drive-once", "robot": "turtlebot", "level": "starter", "world": "room", "order": 99,
            "program": "start.rockly", "goals": [{"kind": "uses_loop"}]}
    (folder / "lesson.yaml").write_text(yaml.safe_dump(data), encoding="utf-8")
    for language, title, step, hint in (("en", "Drive once", "Only two blocks", "Drive, then turn."),
                                        ("de", "Einmal fahren", "Nur zwei Blöcke", "Fahre, dann drehe.")):
        (folder / f"lesson.{language}.md").write_text(
            f"# {title}\nIntro.\n## {step}\nText.\n> {hint}\nBlocks: turtlebot_drive\n"
            "Toolbox: turtlebot_drive, turtlebot_turn, controls_if\n## Two\nMore text.\n", encoding="utf-8")
    yield folder
    shutil.rmtree(folder)


def test_lessons_listed_by_level_with_steps_hints_marks_and_a_restricted_toolbox(qtbot, window, user_lesson):
    choose_robot(qtbot, window, "turtlebot")
    dock = show_lessons(qtbot, window)
    headings = [dock.lesson_list.topLevelItem(i).text(0) for i in range(dock.lesson_list.topLevelItemCount())]
    assert headings == ["Starter (7–10)", "Explorer (11–14)", "Full"]
    assert lesson_item(dock, "turtlebot-square").text(0) == "○ Drive a square"
    full_toolbox = toolbox_types(qtbot, window)
    assert "controls_repeat_ext" in full_toolbox

    start_lesson(qtbot, dock, "drive-once")
    # its start program replaced the (unchanged) program on screen; the first step is shown
    qtbot.waitUntil(lambda: [b["type"] for b in state(qtbot, window)["workspace"]["blocks"]["blocks"]]
                    == ["controls_repeat_ext"], timeout=15000)
    assert dock.title.text() == "Drive once"
    assert dock.step_heading.text() == "Step 1 of 2: Only two blocks"
    assert not dock.hints.isVisible() and dock.hint_button.isEnabled()
    qtbot.mouseClick(dock.hint_button, Qt.MouseButton.LeftButton)
    assert dock.hints.text() == "Hint: Drive, then turn." and not dock.hint_button.isEnabled()
    qtbot.waitUntil(lambda: toolbox_types(qtbot, window) == ["controls_if", "turtlebot_drive", "turtlebot_turn"],
                    timeout=15000)
    marks = marked_types(qtbot, window)
    assert marks["categories"] >= 1 and marks["blocks"] and set(marks["blocks"]) == {"turtlebot_drive"}
    # a drawer opened: its blocks of the step glow there too
    run_js(qtbot, window.editor, "(() => { const tb = Blockly.getMainWorkspace().getToolbox(); "
                                 "tb.setSelectedItem(tb.getToolboxItems()[0]); return true; })()")
    qtbot.waitUntil(lambda: flyout_marked(qtbot, window) == ["turtlebot_drive"], timeout=15000)

    qtbot.mouseClick(dock.next_button, Qt.MouseButton.LeftButton)
    assert dock.step_heading.text() == "Step 2 of 2: Two" and not dock.next_button.isEnabled()
    qtbot.waitUntil(lambda: toolbox_types(qtbot, window) == full_toolbox, timeout=15000)  # the level's again
    qtbot.waitUntil(lambda: marked_types(qtbot, window) == {"blocks": [], "categories": 0}, timeout=15000)
    qtbot.mouseClick(dock.back_button, Qt.MouseButton.LeftButton)
    assert dock.step_heading.text() == "Step 1 of 2: Only two blocks"

    assert not dock.lesson_list.isVisible()  # an open lesson has the dock's room; "All lessons" gives the list back
    qtbot.mouseClick(dock.all_button, Qt.MouseButton.LeftButton)
    assert dock.lesson_list.isVisible() and dock.start_button.isVisible()


def test_a_step_narrows_the_teachers_level_and_never_widens_it(qtbot, window, user_lesson):
    choose_robot(qtbot, window, "turtlebot")
    window.settings.teacher.set_level("turtlebot", "starter")  # drive, turn, stop, wait, repeat: no "if"
    window.lessons.apply_toolbox()  # as Preferences does when the teacher changed the level
    qtbot.waitUntil(lambda: "controls_if" not in toolbox_types(qtbot, window), timeout=15000)
    dock = show_lessons(qtbot, window)
    start_lesson(qtbot, dock, "drive-once")
    qtbot.waitUntil(lambda: toolbox_types(qtbot, window) == ["turtlebot_drive", "turtlebot_turn"], timeout=15000)

    dock.hide()  # another robot chosen while the dock is away: its lesson closes, the toolbox is the robot's own
    choose_robot(qtbot, window, "hobbit")
    assert dock.lesson is None
    qtbot.waitUntil(lambda: "hobbit_emo" in toolbox_types(qtbot, window), timeout=15000)


def test_opening_a_lesson_asks_before_replacing_unsaved_work(qtbot, window, answer_prompts):
    choose_robot(qtbot, window, "hobbit")
    dock = show_lessons(qtbot, window)
    loaded = []
    window.editor.load_workspace({"blocks": {"languageVersion": 0, "blocks": [
        {"type": "hobbit_emo", "id": "mine", "x": 10, "y": 10}]}}, lambda result, error: loaded.append(error))
    qtbot.waitUntil(lambda: loaded == [None], timeout=15000)
    window.document.mark_modified()
    asked = answer_prompts(QMessageBox.StandardButton.Cancel)
    item = lesson_item(dock, "hobbit-smile")
    dock.lesson_list.setCurrentItem(item)
    qtbot.mouseClick(dock.start_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: bool(asked), timeout=15000)
    assert dock.lesson is None
    assert [b["id"] for b in state(qtbot, window)["workspace"]["blocks"]["blocks"]] == ["mine"]


def test_check_passes_keeps_the_progress_and_offers_the_next_lesson(qtbot, driver, window):
    choose_robot(qtbot, window, "hobbit")
    dock = show_lessons(qtbot, window)
    start_lesson(qtbot, dock, "hobbit-smile")
    open_program(qtbot, window, PROGRAMS / "hobbit-smile" / "solution.rockly")
    before = state(qtbot, window)["workspace"]
    qtbot.mouseClick(dock.check_button, Qt.MouseButton.LeftButton)
    assert not dock.check_button.isEnabled()  # the check runs off the window's thread: the window goes on
    qtbot.waitUntil(lambda: window.lessons.last_result is not None, timeout=CHECK_MS)
    assert dock.verdict.text() == "Well done! You reached every goal."
    assert [dock.results.item(i).text() for i in range(dock.results.count())][0].startswith("✓ ")
    assert dock.next_lesson_button.isVisible()
    assert dock.next_lesson_button.text().startswith("Next lesson: ")
    assert lesson_item(dock, "hobbit-smile").text(0).startswith("✓ ")
    assert not window.replay_bar.isVisible()
    assert state(qtbot, window)["workspace"] == before
    window.settings.sync()
    assert AppSettings(driver.settings_path).lessons.passed("hobbit-smile")  # kept for the user

    following = dock.next_lesson()
    window.document.modified = False
    qtbot.mouseClick(dock.next_lesson_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: dock.lesson is following, timeout=15000)
    assert dock.results.count() == 0


def test_a_failed_check_opens_the_replay_at_the_failing_moment(qtbot, window):
    choose_robot(qtbot, window, "turtlebot")
    dock = show_lessons(qtbot, window)
    start_lesson(qtbot, dock, "turtlebot-stop-at-wall")
    open_program(qtbot, window, PROGRAMS / "turtlebot-stop-at-wall" / "wrong.rockly")
    before = state(qtbot, window)["workspace"]
    qtbot.mouseClick(dock.check_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.lessons.last_result is not None, timeout=CHECK_MS)
    result = window.lessons.last_result
    assert not result.passed and result.failing is not None
    assert dock.verdict.text().startswith("Not yet.")
    texts = [dock.results.item(i).text() for i in range(dock.results.count())]
    assert any(text.startswith("✗ ") for text in texts)
    assert not dock.next_lesson_button.isVisible()
    qtbot.waitUntil(lambda: window.replay_bar.isVisible(), timeout=CHECK_MS)
    qtbot.waitUntil(lambda: abs(window.replay_bar.position - result.failing[0]) < 0.2, timeout=15000)
    if result.failing[1]:  # the responsible block glows
        qtbot.waitUntil(lambda: highlighted(qtbot, window) == [result.failing[1]], timeout=15000)
    assert dock.verdict.text().startswith("Not yet.")  # the replay's retitling of the docks keeps the results
    assert [dock.results.item(i).text() for i in range(dock.results.count())] == texts
    assert state(qtbot, window)["workspace"] == before

    window.set_language("de")  # the results are said again in German
    qtbot.waitUntil(lambda: dock.verdict.text().startswith("Noch nicht."), timeout=15000)
    german = [dock.results.item(i).text() for i in range(dock.results.count())]
    assert len(german) == len(texts) and german != texts


def test_the_dock_in_german(qtbot, german_window):
    choose_robot(qtbot, german_window, "turtlebot")
    dock = show_lessons(qtbot, german_window)
    assert dock.windowTitle() == "Lektionen"
    assert dock.lesson_list.topLevelItem(0).text(0) == "Einstieg (7–10)"
    assert dock.start_button.text() == "Lektion starten"
    assert dock.check_button.text() == "Prüfen"
    start_lesson(qtbot, dock, "turtlebot-square")
    assert dock.step_heading.text().startswith("Schritt 1 von ")


def test_a_check_that_cannot_run_says_why_and_changes_nothing(qtbot, window):
    choose_robot(qtbot, window, "hobbit")
    dock = show_lessons(qtbot, window)
    start_lesson(qtbot, dock, "hobbit-smile")
    open_program(qtbot, window, PROGRAMS / "hobbit-smile" / "solution.rockly")
    before = state(qtbot, window)["workspace"]
    folder = Path(window.lessons._folder.name)  # where the checks' recordings go: a file now, so none can begin
    shutil.rmtree(folder)
    folder.write_text("not a folder")
    try:
        qtbot.mouseClick(dock.check_button, Qt.MouseButton.LeftButton)
        qtbot.waitUntil(lambda: dock.verdict.text().startswith("The check could not run: "), timeout=CHECK_MS)
        assert dock.check_button.isEnabled() and not dock.results.isVisible()
        assert window.lessons.last_result is None and not window.replay_bar.isVisible()
        assert state(qtbot, window)["workspace"] == before
    finally:
        folder.unlink()
        folder.mkdir()
