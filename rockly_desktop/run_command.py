"""``rockly run PROGRAM``: run a program without a window, on any robot link (``--backend``).

Prints one line per block it enters (id and type) and what the program prints; tablet
questions are answered from ``--answer`` options in the order they come. Ctrl+C or SIGTERM stops
the program (with the robot's safe stop). Exit status: 0 finished, 1 error, 130 stopped by Ctrl+C,
143 by SIGTERM. Every line it prints is in ``language`` (Rockly's catalogue, keys ``cli_*``).
The teacher's limits and switched-off capabilities set in the window's Preferences hold
here too (a line says which); the toolbox level only filters the window's toolbox, so a
program with blocks beyond it runs, as it does in the window.

Generating the program's Python needs the editor page (Blockly in QtWebEngine) and the teacher's
limits are the window's settings: this module does both, then hands the run to the Qt-free
runtime (``runtime.run``), which a robot's computer has without the window.
"""
from pathlib import Path

from rockly_desktop.core.errors import RocklyError
from rockly_desktop.core.program import Program
from rockly_desktop.core.workspace_blocks import block_types_by_id
from rockly_desktop.robot.links import DEFAULT_KIND
from rockly_desktop.runtime.link_host import ProgramProcess
from rockly_desktop.runtime.robot_limits import default_path as default_limits_path
from rockly_desktop.runtime.run import Run, failed

COMMAND = "rockly run"


def run_program(program_path, answers=(), speed: float = 1.0, language: str = "en", out=print,
                backend: str = DEFAULT_KIND, connection: dict = None, record=None, teacher=None,
                python_profile: str = None) -> int:
    """Run ``program_path`` headless on its profile's robot over the ``backend`` kind of robot link
    (the built-in simulator by default; ``connection``: that link's settings); returns the exit status.

    ``record``: the MCAP file to record the run to (none without it); ``teacher`` (TeacherSettings)
    gives the limits the run keeps, by default the window's. A ``.py`` program is turned into blocks in memory
    first, for ``python_profile`` (by default the robot its header names), and runs as those blocks."""
    from rockly_desktop.app import generate_headless
    from rockly_desktop.profiles.opening import opening_warnings

    # the program's own process starts while the page generates its code; the teacher's settings (its limits)
    # and the robot's own limits are out of its reach
    process = ProgramProcess.start(hidden=[settings_folder(), default_limits_path().parent])
    try:
        try:
            program, _python, run_code, workspace = generate_headless(program_path, language, python_profile)
        except RocklyError as error:
            return failed(COMMAND, error, language)
        run = Run(program.profile, run_code, block_types_by_id(workspace), language, COMMAND, out=out,
                  process=process)
        for warning in opening_warnings(program, language):
            run.warn(warning)
        program_path = Path(program_path)
        kept = recorded_program(program_path, program) if record is not None else None
        return run.run(backend, connection, answers, speed, teacher_limits(program.profile.id, teacher), record,
                       program_path.name, kept)
    finally:
        process.close()


def recorded_program(program_path: Path, program) -> bytes:
    """What a recording keeps of the program it ran, to show its blocks at replay: a ``.rockly`` file's bytes, the
    blocks a ``.py`` became as a ``.rockly`` document (``program``: its ProgramToOpen), nothing for an ``.xml``."""
    if program_path.suffix == ".rockly":
        return program_path.read_bytes()
    if program.workspace is None:
        return None
    profile = program.profile
    return Program(profile.id, program.workspace, packs=profile.packs_used(program.workspace)).to_json().encode()


def settings_folder() -> Path:
    """The folder of the window's settings file (the teacher's limits among them)."""
    from rockly_desktop.settings.app_settings import AppSettings

    return AppSettings().folder


def teacher_limits(profile_id: str, teacher=None):
    """The teacher's limits for ``profile_id``: from ``teacher`` (TeacherSettings), by default the window's
    (the same settings file)."""
    if teacher is None:
        from rockly_desktop.settings.app_settings import AppSettings

        teacher = AppSettings().teacher
    return teacher.limits(profile_id)
