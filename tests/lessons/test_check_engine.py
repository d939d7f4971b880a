"""The check engine: simulated time as fast as the machine allows, a time limit, a program that lets no time
pass, a program that raises, blocks beyond the level; and the lessons found and shared as packs."""
import zipfile

import pytest
from lesson_tools import check, program, write_lesson
from profile_copies import REPO
from program_builder import block, workspace

from rockly_desktop.lessons.archive import export_lessons, import_lessons
from rockly_desktop.lessons.check import check_program, summary
from rockly_desktop.lessons.lesson import load_lesson
from rockly_desktop.lessons.lesson_file import LessonError
from rockly_desktop.lessons.library import LessonLibrary

NO_BUMP = [{"kind": "no_bump"}]


def test_a_twenty_second_drive_is_checked_in_simulated_time(tmp_path, profiles):
    # how fast a check runs is benchmarks/lessons_check.py's figure (about 0.5 s for this drive)
    result = check(tmp_path, profiles, ["robot.drive(3.0)"], goals=NO_BUMP, robot="turtlebot", start=[0, -1, 0])
    assert result.ending == "finished" and 19.5 < result.time < 21.5   # 3 m at 0.15 m/s, slowing at the end


def test_hobbit_waits_in_simulated_time(tmp_path, profiles):
    result = check(tmp_path, profiles, ["robot.wait(30)", "robot.move_arm('table')"], goals=NO_BUMP, robot="hobbit")
    assert result.ending == "finished" and result.time == pytest.approx(34.0, abs=0.1)


def test_a_program_that_never_ends_is_stopped_at_the_time_limit(tmp_path, profiles):
    result = check(tmp_path, profiles, ["while True:\n    robot.wait(1)"], goals=NO_BUMP, time_limit=15)
    assert result.ending == "time_limit" and not result.passed
    assert result.ending_text.in_language("en") == "The program did not end within 15 s. The check stopped it."
    assert result.ending_text.in_language("de").startswith("Das Programm war nach 15 s noch nicht fertig.")
    assert 15 <= result.time < 16.1 and result.failing[1] == "b1"


def test_a_loop_of_blocks_that_does_not_wait_still_lets_time_pass(tmp_path, profiles):
    result = check(tmp_path, profiles, ["while True:\n    __rockly__.block('inner')\n    robot.distance('ahead')"],
                   goals=NO_BUMP, time_limit=2)
    assert result.ending == "time_limit" and result.failing[1] == "inner"


def test_a_loop_where_no_time_passes_is_stopped_on_the_real_clock(tmp_path, profiles):
    lesson = load_lesson(write_lesson(tmp_path, goals=NO_BUMP), profiles)
    result = check_program(lesson, program("while True:\n    __rockly__.check()"), real_seconds=0.5)
    assert result.ending == "stuck" and not result.passed
    assert "no time passes" in result.ending_text.in_language("en")


def test_a_program_that_raises_says_its_error_and_where(tmp_path, profiles):
    result = check(tmp_path, profiles, ["robot.wait(2)", "robot.drive('far')"], goals=NO_BUMP)
    assert result.ending == "error" and not result.passed
    assert result.ending_text.in_language("en").startswith("The program stopped with an error: ")
    assert result.failing == (pytest.approx(2.0, abs=0.05), "b2")
    assert summary(result, "de")["ending_words"].startswith("Das Programm hat mit einem Fehler angehalten")


def test_blocks_beyond_the_lessons_level_fail_a_line_of_their_own(tmp_path, profiles):
    blocks = workspace(block("turtlebot_stop", next_block=block("turtlebot_drive_for")))
    result = check(tmp_path, profiles, ["pass"], workspace=blocks, goals=NO_BUMP, level="starter")
    assert [goal.kind for goal in result.goals] == ["no_bump", "level"]
    assert result.goals[1].words("en") == ("The program uses blocks that are not in the level Starter (7–10): "
                                           "turtlebot_drive_for.")
    assert not result.passed


def test_the_library_lists_lessons_by_robot_and_level_and_keeps_broken_ones(tmp_path, profiles):
    write_lesson(tmp_path / "pack" / "b", goals=NO_BUMP, id="b", level="starter", order=2)
    write_lesson(tmp_path / "pack" / "a", goals=NO_BUMP, id="a", level="starter", order=1)
    write_lesson(tmp_path / "pack" / "h", robot="hobbit", goals=NO_BUMP, id="h", level="explorer")
    write_lesson(tmp_path / "pack" / "twice", goals=NO_BUMP, id="a")
    write_lesson(tmp_path / "pack" / "broken", goals=[{"kind": "flies"}], id="broken")
    write_lesson(tmp_path / "pack" / ".import-x1" / "c", goals=NO_BUMP, id="c")  # a pack being imported: not yet
    library = LessonLibrary.discover(profiles, [tmp_path / "pack"])
    listing = library.by_robot_and_level()
    assert {robot: {level: [lesson.id for lesson in lessons] for level, lessons in levels.items()}
            for robot, levels in listing.items()} == {"hobbit": {"explorer": ["h"]},
                                                      "turtlebot": {"starter": ["a", "b"]}}
    assert sorted(error.path.split("/")[-2] for error in library.problems) == ["broken", "twice"]


