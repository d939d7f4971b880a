"""Reading a recording for the replay in a thread of its own, so the window never waits for it.

A run's recording grows with the run (about 0.25 s of reading and decoding per minute of a
driving program): read on the GUI thread after STOP, it froze the window for seconds. The
``RecordingReader`` reads the file and builds everything the replay's timeline needs before the
first moment is shown (``ReplayData``); the window shows the timeline when it is done.
"""
import logging
from dataclasses import dataclass

from PySide6.QtCore import QThread, Signal

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class ReplayData:
    """What the replay shows of one recording: its ``moments`` (``Moments``), robot ``topics``
    (``RecordedTopics``), a real robot's ``path`` (``RecordedPath``, None with simulator snapshots or
    without ``/odom``), the timeline's ``markers``, the ``printed`` lines and whether the file was ``complete``."""

    moments: object
    topics: object
    path: object
    markers: list
    printed: list
    complete: bool


def replay_data(path, skipped_text) -> ReplayData:
    """Read the recording at ``path`` and prepare its replay (``skipped_text(count)``: the line that says how many
    printed lines were not recorded); raises ``RecordingUnreadable`` for a file that is no recording."""
    # Imported when first used: reading and decoding recordings (mcap, numpy) costs 0.1 s at start.
    from rockly_desktop.recording import channels
    from rockly_desktop.recording.moments import Moments
    from rockly_desktop.recording.odometry import RecordedPath
    from rockly_desktop.recording.reading import read_recording
    from rockly_desktop.recording.topics import RecordedTopics

    recording = read_recording(path)
    moments = Moments(recording)
    topics = RecordedTopics(recording)
    robot_path = None if recording.on(channels.SIMULATOR) else RecordedPath(topics)
    return ReplayData(moments, topics, robot_path or None, moments.markers(), moments.printed_lines(skipped_text),
                      recording.complete)


class RecordingReader(QThread):
    """Reads the recording at ``path`` (see ``replay_data``), then says ``sig_read(self)``: ``data`` holds the
    ``ReplayData``, or ``error`` the ``RecordingUnreadable`` (both None after an unexpected failure, logged).
    ``quiet``: a failure is not to be shown (the caller's flag, kept with the reading)."""

    sig_read = Signal(object)

    def __init__(self, path, skipped_text, parent=None):
        super().__init__(parent)
        self.path = path
        self.data = None
        self.error = None
        self.quiet = False
        self._skipped_text = skipped_text

    def run(self):
        """Qt override: the reading thread's body."""
        from rockly_desktop.recording.reading import RecordingUnreadable

        try:
            self.data = replay_data(self.path, self._skipped_text)
        except RecordingUnreadable as error:
            self.error = error
        except Exception:
            log.exception("the recording %s could not be read", self.path)
        self.sig_read.emit(self)
