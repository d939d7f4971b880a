"""The Lessons dock follows the lesson folders on disk: a lesson that cannot be read is said to the teacher
(its folder, file, line and what is wrong, in English and German) under the child's list, and lessons
imported, changed or removed while the window runs appear, change and go without a restart, while the open
lesson keeps its step and the progress stays."""
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import yaml
from PySide6.QtCore import QPoint, Qt
from test_lessons_dock import choose_robot, lesson_item, show_lessons, start_lesson

from rockly_desktop.core.paths import user_data_dir
from rockly_desktop.lessons.archive import export_lessons

ROOT = Path(__file__).resolve().parents[2]
CHANGE_MS = 30000  # the watch settles, reads off the window's thread and lists: generous for a loaded machine


def write_lesson(folder: Path, lesson_id: str, title: str, steps=("One", "Two"), goals=None) -> Path:
    """A TurtleBot lesson folder with ``steps`` (English; German with "DE " before each)."""
    folder.mkdir(parents=True, exist_ok=True)
    data = {"id": lesson_id, "robot": "turtlebot", "level": "starter", "world": "room", "order": 50,
            "goals": goals if goals is not None else [{"kind": "no_bump"}]}
    (folder / "lesson.yaml").write_text(yaml.safe_dump(data, sort_keys=False), encoding="utf-8")
    for language, before in (("en", ""), ("de", "DE ")):
        text = f"# {before}{title}\n" + "".join(f"## {before}{step}\nText of {step}.\n" for step in steps)
        (folder / f"lesson.{language}.md").write_text(text, encoding="utf-8")
    return folder


def listed(dock) -> set:
    """The ids of the lessons the dock lists."""
    ids = set()
    for top in range(dock.lesson_list.topLevelItemCount()):
        heading = dock.lesson_list.topLevelItem(top)
        ids |= {heading.child(index).data(0, Qt.ItemDataRole.UserRole).id for index in range(heading.childCount())}
    return ids


