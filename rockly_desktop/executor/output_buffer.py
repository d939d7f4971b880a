"""What a running program prints, held for the window to show in batches.

A program printing in a tight loop would otherwise send the window one event per line,
thousands a second, and the window (and STOP with it) would fall seconds behind. The
program's thread adds lines here; the window takes them all at once on its 30 Hz timer.
Only the newest ``limit`` lines are kept; the others are counted as skipped.
"""
import threading
from collections import deque


class OutputBuffer:
    """Thread-safe, bounded lines of program output waiting to be shown."""

    def __init__(self, limit: int = 5000):
        self._lines = deque(maxlen=limit)
        self._skipped = 0
        self._lock = threading.Lock()

    def add(self, line: str):
        """Keep ``line`` (dropping the oldest waiting one when full)."""
        with self._lock:
            if len(self._lines) == self._lines.maxlen:
                self._skipped += 1
            self._lines.append(line)

    def take(self) -> tuple:
        """Everything waiting, as (lines, how many older lines were skipped); empties the buffer."""
        with self._lock:
            lines, skipped = list(self._lines), self._skipped
            self._lines.clear()
            self._skipped = 0
        return lines, skipped
