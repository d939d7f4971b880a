"""Interruptible waiting: every robot wait goes through an Interrupt so Stop is immediate."""
import threading
import time

from rockly_desktop.core.errors import ProgramStopped

POLL_SECONDS = 0.01


class Interrupt:
    """A stop flag that waits can watch. ``request_stop`` may be called from any thread.

    ``sleep`` and ``wait_until`` raise ProgramStopped within ~10 ms of a stop request.
    """

    def __init__(self):
        self._stopped = threading.Event()

    def request_stop(self):
        """Make every current and future wait raise ProgramStopped."""
        self._stopped.set()

    @property
    def stop_requested(self) -> bool:
        """True once a stop was requested."""
        return self._stopped.is_set()

    def check(self):
        """Raise ProgramStopped if a stop was requested."""
        if self._stopped.is_set():
            raise ProgramStopped("the program was stopped")

    def sleep(self, seconds: float):
        """Wait ``seconds``; raise ProgramStopped as soon as a stop is requested."""
        if self._stopped.wait(max(0.0, seconds)):
            raise ProgramStopped("the program was stopped")

    def wait_until(self, predicate, timeout: float) -> bool:
        """Poll ``predicate`` until it is true (True) or ``timeout`` passes (False); stop raises."""
        deadline = time.monotonic() + timeout
        while True:
            self.check()
            if predicate():
                return True
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                return False
            self.sleep(min(POLL_SECONDS, remaining))
