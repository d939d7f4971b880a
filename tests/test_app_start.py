"""Start-up work off the GUI thread: the event loop keeps running while it is done."""
import threading

import pytest
from PySide6.QtCore import QTimer

from rockly_desktop.app import while_events_run


def test_work_runs_in_another_thread_while_the_event_loop_runs(qapp):
    delivered = threading.Event()
    QTimer.singleShot(0, delivered.set)  # only the event loop delivers this

    def work():
        assert delivered.wait(timeout=10), "the GUI thread's event loop did not run meanwhile"
        return threading.current_thread() is not threading.main_thread()

    assert while_events_run(work) is True


def test_the_work_s_exception_is_raised_in_the_calling_thread(qapp):
    def work():
        raise LookupError("no such profile")

    with pytest.raises(LookupError, match="no such profile"):
        while_events_run(work)
