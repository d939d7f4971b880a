"""The one Qt part of the executor: runs a ProgramRunner in a QThread, events as a signal.

The worker never touches a widget; the GUI thread receives events through a queued
signal and polls ``current_block`` / variables on a timer (coalesced highlighting).
"""
from PySide6.QtCore import QThread, Signal


class ProgramThread(QThread):
    """Runs ``runner.run()`` in its own thread; every runner event arrives as ``sig_event``."""

    sig_event = Signal(object)

    def __init__(self, make_runner, parent=None):
        """``make_runner(emit)`` builds the ProgramRunner that reports through ``emit``."""
        super().__init__(parent)
        self.runner = make_runner(self.sig_event.emit)

    def run(self):  # noqa: D401 - Qt override
        """Qt override: the worker thread's body."""
        self.runner.run()
