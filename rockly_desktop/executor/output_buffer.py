"""What a running program prints, held for the window to show in batches.

A program printing in a tight loop would otherwise send the window one event per line,
thousands a second, and the window (and STOP with it) would fall seconds behind. The
program's thread adds lines here; the window takes a batch of at most ``batch`` lines on
its 30 Hz timer (oldest first), so drawing them stays short. Only the newest ``limit``
lines wait; older ones are counted as skipped.
"""
import threading
from collections import deque


class OutputBuffer:
    """Thread-safe, bounded lines of program output waiting to be shown."""

    def __init__(self, limit: int = 2000, batch: int = 300):
        self._batch = batch
        self._lines = deque(maxlen=limit)
        self._skipped = 0
        self._lock = threading.Lock()

    def add(self, line: str):
        """Keep ``line`` (dropping the oldest waiting one when full)."""
        with self._lock:
            if len(self._lines) == self._lines.maxlen:
                self._skipped += 1
            self._lines.append(line)

    def take(self, everything: bool = False) -> tuple:
        """The oldest waiting lines (a batch, or ``everything``) and how many lines were skipped before them."""
        with self._lock:
            count = len(self._lines) if everything else min(self._batch, len(self._lines))
            lines = [self._lines.popleft() for _ in range(count)]
            skipped, self._skipped = self._skipped, 0
        return lines, skipped
