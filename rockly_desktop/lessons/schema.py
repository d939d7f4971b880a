"""What a lesson's ``lesson.yaml`` and its goals may hold: one table, read by the validation and the reference.

A field's ``kind`` says what its value must be; ``docs/lessons.md`` holds the reference this module
writes (``lesson_reference_markdown``), and a test keeps the two the same.
"""
import math
import re
from dataclasses import dataclass

from rockly_desktop.core.app_texts import app_local_text

LEVELS = ("starter", "explorer", "full")
IDENTIFIER = re.compile(r"^[a-z][a-z0-9_-]{0,63}$")

KIND_EXPECTED = {
    "text": app_local_text("lesson_expect_text"),
    "identifier": app_local_text("lesson_expect_identifier"),
    "number": app_local_text("lesson_expect_number"),
    "positive": app_local_text("lesson_expect_positive"),
    "not_negative": app_local_text("lesson_expect_not_negative"),
    "count": app_local_text("lesson_expect_count"),
    "level": app_local_text("lesson_expect_level", levels=", ".join(LEVELS)),
    "pose": app_local_text("lesson_expect_pose"),
    "rect": app_local_text("lesson_expect_rect"),
    "area": app_local_text("lesson_expect_area"),
    "thing": app_local_text("lesson_expect_thing"),
    "goal": app_local_text("lesson_expect_goal"),
    "block": app_local_text("lesson_expect_block"),
    "texts": app_local_text("lesson_expect_texts"),
    "bool": app_local_text("lesson_expect_bool", values="true, false"),
    "words": app_local_text("lesson_expect_words"),
    "areas": app_local_text("lesson_expect_areas"),
    "goals": app_local_text("lesson_expect_goals"),
}


@dataclass(frozen=True)
class Field:
    """One field: its name, the kind of value, whether it must be there, what it means; ``choices`` for a choice."""

    name: str
    kind: str
    required: bool
    meaning: str
    choices: tuple = ()

    @property
    def expected(self):
        """What the value must be, in words (a LocalText: ``str()`` is English)."""
        if self.choices:
            return app_local_text("lesson_expect_choice", choices=", ".join(str(choice) for choice in self.choices))
        return KIND_EXPECTED[self.kind]


LESSON_FIELDS = (
    Field("id", "identifier", True, "The lesson's id, unique among the lessons (progress is kept by it)."),
    Field("robot", "identifier", True, "The id of the robot profile the lesson is for."),
    Field("level", "level", True, "Starter (7–10), Explorer (11–14) or Full: the toolbox level it is written for."),
    Field("order", "count", False, "Where it comes in the list of its robot and level (default 0)."),
    Field("world", "identifier", True, "The simulated world it happens in: the id its simulator gives it (WORLD_ID)."),
    Field("start", "pose", False, "Where the robot starts: [x, y, heading in degrees] (default [0, 0, 0])."),
    Field("program", "text", False, "A .rockly file in the lesson's folder the child starts from."),
    Field("time_limit", "positive", False,
          "Simulated seconds a program may run before the check stops it and says so (default 120)."),
    Field("answers", "texts", False, "What a person answers on the robot's tablet during the check, in order."),
    Field("areas", "areas", False,
          "Named places on the world's map: {NAME: {rect: [x0, y0, x1, y1], name: {en: the kitchen, de: die Küche}}}."),
    Field("goals", "goals", True, "What the program must make the robot do: a list of goals (below), each a kind."),
)
GOAL_COMMON = (
    Field("kind", "identifier", True, "The goal's kind (the table below)."),
    Field("id", "identifier", False, "A name other goals (before, within) refer to it by."),
    Field("name", "words", False, "What a child reads for it when another goal names it: {en: .., de: ..}."),
)


def check_value(field: Field, value, names: dict):
    """None when ``value`` fits ``field``, else what was expected, a LocalText (``names``: kind -> the names that
    exist)."""
    kind = field.kind
    if field.choices:
        return None if value in field.choices else field.expected
    if kind in ("text",):
        return None if isinstance(value, str) and value.strip() else field.expected
    if kind == "identifier":
        return None if isinstance(value, str) and IDENTIFIER.match(value) else field.expected
    if kind == "bool":
        return None if isinstance(value, bool) else field.expected
    if kind in ("number", "positive", "not_negative", "count"):
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
            return field.expected
        if (kind == "positive" and value <= 0 or kind == "not_negative" and value < 0
                or kind == "count" and (value < 0 or int(value) != value)):
            return field.expected
        return None
    if kind == "level":
        return None if value in LEVELS else field.expected
    if kind in ("pose", "rect"):
        size = 3 if kind == "pose" else 4
        if not (isinstance(value, list) and len(value) == size
                and all(isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) for v in value)):
            return field.expected
        if kind == "rect" and not (value[0] < value[2] and value[1] < value[3]):
            return field.expected
        return None
    if kind == "words":
        good = isinstance(value, dict) and isinstance(value.get("en"), str) and all(
            isinstance(text, str) and text.strip() for text in value.values())
        return None if good else field.expected
    if kind == "texts":
        return None if isinstance(value, list) and all(isinstance(v, str) for v in value) else field.expected
    if kind in ("area", "thing", "goal", "block"):
        known = names.get(kind, ())
        if isinstance(value, str) and value in known:
            return None
        shown = ", ".join(sorted(known)[:12]) or "-"
        return app_local_text("lesson_expect_names", expected=field.expected, names=shown)
    raise ValueError(f"unknown field kind {kind!r}")


def _cell(text: str) -> str:
    return text.replace("|", "\\|").replace("<", "&lt;").replace(">", "&gt;")


def goal_table(goal_kinds) -> list:
    """The Markdown rows of a table of ``goal_kinds`` (LessonGoal classes)."""
    rows = ["| Goal kind | Fields | Meaning |", "| --- | --- | --- |"]
    for goal in goal_kinds:
        fields = "; ".join(f"`{field.name}`{'' if field.required else ' (optional)'}: {field.expected}"
                           for field in goal.fields) or "none"
        rows.append(f"| `{goal.kind}` | {_cell(fields)} | {_cell(goal.meaning)} |")
    return rows


def lesson_reference_markdown(generic_kinds, profile_kinds: dict) -> str:
    """The reference of ``lesson.yaml``, the ``generic_kinds`` of goals and each profile's own
    (``profile_kinds``: {robot name: [LessonGoal classes]}), as Markdown."""
    rows = ["| Field | Required | Meaning |", "| --- | --- | --- |"]
    rows += [f"| `{field.name}` | {'yes' if field.required else 'no'} | {_cell(field.meaning)} |"
             for field in LESSON_FIELDS]
    rows += ["", "Every goal has:", "", "| Field | Required | Meaning |", "| --- | --- | --- |"]
    rows += [f"| `{field.name}` | {'yes' if field.required else 'no'} | {_cell(field.meaning)} |"
             for field in GOAL_COMMON]
    rows += ["", "Goals every robot has:", ""] + goal_table(generic_kinds)
    for robot, kinds in sorted(profile_kinds.items()):
        rows += ["", f"Goals {robot} adds (its profile's `lesson_goals`):", ""] + goal_table(kinds)
    return "\n".join(rows) + "\n"


REFERENCE_START = "<!-- lesson reference: generated by `rockly lessons reference` -->"
REFERENCE_END = "<!-- end of the lesson reference -->"
