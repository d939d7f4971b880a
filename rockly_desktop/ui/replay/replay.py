"""Replaying a recorded run in the window: the block that ran glows, the Variables dock and the
Simulator view show that moment (for a real robot's run, without simulator snapshots: a plan view
of its recorded ``/odom``), the Robot state panels the recorded topics then, the Console what had
been printed by then and the Plot the recorded series with a cursor at it. Replay only ever
changes what is on screen: it sends nothing to a robot, and a file that is no recording changes
nothing at all. A recording shows only on the robot it was recorded with (its profile) and, for a
simulator's run, in the same solid world: one robot's run drawn in another robot's world would
show a robot where no robot was.
"""
from PySide6.QtCore import QObject, Signal
from PySide6.QtWidgets import QMessageBox

from rockly_desktop.ui.docks.plan_view import PlanView
from rockly_desktop.ui.files.file_dialogs import FileDialogs
from rockly_desktop.ui.message_boxes import plain_message_box
from rockly_desktop.ui.replay.recording_reader import RecordingReader, release
from rockly_desktop.ui.run.block_badges import badge_texts
from rockly_desktop.ui.texts import tr


class Replay(QObject):
    """Drives the ``bar`` (``ReplayBar``) and shows its moments in the ``editor``, the ``variables`` dock,
    the ``simulator`` dock (whose live refresh pauses while a moment is shown), the ``console`` and the
    plot panel. ``sig_opened(shown)``: a recording asked for with ``open`` was read, and shown or not;
    ``sig_past_shown(keys)`` names the docks (by their registry keys) that show a moment instead of the robot now."""

    sig_opened = Signal(bool)
    sig_past_shown = Signal(tuple)  # the keys of the docks a moment drives (none: all show the robot live again)

    def __init__(self, bar, editor, variables, simulator, language, parent=None, badges=lambda: True,
                 console=None, plot=lambda: None, state_panels=lambda: None, robots=None, registry=None):
        """``language`` is the window's ``CurrentLanguage``, read whenever the replay speaks. ``badges()`` says
        whether the blocks' badges and values are shown (not at the Starter level); ``plot()`` is
        the Plot panel and ``state_panels()`` the Robot state panels, each None while there is none;
        ``robots`` (a ``RobotChoice``) is the window's robot, whose profile and world a recording must have
        (None: any recording shows); the ``registry``'s profiles name the robot of a recording made on another."""
        super().__init__(parent)
        self._robots = robots
        self._registry = registry
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
        self._language = language
        self.moments = None
        self._printed = None  # the lines printed, as the console shows them
        self._reader = None  # the RecordingReader whose recording is to be shown
        self._data = None  # the ReplayData shown
        self._shown_block = None
        self._past = ()  # the keys of the docks showing a moment, as last said
        self._snapshot_shown = False  # the simulator view shows a recorded snapshot, not the robot now
        self.file_dialogs = FileDialogs()  # kiosk mode puts dialogs kept in one folder in its place
        bar.sig_moment.connect(self.show_moment)
        bar.sig_closed.connect(self._back_to_live)

    def choose(self, folder: str = ""):
        """Ask for a recording (File → Open recording…) and open it."""
        path = self.file_dialogs.open_file(self.parent(), tr("open_recording", self.language).replace(
            "&", "").rstrip("…"), folder, tr("recording_filter", self.language))
        if path:
            self.open(path)

    def open(self, path, quiet: bool = False):
        """Show the timeline of the recording at ``path`` once a thread of its own has read it (the window goes on
        meanwhile), then say ``sig_opened(shown)``. A file that cannot be read, or a recording of another robot or
        world, is said in a message box and nothing changes; what reading left out of one in a message box and
        the bar's note (``quiet``, e.g. after a run: only in the note). A later ``open`` or ``close`` drops what
        this one reads."""
        reader = RecordingReader(path, lambda count: tr("output_not_recorded", self.language, count=count), self)
        reader.quiet = quiet
        self._reader = reader
        reader.sig_read.connect(self._read)  # queued: this object lives in the GUI thread
        reader.finished.connect(reader.deleteLater)
        reader.start()

    def _read(self, reader):
        data, reader.data = reader.data, None  # the reader is deleted in this thread: it must not hold the data
        if reader is not self._reader:  # another recording was asked for, or a run started meanwhile
            if data is not None:
                release(data)
            return
        self._reader = None
        self.sig_opened.emit(self._show(data, reader.error, reader.quiet))

    def _show(self, data, error, quiet: bool) -> bool:
        """Show ``data`` (a ``ReplayData``; None: unread, ``error`` says why); whether it is shown."""
        if data is None:
            if error is not None and not quiet:
                self._say("recording_unreadable_box", tr("recording_unreadable", self.language),
                          error.in_language(self.language))
            return False
        refusal = self._shown_elsewhere(data.metadata)
        if refusal is not None:
            release(data)
            if not quiet:
                box = plain_message_box(self.parent(), QMessageBox.Icon.Information,
                                        tr("recording_other_robot_title", self.language), refusal)
                box.setObjectName("recording_other_robot_box")
                box.open()
            return False
        shown, self._data = self._data, data
        self.moments, self.topics, self.path, self._printed = data.moments, data.topics, data.path, data.printed
        if shown is not None:
            release(shown)
        self.simulator.show_live_view()
        self.plan = None
        short, notes = self._bar_note()
        self.bar.show_timeline(self.moments.duration, data.markers, short, notes)
        if notes and not quiet:
            self._say("recording_partly_read_box", tr("recording_partly_read", self.language), notes)
        return True

    def _bar_note(self) -> tuple:
        """(the bar's short note, what it stands for) on what reading the recording left out, in the
        window's language."""
        if self._data is None:
            return "", ""
        notes = "\n".join(note.in_language(self.language) for note in self._data.notes)
        short = [tr(key, self.language) for key, shown in (("replay_cut_short", not self._data.complete),
                                                            ("replay_parts_left_out", notes)) if shown]
        return " ".join(short), notes

    @property
    def language(self) -> str:
        """The language the replay speaks: the window's, now."""
        return self._language.code

    def retitle(self):
        """Say the bar in the current language (after it changed; what a moment shows follows by itself)."""
        self.bar.retitle()
        self.bar.set_note(*self._bar_note())

    def _say(self, name: str, title: str, text: str):
        box = plain_message_box(self.parent(), QMessageBox.Icon.Warning, title, text)
        box.setObjectName(name)
        box.open()

    def close(self):
        """Hide the timeline (a run is starting, or another program opens); a recording being read is not shown."""
        self._reader = None
        if self.bar.isVisible():
            self.bar.close_timeline()

    def end(self):
        """Hide the timeline and forget the recording: another program or robot is on screen, and the
        old run's moments are not its own."""
        self.close()
        shown, self._data = self._data, None
        if shown is not None:
            release(shown)
        self.moments = self.topics = self.path = self.plan = self._printed = None

    def _shown_elsewhere(self, metadata: dict):
        """Why a recording with ``metadata`` cannot show on the window's robot now, or None when it can."""
        if self._robots is None:
            return None
        profile = self._robots.document.profile
        recorded = metadata.get("profile")
        if recorded and recorded != profile.id:
            profiles = self._registry.profiles if self._registry is not None else {}
            name = profiles[recorded].display_name(self.language) if recorded in profiles else recorded
            return tr("recording_other_robot", self.language, robot=name, here=profile.display_name(self.language))
        world, here = metadata.get("world"), self._robots.world_id()
        if world and here is not None and world != here:
            return tr("recording_other_world", self.language, robot=profile.display_name(self.language))
        return None

    def wait_for_reading(self, timeout_ms: int = 30000) -> bool:
        """Wait until no recording is being read (the window is closing); True when none is."""
        return all(reader.wait(timeout_ms) for reader in self.findChildren(RecordingReader))

    def show_moment(self, seconds: float):
        """Show the run as it was ``seconds`` after it began."""
        if self.moments is None:
            return
        moment = self.moments.at(seconds)
        past = ["variables_dock"]
        if moment.block != self._shown_block:
            self._shown_block = moment.block
            self.editor.call("highlight", {"id": moment.block})
        self.variables.show_values(moment.variables)
        if self.console is not None and moment.printed != self._shown_printed:
            self._shown_printed = moment.printed
            self.console.show_recorded(self._printed, moment.printed)
        if self.console is not None:
            past.append("console_dock")
        plot = self._plot()
        if plot is not None:
            plot.show_recorded(self.topics, seconds, self.moments.duration)
            past.append("plot_dock")
        if self._badges_wanted():
            badges = self.moments.badges(seconds)
            if badges != self._shown_badges:
                self._shown_badges = badges
                self.editor.call("setBadges", {"badges": badge_texts(badges, self.language)})
            values = self.moments.values(seconds)
            if values != self._shown_values:
                self._shown_values = values
                self.editor.call("setValues", {"values": values, "label": tr("block_value", self.language)})
        if self._show_state(seconds):
            past.append("state_dock")
        view = self.simulator.view
        if moment.snapshot is not None and view is not None:
            self.simulator.stop()
            view.set_snapshot(moment.snapshot)
            self._snapshot_shown = True
        elif self.path is not None:
            if self.plan is None:
                self.plan = PlanView(self.path.bounds(), self.language)
                self.simulator.show_recorded_view(self.plan)
            self.plan.show_poses(self.path.until(seconds))
        if self._snapshot_shown or self.plan is not None:  # a snapshot shown stays until the view is live again
            past.append("simulator_dock")
        self._say_past(tuple(past))

    def _say_past(self, keys: tuple):
        if keys != self._past:
            self._past = keys
            self.sig_past_shown.emit(keys)

    def _show_state(self, seconds: float) -> bool:
        """Show the recorded topics at ``seconds`` in the Robot state panels; whether there are any."""
        panels = self._state_panels()
        if panels is None:
            return False
        if self._live_panels is None or self._live_panels[0] is not panels:
            self._live_panels = (panels, panels.store)
        panels.set_store(self.topics.at(seconds))
        return True

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
        self._snapshot_shown = False
        self._say_past(())
