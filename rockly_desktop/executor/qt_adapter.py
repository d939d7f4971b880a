"""The one Qt part of the executor: runs a ProgramRunner in a QThread, events as a signal.

The worker never touches a widget; the GUI thread receives events through a queued
signal and polls ``current_block``, variables and the printed ``output`` on a timer
(coalesced highlighting and output).
"""
from PySide6.QtCore import QThread, Signal

from rockly_desktop.executor.events import OutputPrinted
from rockly_desktop.executor.output_buffer import OutputBuffer


class ProgramThread(QThread):
    """Runs ``runner.run()`` in its own thread. Printed lines wait in ``output``; every other
    runner event arrives as ``sig_event`` (take ``output`` first to keep the order)."""

    sig_event = Signal(object)

    def __init__(self, make_runner, parent=None):
        """``make_runner(emit)`` builds the ProgramRunner that reports through ``emit``."""
        super().__init__(parent)
        self.output = OutputBuffer()
        self.runner = make_runner(self._emit)

    def _emit(self, event):
        if isinstance(event, OutputPrinted):
            self.output.add(event.text)
        else:
            self.sig_event.emit(event)

    def run(self):
        """Qt override: the worker thread's body."""
        self.runner.run()
