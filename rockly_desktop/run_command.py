"""``rockly run PROGRAM``: run a program without a window, on the built-in simulator or ROS 1.

Prints one line per block it enters (id and type) and what the program prints; tablet
questions are answered from ``--answer`` options in the order they come. Ctrl+C stops
the program (with the robot's safe stop). Exit status: 0 finished, 1 error, 130 stopped.
"""
import signal
import sys

from rockly_desktop.core.errors import RobotCommandError, RocklyError
from rockly_desktop.core.workspace_blocks import block_types_by_id
from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.events import BlockEntered, OutputPrinted, RunFinished
from rockly_desktop.executor.robot_link import RosRobot, SimulatedRobot
from rockly_desktop.executor.run_setup import make_runner

EXIT_STOPPED = 130


class AnswerList:
    """A tablet that answers from a list given on the command line."""

    def __init__(self, answers, out):
        self._answers = list(answers)
        self._out = out

    def ask(self, kind, text, timeout, interrupt) -> str:
        """Take the next answer (OK dialogs need none); fail clearly when none is left."""
        self._out(f"tablet  {kind}: {text!r}")
        if kind == "D_OK":
            return ""
        if not self._answers:
            raise RobotCommandError(f"the program asks on the tablet {text!r}, but no --answer is left for it")
        answer = self._answers.pop(0)
        self._out(f"answer  {answer!r}")
        return answer

    def notify(self, kind, text):
        """Show a message or function on the terminal."""
        self._out(f"tablet  {kind}: {text!r}")


def run_program(program_path, answers=(), speed: float = 1.0, language: str = "en", out=print,
                backend: str = "sim", master_uri: str = None) -> int:
    """Run ``program_path`` headless on its profile's simulator (or on ROS 1); returns the exit status."""
    from rockly_desktop.app import generate_headless

    try:
        program, _python, run_code, workspace = generate_headless(program_path, language)
    except RocklyError as error:
        print(f"rockly run: {error}", file=sys.stderr)
        return 1
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
        result = make_runner(program.profile, robot, run_code, control, report).run()
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
                    out=lambda text: print(text, flush=True)) -> int:
    """``rockly sim PROFILE --ros``: the profile's simulator as a ROS node until Ctrl+C (exit 0)."""
    import threading

    from rockly_desktop.plugins.registry import ProfileRegistry
    from rockly_desktop.robot.ros1.messages import MessageTypes
    from rockly_desktop.robot.ros1.sim_bridge import run_simulator_node
    from rockly_desktop.executor.robot_link import profile_message_folders

    registry = ProfileRegistry.discover()
    if profile_id not in registry.profiles:
        print(f"rockly sim: no robot profile '{profile_id}' (installed: {', '.join(registry.profiles)})", file=sys.stderr)
        return 2
    profile = registry.get(profile_id)
    stop = threading.Event()
    previous = signal.signal(signal.SIGINT, lambda *_: stop.set())
    previous_term = signal.signal(signal.SIGTERM, lambda *_: stop.set())
    try:
        types = MessageTypes(profile_message_folders(profile))
        run_simulator_node(profile, types, master_uri, speed, AnswerList(answers, out), stop,
                           on_ready=lambda: out(f"simulated {profile.display_name()} is up on ROS (Ctrl+C ends it)"))
    except RocklyError as error:
        print(f"rockly sim: {error}", file=sys.stderr)
        return 1
    finally:
        signal.signal(signal.SIGINT, previous)
        signal.signal(signal.SIGTERM, previous_term)
    return 0
