"""The small window of ``rockly sim PROFILE --ros``: the simulated robot, live, and its tablet.

The simulator runs as a ROS node in this process (its service and action threads are
rospy's); this window only reads ``simulator.snapshot()`` on a timer in the GUI thread and
shows tablet questions through ``QtTablet``, which marshals them to the GUI thread and
lets the ROS thread wait for the person's answer.
"""
from PySide6.QtCore import Qt, QTimer, Signal
from PySide6.QtWidgets import QMainWindow

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import RocklyError
from rockly_desktop.ui.docks.simulator_dock import REFRESH_MS
from rockly_desktop.ui.docks.tablet import QtTablet
from rockly_desktop.ui.plain_text import plain_label
from rockly_desktop.ui.texts import tr

# Goes back to the program that asked (in another process), like the robot's other errors: English.
UNANSWERED = app_local_text("sim_unanswered")


class SimulatorWindow(QMainWindow):
    """Shows ``profile``'s simulator view, fed once ``show_simulator`` is called; ``tablet`` is its port.

    ``tablet.ask`` and ``tablet.notify`` may be called from any thread. Closing the
    window emits ``sig_closed`` (whoever runs the node ends it then).
    """

    sig_closed = Signal()

    def __init__(self, profile, language: str = "en", parent=None):
        super().__init__(parent)
        self.setObjectName("sim_window")
        self.language = language
        self.profile = profile
        name = profile.display_name(language)
        self.setWindowTitle(tr("sim_window_title", language, robot=name, master="…"))
        self.tablet = QtTablet(self, name, lambda: self.language, unanswered=UNANSWERED)
        self.tablet.sig_notice.connect(self._show_notice)
        self.simulator = None
        self.view = self._make_view()
        self.setCentralWidget(self.view)
        self.where_label = plain_label(parent=self)
        self.statusBar().addPermanentWidget(self.where_label)
        self._timer = QTimer(self)
        self._timer.setInterval(REFRESH_MS)
        self._timer.timeout.connect(self.refresh)
        self.resize(self.view.sizeHint().expandedTo(self.view.minimumSizeHint()))

    def _make_view(self):
        note = None
        try:
            view_class = self.profile.simulator_view_class()
            if view_class is not None:
                return view_class(language=self.language)
        except RocklyError as error:
            note = str(error)
        label = plain_label(note or tr("sim_no_view", self.language), self)
        label.setWordWrap(True)
        label.setAlignment(Qt.AlignmentFlag.AlignCenter)
        label.setMinimumSize(360, 120)
        return label

    def show_simulator(self, simulator, where: str):
        """Draw ``simulator.snapshot()`` in the view, 30 times a second; name ``where`` it is served
        (a ROS master's URI, or 'ROS 2, domain 7, localhost')."""
        self.simulator = simulator
        self.setWindowTitle(tr("sim_window_title", self.language, robot=self.profile.display_name(self.language),
                               master=where))
        self.where_label.setText(tr("sim_window_where", self.language, where=where))
        self.statusBar().showMessage(tr("sim_window_status", self.language))
        if hasattr(self.view, "set_snapshot"):
            self.refresh()
            self._timer.start()

    def refresh(self):
        """Give the view the simulator's current state."""
        if self.simulator is not None and hasattr(self.view, "set_snapshot"):
            self.view.set_snapshot(self.simulator.snapshot())

    def _show_notice(self, _robot: str, text: str):
        self.statusBar().showMessage(tr("robot_says", self.language, text=text))

    def closeEvent(self, event):
        """Closing the window ends the simulated robot (``sig_closed``)."""
        self._timer.stop()
        super().closeEvent(event)
        self.sig_closed.emit()
