"""A lesson's files: every broken one is refused with its file, its line and what was expected, and the
reference in docs/lessons.md is the one the code writes."""
import pytest
import yaml
from lesson_tools import write_lesson
from profile_copies import REPO

from rockly_desktop.lessons.lesson import goal_kinds, load_lesson
from rockly_desktop.lessons.lesson_file import LessonError
from rockly_desktop.lessons.library import lesson_reference
from rockly_desktop.lessons.schema import REFERENCE_END, REFERENCE_START

GOOD = [{"kind": "no_bump"}]


def refused(folder, profiles) -> LessonError:
    with pytest.raises(LessonError) as caught:
        load_lesson(folder, profiles)
    return caught.value


def test_a_good_lesson_is_read_with_its_steps_hints_and_blocks(tmp_path, profiles):
    folder = write_lesson(tmp_path, robot="hobbit", goals=GOOD)
    (folder / "lesson.en.md").write_text("# Smile\nHello!\n## Show a face\nPick happy.\n> Look in Head.\n"
                                         "Blocks: hobbit_emo\nToolbox: hobbit_emo, hobbit_wait\n"
                                         "## Check\nPress Check.\n")
    (folder / "lesson.de.md").write_text("# Lächeln\n## Zeig ein Gesicht\nWähle fröhlich.\n## Prüfen\nDrück Prüfen.\n")
    lesson = load_lesson(folder, profiles)
    assert lesson.title("de") == "Lächeln" and lesson.robot == "hobbit"
    first = lesson.steps("en")[0]
    assert (first.title, first.text, first.hints) == ("Show a face", "Pick happy.", ["Look in Head."])
    assert first.blocks == ["hobbit_emo"] and first.toolbox == ["hobbit_emo", "hobbit_wait"]
    assert lesson.steps("en")[1].toolbox is None
    assert lesson.start == (0.0, 0.0, 0.0) and lesson.time_limit == 120.0


def test_broken_yaml_names_its_line(tmp_path, profiles):
    folder = write_lesson(tmp_path, goals=GOOD)
    (folder / "lesson.yaml").write_text("id: a\nrobot: turtlebot\ngoals: [\n  {kind: no_bump\n")
    error = refused(folder, profiles)
    assert error.path.endswith("lesson.yaml") and error.line >= 4 and "not valid YAML" in error.problem


@pytest.mark.parametrize("change, line, expected", [
    ({"colour": "red"}, "colour", "'colour' is no lesson field"),
    ({"robot": "r2d2"}, "robot", "expected one of the installed robots (hobbit, turtlebot), not 'r2d2'"),
    ({"world": "moon"}, "world", "turtlebot's simulator has the world 'room', not 'moon'"),
    ({"level": "expert"}, "level", "expected one of starter, explorer, full"),
    ({"start": [1.9, -0.1, 0]}, "start", "the robot does not fit at (1.9, -0.1)"),
    ({"goals": [{"kind": "flies"}]}, "kind", "expected one of"),
    ({"goals": [{"kind": "ends_near", "thing": "sofa", "within": 0.2}]}, "thing", "the id of a wall or piece"),
    ({"goals": [{"kind": "ends_near", "thing": "box_1", "within": -1}]}, "within", "expected a number above 0"),
    ({"goals": [{"kind": "within", "goal": "nothing", "seconds": 3}]}, "goal", "the id of another goal"),
    ({"goals": [{"kind": "ends_near", "thing": "box_1", "within": 0.2, "at_least": -0.1}]}, "at_least",
     "expected a number, 0 or more"),
    ({"goals": [{"kind": "ends_near", "thing": "box_1", "within": 0.2, "at_least": 0.3}]}, "at_least",
     "expected 'at_least' (0.3 m) below 'within' (0.2 m)"),
    ({"goals": [{"kind": "ends_near", "thing": "box_1", "within": 0.01}]}, "within",
     "expected 'at_least' (0.02 m) below 'within' (0.01 m)"),
    ({"goals": [{"kind": "no_bump", "speed": 3}]}, "speed", "'speed' is not one of its fields"),
    ({"goals": [{"kind": "uses_block", "block": "hobbit_emo"}]}, "block", "a block type of the lesson's robot"),
])
def test_each_broken_field_is_named_with_its_line(tmp_path, profiles, change, line, expected):
    folder = write_lesson(tmp_path, **{"goals": GOOD, **change})
    error = refused(folder, profiles)
    text = (folder / "lesson.yaml").read_text().splitlines()
    assert expected in error.problem
    assert line in text[error.line - 1], (error.line, text)
    assert str(error).startswith(f"{folder / 'lesson.yaml'}:{error.line}: ")


