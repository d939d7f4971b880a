"""Writing small lessons into a folder and checking code against them, without the editor page."""
from pathlib import Path

import yaml

from rockly_desktop.lessons.check import GeneratedProgram, check_program
from rockly_desktop.lessons.lesson import load_lesson


def write_lesson(folder: Path, robot="turtlebot", goals=(), steps=1, **fields) -> Path:
    """A lesson folder with ``goals`` and ``fields`` (id, level, world... defaulted), English and German."""
    folder.mkdir(parents=True, exist_ok=True)
    data = {"id": "test", "robot": robot, "level": "full", "world": "room" if robot == "turtlebot" else "house",
            "goals": list(goals), **fields}
    (folder / "lesson.yaml").write_text(yaml.safe_dump(data, allow_unicode=True), encoding="utf-8")
    for language, word in (("en", "Step"), ("de", "Schritt")):
        text = "# Test\n" + "".join(f"## {word} {number}\nText.\n" for number in range(1, steps + 1))
        (folder / f"lesson.{language}.md").write_text(text, encoding="utf-8")
    return folder


def program(*lines, workspace=None) -> GeneratedProgram:
    """Generated code of ``lines`` (each a statement; a block id is put before each, b1, b2, ...)."""
    code = "".join(f"__rockly__.block('b{number}')\n{line}\n" for number, line in enumerate(lines, start=1))
    return GeneratedProgram("test.rockly", {"code": code, "variables": []}, workspace or {}, {})


def check(folder, profiles, code_lines, workspace=None, **lesson_fields):
    """The CheckResult of ``code_lines`` against the lesson written with ``lesson_fields`` into ``folder``."""
    lesson = load_lesson(write_lesson(folder, **lesson_fields), profiles)
    return check_program(lesson, program(*code_lines, workspace=workspace))
