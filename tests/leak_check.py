"""Fails a test that leaves a QThread running, a child process alive or a mouse button held down in
Qt's state (a plugin conftest.py loads).

A test that starts a thread or a process must end it: the next test would otherwise share
the CPU, the ROS master or the QApplication with it. Processes of session and module
fixtures are not the test's: those already running when the test starts are left alone,
and a fixture's process that a test restarts (the shared master) is named with
``shared_process``. Chromium's helpers (QtWebEngineProcess) belong to the QApplication.
"""
import os
import signal
from pathlib import Path

import pytest
import shiboken6
from PySide6.QtCore import Qt, QThread
from PySide6.QtGui import QGuiApplication
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QWidget
from waiting import eventually

GRACE_SECONDS = 5.0  # a thread or process that ends within this after the test was only finishing
QT_HELPERS = "QtWebEngineProc"  # the name the kernel keeps (15 characters) of QtWebEngineProcess

_started_threads = []  # QThreads started since the current test began
_kept_threads = []     # leaked ones: a running QThread whose Python object is freed aborts the process
_shared = []           # objects whose ``process`` (a Popen) belongs to a fixture that outlives tests

_original_start = QThread.start


def _start_tracked(thread, *args, **kwargs):
    _started_threads.append(thread)
    return _original_start(thread, *args, **kwargs)


QThread.start = _start_tracked


def shared_process(owner):
    """Mark ``owner.process`` (also after ``owner`` restarts it) as a long-lived fixture's; returns ``owner``."""
    _shared.append(owner)
    return owner


def _children() -> set:
    """(pid, start time, name) of every child process of this one that has not ended."""
    pids, found = set(), set()
    for children in Path(f"/proc/{os.getpid()}/task").glob("*/children"):
        try:
            pids.update(children.read_text().split())
        except OSError:
            continue  # the thread ended meanwhile
    for pid in pids:
        try:
            stat = Path(f"/proc/{pid}/stat").read_text()
        except OSError:
            continue  # it ended meanwhile
        name = stat[stat.index("(") + 1:stat.rindex(")")]
        state, _parent, *rest = stat[stat.rindex(")") + 2:].split()
        if state != "Z" and name != QT_HELPERS:  # a zombie has ended; its Popen has not asked yet
            found.add((int(pid), rest[17], name))
    return found


def _running(thread) -> bool:
    return shiboken6.isValid(thread) and thread.isRunning()


def _left_over(before: set) -> tuple:
    shared = {owner.process.pid for owner in _shared if owner.process is not None}
    threads = [thread for thread in _started_threads if _running(thread)]
    processes = {child for child in _children() - before if child[0] not in shared}
    return threads, processes


@pytest.fixture(autouse=True)
def nothing_left_running():
    """After the test (and its own fixtures' teardown): no QThread it started runs, no process it started lives."""
    before = _children()
    _started_threads.clear()
    yield
    try:
        eventually(lambda: not any(_left_over(before)), GRACE_SECONDS)
    except AssertionError:
        pass  # named below
    threads, processes = _left_over(before)
    _started_threads.clear()
    _kept_threads.extend(threads)
    for pid, _started, _name in processes:
        os.kill(pid, signal.SIGKILL)  # so that the tests after this one do not inherit it
    left = [f"a running QThread ({type(thread).__name__})" for thread in threads]
    left += [f"the process {pid} ({name})" for pid, _started, name in sorted(processes)]
    if left:
        pytest.fail("the test left " + ", ".join(left) + " behind", pytrace=False)


@pytest.fixture(autouse=True)
def no_mouse_button_held():
    """After the test: no mouse button is down in Qt's application-wide state. (QTest's mouseDClick presses
    a second time without a release; the windows of every later test would then take each focus change
    for a click, and the keyboard's focus ring would never show.) A button left down is released here."""
    yield
    held = QGuiApplication.mouseButtons() if QGuiApplication.instance() is not None else Qt.MouseButton.NoButton
    if held == Qt.MouseButton.NoButton:
        return
    QTest.mouseRelease(QWidget(), held)  # (any widget: Qt's state is the application's)
    pytest.fail(f"the test left a mouse button held down ({held.name}): a press without its release",
                pytrace=False)
