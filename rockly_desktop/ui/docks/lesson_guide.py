"""What the Lessons dock's requests do in the window: open a lesson, follow its steps, check the program.

``LessonGuide`` takes its collaborators explicitly: the ``dock`` (``lessons_dock.LessonsDock``), the
``editor`` (the page: ``call``, ``set_toolbox``), ``files`` (``maybe_save``, ``new``, ``open_copy``: a
lesson's start program replaces the program only after asking, as File → Open does), ``replay``
(``open``, ``bar.jump_to``, ``sig_opened``), ``progress`` (``settings.lessons.LessonProgress``),
``profiles`` ({id: Profile}), ``profile()`` (the chosen robot's), ``toolbox()`` (the teacher's level's
toolbox JSON) and ``language()``. A check runs off the window's thread on what the page generates
(the program on screen is never changed); a failed one opens its recording at the failing moment.
"""
import tempfile
from pathlib import Path

from PySide6.QtCore import QObject

from rockly_desktop.core.workspace_blocks import block_types_by_id
from rockly_desktop.ui.docks.lesson_check import LessonCheck
from rockly_desktop.ui.docks.lesson_watch import LessonWatch
from rockly_desktop.ui.texts import tr

PAGE_TIMEOUT_MS = 10000


def restricted_toolbox(toolbox: dict, allowed) -> dict:
    """``toolbox`` (Blockly's JSON) with only the blocks of ``allowed`` types (None: all), empty categories left out."""
    if allowed is None:
        return toolbox
    allowed = set(allowed)

    def keep(items):
        kept = []
        for item in items:
            kind = str(item.get("kind", "")).lower()
            if kind == "block":
                if item.get("type") in allowed:
                    kept.append(item)
            elif kind == "category" and "contents" in item:
                contents = keep(item["contents"])
                if any(str(entry.get("kind", "")).lower() in ("block", "category") for entry in contents):
                    kept.append(dict(item, contents=contents))
            elif kind != "category":
                kept.append(item)
        return kept

    return dict(toolbox, contents=keep(toolbox.get("contents", [])))


