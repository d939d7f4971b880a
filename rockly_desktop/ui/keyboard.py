"""The main window from the keyboard alone: Tab and Shift+Tab through every control in reading order, a ring
that shows where the keys go (in the window and in the dialogs it opens), keys to jump to the toolbox, the
blocks, the code, the console and the simulator, and focus that enters the block editor on the workspace with
Blockly's own keys on.

Tab is the window's shortcut, not each widget's: tables, the web view and text views would keep it.
"""
import shiboken6
from PySide6.QtCore import QEvent, QObject, QPoint, QRect, Qt
from PySide6.QtGui import QAction, QKeySequence, QShortcut
from PySide6.QtWidgets import QApplication, QDockWidget, QFrame, QTabBar, QToolBar, QToolButton

from rockly_desktop.ui.accessible_names import name_controls
from rockly_desktop.ui.texts import tr

# (action key in the catalogue, keys, where it goes: the editor's toolbox or blocks, or a dock's key in
# ui/docks/registry.py); Ctrl+digit clashes with none of Rockly's or Blockly's keys
JUMPS = (("jump_toolbox", "Ctrl+1", "toolbox"), ("jump_blocks", "Ctrl+2", "blocks"),
         ("jump_code", "Ctrl+3", "code_dock"), ("jump_console", "Ctrl+4", "console_dock"),
         ("jump_simulator", "Ctrl+5", "simulator_dock"))

# The focus ring: a frame laid over the focused control, drawn by this style sheet rule.
FOCUS_RING_STYLE = "QFrame#focus_ring { border: 3px solid #ff6d00; border-radius: 4px; background: transparent; }"


class FocusRing(QFrame):
    """A thick orange frame over the control that has the keyboard (it takes no clicks and no focus)."""

    def __init__(self, window):
        super().__init__(window)
        self.setObjectName("focus_ring")
        self.setStyleSheet(FOCUS_RING_STYLE)
        self.setAttribute(Qt.WidgetAttribute.WA_TransparentForMouseEvents)
        self.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        self.target = None

    def follow(self, widget):
        """Lie over ``widget`` (None: hide)."""
        if self.target is not None and shiboken6.isValid(self.target):
            self.target.removeEventFilter(self)
        self.target = widget
        if widget is None:
            self.hide()
            return
        self.setParent(widget)
        widget.installEventFilter(self)
        self._fit()
        self.show()
        self.raise_()

    def _fit(self):
        self.setGeometry(self.target.rect())

    def eventFilter(self, watched, event):
        """Qt override: keep the ring the size of its control."""
        if watched is self.target and event.type() == QEvent.Type.Resize:
            self._fit()
        return False


