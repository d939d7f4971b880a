"""Interruptible waiting: every robot wait goes through an Interrupt so Stop is immediate."""
import threading
import time

from rockly_desktop.core.errors import ProgramStopped

POLL_SECONDS = 0.01


class Interrupt:
    """A stop flag (and a pause request) that robot waits watch; any thread may set them.

    ``sleep`` and ``wait_until`` raise ProgramStopped within ~10 ms of a stop request. A
    command in the middle of a motion checks ``pause_requested``, halts the robot, calls
    ``hold()`` and then completes what is left of the motion.
    """

    def __init__(self):
        self._stopped = threading.Event()
        self._pause = threading.Event()
        self.hold_handler = None

    @property
    def pause_requested(self) -> bool:
        """True while the person asked the program to pause (a long motion should halt)."""
        return self._pause.is_set()

    def set_pause_requested(self, requested: bool):
        """Raise or lower the pause request (done by the run controls)."""
        if requested:
            self._pause.set()
        else:
            self._pause.clear()

    def hold(self):
        """Called by a command that halted the robot for a pause: returns when the program
        may go on (the command then finishes its motion); a stop raises ProgramStopped."""
        if self.hold_handler is not None:
            self.hold_handler()
        while self._pause.is_set():
            self.sleep(POLL_SECONDS)

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

    def sleep(self, seconds: float, watch=None):
        """Wait ``seconds``; a stop raises ProgramStopped at once, a pause holds the clock.
        ``watch()``, called every step, may raise to end the wait (a lost robot)."""
        deadline = time.monotonic() + max(0.0, seconds)
        while True:
            if self._pause.is_set() and self.hold_handler is not None:
                paused_at = time.monotonic()
                self.hold()
                deadline += time.monotonic() - paused_at
            if watch is not None:
                watch()
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                return
            self.nap(min(remaining, POLL_SECONDS) if self.hold_handler or watch else remaining)

    def nap(self, seconds: float):
        """Wait up to ``seconds`` for a stop (then raise ProgramStopped); a pause does not hold it."""
        if self._stopped.wait(seconds):
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
            self.nap(min(POLL_SECONDS, remaining))
