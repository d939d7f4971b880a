"""The run toolbar: Run, Pause (Continue in its place while paused), Step, a big red STOP, slow motion
and where the program runs (every kind of robot link in the registry, ``robot/links.py``)."""
from PySide6.QtCore import Qt, Signal
from PySide6.QtGui import QAction, QKeySequence
from PySide6.QtWidgets import QComboBox, QLabel, QMainWindow, QSlider, QStyle, QToolBar

from rockly_desktop.robot.links import link_kind, link_kinds
from rockly_desktop.ui.texts import tr

SLIDER_STEPS = 10
SLOWEST_DELAY = 2.0  # seconds per block at the slowest setting
RUN_KEYS = "F5"  # Run's while idle, Continue's while paused


class RunToolbar(QToolBar):
    """Actions for running programs; ``set_state`` enables what makes sense. ``big``: larger
    buttons and an even bigger STOP, for a fair stand's touch screen (kiosk mode), no choice
    of robot (a kiosk runs on the simulator), and a toolbar that cannot be moved or hidden."""

    sig_delay_changed = Signal(float)

    def __init__(self, language: str, parent=None, big: bool = False):
        super().__init__(tr("run", language), parent)
        self._language = language
        self._always_shown = big
        self._robot_locked = False
        self._watching = False  # attached to a run another window controls
        if big:
            self.setMovable(False)
            self.setFloatable(False)
            self.toggleViewAction().setEnabled(False)
            self.toggleViewAction().setVisible(False)
        self.setObjectName("run_toolbar")
        self.setToolButtonStyle(Qt.ToolButtonStyle.ToolButtonTextBesideIcon)
        # Narrow enough that every command fits a 1280 px window in German too (nothing behind the » button).
        self.setStyleSheet("QToolButton { font-size: 19px; font-weight: bold; padding: 10px 8px; }" if big else
                           "QToolButton { font-size: 15px; font-weight: bold; padding: 6px 7px; }")
        icons = QStyle.StandardPixmap
        self.run_action = self._action("run", "run_tip", RUN_KEYS, icons.SP_MediaPlay)
        if big:  # a visitor's buttons first: on a narrow screen the toolbar folds its last ones into »
            self._add_stop(big)
            self.reset_action = self._add_reset()
        self.pause_action = self._action("pause", "pause_tip", "F6", icons.SP_MediaPause)
        self.step_action = self._action("step", "step_tip", "F10", icons.SP_MediaSkipForward)
        self.continue_action = self._action("continue", "continue_tip", None, icons.SP_MediaSeekForward)
        if not big:
            self._add_stop(big)
        self.addSeparator()
        self.addWidget(QLabel(f" {tr('speed', language)}:  {tr('slow', language)} ", self))
        self.speed = QSlider(Qt.Orientation.Horizontal, self)
        self.speed.setRange(0, SLIDER_STEPS)
        self.speed.setValue(SLIDER_STEPS)
        self.speed.setFixedWidth(100 if big else 110)
        self._speed_tip()
        self.speed.valueChanged.connect(lambda _value: self.sig_delay_changed.emit(self.delay))
        self.speed.valueChanged.connect(self._speed_tip)
        self.addWidget(self.speed)
        self.addWidget(QLabel(f" {tr('fast', language)}  ", self))
        self.addSeparator()
        # "Run on", not "Robot": the Robot menu chooses which robot, this box where the program runs
        robot_choice = [self.addWidget(QLabel(f" {tr('run_on', language)} ", self))]
        self.backend = QComboBox(self)
        self.backend.setToolTip(tr("run_on_tip", language))
        # as wide as the usual choices; a longer one is cut off in the box, whole in its list
        self.backend.setSizeAdjustPolicy(QComboBox.SizeAdjustPolicy.AdjustToMinimumContentsLengthWithIcon)
        self.backend.setMinimumContentsLength(14)
        for entry in link_kinds():
            self.backend.addItem(tr(entry.name, language), entry.kind)
        robot_choice += [self.addWidget(self.backend), self.addSeparator()]
        for action in robot_choice if big else ():  # a kiosk runs on the simulator; the room goes to big buttons
            action.setVisible(False)
        if not big:
            self.reset_action = self._add_reset()
        self.backend.currentIndexChanged.connect(lambda _index: self.set_state(self._state))
        self.set_state("idle")

    def _add_stop(self, big: bool):
        self.stop_action = QAction(self.style().standardIcon(QStyle.StandardPixmap.SP_MediaStop),
                                   tr("stop", self._language), self)
        self.stop_action.setObjectName("action_stop")
        self.stop_action.setToolTip(tr("stop_tip", self._language))
        self.stop_action.setShortcut(QKeySequence(Qt.Key.Key_Escape))
        self.stop_action.setShortcutContext(Qt.ShortcutContext.WindowShortcut)
        self.addAction(self.stop_action)
        stop_button = self.widgetForAction(self.stop_action)
        stop_button.setObjectName("stop_button")
        stop_size = "font-size: 28px; padding: 12px 26px;" if big else "font-size: 18px; padding: 6px 16px;"
        stop_button.setStyleSheet(f"QToolButton {{ background: #d32f2f; color: white; {stop_size} font-weight: bold;"
                                  " border-radius: 6px; margin: 2px 6px; }"
                                  "QToolButton:disabled { background: #e8a0a0; }"
                                  "QToolButton:hover { background: #b71c1c; }")

    def _add_reset(self) -> QAction:
        # put the simulated robot back: also in the Robot menu, so its shortcut is the window's
        return self._action("reset_robot", "reset_robot_tip", "Ctrl+R", QStyle.StandardPixmap.SP_BrowserReload)

    def _action(self, key, tip_key, shortcut, icon):
        language = self._language
        action = QAction(self.style().standardIcon(icon), tr(key, language), self)
        action.setObjectName(f"action_{key}")
        action.setToolTip(tr(tip_key, language))
        if shortcut:
            action.setShortcut(shortcut)
        self.addAction(action)
        return action

    def setVisible(self, visible: bool):
        """Qt override: a kiosk's toolbar stays shown while it is in its window (its toggle action, a
        menu or ``hide()`` cannot take STOP away); taken out of the window, it hides."""
        window = self.parentWidget()
        if (not visible and getattr(self, "_always_shown", False) and isinstance(window, QMainWindow)
                and window.toolBarArea(self) != Qt.ToolBarArea.NoToolBarArea):
            visible = True
        super().setVisible(visible)

    def set_robot_locked(self, locked: bool):
        """The teacher locked the robot choice: the Run-on box stays as it is, and says why."""
        self._robot_locked = locked
        self.backend.setToolTip(tr("robot_locked_tip" if locked else "run_on_tip", self._language))
        self.set_state(self._state)

    def set_watching(self, watching: bool):
        """Attached to a run on the robot that another window controls: Pause, Step and Continue are that
        window's (and say so); STOP stays, as a STOP from any window stops the robot."""
        self._watching = watching
        for action, tip in ((self.pause_action, "pause_tip"), (self.step_action, "step_tip"),
                            (self.continue_action, "continue_tip")):
            action.setToolTip(tr("attach_watching_tip" if watching else tip, self._language))
        self.set_state(self._state)

    def _speed_tip(self, *_value):
        """The slider's tooltip says how long each block waits, in the window's language ("0,4 s")."""
        delay = self.delay
        self.speed.setToolTip(tr("speed_tip_wait", self._language, seconds=delay) if delay else
                              tr("speed_tip", self._language))

    @property
    def delay(self) -> float:
        """Seconds to wait at each block for the slider's position."""
        return (SLIDER_STEPS - self.speed.value()) * SLOWEST_DELAY / SLIDER_STEPS

    def set_state(self, state: str):
        """'idle', 'starting', 'running' or 'paused': enable (and show) the actions that apply."""
        self._state = state
        self.reset_action.setEnabled(state == "idle" and link_kind(self.backend.currentData()).simulated)
        self.run_action.setEnabled(state == "idle")
        self.pause_action.setEnabled(state == "running")
        # Pause and Continue take turns in one place (never both needed at once): the bar fits 1280 px in German
        self.pause_action.setVisible(state != "paused")
        self.continue_action.setVisible(state == "paused")
        self.step_action.setEnabled(state in ("idle", "paused"))
        self.continue_action.setEnabled(state == "paused")
        self.continue_action.setShortcut(RUN_KEYS if state == "paused" else "")
        self.run_action.setShortcut(RUN_KEYS if state == "idle" else "")
        self.stop_action.setEnabled(state != "idle")
        if self._watching and state != "idle":
            for action in (self.pause_action, self.step_action, self.continue_action):
                action.setEnabled(False)
        self.backend.setEnabled(state == "idle" and not self._robot_locked)

