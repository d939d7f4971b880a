"""Start-up work off the GUI thread: the event loop keeps running while it is done."""
import json
import os
import subprocess
import sys
import threading
from pathlib import Path

import pytest
from PySide6.QtCore import QTimer

from rockly_desktop.app import while_events_run

REPO = Path(__file__).resolve().parents[1]


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


def test_the_window_s_modules_leave_what_start_up_does_not_need_unimported():
    """Plotting, recordings, ROS and YAML are imported when first used, not by the window's start."""
    script = ("import sys, json; import rockly_desktop.ui.main_window; "
              "print(json.dumps(sorted(name for name in ('numpy', 'pyqtgraph', 'mcap', 'mcap_ros1', 'rospy', 'genpy', "
              "'rclpy', 'yaml', 'urllib.request') if name in sys.modules)))")
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen")
    result = subprocess.run([sys.executable, "-c", script], cwd=REPO, env=env, capture_output=True, text=True,
                            timeout=60, check=False)
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout) == []


def test_chromium_keeps_a_page_not_yet_on_screen_at_full_speed(monkeypatch):
    # run_gui sends the start-up program before the window shows; a backgrounded page loaded it a third slower.
    from rockly_desktop.app import prepare_qt_environment

    monkeypatch.setenv("QTWEBENGINE_CHROMIUM_FLAGS", "--lang=de")
    prepare_qt_environment()
    prepare_qt_environment()  # (each flag once)
    assert os.environ["QTWEBENGINE_CHROMIUM_FLAGS"].split() == ["--lang=de", "--log-level=3",
                                                               "--disable-renderer-backgrounding"]
