"""What a recording says about one moment of its run, and the moments worth a marker.

The replay asks ``Moments.at(seconds)`` for the block that was running then, the
variables' values, the simulator's state and how many lines had been printed, and puts
``markers()`` on its timeline: errors, pauses, breakpoints, bumps and goal outcomes.
"""
import bisect
from dataclasses import dataclass

from rockly_desktop.recording import channels
from rockly_desktop.recording.badges import BadgeStates
from rockly_desktop.recording.reading import Recording

BUMP_TOPICS = ("/sim/contact",)  # the simulators say here what the robot bumped into


@dataclass(frozen=True)
class Moment:
    """The run at one time: its block (None before the first), variables, simulator snapshot, lines printed."""

    block: str
    variables: dict
    snapshot: dict
    printed: int


@dataclass(frozen=True)
class Marker:
    """Something worth finding on the timeline: ``kind`` is 'error', 'pause', 'breakpoint', 'bump' or 'goal'."""

    time: float
    kind: str
    text: str


def _blocks_entered(recording: Recording) -> list:
    """The entries that say which block ran from when: blocks entered, and pauses, which name the
    block they hold at (a block's entry may be noted a moment after a pause the program made in it).
    One pass over the entries, already in time order: joining and sorting a million entries in C held
    the GIL for a third of a second, the window waiting although the replay is read in another thread."""
    return [entry for entry in recording.entries if entry.channel == channels.BLOCKS or (
        entry.channel == channels.RUN and entry.data.get("event") == "pause" and entry.data.get("block"))]


class _Series:
    def __init__(self, entries, value):
        self.times = [entry.time for entry in entries]
        self.values = [value(entry) for entry in entries]

    def at(self, seconds, default=None):
        index = bisect.bisect_right(self.times, seconds)
        return self.values[index - 1] if index else default


class Moments:
    """Looks moments of ``recording`` up (each in O(log n))."""

    def __init__(self, recording: Recording):
        self.recording = recording
        self._blocks = _Series(_blocks_entered(recording), lambda entry: entry.data["block"])
        self._variables = _Series(recording.on(channels.VARIABLES), lambda entry: entry.data.get("values") or {})
        self._snapshots = _Series(recording.on(channels.SIMULATOR), lambda entry: entry.data)
        self._output = recording.on(channels.OUTPUT)
        self._output_times = [entry.time for entry in self._output]
        self._printed = None
        self._values = recording.on(channels.VALUES)
        self._values_times = [entry.time for entry in self._values]
        self._commands = recording.on(channels.COMMANDS)
        self._command_times = [entry.time for entry in self._commands]
        ends = [entry.time for entry in recording.on(channels.RUN) if entry.data.get("event") == "end"]
        self.duration = max([recording.duration] + ends)

    @property
    def output(self) -> list:
        """The lines the program printed, in order (those recorded: not the ones printed too fast)."""
        return [entry.data.get("text", "") for entry in self._output if "skipped" not in entry.data]

    def printed_lines(self, skipped_text) -> list:
        """The lines printed, each after its time since the run began ("   1.25 s  text"); lines printed too fast to
        record are one line of ``skipped_text(count)``. The same list each time."""
        if self._printed is None:
            self._printed = [f"{entry.time:7.2f} s  " + (skipped_text(entry.data["skipped"]) if "skipped" in entry.data
                                                         else entry.data.get("text", "")) for entry in self._output]
        return self._printed

    def at(self, seconds: float) -> Moment:
        """The run as it was ``seconds`` after the recording began."""
        return Moment(self._blocks.at(seconds), self._variables.at(seconds, {}), self._snapshots.at(seconds),
                      bisect.bisect_right(self._output_times, seconds))

    def values(self, seconds: float) -> dict:
        """Block id -> the text of the expression block's last value ``seconds`` into the run."""
        values = {}
        for entry in self._values[:bisect.bisect_right(self._values_times, seconds)]:
            values.update(entry.data.get("values") or {})
        return values

    def badges(self, seconds: float) -> dict:
        """Block id -> (state, seconds) as the blocks' badges showed them ``seconds`` into the run."""
        states = BadgeStates()
        for entry in self._commands[:bisect.bisect_right(self._command_times, seconds)]:
            states.take(entry.data)
        return states.states

    def markers(self) -> list:
        """Errors, pauses, breakpoints (a pause at one), bumps and goal outcomes, in time order."""
        found = []
        for entry in self.recording.entries:
            data = entry.data
            if entry.channel == channels.RUN and data.get("event") == "end" and data.get("outcome") == "error":
                found.append(Marker(entry.time, "error", data.get("message") or ""))
            elif entry.channel == channels.RUN and data.get("event") == "pause" and data.get("reason") == "breakpoint":
                found.append(Marker(entry.time, "breakpoint", data.get("block") or ""))
            elif entry.channel == channels.RUN and data.get("event") == "pause":
                found.append(Marker(entry.time, "pause", data.get("reason") or ""))
            elif entry.channel == channels.COMMANDS and data.get("kind") == "failed":
                found.append(Marker(entry.time, "error", f"{data.get('name')}: {data.get('text', '')}"))
            elif entry.channel == channels.COMMANDS and data.get("kind") == "outcome":
                found.append(Marker(entry.time, "goal", f"{data.get('name')}: {data.get('status')}"))
        for topic in BUMP_TOPICS:
            found += [Marker(time, "bump", topic) for time in self.recording.topic_times.get(topic, ())]
        return sorted(found, key=lambda marker: marker.time)
