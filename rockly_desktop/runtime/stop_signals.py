"""Ctrl+C (SIGINT) and SIGTERM asking a run to stop, safely.

A Python signal handler runs in the main thread between two of its bytecodes, possibly while that thread holds a
lock: inside ``threading.Event.wait`` polling for a stop, say. A handler that set the Event itself would wait for
that lock for ever (seen: ``rockly run`` hanging on a SIGTERM once in a full test run). So the handler only writes
a byte to a pipe (no lock taken); a thread of its own reads it and asks the run to stop.
"""
import os
import signal
import threading

STOP_SIGNALS = (signal.SIGINT, signal.SIGTERM)


class StopOnSignals:
    """While entered, the first SIGINT or SIGTERM calls ``request_stop()`` (on a thread of its own) and is kept as
    ``signum``; later ones are ignored. The previous handlers are put back on leaving."""

    def __init__(self, request_stop):
        self.request_stop = request_stop
        self.signum = None
        self._previous = {}
        self._read = self._write = None
        self._reader = None

    def __enter__(self):
        self._read, self._write = os.pipe()
        self._reader = threading.Thread(target=self._wait, name="rockly-stop-signal", daemon=True)
        self._reader.start()
        self._previous = {signum: signal.signal(signum, self._handle) for signum in STOP_SIGNALS}
        return self

    def __exit__(self, *_exc):
        for signum, handler in self._previous.items():
            signal.signal(signum, handler)
        os.close(self._write)  # the reader wakes with nothing read and leaves
        self._reader.join(5)
        os.close(self._read)

    def _handle(self, signum, _frame):
        if self.signum is None:
            self.signum = signum
            os.write(self._write, b"s")

    def _wait(self):
        if os.read(self._read, 1):
            self.request_stop()
