"""Checking one program against a lesson: its generated code run on the simulated robot, its goals judged.

``check_program(lesson, program)`` makes a fresh simulator for the lesson's robot, puts the robot at the
lesson's start, and runs the program's code (``GeneratedProgram``: what the editor generated) in
stepped simulated time (``stepping.py``) until it ends, raises, or passes the lesson's time limit. An
observer feeds every goal the run as it happens: the simulator's snapshot after each tick, what went
over the robot's topics and services, the program's printed lines and the block running. The result
says per goal whether it passed, in words a child reads, with the simulated time and the block of a
failing moment (for a replay). The program's file is never touched: the check gets generated code only.
"""
import math
import threading
import time
from dataclasses import dataclass, field

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.events import BlockEntered, OutputPrinted
from rockly_desktop.executor.run_setup import make_runner
from rockly_desktop.executor.run_to_mcap import RunRecording
from rockly_desktop.lessons.goals import Moment, Words, blocks_of, toolbox_blocks
from rockly_desktop.lessons.lesson import Lesson, start_heading
from rockly_desktop.lessons.stepping import BLOCK_SECONDS, SteppedClock, SteppedRobot
from rockly_desktop.recording import channels
from rockly_desktop.robot.sim.answer_list import AnswerList
from rockly_desktop.robot.wrappers.limits import Limits

REAL_SECONDS = 60.0   # a program that lets no simulated time pass (an empty endless loop) is stopped after this
SNAPSHOT_SECONDS = 0.1   # simulated seconds between two simulator snapshots in a check's recording


@dataclass
class GeneratedProgram:
    """A program as the editor generated it: ``name`` (its file's), ``run_code`` (the page's getRunCode
    answer: code and variables), ``workspace`` (the blocks as Blockly JSON) and ``types`` {block id: type}."""

    name: str
    run_code: dict
    workspace: dict
    types: dict = field(default_factory=dict)


@dataclass
class GoalResult:
    """One goal's result: its ``kind`` and ``id``, ``passed``, the words (``text``, a LocalText), and the
    failing moment's simulated ``time`` and ``block`` (None when it has none)."""

    kind: str
    id: str
    passed: bool
    text: object
    time: float = None
    block: str = None

    def words(self, language: str = "en") -> str:
        """What to tell the child, in ``language``."""
        return self.text.in_language(language)


@dataclass
class CheckResult:
    """A program checked against a lesson: the ``goals``' results in the lesson's order, how the run
    ended (``ending``: finished, error, time_limit or stuck; ``ending_text`` in words), its simulated
    ``time``, and ``failing`` ((time, block) of the first failing moment, or None)."""

    lesson: str
    program: str
    goals: list
    ending: str
    ending_text: object
    time: float
    failing: tuple = None

    @property
    def passed(self) -> bool:
        """True when the program ended by itself and every goal passed."""
        return self.ending == "finished" and all(goal.passed for goal in self.goals)


def level_blocks(profile, level: str):
    """The block types the toolbox offers at ``level`` (None: every block, the Full level)."""
    if level == "full" or profile.level(level) is None:
        return None
    return toolbox_blocks(profile, level)


class _Observer:
    """Feeds the goals the run as it happens and keeps the block running."""

    def __init__(self, goals, simulator, commands=()):
        self.goals = goals
        self.simulator = simulator
        self.commands = frozenset(commands)   # topics that change what the snapshot shows at once
        self.block = None
        self.travelled = 0.0
        self.recording = None   # a RunRecording the snapshots are noted in, as simulated time passes
        self._next_snapshot = 0.0
        self._last = None
        self._order = 0
        self.moment = self.look()

    def _next(self, moment: Moment) -> Moment:
        self._order += 1
        self.moment = Moment(moment.time, moment.snapshot, self.block, moment.travelled, self._order)
        return self.moment

    def look(self) -> Moment:
        snapshot = self.simulator.snapshot()
        here = (float(snapshot.get("x", 0.0)), float(snapshot.get("y", 0.0)))
        if self._last is not None:
            self.travelled += math.dist(self._last, here)
        self._last = here
        return self._next(Moment(float(snapshot.get("time", self.simulator.time)), snapshot, self.block,
                                 self.travelled))

    def tick(self):
        moment = self.look()
        for goal in self.goals:
            goal.see(moment)
        if self.recording is not None and moment.time >= self._next_snapshot:
            self._next_snapshot = moment.time + SNAPSHOT_SECONDS
            self.recording.recorder.note(channels.SIMULATOR, moment.snapshot)

    def heard(self, topic, _msg_type, message):
        if topic in self.commands:
            self.tick()   # a face, a look: shown at once, before what comes next in the same tick
        if isinstance(message, dict):
            moment = self._next(self.moment)
            for goal in self.goals:
                goal.heard(topic, message, moment)

    def event(self, event):
        if isinstance(event, BlockEntered):
            self.block = event.block_id
        elif isinstance(event, OutputPrinted):
            moment = self._next(self.moment)
            for goal in self.goals:
                goal.printed(event.text, moment)


