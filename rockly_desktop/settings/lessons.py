"""A person's lesson progress: which lessons they passed (kept under ``lessons/`` in Rockly's QSettings,
which belong to the computer's user)."""
from rockly_desktop.settings.group import SettingsGroup


class LessonProgress(SettingsGroup):
    """The lessons passed, by id. A kiosk's visitors get a progress of their own that is never written
    (``kept=False``): every visitor starts afresh and the teacher's own stays untouched."""

    prefix = "lessons"

    def __init__(self, store, kept: bool = True):
        super().__init__(store)
        self._kept = kept
        self._visitor = set()

    def _passed_ids(self) -> set:
        if not self._kept:
            return set(self._visitor)
        value = self._get("passed", [])
        return {value} if isinstance(value, str) else set(value or [])

    def passed(self, lesson_id: str) -> bool:
        """True when the lesson ``lesson_id`` was passed."""
        return lesson_id in self._passed_ids()

    def mark_passed(self, lesson_id: str):
        """Remember that the lesson ``lesson_id`` was passed."""
        if not self._kept:
            self._visitor.add(lesson_id)
            return
        self._set("passed", sorted(self._passed_ids() | {lesson_id}))

    def forget_visitor(self):
        """Start a new visitor's progress (kiosk mode; nothing was written)."""
        self._visitor.clear()
