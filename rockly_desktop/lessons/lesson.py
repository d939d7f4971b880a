"""A lesson read from its folder: ``lesson.yaml`` (robot, level, world, start, goals) and its text per language.

``load_lesson(folder, profiles)`` checks everything a child would otherwise meet broken: the YAML,
every field against ``schema.LESSON_FIELDS``, the robot and its world, the areas, each goal against
its kind's fields, the texts in English and German (the same steps in both), the start program.
Each problem is a LessonError naming the file, the line and what was expected.
"""
import math
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.lessons.goals import GENERIC_GOALS, Area, GoalContext, Words, known_blocks
from rockly_desktop.lessons.lesson_file import LessonError, read_located
from rockly_desktop.lessons.schema import GOAL_COMMON, LESSON_FIELDS, Field, check_value
from rockly_desktop.lessons.steps import read_steps

LESSON_FILE = "lesson.yaml"
LANGUAGES = ("en", "de")
DEFAULT_TIME_LIMIT = 120.0


def text_file(language: str) -> str:
    """The name of a lesson's text in ``language``: ``lesson.LANG.md``."""
    return f"lesson.{language}.md"


def is_lesson_folder(path) -> bool:
    """True when ``path`` is a folder holding a lesson.yaml."""
    return (Path(path) / LESSON_FILE).is_file()


@dataclass
class Lesson:
    """A checked lesson. ``texts`` is {language: LessonText}; ``goals`` the goals' data in order;
    ``areas`` {name: Area}; ``start`` (x, y, heading in degrees); ``program`` the start program's path or None."""

    folder: Path
    id: str
    profile: object
    level: str
    order: int
    world: str
    start: tuple
    time_limit: float
    answers: list
    areas: dict
    goals: list
    texts: dict
    program: Path = None
    goal_kinds: dict = field(default_factory=dict, repr=False)

    @property
    def robot(self) -> str:
        """The id of the lesson's robot profile."""
        return self.profile.id

    def title(self, language: str = "en") -> str:
        """The lesson's title in ``language`` (English when it has no text in it)."""
        return (self.texts.get(language) or self.texts["en"]).title

    def steps(self, language: str = "en") -> list:
        """The lesson's steps (``steps.Step``) in ``language`` (English when it has no text in it)."""
        return (self.texts.get(language) or self.texts["en"]).steps

    def make_goals(self, workspace: dict) -> list:
        """Fresh goal objects for one check of a program whose blocks are ``workspace``."""
        context = GoalContext(self.profile.display_name("en"), world_of(self.profile), self.areas, self.profile,
                              workspace=workspace or {})
        goals = [self.goal_kinds[spec["kind"]](spec, context) for spec in self.goals]
        context.goals = {goal.id: goal for goal in goals if goal.id}
        return goals


def goal_kinds(profile) -> dict:
    """{kind: LessonGoal class}: the generic kinds and those the profile's manifest names in ``lesson_goals``."""
    kinds = {goal.kind: goal for goal in GENERIC_GOALS}
    kinds.update((goal.kind, goal) for goal in profile.lesson_goals())
    return kinds


@lru_cache(maxsize=None)
def _simulator_of(profile):
    from rockly_desktop.robot.sim.sim_world import SimWorld

    return profile.create("simulator", SimWorld())   # never started: only its world and its names are read


def world_of(profile):
    """The solid World (obstacles, footprint) of the profile's simulator."""
    return _simulator_of(profile).solid_world


def world_name(profile) -> str:
    """The name lessons give the world of the profile's simulator."""
    return _simulator_of(profile).WORLD_ID


def load_lesson(folder, profiles: dict) -> Lesson:
    """The lesson in ``folder``, checked; ``profiles`` is {id: Profile}. Raises LessonError."""
    folder = Path(folder)
    located = read_located(folder / LESSON_FILE)
    data = located.data
    if not isinstance(data, dict):
        raise located.error(app_local_text("lesson_problem_not_mapping", fields="id: ..., robot: ..., goals: ..."))
    known = {spec.name: spec for spec in LESSON_FIELDS}
    for key in data:
        if key not in known:
            raise located.error(app_local_text("lesson_problem_unknown_field", field=key, known=", ".join(known)), key)
    for spec in LESSON_FIELDS:
        if spec.required and spec.name not in data:
            raise located.error(app_local_text("lesson_problem_field_missing", field=spec.name))
        if spec.name in data and spec.kind not in ("areas", "goals"):
            problem = check_value(spec, data[spec.name], {})
            if problem:
                raise located.error(app_local_text("lesson_problem_field", field=spec.name, expected=problem),
                                    spec.name)
    profile = profiles.get(data["robot"])
    if profile is None:
        raise located.error(app_local_text("lesson_problem_robot", robots=", ".join(sorted(profiles)),
                                           robot=data["robot"]), "robot")
    if not profile.has_simulator:
        raise located.error(app_local_text("lesson_problem_no_simulator", robot=profile.id), "robot")
    if data["world"] != world_name(profile):
        raise located.error(app_local_text("lesson_problem_world", robot=profile.id, known=world_name(profile),
                                           world=data["world"]), "world")
    world = world_of(profile)
    start = tuple(float(value) for value in data.get("start", (0.0, 0.0, 0.0)))
    if world is not None and not (world.in_area(start[0], start[1]) and world.fits(start[0], start[1])):
        raise located.error(app_local_text("lesson_problem_start", x=start[0], y=start[1]), "start")
    areas = _areas(located, data.get("areas", {}))
    kinds = goal_kinds(profile)
    goals = _goals(located, data["goals"], kinds, {
        "area": set(areas), "thing": {obstacle.id for obstacle in (world.obstacles if world else ())},
        "block": known_blocks(profile)})
    texts = _texts(folder, profile)
    program = None
    if data.get("program"):
        program = folder / data["program"]
        if not program.is_file() or program.resolve().parent != folder.resolve():
            raise located.error(app_local_text("lesson_problem_program", program=data["program"]), "program")
    return Lesson(folder, data["id"], profile, data["level"], int(data.get("order", 0)), data["world"],
                  (start[0], start[1], start[2]), float(data.get("time_limit", DEFAULT_TIME_LIMIT)),
                  list(data.get("answers", [])), areas, goals, texts, program, kinds)


