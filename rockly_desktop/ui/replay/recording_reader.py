"""Reading a recording for the replay in a thread of its own, so the window never waits for it.

A run's recording grows with the run (ten minutes of a tight loop: two million messages, 17 s to
read and prepare on a loaded machine): read on the GUI thread after STOP, it froze the window for
as long. The ``RecordingReader`` reads the file and builds everything the replay's timeline needs
before the first moment is shown (``ReplayData``); the window shows the timeline when it is done.
A thread of its own is not enough under the GIL: what holds it for long in one go froze the window
too (the collector's full passes, sorting or freeing a million objects at once), hence
``collector_paused`` and ``release``.
"""
import gc
import logging
import threading
from contextlib import contextmanager
from dataclasses import dataclass

from PySide6.QtCore import QThread, Signal

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class ReplayData:
    """What the replay shows of one recording: its ``moments`` (``Moments``), robot ``topics``
    (``RecordedTopics``), a real robot's ``path`` (``RecordedPath``, None with simulator snapshots or
    without ``/odom``), the timeline's ``markers``, the ``printed`` lines, whether the file was ``complete``, its
    ``metadata`` (the robot and world it was recorded with) and the ``notes`` on what reading left out."""

    moments: object
    topics: object
    path: object
    markers: list
    printed: list
    complete: bool
    metadata: dict
    notes: list


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
                      recording.complete, dict(recording.metadata), recording.notes())


_pausing = threading.Lock()
_readings = 0  # readings under way, while the collector is paused


@contextmanager
def collector_paused():
    """Pause Python's cyclic garbage collector while a recording is read, and keep what was read out of its later
    passes (``gc.freeze``).

    A long run's recording becomes millions of objects, and each full pass of the collector walks all of them holding
    the GIL: reading a ten-minute tight loop's recording in its own thread still froze the window for 0.95 s at a
    time. What is read holds no reference cycles: it is freed by reference counting when the replay lets it go. The
    price: a cycle that becomes garbage in another thread during a reading is never collected."""
    global _readings
    with _pausing:
        _readings += 1
        gc.disable()
    try:
        yield
    finally:
        with _pausing:
            _readings -= 1
            if not _readings:
                gc.freeze()
                gc.enable()


RELEASE_SLICE = 20_000


def _empty(value, depth: int = 5):
    """Empty the lists in ``value``, in the dicts it holds and in Rockly's objects it holds, a slice at a time."""
    if isinstance(value, list):
        while value:
            del value[-RELEASE_SLICE:]
    elif isinstance(value, dict) and depth:
        for item in list(value.values()):
            _empty(item, depth - 1)
    elif depth and type(value).__module__.startswith("rockly_desktop.") and hasattr(value, "__dict__"):
        for item in vars(value).values():
            _empty(item, depth - 1)


def release(data: ReplayData):
    """Let ``data`` go in a thread of its own, a slice at a time: a long run's replay freed at once held the GIL for
    0.3 s, the window waiting."""
    threading.Thread(target=_empty, args=(data,), name="rockly-replay-release", daemon=True).start()


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
            with collector_paused():
                self.data = replay_data(self.path, self._skipped_text)
        except RecordingUnreadable as error:
            self.error = error
        except Exception:
            log.exception("the recording %s could not be read", self.path)
        self.sig_read.emit(self)
