"""A lesson's check run off the window's thread: ``lessons.check.check_program`` takes about a second.

``LessonCheck.start(lesson, program, record)`` checks a ``check.GeneratedProgram`` in a thread of its
own, recording the run to ``record``; ``sig_checked(result, record)`` (a ``CheckResult``) or
``sig_failed(text)`` (in the window's language) come back in the window's thread. One check at a time.
"""
import threading

from PySide6.QtCore import QObject, Signal

from rockly_desktop.core.errors import RocklyError
from rockly_desktop.ui.texts import tr


class LessonCheck(QObject):
    """Checks one program at a time against a lesson, off the window's thread."""

    sig_checked = Signal(object, str)  # the CheckResult, the recording's path
    sig_failed = Signal(str)  # why the check could not run

    def __init__(self, language, parent=None):
        super().__init__(parent)
        self._language = language  # () -> the window's language
        self._thread = None

    @property
    def running(self) -> bool:
        """True while a check runs."""
        return self._thread is not None and self._thread.is_alive()

    def start(self, lesson, program, record) -> bool:
        """Check ``program`` against ``lesson``, recording the run to ``record``; False when one already runs."""
        if self.running:
            return False
        self._thread = threading.Thread(target=self._check, args=(lesson, program, str(record)),
                                        name="lesson-check", daemon=True)
        self._thread.start()
        return True

    def _check(self, lesson, program, record: str):
        language = self._language()
        try:
            from rockly_desktop.lessons.check import check_program  # the simulator, recordings: when checked

            result = check_program(lesson, program, language, record=record)
        except (RocklyError, OSError) as error:
            text = error.in_language(language) if isinstance(error, RocklyError) else str(error)
            self.sig_failed.emit(tr("lessons_cannot_check", language, error=text))
            return
        self.sig_checked.emit(result, record)

    def wait(self, timeout: float = 30.0) -> bool:
        """Wait for a running check to end (the window closes); True when none runs."""
        if self._thread is not None:
            self._thread.join(timeout)
        return not self.running
