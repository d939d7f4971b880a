"""Every run in the window is recorded: in the preferences' folder, the last N kept.

``open_run_recording`` opens the recording of the run about to start (its program is the
workspace on screen); a recording that cannot be opened (a full disk, a folder that
cannot be made) never keeps the program from running: the run goes on without one, and
the person is told, as when a full disk stops a recording during the run.
"""
import logging
from pathlib import Path

from rockly_desktop.core.program import Program
from rockly_desktop.core.workspace_blocks import block_types_by_id
from rockly_desktop.recording.library import keep_last, new_recording_path
from rockly_desktop.ui.texts import tr

log = logging.getLogger(__name__)


def open_run_recording(settings, document, workspace: dict, robot, say=lambda text: None):
    """A started ``RunRecording`` for a window run of ``document`` on ``robot``; None when the preferences
    keep no recordings, or it cannot be made. ``say(text)`` tells the person, in the window's language,
    that the run is not recorded, or (called from the recording's thread) that its recording stopped."""
    from rockly_desktop.executor.run_recording import RunRecording
    from rockly_desktop.recording.mcap_file import problem_text

    if settings.recordings_kept == 0:
        return None
    profile = document.profile
    name = Path(document.path).name if document.path else "Untitled.rockly"
    folder, language = settings.recordings_folder, settings.language
    path = folder

    def stopped(error):
        say(tr("recording_stopped", language, path=path, reason=problem_text(error, language)))

    try:
        keep_last(folder, settings.recordings_kept - 1)  # room for this one
        program = Program(profile.id, workspace or {}, list(document.breakpoints),
                          profile.packs_used(workspace)).to_json().encode("utf-8")
        path = new_recording_path(folder, name, robot.kind)
        return RunRecording(path, profile, robot, name, program, block_types_by_id(workspace or {}),
                            settings.recording_topic_rate, on_stopped=stopped)
    except OSError as error:
        log.warning("this run is not recorded: %s", error)
        say(tr("recording_not_started", language, path=path, reason=problem_text(error, language)))
        return None
