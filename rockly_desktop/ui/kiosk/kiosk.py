"""Kiosk mode for a fair stand (``rockly --kiosk [PROGRAM]``): the stage layout, locked, a big STOP that
cannot be hidden, no context menus, no way out without the teacher's PIN or key chord (nor to
the robot choice and Preferences), a window that comes back full screen, file dialogs kept in
the kiosk's folders, a start program nobody can write over, a visitor's changes kept without a question,
and a fresh start (the whole layout too) for the next visitor after a few minutes without input."""
from datetime import datetime

from PySide6.QtCore import QEvent, QObject, Qt, QTimer
from PySide6.QtGui import QKeySequence, QShortcut
from PySide6.QtWidgets import (
    QDialog,
    QDialogButtonBox,
    QDockWidget,
    QLabel,
    QLineEdit,
    QToolBar,
    QVBoxLayout,
)

from rockly_desktop.bridge.editor_view import ANSWER_TIMEOUT_MS
from rockly_desktop.core.errors import RocklyError
from rockly_desktop.core.program import PROGRAM_SUFFIX, Program, save_program
from rockly_desktop.settings.teacher import wait_text
from rockly_desktop.ui.docks.registry import InKiosk
from rockly_desktop.ui.files.file_dialogs import ConfinedFileDialogs
from rockly_desktop.ui.kiosk.idle_watch import IdleWatch
from rockly_desktop.ui.texts import tr


def can_be_left(settings) -> bool:
    """True when a teacher can leave kiosk mode: a teacher PIN or a key chord is set."""
    return settings.teacher.has_pin or bool(settings.kiosk.quit_chord)


# what the window itself is told when the mouse is on an edge between docks: a drag there resizes them
_EDGE_DRAGGING = (QEvent.Type.MouseButtonPress, QEvent.Type.MouseButtonDblClick, QEvent.Type.MouseMove,
                  QEvent.Type.HoverMove)


