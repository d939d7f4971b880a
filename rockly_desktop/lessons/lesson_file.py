"""Reading a lesson's YAML with the line of every value, and the error that names file, line and what was expected."""
from pathlib import Path

import yaml

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import RocklyError
from rockly_desktop.core.yaml_nesting import too_deep

MAX_BYTES = 256 * 1024   # a lesson's file is a page of text


class LessonError(RocklyError):
    """A lesson (or a lesson pack) is broken: ``path``, ``line`` (1-based, 0 when unknown) and what was expected
    (``problem``: a catalogue's LocalText, ``in_language`` says it in any language; ``str()`` is English)."""

    def __init__(self, path, line: int, problem):
        self.path = str(path)
        self.line = int(line or 0)
        self._problem = problem
        self.problem = str(problem)
        super().__init__(f"{self.where}: {self.problem}")

    @property
    def where(self) -> str:
        """``path:line`` (the path alone when the line is not known)."""
        return f"{self.path}:{self.line}" if self.line else self.path

    def in_language(self, language: str) -> str:
        """``path:line: problem`` with the problem in ``language``."""
        return f"{self.where}: {self.problem_in(language)}"

    def problem_in(self, language: str) -> str:
        """What was expected (the problem alone, without the file and line), in ``language``."""
        problem = self._problem
        return problem.in_language(language) if hasattr(problem, "in_language") else str(problem)


class Located:
    """A YAML file's data and where each value is: ``line(*keys)`` is the line of the value at that path."""

    def __init__(self, path, data, lines: dict):
        self.path = Path(path)
        self.data = data
        self._lines = lines

    def line(self, *keys) -> int:
        """The line of the value at ``keys`` (a mapping's keys and a list's indexes), or of its nearest parent."""
        keys = tuple(keys)
        while keys and keys not in self._lines:
            keys = keys[:-1]
        return self._lines.get(keys, 1)

    def error(self, problem, *keys) -> LessonError:
        """A LessonError at the value at ``keys``."""
        return LessonError(self.path, self.line(*keys), problem)


def read_text(path) -> str:
    """The UTF-8 text of ``path``; LessonError when it is missing, too large or not text."""
    path = Path(path)
    try:
        if path.stat().st_size > MAX_BYTES:
            raise LessonError(path, 0, app_local_text("lesson_problem_too_large", kilobytes=MAX_BYTES // 1024))
        return path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise LessonError(path, 0, app_local_text("lesson_problem_missing_file")) from None
    except UnicodeDecodeError as error:
        raise LessonError(path, 0, app_local_text("lesson_problem_not_utf8", reason=error.reason)) from None
    except OSError as error:
        raise LessonError(path, 0, app_local_text("lesson_problem_unreadable",
                                                  reason=error.strerror or error)) from None


def read_located(path) -> Located:
    """``path`` read as YAML with every value's line; LessonError for broken YAML (with its line)."""
    text = read_text(path)
    if too_deep(text):
        raise LessonError(path, 0, app_local_text("lesson_problem_too_deep"))
    try:
        node = yaml.compose(text, Loader=yaml.SafeLoader)
        data = yaml.safe_load(text)
    except yaml.MarkedYAMLError as error:
        mark = error.problem_mark or error.context_mark
        raise LessonError(path, mark.line + 1 if mark else 0,
                          app_local_text("lesson_problem_yaml", problem=error.problem or error.context)) from None
    except yaml.YAMLError as error:
        raise LessonError(path, 0, app_local_text("lesson_problem_yaml", problem=error)) from None
    lines = {}
    if node is not None:
        _note_lines(node, (), lines)
    return Located(path, data, lines)


def _note_lines(node, keys: tuple, lines: dict):
    lines[keys] = node.start_mark.line + 1
    if isinstance(node, yaml.MappingNode):
        for key_node, value_node in node.value:
            lines[keys + (key_node.value,)] = key_node.start_mark.line + 1
            _note_lines(value_node, keys + (key_node.value,), lines)
            lines[keys + (key_node.value,)] = key_node.start_mark.line + 1
    elif isinstance(node, yaml.SequenceNode):
        for index, item in enumerate(node.value):
            _note_lines(item, keys + (index,), lines)
