"""Which robot programs run on: any kind of robot link in the registry (``robot/links.py``):
the profile's built-in simulator, or a robot over ROS.

Owns the robots it made (one simulator per profile, one link per kind and profile), the
connection dialog and the connection indicator in the status bar, which says what the health
light saw (``show_health``), so the two always agree.
"""
from PySide6.QtCore import QObject, Signal
from PySide6.QtWidgets import QMessageBox

from rockly_desktop.core.errors import RocklyError
from rockly_desktop.core.numbers import number_format
from rockly_desktop.robot.health import AMBER, link_state, overall
from rockly_desktop.robot.links import DEFAULT_KIND, check_available, link_kind, open_link
from rockly_desktop.ui.message_boxes import plain_message_box
from rockly_desktop.ui.plain_text import plain_label, tooltip_text
from rockly_desktop.ui.robot.connection_dialog import ConnectionDialog
from rockly_desktop.ui.robot.health_bar import COLOURS
from rockly_desktop.ui.texts import robot_problem, said_in, tr

CONNECT_TIMEOUT = 1.0  # seconds a robot chosen in the window has to answer


class RobotChoice(QObject):
    """The active robot for the document's profile; ``kind`` is a kind of robot link ('sim', 'ros1', 'ros2').

    Simulators answer tablet questions on ``tablet``; connections are remembered in
    ``settings``; ``parent`` is the widget the connection dialog belongs to. Another robot
    (profile) on a real kind of link is reached the way the person chose in the dialog: the
    connection in use carries over, and is remembered for that robot too.
    """

    sig_robot_changed = Signal()  # another kind of robot was chosen
    simulator_speed = 1.0  # how much faster than real time the built-in simulator runs

    def __init__(self, document, tablet, settings, parent):
        super().__init__(parent)
        self.document = document
        self.tablet = tablet
        self.settings = settings
        self.kind = DEFAULT_KIND
        self._robots = {}
        self._chosen = {}  # kind -> the connection the person last gave in its dialog
        self.status = plain_label(parent=parent)
        self.status.hide()

    def robot(self):
        """The robot of the active kind for the document's profile (made on first use)."""
        profile = self.document.profile
        if (self.kind, profile.id) not in self._robots:
            self._open(self.kind)
        return self._robots[(self.kind, profile.id)]

    def _open(self, kind: str, connection: dict = None, timeout: float = 5.0):
        profile, entry = self.document.profile, link_kind(kind)
        key = (kind, profile.id)
        if entry.simulated:
            self.tablet.robot_name = profile.display_name(self.settings.language)
        if connection is None and kind in self._chosen:  # a robot switch: where the person said
            connection = self._chosen[kind]
            self.settings.remember_link_connection(entry, profile.id, connection)
        elif connection is None:
            connection = self.settings.link_connection(entry, profile.id)
        robot = open_link(kind, profile, connection, tablet=self.tablet, speed=self.simulator_speed, timeout=timeout)
        for other in [k for k in self._robots if link_kind(k[0]).simulated and k != key]:
            self._robots.pop(other).shutdown()  # at most one simulator ticking, and none beside a real robot
        self._robots[key] = robot
        return robot

    def choose(self, kind: str) -> bool:
        """Switch to ``kind``; for a real robot asks where it is and connects. False if that failed."""
        if kind == self.kind:
            return True
        entry = link_kind(kind)
        if not entry.simulated and not self._connect(entry):
            return False
        self.kind = kind
        self.status.setVisible(not entry.simulated)
        if not entry.simulated:  # until the health light first looks
            self._say_state("connecting", AMBER, self._active().status())
        self.sig_robot_changed.emit()
        return True

    def world_id(self):
        """The solid world of the active robot (a simulator's ``world_id``); None for a real robot, a
        simulator without one, or a robot not made yet."""
        robot = self._robots.get((self.kind, self.document.profile.id))
        return getattr(robot, "world_id", None)

    @property
    def simulated(self) -> bool:
        """True when the active robot is the profile's simulator in this process (shown in the
        Simulator dock, and it can be put back)."""
        return link_kind(self.kind).simulated

    def reset(self) -> bool:
        """Put the simulated robot back where it started; False (nothing done) for a real robot or a
        simulator whose profile does not implement ``reset()``."""
        if not self.simulated:
            return False
        try:
            self.robot().reset()
        except NotImplementedError:
            return False
        return True

    def reset_if_wanted(self):
        """Put the simulated robot back when the preference says so (before a Run, on New and Open)."""
        if self.settings.reset_before_run:
            self.reset()

    def _connect(self, entry) -> bool:
        """Ask how to reach the robot over ``entry``'s kind of link, and reach it; False if that failed."""
        language, profile = self.settings.language, self.document.profile
        try:
            check_available(entry.kind)
        except RocklyError as error:
            self._refused(error)
            return False
        dialog = ConnectionDialog(language, profile.display_name(language), entry,
                                  self.settings.link_connection(entry, profile.id), self.parent())
        if not dialog.exec():
            return False
        stale = self._robots.pop((entry.kind, profile.id), None)
        if stale is not None:
            stale.shutdown()
        try:
            robot = self._open(entry.kind, dialog.values, CONNECT_TIMEOUT)
        except RocklyError as error:
            self._refused(error)
            return False
        self.settings.remember_link_connection(entry, profile.id, dialog.values)
        self._chosen[entry.kind] = dialog.values
        for warning in robot.warnings():
            box = plain_message_box(self.parent(), QMessageBox.Icon.Warning, tr(f"ros_{warning.title}", language),
                                    robot_problem(warning, language)[0])
            box.setObjectName("link_warning_box")
            box.open()
        return True

    def _refused(self, error):
        problem, next_step = robot_problem(error, self.settings.language)
        box = plain_message_box(self.parent(), QMessageBox.Icon.Warning,
                                tr("connect_failed", self.settings.language), problem)
        box.setInformativeText(next_step)
        box.setObjectName("connect_failed_box")
        box.exec()

    def _active(self):
        """The active robot, None when it is not made yet."""
        return self._robots.get((self.kind, self.document.profile.id))

    def show_health(self, robot, items: list):
        """Say in the status bar how the link to the active real robot is, from the health light's look
        at ``robot`` (its HealthItems ``items``): the same state, in the light's colour."""
        if robot is None or robot is not self._active() or self.simulated:
            return
        self._say_state(link_state(items), overall(items) if items else AMBER, robot.status())

    def _say_state(self, state: str, level: str, status):
        language = self.settings.language
        where = said_in(status.where, language) if status is not None else ""
        text = tr(f"ros_{state}", language)
        self.status.setText(f"{text} — {where}" if where else text)  # e.g. its domain on ROS 2
        self.status.setStyleSheet(f"color: {COLOURS[level]}; font-weight: bold;")
        if status is not None and status.round_trip is not None:
            took = number_format(language).format("{:.1f} ms", status.round_trip * 1000)
            self.status.setToolTip(tooltip_text(f"{where} — {took}"))

    def shutdown(self):
        """Stop every robot safely (the window is closing)."""
        for robot in self._robots.values():
            robot.shutdown()
        self._robots.clear()