class Kiosk(QObject):
    """Turns ``frame`` (the QMainWindow of a window built with ``settings.kiosk_mode`` on) into a kiosk
    whose start program is ``start_program`` (a path, or None for an empty program). The caller
    shows the window full screen, runs the window's teacher commands through ``ask_teacher`` and
    starts it with the same program.

    What it works with: ``settings`` (AppSettings: the kiosk's, the teacher's, the recordings' folder),
    ``language()`` (the window's, which may change behind the PIN), the window's ``stage``
    (StageLayout), ``docks`` (registry.Docks), the block ``editor``, the ``document`` on screen, the
    program ``files`` (ProgramFiles), the ``replay``, the run session ``runs``, the robot choice
    ``robots``, ``run_toolbar()`` (the run toolbar of the moment, with STOP) and the ``lessons``
    (``ui.docks.lesson_guide.LessonGuide``: every visitor gets the challenge of the day afresh).
    """

    def __init__(self, frame, start_program=None, *, settings, language, stage, docks, editor, document, files,
                 replay, runs, robots, run_toolbar, lessons):
        super().__init__(frame)
        self.frame = frame
        self._app_settings = settings
        self.settings = settings.kiosk
        self._language = language
        self._stage = stage
        self._docks, self._editor, self._document, self._files = docks, editor, document, files
        self._replay, self._runs, self._robots, self._run_toolbar = replay, runs, robots, run_toolbar
        self._lessons = lessons
        self.start_program = str(start_program) if start_program else None
        self._may_close = False
        self._starting_over = False
        self.leave_dialog = self.teacher_dialog = None
        stage.set_active(True)
        stage.action.setEnabled(False)
        for dock in frame.findChildren(QDockWidget):
            dock.setFeatures(QDockWidget.DockWidgetFeature.NoDockWidgetFeatures)  # no closing, no floating away
        for closed in docks.where(lambda spec: spec.in_kiosk == InKiosk.CLOSED):
            closed.hide()
            closed.toggleViewAction().setEnabled(False)
        files.file_dialogs = ConfinedFileDialogs(
            [self.settings.programs_folder, self.settings.visitors_folder], self.settings.visitors_folder, language)
        replay.file_dialogs = ConfinedFileDialogs([settings.recordings_folder], None, language)
        # Chromium's own menu (Back, Reload, Save page…) where the page shows none; Blockly's menus stay
        editor.setContextMenuPolicy(Qt.ContextMenuPolicy.NoContextMenu)
        self._refuse_context_menus()
        files.sig_program_replaced.connect(self._keep_programs_safe)
        files.keep_changes = self._keep_visitor_program  # New, an example…: nobody is asked to save "Untitled"
        frame.installEventFilter(self)
        self.chord = None
        if self.settings.quit_chord:
            self.chord = QShortcut(QKeySequence(self.settings.quit_chord), frame)
            self.chord.setContext(Qt.ShortcutContext.ApplicationShortcut)
            self.chord.activated.connect(self.leave)
        self.idle = IdleWatch(self.settings.idle_minutes * 60, frame, self)
        self.idle.sig_idle.connect(self._on_idle)
        lessons.start_challenge(self.settings.challenge)

    # --- leaving ------------------------------------------------------------------------

    def eventFilter(self, watched, event):
        """Closing the window (Quit, Alt+F4) asks for the teacher's PIN first; a minimised window (the
        window manager's Iconify) or one no longer full screen comes back full screen at once; the edges
        between the docks take no mouse (the mouse reaches the window itself only there)."""
        if watched is not self.frame or self._may_close:
            return False
        if event.type() in _EDGE_DRAGGING:
            return True
        if event.type() == QEvent.Type.Close:
            event.ignore()
            self.ask_pin()
            return True
        if event.type() == QEvent.Type.WindowStateChange and (self.frame.isMinimized()
                                                              or not self.frame.isFullScreen()):
            QTimer.singleShot(0, self, self.to_the_front)
        return False

    def to_the_front(self):
        """Full screen, in front of every other window (after a minimise, or for the next visitor)."""
        if not self._may_close:
            self.frame.showFullScreen()
            self.frame.raise_()
            self.frame.activateWindow()

    def _refuse_context_menus(self):
        """No menu on a right-click on the toolbars, docks, tabs, menu bar or status bar: the window's
        menu there would hide the toolbar with STOP. (``MainWindow.createPopupMenu`` gives none in
        kiosk mode; a refusal here also stops what its children leave to it.)"""
        frame, prevent = self.frame, Qt.ContextMenuPolicy.PreventContextMenu
        frame.setContextMenuPolicy(prevent)
        for part in frame.findChildren(QToolBar) + frame.findChildren(QDockWidget) + [frame.menuBar(),
                                                                                       frame.statusBar()]:
            part.setContextMenuPolicy(prevent)

    def ask_pin(self):
        """Show the dialog that asks for the teacher's PIN to leave kiosk mode."""
        if self.leave_dialog is not None:
            self.leave_dialog.deleteLater()  # made anew: the language may have changed
        self.leave_dialog = LeaveDialog(self._app_settings.teacher, self._language(), self.frame)
        self.leave_dialog.accepted.connect(self.leave)
        self.leave_dialog.open()

    def ask_teacher(self, then):
        """Run ``then()`` (choosing the robot, Preferences) once the teacher's PIN was given."""
        if self.teacher_dialog is not None:
            self.teacher_dialog.deleteLater()
        self.teacher_dialog = PinDialog(self._app_settings.teacher, self._language(), "kiosk_teacher_title",
                                        "kiosk_teacher_text", self.frame)
        self.teacher_dialog.setObjectName("kiosk_teacher_dialog")
        self.teacher_dialog.accepted.connect(then)
        self.teacher_dialog.open()

    def leave(self):
        """Keep the visitor's program, then close the window (the teacher gave the PIN or the chord)."""
        self.idle.stop()

        def close():
            self._document.modified = False  # the visitor's program is kept in the visitors' folder
            self._may_close = True
            self.frame.showNormal()
            self.frame.close()

        self._keep_visitor_program(close)

    # --- the next visitor ---------------------------------------------------------------

    def _on_idle(self):
        if self._starting_over:
            return
        if self._runs.state != "idle":
            self._runs.stop()  # the next check starts over once the run has ended
            return
        modal = self.frame.active_dialog()
        if modal is not None:  # a question nobody answers; starting over waits until it is gone
            modal.close()
            return
        self._starting_over = True
        self._keep_visitor_program(self._start_over)

    def _keep_visitor_program(self, then):
        """Save a changed program into a dated file in the visitors' folder, then ``then()``."""
        document = self._document
        if not document.modified:
            then()
            return

        def answered(state, error):
            if not error:
                try:
                    save_program(self._dated_path(), Program(document.profile.id, state["workspace"],
                                                             document.breakpoints,
                                                             document.profile.packs_used(state["workspace"])))
                except (RocklyError, OSError) as problem:
                    error = problem
            if error:
                self._docks["console_dock"].append(tr("kiosk_not_kept", self._language(), error=error), "error")
            then()

        self._editor.call("getState", None, answered, timeout_ms=ANSWER_TIMEOUT_MS)

    def _dated_path(self):
        folder = self.settings.visitors_folder
        folder.mkdir(parents=True, exist_ok=True)
        stem = datetime.now().strftime("%Y-%m-%d_%H-%M-%S")
        path, number = folder / f"{stem}{PROGRAM_SUFFIX}", 1
        while path.exists():
            number += 1
            path = folder / f"{stem}-{number}{PROGRAM_SUFFIX}"
        return path

    def _start_over(self):
        self._document.modified = False
        self._forget_visitor()

        def opened(_ok=True):
            self._robots.reset()
            self._starting_over = False
            self.idle.rest()
            self.frame.statusBar().showMessage(tr("kiosk_started_over", self._language()), 10000)

        if self.start_program:
            self._files.open(self.start_program, then=opened)
        else:
            self._files.new(ask=False)
            opened()

    def _forget_visitor(self):
        """Nothing of the last visitor stays in sight: console, replay, variables, the blocks' badges
        and values; the toolbar (with STOP) shown, the stage's docks at their sizes (the View menu or the
        teacher may have changed them), the window full screen in front."""
        self._replay.close()
        self._docks["console_dock"].clear()
        self._docks["variables_dock"].clear()
        self._editor.call("clearMarks")
        self._run_toolbar().show()
        self._stage.arrange()
        self._lessons.start_challenge(self.settings.challenge)  # the stage's docks, and the challenge's
        self.to_the_front()

    def _keep_programs_safe(self):
        """Every program opened is shown as a new one (the start program too), so Save asks for a new
        name in the visitors' folder: only a file saved in this visit is ever written again."""
        if self._document.path is not None:
            self._document.set_file(None, self._document.modified)


