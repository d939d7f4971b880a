"""Rockly's main window: the block editor, the run toolbar, the docks, menus and the status bar."""
from PySide6.QtCore import QEvent, Qt, QTimer
from PySide6.QtGui import QAction, QActionGroup, QKeySequence
from PySide6.QtWidgets import QApplication, QLabel, QMainWindow, QMessageBox

from rockly_desktop import __version__
from rockly_desktop.bridge.editor_view import ANSWER_TIMEOUT_MS, EditorView
from rockly_desktop.core.errors import RocklyError
from rockly_desktop.core.recovery import RecoverySession, claim_abandoned
from rockly_desktop.robot.links import link_kind
from rockly_desktop.runtime.agent.protocol import DEFAULT_PORT
from rockly_desktop.ui.agent.agent_bar import AgentBar, AgentWay, agent_address
from rockly_desktop.ui.agent.attached_run import AttachedRun
from rockly_desktop.ui.docks.lesson_guide import LessonGuide
from rockly_desktop.ui.docks.registry import Docks
from rockly_desktop.ui.docks.stage_layout import BottomTabSizes, StageLayout, keep_side_docks_full_height
from rockly_desktop.ui.docks.state_panels import StatePanels
from rockly_desktop.ui.docks.tablet import QtTablet
from rockly_desktop.ui.docks.tablet_placement import global_rect
from rockly_desktop.ui.files.autosave import Autosave
from rockly_desktop.ui.files.document import Document
from rockly_desktop.ui.files.examples_menu import ExamplesMenu
from rockly_desktop.ui.files.program_files import ProgramFiles
from rockly_desktop.ui.files.recovery_prompt import RecoveryPrompt
from rockly_desktop.ui.keyboard import KeyboardAccess
from rockly_desktop.ui.message_boxes import plain_message_box
from rockly_desktop.ui.plain_text import mnemonic_free, plain_label
from rockly_desktop.ui.replay.replay import Replay
from rockly_desktop.ui.replay.replay_bar import ReplayBar, under
from rockly_desktop.ui.robot.health_bar import HealthBar
from rockly_desktop.ui.robot.robot_choice import RobotChoice
from rockly_desktop.ui.run.block_badges import badges_shown
from rockly_desktop.ui.run.run_session import RunSession
from rockly_desktop.ui.run.run_toolbar import RunToolbar
from rockly_desktop.ui.run.stop_anywhere import StopAnywhere
from rockly_desktop.ui.texts import editor_page_texts, tr
from rockly_desktop.ui.window_fit import fit_first_window


