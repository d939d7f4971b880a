"""A tablet that answers from a list given on the command line (``rockly run``/``rockly sim --answer``)."""
import threading

from rockly_desktop.core.errors import RobotCommandError


class AnswerList:
    """A tablet that answers from a list given on the command line.

    With ``then`` (another tablet: ``rockly sim``'s window), questions that come after the
    list has run out are passed on to it; without, they fail clearly.
    """

    def __init__(self, answers, out, then=None):
        self._answers = list(answers)
        self._out = out
        self._then = then
        self._lock = threading.Lock()  # ROS may ask two questions at once

    def ask(self, kind, text, timeout, interrupt) -> str:
        """Take the next answer (OK dialogs need none while answers are left); when none is
        left, ask ``then`` (OK dialogs included) or fail clearly."""
        self._out(f"tablet  {kind}: {text!r}")
        with self._lock:
            left = bool(self._answers)
            answer = self._answers.pop(0) if left and kind != "D_OK" else None
        if not left and self._then is not None:
            self._out("asking in the window")
            answer = self._then.ask(kind, text, timeout, interrupt)
        elif kind == "D_OK":
            return ""
        elif answer is None:
            raise RobotCommandError(f"the program asks on the tablet {text!r}, but no --answer is left for it")
        self._out(f"answer  {answer!r}")
        return answer

    def notify(self, kind, text):
        """Show a message or function on the terminal (and in the window, if there is one)."""
        self._out(f"tablet  {kind}: {text!r}")
        if self._then is not None:
            self._then.notify(kind, text)
