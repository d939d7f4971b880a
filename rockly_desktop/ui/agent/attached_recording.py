"""What the window saw of a run on the robot, recorded as a run in the window is (``ui/run/run_recordings``): the
same MCAP file, channels and folder, so the replay bar shows it once the window detaches or the run ends.

The window sees the run's events, not the robot's topics: the recording holds the blocks entered, the variables,
what was printed, the pauses and the end, from the moment of attaching (the run so far starts it: the block it
was at, its variables and the lines printed before).
"""
import datetime
import logging
import time
from pathlib import Path

from rockly_desktop import __version__
from rockly_desktop.core.program import Program
from rockly_desktop.core.workspace_blocks import block_types_by_id
from rockly_desktop.recording import channels
from rockly_desktop.recording.library import keep_last, new_recording_path
from rockly_desktop.recording.recorder import Recorder
from rockly_desktop.ui.texts import tr

log = logging.getLogger(__name__)

ROBOT = "agent"  # the recording's robot kind: a run on the robot under its agent


class AttachedRecording:
    """Records the run ``snapshot`` (the agent's state of the run when the window attached) to ``path``;
    ``program``: the ``.rockly`` bytes of the window's program, ``block_types``: block id -> type. Raises
    OSError when it cannot be begun; ``on_stopped(error)`` is called once if a write fails later (a full disk)."""

    def __init__(self, path, snapshot: dict, program: bytes, block_types: dict, on_stopped=None):
        self.path = path
        self._block_types = block_types
        self._now = time.time_ns()  # the run so far is written as one moment, the first of the timeline
        self.recorder = Recorder(path, clock=lambda: self._now or time.time_ns(), on_stopped=on_stopped)
        self.recorder.start({"program": snapshot["program"], "profile": snapshot.get("profile") or "",
                             "robot": ROBOT, "rockly": __version__,
                             "started": datetime.datetime.now().astimezone().isoformat(timespec="seconds")}, program)
        self.recorder.note(channels.RUN, {"event": "start"})
        for line in snapshot.get("prints") or []:
            if line is not None:
                self.recorder.printed(str(line))
        self.take({"event": "variables", "values": snapshot.get("variables") or {}})
        if snapshot.get("block"):
            self.take({"event": "block", "id": snapshot["block"]})
        if snapshot.get("paused"):
            self.take(snapshot["paused"])
        self._now = None

    def take(self, event: dict):
        """Record one of the run's events (``runtime.event_stream``'s lines)."""
        kind, note = event.get("event"), self.recorder.note
        if kind == "block" and event.get("id"):
            block = str(event["id"])
            note(channels.BLOCKS, {"block": block, "type": self._block_types.get(block, "")})
        elif kind == "print" and event.get("text") is not None:
            self.recorder.printed(str(event["text"]))
        elif kind == "variables":
            note(channels.VARIABLES, {"values": {str(name): None if value is None else str(value)
                                                 for name, value in (event.get("values") or {}).items()}})
        elif kind == "paused":
            note(channels.RUN, {"event": "pause", "block": event.get("block"), "reason": event.get("reason")})
        elif kind == "resumed":
            note(channels.RUN, {"event": "resume"})
        elif kind == "finished":
            note(channels.RUN, {"event": "end", "outcome": event.get("outcome"), "block": event.get("block"),
                                "message": event.get("message")})

    def close(self):
        """Finish the file (idempotent)."""
        try:
            self.recorder.close()
        except Exception:
            log.exception("finishing the recording %s failed", self.path)


def open_attached_recording(settings, document, workspace: dict, snapshot: dict, say=lambda text: None):
    """An ``AttachedRecording`` of the run ``snapshot`` in the preferences' recordings folder (the window's program,
    ``document`` and its ``workspace``, stored in it); None when the preferences keep no recordings or it cannot
    be made (``say(text)`` tells the person why, as for a run in the window)."""
    from rockly_desktop.recording.mcap_file import problem_text

    if settings.recordings_kept == 0:
        return None
    folder, language, path = settings.recordings_folder, settings.language, settings.recordings_folder

    def stopped(error):
        say(tr("recording_stopped", language, path=path, reason=problem_text(error, language)))

    try:
        keep_last(folder, settings.recordings_kept - 1)
        program = Program(document.profile.id, workspace or {}, list(document.breakpoints),
                          document.profile.packs_used(workspace or {})).to_json().encode("utf-8")
        path = new_recording_path(folder, Path(snapshot["program"]).name, ROBOT)
        return AttachedRecording(path, snapshot, program, block_types_by_id(workspace or {}), stopped)
    except OSError as error:
        log.warning("the attached run is not recorded: %s", error)
        say(tr("recording_not_started", language, path=path, reason=problem_text(error, language)))
        return None
