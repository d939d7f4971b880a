"""The lesson folders watched while the window runs: a lesson added (``rockly lessons import``), changed or
removed is read again without a restart.

``LessonWatch(read, roots, depth)`` watches each folder of ``roots`` (lesson folders lie at most ``depth``
below one; a root not made yet is watched through its nearest folder that is) and every file of the
folders below. Once changes have settled (``SETTLE_MS`` without another), ``read()`` (all the lessons: a
``LessonLibrary``) runs off the window's thread and ``sig_read(library)`` brings the result back to it.
Changes made while a reading runs lead to one more reading after it.
"""
import threading
from pathlib import Path

from PySide6.QtCore import QFileSystemWatcher, QObject, QTimer, Signal

SETTLE_MS = 400  # an import or an editor's save is a burst of changes: read once, after the last


def watched_paths(roots, depth: int) -> list:
    """The folders (and their files) whose changes can add, change or remove a lesson below ``roots``: every
    folder down to ``depth`` below a root (hidden ones left out) and the files in them; for a root that is not
    there, its nearest existing parent folder."""
    paths = []
    for root in map(Path, roots):
        if not root.is_dir():
            parent = next((folder for folder in root.parents if folder.is_dir()), None)
            paths += [str(parent)] if parent is not None else []
            continue
        level = [root]
        for _ in range(depth + 1):
            paths += [str(folder) for folder in level]
            below = []
            for folder in level:
                try:
                    entries = sorted(folder.iterdir())
                except OSError:
                    continue
                paths += [str(entry) for entry in entries if entry.is_file() and not entry.name.startswith(".")]
                below += [entry for entry in entries if entry.is_dir() and not entry.name.startswith(".")]
            level = below
    return list(dict.fromkeys(paths))


class LessonWatch(QObject):
    """Reads the lessons again, off the window's thread, once their folders changed."""

    sig_read = Signal(object)  # the lessons read again (a LessonLibrary), in the window's thread

    def __init__(self, read, roots, depth: int, parent=None):
        super().__init__(parent)
        self._read, self._roots, self._depth = read, list(roots), depth
        self._thread = None
        self._again = False  # a change came while a reading ran
        self._settle = QTimer(self, singleShot=True, interval=SETTLE_MS)
        self._settle.timeout.connect(self._start_reading)
        self._watcher = QFileSystemWatcher(self)
        self._watcher.directoryChanged.connect(self._changed)
        self._watcher.fileChanged.connect(self._changed)
        self.sig_read.connect(self._after_reading)
        self._follow_folders()

    @property
    def reading(self) -> bool:
        """True while the lessons are being read, or changes wait to settle before they are."""
        return self._settle.isActive() or (self._thread is not None and self._thread.is_alive())

    def _follow_folders(self):
        """Watch the folders and files there are now (a new pack's folder, a lesson's new file)."""
        old = self._watcher.directories() + self._watcher.files()
        if old:
            self._watcher.removePaths(old)
        paths = watched_paths(self._roots, self._depth)
        if paths:
            self._watcher.addPaths(paths)

    def _changed(self, _path: str):
        if self._thread is not None and self._thread.is_alive():
            self._again = True
        else:
            self._settle.start()

    def _start_reading(self):
        self._again = False
        self._thread = threading.Thread(target=lambda: self.sig_read.emit(self._read()), name="lesson-reading",
                                        daemon=True)
        self._thread.start()

    def _after_reading(self, _library):
        self._follow_folders()
        if self._again:
            self._again = False
            self._settle.start()

    def stop(self, timeout: float = 30.0):
        """Watch no more and wait for a reading that runs (the window closes)."""
        self._settle.stop()
        self._watcher.removePaths(self._watcher.directories() + self._watcher.files())
        if self._thread is not None:
            self._thread.join(timeout)