def _areas(located, data) -> dict:
    if not isinstance(data, dict):
        raise located.error(app_local_text("lesson_problem_areas"), "areas")
    areas = {}
    for name, entry in data.items():
        where = ("areas", name)
        if not isinstance(entry, dict) or set(entry) - {"rect", "name"} or "rect" not in entry:
            raise located.error(app_local_text("lesson_problem_area", area=name), *where)
        problem = check_value(Field("rect", "rect", True, ""), entry["rect"], {})
        if problem:
            raise located.error(app_local_text("lesson_problem_area_rect", area=name, expected=problem), *where, "rect")
        label = entry.get("name", {"en": name})
        if not (isinstance(label, dict) and isinstance(label.get("en"), str)
                and all(isinstance(text, str) for text in label.values())):
            raise located.error(app_local_text("lesson_problem_area_name", area=name), *where, "name")
        areas[str(name)] = Area(tuple(float(v) for v in entry["rect"]), Words(label))
    return areas


def _goals(located, data, kinds: dict, names: dict) -> list:
    if not isinstance(data, list) or not data:
        raise located.error(app_local_text("lesson_problem_goals"), "goals")
    ids = {entry.get("id") for entry in data if isinstance(entry, dict) and isinstance(entry.get("id"), str)}
    names = dict(names, goal=ids)
    seen = set()
    for index, entry in enumerate(data):
        where = ("goals", index)
        if not isinstance(entry, dict):
            raise located.error(app_local_text("lesson_problem_goal", number=index + 1), *where)
        kind = kinds.get(entry.get("kind"))
        if kind is None:
            raise located.error(app_local_text("lesson_problem_goal_kind", number=index + 1,
                                               known=", ".join(sorted(kinds)), kind=entry.get("kind")),
                                *where, "kind")
        fields = {spec.name: spec for spec in GOAL_COMMON + tuple(kind.fields)}
        for key in entry:
            if key not in fields:
                raise located.error(app_local_text("lesson_problem_goal_field", number=index + 1, kind=kind.kind,
                                                   field=key, known=", ".join(fields)), *where, key)
        for spec in fields.values():
            if spec.name == "kind":
                continue
            if spec.name not in entry:
                if spec.required:
                    raise located.error(app_local_text("lesson_problem_goal_missing", number=index + 1, kind=kind.kind,
                                                       field=spec.name), *where)
                continue
            problem = check_value(spec, entry[spec.name], names)
            if problem:
                raise located.error(app_local_text("lesson_problem_goal_value", number=index + 1, kind=kind.kind,
                                                   field=spec.name, expected=problem), *where, spec.name)
        mismatch = kind.spec_problem(entry)
        if mismatch:
            field, expected = mismatch
            raise located.error(app_local_text("lesson_problem_goal_value", number=index + 1, kind=kind.kind,
                                               field=field, expected=expected), *where, field)
        if entry.get("id") is not None and entry["id"] in seen:
            raise located.error(app_local_text("lesson_problem_goal_twice", number=index + 1, id=entry["id"]),
                                *where, "id")
        seen.add(entry.get("id"))
        if any(entry.get(name) == entry.get("id") for name in ("first", "then", "goal") if entry.get("id")):
            raise located.error(app_local_text("lesson_problem_goal_itself", number=index + 1), *where)
    return [dict(entry) for entry in data]


def _texts(folder: Path, profile) -> dict:
    blocks = known_blocks(profile)
    texts = {language: read_steps(folder / text_file(language), blocks) for language in LANGUAGES}
    english = len(texts["en"].steps)
    for language, text in texts.items():
        if len(text.steps) != english:
            raise LessonError(folder / text_file(language), 0, app_local_text(
                "lesson_problem_steps", steps=english, english=text_file("en"), found=len(text.steps)))
    return texts


def start_heading(lesson: Lesson) -> float:
    """The lesson's start heading in radians."""
    return math.radians(lesson.start[2])
