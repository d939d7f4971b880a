"""The recordings folder: a new recording's name (date, program, robot), the last N kept, the list."""
import datetime
import re
from pathlib import Path

from rockly_desktop.recording.mcap_file import held

SUFFIX = ".mcap"
_UNSAFE = re.compile(r"[^\w.-]+")
_NAMED = re.compile(r"^\d{4}-\d{2}-\d{2}_\d{2}-\d{2}-\d{2}(-\d+)?_.+\.mcap$")


def _part(text: str) -> str:
    return _UNSAFE.sub("-", str(text)).strip("-.") or "untitled"


def new_recording_path(folder, program: str, robot: str, now=None) -> Path:
    """A free path in ``folder`` (created) named ``YYYY-MM-DD_HH-MM-SS_program_robot.mcap``."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    stamp = (now or datetime.datetime.now()).strftime("%Y-%m-%d_%H-%M-%S")
    name = f"{_part(Path(program).stem)}_{_part(robot)}"
    path, number = folder / f"{stamp}_{name}{SUFFIX}", 1
    while path.exists():
        number += 1
        path = folder / f"{stamp}-{number}_{name}{SUFFIX}"
    return path


def recordings_in(folder) -> list:
    """The recordings Rockly named in ``folder``, oldest first."""
    folder = Path(folder)
    if not folder.is_dir():
        return []
    return sorted(path for path in folder.iterdir() if path.is_file() and _NAMED.match(path.name))


def keep_last(folder, count: int) -> list:
    """Delete all but the newest ``count`` recordings Rockly named in ``folder``, but for those a run is
    recording to now (another window's); returns the deleted paths."""
    old = recordings_in(folder)[:-count] if count > 0 else recordings_in(folder)
    old = [path for path in old if not held(path)]
    for path in old:
        path.unlink(missing_ok=True)
    return old
