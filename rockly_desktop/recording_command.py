"""``rockly replay RECORDING`` and ``rockly recordings list``: recorded runs on the command line.

Their messages are in ``language`` (Rockly's catalogue): a file that cannot be read is said
on standard error (exit status 1), what reading left out of one as warnings after its timeline.
"""
import sys

from rockly_desktop.core.app_texts import app_text
from rockly_desktop.recording.library import recordings_in
from rockly_desktop.recording.reading import RecordingUnreadable, read_recording
from rockly_desktop.recording.timeline import timeline_lines


def replay(path, language: str = "en") -> int:
    """Print the timeline of the recording at ``path``; 1 when it cannot be read."""
    try:
        recording = read_recording(path)
    except RecordingUnreadable as error:
        print(f"rockly replay: {error.in_language(language)}", file=sys.stderr)
        return 1
    for line in timeline_lines(recording):
        print(line)
    for note in recording.notes():
        print(app_text("cli_warning", language, command="rockly replay", warning=note.in_language(language)),
              file=sys.stderr)
    return 0


def list_recordings(folder=None, language: str = "en") -> int:
    """Print the recordings in ``folder`` (default: the preferences' recordings folder), newest first;
    1 when the folder cannot be read."""
    if folder is None:
        from rockly_desktop.settings.app_settings import AppSettings

        folder = AppSettings().recordings_folder
    try:
        paths = recordings_in(folder)
    except OSError as error:
        print("rockly recordings list: " + app_text("recording_cannot_read", language, path=folder,
                                                     reason=error.strerror or error), file=sys.stderr)
        return 1
    for path in reversed(paths):
        try:
            size = f"{path.stat().st_size / 1024:9.1f} KiB"
        except OSError:  # gone meanwhile
            continue
        print(f"{size}  {path}")
    if not paths:
        print(app_text("recordings_none", language, folder=folder))
    return 0