def click_problems_line(qtbot, dock):
    """Click the "lessons could not be read" line (a link) as a person does."""
    line = dock.problems_line
    qtbot.mouseClick(line, Qt.MouseButton.LeftButton, pos=QPoint(6, line.height() // 2))


@pytest.fixture
def user_lessons():
    """The user's lessons folder (where ``rockly lessons import`` puts packs), emptied afterwards."""
    folder = user_data_dir() / "lessons"
    folder.mkdir(parents=True, exist_ok=True)
    before = set(folder.iterdir())
    yield folder
    for path in set(folder.iterdir()) - before:
        shutil.rmtree(path)


@pytest.fixture
def broken_lesson(user_lessons):
    """A lesson in the user's folder whose goal has a distance below 0 (line 9 of its lesson.yaml)."""
    folder = write_lesson(user_lessons / "stop-early", "stop-early", "Stop early", goals=[
        {"kind": "ends_near", "thing": "wall_front", "within": -1}])
    line = (folder / "lesson.yaml").read_text().splitlines().index("  within: -1") + 1
    return folder, line


def test_a_broken_lesson_is_said_to_the_teacher_under_the_childs_list(qtbot, window, broken_lesson):
    folder, line = broken_lesson
    window.resize(1280, 800)
    choose_robot(qtbot, window, "turtlebot")
    dock = show_lessons(qtbot, window)
    assert "turtlebot-square" in listed(dock) and "stop-early" not in listed(dock)  # the others are all there
    assert dock.problems_line.isVisible() and not dock.problems_text.isVisible()    # one line, closed
    assert dock.problems_line.text().endswith("▸ 1 lesson could not be read</a>")
    said = (f"stop-early (in the folder {folder.parent})\nlesson.yaml, line {line}: goal 1 (ends_near): 'within': "
            "expected a number above 0")
    assert said in dock.problems_line.toolTip()

    click_problems_line(qtbot, dock)
    qtbot.waitUntil(dock.problems_text.isVisible, timeout=5000)
    text = dock.problems_text.toPlainText()
    assert said in text and "The other lessons work." in text
    scroller = dock.widget()   # the dock is short at 1280×800: it scrolls to the problems opened
    qtbot.waitUntil(lambda: dock.problems_text.geometry().bottom() - scroller.verticalScrollBar().value()
                    <= scroller.viewport().height(), timeout=5000)
    assert dock.problems_line.text().endswith("▾ 1 lesson could not be read</a>")
    assert dock.lesson_list.isVisible() and dock.start_button.isVisible()

    window.set_language("de")
    qtbot.waitUntil(lambda: "Zeile" in dock.problems_text.toPlainText(), timeout=5000)
    assert (f"stop-early (im Ordner {folder.parent})\nlesson.yaml, Zeile {line}: Ziel 1 (ends_near): 'within': "
            "erwartet: eine Zahl über 0") in dock.problems_text.toPlainText()
    assert dock.problems_line.text().endswith("▾ 1 Lektion konnte nicht gelesen werden</a>")
    click_problems_line(qtbot, dock)
    qtbot.waitUntil(lambda: not dock.problems_text.isVisible(), timeout=5000)

    start_lesson(qtbot, dock, "turtlebot-square")  # an open lesson has the dock's room: the line goes with the list
    assert not dock.problems_line.isVisible()


def test_no_line_while_every_lesson_reads(qtbot, window, user_lessons):
    choose_robot(qtbot, window, "hobbit")
    dock = show_lessons(qtbot, window)
    assert not dock.problems_line.isVisible() and not dock.problems_text.isVisible()


def test_lessons_imported_changed_and_removed_while_the_window_runs(qtbot, window, user_lessons, tmp_path):
    choose_robot(qtbot, window, "turtlebot")
    dock = show_lessons(qtbot, window)
    window.settings.lessons.mark_passed("turtlebot-square")
    start_lesson(qtbot, dock, "turtlebot-square")
    qtbot.mouseClick(dock.next_button, Qt.MouseButton.LeftButton)
    square_step = dock.step_heading.text()
    assert square_step.startswith("Step 2 of ")

    # a teacher imports a pack while the window runs
    pack = tmp_path / "class-pack"
    write_lesson(pack / "drive-far", "drive-far", "Drive far", steps=("Look", "Drive", "Stop"))
    archive = export_lessons(pack, tmp_path / "class-pack.zip")
    imported = subprocess.run([sys.executable, "-m", "rockly_desktop", "lessons", "import", str(archive)],
                              capture_output=True, text=True, timeout=240, cwd=ROOT)
    assert imported.returncode == 0, imported.stderr
    qtbot.waitUntil(lambda: "drive-far" in listed(dock), timeout=CHANGE_MS)
    assert dock.step_heading.text() == square_step and dock.lesson.id == "turtlebot-square"   # the child's step
    assert lesson_item(dock, "turtlebot-square").text(0).startswith("✓ ")                     # and progress

    # the open lesson's text changes: it stays at its step and shows the new words
    installed = user_lessons / "class-pack" / "drive-far"
    start_lesson(qtbot, dock, "drive-far")
    qtbot.mouseClick(dock.next_button, Qt.MouseButton.LeftButton)
    assert dock.step_heading.text() == "Step 2 of 3: Drive"
    english = installed / "lesson.en.md"
    english.write_text(english.read_text().replace("## Drive\n", "## Drive slowly\n"), encoding="utf-8")
    qtbot.waitUntil(lambda: dock.step_heading.text() == "Step 2 of 3: Drive slowly", timeout=CHANGE_MS)

    # a lesson written with a mistake is said; once fixed it is listed
    broken = write_lesson(user_lessons / "class-pack" / "turn", "turn", "Turn", goals=[{"kind": "spins"}])
    qtbot.waitUntil(lambda: "1 lesson could not be read" in dock.problems_line.text(), timeout=CHANGE_MS)
    qtbot.mouseClick(dock.all_button, Qt.MouseButton.LeftButton)
    assert dock.problems_line.isVisible() and "turn" not in listed(dock)
    write_lesson(broken, "turn", "Turn")
    qtbot.waitUntil(lambda: "turn" in listed(dock) and not dock.problems_line.isVisible(), timeout=CHANGE_MS)

    # the pack removed: its lessons go from the list; the open one stays open at its step until the child leaves it
    shutil.rmtree(user_lessons / "class-pack")
    qtbot.waitUntil(lambda: not {"drive-far", "turn"} & listed(dock), timeout=CHANGE_MS)
    assert dock.lesson.id == "drive-far" and dock.step_heading.text() == "Step 2 of 3: Drive slowly"
    assert lesson_item(dock, "turtlebot-square").text(0).startswith("✓ ")
