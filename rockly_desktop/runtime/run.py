"""Running generated code on a robot to its end, without the window: what ``rockly run`` and a
standalone export (``rockly export --standalone``) share.

The caller hands in what a program is once generated (the profile, the page's run code, the
block types by id) and the teacher's ``Limits`` in force; nothing here reads the window's settings,
so it runs where Qt is not installed. The robot's safe stop runs however the run ends: finished,
an error, Ctrl+C (SIGINT) or SIGTERM (a launch file or systemd ending it).

This process owns the robot link; the program's code runs in a process of its own
(``runtime/program_process.py``) that asks this one for every robot command, so the limits, the
recording and the safe stop stay out of the program's reach (``runtime/link_host.py``, decision 039).
"""
import signal
import sys

from rockly_desktop.core.app_texts import app_text
from rockly_desktop.core.errors import RocklyError
from rockly_desktop.executor.events import BlockEntered, OutputPrinted, RunFinished
from rockly_desktop.executor.run_setup import limited_backend, limits_line
from rockly_desktop.recording.mcap_file import disk_full, problem_text
from rockly_desktop.robot.links import open_link
from rockly_desktop.robot.sim.answer_list import AnswerList
from rockly_desktop.robot.wrappers.limits import Limits
from rockly_desktop.robot.wrappers.recorded import RecordedBackend
from rockly_desktop.robot.wrappers.ros_versions import link_backend
from rockly_desktop.runtime.link_host import HostControl, LinkHost, ProgramMirror, ProgramProcess
from rockly_desktop.runtime.stop_signals import StopOnSignals

EXIT_FINISHED, EXIT_ERROR = 0, 1


def failed(command: str, error: RocklyError, language: str) -> int:
    """Say ``error`` on standard error, after ``command``'s name; the exit status of a failed run."""
    print(f"{command}: {error.in_language(language)}", file=sys.stderr)
    return EXIT_ERROR


def exit_status_stopped(signum) -> int:
    """The exit status of a run a signal stopped: 128 + its number (130 Ctrl+C, 143 SIGTERM), as a shell says."""
    return 128 + int(signum)


