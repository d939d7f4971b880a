"""Which robot programs run on: the profile's built-in simulator, or a robot over ROS 1.

Owns the robots it made (one simulator per profile, one ROS robot per profile), the ROS
connection dialog and the connection indicator in the status bar.
"""
from PySide6.QtCore import QObject, QTimer, Signal
from PySide6.QtWidgets import QLabel, QMessageBox

from rockly_desktop.core.errors import RocklyError
from rockly_desktop.ui.connection_dialog import ConnectionDialog
from rockly_desktop.ui.message_boxes import plain_message_box
from rockly_desktop.ui.texts import robot_problem, tr

SIMULATOR, ROS1 = "simulator", "ros1"
STATUS_COLOURS = {"connected": "#2e7d32", "connecting": "#f9a825", "lost": "#c62828"}


class RobotChoice(QObject):
    """The active robot for the document's profile; ``kind`` is 'simulator' or 'ros1'.

    Simulators answer tablet questions on ``tablet``; ROS connections are remembered in
    ``settings``; ``parent`` is the widget the connection dialog belongs to.
    """

    sig_robot_changed = Signal()  # another kind of robot was chosen
    simulator_speed = 1.0  # how much faster than real time the built-in simulator runs

    def __init__(self, document, tablet, settings, parent):
        super().__init__(parent)
        self.document = document
        self.tablet = tablet
        self.settings = settings
        self.kind = SIMULATOR
        self._robots = {}
        self.status = QLabel(parent)
        self.status.hide()
        self._timer = QTimer(self)
        self._timer.setInterval(500)
        self._timer.timeout.connect(self._show_status)

    def robot(self):
        """The robot of the active kind for the document's profile (made on first use)."""
        profile = self.document.profile
        key = (self.kind, profile.id)
        if key not in self._robots:
            from rockly_desktop.executor.robot_link import RosRobot, SimulatedRobot  # made after the editor is up

            for other in [k for k in self._robots if k[0] == SIMULATOR and k != key]:
                self._robots.pop(other).shutdown()  # one simulator ticking at a time
            if self.kind == SIMULATOR:
                self.tablet.robot_name = profile.display_name(self.settings.language)
                self._robots[key] = SimulatedRobot(profile, tablet=self.tablet, speed=self.simulator_speed)
            else:
                master_uri, _host = self.settings.ros_connection(profile.id)
                self._robots[key] = RosRobot(profile, master_uri)
        return self._robots[key]

    def choose(self, kind: str) -> bool:
        """Switch to ``kind``; for ROS asks where the robot is and connects. False if that failed."""
        if kind == self.kind:
            return True
        if kind == ROS1 and not self._connect():
            return False
        self.kind = kind
        self.status.setVisible(kind == ROS1)
        if kind == ROS1:
            self._timer.start()
            self._show_status()
        else:
            self._timer.stop()
        self.sig_robot_changed.emit()
        return True

    @property
    def can_reset(self) -> bool:
        """True when the active robot is the built-in simulator, which can be put back."""
        return self.kind == SIMULATOR

    def reset(self) -> bool:
        """Put the simulated robot back where it started; False (nothing done) for a real robot or a
        simulator whose profile does not implement ``reset()``."""
        if not self.can_reset:
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

    def _connect(self) -> bool:
        language, profile = self.settings.language, self.document.profile
        remembered_uri, remembered_host = self.settings.ros_connection(profile.id)
        dialog = ConnectionDialog(language, profile.display_name(language), remembered_uri, remembered_host,
                                  self.parent())
        if not dialog.exec():
            return False
        from rockly_desktop.robot.ros1.connection import RosConnection  # xmlrpc and http: only when connecting

        try:
            connection = RosConnection.get(dialog.master_uri, dialog.host or None, timeout=1.0)
        except RocklyError as error:
            problem, next_step = robot_problem(error, language)
            box = plain_message_box(self.parent(), QMessageBox.Icon.Warning, tr("connect_failed", language), problem)
            box.setInformativeText(next_step)
            box.setObjectName("connect_failed_box")
            box.exec()
            return False
        self.settings.remember_ros_connection(profile.id, dialog.master_uri, dialog.host)
        if connection.address_problem:
            kind, address = connection.address_problem
            box = plain_message_box(self.parent(), QMessageBox.Icon.Warning, tr("ros_address_title", language),
                                    tr(f"ros_address_{kind}", language, address=address))
            box.setObjectName("ros_address_box")
            box.open()
        return True

    def _show_status(self):
        robot = self._robots.get((ROS1, self.document.profile.id))
        status = robot.connection.status if robot is not None else "connecting"
        self.status.setText(tr(f"ros_{status}", self.settings.language))
        self.status.setStyleSheet(f"color: {STATUS_COLOURS[status]}; font-weight: bold;")
        if robot is not None and robot.connection.round_trip is not None:
            self.status.setToolTip(f"{robot.connection.master_uri} — {robot.connection.round_trip * 1000:.1f} ms")

    def shutdown(self):
        """Stop every robot safely (the window is closing)."""
        self._timer.stop()
        for robot in self._robots.values():
            robot.shutdown()
        self._robots.clear()
