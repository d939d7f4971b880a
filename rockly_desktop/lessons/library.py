"""Where lessons are and which there are: the shipped ones (``lessons/`` beside the profiles), the user's
(``$XDG_DATA_HOME/rockly/lessons``, where ``rockly lessons import`` puts packs), listed by robot and level.

``LessonLibrary.discover(profiles)`` reads every lesson it finds; a broken one does not hide the others
but is kept in ``problems`` (LessonErrors), so a teacher sees it in ``rockly lessons list``.
"""
from pathlib import Path

from rockly_desktop.core import paths
from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.lessons.goals import GENERIC_GOALS
from rockly_desktop.lessons.lesson import LESSON_FILE, goal_kinds, load_lesson
from rockly_desktop.lessons.lesson_file import LessonError
from rockly_desktop.lessons.schema import LEVELS, lesson_reference_markdown

DEPTH = 3   # a lesson folder lies at most this deep below a lessons folder (a pack's folder, a robot's)


def builtin_lessons_dir() -> Path:
    """The lessons shipped with Rockly."""
    return paths.data_root() / "lessons"


def user_lessons_dir() -> Path:
    """Where the user's lessons and imported lesson packs live."""
    return paths.user_data_dir() / "lessons"


def lesson_roots() -> tuple:
    """The folders lessons are found in, in order: the shipped lessons, then the user's."""
    return builtin_lessons_dir(), user_lessons_dir()


def lesson_folders(folder) -> list:
    """Every folder holding a lesson.yaml in ``folder`` or below it (at most DEPTH deep; hidden folders, such as
    a pack being imported, left out), sorted."""
    folder = Path(folder)
    if (folder / LESSON_FILE).is_file():
        return [folder]
    found = []
    for depth in range(1, DEPTH + 1):
        found += [path.parent for path in folder.glob("/".join(["*"] * depth) + "/" + LESSON_FILE)
                  if not any(part.startswith(".") for part in path.relative_to(folder).parts)]
    return sorted(found)


class LessonLibrary:
    """The lessons found (``lessons``, by id) and the broken ones (``problems``: LessonErrors)."""

    def __init__(self, lessons: dict, problems: list):
        self.lessons = lessons
        self.problems = problems

    @classmethod
    def discover(cls, profiles: dict, folders=None) -> "LessonLibrary":
        """Every lesson in ``folders`` (by default the shipped lessons, then the user's); ``profiles`` is
        {id: Profile}. A lesson whose id an earlier one has is a problem, not a replacement."""
        lessons, problems = {}, []
        for root in folders if folders is not None else lesson_roots():
            for folder in lesson_folders(root) if Path(root).is_dir() else ():
                try:
                    lesson = load_lesson(folder, profiles)
                except LessonError as error:
                    problems.append(error)
                    continue
                if lesson.id in lessons:
                    problems.append(LessonError(folder / LESSON_FILE, 1, app_local_text(
                        "lesson_problem_id_taken", id=lesson.id, folder=lessons[lesson.id].folder)))
                    continue
                lessons[lesson.id] = lesson
        return cls(lessons, problems)

    def get(self, lesson_id: str):
        """The lesson with this id, or None."""
        return self.lessons.get(lesson_id)

    def for_robot(self, robot: str, level: str = None) -> list:
        """The lessons of ``robot`` (a profile id), of ``level`` only when given, in their order."""
        found = [lesson for lesson in self.lessons.values()
                 if lesson.robot == robot and (level is None or lesson.level == level)]
        return sorted(found, key=lambda lesson: (LEVELS.index(lesson.level), lesson.order, lesson.id))

    def by_robot_and_level(self) -> dict:
        """{robot: {level: [lessons in order]}} for every robot and level that has lessons."""
        listing = {}
        for robot in sorted({lesson.robot for lesson in self.lessons.values()}):
            for lesson in self.for_robot(robot):
                listing.setdefault(robot, {}).setdefault(lesson.level, []).append(lesson)
        return listing


def lesson_reference(profiles: dict) -> str:
    """The lesson reference (``rockly lessons reference``; docs/lessons.md holds it): the fields, the goals every
    robot has and each profile's own."""
    own = {}
    for profile in profiles.values():
        added = [kind for kind in goal_kinds(profile).values() if kind not in GENERIC_GOALS]
        if added:
            own[profile.display_name("en")] = added
    return lesson_reference_markdown(GENERIC_GOALS, own)