class Run:
    """One run of ``run_code`` (the page's ``getRunCode`` answer) on ``profile``'s robot.

    ``types``: block id -> block type (what the lines and events name); ``command``: the name the
    lines on standard error start with; ``out``: where the program's lines go (its prints, the tablet's
    questions, the teacher's limits); ``end_out``: where the line saying how it ended goes (an error's goes to
    standard error); ``on_event``:
    every executor event as it happens (an event stream, see ``runtime.event_stream``); ``trace``:
    report every block entered (``rockly run`` prints them; an event stream needs them); ``process``: a
    ``ProgramProcess`` started for ``profile`` before (a warm one), else one is started as the link opens.
    """

    def __init__(self, profile, run_code: dict, types: dict, language: str = "en", command: str = "rockly run",
                 out=print, on_event=None, trace: bool = True, end_out=print, process: ProgramProcess = None):
        self.profile = profile
        self.run_code = run_code
        self.types = types
        self.language = language
        self.command = command
        self.out = out
        self.end_out = end_out
        self.on_event = on_event
        self.control = HostControl(trace=trace)
        self.runner = None  # the program's runner as this process sees it (a ProgramMirror), once it runs
        self.process = process
        self.host = None  # the LinkHost serving the program, while it runs
        self.stopped_by = signal.SIGINT

    def fail(self, error: RocklyError) -> int:
        """Say ``error`` on standard error; the exit status of a failed run."""
        return failed(self.command, error, self.language)

    def warn(self, warning: str):
        """Say ``warning`` on standard error."""
        print(app_text("cli_warning", self.language, command=self.command, warning=warning), file=sys.stderr)

    def run(self, backend: str, connection: dict = None, answers=(), speed: float = 1.0, limits: Limits = None,
            record=None, program_name: str = None, program_bytes: bytes = None, print_blocks: bool = True) -> int:
        """Open the ``backend`` link, run the program under ``limits`` and return the exit status
        (0 finished, 1 error, 128 + the signal's number when SIGINT or SIGTERM stopped it).

        ``record``: an MCAP file to record the run to (``program_name``, ``program_bytes``: what it keeps
        of the program); ``print_blocks``: a line on ``out`` for every block entered."""
        language = self.language
        process = self.process or ProgramProcess.start()  # it starts while the link opens
        process.prepare(self.profile)
        try:
            robot = open_link(backend, self.profile, connection,
                              tablet=AnswerList(answers, self.out, language=language), speed=speed)
        except RocklyError as error:
            process.close()
            return self.fail(error)
        for warning in robot.warnings():
            self.warn(app_text(f"ros_{warning.reason}", language, **warning.values))
        limits = limits or Limits()
        line = limits_line(self.profile, limits, language)
        if line:
            self.out(line)
        try:
            recording = self._recording(record, robot, program_name, program_bytes)
        except OSError as error:  # a path the person can mend: nothing has moved yet
            print(app_text("cli_cannot_record", language, command=self.command, path=record,
                           reason=problem_text(error, language)), file=sys.stderr)
            process.close()
            robot.shutdown()
            return EXIT_ERROR
        signals = StopOnSignals(self.control.request_stop)
        try:
            with signals:
                self.host = self._host(process, robot, limits, recording, print_blocks)
                result = self.host.serve(self.run_code)
        finally:
            self.stopped_by = signals.signum or signal.SIGINT
            if recording is not None:
                recording.close()
            robot.shutdown()
        if result is None:  # the profile's commands could not be made
            print(f"{self.command}: {self.host.refused}", file=sys.stderr)
            return EXIT_ERROR
        return self._report_end(result)

    def _host(self, process, robot, limits: Limits, recording, print_blocks: bool) -> LinkHost:
        """The link host for this run: the link's backend under the limits (and the recording), serving
        ``process``."""
        emit = self._reporter(print_blocks)
        if recording is not None:
            emit = _both(recording.emit, emit)
        limited = limited_backend(self.profile, link_backend(robot, self.control.interrupt), limits, self.language)
        backend = limited if recording is None else RecordedBackend(limited, recording.command)

        def note(text: str):  # what the limits tell the person, as the program's own output
            for line in str(text).splitlines() or [""]:
                emit(OutputPrinted(line))
        limited.note = note
        self.runner = ProgramMirror(None if recording is None else recording.recorder.blocks)
        if recording is not None:
            recording.follow(self.runner)
        return LinkHost(process, backend, robot, self.control, emit, self.language, self.runner,
                        on_safe_stop=None if recording is None else recording.safe_stop)

    def _reporter(self, print_blocks: bool):
        language, types, out, on_event = self.language, self.types, self.out, self.on_event

        def report(event):
            if isinstance(event, BlockEntered):
                if print_blocks:
                    out(app_text("cli_block", language, id=event.block_id, type=types.get(event.block_id, "?")))
            elif isinstance(event, OutputPrinted):
                out(app_text("cli_print", language, text=event.text))
            if on_event is not None:
                on_event(event)
        return report

    def _recording(self, record, robot, program_name, program_bytes):
        """The run's recording to ``record`` (None without one, or when the disk is full: said, and the
        program runs all the same); a write failing later is said once."""
        if record is None:
            return None
        from rockly_desktop.executor.run_to_mcap import RunRecording

        def stopped(error):
            self.warn(app_text("recording_stopped", self.language, path=record,
                               reason=problem_text(error, self.language)))

        try:
            return RunRecording(record, self.profile, robot, program_name, program_bytes, self.types,
                                on_stopped=stopped)
        except OSError as error:
            if not disk_full(error):
                raise
            self.warn(app_text("recording_not_started", self.language, path=record,
                               reason=problem_text(error, self.language)))
            return None

    def _report_end(self, result: RunFinished) -> int:
        language = self.language
        if result.outcome == "finished":
            self.end_out(app_text("cli_finished", language))
            return EXIT_FINISHED
        if result.outcome == "stopped":
            self.end_out(app_text("cli_stopped", language))
            return exit_status_stopped(self.stopped_by)
        if result.block_id:
            text = app_text("cli_error_in_block", language, id=result.block_id,
                            type=self.types.get(result.block_id, "?"), message=result.message)
        else:
            text = app_text("cli_error_in_program", language, message=result.message)
        print(text, file=sys.stderr)
        return EXIT_ERROR


def _both(first, second):
    def emit(event):
        first(event)
        second(event)
    return emit
