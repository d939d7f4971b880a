"""ROS 1 service calls that Stop, a lost master or a timeout end within milliseconds.

A call on a connected persistent ``rospy.ServiceProxy`` runs on the caller's own thread:
handing it to another thread and back costs more than the call itself. While it waits, a
:class:`CallGuard` thread looks at the calls in flight every ``POLL_SECONDS`` and cuts one
that must end by closing its connection, which makes rospy's blocked read return and the
call fail. A proxy's first call also connects (a question to the master, then a TCP connect),
which closing cannot cut; it runs on a helper thread that the caller stops waiting for (the
abandoned call, e.g. a question on the robot's tablet, finishes on its own).
"""
import threading
import time
from concurrent.futures import ThreadPoolExecutor

from rockly_desktop.robot.ros1.message_values import to_message

POLL_SECONDS = 0.01
SERVICE_WORKERS = 16
GUARD_LINGER_SECONDS = 2.0  # the guard keeps polling this long after the last call, so a run of calls wakes it once


class CallOutcome:
    """How a call went: ``response`` (a genpy message), or ``error`` (what rospy raised), and
    ``ended``: True when it was cut because it had to end (Stop, a lost master, its timeout)."""

    __slots__ = ("response", "error", "ended")

    def __init__(self):
        self.response = None
        self.error = None
        self.ended = False


class _Watched:
    __slots__ = ("should_end", "cut", "ended")

    def __init__(self, should_end, cut):
        self.should_end = should_end
        self.cut = cut
        self.ended = False


class CallGuard:
    """Ends waits it is told about: after ``watch(should_end, cut)`` it calls ``cut()`` (once) as
    soon as ``should_end()`` is true, checking every ``poll`` seconds while anything is watched.

    Its daemon thread starts on first use and sleeps when nothing has been watched for
    ``linger`` seconds. ``cut`` runs under the guard's lock, so once ``unwatch`` has returned
    no cut of that wait is still under way.
    """

    def __init__(self, poll: float = POLL_SECONDS, linger: float = GUARD_LINGER_SECONDS):
        self._poll = poll
        self._linger = linger
        self._lock = threading.Lock()
        self._watched = set()
        self._wake = threading.Event()
        self._sleeping = False
        self._thread = None

    @property
    def sleeping(self) -> bool:
        """True while the guard's thread waits for something to watch (not polling)."""
        with self._lock:
            return self._thread is None or self._sleeping

    def watch(self, should_end, cut):
        """Start watching a wait; pass what this returns to :meth:`unwatch` when the wait is over."""
        watched = _Watched(should_end, cut)
        with self._lock:
            self._watched.add(watched)
            if self._thread is None:
                self._thread = threading.Thread(target=self._run, name="rockly-service-guard", daemon=True)
                self._thread.start()
            elif self._sleeping:
                self._wake.set()
        return watched

    def unwatch(self, watched) -> bool:
        """Stop watching; True if the wait was cut."""
        with self._lock:
            self._watched.discard(watched)
        return watched.ended

    def _run(self):
        quiet_since = None
        while True:
            with self._lock:
                for watched in self._watched:
                    if not watched.ended and watched.should_end():
                        watched.ended = True
                        watched.cut()
                if self._watched:
                    quiet_since = None
                elif quiet_since is None:
                    quiet_since = time.monotonic()
                elif time.monotonic() - quiet_since >= self._linger:
                    self._sleeping = True
                    self._wake.clear()
            if self._sleeping:
                self._wake.wait()
                with self._lock:
                    self._sleeping = False
                quiet_since = None
            else:
                time.sleep(self._poll)


class ServiceCaller:
    """Makes a RosGraph's service calls: on the caller's thread when connected, else on a helper thread."""

    def __init__(self):
        self.guard = CallGuard()
        self._pool = ThreadPoolExecutor(max_workers=SERVICE_WORKERS, thread_name_prefix="rockly-service")

    def call(self, proxy, request: dict, should_end, cut) -> CallOutcome:
        """Call persistent ``proxy`` with ``request`` (a dict) until it answers or ``should_end()``;
        then ``cut()`` must close its connection (the proxy is not used again)."""
        # rospy keeps a persistent proxy's connection in ``transport`` once its first call connected.
        if getattr(proxy, "transport", None) is None:
            return self._call_on_helper(proxy, request, should_end, cut)
        outcome = CallOutcome()
        watched = self.guard.watch(should_end, cut)
        try:
            _call(proxy, request, outcome)
        finally:
            outcome.ended = self.guard.unwatch(watched)
        return outcome

    def _call_on_helper(self, proxy, request, should_end, cut) -> CallOutcome:
        outcome, done = CallOutcome(), threading.Event()

        def call():
            _call(proxy, request, outcome)
            done.set()

        self._pool.submit(call)
        while not done.wait(POLL_SECONDS):
            if should_end():
                if not done.is_set():  # the abandoned call still owns the connection: the next call needs its own
                    cut()
                    outcome.ended = True
                break
        return outcome


def _call(proxy, request, outcome):
    try:
        outcome.response = proxy.call(to_message(proxy.request_class, request))
    except Exception as error:
        outcome.error = error
