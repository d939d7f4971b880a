"""The program the window edits, as its helpers share it: file, robot profile, breakpoints, changes,
and what its file was on disk when this window last read or wrote it.

No widgets: the window's helpers (file commands, the run session, the robot choice)
read and change it, and the window follows its signals (title, Robot menu, editor).
"""
from pathlib import Path

from PySide6.QtCore import QObject, Signal

from rockly_desktop.core.file_stamp import stamp_file
from rockly_desktop.ui.texts import tr


class Document(QObject):
    """The open program: ``path`` (None until saved), ``profile``, ``breakpoints`` (block ids), ``modified``;
    ``disk_stamp``, the FileStamp of ``path`` as this window last read or wrote it (None: not known)."""

    sig_changed = Signal()  # path or modified flag changed
    sig_profile_changed = Signal(object)  # the Profile programs are now made for

    def __init__(self, profile, parent=None):
        super().__init__(parent)
        self._profile = profile
        self._path = None
        self._modified = False
        self.breakpoints = []
        self.disk_stamp = None

    @property
    def path(self):
        """The program's file, or None for a program never saved (or imported)."""
        return self._path

    @property
    def modified(self) -> bool:
        """True when the program on screen differs from its file."""
        return self._modified

    @modified.setter
    def modified(self, value: bool):
        if value != self._modified:
            self._modified = value
            self.sig_changed.emit()

    @property
    def profile(self):
        """The robot profile whose blocks the program uses."""
        return self._profile

    @profile.setter
    def profile(self, profile):
        if profile is not self._profile:
            self._profile = profile
            self.sig_profile_changed.emit(profile)

    def mark_modified(self):
        """The person changed the program."""
        self.modified = True

    def set_file(self, path, modified: bool, disk_stamp=None):
        """The program on screen now belongs to ``path`` (None: no file yet), which was ``disk_stamp``
        when this window read or wrote it."""
        self._path = str(path) if path else None
        self._modified = modified
        self.disk_stamp = disk_stamp if path else None
        self.sig_changed.emit()

    def changed_on_disk(self):
        """The file's FileStamp now when another window or program changed its content since this
        window read or wrote it; None while it has not (or is gone: saving then loses nothing)."""
        if self._path is None or self.disk_stamp is None:
            return None
        now = stamp_file(self._path, self.disk_stamp)
        if now is None or now == self.disk_stamp:
            return None
        if now.sha256 == self.disk_stamp.sha256:  # touched, or written again with the same content
            self.disk_stamp = now
            return None
        return now

    def display_name(self, language: str) -> str:
        """The file name for the title bar and prompts."""
        return Path(self._path).name if self._path else tr("untitled", language)
