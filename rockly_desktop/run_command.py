"""``rockly run PROGRAM``: run a program without a window, on any robot link (``--backend``).

Prints one line per block it enters (id and type) and what the program prints; tablet
questions are answered from ``--answer`` options in the order they come. Ctrl+C stops
the program (with the robot's safe stop). Exit status: 0 finished, 1 error, 130 stopped.
"""
import signal
import sys

from rockly_desktop.core.errors import RocklyError
from rockly_desktop.core.workspace_blocks import block_types_by_id
from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.events import BlockEntered, OutputPrinted, RunFinished
from rockly_desktop.executor.run_setup import make_runner
from rockly_desktop.robot.answer_list import AnswerList
from rockly_desktop.robot.links import DEFAULT_KIND, open_link

EXIT_STOPPED = 130


def run_program(program_path, answers=(), speed: float = 1.0, language: str = "en", out=print,
                backend: str = DEFAULT_KIND, connection: dict = None, record=None) -> int:
    """Run ``program_path`` headless on its profile's robot over the ``backend`` kind of robot link
    (the built-in simulator by default; ``connection``: that link's settings); returns the exit status.

    ``record``: the MCAP file to record the run to (none without it)."""
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
        robot = open_link(backend, program.profile, connection, tablet=AnswerList(answers, out), speed=speed)
    except RocklyError as error:
        print(f"rockly run: {error}", file=sys.stderr)
        return 1
    for warning in robot.warnings():
        print(f"rockly run: warning: {warning}", file=sys.stderr)
    control = RunControl(trace=True)

    def report(event):
        if isinstance(event, BlockEntered):
            out(f"block   {event.block_id}  {types.get(event.block_id, '?')}")
        elif isinstance(event, OutputPrinted):
            out(f"print   {event.text}")

    try:
        recording = _recording(record, program_path, program.profile, robot, types)
    except OSError as error:
        print(f"rockly run: cannot record to {record}: {error.strerror or error}", file=sys.stderr)
        robot.shutdown()
        return 1
    previous = signal.signal(signal.SIGINT, lambda *_: control.request_stop())
    try:
        result = make_runner(program.profile, robot, run_code, control, report, language,
                             recording=recording).run()
    except RocklyError as error:  # the profile's commands could not be made
        print(f"rockly run: {error}", file=sys.stderr)
        return 1
    finally:
        signal.signal(signal.SIGINT, previous)
        if recording is not None:
            recording.close()
        robot.shutdown()
    return _report_end(result, types)


def _recording(record, program_path, profile, robot, types):
    if record is None:
        return None
    from pathlib import Path

    from rockly_desktop.executor.run_recording import RunRecording

    program_path = Path(program_path)
    program = program_path.read_bytes() if program_path.suffix == ".rockly" else None
    return RunRecording(record, profile, robot, program_path.name, program, types)


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
