"""Running a call in a thread (as a program's worker would) and looking at how it ended."""
import threading
import time


class Background:
    """Runs ``function`` in a thread; records its result or error and when it ended."""

    def __init__(self, function):
        self.result = self.error = self.ended_at = None
        self.thread = threading.Thread(target=self._run, args=(function,), daemon=True)
        self.thread.start()

    def _run(self, function):
        try:
            self.result = function()
        except Exception as error:
            self.error = error
        finally:
            self.ended_at = time.monotonic()

    def join(self, timeout=20.0):
        """Wait for the call to end (failing the test if it does not)."""
        self.thread.join(timeout)
        assert not self.thread.is_alive(), "the background call did not end"
        return self