class LessonGuide(QObject):
    """The Lessons dock's requests carried out with the window's editor, files, replay and settings."""

    def __init__(self, dock, editor, files, replay, progress, profiles, profile, toolbox, language, parent=None):
        super().__init__(parent)
        self.dock, self.editor, self.files, self.replay = dock, editor, files, replay
        self.progress, self._profiles, self._profile = progress, profiles, profile
        self._toolbox, self._language = toolbox, language
        self._library = None
        self.watch = None  # the lesson folders' LessonWatch, once the lessons are read
        self._step = None
        self._failing = None  # (seconds, block) to show once the check's recording is read
        self._folder = tempfile.TemporaryDirectory(prefix="rockly-lessons-")
        self.checker = LessonCheck(language, self)
        self.checker.sig_checked.connect(self._checked)
        self.checker.sig_failed.connect(self._check_failed)
        self.last_result = None
        dock.sig_open.connect(self.open)
        dock.sig_step.connect(self._show_step)
        dock.sig_check.connect(self.check)
        replay.sig_opened.connect(self._show_failing)
        editor.sig_ready.connect(lambda: self._step is not None and self._show_step(self._step))  # a new page

    @property
    def library(self):
        """Every lesson (read when first needed, then again whenever the lesson folders change)."""
        if self._library is None:
            from rockly_desktop.lessons.library import DEPTH, LessonLibrary, lesson_roots  # YAML: not at start-up

            self.watch = LessonWatch(lambda: LessonLibrary.discover(self._profiles), lesson_roots(), DEPTH, self)
            self.watch.sig_read.connect(self._lessons_read)  # watched first: a change while reading is not missed
            self._library = LessonLibrary.discover(self._profiles)
            self.dock.show_problems(self._library.problems)
        return self._library

    def _lessons_read(self, library):
        """The lessons read again: the list and the broken ones follow; the open lesson stays open at its step
        (its new text shown when it changed; kept as it was when it is gone), the progress is untouched."""
        self._library = library
        self.dock.show_problems(library.problems)
        opened = self.dock.lesson
        renewed = library.get(opened.id) if opened is not None else None
        if renewed is not None and renewed.robot == opened.robot:
            self.dock.renew(renewed)
        self.follow_robot()

    def follow_robot(self):
        """Close a lesson of another robot than the chosen one, and list the chosen robot's lessons when the dock
        shows (a hidden dock's list is made once it shows)."""
        robot = self._profile().id
        if self.dock.lesson is not None and self.dock.lesson.robot != robot:
            self.dock.begin(None)
        if self.dock.isVisible():
            self.dock.show_lessons(self.library.for_robot(robot), self.progress.passed)

    def open(self, lesson):
        """Open ``lesson``: its start program (or an empty one) replaces the program on screen, after asking to
        save changes, and its first step shows."""
        def replaced(ok: bool):
            if ok:
                self.dock.begin(lesson)
        if lesson.program is not None:
            self.files.open_copy(lesson.program, lesson.title(self._language()), then=replaced)
        else:
            self.files.maybe_save(then=lambda ok: ok and (self.files.new(ask=False), replaced(True)))

    def start_challenge(self, lesson_id: str):
        """A new kiosk visitor: no progress, and the lesson ``lesson_id`` (the challenge of the day, "" for none;
        one of another robot is none) shown from its first step in the dock, brought to the front."""
        self.progress.forget_visitor()
        lesson = self.library.get(lesson_id) if lesson_id else None
        if lesson is not None and lesson.robot != self._profile().id:
            lesson = None
        if lesson is not None:
            self.dock.show()
            self.dock.raise_()
        self.follow_robot()
        self.dock.begin(lesson, challenge=lesson is not None)

    def _show_step(self, step):
        self._step = step
        self.apply_toolbox()
        self.editor.call("markLessonBlocks", {"types": list(step.blocks) if step else []})

    def apply_toolbox(self):
        """Show the teacher's level's toolbox, narrowed to what the step shown allows."""
        allowed = self._step.toolbox if self._step is not None else None
        self.editor.set_toolbox(restricted_toolbox(self._toolbox(), allowed))

    # --- checking --------------------------------------------------------------------------

    def check(self, lesson):
        """Check the program on screen against ``lesson`` (what the page generates: the program is not touched)."""
        if self.checker.running:
            return
        self.dock.set_checking(True)
        self.replay.close()
        self.editor.call("getRunCode", {"values": False}, lambda run_code, error: self._got_code(
            lesson, run_code, error), timeout_ms=PAGE_TIMEOUT_MS)

    def _got_code(self, lesson, run_code, error):
        if error:
            self._check_failed(tr("lessons_cannot_check", self._language(), error=error))
            return
        self.editor.call("getState", None, lambda state, failure: self._got_state(lesson, run_code, state, failure),
                         timeout_ms=PAGE_TIMEOUT_MS)

    def _got_state(self, lesson, run_code, state, error):
        if error:
            self._check_failed(tr("lessons_cannot_check", self._language(), error=error))
            return
        workspace = state["workspace"]
        from rockly_desktop.lessons.check import GeneratedProgram  # the simulator, recordings: when checked

        program = GeneratedProgram(self.files.document.display_name(self._language()), run_code, workspace,
                                   block_types_by_id(workspace))
        self.checker.start(lesson, program, Path(self._folder.name) / f"{lesson.id}.mcap")

    def _checked(self, result, record: str):
        self.last_result = result
        if result.passed:
            self.progress.mark_passed(result.lesson)
        self.dock.set_checking(False)
        if self.dock.lesson is None or self.dock.lesson.id != result.lesson:  # another lesson opened meanwhile
            self.dock.show_lessons(self.library.for_robot(self._profile().id), self.progress.passed)
            return
        self.dock.show_result(result)
        if not result.passed and result.failing is not None:
            self._failing = result.failing
            self.replay.open(record, quiet=True)

    def _check_failed(self, text: str):
        self.dock.set_checking(False)
        self.dock.show_problem(text)

    def _show_failing(self, shown: bool):
        failing, self._failing = self._failing, None
        if not shown or failing is None:
            return
        seconds, block = failing
        self.replay.bar.jump_to(seconds)
        if block:  # the block the goal names, glowing (the recorded moment's may be the one before it)
            self.editor.call("highlight", {"id": block})

    def shutdown(self):
        """Wait for a running check and a reading of the lessons, then remove the checks' recordings (the
        window closes)."""
        if self.watch is not None:
            self.watch.stop()
        self.checker.wait()
        self.replay.close()
        self._folder.cleanup()

