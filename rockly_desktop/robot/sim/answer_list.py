"""A tablet that answers from a list given on the command line (``rockly run``/``rockly sim --answer``)."""
import threading

from rockly_desktop.core.app_texts import app_local_text, app_text
from rockly_desktop.core.errors import RobotCommandError
from rockly_desktop.robot.sim.tablet import TabletQuestion


class AnswerList:
    """A tablet that answers from a list given on the command line.

    With ``then`` (another tablet: ``rockly sim``'s window), questions that come after the
    list has run out are passed on to it; without, they fail clearly.
    """

    def __init__(self, answers, out, then=None, language: str = "en"):
        self._language = language   # of the lines it writes to ``out``
        self._answers = list(answers)
        self._out = out
        self._then = then
        self._lock = threading.Lock()  # ROS may ask two questions at once

    def ask(self, question: TabletQuestion, text, timeout, interrupt) -> str:
        """Take the next answer (an OK question needs none while answers are left); when none
        is left, ask ``then`` (OK questions included) or fail clearly."""
        kind = app_text(f"cli_kind_{TabletQuestion(question).value}", self._language)
        self._out(app_text("cli_tablet", self._language, kind=kind, text=repr(text)))
        with self._lock:
            left = bool(self._answers)
            answer = self._answers.pop(0) if left and question != TabletQuestion.OK else None
        if not left and self._then is not None:
            self._out(app_text("cli_asking_window", self._language))
            answer = self._then.ask(question, text, timeout, interrupt)
        elif question == TabletQuestion.OK:
            return ""
        elif answer is None:
            raise RobotCommandError(app_local_text("answer_list_empty", text=repr(text)))
        self._out(app_text("cli_answer", self._language, answer=repr(answer)))
        return answer

    def notify(self, text):
        """Show a message on the terminal (and in the window, if there is one)."""
        self._out(app_text("cli_tablet_notice", self._language, text=repr(text)))
        if self._then is not None:
            self._then.notify(text)
