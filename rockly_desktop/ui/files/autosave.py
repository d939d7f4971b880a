"""Keeping a copy of the window's unsaved program for after a crash (core/recovery.py does the files).

The copy is written a few seconds after the last change (at the latest every
``MAX_DELAY_MS`` while the person keeps editing) and before every run, from the workspace
the page sends with every change: no round trip to the page. It exists only while the
program has unsaved changes: a save, a new or opened program, or a clean close removes it.
"""
import time

from PySide6.QtCore import QObject, QTimer, Signal

from rockly_desktop.core.errors import ProgramFileError
from rockly_desktop.core.program import Program
from rockly_desktop.ui.texts import tr

DELAY_MS = 3000
MAX_DELAY_MS = 30000


class Autosave(QObject):
    """Writes the ``document``'s program, as the ``editor`` last sent it, to ``session``
    (a RecoverySession). ``language`` is a callable giving the window's language."""

    sig_failed = Signal(str)  # a status-bar message: the copy could not be written

    def __init__(self, document, editor, session, language, parent=None):
        super().__init__(parent)
        self.document = document
        self.session = session
        self._language = language
        self._workspace = None
        self._pending_since = 0.0
        self._adopted = None  # a restored Recovery: deleted once this window's own copy is written
        self._timer = QTimer(self)
        self._timer.setSingleShot(True)
        self._timer.timeout.connect(self._write)
        editor.sig_changed.connect(self._on_editor_changed)
        editor.sig_breakpoints.connect(lambda _ids: self._schedule())
        document.sig_changed.connect(self._on_document_changed)

    @property
    def pending(self) -> bool:
        """True while a change waits to be written."""
        return self._timer.isActive()

    def flush(self):
        """Write a waiting change now (a run is about to start)."""
        if self._timer.isActive():
            self._timer.stop()
            self._write()

    def adopt(self, recovery):
        """The window now shows ``recovery``'s program: write this window's copy now, then
        delete the old recovery file (kept if the copy cannot be written, until a clean close)."""
        self._adopted = recovery
        self._timer.stop()
        self._write()

    def finish(self):
        """A clean close: no copy is needed any more."""
        self._timer.stop()
        self.session.close()
        self._discard_adopted()

    def _on_editor_changed(self, workspace, _python, _origin):
        self._workspace = workspace
        self._schedule()

    def _on_document_changed(self):
        if self.document.modified:
            self._schedule()
        else:
            self._timer.stop()
            self.session.remove()

    def _schedule(self):
        if not self.document.modified:
            return
        now = time.monotonic()
        if not self._timer.isActive():
            self._pending_since = now
        waited_ms = (now - self._pending_since) * 1000
        self._timer.start(int(max(0.0, min(DELAY_MS, MAX_DELAY_MS - waited_ms))))

    def _write(self):
        if not self.document.modified or self._workspace is None:
            return
        program = Program(self.document.profile.id, self._workspace, self.document.breakpoints,
                          self.document.profile.packs_used(self._workspace))
        try:
            self.session.write(program, self.document.path, self.document.disk_stamp)
        except ProgramFileError as error:
            self.sig_failed.emit(tr("autosave_failed", self._language(), error=error))
            return
        self._discard_adopted()

    def _discard_adopted(self):
        if self._adopted is not None:
            self._adopted.discard()
            self._adopted = None
