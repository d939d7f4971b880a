"""The controls a person uses on a running program: stop, pause, step, continue, breakpoints, speed.

Every method may be called from any thread. The runner reads the state at each block
through one cheap flag (``attention``), so a program at full speed pays almost nothing.
"""
import threading

from rockly_desktop.robot.interrupt import Interrupt


class RunControl:
    """Thread-safe run controls shared by the UI (or CLI) and the runner."""

    def __init__(self, breakpoints=(), delay: float = 0.0, trace: bool = False):
        """``trace``: report every block entered (BlockEntered), as the command line does."""
        self.interrupt = Interrupt()
        self.trace = trace
        self._lock = threading.Condition()
        self._breakpoints = frozenset(breakpoints)
        self._delay = max(0.0, delay)
        self._pause_requested = False
        self._step_requested = False
        self._release = False
        self.attention = False
        self.on_hold = None  # set by the runner: shows a pause inside a block, waits for release
        self.interrupt.hold_handler = self._hold
        self._update_attention()

    def _update_attention(self):
        self.attention = bool(self.interrupt.stop_requested or self._pause_requested or self._step_requested
                              or self._breakpoints or self._delay or self.trace)

    @property
    def breakpoints(self) -> frozenset:
        """Block ids the program pauses before."""
        return self._breakpoints

    @property
    def delay(self) -> float:
        """Seconds the program waits at each block (slow motion); 0 is full speed."""
        return self._delay

    def set_breakpoints(self, block_ids):
        """Pause before any of these blocks from now on."""
        with self._lock:
            self._breakpoints = frozenset(block_ids)
            self._update_attention()

    def set_delay(self, seconds: float):
        """Wait this long at each block (0 = full speed)."""
        with self._lock:
            self._delay = max(0.0, float(seconds))
            self._update_attention()

    def request_stop(self):
        """End the run at the next block or inside the current robot wait."""
        with self._lock:
            self.interrupt.request_stop()
            self._update_attention()
            self._lock.notify_all()

    def request_pause(self):
        """Pause before the next block, or at once inside a motion that can be halted."""
        with self._lock:
            self._pause_requested = True
            self.interrupt.set_pause_requested(True)
            self._update_attention()

    def step(self):
        """Run one block, then pause again (also pauses a running program at the next block)."""
        with self._lock:
            self._step_requested = True
            self._release = True
            self.interrupt.set_pause_requested(False)
            self._update_attention()
            self._lock.notify_all()

    def resume(self):
        """Continue a paused program at full (or slow-motion) speed."""
        with self._lock:
            self._pause_requested = False
            self._step_requested = False
            self._release = True
            self.interrupt.set_pause_requested(False)
            self._update_attention()
            self._lock.notify_all()

    def pause_reason(self, block_id: str):
        """Why the program must pause before ``block_id`` ('step', 'pause', 'breakpoint'), or None.

        Consumes a pending step or pause request.
        """
        with self._lock:
            if self._step_requested:
                self._step_requested = False
                reason = "step"
            elif self._pause_requested:
                self._pause_requested = False
                reason = "pause"
            elif block_id in self._breakpoints:
                reason = "breakpoint"
            else:
                return None
            self._release = False
            self._update_attention()
            return reason

    def _hold(self):
        """A command halted the robot for a pause, in the middle of a block."""
        with self._lock:
            self._pause_requested = False
            self._release = False
            self._update_attention()
        if self.on_hold is not None:
            self.on_hold()
        else:
            self.wait_for_release()

    def wait_for_release(self):
        """Block the program until resume(), step() or a stop (which raises ProgramStopped)."""
        with self._lock:
            while not self._release:
                self.interrupt.check()
                self._lock.wait(0.05)
            self.interrupt.check()