class PinDialog(QDialog):
    """Asks for the teacher's PIN (``teacher``: TeacherSettings), saying the texts ``title_key`` and
    ``text_key``; accepted only with the right one."""

    def __init__(self, teacher, language: str, title_key: str, text_key: str, parent=None):
        super().__init__(parent)
        self.setWindowTitle(tr(title_key, language))
        self._teacher, self._language = teacher, language
        self.pin = QLineEdit(self, objectName="kiosk_pin", echoMode=QLineEdit.EchoMode.Password)
        self.problem = QLabel(self, objectName="kiosk_problem", wordWrap=True)
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel, self)
        buttons.accepted.connect(self.accept)
        buttons.rejected.connect(self.reject)
        layout = QVBoxLayout(self)
        layout.addWidget(QLabel(tr(text_key, language), self, wordWrap=True))
        layout.addWidget(self.pin)
        layout.addWidget(self.problem)
        layout.addWidget(buttons)

    def accept(self):
        """Qt override: close only when the PIN is right."""
        pin = self.pin.text()
        self.pin.clear()
        if not self._teacher.has_pin:
            self.problem.setText(tr("teacher_wrong_pin", self._language))
            return
        answer = self._teacher.try_pin(pin)
        self._say(answer.problem(self._language))
        if answer.right:
            super().accept()

    def open(self):
        """Qt override: open with an empty PIN field."""
        wait = self._teacher.pin_wait()
        self._say(wait_text(wait, self._language) if wait > 0 else "")
        self.pin.clear()
        super().open()
        self.pin.setFocus()

    def _say(self, problem: str):
        """Show ``problem`` whole: a window does not grow by itself for a wrapped text's extra lines."""
        self.problem.setText(problem)
        self.layout().activate()
        needed = self.heightForWidth(self.width())
        if needed > self.height():
            self.resize(self.width(), needed)


class LeaveDialog(PinDialog):
    """Asks for the teacher's PIN to leave kiosk mode."""

    def __init__(self, teacher, language: str, parent=None):
        super().__init__(teacher, language, "kiosk_leave_title", "kiosk_leave_text", parent)
        self.setObjectName("leave_kiosk_dialog")