class KeyboardAccess(QObject):
    """Installs Tab order, the focus ring and the jump keys on ``frame`` (the QMainWindow).

    ``editor`` is the block editor, ``run_toolbar()`` the run toolbar of the moment, ``docks`` the
    window's ``registry.Docks``, ``language()`` the window's language; with ``settings.kiosk_mode`` a
    closed dock stays closed. Each signal in ``renamed_on`` says that controls may have come or gone.

    The keys work at once; the controls get their names, the toolbar's buttons the keyboard and the
    ring its first control once the editor is up (or has said it cannot start): done while the window
    was built, that work (Python wrappers and enums for every control) delayed the editor's start.
    """

    def __init__(self, frame, editor, run_toolbar, docks, language, settings, renamed_on=()):
        super().__init__(frame)
        self.frame = frame
        self._editor = editor
        self._run_toolbar = run_toolbar
        self._docks = docks
        self._language = language
        self._settings = settings
        self.ring = None
        self._previous = QShortcut(QKeySequence("Shift+Tab"), frame, lambda: self.move(-1))  # (Backtab too)
        self._next = QShortcut(QKeySequence(Qt.Key.Key_Tab), frame, lambda: self.move(1))
        self.jump_actions = {}
        for key, keys, place in JUMPS:
            action = QAction(tr(key, language()), frame)
            action.setObjectName(f"action_{key}")
            action.setShortcut(QKeySequence(keys))
            action.setShortcutContext(Qt.ShortcutContext.WindowShortcut)
            action.triggered.connect(lambda _checked=False, place=place: self.jump(place))
            frame.addAction(action)
            self.jump_actions[key] = action
        QApplication.instance().focusChanged.connect(self._on_focus_changed)
        self._following = True
        self._controls_set_up = False
        self._connections = [(editor.sig_ready, self._on_editor_ready),
                             (editor.sig_page_error, self._set_up_controls)]
        self._connections += [(signal, self._rename) for signal in renamed_on]
        for signal, slot in self._connections:
            signal.connect(slot)

    def stop(self):
        """The window is closing: follow the application's focus, the editor and the signals that rename no
        more, and take the ring off its control (a slot still connected would be handed the window's widgets
        while they are destroyed: a tabbed dock says it is shown when the dock before it goes)."""
        if self._following:
            QApplication.instance().focusChanged.disconnect(self._on_focus_changed)
            for signal, slot in self._connections:
                signal.disconnect(slot)
            self._following = False
        if self.ring is not None and shiboken6.isValid(self.ring):
            self.ring.follow(None)

    # --- Tab order ----------------------------------------------------------------------

    def stops(self) -> list:
        """Every control Tab reaches, in reading order: the run toolbar, the blocks (and the replay bar
        under them), then the docks on the right and at the bottom, each from top to bottom, left to right."""
        frame, editor = self.frame, self._editor
        self._toolbar_buttons_take_focus()
        order = {widget: index for index, widget in enumerate(_focus_chain(frame))}
        groups = {}
        for widget in order:
            if widget is frame or not _reachable(widget, frame):
                continue
            if _inside(widget, editor) and widget is not editor:
                continue  # the web view's inner widget: the view itself is the stop
            groups.setdefault(self._container(widget), []).append(widget)
        for dock in frame.findChildren(QDockWidget):  # a dock with nothing to focus is one stop itself
            content = dock.widget()
            if content is not None and dock not in groups and _reachable(content, frame, any_policy=True):
                content.setFocusPolicy(Qt.FocusPolicy.TabFocus)
                groups[dock] = [content]
        if editor.isVisible():
            groups.setdefault(editor, [editor])
        ordered = sorted(groups, key=self._reading_place)
        stops, taking = [], set()
        for container in ordered:
            for widget in sorted(groups[container], key=lambda w: order.get(w, len(order))):
                if _taker(widget) not in taking:  # (a widget and the one it hands the keyboard to: one stop)
                    taking.add(_taker(widget))
                    stops.append(widget)
        return stops

    def _toolbar_buttons_take_focus(self):
        """Run, STOP and Put back are controls too (a toolbar's buttons take no focus of their own)."""
        toolbar = self._run_toolbar()
        for action in toolbar.actions():
            button = toolbar.widgetForAction(action)
            if isinstance(button, QToolButton) and button.focusPolicy() == Qt.FocusPolicy.NoFocus:
                button.setFocusPolicy(Qt.FocusPolicy.TabFocus)

    def _container(self, widget):
        """What ``widget`` belongs to for the reading order: a toolbar, a dock, a dock's tab bar, the centre."""
        frame = self.frame
        node = widget
        while node is not None and node is not frame:
            if isinstance(node, (QToolBar, QDockWidget)) or node is self._editor:
                return node
            if isinstance(node, QTabBar) and node.parentWidget() is frame:
                return node
            node = node.parentWidget()
        return frame.centralWidget()

    def _reading_place(self, container):
        """Where ``container`` comes in the reading order: (region, top, left, 0); the tab bar of tabbed docks
        right after the dock it shows (it belongs to that group, not to the next one down)."""
        if isinstance(container, QTabBar):
            dock = self._shown_by(container)
            if dock is not None:
                return self._reading_place(dock)[:3] + (1,)
        frame = self.frame
        if isinstance(container, QToolBar):
            region = 0
        elif container is self._editor or container is frame.centralWidget():
            region = 1 if container is self._editor else 2
        else:
            area = frame.dockWidgetArea(container) if isinstance(container, QDockWidget) else None
            top_left = container.mapTo(frame, container.rect().topLeft())
            bottom = area == Qt.DockWidgetArea.BottomDockWidgetArea or (
                area is None and top_left.y() > frame.centralWidget().geometry().bottom() - 1)
            region = 4 if bottom else 3
        top_left = container.mapTo(frame, container.rect().topLeft())
        return region, top_left.y(), top_left.x(), 0

    def _shown_by(self, bar):
        """The dock a main window's tab ``bar`` shows now: the one in sight over (or under) it."""
        frame = self.frame
        place = QRect(bar.mapTo(frame, QPoint(0, 0)), bar.size())
        beside = []
        for dock in frame.findChildren(QDockWidget):
            if not dock.isVisible() or dock.visibleRegion().isEmpty():
                continue
            area = QRect(dock.mapTo(frame, QPoint(0, 0)), dock.size())
            if area.left() <= place.center().x() <= area.right():
                beside.append((min(abs(area.bottom() - place.top()), abs(place.bottom() - area.top())), dock))
        return min(beside, key=lambda pair: pair[0])[1] if beside else None

    def move(self, step: int):
        """Give the keyboard to the next (``step`` 1) or previous (-1) control; from nowhere, to the first."""
        stops = self.stops()
        if not stops:
            return
        current = self._current_stop(stops)
        index = stops.index(current) + step if current in stops else (0 if step > 0 else -1)
        self.give_focus(stops[index % len(stops)], Qt.FocusReason.TabFocusReason if step > 0
                        else Qt.FocusReason.BacktabFocusReason)

    def _current_stop(self, stops):
        by_taker = {_taker(stop): stop for stop in stops}
        focused = QApplication.focusWidget()
        while focused is not None and focused not in stops and focused not in by_taker:
            focused = focused.parentWidget()
        return by_taker.get(focused, focused)

    def give_focus(self, widget, reason=Qt.FocusReason.OtherFocusReason):
        """Focus ``widget``; the block editor gets its workspace focused, Blockly's keys on."""
        widget.setFocus(reason)
        if widget is self._editor:
            self._editor.call("focusWorkspace")

    # --- jumps --------------------------------------------------------------------------

    def jump(self, place: str):
        """Give the keyboard to the toolbox, the blocks, or a dock by its key (code, console, simulator)."""
        frame = self.frame
        if place in ("toolbox", "blocks"):
            self._editor.setFocus(Qt.FocusReason.ShortcutFocusReason)
            self._editor.call("focusToolbox" if place == "toolbox" else "focusWorkspace")
            return
        dock = self._docks[place]
        if dock.isHidden():
            if self._settings.kiosk_mode:
                return  # a kiosk's closed docks stay closed
            dock.show()
        dock.raise_()
        self.stops()  # (makes a dock with nothing else to focus focusable)
        target = dock.widget()
        candidates = [widget for widget in _focus_chain(frame) if _inside(widget, target)
                      and widget.focusPolicy() & Qt.FocusPolicy.TabFocus and widget.isVisibleTo(frame)]
        target = candidates[0] if candidates else target
        target.setFocus(Qt.FocusReason.ShortcutFocusReason)

    # --- names, ring and language -------------------------------------------------------

    def name_controls(self, *_args):
        """Give every control of the window its accessible name in the window's language (none once the window
        is deleted: one deleted without closing, e.g. a kiosk that cannot start, still has its docks' signals)."""
        if shiboken6.isValid(self.frame):
            name_controls(self.frame, self._language(), self._editor, self._run_toolbar())

    def set_language(self, language: str):
        """The window now speaks ``language``: the jump keys' names and the controls' names follow."""
        for key, action in self.jump_actions.items():
            action.setText(tr(key, language))
        self._toolbar_buttons_take_focus()  # (the toolbar was made anew)
        name_controls(self.frame, language, self._editor, self._run_toolbar())

    def _set_up_controls(self, *_args):
        """Name the controls and let the toolbar's buttons take the keyboard (the first time only)."""
        if self._controls_set_up or not shiboken6.isValid(self.frame):
            return
        self._controls_set_up = True
        self._toolbar_buttons_take_focus()
        self.name_controls()

    def _rename(self, *_args):
        if self._controls_set_up:  # (before, the set-up names them all)
            self.name_controls()

    def _on_editor_ready(self):
        if self._controls_set_up:
            self.name_controls()  # a new page (another robot or language): controls may have changed
        else:
            self._set_up_controls()
        focused = QApplication.focusWidget()
        if focused is None or _inside(focused, self._editor):  # a fresh window: keys go to the blocks
            self.give_focus(self._editor)

    def _on_focus_changed(self, _old, new):
        if not self._controls_set_up:
            return  # the editor's start gives the keyboard to the blocks, with the ring
        if not shiboken6.isValid(self.frame) or new is None or not _opened_by(new.window(), self.frame):
            return  # (another window has the keyboard: the ring stays where it comes back to)
        if new.window() is self.frame and not new.accessibleName():  # a control made since the window was named
            self.name_controls()
        if self.ring is None or not shiboken6.isValid(self.ring):  # it went with the control it lay over
            self.ring = FocusRing(self.frame)
        if QApplication.mouseButtons() != Qt.MouseButton.NoButton:
            self.ring.follow(None)  # a click or a touch shows where it went by itself: the ring is for keys
            return
        self.ring.follow(self._editor if _inside(new, self._editor) else new)


