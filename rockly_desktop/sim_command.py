"""``rockly sim PROFILE --ros``: a profile's simulated robot served as a ROS 1 node
(``ros2=Ros2Settings(...)``: on ROS 2, through the ROS 2 helper process).

By default a small window shows the robot and asks its tablet questions beyond ``--answer``;
``--no-window`` runs it headless. Closing the window, Ctrl+C or SIGTERM ends the node (exit 0).
"""
import os
import signal
import sys
import threading

from rockly_desktop.core.errors import RocklyError
from rockly_desktop.robot.answer_list import AnswerList


def serve_simulator(profile_id: str, master_uri=None, speed: float = 1.0, answers=(),
                    out=lambda text: print(text, flush=True), window: bool = True, ros2=None) -> int:
    """``rockly sim PROFILE --ros``: the profile's simulator as a ROS node until its window is
    closed or Ctrl+C (exit 0). ``window=False``: no window, questions only from ``answers``.
    ``ros2`` (Ros2Settings: domain id, discovery range) serves it on ROS 2 instead of ROS 1."""
    from rockly_desktop.profiles.registry import ProfileRegistry

    registry = ProfileRegistry.discover()
    if profile_id not in registry.profiles:
        print(f"rockly sim: no robot profile '{profile_id}' (installed: {', '.join(registry.profiles)})",
              file=sys.stderr)
        return 2
    profile = registry.get(profile_id)
    if not window:
        if ros2 is not None:
            return _serve_headless_ros2(profile, ros2, speed, answers, out)
        return _serve_headless(profile, master_uri, speed, answers, out)
    if _no_display():
        print("rockly sim: there is no display to open the simulator's window on; "
              "use --no-window to run it without one", file=sys.stderr)
        return 2
    return _serve_with_window(profile, master_uri, speed, answers, out, ros2)


def _message_types(profile):
    from rockly_desktop.robot.ros1.message_classes import MessageTypes

    return MessageTypes(profile.message_folders)


def _serve_headless(profile, master_uri, speed, answers, out) -> int:
    from rockly_desktop.robot.ros1.sim_bridge import run_simulator_node

    stop = threading.Event()
    previous = signal.signal(signal.SIGINT, lambda *_: stop.set())
    previous_term = signal.signal(signal.SIGTERM, lambda *_: stop.set())
    try:
        run_simulator_node(profile, _message_types(profile), master_uri, speed, AnswerList(answers, out), stop,
                           on_ready=lambda: out(f"simulated {profile.display_name()} is up on ROS (Ctrl+C ends it)"))
    except RocklyError as error:
        print(f"rockly sim: {error}", file=sys.stderr)
        return 1
    finally:
        signal.signal(signal.SIGINT, previous)
        signal.signal(signal.SIGTERM, previous_term)
    return 0


def _serve_headless_ros2(profile, settings, speed, answers, out) -> int:
    from rockly_desktop.robot.ros2.sim_bridge import run_ros2_simulator_node

    stop = threading.Event()
    previous = signal.signal(signal.SIGINT, lambda *_: stop.set())
    previous_term = signal.signal(signal.SIGTERM, lambda *_: stop.set())

    def ready(node):
        for name, type_name, why in node.left_out:
            out(f"not on ROS 2: {name} ({type_name}): {why}")
        out(f"simulated {profile.display_name()} is up on {node.where} (Ctrl+C ends it)")

    try:
        run_ros2_simulator_node(profile, settings, speed, AnswerList(answers, out), stop, on_ready=ready)
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


def _serve_with_window(profile, master_uri, speed, answers, out, ros2=None) -> int:
    """The node's threads serve ROS; this (main) thread runs the window until it is closed."""
    from PySide6.QtCore import QTimer

    from rockly_desktop.app import create_application
    from rockly_desktop.robot.ros1.sim_bridge import SimulatorNode
    from rockly_desktop.ui.settings import AppSettings
    from rockly_desktop.ui.sim_window import SimulatorWindow

    app = create_application()
    window = SimulatorWindow(profile, AppSettings().language)
    try:
        if ros2 is not None:
            from rockly_desktop.robot.ros2.sim_bridge import Ros2SimulatorNode

            node = Ros2SimulatorNode(profile, ros2, speed, AnswerList(answers, out, then=window.tablet))
        else:
            node = SimulatorNode(profile, _message_types(profile), master_uri, speed,
                                 AnswerList(answers, out, then=window.tablet))
    except RocklyError as error:
        print(f"rockly sim: {error}", file=sys.stderr)
        return 1
    window.show_simulator(node.simulator, node.where if ros2 is not None else node.connection.master_uri)

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