def test_a_missing_field_is_named(tmp_path, profiles):
    folder = write_lesson(tmp_path, goals=GOOD)
    data = yaml.safe_load((folder / "lesson.yaml").read_text())
    del data["goals"]
    (folder / "lesson.yaml").write_text(yaml.safe_dump(data))
    assert "'goals' is missing" in refused(folder, profiles).problem


@pytest.mark.parametrize("text, line, expected", [
    ("No title\n## Step\n", 1, "expected the title as the first line"),
    ("# Title\nJust words.\n", 2, "expected at least one step"),
    ("# Title\n## Step\nBlocks: hobbit_emo\n", 3, "expected block types of the lesson's robot, not hobbit_emo"),
    ("# Title\n## Step\n# Another title\n", 3, "expected one title only"),
])
def test_broken_markdown_names_its_line(tmp_path, profiles, text, line, expected):
    folder = write_lesson(tmp_path, goals=GOOD)
    (folder / "lesson.de.md").write_text(text)
    error = refused(folder, profiles)
    assert error.path.endswith("lesson.de.md") and error.line == line and expected in error.problem


def test_english_and_german_have_the_same_steps(tmp_path, profiles):
    folder = write_lesson(tmp_path, goals=GOOD, steps=2)
    (folder / "lesson.de.md").write_text("# Titel\n## Schritt\n")
    error = refused(folder, profiles)
    assert error.path.endswith("lesson.de.md") and "expected 2 steps" in error.problem


def test_a_missing_text_and_a_missing_program_are_named(tmp_path, profiles):
    folder = write_lesson(tmp_path / "a", goals=GOOD)
    (folder / "lesson.de.md").unlink()
    assert refused(folder, profiles).problem == "the file is missing"
    folder = write_lesson(tmp_path / "b", goals=GOOD, program="../start.rockly")
    assert "expected a .rockly file in the lesson's folder" in refused(folder, profiles).problem


def test_profiles_add_their_goal_kinds(profiles):
    assert {"shows_emotion", "asks", "arm_at", "gripper", "looks", "shows_text"} <= set(goal_kinds(profiles["hobbit"]))
    assert "follows_wall" in goal_kinds(profiles["turtlebot"]) and "asks" not in goal_kinds(profiles["turtlebot"])


def test_the_docs_hold_the_generated_reference_exactly(profiles):
    text = (REPO / "docs" / "lessons.md").read_text(encoding="utf-8")
    section = text.split(REFERENCE_START + "\n", 1)[1].split(REFERENCE_END, 1)[0]
    assert section == lesson_reference(profiles), "docs/lessons.md is out of date: paste `rockly lessons reference` in"


def test_a_broken_lesson_is_said_in_german_too(tmp_path, profiles):
    folder = write_lesson(tmp_path, goals=[{"kind": "ends_near", "thing": "box_1", "within": -1}])
    error = refused(folder, profiles)
    assert error.in_language("de").endswith("Ziel 1 (ends_near): 'within': erwartet: eine Zahl über 0")
    assert str(error).endswith("goal 1 (ends_near): 'within': expected a number above 0")
