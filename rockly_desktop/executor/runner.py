"""Running a generated program in the current thread: no Qt, testable on its own.

The page instruments the code: ``__rockly__.block('ID')`` before every statement block
and ``__rockly__.check()`` at the top of every loop body (and, when the blocks show their
values, ``__rockly__.value('ID', value)`` around every expression block). Those calls are where pause,
step, breakpoints, slow motion and stop happen; robot waits watch the same Interrupt,
so a stop also ends a long drive or a dialog.
"""
import builtins
import io
import logging
import time
import tokenize
import traceback

from rockly_desktop.core.errors import ProgramStopped, RobotCommandError
from rockly_desktop.executor import large_results
from rockly_desktop.executor.events import (
    BlockEntered,
    OutputPrinted,
    RunFinished,
    RunPaused,
    RunResumed,
    VariablesChanged,
)
from rockly_desktop.executor.problems import explain, text
from rockly_desktop.executor.value_text import value_text

log = logging.getLogger(__name__)
PROGRAM_FILENAME = "<rockly program>"



class BlockHooks:
    """The ``__rockly__`` object the instrumented program calls."""

    power = staticmethod(large_results.power)
    times = staticmethod(large_results.times)

    def __init__(self, control, emit, variables):
        self._control = control
        self._emit = emit
        self._variables = variables
        self.current_block = None
        self.values = {}  # expression block id -> its last value (when the code hands them in)

    def block(self, block_id: str):
        """Called before each statement block."""
        self.current_block = block_id
        if self._control.attention:
            self._at_block(block_id)

    def value(self, block_id: str, value):
        """Called with each expression block's value (values on): kept as its last, and passed on."""
        self.values[block_id] = value
        return value

    def check(self):
        """Called at the top of each loop body, so even an empty loop can be stopped."""
        if self._control.attention:
            self._control.interrupt.check()

    def hold_inside_block(self):
        """The robot was halted for a pause in the middle of the current block."""
        self._pause_here(self.current_block, "pause")

    def _pause_here(self, block_id, reason):
        self._emit(self._variables())
        self._emit(RunPaused(block_id, reason))
        self._control.wait_for_release()
        self._emit(RunResumed())

    def _at_block(self, block_id):
        control = self._control
        control.interrupt.check()
        if control.trace:
            self._emit(BlockEntered(block_id))
        reason = control.pause_reason(block_id)
        if reason is not None:
            self._pause_here(block_id, reason)
        elif control.delay:
            control.interrupt.sleep(control.delay)


class RecordedBlockHooks(BlockHooks):
    """``BlockHooks`` that also note each block entered, with its ``stamp()`` (``time.monotonic_ns()``), in
    ``entered`` while ``block_budget`` lasts (a recorder refills it, so a tight loop costs one test)."""

    def __init__(self, control, emit, variables, entered, stamp=time.monotonic_ns):
        super().__init__(control, emit, variables)
        self.entered = entered
        self._stamp = stamp
        self.block_budget = 0

    def block(self, block_id: str):
        """Called before each statement block."""
        self.current_block = block_id
        if self.block_budget:
            self.block_budget -= 1
            self.entered.append((self._stamp(), block_id))
        if self._control.attention:
            self._at_block(block_id)