def check_program(lesson: Lesson, program: GeneratedProgram, language: str = "en",
                  real_seconds: float = REAL_SECONDS, record=None, program_bytes: bytes = None) -> CheckResult:
    """Run ``program`` on the lesson's simulated robot in simulated time and judge the lesson's goals.

    ``language``: of the run's own error messages (the results' words are LocalTexts, in any language).
    ``record``: an MCAP file to record the run to, stamped in simulated time from now (a replay's timeline
    is then the simulated one, and ``CheckResult.failing``'s time is a moment on it); ``program_bytes``:
    the ``.rockly`` file it keeps. Raises OSError when that recording cannot be begun."""
    profile = lesson.profile
    goals = lesson.make_goals(program.workspace)
    robot = SteppedRobot(profile, tablet=AnswerList(lesson.answers, lambda _line: None, language=language),
                         keep_state=record is not None)
    control = RunControl(trace=True)
    recording = None
    try:
        robot.simulator.place(lesson.start[0], lesson.start[1], start_heading(lesson))
        commands = set(profile.ros_interface.get("subscribes") or {}) - set(profile.velocity_topics)
        observer = _Observer(goals, robot.simulator, commands)
        for goal in goals:
            goal.see(observer.moment)
        clock = SteppedClock(robot.simulator, robot.world, lesson.time_limit, observer.tick, control.request_stop)
        robot.use_clock(clock)
        robot.world.tap(observer.heard, skip=profile.ros_interface.get("streams") or ())  # those: in snapshots

        def on_event(event):
            observer.event(event)
            if isinstance(event, BlockEntered):
                clock.spend(BLOCK_SECONDS)

        if record is not None:
            started = time.time_ns()
            recording = RunRecording(record, profile, robot, program.name, program_bytes, program.types,
                                     clock=lambda: started + int(robot.simulator.time * 1e9), snapshots=False)
            observer.recording = recording
        stuck = threading.Event()
        guard = threading.Timer(real_seconds, lambda: (stuck.set(), control.request_stop()))
        guard.daemon = True
        runner = make_runner(profile, robot, program.run_code, control, on_event, language, Limits(),
                             recording=recording)
        guard.start()
        try:
            finished = runner.run()
        finally:
            guard.cancel()
        end = observer.look()
    finally:
        if recording is not None:
            recording.recorder.note(channels.SIMULATOR, observer.moment.snapshot)
            recording.close()
        robot.shutdown()
    results = [_result(goal, goal.verdict(end)) for goal in goals]
    beyond = _beyond_level(lesson, program.workspace)
    if beyond is not None:
        results.append(beyond)
    ending, ending_text, failing = _ending(finished, clock.reached_limit, stuck.is_set(), lesson, end)
    moments = [(result.time, result.block) for result in results if not result.passed and result.time is not None]
    if failing is not None:
        moments.append(failing)
    failing = min(moments, key=lambda moment: moment[0]) if moments else None   # the first thing that went wrong
    return CheckResult(lesson.id, program.name, results, ending, ending_text, end.time, failing)


def _result(goal, verdict) -> GoalResult:
    return GoalResult(goal.kind, goal.id, bool(verdict.passed), verdict.text, verdict.time, verdict.block)


def _beyond_level(lesson, workspace):
    allowed = level_blocks(lesson.profile, lesson.level)
    if allowed is None:
        return None
    beyond = sorted({block.get("type") for block in blocks_of(workspace)} - allowed - {None})
    if not beyond:
        return None
    name = lesson.profile.level(lesson.level)["name"]
    level = Words(name if isinstance(name, dict) else {"en": str(name)})
    return GoalResult("level", None, False, app_local_text("lesson_beyond_level", blocks=", ".join(beyond),
                                                           level=level))


def _ending(finished, reached_limit, stuck, lesson, end):
    if reached_limit:
        return "time_limit", app_local_text("lesson_end_time_limit", seconds=lesson.time_limit), (end.time, end.block)
    if stuck:
        return "stuck", app_local_text("lesson_end_stuck"), (end.time, end.block)
    if finished.outcome == "finished":
        return "finished", app_local_text("lesson_end_finished", time=end.time), None
    block = finished.block_id or end.block
    return "error", app_local_text("lesson_end_error", message=finished.message or ""), (end.time, block)


def summary(result: CheckResult, language: str = "en") -> dict:
    """``result`` as plain data in ``language`` (for another process, a table or JSON): lesson, program,
    passed, ending, ending_words, time, failing, and goals [{kind, id, passed, words, time, block}]."""
    return {"lesson": result.lesson, "program": result.program, "passed": result.passed, "ending": result.ending,
            "ending_words": result.ending_text.in_language(language), "time": result.time,
            "failing": list(result.failing) if result.failing else None,
            "goals": [{"kind": goal.kind, "id": goal.id, "passed": goal.passed, "words": goal.words(language),
                       "time": goal.time, "block": goal.block} for goal in result.goals]}
