"""``rockly lessons`` as a teacher types it: list, validate, check a class's folder (with --csv, in German),
the exit status, programs of another robot, and the programs' files left as they were."""
import csv
import hashlib
import io
import shutil
import subprocess
import sys

from lesson_tools import write_lesson
from profile_copies import REPO

PROGRAMS = REPO / "tests" / "lessons" / "programs"


def rockly(*args, timeout=240):
    return subprocess.run([sys.executable, "-m", "rockly_desktop", "lessons", *map(str, args)],
                          capture_output=True, text=True, timeout=timeout, cwd=REPO)


def digest(folder):
    return {path.name: hashlib.sha256(path.read_bytes()).hexdigest() for path in sorted(folder.iterdir())}


def test_list_names_the_shipped_lessons_by_robot_and_level():
    result = rockly("list", "--language", "de", "--robot", "turtlebot")
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert lines[0] == "TurtleBot" and "  Einsteiger (7–10)" in lines and "HOBBIT" not in result.stdout
    assert any(line.split()[:1] == ["turtlebot-stop-at-wall"] and "Halt vor der Wand" in line for line in lines)


def test_validate_says_each_lesson_and_names_a_broken_one(tmp_path):
    write_lesson(tmp_path / "good", goals=[{"kind": "no_bump"}], id="good")
    write_lesson(tmp_path / "bad", goals=[{"kind": "no_bump"}], id="bad", world="moon")
    result = rockly("validate", tmp_path)
    assert result.returncode == 1
    assert f"{tmp_path / 'good'}: the lesson 'good' is fine." in result.stdout
    assert f"BROKEN  {tmp_path / 'bad' / 'lesson.yaml'}:" in result.stderr and "not 'moon'" in result.stderr
    assert rockly("validate", REPO / "lessons").returncode == 0


def test_check_a_class_folder_in_parallel_with_a_table(tmp_path):
    folder = tmp_path / "class"
    folder.mkdir()
    for lesson in ("turtlebot-stop-at-wall", "hobbit-smile"):
        for name in ("solution", "wrong"):
            shutil.copy(PROGRAMS / lesson / f"{name}.rockly", folder / f"{lesson.split('-')[0]}-{name}.rockly")
    before = digest(folder)
    result = rockly("check", "turtlebot-stop-at-wall", folder, "--csv", tmp_path / "grades.csv", "--jobs", "2",
                    "--language", "de")
    assert result.returncode == 1, result.stderr   # not every program passed
    out = result.stdout
    assert "turtlebot-solution.rockly: alle Ziele erreicht." in out
    assert "turtlebot-wrong.rockly: noch nicht alle Ziele erreicht." in out
    assert "[noch nicht] TurtleBot ist nach " in out and "gegen die Wand gestoßen" in out
    assert "hobbit-solution.rockly ist ein Programm für HOBBIT; die Lektion ist für TurtleBot." in out
    rows = list(csv.DictReader(io.StringIO((tmp_path / "grades.csv").read_text())))
    assert [(row["program"], row["passed"], row["ending"]) for row in rows] == [
        ("hobbit-solution.rockly", "0", "not_checked"), ("hobbit-wrong.rockly", "0", "not_checked"),
        ("turtlebot-solution.rockly", "1", "finished"), ("turtlebot-wrong.rockly", "0", "error")]
    assert rows[3]["2:no_bump"] == "0" and rows[2]["2:no_bump"] == "1"
    assert digest(folder) == before   # nothing the check did changed a student's file


def test_check_exits_0_when_every_program_passed():
    lesson = REPO / "lessons" / "hobbit" / "hobbit-smile"
    result = rockly("check", lesson, PROGRAMS / "hobbit-smile" / "solution.rockly")
    assert result.returncode == 0, result.stdout + result.stderr
    assert "solution.rockly: all goals reached." in result.stdout
    assert "[passed] HOBBIT looked “happy” after 0.0 s." in result.stdout
