"""Replaying a recorded run in the window: the block that ran glows, the Variables dock and the
Simulator view show that moment (for a real robot's run, without simulator snapshots: a plan view
of its recorded ``/odom``), the Robot state panels the recorded topics then, the Console what had
been printed by then and the Plot the recorded series with a cursor at it. Replay only ever
changes what is on screen: it sends nothing to a robot, and a file that is no recording changes
nothing at all.
"""
from PySide6.QtCore import QObject
from PySide6.QtWidgets import QMessageBox

from rockly_desktop.recording import channels
from rockly_desktop.ui.block_badges import badge_texts
from rockly_desktop.ui.file_dialogs import FileDialogs
from rockly_desktop.ui.message_boxes import plain_message_box
from rockly_desktop.ui.plan_view import PlanView
from rockly_desktop.ui.texts import tr


class Replay(QObject):
    """Drives the ``bar`` (``ReplayBar``) and shows its moments in the ``editor``, the ``variables`` dock,
    the ``simulator`` dock (whose live refresh pauses while a moment is shown), the ``console`` and the
    plot panel."""

    def __init__(self, bar, editor, variables, simulator, language: str, parent=None, badges=lambda: True,
                 console=None, plot=lambda: None, state_panels=lambda: None):
        """``badges()`` says whether the blocks' badges and values are shown (not at the Starter level); ``plot()`` is
        the Plot panel and ``state_panels()`` the Robot state panels, each None while there is none."""
        super().__init__(parent)
        self.console = console
        self._plot = plot
        self._state_panels = state_panels
        self._live_panels = None  # (the panels, their live store) while they show a moment
        self.path = None  # a real robot's recorded path (no simulator snapshots)
        self.plan = None
        self.topics = None
        self._shown_printed = None
        self._badges_wanted = badges
        self._shown_badges = None
        self._shown_values = None
        self.bar = bar
        self.editor = editor
        self.variables = variables
        self.simulator = simulator
        self.language = language
        self.moments = None
        self._shown_block = None
        self.file_dialogs = FileDialogs()  # kiosk mode puts dialogs kept in one folder in its place
        bar.sig_moment.connect(self.show_moment)
        bar.sig_closed.connect(self._back_to_live)

    def choose(self, folder: str = ""):
        """Ask for a recording (File → Open recording…) and open it."""
        path = self.file_dialogs.open_file(self.parent(), tr("open_recording", self.language).replace(
            "&", "").rstrip("…"), folder, tr("recording_filter", self.language))
        if path:
            self.open(path)

    def open(self, path, quiet: bool = False) -> bool:
        """Show the timeline of the recording at ``path``. A file that cannot be read is said in a message
        box (``quiet``: only logged, e.g. after a run) and nothing changes; returns whether it opened."""
        # Imported when first used: reading and decoding recordings (mcap, numpy) costs 0.1 s at start.
        from rockly_desktop.recording.moments import Moments
        from rockly_desktop.recording.odometry import RecordedPath
        from rockly_desktop.recording.reading import RecordingUnreadable, read_recording
        from rockly_desktop.recording.topics import RecordedTopics

        try:
            recording = read_recording(path)
        except RecordingUnreadable as error:
            if not quiet:
                box = plain_message_box(self.parent(), QMessageBox.Icon.Warning,
                                        tr("recording_unreadable", self.language), str(error))
                box.setObjectName("recording_unreadable_box")
                box.open()
            return False
        self.moments = Moments(recording)
        self.topics = RecordedTopics(recording)
        self.simulator.show_live_view()
        self.plan = None
        path = None if recording.on(channels.SIMULATOR) else RecordedPath(self.topics)
        self.path = path or None
        self.bar.show_timeline(self.moments.duration, self.moments.markers(),
                               "" if recording.complete else tr("replay_cut_short", self.language))
        return True

    def close(self):
        """Hide the timeline (a run is starting, or another program opens)."""
        if self.bar.isVisible():
            self.bar.close_timeline()

    def show_moment(self, seconds: float):
        """Show the run as it was ``seconds`` after it began."""
        if self.moments is None:
            return
        moment = self.moments.at(seconds)
        if moment.block != self._shown_block:
            self._shown_block = moment.block
            self.editor.call("highlight", {"id": moment.block})
        self.variables.show_values(moment.variables)
        if self.console is not None and moment.printed != self._shown_printed:
            self._shown_printed = moment.printed
            self.console.show_recorded(self.moments.printed_lines(), moment.printed)
        plot = self._plot()
        if plot is not None:
            plot.show_recorded(self.topics, seconds, self.moments.duration)
        if self._badges_wanted():
            badges = self.moments.badges(seconds)
            if badges != self._shown_badges:
                self._shown_badges = badges
                self.editor.call("setBadges", {"badges": badge_texts(badges, self.language)})
            values = self.moments.values(seconds)
            if values != self._shown_values:
                self._shown_values = values
                self.editor.call("setValues", {"values": values, "label": tr("block_value", self.language)})
        self._show_state(seconds)
        view = self.simulator.view
        if moment.snapshot is not None and view is not None:
            self.simulator.stop()
            view.set_snapshot(moment.snapshot)
        elif self.path is not None:
            if self.plan is None:
                self.plan = PlanView(self.path.bounds(), self.language)
                self.simulator.show_recorded_view(self.plan)
            self.plan.show_poses(self.path.until(seconds))

    def _show_state(self, seconds: float):
        panels = self._state_panels()
        if panels is None:
            return
        if self._live_panels is None or self._live_panels[0] is not panels:
            self._live_panels = (panels, panels.store)
        panels.set_store(self.topics.at(seconds))

    def _back_to_live(self):
        self._shown_block = self._shown_badges = self._shown_printed = self._shown_values = None
        self.editor.call("highlight", {"id": None})
        if self.console is not None:
            self.console.show_live()
        if self._live_panels is not None:
            panels, store = self._live_panels
            self._live_panels = None
            if panels is self._state_panels():  # not when the robot changed meanwhile
                panels.set_store(store)
        self.plan = None
        self.simulator.show_live_view()
        plot = self._plot()
        if plot is not None:
            plot.show_live()
        self.simulator.resume()
