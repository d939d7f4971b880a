"""How the window's docks are laid out: the stage (the simulator large, the blocks beside it, the code
and the console out of the way) and bottom tabs that each keep their own height."""
from PySide6.QtCore import QEvent, QObject, Qt, QTimer
from PySide6.QtGui import QAction, QKeySequence

from rockly_desktop.ui.docks.registry import OnStage
from rockly_desktop.ui.texts import tr

STAGE_SHARE = 0.62  # of the window's width the simulator gets on stage, until the person drags the edge
MIN_SHARE, MAX_SHARE = 0.3, 0.85
CONSOLE_STRIP = 96  # px: on stage the console is a strip under the blocks
BLOCKS_PX = 600  # on stage the blocks keep at least this width (toolbox included) unless the person drags


def keep_side_docks_full_height(frame):
    """Let ``frame``'s (a QMainWindow's) right dock area (simulator, code) own the bottom-right corner, so
    that a taller bottom panel (console, topic monitor, plot) takes room from the blocks, never from the simulator."""
    frame.setCorner(Qt.Corner.BottomRightCorner, Qt.DockWidgetArea.RightDockWidgetArea)


class BottomTabSizes(QObject):
    """Each tab of the bottom dock area of ``frame`` (a QMainWindow) keeps its own height: switching tabs
    gives the shown tab the height it had when last shown. A ``roomy`` tab (a message tree, a plot)
    shown for the first time gets a third of the window; the console keeps the strip it had."""

    def __init__(self, frame, docks, roomy=()):
        super().__init__(frame)
        self._frame = frame
        self._docks = tuple(docks)
        self._roomy = set(roomy)
        self._heights = {}
        self._current = None  # the bottom tab on screen, as last seen
        frame.tabifiedDockWidgetActivated.connect(self._switched)
        frame.installEventFilter(self)

    def eventFilter(self, watched, event):
        """Once the window has laid its docks out anew (a layout restored, say), see which
        bottom tab is on screen: Qt changes tabs that way without telling."""
        if watched is self._frame and event.type() == QEvent.Type.LayoutRequest:
            QTimer.singleShot(0, self, self._see_current)
        return False

    def _see_current(self):
        # Qt keeps the tabs not shown at their size, moved off screen.
        self._current = next((dock for dock in self._docks if dock.isVisible() and dock.y() >= 0), self._current)

    def _switched(self, dock):
        """A tab was raised (by the person or in code); the tab left still has its size, off screen."""
        left = self._current
        if dock not in self._docks or dock is left:
            return
        if left is not None and left.height() > 0 and not self._frame.isMinimized():
            self._heights[left] = left.height()
        self._current = dock
        wanted = self._heights.get(dock)
        if wanted is None and dock in self._roomy:
            wanted = max(dock.height(), self._frame.height() // 3)
        if wanted is not None and wanted != dock.height():
            self._frame.resizeDocks([dock], [wanted], Qt.Orientation.Vertical)
            QTimer.singleShot(0, self, lambda: self._correct(dock, wanted))

    def _correct(self, dock, wanted: int):
        """The size resizeDocks gives tabbed docks includes their tab bar: add what is missing."""
        missing = wanted - dock.height()
        if dock is self._current and missing:
            self._frame.resizeDocks([dock], [wanted + missing], Qt.Orientation.Vertical)


class StageLayout(QObject):
    """View → Stage (F11): ``frame`` (the QMainWindow) is maximised (until the stage is left, when it was
    smaller than its screen), the simulator (a real robot's state panels) takes most of it, the blocks stay
    beside it, drawn larger, the console is a strip under them; code, variables, topic monitor and plot are
    closed (each as its entry in ``docks``, a ``registry.Docks``, says). Leaving
    puts back the layout from before. ``settings`` (AppSettings) remember whether the stage was on, the
    simulator's share of the width and the layout to go back to; the page in ``editor`` is told when
    the stage is on; ``robots`` (RobotChoice) says whether the robot is simulated.
    """

    def __init__(self, frame, settings, editor, robots, docks):
        super().__init__(frame)
        self._frame = frame
        self._settings = settings
        self._editor = editor
        self._robots = robots
        self._docks = docks
        self._normal_state = None
        self._share = settings.stage_share or STAGE_SHARE
        self._persons_share = settings.stage_share is not None  # a width the person dragged is kept as it is
        self._settled = False  # the docks have the sizes given (only then is a share the person's)
        self._given = 0  # px the simulator was given last
        self._maximised_for_stage = False  # the stage maximised the window: leaving gives it its size back
        self._normal_sizes = None  # (the big dock, its width and height) before the stage
        self._left_state = None  # the layout the stage was left for
        self._resized_back = True  # False from leaving a stage that maximised the window until it has its size
        self.action = QAction(frame, checkable=True)
        self.action.setObjectName("action_stage")
        self.action.setShortcut(QKeySequence(Qt.Key.Key_F11))
        self.action.toggled.connect(self._toggled)
        frame.installEventFilter(self)
        # the page keeps its flyout and zoom controls off the blocks on stage (a page made anew is told again)
        editor.sig_ready.connect(self._tell_page)
        # another robot shows or hides the simulator: arrange again once the window has done so
        robots.sig_robot_changed.connect(lambda: self.active and QTimer.singleShot(0, self, self.arrange))

    @property
    def active(self) -> bool:
        """True while the stage layout is on."""
        return self._normal_state is not None

    def action_for(self, language: str) -> QAction:
        """The checkable View → Stage action, with its texts in ``language``."""
        self.action.setText(tr("stage", language))
        self.action.setToolTip(tr("stage_tip", language))
        return self.action

    def restore_remembered(self):
        """Go on stage when the window was on stage when it last closed."""
        if self._settings.stage:
            self._normal_state = self._settings.normal_window_state or self._frame.saveState()
            self.arrange()
            self.action.setChecked(True)

    def set_active(self, on: bool):
        """Go on stage, or back to the layout from before."""
        self.action.setChecked(on)

    def _toggled(self, on: bool):
        if on == self.active:
            return
        frame = self._frame
        if on:
            self._normal_state = frame.saveState()
            big = self._big_dock()
            self._normal_sizes = (big, big.width(), big.height()) if big.isVisible() else None
            self._maximised_for_stage = not self._fills_its_screen()
            if self._maximised_for_stage:
                frame.showMaximized()
            self.arrange()
        else:
            self._keep_share()
            self._left_state, self._normal_state = self._normal_state, None
            if self._maximised_for_stage:
                self._maximised_for_stage = False
                self._resized_back = False  # the layout is given again once the window has its size back
                frame.showNormal()
            self._go_back()
        self._settings.stage = on
        self._tell_page()

    def _fills_its_screen(self) -> bool:
        """The window is maximised or full screen, or as wide or as tall as its screen's room anyway."""
        frame = self._frame
        if frame.isMaximized() or frame.isFullScreen() or frame.screen() is None:
            return True
        room, size = frame.screen().availableGeometry(), frame.frameGeometry()
        return size.width() >= room.width() or size.height() >= room.height()

    def _go_back(self):
        """The layout from before the stage, with the big dock's size from then (restoring a layout in a window
        of another size gives docks other sizes: a maximised window's simulator came back a sliver)."""
        if self.active or self._left_state is None:
            return
        self._frame.restoreState(self._left_state)
        if self._normal_sizes is None:
            return
        dock, width, height = self._normal_sizes
        self._frame.resizeDocks([dock], [width], Qt.Orientation.Horizontal)
        self._frame.resizeDocks([dock], [height], Qt.Orientation.Vertical)

    def _tell_page(self):
        self._editor.call("setStage", {"on": self.active})

    def state_to_keep(self):
        """The dock layout the window keeps when it closes: the one from before the stage while on stage
        (the stage is remembered apart, with the simulator's share)."""
        if not self.active:
            return self._frame.saveState()
        self._keep_share()
        self._settings.normal_window_state = self._normal_state
        return self._normal_state

    def _big_dock(self):
        big = OnStage.BIG_SIMULATED if self._robots.simulated else OnStage.BIG_REAL
        return self._docks.where(lambda spec: spec.on_stage == big)[0]

    def _strips(self):
        return self._docks.where(lambda spec: spec.on_stage == OnStage.STRIP)

    def arrange(self):
        """On stage, show only the stage's docks, at the stage's sizes (again, after they were changed)."""
        big, strips = self._big_dock(), self._strips()
        for dock in self._docks.values():
            if dock is not big and dock not in strips:
                dock.hide()
        big.show()
        for strip in strips:
            strip.show()
            strip.raise_()
        self._apply_sizes()
        self._apply_later()

    def _apply_later(self):
        """Give the sizes again once the docks have been laid out, and count them as settled after that."""
        self._settled = False
        QTimer.singleShot(0, self, self._apply_sizes)
        QTimer.singleShot(0, self, lambda: QTimer.singleShot(0, self, self._settle))

    def _settle(self):
        self._settled = True

    def _apply_sizes(self):
        if not self.active:
            return
        frame = self._frame
        share = self._share
        if not self._persons_share:
            share = min(share, max(MIN_SHARE, 1 - BLOCKS_PX / max(1, frame.width())))
        self._given = round(frame.width() * share)
        frame.resizeDocks([self._big_dock()], [self._given], Qt.Orientation.Horizontal)
        strips = self._strips()
        frame.resizeDocks(strips, [CONSOLE_STRIP] * len(strips), Qt.Orientation.Vertical)

    def _keep_share(self):
        """Remember the share of the width the person left the simulator (it may have been dragged)."""
        width, big = self._frame.width(), self._big_dock()
        dragged = abs(big.width() - self._given) > 4  # not the width the blocks' minimum gave it
        if self._settled and big.isVisible() and width > 0 and dragged:
            self._share = min(MAX_SHARE, max(MIN_SHARE, big.width() / width))
            self._persons_share = True
            self._settings.stage_share = self._share

    def eventFilter(self, watched, event):
        """On stage, a window shown, grown or shrunk gives the simulator its share of its width; a window the
        stage maximised gets the layout from before once it has its size back."""
        if watched is self._frame and event.type() in (QEvent.Type.Resize, QEvent.Type.Show):
            if self.active:
                self._apply_later()
            elif event.type() == QEvent.Type.Resize and not self._resized_back and not self._frame.isMaximized():
                self._resized_back = True
                QTimer.singleShot(0, self, self._go_back)  # once the docks have been laid out at that size
        return False
