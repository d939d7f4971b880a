"""``rockly sim PROFILE --ros``: a profile's simulated robot served on a robot link's middleware.

Which option serves on what (``--ros``: a ROS 1 node, ``--ros2``: ROS 2 through its helper) is the
robot-link registry's (``robot/links.py``).

By default a small window shows the robot and asks its tablet questions beyond ``--answer``;
``--no-window`` runs it headless. Closing the window, Ctrl+C or SIGTERM ends the node (exit 0).
"""
import os
import signal
import sys
import time

from rockly_desktop.core.errors import RocklyError
from rockly_desktop.robot import links
from rockly_desktop.robot.sim.answer_list import AnswerList


def serve_simulator(profile_id: str, kind: str, connection: dict = None, speed: float = 1.0, answers=(),
                    out=lambda text: print(text, flush=True), window: bool = True) -> int:
    """``rockly sim PROFILE --ros``: the profile's simulator served on the ``kind`` of robot link (with
    its ``connection`` settings) until its window is closed or Ctrl+C (exit 0). ``window=False``: no
    window, questions only from ``answers``."""
    from rockly_desktop.profiles.registry import ProfileRegistry

    registry = ProfileRegistry.discover()
    if profile_id not in registry.profiles:
        print(f"rockly sim: no robot profile '{profile_id}' (installed: {', '.join(registry.profiles)})",
              file=sys.stderr)
        return 2
    profile = registry.get(profile_id)
    if not window:
        return _serve_headless(profile, kind, connection, speed, answers, out)
    if _no_display():
        print("rockly sim: there is no display to open the simulator's window on; "
              "use --no-window to run it without one", file=sys.stderr)
        return 2
    return _serve_with_window(profile, kind, connection, speed, answers, out)


def _serve_headless(profile, kind, connection, speed, answers, out) -> int:
    # The handler only notes the signal: one that takes a lock (an Event's set()) can interrupt the
    # main thread holding that lock, or a second signal interrupt the first handler inside it, and
    # then waits for itself forever (SIGTERM followed by Ctrl+C did).
    signalled = []
    previous = signal.signal(signal.SIGINT, lambda *_: signalled.append(True))
    previous_term = signal.signal(signal.SIGTERM, lambda *_: signalled.append(True))
    try:
        server = links.serve_simulator(kind, profile, connection, speed, AnswerList(answers, out))
        try:
            out(f"simulated {profile.display_name()} is up on ROS (Ctrl+C ends it)")
            while not signalled:
                time.sleep(0.2)  # seen within 0.2 s
        finally:
            server.shutdown()
    except RocklyError as error:
        print(f"rockly sim: {error}", file=sys.stderr)
        return 1
    finally:
        signal.signal(signal.SIGINT, previous)
        signal.signal(signal.SIGTERM, previous_term)
    return 0


def _no_display() -> bool:
    """True on a Linux without X11 or Wayland, where Qt would abort instead of opening a window."""
    return (sys.platform.startswith("linux") and not os.environ.get("QT_QPA_PLATFORM")
            and not os.environ.get("DISPLAY") and not os.environ.get("WAYLAND_DISPLAY"))


def _serve_with_window(profile, kind, connection, speed, answers, out) -> int:
    """The node's threads serve ROS; this (main) thread runs the window until it is closed."""
    from PySide6.QtCore import QTimer

    from rockly_desktop.app import create_application
    from rockly_desktop.settings.app_settings import AppSettings
    from rockly_desktop.ui.docks.sim_window import SimulatorWindow

    app = create_application()
    window = SimulatorWindow(profile, AppSettings().language)
    try:
        node = links.serve_simulator(kind, profile, connection, speed, AnswerList(answers, out, then=window.tablet))
    except RocklyError as error:
        print(f"rockly sim: {error}", file=sys.stderr)
        return 1
    window.show_simulator(node.simulator, node.where)

    def end():
        # Before Qt quits (which closes every window, open tablet dialogs too): a question
        # still waiting then ends as "shut down", not as closed by the person.
        node.shutdown()
        app.quit()

    window.sig_closed.connect(end)
    # Ctrl+C and SIGTERM close the window; the timer lets Python see signals while Qt waits.
    previous = signal.signal(signal.SIGINT, lambda *_: window.close())
    previous_term = signal.signal(signal.SIGTERM, lambda *_: window.close())
    wake = QTimer()
    wake.timeout.connect(lambda: None)
    wake.start(200)
    try:
        window.show()
        out(f"simulated {profile.display_name()} is up on ROS (close its window or press Ctrl+C to end it)")
        app.exec()
    finally:
        wake.stop()
        signal.signal(signal.SIGINT, previous)
        signal.signal(signal.SIGTERM, previous_term)
        node.shutdown()
    return 0
