"""The simulated robot's tablet in the app: its questions appear as real dialogs.

``QtTablet.ask`` is called from a simulator thread; the dialog is shown by the GUI
thread, beside the simulator view (never over the robot), and the caller waits
(interruptibly) for the person's answer.
"""
import threading

from PySide6.QtCore import QObject, Qt, Signal
from PySide6.QtWidgets import QDialog, QDialogButtonBox, QLabel, QLineEdit, QVBoxLayout

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import RobotCommandError, RobotTimeout
from rockly_desktop.robot.sim.tablet import TabletQuestion
from rockly_desktop.ui.docks.tablet_placement import place_clear_of
from rockly_desktop.ui.texts import tr


class TabletRequest:
    """One question to the person, answered from the GUI thread."""

    def __init__(self, question: TabletQuestion, text: str):
        self.question = question
        self.text = text
        self.answer = ""
        self.answered = False  # False when the dialog was closed without an answer
        self.closed = False  # its window was closed (×): "no answer" is the answer
        self.done = threading.Event()


class TabletDialog(QDialog):
    """A big, friendly dialog showing the robot's text and the answer buttons it needs."""

    def __init__(self, request: TabletRequest, title: str, language: str, parent=None):
        super().__init__(parent)
        self.request = request
        self.setObjectName("tablet_dialog")
        self.setAttribute(Qt.WidgetAttribute.WA_DeleteOnClose)
        self.setWindowTitle(title)
        self.setStyleSheet("QDialog { background: #e0f2f1; } QLabel { font-size: 20px; color: #004d40; }"
                           "QPushButton { font-size: 18px; padding: 8px 24px; } QLineEdit { font-size: 18px; }")
        layout = QVBoxLayout(self)
        self.label = QLabel(request.text, self)
        self.label.setTextFormat(Qt.TextFormat.PlainText)  # a program's text is shown, never interpreted
        self.label.setWordWrap(True)
        self.label.setMinimumWidth(380)
        layout.addWidget(self.label)
        self.entry = None
        buttons = QDialogButtonBox(self)
        if request.question == TabletQuestion.YES_NO:
            yes = buttons.addButton(tr("yes", language), QDialogButtonBox.ButtonRole.YesRole)
            no = buttons.addButton(tr("no", language), QDialogButtonBox.ButtonRole.NoRole)
            yes.clicked.connect(lambda: self._answer("yes"))
            no.clicked.connect(lambda: self._answer("no"))
        else:
            if request.question == TabletQuestion.TEXT:
                self.entry = QLineEdit(self)
                layout.addWidget(self.entry)
            ok = buttons.addButton(tr("ok", language), QDialogButtonBox.ButtonRole.AcceptRole)
            ok.clicked.connect(lambda: self._answer(self.entry.text() if self.entry else ""))
        layout.addWidget(buttons)

    def _answer(self, answer: str):
        self.request.answer = answer
        self.request.answered = True
        self.accept()

    def closeEvent(self, event):
        """Qt override: the window's × (the reject that follows says so: Esc alone stops the program)."""
        if self.isVisible():
            self.request.closed = True
        super().closeEvent(event)

    def done(self, result):
        """Qt override: whatever closes the dialog answers the request."""
        super().done(result)
        self.request.done.set()


class QtTablet(QObject):
    """The tablet port a simulator uses: ``ask`` (blocking) and ``notify``."""

    _sig_show = Signal(object)
    _sig_close = Signal(object)
    sig_notice = Signal(str, str)  # the robot's name, the text it shows
    sig_dismissed = Signal()  # the person left a question with Esc (the app stops the run)
    sig_unanswered = Signal(str)  # the robot's name: the person closed a question's window (×), which answers ''

    def __init__(self, parent, robot_name: str, language, unanswered: str = None, clear_of=lambda: None):
        """``parent`` is the dialogs' parent; ``language()`` the language they speak; ``clear_of()`` the
        rectangle (screen coordinates) a dialog must not cover, or None. With ``unanswered``, a question
        closed without an answer raises RobotCommandError(``unanswered``); without, it answers ''
        (Esc: the app stops the run on ``sig_dismissed``; ×: ``sig_unanswered`` says so)."""
        super().__init__(parent)
        self._parent = parent
        self._clear_of = clear_of
        self._language = language
        self.robot_name = robot_name
        self.unanswered = unanswered
        self.open_dialogs = {}
        self._closing = set()
        self._sig_show.connect(self._show, Qt.ConnectionType.QueuedConnection)
        self._sig_close.connect(self._close, Qt.ConnectionType.QueuedConnection)

    def ask(self, question: TabletQuestion, text: str, timeout: float, interrupt) -> str:
        """Show a dialog and wait for the answer ('yes'/'no', typed text, or '')."""
        request = TabletRequest(TabletQuestion(question), text)
        self._sig_show.emit(request)
        try:
            if not interrupt.wait_until(request.done.is_set, timeout):
                raise RobotTimeout(app_local_text("tablet_timeout", timeout=timeout))
        finally:
            if not request.done.is_set():
                self._sig_close.emit(request)
        if self.unanswered is not None and not request.answered:
            raise RobotCommandError(self.unanswered)
        return request.answer

    def notify(self, text: str):
        """A message that waits for no answer (``sig_notice``)."""
        self.sig_notice.emit(self.robot_name, text)

    def _show(self, request: TabletRequest):
        language = self._language()
        dialog = TabletDialog(request, tr("tablet_title", language, robot=self.robot_name), language, self._parent)
        dialog.finished.connect(lambda _result: self.open_dialogs.pop(id(request), None))
        dialog.rejected.connect(lambda: self._rejected(request))
        self.open_dialogs[id(request)] = dialog
        dialog.setModal(False)  # the big STOP button must stay reachable
        self._place(dialog)
        dialog.show()

    def _place(self, dialog):
        avoid = self._clear_of()
        if avoid is None:
            return
        dialog.adjustSize()
        window = self._parent.window()
        near = window.frameGeometry()
        screen = window.screen().availableGeometry() if window.screen() is not None else near
        dialog.move(place_clear_of(dialog.frameGeometry().size(), avoid, near, screen.united(near)))

    def _rejected(self, request: TabletRequest):
        if id(request) in self._closing:
            return
        if request.closed and self.unanswered is None:
            self.sig_unanswered.emit(self.robot_name)
        else:
            self.sig_dismissed.emit()

    def _close(self, request: TabletRequest):
        dialog = self.open_dialogs.pop(id(request), None)
        if dialog is not None:
            self._closing.add(id(request))
            dialog.reject()
            self._closing.discard(id(request))
