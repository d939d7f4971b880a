"""The Lessons dock: the chosen robot's lessons by level, the open lesson's step with its hints, and Check.

It shows and asks only: the window decides what opening a lesson or checking it does. ``show_lessons``
lists lessons (``lessons.Lesson``) with ``passed(lesson_id)`` marking those passed; a click on Start
asks ``sig_open(lesson)``; ``begin(lesson)`` then shows its first step. Each step shown is said with
``sig_step(step)`` (the window marks its blocks and limits the toolbox); Check asks ``sig_check(lesson)``
and ``show_result`` / ``show_problem`` say how it went; "Next lesson" asks ``sig_open`` for the next one.
``show_problems`` says, under the list, which lessons could not be read and why (for the teacher: a line
that opens); ``renew`` takes the open lesson read again.
"""
import html
from pathlib import Path

from PySide6.QtCore import QRect, Qt, QTimer, Signal
from PySide6.QtGui import QBrush, QColor, QTextOption
from PySide6.QtWidgets import (
    QDockWidget,
    QFrame,
    QHBoxLayout,
    QLabel,
    QListWidget,
    QListWidgetItem,
    QPushButton,
    QScrollArea,
    QSizePolicy,
    QTextBrowser,
    QTreeWidget,
    QTreeWidgetItem,
    QVBoxLayout,
    QWidget,
)

from rockly_desktop.lessons.schema import LEVELS
from rockly_desktop.ui.texts import tr

PASSED, FAILED = "#2e7d32", "#c62828"
BROKEN = "#8a5a00"  # the line saying which lessons could not be read: seen, but no alarm for a child
PROBLEMS_HEIGHT = 160  # px: the broken lessons' details at most (they scroll beyond)
STEP_TEXT_HEIGHT = 110  # px
RESULTS_HEIGHT = 100  # px: the results' height, between half this and twice this
LIST_HEIGHT = 120  # px


