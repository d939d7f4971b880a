"""A run whose program is in a process of its own, as a runner: what the window's program thread runs.

The window owns the robot link; the program's code runs in a child (``runtime/program_process.py``) without
the link, the limits or the network (decision 041, following 039). ``HostedRunner`` offers what a
``ProgramRunner`` offers the window (``run()``, ``hooks.current_block``, ``variables_snapshot()``,
``values_snapshot()``), so the window's 33 ms poll, highlighting, badges, values and recording follow it as
they follow a runner in the window's process; its ``run()`` serves the child on the link (``LinkHost.serve``).

``WarmProcess`` keeps a program's process started and made ready for the profile, so Run → first block does
not wait for a Python start and Rockly's imports.
"""
from rockly_desktop.executor.events import OutputPrinted, RunFinished
from rockly_desktop.executor.run_setup import limited_backend
from rockly_desktop.robot.wrappers.limits import Limits
from rockly_desktop.robot.wrappers.recorded import RecordedBackend
from rockly_desktop.robot.wrappers.ros_versions import link_backend
from rockly_desktop.runtime.link_host import LinkHost, ProgramMirror, ProgramProcess


class HostedRunner:
    """One run of ``run_code`` served by ``host`` (a ``LinkHost``); the program's state as ``mirror`` says it."""

    def __init__(self, host: LinkHost, run_code: dict, mirror: ProgramMirror, emit, language: str):
        self.host = host
        self.run_code = run_code
        self.mirror = mirror
        self.hooks = mirror.hooks
        self._emit = emit
        self._language = language

    def run(self) -> RunFinished:
        """Serve the program until it ends (the robot's safe stop done); how it ended, as its last event said."""
        result = self.host.serve(self.run_code)
        if result is None:  # the profile's commands could not be made in the program's process
            result = RunFinished("error", None, self.host.refused)
            self._emit(result)
        return result

    def variables_snapshot(self) -> dict:
        """The program's variables, as its process last said them."""
        return self.mirror.variables_snapshot()

    def values_snapshot(self) -> dict:
        """The expression blocks' last values, as the program's process last said them."""
        return self.mirror.values_snapshot()


def hosted_runner(process: ProgramProcess, profile, robot, run_code: dict, control, emit, language: str = "en",
                  limits: Limits = None, recording=None, notes=None) -> HostedRunner:
    """A run of the page's ``getRunCode`` answer in ``process`` on ``robot``, as ``make_runner`` makes one in this
    process: the profile's commands through the teacher's ``limits``, the ``recording`` (a ``RunRecording``) and
    ``notes(entry)`` (the block maker's "Try it") here, below the program; ``control``: a ``HostControl``. The
    robot's safe stop runs however the run ends, the process's death (a crash, SIGKILL) included."""
    limited = limited_backend(profile, link_backend(robot, control.interrupt), limits or Limits(), language)
    backend = limited if recording is None else RecordedBackend(limited, recording.command)
    if notes is not None:
        backend = RecordedBackend(backend, notes)
    if recording is not None:
        emit = _both(recording.emit, emit)

    def note(text: str):  # what the limits tell the person, as the program's own output
        for line in str(text).splitlines() or [""]:
            emit(OutputPrinted(line))
    limited.note = note
    mirror = ProgramMirror(None if recording is None else recording.recorder.blocks)
    process.prepare(profile)
    if recording is not None:
        recording.follow(mirror)
    host = LinkHost(process, backend, robot, control, emit, language, mirror,
                    on_safe_stop=None if recording is None else recording.safe_stop)
    return HostedRunner(host, run_code, mirror, emit, language)


class WarmProcess:
    """A program's process kept started for the next run, made ready for its profile; the program never sees
    the ``hidden`` folders (the window's settings with the teacher's limits, the robot's limits)."""

    def __init__(self, hidden=()):
        self.hidden = tuple(hidden)
        self._process = None

    def warm(self, profile):
        """Start a process for ``profile`` now, unless one is waiting for it already (a finished run's is not)."""
        waiting = self._process
        if waiting is not None and waiting.process.poll() is None and _same(waiting.profile, profile):
            return
        self.close()
        self._process = ProgramProcess.start(profile, self.hidden)

    def take(self, profile) -> ProgramProcess:
        """The process for ``profile``'s next run: the waiting one, or one started now."""
        self.warm(profile)
        process, self._process = self._process, None
        return process

    def close(self):
        """End the waiting process, if any (it runs nothing yet: killed, not waited for while it imports)."""
        waiting, self._process = self._process, None
        if waiting is not None:
            waiting.kill()
            waiting.close()


def _same(prepared, profile) -> bool:
    return prepared is not None and prepared.command_side() == profile.command_side()


def _both(first, second):
    def emit(event):
        first(event)
        second(event)
    return emit
