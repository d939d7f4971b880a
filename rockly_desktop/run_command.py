"""``rockly run PROGRAM``: run a program without a window, on the built-in simulator or ROS 1.

Prints one line per block it enters (id and type) and what the program prints; tablet
questions are answered from ``--answer`` options in the order they come. Ctrl+C stops
the program (with the robot's safe stop). Exit status: 0 finished, 1 error, 130 stopped.
"""
import os
import signal
import sys
import threading

from rockly_desktop.core.errors import RobotCommandError, RocklyError
from rockly_desktop.core.workspace_blocks import block_types_by_id
from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.events import BlockEntered, OutputPrinted, RunFinished
from rockly_desktop.executor.robot_link import RosRobot, SimulatedRobot
from rockly_desktop.executor.run_setup import make_runner

EXIT_STOPPED = 130


class AnswerList:
    """A tablet that answers from a list given on the command line.

    With ``then`` (another tablet: ``rockly sim``'s window), questions that come after the
    list has run out are passed on to it; without, they fail clearly.
    """

    def __init__(self, answers, out, then=None):
        self._answers = list(answers)
        self._out = out
        self._then = then
        self._lock = threading.Lock()  # ROS may ask two questions at once

    def ask(self, kind, text, timeout, interrupt) -> str:
        """Take the next answer (OK dialogs need none while answers are left); when none is
        left, ask ``then`` (OK dialogs included) or fail clearly."""
        self._out(f"tablet  {kind}: {text!r}")
        with self._lock:
            left = bool(self._answers)
            answer = self._answers.pop(0) if left and kind != "D_OK" else None
        if not left and self._then is not None:
            self._out("asking in the window")
            answer = self._then.ask(kind, text, timeout, interrupt)
        elif kind == "D_OK":
            return ""
        elif answer is None:
            raise RobotCommandError(f"the program asks on the tablet {text!r}, but no --answer is left for it")
        self._out(f"answer  {answer!r}")
        return answer

    def notify(self, kind, text):
        """Show a message or function on the terminal (and in the window, if there is one)."""
        self._out(f"tablet  {kind}: {text!r}")
        if self._then is not None:
            self._then.notify(kind, text)


def run_program(program_path, answers=(), speed: float = 1.0, language: str = "en", out=print,
                backend: str = "sim", master_uri: str = None) -> int:
    """Run ``program_path`` headless on its profile's simulator (or on ROS 1); returns the exit status."""
    from rockly_desktop.app import generate_headless
    from rockly_desktop.plugins.opening import opening_warnings

    try:
        program, _python, run_code, workspace = generate_headless(program_path, language)
    except RocklyError as error:
        print(f"rockly run: {error}", file=sys.stderr)
        return 1
    for warning in opening_warnings(program):
        print(f"rockly run: warning: {warning}", file=sys.stderr)
    types = block_types_by_id(workspace)
    try:
        if backend == "ros1":
            robot = RosRobot(program.profile, master_uri)
        else:
            robot = SimulatedRobot(program.profile, tablet=AnswerList(answers, out), speed=speed)
    except RocklyError as error:
        print(f"rockly run: {error}", file=sys.stderr)
        return 1
    control = RunControl(trace=True)

    def report(event):
        if isinstance(event, BlockEntered):
            out(f"block   {event.block_id}  {types.get(event.block_id, '?')}")
        elif isinstance(event, OutputPrinted):
            out(f"print   {event.text}")

    previous = signal.signal(signal.SIGINT, lambda *_: control.request_stop())
    try:
        result = make_runner(program.profile, robot, run_code, control, report, language).run()
    finally:
        signal.signal(signal.SIGINT, previous)
        robot.shutdown()
    return _report_end(result, types)


def _report_end(result: RunFinished, types: dict) -> int:
    if result.outcome == "finished":
        print("finished")
        return 0
    if result.outcome == "stopped":
        print("stopped (the robot was stopped safely)")
        return EXIT_STOPPED
    where = f"block {result.block_id} ({types.get(result.block_id, '?')})" if result.block_id else "the program"
    print(f"error in {where}: {result.message}", file=sys.stderr)
    return 1


def serve_simulator(profile_id: str, master_uri=None, speed: float = 1.0, answers=(),
                    out=lambda text: print(text, flush=True), window: bool = True) -> int:
    """``rockly sim PROFILE --ros``: the profile's simulator as a ROS node until its window is
    closed or Ctrl+C (exit 0). ``window=False``: no window, questions only from ``answers``."""
    from rockly_desktop.plugins.registry import ProfileRegistry

    registry = ProfileRegistry.discover()
    if profile_id not in registry.profiles:
        print(f"rockly sim: no robot profile '{profile_id}' (installed: {', '.join(registry.profiles)})", file=sys.stderr)
        return 2
    profile = registry.get(profile_id)
    if not window:
        return _serve_headless(profile, master_uri, speed, answers, out)
    if _no_display():
        print("rockly sim: there is no display to open the simulator's window on; "
              "use --no-window to run it without one", file=sys.stderr)
        return 2
    return _serve_with_window(profile, master_uri, speed, answers, out)


def _message_types(profile):
    from rockly_desktop.executor.robot_link import profile_message_folders
    from rockly_desktop.robot.ros1.messages import MessageTypes

    return MessageTypes(profile_message_folders(profile))


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


def _no_display() -> bool:
    """True on a Linux without X11 or Wayland, where Qt would abort instead of opening a window."""
    return (sys.platform.startswith("linux") and not os.environ.get("QT_QPA_PLATFORM")
            and not os.environ.get("DISPLAY") and not os.environ.get("WAYLAND_DISPLAY"))


def _serve_with_window(profile, master_uri, speed, answers, out) -> int:
    """The node's threads serve ROS; this (main) thread runs the window until it is closed."""
    from PySide6.QtCore import QTimer

    from rockly_desktop.app import create_application
    from rockly_desktop.robot.ros1.sim_bridge import SimulatorNode
    from rockly_desktop.ui.settings import AppSettings
    from rockly_desktop.ui.sim_window import SimulatorWindow

    app = create_application()
    window = SimulatorWindow(profile, AppSettings().language)
    try:
        node = SimulatorNode(profile, _message_types(profile), master_uri, speed, AnswerList(answers, out, then=window.tablet))
    except RocklyError as error:
        print(f"rockly sim: {error}", file=sys.stderr)
        return 1
    window.show_simulator(node.simulator, node.connection.master_uri)

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
