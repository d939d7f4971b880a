"""STOP outside the modal chain: the window's STOP (its button, its Esc, a kiosk's big STOP) stops the robot
whatever dialog or menu is open (decision 032).

Qt drops a click on a window that a modal dialog blocks before any Python sees it, so a dialog of the window's
is shown modeless at the Qt level, and this keeps it modal for everything but STOP: while the dialog is open,
input to the window (and to the dialogs under it) is swallowed, except a press on STOP, which stops. Esc stops
from a dialog or a menu too (which still closes as it did), and a press on STOP while a menu is open stops at
once (Qt only closes the menu with that press).

Filters sit on the window, its dialogs and the top-level QWindows that get the focus, never on the QApplication
(a Python filter there crashes PySide 6.11: decision 027).
"""
from PySide6.QtCore import QEvent, QObject, Qt
from PySide6.QtGui import QGuiApplication, QWindow
from PySide6.QtWidgets import QDialog, QWidget
from shiboken6 import isValid

# what a modal dialog keeps from the windows under it
_INPUT = frozenset({
    QEvent.Type.MouseButtonPress, QEvent.Type.MouseButtonRelease, QEvent.Type.MouseButtonDblClick,
    QEvent.Type.MouseMove, QEvent.Type.Wheel, QEvent.Type.KeyPress, QEvent.Type.KeyRelease,
    QEvent.Type.TouchBegin, QEvent.Type.TouchUpdate, QEvent.Type.TouchEnd, QEvent.Type.TabletPress})
_PRESSES = frozenset({QEvent.Type.MouseButtonPress, QEvent.Type.MouseButtonDblClick})


class StopAnywhere(QObject):
    """STOP through dialogs and menus for ``window`` (a top-level widget); ``toolbar()`` gives the run toolbar
    of the moment (it is rebuilt when the language changes), whose ``stop_action`` it triggers."""

    def __init__(self, window: QWidget, toolbar):
        super().__init__(window)
        self._toolbar = toolbar
        self._dialogs = []  # the window's open dialogs that are modal to Rockly, the newest last
        self._watched = []  # the QWindows whose input is filtered
        window.winId()  # its QWindow exists from now on
        self._main = window.windowHandle()
        window.installEventFilter(self)  # its dialogs, as they are polished (before they show)
        self._watch(self._main)
        QGuiApplication.instance().focusWindowChanged.connect(self._watch)

    @property
    def open_dialogs(self) -> list:
        """The window's dialogs that are open and modal (to Rockly), the newest last."""
        self._dialogs = [dialog for dialog in self._dialogs if isValid(dialog) and dialog.isVisible()]
        return list(self._dialogs)

    def _watch(self, window):
        self._watched = [watched for watched in self._watched if isValid(watched)]
        if window is not None and window not in self._watched and self._within(window, self._main):
            self._watched.append(window)
            window.installEventFilter(self)

    def eventFilter(self, watched, event) -> bool:
        """Qt override: keep modal dialogs modal for everything but STOP, and let STOP act through them."""
        kind = event.type()
        if kind in _INPUT and isinstance(watched, QWindow):
            return self._filter_input(watched, event)
        if kind == QEvent.Type.FocusIn and isinstance(watched, QWindow):
            self._keep_in_front(watched)  # the window's shortcuts act before its filters: keys stay with the dialog
        if kind == QEvent.Type.ChildPolished and isinstance(event.child(), QDialog) and event.child().isWindow():
            event.child().installEventFilter(self)  # its Show comes here, and its own dialogs' polish
        elif kind == QEvent.Type.Show and isinstance(watched, QDialog):
            self._take_modality(watched)
        return False

    def _take_modality(self, dialog: QDialog):
        # Its QWindow's modality, not the widget's: Qt reads it as the window shows, just after this Show event
        # (and the widget's would make a new native window, hiding the dialog).
        window = dialog.windowHandle()
        if dialog.windowModality() != Qt.WindowModality.NonModal and window is not None:
            window.setModality(Qt.WindowModality.NonModal)
            if dialog not in self._dialogs:
                self._dialogs.append(dialog)

    def _filter_input(self, window: QWindow, event) -> bool:
        kind = event.type()
        popup = window.type() == Qt.WindowType.Popup  # a menu, a box's list
        if kind == QEvent.Type.KeyPress and event.key() == Qt.Key.Key_Escape and window is not self._main:
            self._stop()  # from a dialog or a menu, which still closes as it always did
            return False
        if kind in _PRESSES and popup:
            where = event.globalPosition().toPoint()
            if not window.geometry().contains(where) and self._on_stop(where):
                self._stop()  # Qt closes the menu with this press and gives it to nothing else
            return False
        dialogs = self.open_dialogs
        if not dialogs or popup or self._within(window, dialogs[-1].windowHandle()):
            return False
        if kind in _PRESSES and window is self._main and self._on_stop(event.globalPosition().toPoint()):
            self._stop()
        elif kind == QEvent.Type.MouseButtonPress:
            self._keep_in_front(window)
        return True

    def _keep_in_front(self, window: QWindow):
        """As a modal dialog does: the newest dialog comes to the front when ``window`` under it is used."""
        dialogs = self.open_dialogs
        if dialogs and window.type() != Qt.WindowType.Popup and not self._within(window, dialogs[-1].windowHandle()):
            dialogs[-1].raise_()
            dialogs[-1].activateWindow()

    @staticmethod
    def _within(window: QWindow, owner: QWindow) -> bool:
        """Whether ``window`` is ``owner`` or one of its dialogs or menus (at any depth)."""
        while window is not None:
            if window is owner:
                return True
            window = window.transientParent() or window.parent()
        return False

    def _on_stop(self, global_point) -> bool:
        toolbar = self._toolbar()
        button = toolbar.widgetForAction(toolbar.stop_action)
        return (button is not None and button.isVisible()
                and button.rect().contains(button.mapFromGlobal(global_point)))

    def _stop(self):
        action = self._toolbar().stop_action
        if action.isEnabled():
            action.trigger()