class MainWindow(QMainWindow):
    """The editor window. ``registry`` holds the profiles, ``settings`` what is remembered;
    ``editor`` may be passed in already loading its page (see ``app.build_main_window``).

    It builds the widgets and the helpers (file commands, run session, robot choice) and
    wires them: the helpers share the ``document`` and report back with signals.
    """

    def __init__(self, registry, settings, editor: EditorView = None):
        super().__init__()
        self.registry = registry
        self.settings = settings
        self.document = Document(self._initial_profile(), self)
        self._starting = False
        self._editor_started = False
        self._robot_shown = False
        self._close_waiting = False  # closing waits until the program is saved
        self._close_approved = False
        self._in_close_event = False
        # runs a teacher's command (choosing the robot, Preferences); kiosk mode asks for the PIN first
        self.teacher_gate = lambda command: command()
        self.gate_asks_pin = False  # True when teacher_gate has checked the PIN (Preferences then asks no more)
        self.setObjectName("main_window")

        self.editor = editor or EditorView()
        self.editor.set_look(settings.block_look)
        self.replay_bar = ReplayBar(settings.current_language, self)
        self.setCentralWidget(under(self.editor, self.replay_bar))
        self.docks = Docks(self, self.language)  # every dock, as ui/docks/registry.py lists them
        # the docks the window itself fills or talks to
        self.simulator_dock, self.code_dock = self.docks["simulator_dock"], self.docks["code_dock"]
        self.variables, self.state_dock = self.docks["variables_dock"], self.docks["state_dock"]
        self.console, self.monitor_dock = self.docks["console_dock"], self.docks["monitor_dock"]
        self.plot_dock, self.lessons_dock = self.docks["plot_dock"], self.docks["lessons_dock"]
        # the plot is made when its tab first shows (once a robot's store is there to plot from)
        self.plot_dock.visibilityChanged.connect(
            lambda visible: visible and self._plot_store is not None and self.plot_panel())
        bottom = Qt.DockWidgetArea.BottomDockWidgetArea
        self.bottom_tabs = BottomTabSizes(self, self.docks.where(lambda spec: spec.area == bottom),
                                          roomy=self.docks.where(lambda spec: spec.roomy))
        keep_side_docks_full_height(self)
        self._plot_store = None
        self.docks.place()
        self.profile_label = plain_label(parent=self, objectName="profile_label")
        self.tablet = QtTablet(self, self.profile.display_name(), lambda: self.language,
                               clear_of=lambda: global_rect(self.simulator_dock))
        self.tablet.sig_unanswered.connect(lambda robot: self.console.append(
            tr("tablet_no_answer", self.language, robot=robot), "robot"))
        self.tablet.sig_notice.connect(lambda _robot, text: self.console.append(
            tr("robot_says", self.language, text=text), "robot"))
        self.robots = RobotChoice(self.document, self.tablet, settings, self)
        self.robots.sig_robot_changed.connect(self.show_robot)
        self.runs = RunSession(self.document, self.editor, self.robots, self.console, self.variables, settings, self)
        self.attached = AttachedRun(self.editor, self.console, self.variables, lambda: self.language, self,
                                    breakpoints=lambda: self.document.breakpoints, record=self._record_attached)
        self.runs.sig_state_changed.connect(self._on_run_state)
        self.attached.sig_state_changed.connect(self._on_run_state)
        self.attached.sig_state_changed.connect(lambda _state: self.simulator_dock.say_not_the_robot(
            tr("simulator_not_the_robot", self.language) if self.attached.active else ""))
        self.attached.sig_control_changed.connect(lambda controls: self.run_toolbar.set_watching(not controls))
        self.attached.sig_status.connect(lambda text: self.statusBar().showMessage(text))
        self.runs.sig_status.connect(lambda text: self.statusBar().showMessage(text))
        self.tablet.sig_dismissed.connect(self.runs.stop)
        self.replay = Replay(self.replay_bar, self.editor, self.variables, self.simulator_dock,
                             settings.current_language, self,
                             lambda: badges_shown(self.settings, self.profile.id), self.console, self._made_plot,
                             lambda: self.state_dock.widget() if isinstance(self.state_dock.widget(), StatePanels)
                             else None, self.robots, registry)
        self.replay.sig_past_shown.connect(lambda keys: self.docks.mark_past(keys, self.language))
        self.runs.sig_state_changed.connect(lambda state: state == "starting" and self.replay.close())
        self.runs.sig_finished.connect(lambda _result: self.runs.last_recording and self.replay.open(
            self.runs.last_recording, quiet=True))
        self.attached.sig_recorded.connect(lambda path: self.replay.open(path, quiet=True))
        self.health = HealthBar(settings.current_language, self)
        self.health.sig_refreshed.connect(self.robots.show_health)  # one source for the light and the status
        self.agent_bar = AgentBar(self.attached, lambda: self.language, self._agent_way, self,
                                  gate=lambda command: self.teacher_gate(command))
        self.robots.sig_robot_changed.connect(self.agent_bar.look)
        self.statusBar().addPermanentWidget(self.agent_bar)
        self.statusBar().addPermanentWidget(self.health)
        self.statusBar().addPermanentWidget(self.robots.status)
        self.statusBar().addPermanentWidget(self.profile_label)
        self._build_run_toolbar()
        self.stop_anywhere = StopAnywhere(self, lambda: self.run_toolbar)  # STOP acts through dialogs and menus

        self.files = ProgramFiles(self.document, self.editor, settings, registry, self)
        self.files.sig_status.connect(lambda text: self.statusBar().showMessage(text, 8000))
        self.files.may_reload = lambda: self.runs.state == "idle"
        self.files.sig_show_program.connect(self.show_program)
        self.files.sig_program_replaced.connect(self.robots.reset_if_wanted)
        self.files.sig_program_replaced.connect(self._forget_old_program)
        self.robots.sig_robot_changed.connect(self._forget_old_program)
        self.autosave = Autosave(self.document, self.editor, RecoverySession(), lambda: self.language, self)
        self.autosave.sig_failed.connect(lambda text: self.statusBar().showMessage(text, 8000))
        self.runs.sig_state_changed.connect(lambda state: state == "starting" and self.autosave.flush())
        self.recovery_prompt = None
        self.document.sig_changed.connect(self._update_title)
        self.editor.sig_changed.connect(self._on_editor_changed)
        self.editor.sig_ready.connect(self.statusBar().clearMessage)
        self.editor.sig_ready.connect(self._first_show_robot)
        self.editor.sig_breakpoints.connect(self._on_breakpoints)
        self.editor.sig_edit_made_block.connect(
            lambda block_id: self.teacher_gate(lambda: self.edit_made_block(block_id)))
        self.editor.sig_page_error.connect(
            lambda message: self.statusBar().showMessage(tr("editor_error", self.language, message=message), 15000))

        self.lessons = LessonGuide(self.lessons_dock, self.editor, self.files, self.replay, settings.lessons,
                                   registry.profiles, lambda: self.profile,
                                   lambda: self.profile.toolbox(self.language, *self._toolbox_choice()),
                                   lambda: self.language, self)
        self.lessons_dock.visibilityChanged.connect(lambda visible: visible and self.lessons.follow_robot())
        self.document.sig_profile_changed.connect(lambda _profile: self.lessons.follow_robot())
        self.stage = StageLayout(self, settings, self.editor, self.robots, self.docks)
        self._build_menus()
        self.document.sig_profile_changed.connect(self._on_profile_changed)
        self.keys = KeyboardAccess(self, self.editor, lambda: self.run_toolbar, self.docks, lambda: self.language,
                                   settings, renamed_on=(self.robots.sig_robot_changed,
                                                         self.plot_dock.visibilityChanged))
        fit_first_window(self)
        if settings.window_geometry is not None:
            self.restoreGeometry(settings.window_geometry)
        if settings.window_state is None or not self.restoreState(settings.window_state):
            self.docks.give_first_sizes()
        self.stage.restore_remembered()
        self._update_title()

    @property
    def profile(self):
        """The robot profile of the program on screen (the document's)."""
        return self.document.profile

    @property
    def simulator_speed(self) -> float:
        """How much faster than real time the built-in simulator runs (for robots made from now on)."""
        return self.robots.simulator_speed

    @simulator_speed.setter
    def simulator_speed(self, speed: float):
        self.robots.simulator_speed = speed

    # --- start-up -----------------------------------------------------------------------

    def _initial_profile(self):
        remembered = self.settings.profile_id
        if remembered in self.registry.profiles:
            return self.registry.get(remembered)
        return self.registry.default()

    def start(self, open_path=None):
        """Start the editor, with ``open_path`` or the last file shown in its first frame, and
        offer the unsaved program a Rockly that did not close cleanly left behind."""
        self.statusBar().showMessage(tr("loading_editor", self.language))
        self._starting = True
        path = open_path or self.settings.last_file
        if path:
            self.files.open(path)
        self._starting = False
        if not self._editor_started:
            self._restart_editor()
        # once the window shows (it may show after start()); not at all once the window is gone
        QTimer.singleShot(0, self, self._ask_what_the_start_found)

    def _ask_what_the_start_found(self):
        """Offer the unsaved program a Rockly that did not close cleanly left behind; name the profiles that broke."""
        recovery = claim_abandoned()
        if recovery is not None:
            self.recovery_prompt = RecoveryPrompt(recovery, self.files, self.autosave, self.language, self)
        if self.registry.errors:
            details = "\n\n".join(str(error) for error in self.registry.errors)
            box = plain_message_box(self, QMessageBox.Icon.Warning, tr("profile_errors_title", self.language), details)
            box.setObjectName("profile_errors_box")
            box.open()

    def _restart_editor(self, first_call=None, on_first_result=None):
        self._editor_started = True
        self.editor.start(self.profile.editor_config(self.language, *self._toolbox_choice()), self.language,
                          first_call, on_first_result, editor_page_texts(self.language))
        self.profile_label.setText(tr("robot_status", self.language, name=self.profile.display_name(self.language)))
        if self._robot_shown:
            self.show_robot()

    def become_kiosk(self, start_program=None):
        """Make this window (built with ``settings.kiosk_mode`` on) a kiosk whose start program is
        ``start_program`` (see ``kiosk.Kiosk``); the teacher's commands then ask for the PIN first."""
        from rockly_desktop.ui.kiosk.kiosk import Kiosk  # not needed outside kiosk mode

        kiosk = Kiosk(self, start_program, settings=self.settings, language=lambda: self.language, stage=self.stage,
                      docks=self.docks, editor=self.editor, document=self.document, files=self.files,
                      replay=self.replay, runs=self.runs, robots=self.robots, run_toolbar=lambda: self.run_toolbar,
                      lessons=self.lessons)
        self.teacher_gate = kiosk.ask_teacher
        self.gate_asks_pin = True
        return kiosk

    # --- the robot ----------------------------------------------------------------------

    def robot(self):
        """The robot programs run on (a ``robot.link.RobotLink``): the profile's simulator, or a robot over ROS."""
        return self.robots.robot()

    def _first_show_robot(self):
        if not self._robot_shown:  # at start the simulator waits until the editor is up
            self._robot_shown = True
            self.show_robot()
            self.agent_bar.start()

    def show_robot(self):
        """Show the active robot in the Simulator dock (a note for a real robot)."""
        try:
            robot = self.robot()
            view_class = self.profile.simulator_view_class()
        except RocklyError as error:
            self.console.append(str(error), "error")
            return
        if self.simulator_dock.robot is robot:
            return
        robot.follow_graph()
        from rockly_desktop.ui.docks.topic_monitor import TopicMonitor  # not needed before the editor is up

        panels = StatePanels(self.profile.state_panels, self.language, self.state_dock)
        panels.set_store(robot.state)
        self.health.show_robot(robot)
        self._replace_dock_widget(self.state_dock, panels)
        monitor = TopicMonitor(robot.state, robot.graph_topics, self.language, own=robot.own_publishers,
                               offers=lambda: [("service", *entry) for entry in robot.graph_services()]
                               + [("action", *entry) for entry in robot.graph_actions()])
        monitor.sig_plot_requested.connect(self._plot)
        monitor.sig_make_block_requested.connect(
            lambda name, kind: self.teacher_gate(lambda: self.make_block(name, kind)))
        self._replace_dock_widget(self.monitor_dock, monitor)
        had_plot = self._made_plot() is not None
        self._plot_store = robot.state
        self._replace_dock_widget(self.plot_dock, QLabel(self.plot_dock))  # the plot is made when first shown
        if had_plot or self.plot_dock.isVisible():  # a restart may bring its tab back on top
            self.plot_panel()
        if robot.snapshot() is None:
            self.simulator_dock.show_robot(None, None, tr("real_robot_view", self.language))
        else:
            self.simulator_dock.show_robot(robot, view_class(language=self.language) if view_class else None)

    def _forget_old_program(self):
        """Another program or robot is on screen: the last run's replay, variables and marks are not its own."""
        self.replay.end()
        self.variables.clear()
        self.editor.call("clearMarks")

    def _made_plot(self):
        widget = self.plot_dock.widget()
        return widget if widget is not None and widget.objectName() == "plot_panel" else None

    def plot_panel(self):
        """The Plot dock's panel, made on first use (pyqtgraph takes a while to load)."""
        widget = self.plot_dock.widget()
        if widget is None or widget.objectName() != "plot_panel":
            from rockly_desktop.ui.docks.plot_panel import PlotPanel

            widget = PlotPanel(self._plot_store, self.language)
            widget.setObjectName("plot_panel")
            self._replace_dock_widget(self.plot_dock, widget)
        return widget

    def _plot(self, topic: str, path: str):
        self.plot_panel().add_curve(topic, path)
        self.plot_dock.raise_()

    def _choose_backend(self, index):
        kind = self.run_toolbar.backend.itemData(index)
        if self.robots.choose(kind):
            # On a real robot its state panels take the simulator view's place.
            self.simulator_dock.setVisible(self.robots.simulated)
            if not self.robots.simulated:
                self.state_dock.raise_()
        else:
            self.run_toolbar.backend.blockSignals(True)
            self.run_toolbar.backend.setCurrentIndex(self.run_toolbar.backend.findData(self.robots.kind))
            self.run_toolbar.backend.blockSignals(False)

    @staticmethod
    def _replace_dock_widget(dock, widget):
        if dock.widget() is not None:
            dock.widget().deleteLater()
        dock.setWidget(widget)

    # Commands that replace the program or the editor page must wait until the run ends.
    _IDLE_ONLY_ACTIONS = ("action_new", "action_open", "action_import_xml", "action_preferences")

    def _agent_address(self):
        """Where the chosen robot's agent is (``agent_bar.agent_address``), None when nowhere is known."""
        kind = link_kind(self.robots.kind)
        connection = self.settings.link_connection(kind, self.profile.id) if kind.settings else {}
        return agent_address(kind.kind, connection, self.settings.agent_address)

    def _agent_way(self):
        """How the robot bar asks the chosen robot's agent (an ``AgentWay``): as the Programs dialog reaches it, over
        the robot's ROS graph first when it is on one; None when there is no way."""
        address = self._agent_address()
        if not link_kind(self.robots.kind).agent_topics:
            return AgentWay(*address) if address else None
        return AgentWay(*(address or (None, DEFAULT_PORT)), via="auto", graph_kind=self.robots.kind)

    def _remember_agent(self, host: str, port: int):
        """The Programs dialog reached an agent at ``host``:``port``: the robot bar looks there from now on."""
        self.settings.agent_address = f"{host}:{port}"
        self.agent_bar.look()

    def _record_attached(self, snapshot: dict):
        """The recording of what the window sees of the run on the robot (``snapshot``: the run so far)."""
        from rockly_desktop.ui.agent.attached_recording import open_attached_recording

        self.replay.close()  # as when a run in the window starts
        return open_attached_recording(self.settings, self.document, self.editor.workspace, snapshot,
                                       lambda text: self.console.append(text, "error"))

    def _on_run_state(self, state: str):
        self.run_toolbar.set_state(state)
        if state == "idle":
            self.run_toolbar.set_watching(False)
        idle = state == "idle"
        for action in self.findChildren(QAction):
            if action.objectName() in self._IDLE_ONLY_ACTIONS:
                action.setEnabled(idle)
        self.recent_menu.setEnabled(idle)
        self.examples_menu.setEnabled(idle)
        self._follow_robot_lock()

    def _follow_robot_lock(self):
        """The Robot menu and the Run-on box can be used while idle, unless the teacher locked the robot."""
        locked = self.settings.teacher.robot_locked
        self.run_toolbar.set_robot_locked(locked)
        for action in self.profile_actions.actions():
            action.setEnabled(self.runs.state == "idle" and not locked)
            action.setToolTip(tr("robot_locked_tip", self.language) if locked else "")

    def _reset_robot(self):
        if self.runs.state == "idle":
            done = self.robots.reset()
            self.statusBar().showMessage(tr("robot_put_back" if done else "robot_not_put_back", self.language), 3000)

    def _on_breakpoints(self, block_ids):
        self.document.breakpoints = list(block_ids)
        self.runs.set_breakpoints(block_ids)
        self.attached.set_breakpoints(block_ids)
        self.document.mark_modified()

    def _run_in_charge(self):
        """The run the toolbar acts on: the robot's while attached to it, else the window's own."""
        return self.attached if self.attached.active else self.runs

    def _build_run_toolbar(self):
        toolbar = RunToolbar(self.language, self, big=self.settings.kiosk_mode)
        toolbar.run_action.triggered.connect(lambda: self.runs.run())
        toolbar.pause_action.triggered.connect(lambda: self._run_in_charge().pause())
        toolbar.step_action.triggered.connect(lambda: self._run_in_charge().step())
        toolbar.continue_action.triggered.connect(lambda: self._run_in_charge().resume())
        toolbar.stop_action.triggered.connect(lambda: self._run_in_charge().stop())
        toolbar.sig_delay_changed.connect(self.runs.set_delay)
        toolbar.set_state(self.runs.state)
        toolbar.backend.setCurrentIndex(toolbar.backend.findData(self.robots.kind))
        toolbar.backend.currentIndexChanged.connect(self._choose_backend)
        toolbar.reset_action.triggered.connect(self._reset_robot)
        old = getattr(self, "run_toolbar", None)
        if old is not None:
            toolbar.speed.setValue(old.speed.value())
            self.insertToolBar(old, toolbar)
            self.removeToolBar(old)
            old.deleteLater()
        else:
            self.addToolBar(Qt.ToolBarArea.TopToolBarArea, toolbar)
        self.run_toolbar = toolbar
        self.runs.set_delay(toolbar.delay)

    def show_program(self, program, callback):
        """Show a checked program (switching to its robot); ``callback(result, error)`` gets the page's answer."""
        call = program.editor_call()
        if self.settings.teacher.robot_locked and program.profile.id != self.profile.id and not self._starting:
            callback(None, tr("robot_locked_program", self.language, name=self.profile.display_name(self.language)))
            return
        if self._starting:
            self.document.profile = program.profile
            self._restart_editor(call, callback)
        else:
            self.activate_profile(program.profile)
            self.editor.call(*call, callback)

    # --- profile and language -----------------------------------------------------------

    def activate_profile(self, profile):
        """Make ``profile`` the active robot (reloading the editor if it changes)."""
        if profile.id != self.profile.id:
            self.document.profile = profile
            self._restart_editor()

    def _on_profile_changed(self, profile):
        self.settings.profile_id = profile.id
        self._check_active_profile_action()

    def choose_profile(self, profile_id: str):
        """The user picked a robot in the Robot menu: a new program for that robot (once the old one is saved)."""
        self._check_active_profile_action()  # the old robot stays checked until the program is put away
        if profile_id == self.profile.id or self.settings.teacher.robot_locked:
            return
        profile = self.registry.get(profile_id)
        self.teacher_gate(lambda: self.files.maybe_save(then=lambda ok: ok and self._new_program_for(profile)))

    def _new_program_for(self, profile):
        self.activate_profile(profile)
        self.files.new(ask=False)

    def _check_active_profile_action(self):
        for action in self.profile_actions.actions():
            action.setChecked(action.data() == self.profile.id)

    @property
    def language(self) -> str:
        """The language the window speaks now (its one owner is ``settings.current_language``)."""
        return self.settings.current_language.code

    def set_language(self, language: str):
        """Switch the window and the blocks to ``language``, keeping the program (once the page has given it)."""
        if language == self.language:
            return
        if not self.editor.is_ready:
            self._switch_language(language, None)
            return

        def answered(state, error):
            if error:
                self.statusBar().showMessage(tr("editor_error", self.language, message=error), 15000)
            elif language != self.language:
                self._switch_language(language, state["workspace"])

        self.editor.call("getState", None, answered, timeout_ms=ANSWER_TIMEOUT_MS)

    def _switch_language(self, language: str, workspace):
        self.settings.current_language.code = language
        self.simulator_dock.robot = None  # the simulator view is made anew in the new language
        self._restart_editor()
        if workspace:
            self.editor.load_workspace(workspace, breakpoints=self.document.breakpoints)
        self.docks.retitle(language)
        self.replay.retitle()
        self._build_run_toolbar()
        for old_menu in (action.menu() for action in self.menuBar().actions() if action.menu() is not None):
            old_menu.deleteLater()  # with its actions: the shortcut list names only the new ones
        self.menuBar().clear()
        self._build_menus()
        self.keys.set_language(language)
        from rockly_desktop.ui.help_dialogs import retitle_help_pages  # (help pages: imported when first opened)

        retitle_help_pages(self, language)
        self._update_title()

    def show_preferences(self):
        """Open the Preferences dialog (once ``teacher_gate`` lets it) and apply the chosen language, the
        Put-back preference and the teacher's settings."""
        self.teacher_gate(self._show_preferences)

    def _show_preferences(self):
        from rockly_desktop.ui.preferences.preferences import PreferencesDialog  # not needed to start

        dialog = PreferencesDialog(self.language, self, self.profile, self.settings.teacher,
                                   reset_before_run=self.settings.reset_before_run, kiosk=self.settings.kiosk,
                                   kiosk_mode=self.settings.kiosk_mode, block_look=self.settings.block_look,
                                   pin_given=self.gate_asks_pin, robot_limits=self._robot_limits_way(), challenges=[
                                       (lesson.id, lesson.title(self.language))
                                       for lesson in self.lessons.library.for_robot(self.profile.id)])
        if dialog.exec():
            self.settings.reset_before_run = dialog.reset_before_run
            self.settings.block_look = dialog.block_look
            self.editor.set_look(dialog.block_look)
            if dialog.kiosk_tab is not None:
                dialog.kiosk_tab.apply()
            if dialog.teacher_tab is not None and dialog.teacher_tab.apply():  # the program stays; only the toolbox
                self.lessons.apply_toolbox()
            self._follow_robot_lock()
            self.set_language(dialog.language)

    def _robot_limits_way(self):
        """How the Teacher tab asks the chosen robot's agent for the robot's own limits (None: no agent known)."""
        way = self._agent_way()
        if way is None:
            return None
        from rockly_desktop.ui.agent.robot_limits_calls import RobotLimitsOnRobot  # not needed to start

        return lambda owner: RobotLimitsOnRobot(owner, way, self.language)

    def show_robot_programs(self):
        """Robot → Programs on the robot…: the agent's programs, sending, starting and attaching."""
        # imported when first asked for: it brings the runtime's export (60 ms), which start-up does not need
        from rockly_desktop.ui.agent.robot_programs_dialog import RobotProgramsDialog

        address = self._agent_address() or ("localhost", DEFAULT_PORT)
        on_ros = bool(link_kind(self.robots.kind).agent_topics)  # the agent is asked on the chosen robot's graph
        RobotProgramsDialog(self.attached, self.language, self, *address,
                            open_copy=lambda path, name: self.files.open_copy(path, name), document=self.document,
                            limits=lambda: self.settings.teacher.limits(self.profile.id),
                            reached=self._remember_agent,
                            via="auto" if on_ros else "tcp", graph_kind=self.robots.kind if on_ros else None,
                            pair_as_student=self.settings.kiosk_mode).show()  # a kiosk laptop is a student

    def make_block(self, chosen: str = "", kind: str = ""):
        """Open the block maker (Tools → Make a block…), with the topic, service or action ``chosen`` (of
        ``kind``, "" for any) chosen."""
        from rockly_desktop.ui.blockmaker.editing import keeping_only
        from rockly_desktop.ui.blockmaker.maker_dialog import open_block_maker  # not needed before it is opened
        from rockly_desktop.ui.blockmaker.offers import LiveGraph

        wishing = []  # the links told the maker wants their parameters (the robot may change while it is open)

        def graph() -> LiveGraph:
            try:
                if not self._robot_shown:
                    return LiveGraph()
                link = self.robot()
            except RocklyError:  # no robot to ask: the maker offers what the profile declares and knows
                return LiveGraph()
            if link not in wishing:
                wishing.append(link)
                link.want_parameters(True)
            return LiveGraph.of(link)

        def asker():  # the robot's now, asked of the live offers whose types Rockly has no definition for
            try:
                return self.robot().interface_definition if self._robot_shown else None
            except RocklyError:
                return None

        def unwish():
            for link in wishing:
                link.want_parameters(False)
        from rockly_desktop.ui.blockmaker.trial import BlockTrial

        maker = self.block_maker = open_block_maker(self.profile, self.language, graph, self, chosen, kind, asker)
        maker.finished.connect(unwish)
        maker.sig_saved.connect(lambda block_id: self.reload_packs(keeping_only(maker.block()), tr(
            "maker_saved", self.language, block=block_id, category=maker.category.currentText().strip())))
        BlockTrial(maker, self.runs, lambda: self.simulator_dock if self.simulator_dock.isVisible() else None)
        return self.block_maker

    def edit_made_block(self, block_id: str = ""):
        """Open a block made with the maker in it again to change it (its "Edit this block…", or Tools → Edit a
        made block…, which asks which); what the open program puts into the block's inputs is checked."""
        from rockly_desktop.ui.blockmaker.editing import choose_made_block, inputs_in_use, saved_block

        block_id = block_id or choose_made_block(self.profile, self.language, self)
        found = saved_block(self.profile, block_id) if block_id else None
        if found is not None:
            self.make_block().edit(found[1], found[0], inputs_in_use(self.editor.workspace, block_id))

    def reload_packs(self, adapt=None, said: str = ""):
        """Read the block packs again and show the toolbox with them, keeping the program on screen as
        ``adapt(workspace)`` gives it, if given, and then saying ``said`` in the status bar (once a run, such
        as the maker's "Try it", has ended: the page is not replaced under it)."""
        if self.runs.state != "idle":
            self.runs.sig_finished.connect(lambda _result: self.reload_packs(adapt, said),
                                           Qt.ConnectionType.SingleShotConnection)
            return
        self.registry.reload_packs()

        def answered(state, error):
            self.document.profile = self.registry.get(self.profile.id)
            if said:  # once the page is ready (which clears the status bar)
                self.editor.sig_ready.connect(lambda: self.statusBar().showMessage(said, 30000),
                                              Qt.ConnectionType.SingleShotConnection)
            self._restart_editor()
            if not error:
                workspace = adapt(state["workspace"]) if adapt is not None else state["workspace"]
                self.editor.load_workspace(workspace, breakpoints=self.document.breakpoints)
                if workspace != state["workspace"]:  # what a changed block no longer takes was dropped: not silently
                    self.document.mark_modified()

        self.editor.call("getState", None, answered, timeout_ms=ANSWER_TIMEOUT_MS)

    def _toolbox_choice(self):
        """(level id, capability ids switched off) the teacher chose for the profile's toolbox."""
        teacher = self.settings.teacher
        return teacher.level(self.profile.id), teacher.switched_off(self.profile.id)

    # --- editor events ------------------------------------------------------------------

    def _on_editor_changed(self, workspace, python, origin):
        self.code_dock.view.set_code(python)
        if origin == "user":
            self.document.mark_modified()

    def _update_title(self):
        self.setWindowTitle(f"{self.document.display_name(self.language)}[*] — {tr('app_name', self.language)}")
        self.setWindowModified(self.document.modified)

    # --- menus --------------------------------------------------------------------------

    def _action(self, menu, key, slot, shortcut=None):
        action = QAction(tr(key, self.language), menu)  # the menu's: made anew with it in another language
        action.setObjectName(f"action_{key}")
        if shortcut is not None:
            action.setShortcut(shortcut)
        action.triggered.connect(slot)
        menu.addAction(action)
        return action

    def _teacher_action(self, menu, key, command, shortcut=None):
        """An action whose ``command`` reaches beyond the window's own program (other files, the robot's
        programs, the profile's blocks): it runs through ``teacher_gate``, so a kiosk asks for the PIN first."""
        return self._action(menu, key, lambda: self.teacher_gate(command), shortcut)

    def _build_menus(self):
        language, bar = self.language, self.menuBar()
        file_menu = bar.addMenu(tr("menu_file", language))
        self._action(file_menu, "new", lambda: self.files.new(), QKeySequence.StandardKey.New)
        self._teacher_action(file_menu, "open", lambda: self.files.open(), QKeySequence.StandardKey.Open)
        self.recent_menu = file_menu.addMenu(tr("open_recent", language))
        self._teacher_action(file_menu, "open_recording", lambda: self.replay.choose(self.settings.recordings_folder))
        self.recent_menu.aboutToShow.connect(self._fill_recent_menu)
        self.examples_menu = ExamplesMenu(self.files, lambda: self.profile, language, file_menu)
        file_menu.addMenu(self.examples_menu)
        file_menu.addSeparator()
        self._action(file_menu, "save", lambda: self.files.save(), QKeySequence.StandardKey.Save)
        self._action(file_menu, "save_as", lambda: self.files.save_as(), QKeySequence.StandardKey.SaveAs)
        file_menu.addSeparator()
        self._teacher_action(file_menu, "import_xml", lambda: self.files.import_xml())
        self._teacher_action(file_menu, "export_python", lambda: self.files.export_python(), "Ctrl+E")
        file_menu.addSeparator()
        self._action(file_menu, "quit", self.close, QKeySequence.StandardKey.Quit)

        edit_menu = bar.addMenu(tr("menu_edit", language))
        self._action(edit_menu, "undo", self.editor.undo, QKeySequence.StandardKey.Undo)
        self._action(edit_menu, "redo", self.editor.redo, QKeySequence.StandardKey.Redo)

        robot_menu = bar.addMenu(tr("menu_robot", language))
        self.profile_actions = QActionGroup(self)
        for profile in self.registry.profiles.values():
            action = QAction(mnemonic_free(f"{profile.display_name(language)} ({profile.version})"), self,
                             checkable=True)
            action.setData(profile.id)
            action.setChecked(profile.id == self.profile.id)
            action.triggered.connect(lambda _checked=False, pid=profile.id: self.choose_profile(pid))
            self.profile_actions.addAction(action)
            robot_menu.addAction(action)
        robot_menu.setToolTipsVisible(True)  # a locked robot says why
        self._follow_robot_lock()
        robot_menu.addSeparator()
        robot_menu.addAction(self.run_toolbar.reset_action)
        self._teacher_action(robot_menu, "robot_programs", self.show_robot_programs)

        view_menu = bar.addMenu(tr("menu_view", language))
        for dock in self.docks.values():
            view_menu.addAction(dock.toggleViewAction())
        view_menu.addSeparator()
        view_menu.addAction(self.stage.action_for(language))

        tools_menu = bar.addMenu(tr("menu_tools", language))
        self._teacher_action(tools_menu, "make_block", self.make_block)
        self._teacher_action(tools_menu, "edit_made_block", self.edit_made_block)

        settings_menu = bar.addMenu(tr("menu_settings", language))
        self._action(settings_menu, "preferences", self.show_preferences, QKeySequence.StandardKey.Preferences)

        help_menu = bar.addMenu(tr("menu_help", language))
        self._action(help_menu, "first_steps", lambda: self._help("show_first_steps", language),
                     QKeySequence.StandardKey.HelpContents)
        self._action(help_menu, "keyboard_shortcuts", lambda: self._help("show_shortcuts", language))
        self._action(help_menu, "about", lambda: QMessageBox.about(
            self, tr("app_name", language), tr("about_text", language, version=__version__)))

    def _help(self, name: str, language: str):
        """Show a help page (``help_dialogs.show_first_steps`` or ``show_shortcuts``) in ``language``; the
        module is imported when first asked for, as start-up does not need it."""
        from rockly_desktop.ui import help_dialogs

        getattr(help_dialogs, name)(self, language)

    def createPopupMenu(self):
        """Qt override: the menu a right-click on a toolbar or dock offers (to hide them); none in kiosk mode."""
        return None if self.settings.kiosk_mode else super().createPopupMenu()

    def _fill_recent_menu(self):
        self.recent_menu.clear()
        for path in self.settings.recent_files:
            self.recent_menu.addAction(mnemonic_free(path),
                                       lambda p=path: self.teacher_gate(lambda: self.files.open(p)))
        self.recent_menu.addSeparator()
        self.recent_menu.addAction(tr("clear_recent", self.language),
                                   lambda: self.teacher_gate(self.settings.clear_recent_files))

    def event(self, event):
        """Qt override: back at the front, the window takes in a change another window or program made
        to its file (once the activation is over: a question must not open inside it)."""
        if event.type() == QEvent.Type.WindowActivate:
            QTimer.singleShot(0, self, self._follow_disk)
        return super().event(event)

    def active_dialog(self):
        """The dialog that waits for an answer (modal), or None: one of the window's, which ``stop_anywhere`` keeps
        modal, or another."""
        dialogs = self.stop_anywhere.open_dialogs
        return dialogs[-1] if dialogs else QApplication.activeModalWidget()

    def _follow_disk(self):
        if self.runs.state == "idle" and not self._close_waiting and self.active_dialog() is None:
            self.files.follow_disk()

    # --- closing ------------------------------------------------------------------------

    def closeEvent(self, event):
        """Qt override: ask to save changes, then stop everything and remember the layout.

        When the program must first be saved (or a save is still waiting for the page),
        the event is ignored and the window closes itself once the file is written.
        """
        if not self._close_approved and not self._close_waiting:
            self._close_waiting = True
            self._in_close_event = True
            self.files.maybe_save(then=self._close_decided)
            self._in_close_event = False
        if not self._close_approved:
            event.ignore()
            return
        self._close_approved = False
        self.keys.stop()
        self.agent_bar.stop()
        self.attached.detach()
        self.runs.shutdown()
        self.lessons.shutdown()
        self.replay.wait_for_reading()
        self.simulator_dock.stop()
        self.health.stop()
        self.robots.shutdown()
        self.autosave.finish()
        self.settings.save_window(self.saveGeometry(), self.stage.state_to_keep())
        self.settings.last_file = self.document.path
        self.settings.sync()
        event.accept()

    def _close_decided(self, may_close: bool):
        self._close_waiting = False
        self._close_approved = may_close
        if may_close and not self._in_close_event:  # the save waited for the page: close now it is written
            self.close()