class ProgramRunner:
    """Runs one program to its end and reports what happens through ``emit(event)``.

    ``namespace`` holds what the program may use (``robot``); ``variables`` maps the
    Blockly variable names to their Python names; ``on_end()`` (the robot's safe stop)
    runs whenever the run ends, for any reason. ``language`` ('en' or 'de') is the
    language of the messages a run reports (an error, a failed safe stop). With ``entered`` (a deque),
    the blocks entered are noted there for a recording (see ``RecordedBlockHooks``), stamped by
    ``entered_stamp()`` (``time.monotonic_ns``; a lesson's check records in simulated time).
    """

    def __init__(self, code: str, namespace: dict, control, emit, variables=None, on_end=None, language: str = "en",
                 entered=None, entered_stamp=time.monotonic_ns):
        self._code = code
        self.language = language
        self._control = control
        self._emit = emit
        self._variable_names = dict(variables or {})
        self._on_end = on_end
        self.hooks = (BlockHooks(control, emit, self.variables_event) if entered is None
                      else RecordedBlockHooks(control, emit, self.variables_event, entered, entered_stamp))
        control.on_hold = self.hooks.hold_inside_block
        self.globals = {"__builtins__": builtins, "__name__": "__rockly__",
                        **namespace, "__rockly__": self.hooks, "print": self._print}

    def _print(self, *values, sep=" ", end="\n", **_ignored):
        self.show_output(sep.join(str(value) for value in values))

    def show_output(self, text: str):
        """Show ``text`` in the run's output, one event per line."""
        for line in str(text).splitlines() or [""]:
            self._emit(OutputPrinted(line))

    def variables_snapshot(self) -> dict:
        """The program's variables now: Blockly name -> the value as people read it (``value_text``)."""
        values = {}
        for display, python_name in self._variable_names.items():
            try:
                values[display] = value_text(self.globals.get(python_name), self.language)
            except Exception as error:
                values[display] = f"<{type(error).__name__}>"
        return values

    def values_snapshot(self) -> dict:
        """The expression blocks' last values: block id -> the value as people read it (``value_text``)."""
        values = {}
        for block_id, value in dict(self.hooks.values).items():  # a copy: the program goes on meanwhile
            try:
                values[block_id] = value_text(value, self.language)
            except Exception as error:
                values[block_id] = f"<{type(error).__name__}>"
        return values

    def variables_event(self) -> VariablesChanged:
        """The variables as an event."""
        return VariablesChanged(self.variables_snapshot())

    def run(self) -> RunFinished:
        """Execute the program; always runs ``on_end`` and emits (and returns) RunFinished."""
        try:
            compiled = compile(self._code, PROGRAM_FILENAME, "exec")
            exec(compiled, self.globals)
            result = RunFinished("finished")
        except ProgramStopped:
            result = RunFinished("stopped", self.hooks.current_block)
        except SyntaxError as error:
            result = RunFinished("error", None, text("unreadable", self.language, detail=error.msg),
                                 traceback.format_exc())
        except RobotCommandError as error:  # the robot's own refusal: its words, no traceback
            result = RunFinished("error", self.hooks.current_block, self.explain(error), by_robot=True)
        except Exception as error:
            result = RunFinished("error", self.hooks.current_block, self.explain(error), _program_traceback(error))
        self._finish()
        self._emit(self.variables_event())
        self._emit(result)
        return result

    def _finish(self):
        if self._on_end is None:
            return
        try:
            self._on_end()
        except Exception:
            log.exception("the safe stop failed")
            self._emit(OutputPrinted(text("unsafe_stop", self.language)))

    def explain(self, error: BaseException) -> str:
        """The run's error in plain words, naming the variables of the line that failed."""
        names = {python: display for display, python in self._variable_names.items()}
        return explain(error, self.language, self._variables_on_failing_line(error, names), names)

    def _variables_on_failing_line(self, error: BaseException, names: dict) -> list:
        """(Blockly name, value) of the program's variables on the line of the program where ``error`` happened."""
        frame = lineno = None
        tb = error.__traceback__
        while tb is not None:  # the innermost frame of the program (not of Rockly or a robot command)
            if tb.tb_frame.f_code.co_filename == PROGRAM_FILENAME:
                frame, lineno = tb.tb_frame, tb.tb_lineno
            tb = tb.tb_next
        lines = self._code.splitlines()
        if frame is None or not 0 < lineno <= len(lines):
            return []
        found = {}
        for name in _names_in(lines[lineno - 1]):
            if name in names and names[name] not in found:
                scope = frame.f_locals if name in frame.f_locals else frame.f_globals
                if name in scope:
                    found[names[name]] = scope[name]
        return list(found.items())


def _names_in(line: str) -> list:
    """The names a line of Python reads or writes, in order (attributes like ``robot.drive`` left out)."""
    names, previous = [], None
    try:
        for token in tokenize.generate_tokens(io.StringIO(line.strip()).readline):
            if token.type == tokenize.NAME and previous != ".":
                names.append(token.string)
            previous = token.string
    except (tokenize.TokenError, SyntaxError):  # a line of a longer statement: the names so far
        pass
    return names


def _program_traceback(error: BaseException) -> str:
    """The traceback from the program's frames down (Rockly's own frames left out)."""
    frames = traceback.extract_tb(error.__traceback__)
    first = next((i for i, frame in enumerate(frames) if frame.filename == PROGRAM_FILENAME), 0)
    lines = traceback.format_list(frames[first:]) + traceback.format_exception_only(type(error), error)
    return "Traceback (most recent call last):\n" + "".join(lines)