def _opened_by(window, frame) -> bool:
    """True for ``frame`` itself and for a dialog it opened (or one such a dialog opened): the ring goes there too."""
    while window is not None:
        if window is frame:
            return True
        parent = window.parentWidget()
        window = parent.window() if parent is not None else None
    return False


def _focus_chain(window) -> list:
    """The window's widgets in Qt's focus chain order (the order they were made in)."""
    chain, widget = [], window.nextInFocusChain()
    while widget is not None and widget is not window and len(chain) < 10000:
        chain.append(widget)
        widget = widget.nextInFocusChain()
    return chain


def _taker(widget):
    """The widget that gets the keyboard when ``widget`` is focused (its focus proxy's, if it has one)."""
    while widget.focusProxy() is not None:
        widget = widget.focusProxy()
    return widget


def _inside(widget, ancestor) -> bool:
    while widget is not None:
        if widget is ancestor:
            return True
        widget = widget.parentWidget()
    return False


def _reachable(widget, window, any_policy=False) -> bool:
    """True when ``widget`` can take the keyboard by Tab now: shown, enabled, in sight, in ``window``."""
    if not any_policy and not widget.focusPolicy() & Qt.FocusPolicy.TabFocus:
        return False
    if isinstance(widget, FocusRing) or widget.window() is not window:
        return False
    return widget.isVisible() and widget.isEnabled() and not widget.visibleRegion().isEmpty()
