"""``rockly run PROGRAM``: run a program without a window, on the built-in simulator or ROS 1.

Prints one line per block it enters (id and type) and what the program prints; tablet
questions are answered from ``--answer`` options in the order they come. Ctrl+C stops
the program (with the robot's safe stop). Exit status: 0 finished, 1 error, 130 stopped.
The teacher's limits and switched-off capabilities set in the window's Preferences hold
here too (a line says which); the toolbox level only filters the window's toolbox, so a
program with blocks beyond it runs, as it does in the window.
"""
import signal
import sys

from rockly_desktop.core.errors import RocklyError
from rockly_desktop.core.workspace_blocks import block_types_by_id
from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.events import BlockEntered, OutputPrinted, RunFinished
from rockly_desktop.executor.robot_link import RosRobot, SimulatedRobot
from rockly_desktop.executor.run_setup import limits_line, make_runner
from rockly_desktop.robot.answer_list import AnswerList

EXIT_STOPPED = 130


def run_program(program_path, answers=(), speed: float = 1.0, language: str = "en", out=print,
                backend: str = "sim", master_uri: str = None, teacher=None) -> int:
    """Run ``program_path`` headless on its profile's simulator (or on ROS 1); returns the exit status.

    ``teacher`` (TeacherSettings) gives the limits the run keeps; by default the window's.
    """
    from rockly_desktop.app import generate_headless
    from rockly_desktop.profiles.opening import opening_warnings

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
    connection = getattr(robot, "connection", None)
    if connection is not None and connection.address_problem:
        from rockly_desktop.robot.ros1.connection import address_problem_text

        print(f"rockly run: warning: {address_problem_text(connection.address_problem)}", file=sys.stderr)
    limits = _teacher(teacher).limits(program.profile.id)
    line = limits_line(program.profile, limits, language)
    if line:
        out(line)
    control = RunControl(trace=True)

    def report(event):
        if isinstance(event, BlockEntered):
            out(f"block   {event.block_id}  {types.get(event.block_id, '?')}")
        elif isinstance(event, OutputPrinted):
            out(f"print   {event.text}")

    previous = signal.signal(signal.SIGINT, lambda *_: control.request_stop())
    try:
        result = make_runner(program.profile, robot, run_code, control, report, language, limits).run()
    except RocklyError as error:  # the profile's commands could not be made
        print(f"rockly run: {error}", file=sys.stderr)
        return 1
    finally:
        signal.signal(signal.SIGINT, previous)
        robot.shutdown()
    return _report_end(result, types)


def _teacher(teacher):
    """``teacher``, or the teacher's settings the window keeps (the same QSettings file)."""
    if teacher is not None:
        return teacher
    from rockly_desktop.ui.settings import AppSettings

    return AppSettings().teacher


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
