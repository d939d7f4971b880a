"""``rockly run PROGRAM``: run a program without a window, on any robot link (``--backend``).

Prints one line per block it enters (id and type) and what the program prints; tablet
questions are answered from ``--answer`` options in the order they come. Ctrl+C stops
the program (with the robot's safe stop). Exit status: 0 finished, 1 error, 130 stopped.
Every line it prints is in ``language`` (Rockly's catalogue, keys ``cli_*``).
The teacher's limits and switched-off capabilities set in the window's Preferences hold
here too (a line says which); the toolbox level only filters the window's toolbox, so a
program with blocks beyond it runs, as it does in the window.
"""
import signal
import sys

from rockly_desktop.core.app_texts import app_text
from rockly_desktop.core.errors import RocklyError
from rockly_desktop.core.workspace_blocks import block_types_by_id
from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.events import BlockEntered, OutputPrinted, RunFinished
from rockly_desktop.executor.run_setup import limits_line, make_runner
from rockly_desktop.recording.mcap_file import disk_full, problem_text
from rockly_desktop.robot.links import DEFAULT_KIND, open_link
from rockly_desktop.robot.sim.answer_list import AnswerList

EXIT_STOPPED = 130


def run_program(program_path, answers=(), speed: float = 1.0, language: str = "en", out=print,
                backend: str = DEFAULT_KIND, connection: dict = None, record=None, teacher=None) -> int:
    """Run ``program_path`` headless on its profile's robot over the ``backend`` kind of robot link
    (the built-in simulator by default; ``connection``: that link's settings); returns the exit status.

    ``record``: the MCAP file to record the run to (none without it); ``teacher`` (TeacherSettings)
    gives the limits the run keeps, by default the window's."""
    from rockly_desktop.app import generate_headless
    from rockly_desktop.profiles.opening import opening_warnings

    def fail(error):
        print(f"rockly run: {error.in_language(language)}", file=sys.stderr)
        return 1

    try:
        program, _python, run_code, workspace = generate_headless(program_path, language)
    except RocklyError as error:
        return fail(error)
    for warning in opening_warnings(program, language):
        print(app_text("cli_warning", language, command="rockly run", warning=warning), file=sys.stderr)
    types = block_types_by_id(workspace)
    try:
        robot = open_link(backend, program.profile, connection,
                          tablet=AnswerList(answers, out, language=language), speed=speed)
    except RocklyError as error:
        return fail(error)
    for warning in robot.warnings():
        print(app_text("cli_warning", language, command="rockly run",
                       warning=app_text(f"ros_{warning.reason}", language, **warning.values)), file=sys.stderr)
    limits = _teacher(teacher).limits(program.profile.id)
    line = limits_line(program.profile, limits, language)
    if line:
        out(line)
    control = RunControl(trace=True)

    def report(event):
        if isinstance(event, BlockEntered):
            out(app_text("cli_block", language, id=event.block_id, type=types.get(event.block_id, "?")))
        elif isinstance(event, OutputPrinted):
            out(app_text("cli_print", language, text=event.text))

    try:
        recording = _recording(record, program_path, program.profile, robot, types, language)
    except OSError as error:
        if not disk_full(error):  # a path the person can mend: nothing has moved yet
            print(app_text("cli_cannot_record", language, command="rockly run", path=record,
                           reason=problem_text(error, language)), file=sys.stderr)
            robot.shutdown()
            return 1
        recording = None  # a full disk never keeps the program from running
        print(app_text("cli_warning", language, command="rockly run", warning=app_text(
            "recording_not_started", language, path=record, reason=problem_text(error, language))), file=sys.stderr)
    previous = signal.signal(signal.SIGINT, _once(control.request_stop))
    try:
        result = make_runner(program.profile, robot, run_code, control, report, language, limits,
                             recording=recording).run()
    except RocklyError as error:  # the profile's commands could not be made
        return fail(error)
    finally:
        signal.signal(signal.SIGINT, previous)
        if recording is not None:
            recording.close()
        robot.shutdown()
    return _report_end(result, types, language)


def _once(stop):
    """A signal handler calling ``stop()`` for the first signal only: a second Ctrl+C interrupting the
    first inside ``stop()`` would wait forever for the lock the first one holds."""
    stopping = []

    def handler(*_):
        if not stopping:
            stopping.append(True)
            stop()
    return handler


def _recording(record, program_path, profile, robot, types, language):
    """The run's recording to ``record`` (None without one); a write failing later is said once."""
    if record is None:
        return None
    from pathlib import Path

    from rockly_desktop.executor.run_to_mcap import RunRecording

    def stopped(error):
        print(app_text("cli_warning", language, command="rockly run", warning=app_text(
            "recording_stopped", language, path=record, reason=problem_text(error, language))), file=sys.stderr)

    program_path = Path(program_path)
    program = program_path.read_bytes() if program_path.suffix == ".rockly" else None
    return RunRecording(record, profile, robot, program_path.name, program, types, on_stopped=stopped)


def _teacher(teacher):
    """``teacher``, or the teacher's settings the window keeps (the same QSettings file)."""
    if teacher is not None:
        return teacher
    from rockly_desktop.settings.app_settings import AppSettings

    return AppSettings().teacher


def _report_end(result: RunFinished, types: dict, language: str) -> int:
    if result.outcome == "finished":
        print(app_text("cli_finished", language))
        return 0
    if result.outcome == "stopped":
        print(app_text("cli_stopped", language))
        return EXIT_STOPPED
    if result.block_id:
        text = app_text("cli_error_in_block", language, id=result.block_id, type=types.get(result.block_id, "?"),
                        message=result.message)
    else:
        text = app_text("cli_error_in_program", language, message=result.message)
    print(text, file=sys.stderr)
    return 1
