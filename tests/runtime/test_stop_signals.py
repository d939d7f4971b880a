"""A stop signal reaches the run even when it interrupts the main thread while that thread holds the lock the stop
needs (a run polling its stop Event holds the Event's lock between polls)."""
import os
import signal
import threading

from rockly_desktop.runtime.stop_signals import StopOnSignals


def test_a_sigterm_while_the_main_thread_holds_the_stops_lock_still_stops_the_run():
    lock, stopped = threading.Lock(), threading.Event()

    def request_stop():
        with lock:
            stopped.set()

    with StopOnSignals(request_stop) as signals:
        with lock:  # the handler runs in this thread, now: it must not wait for this lock
            os.kill(os.getpid(), signal.SIGTERM)
        assert stopped.wait(10)
    assert signals.signum == signal.SIGTERM


def test_only_the_first_signal_counts_and_the_previous_handlers_come_back():
    before = signal.getsignal(signal.SIGINT)
    stops = []
    with StopOnSignals(lambda: stops.append(1)) as signals:
        os.kill(os.getpid(), signal.SIGINT)
        os.kill(os.getpid(), signal.SIGTERM)
    assert signals.signum == signal.SIGINT and stops == [1]
    assert signal.getsignal(signal.SIGINT) is before
