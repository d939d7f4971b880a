"""``rockly replay RECORDING`` and ``rockly recordings list``: recorded runs on the command line."""
import sys

from rockly_desktop.recording.library import recordings_in
from rockly_desktop.recording.reading import RecordingUnreadable, read_recording
from rockly_desktop.recording.timeline import timeline_lines


def replay(path) -> int:
    """Print the timeline of the recording at ``path``; 1 when it cannot be read."""
    try:
        recording = read_recording(path)
    except RecordingUnreadable as error:
        print(f"rockly replay: {error}", file=sys.stderr)
        return 1
    for line in timeline_lines(recording):
        print(line)
    return 0


def list_recordings(folder=None) -> int:
    """Print the recordings in ``folder`` (default: the preferences' recordings folder), newest first."""
    if folder is None:
        from rockly_desktop.ui.settings import AppSettings

        folder = AppSettings().recordings_folder
    paths = recordings_in(folder)
    for path in reversed(paths):
        print(f"{path.stat().st_size / 1024:9.1f} KiB  {path}")
    if not paths:
        print(f"No recordings in {folder}.")
    return 0
