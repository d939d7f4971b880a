"""One run written to an MCAP recording: opened for a robot and a program, fed by the run, closed at its end.

The recording hooks in above any backend: the state store hands it the robot's topics,
``robot/wrappers/recorded.py`` what the program sends and what comes back, the block hooks the
blocks entered, and the run's events (pauses, output, the safe stop, the end) pass
through ``RunRecording.emit``.
"""
import datetime
import logging

from rockly_desktop import __version__
from rockly_desktop.executor.events import OutputPrinted, RunFinished, RunPaused, RunResumed, VariablesChanged
from rockly_desktop.recording import channels
from rockly_desktop.recording.badges import BadgeStates
from rockly_desktop.recording.recorder import Recorder

log = logging.getLogger(__name__)


class RunRecording:
    """Records one run of ``program_name`` on ``robot`` to ``path``.

    ``program`` is the ``.rockly`` file's bytes (stored in the recording), ``block_types``
    maps block ids to their types, ``topic_rate`` caps each robot topic (messages a second).
    Raises OSError when the recording cannot be begun (``mcap_file.RecordingHeld``: another run
    records to ``path``); ``on_stopped(error)`` is called once if a write fails later (a full disk),
    from the recording's thread: the run goes on unrecorded from then. ``clock()`` (nanoseconds since the
    epoch) stamps everything (a lesson's check: simulated time); with ``snapshots=False`` the recording
    samples no simulator snapshots itself (the check notes them as simulated time passes).
    """

    def __init__(self, path, profile, robot, program_name: str, program: bytes = None, block_types=None,
                 topic_rate: float = 10.0, on_stopped=None, clock=None, snapshots: bool = True):
        self.path = path
        self.recorder = Recorder(path, robot.recording_encoder(), topic_rate, clock=clock, on_stopped=on_stopped)
        self._snapshots = snapshots
        self._robot = robot
        self._block_types = block_types or {}
        self._hooks = None
        self.badges = BadgeStates()  # what the blocks' commands did so far, for their badges
        metadata = {"program": program_name, "profile": profile.id, "robot": robot.kind,
                    "started": datetime.datetime.now().astimezone().isoformat(timespec="seconds"),
                    "rockly": __version__}
        world = getattr(robot, "world_id", None)  # a simulator's solid world: a replay shows only there
        if world is not None:
            metadata["world"] = world
        self.recorder.start(metadata, program)
        robot.state.add_listener(self.recorder.topic)
        robot.follow_graph()  # a ROS robot fills its state store only when asked

    def follow(self, runner):
        """Record ``runner``'s blocks and variables (and the simulator's state), from the start."""
        self._hooks = runner.hooks
        self.recorder.follow(runner.hooks, runner.variables_snapshot, self._robot.snapshot if self._snapshots else None,
                             self._block_types, runner.values_snapshot)
        self.recorder.note(channels.RUN, {"event": "start"})

    def command(self, entry: dict):
        """What the program sent or what came back (``robot/wrappers/recorded.py``'s entries), with the
        current block."""
        block = self._hooks.current_block if self._hooks is not None else None
        entry = {**entry, "block": block}
        self.badges.take(entry)
        self.recorder.note(channels.COMMANDS, entry)

    def safe_stop(self, failures):
        """The robot's safe stop ran (``failures``: what did not work)."""
        self.recorder.note(channels.RUN, {"event": "safe_stop", "failures": list(failures)})

    def emit(self, event):
        """Record a run event; the run's end closes the recording."""
        if isinstance(event, RunPaused):
            self.recorder.note(channels.RUN, {"event": "pause", "block": event.block_id, "reason": event.reason})
        elif isinstance(event, RunResumed):
            self.recorder.note(channels.RUN, {"event": "resume"})
        elif isinstance(event, VariablesChanged):  # exact at a pause and at the end (else sampled)
            self.recorder.note(channels.VARIABLES, {"values": event.values})
        elif isinstance(event, OutputPrinted):
            self.recorder.printed(event.text)
        elif isinstance(event, RunFinished):
            self.recorder.note(channels.RUN, {"event": "end", "outcome": event.outcome, "block": event.block_id,
                                              "message": event.message})
            self.close()

    def close(self):
        """Stop recording and finish the file (idempotent)."""
        self._robot.state.remove_listener(self.recorder.topic)
        try:
            self.recorder.close()
        except Exception:
            log.exception("finishing the recording %s failed", self.path)
