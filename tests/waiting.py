"""Waiting in tests for something that happens in another thread or process."""
import time


def eventually(predicate, timeout=10.0, interval=0.01):
    """Return once ``predicate()`` is true; fail the test if it is not within ``timeout`` s (generous)."""
    deadline = time.monotonic() + timeout
    while not predicate():
        assert time.monotonic() < deadline, "the condition did not come true in time"
        time.sleep(interval)