class LessonsDock(QDockWidget):
    """The lessons of the chosen robot, the open lesson's steps, and its check's results."""

    sig_open = Signal(object)  # a Lesson to open (its start program replaces the program, after asking)
    sig_step = Signal(object)  # the step now shown (steps.Step), or None when no lesson is open
    sig_check = Signal(object)  # the open Lesson, to check the program on screen against

    def __init__(self, title: str, parent=None):
        super().__init__(title, parent)
        self.language = "en"
        self.lesson = None  # the open lesson
        self.challenge = False  # the open lesson is a kiosk's challenge of the day
        self._shown = None  # the check result shown (a CheckResult), or the text of why none could be made
        self.step_index = 0
        self._hints_shown = 0
        self._lessons = []
        self._passed = lambda _lesson_id: False
        self.lesson_list = QTreeWidget(objectName="lesson_list")
        self.lesson_list.setHeaderHidden(True)
        self.lesson_list.setMinimumHeight(LIST_HEIGHT)  # the leftover room, at least this: Start stays in sight
        self.lesson_list.setSizePolicy(QSizePolicy.Policy.Preferred, QSizePolicy.Policy.Ignored)
        self.lesson_list.itemDoubleClicked.connect(lambda item: self._open_item(item))
        self.lesson_list.currentItemChanged.connect(lambda *_: self._follow_choice())
        self.start_button = QPushButton(objectName="lesson_start")
        self.start_button.clicked.connect(lambda: self._open_item(self.lesson_list.currentItem()))
        self.problems_line = QLabel(objectName="lesson_problems", wordWrap=True)  # "2 lessons could not be read"
        self.problems_line.setTextInteractionFlags(Qt.TextInteractionFlag.LinksAccessibleByMouse
                                                   | Qt.TextInteractionFlag.LinksAccessibleByKeyboard)
        self.problems_line.linkActivated.connect(lambda _link: self._open_problems(not self.problems_text.isVisible()))
        self.problems_text = QTextBrowser(objectName="lesson_problems_text")  # which file, which line, what is wrong
        self.problems_text.setWordWrapMode(QTextOption.WrapMode.WrapAtWordBoundaryOrAnywhere)  # long folder paths
        self._problems = []
        self._problems_open = False
        self.all_button = QPushButton(objectName="lesson_all", checkable=True)  # the list again, over an open lesson
        self.all_button.toggled.connect(self._show_list)
        self.prompt = QLabel(objectName="lesson_prompt", wordWrap=True)  # what to do while no lesson is open
        self.lesson_part = QWidget(objectName="lesson_part")  # the open lesson: its steps, Check and the results
        self.title = QLabel(objectName="lesson_title", wordWrap=True)
        self.title.setStyleSheet("font-weight: bold; font-size: 13pt")
        self.step_heading = QLabel(objectName="lesson_step_heading", wordWrap=True)
        self.step_heading.setStyleSheet("font-weight: bold")
        self.step_text = QTextBrowser(objectName="lesson_step_text")
        self.step_text.setOpenExternalLinks(False)
        self.hints = QLabel(objectName="lesson_hints", wordWrap=True)
        self.hints.setStyleSheet("color: #1f5fa8")
        self.hint_button = QPushButton(objectName="lesson_hint")
        self.hint_button.clicked.connect(self._show_hint)
        self.back_button = QPushButton(objectName="lesson_back")
        self.back_button.clicked.connect(lambda: self.show_step(self.step_index - 1))
        self.next_button = QPushButton(objectName="lesson_next")
        self.next_button.clicked.connect(lambda: self.show_step(self.step_index + 1))
        self.check_button = QPushButton(objectName="lesson_check")
        self.check_button.setStyleSheet("font-weight: bold")
        self.check_button.clicked.connect(lambda: self.lesson is not None and self.sig_check.emit(self.lesson))
        self.verdict = QLabel(objectName="lesson_verdict", wordWrap=True)
        self.results = QListWidget(objectName="lesson_results")
        self.results.setWordWrap(True)
        self.next_lesson_button = QPushButton(objectName="lesson_next_lesson")
        self.next_lesson_button.clicked.connect(self._open_next)
        scroller = QScrollArea(self, widgetResizable=True, frameShape=QFrame.Shape.NoFrame)
        scroller.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)  # the texts wrap instead
        scroller.setWidget(self._layout())  # its own minimum is small: the docks it shares tabs with keep their sizes
        self.setWidget(scroller)
        self.all_button.hide()
        self.show_problems([])
        self.show_lessons([], self._passed)

    def _layout(self) -> QWidget:
        page = QWidget(self)
        column = QVBoxLayout(page)
        column.addWidget(self.prompt)
        column.addWidget(self.all_button)
        column.addWidget(self.lesson_list, 1)
        column.addWidget(self.start_button)
        column.addWidget(self.problems_line)
        column.addWidget(self.problems_text)
        column.addWidget(self.lesson_part, 1)
        lesson = QVBoxLayout(self.lesson_part)
        lesson.setContentsMargins(0, 0, 0, 0)
        lesson.addWidget(self.title)
        lesson.addWidget(self.step_heading)
        lesson.addWidget(self.step_text, 1)
        lesson.addWidget(self.hints)
        steps = QHBoxLayout()  # two a row: a narrow dock (German words) keeps them whole
        steps.addWidget(self.back_button)
        steps.addWidget(self.next_button)
        lesson.addLayout(steps)
        lesson.addWidget(self.hint_button)
        lesson.addWidget(self.check_button)
        lesson.addWidget(self.verdict)
        lesson.addWidget(self.results)
        lesson.addWidget(self.next_lesson_button)
        lesson.addStretch(1)
        return page

    # --- the list -------------------------------------------------------------------------

    def show_lessons(self, lessons, passed):
        """List ``lessons`` (one robot's, in order) under their levels; ``passed(lesson_id)`` marks those passed."""
        self._lessons, self._passed = list(lessons), passed
        chosen = self.lesson_list.currentItem()
        chosen_id = chosen.data(0, Qt.ItemDataRole.UserRole).id if chosen and chosen.parent() else None
        self.lesson_list.clear()
        for level in LEVELS:
            of_level = [lesson for lesson in self._lessons if lesson.level == level]
            if not of_level:
                continue
            heading = QTreeWidgetItem([tr(f"lessons_level_{level}", self.language)])
            heading.setFlags(Qt.ItemFlag.ItemIsEnabled)
            self.lesson_list.addTopLevelItem(heading)
            for lesson in of_level:
                item = QTreeWidgetItem(heading, [self._entry(lesson)])
                item.setData(0, Qt.ItemDataRole.UserRole, lesson)
                if lesson.id == chosen_id or (chosen_id is None and self.lesson is not None
                                              and lesson.id == self.lesson.id):
                    self.lesson_list.setCurrentItem(item)
        self.lesson_list.expandAll()
        if not self._lessons:
            self.lesson_list.addTopLevelItem(QTreeWidgetItem([tr("lessons_none", self.language)]))
        self._follow_choice()

    def _entry(self, lesson) -> str:
        mark = "✓ " if self._passed(lesson.id) else "○ "
        return mark + lesson.title(self.language)

    def _chosen(self):
        item = self.lesson_list.currentItem()
        return item.data(0, Qt.ItemDataRole.UserRole) if item is not None else None

    def _follow_choice(self):
        self.start_button.setEnabled(self._chosen() is not None)

    def _show_list(self, shown: bool):
        self.lesson_list.setVisible(shown)
        self.start_button.setVisible(shown)
        self.problems_line.setVisible(shown and bool(self._problems))
        self.problems_text.setVisible(shown and bool(self._problems) and self._problems_open)

    # --- the lessons that could not be read ---------------------------------------------------

    def show_problems(self, problems):
        """Say under the list which lessons could not be read (``problems``: LessonErrors, with their file, line
        and what was expected): a line for the teacher that opens to each lesson's folder, file, line and problem."""
        self._problems = list(problems)
        count = len(self._problems)
        said = tr("lessons_problems_one", self.language) if count == 1 else tr("lessons_problems_many",
                                                                              self.language, count=count)
        arrow = "▾" if self._problems_open else "▸"
        self.problems_line.setText(f'<a href="problems" style="color: {BROKEN}; text-decoration: none">'
                                   f'{arrow} {html.escape(said)}</a>')
        details = "".join(self._problem_html(problem) for problem in self._problems)
        after = html.escape(tr("lessons_problems_after", self.language))
        self.problems_text.setHtml(f"{details}<p><i>{after}</i></p>")
        self.problems_line.setToolTip(self.problems_text.toPlainText())
        self._show_list(self.lesson_list.isVisibleTo(self))
        self._fit_problems()

    def _problem_html(self, problem) -> str:
        path = Path(problem.path)
        folder = path if path.is_dir() else path.parent
        said = problem.problem_in(self.language)
        where = tr("lessons_problem_folder", self.language, folder=folder.parent)
        if path == folder:
            what = said
        elif problem.line:
            what = tr("lessons_problem_line", self.language, file=path.name, line=problem.line, problem=said)
        else:
            what = tr("lessons_problem_file", self.language, file=path.name, problem=said)
        return f"<p><b>{html.escape(folder.name)}</b> ({html.escape(where)})<br>{html.escape(what)}</p>"

    def _open_problems(self, shown: bool):
        self._problems_open = shown
        self.show_problems(self._problems)
        if shown:  # in sight once laid out (the dock may be short): the layout comes after the next turn
            QTimer.singleShot(0, self, lambda: QTimer.singleShot(0, self, self._bring_problems_in_sight))

    def _bring_problems_in_sight(self):
        """Scroll the dock to the problems' end, keeping their line in sight (a text browser's own "visible"
        is its cursor's, at its top)."""
        scroller = self.widget()
        scroller.ensureVisible(0, self.problems_text.geometry().bottom(), 0, 0)
        scroller.ensureWidgetVisible(self.problems_line, 0, 0)

    def _fit_problems(self):
        """As tall as the problems' words, at most PROBLEMS_HEIGHT."""
        document = self.problems_text.document()
        document.setTextWidth(self.problems_text.viewport().width())
        frame = 2 * self.problems_text.frameWidth() + int(document.documentMargin())
        self.problems_text.setFixedHeight(min(PROBLEMS_HEIGHT, int(document.size().height()) + frame))

    def _open_item(self, item):
        lesson = item.data(0, Qt.ItemDataRole.UserRole) if item is not None else None
        if lesson is not None:
            self.sig_open.emit(lesson)

    def next_lesson(self):
        """The lesson after the open one in the list (None: the last, or none open)."""
        ids = [lesson.id for lesson in self._lessons]
        if self.lesson is None or self.lesson.id not in ids:
            return None
        index = ids.index(self.lesson.id) + 1
        return self._lessons[index] if index < len(ids) else None

    def _open_next(self):
        following = self.next_lesson()
        if following is not None:
            self.sig_open.emit(following)

    # --- the open lesson ------------------------------------------------------------------

    def begin(self, lesson, challenge: bool = False):
        """Show ``lesson`` (None: none) from its first step, no results yet; a kiosk's ``challenge`` of the day
        says so in its title."""
        self.lesson, self.challenge = lesson, challenge
        self.all_button.setVisible(lesson is not None)
        self.all_button.setChecked(False)
        self._show_list(lesson is None)  # an open lesson has the room; "All lessons" shows the list again
        self.widget().verticalScrollBar().setValue(0)
        self.clear_result()
        self.show_lessons(self._lessons, self._passed)
        self.show_step(0)

    def show_step(self, index: int):
        """Show the open lesson's step ``index`` (kept within its steps) and say it with ``sig_step``."""
        steps = self.lesson.steps(self.language) if self.lesson is not None else []
        self.step_index = max(0, min(index, len(steps) - 1))
        self._hints_shown = 0
        step = steps[self.step_index] if steps else None
        self.title.setText(self._title())
        self.prompt.setText(tr("lessons_choose", self.language))
        self.prompt.setVisible(self.lesson is None)
        self.lesson_part.setVisible(self.lesson is not None)
        self.step_heading.setText(tr("lessons_step", self.language, number=self.step_index + 1, steps=len(steps),
                                     title=step.title) if step else "")
        self.step_text.setMarkdown(step.text if step else "")
        self.step_text.setVisible(step is not None)
        self._fit_step_text()
        self._show_hints(step)
        self.back_button.setEnabled(step is not None and self.step_index > 0)
        self.next_button.setEnabled(step is not None and self.step_index < len(steps) - 1)
        self.check_button.setEnabled(self.lesson is not None)
        self.sig_step.emit(step)

    def renew(self, lesson):
        """``lesson``, the open one read again (its files changed): it stays at its step, its new text shown when
        its steps or title changed."""
        if self.lesson is None or lesson.id != self.lesson.id:
            return
        changed = (lesson.steps(self.language) != self.lesson.steps(self.language)
                   or lesson.title(self.language) != self.lesson.title(self.language))
        self.lesson = lesson
        if changed:
            self.show_step(self.step_index)

    def _title(self) -> str:
        if self.lesson is None:
            return ""
        title = self.lesson.title(self.language)
        return tr("lessons_challenge", self.language, title=title) if self.challenge else title

    def _fit_step_text(self):
        """As tall as the step's few sentences (at most STEP_TEXT_HEIGHT): the rest is the results' room."""
        document = self.step_text.document()
        document.setTextWidth(self.step_text.viewport().width())
        frame = 2 * self.step_text.frameWidth() + int(document.documentMargin())
        self.step_text.setFixedHeight(min(STEP_TEXT_HEIGHT, int(document.size().height()) + frame))

    def resizeEvent(self, event):
        """Qt override: the step's text and the results fit their new width."""
        super().resizeEvent(event)
        self._fit_step_text()
        self._fit_problems()
        if self.results.count():
            self._fit_results()

    def _step(self):
        steps = self.lesson.steps(self.language) if self.lesson is not None else []
        return steps[self.step_index] if steps else None

    def _show_hints(self, step):
        hints = step.hints if step else []
        shown = hints[:self._hints_shown]
        self.hints.setText("\n".join(tr("lessons_hint_line", self.language, hint=hint) for hint in shown))
        self.hints.setVisible(bool(shown))
        self.hint_button.setEnabled(self._hints_shown < len(hints))

    def _show_hint(self):
        self._hints_shown += 1
        self._show_hints(self._step())

    # --- checking ----------------------------------------------------------------------------

    def set_checking(self, checking: bool):
        """Say that a check runs (Check waits meanwhile) or is over."""
        self.check_button.setEnabled(not checking and self.lesson is not None)
        if checking:
            self.clear_result()
            self.verdict.setText(tr("lessons_checking", self.language))

    def clear_result(self):
        """Forget the last check's results."""
        self._shown = None
        self.verdict.setText("")
        self.verdict.setStyleSheet("")
        self.results.clear()
        self.results.hide()
        self.next_lesson_button.hide()

    def show_result(self, result):
        """Show a ``check.CheckResult``: each goal passed or not, in the child's words; success offers the next
        lesson."""
        self._shown = result
        self.results.clear()
        for goal in result.goals:
            item = QListWidgetItem(("✓ " if goal.passed else "✗ ") + goal.words(self.language))
            item.setForeground(QBrush(QColor(PASSED if goal.passed else FAILED)))
            self.results.addItem(item)
        if result.ending != "finished":
            item = QListWidgetItem("✗ " + result.ending_text.in_language(self.language))
            item.setForeground(QBrush(QColor(FAILED)))
            self.results.addItem(item)
        self.results.show()
        self._fit_results()
        if result.passed:
            self.verdict.setText(tr("lessons_passed", self.language))
            self.verdict.setStyleSheet(f"color: {PASSED}; font-weight: bold; font-size: 13pt")
        else:
            self.verdict.setText(tr("lessons_failed", self.language))
            self.verdict.setStyleSheet(f"color: {FAILED}; font-weight: bold")
        following = self.next_lesson() if result.passed else None
        self.next_lesson_button.setVisible(following is not None)
        if following is not None:
            self.next_lesson_button.setText(tr("lessons_next_lesson", self.language,
                                               title=following.title(self.language)))
        self.show_lessons(self._lessons, self._passed)
        self._bring_results_in_sight()

    def _fit_results(self):
        """As tall as the goals' words (RESULTS_HEIGHT to twice that): the verdict, the results and the next
        lesson's button fit in sight together."""
        metrics, width = self.results.fontMetrics(), max(40, self.results.viewport().width() - 8)
        rows = sum(metrics.boundingRect(QRect(0, 0, width, 10000), Qt.TextFlag.TextWordWrap,
                                        self.results.item(row).text()).height() + 2
                   for row in range(self.results.count()))
        wanted = rows + 2 * self.results.frameWidth() + 4
        self.results.setFixedHeight(max(RESULTS_HEIGHT // 2, min(2 * RESULTS_HEIGHT, wanted)))

    def _bring_results_in_sight(self):
        """Scroll the dock to the verdict and its results (once they are laid out)."""
        last = self.next_lesson_button if self.next_lesson_button.isVisibleTo(self) else self.results
        def in_sight():
            self.widget().ensureWidgetVisible(last, 0, 0)
            self.widget().ensureWidgetVisible(self.verdict, 0, 0)

        def fitted():  # the results' words wrap at their laid-out width: fit them, then scroll once laid out again
            self._fit_results()
            QTimer.singleShot(0, self, in_sight)

        QTimer.singleShot(0, self, fitted)

    def show_problem(self, text: str):
        """Say why the check could not run."""
        self._shown = text
        self.results.clear()
        self.results.hide()
        self.verdict.setText(text)
        self.verdict.setStyleSheet(f"color: {FAILED}")

    # --- language ----------------------------------------------------------------------------

    def retranslate(self, language: str):
        """Say everything in ``language`` (the title comes with the other docks')."""
        self.language = language
        self.start_button.setText(tr("lessons_start", language))
        self.all_button.setText(tr("lessons_all", language))
        self.hint_button.setText(tr("lessons_show_hint", language))
        self.back_button.setText(tr("lessons_back", language))
        self.next_button.setText(tr("lessons_next", language))
        self.check_button.setText(tr("lessons_check", language))
        shown = self._shown
        self.show_problems(self._problems)
        self.show_lessons(self._lessons, self._passed)
        self.show_step(self.step_index)
        if isinstance(shown, str):
            self.show_problem(shown)  # said in the language it was said in: the error's own words
        elif shown is not None:
            self.show_result(shown)