def test_a_pack_goes_to_one_zip_and_back(tmp_path, profiles):
    write_lesson(tmp_path / "my-pack" / "one", goals=NO_BUMP, id="one")
    zipped = export_lessons(tmp_path / "my-pack", tmp_path / "out" / "pack.zip")
    installed = import_lessons(zipped, profiles, folder=tmp_path / "user")
    assert installed == tmp_path / "user" / "my-pack"
    assert load_lesson(installed / "one", profiles).id == "one"
    with pytest.raises(LessonError, match="installed already"):
        import_lessons(zipped, profiles, folder=tmp_path / "user")
    assert import_lessons(zipped, profiles, folder=tmp_path / "user", replace=True) == installed


def test_an_unsafe_or_broken_pack_installs_nothing(tmp_path, profiles):
    unsafe = tmp_path / "unsafe.zip"
    with zipfile.ZipFile(unsafe, "w") as archive:
        archive.writestr("pack/../../evil/lesson.yaml", "id: x")
    with pytest.raises(LessonError, match="unsafe entry"):
        import_lessons(unsafe, profiles, folder=tmp_path / "user")
    write_lesson(tmp_path / "bad" / "one", goals=[{"kind": "flies"}])
    zipped = export_lessons(tmp_path / "bad", tmp_path / "bad.zip")
    with pytest.raises(LessonError) as caught:
        import_lessons(zipped, profiles, folder=tmp_path / "user")
    assert caught.value.path == f"{zipped}: bad/one/lesson.yaml" and caught.value.line == 2
    assert not (tmp_path / "user" / "bad").exists() and list((tmp_path / "user").iterdir()) == []


def test_the_readmes_example_lesson_is_valid_and_its_first_try_passes(tmp_path, profiles):
    readme = (REPO / "README.md").read_text(encoding="utf-8").split("## Lessons and challenges", 1)[1]
    yaml_text = readme.split("```yaml\n", 1)[1].split("```", 1)[0]
    steps = readme.split("```markdown\n", 1)[1].split("```", 1)[0]
    (tmp_path / "lesson.yaml").write_text(yaml_text, encoding="utf-8")
    (tmp_path / "lesson.en.md").write_text(steps, encoding="utf-8")
    (tmp_path / "lesson.de.md").write_text(steps, encoding="utf-8")
    lesson = load_lesson(tmp_path, profiles)
    assert check_program(lesson, program("robot.drive(3)")).passed
    into_the_wall = check_program(lesson, program("robot.drive(3.5)"))   # 0 cm from the wall: too close, a bump
    assert [goal.passed for goal in into_the_wall.goals] == [False, False]
    assert "too close" in into_the_wall.goals[0].words("en")


def test_a_recorded_check_replays_in_simulated_time_at_its_failing_moment(tmp_path, profiles):
    from rockly_desktop.recording.moments import Moments
    from rockly_desktop.recording.reading import read_recording

    lesson = load_lesson(write_lesson(tmp_path / "lesson", goals=NO_BUMP, start=[0, 0, 0]), profiles)
    result = check_program(lesson, program("robot.drive(1.0)", "robot.drive(1.0)"), record=tmp_path / "try.mcap",
                           program_bytes=b"{}")
    failing_time, failing_block = result.failing
    assert failing_block == "b2" and 9 < failing_time < 12.5
    recording = read_recording(tmp_path / "try.mcap")
    assert recording.complete and recording.metadata["world"] and recording.program == b"{}"
    moments = Moments(recording)
    assert moments.duration == pytest.approx(result.time, abs=0.1)   # the timeline is the simulated one
    at_failing = moments.at(failing_time)
    assert at_failing.block == "b2" and moments.at(failing_time - 5).block == "b2"
    assert moments.at(2.0).block == "b1"
    assert at_failing.snapshot["x"] == pytest.approx(1.9 - 0.105, abs=0.02)   # touching the red box
    assert moments.at(3.0).snapshot["x"] == pytest.approx(0.45, abs=0.1)   # 0.15 m/s: driving on sim time


def test_a_check_is_the_same_every_time_goal_threads_and_all(tmp_path, profiles):
    goals = [{"kind": "arm_at", "pose": "table"}, {"kind": "gripper", "state": "open"}]
    lesson = load_lesson(write_lesson(tmp_path, robot="hobbit", goals=goals), profiles)
    code = program("robot.navigate_to(1.5, -1.0, 90)", "robot.move_arm('table')", "robot.gripper('open')")
    times = {tuple(goal.words("en") for goal in result.goals) + (result.time,)
             for result in (check_program(lesson, code) for _ in range(3))}
    assert len(times) == 1, times
