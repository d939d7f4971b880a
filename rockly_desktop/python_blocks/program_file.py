"""A ``.py`` program file turned into blocks in memory, for the robot it was written for: what ``rockly import``
writes, and what ``rockly run`` and ``rockly export`` run and export (nothing is written beside the file)."""
from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import ProgramFileError
from rockly_desktop.profiles.opening import ProgramToOpen, program_to_open
from rockly_desktop.python_blocks.convert import Conversion, python_to_program
from rockly_desktop.python_blocks.source import read_python_file
from rockly_desktop.python_blocks.templates import written_for

PYTHON_SUFFIX = ".py"


def is_python_program(path) -> bool:
    """True for a path whose name ends in ``.py`` (any case)."""
    return str(path).lower().endswith(PYTHON_SUFFIX)


def convert_python_file(path, registry, profile_id: str = None) -> Conversion:
    """Read and convert the Python program at ``path`` for ``profile_id`` (by default the robot its Rockly header
    names, else ``registry``'s default); ProgramFileError (catalogue texts) when it is no Python Rockly can convert
    or it was written for another robot, or for one that is not installed."""
    source = read_python_file(path)
    written = source.profile_id
    if written and profile_id and written != profile_id:
        raise ProgramFileError(path, app_local_text("import_other_robot", written=written, wanted=profile_id))
    wanted = profile_id or written
    if wanted and wanted not in registry.profiles:
        raise ProgramFileError(path, app_local_text("import_unknown_robot", written=wanted))
    profile = registry.get(wanted) if wanted else registry.default()
    other = None if written else written_for(source.tree, profile, registry.profiles.values())
    if other is not None:
        raise ProgramFileError(path, app_local_text("import_other_robot", written=other, wanted=profile.id))
    return python_to_program(source, profile)


def read_python_program_to_open(path, registry, profile_id: str = None) -> ProgramToOpen:
    """The Python program at ``path`` (for ``profile_id``, as ``convert_python_file`` chooses it) as blocks to
    generate and run, checked as a ``.rockly`` file is; its ``python_blocks`` name the lines that stayed Python.
    ProgramFileError as ``convert_python_file`` raises it."""
    conversion = convert_python_file(path, registry, profile_id)
    return program_to_open(path, conversion.program, registry, registry.default(),
                           [(part.first_line, part.last_line) for part in conversion.kept_python])
