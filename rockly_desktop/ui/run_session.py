"""Running the program on screen: start/pause/step/continue/stop, highlighting, variables, errors.

The program runs in a ProgramThread. Its events arrive as queued signals; the block it
is at and its variables are polled every 33 ms, so a tight loop at full speed never
floods the GUI, while a pause shows the exact block and values.
"""
import sys

from PySide6.QtCore import QObject, QTimer, Signal
from PySide6.QtWidgets import QMessageBox

from rockly_desktop.core.errors import RocklyError
from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.events import OutputPrinted, RunFinished, RunPaused, RunResumed, VariablesChanged
from rockly_desktop.executor.qt_adapter import ProgramThread
from rockly_desktop.ui.message_boxes import plain_message_box
from rockly_desktop.ui.texts import robot_problem, tr

FOLLOW_MS = 33
RUN_SWITCH_INTERVAL = 0.001  # seconds


class RunSession(QObject):
    """The window's one program run at a time; ``state`` is 'idle', 'starting', 'running' or 'paused'."""

    sig_state_changed = Signal(str)
    sig_finished = Signal(object)  # RunFinished, once the run's thread has ended

    def __init__(self, window):
        super().__init__(window)
        self.window = window
        self.state = "idle"
        self.control = None
        self.thread = None
        self.last_result = None
        self._switch_interval = sys.getswitchinterval()
        self._shown_block = None
        self._follow = QTimer(self)
        self._follow.setInterval(FOLLOW_MS)
        self._follow.timeout.connect(self._follow_run)

    # --- commands -----------------------------------------------------------------------

    def run(self, step_first: bool = False) -> bool:
        """Run the program in the editor (pausing at its first block if ``step_first``)."""
        window = self.window
        if self.state != "idle":
            return False
        self._set_state("starting")  # asking the page for the code runs a nested event loop
        try:
            run_code = window.editor.call_blocking("getRunCode")
            if not run_code["code"].strip():
                window.console.append(tr("run_empty", window.language), "info")
                self._set_state("idle")
                return False
            control = RunControl(run_code["breakpoints"], window.run_toolbar.delay)
            robot = window.robot()
            language = window.language  # the run's messages are in the window's language
            from rockly_desktop.executor.run_setup import make_runner  # loaded at the first run, not at start-up

            thread = ProgramThread(lambda emit: make_runner(window.profile, robot, run_code, control, emit, language), self)
        except (RocklyError, RuntimeError) as error:
            window.console.append(" ".join(part for part in robot_problem(error, window.language) if part), "error")
            self._set_state("idle")
            return False
        if step_first:
            control.step()
        self.control, self.thread = control, thread
        thread.sig_event.connect(self._on_event)
        thread.finished.connect(self._on_thread_finished)
        window.editor.call("clearMarks")
        window.console.append(tr("run_started", window.language), "info")
        self._shown_block = None
        self._set_state("running")
        # A program in a tight loop holds the GIL; hand it over more often so the window
        # keeps drawing (Python's default is every 5 ms).
        self._switch_interval = sys.getswitchinterval()
        sys.setswitchinterval(RUN_SWITCH_INTERVAL)
        thread.start()
        self._follow.start()
        return True

    def pause(self):
        """Pause before the next block."""
        if self.state == "running":
            self.control.request_pause()

    def step(self):
        """Run one block (starting the program paused at its first block when idle)."""
        if self.state == "idle":
            self.run(step_first=True)
        elif self.state == "paused":
            self._set_state("running")
            self.control.step()

    def resume(self):
        """Continue a paused program."""
        if self.state == "paused":
            self._set_state("running")
            self.control.resume()

    def stop(self):
        """Stop the program; the robot's safe stop follows."""
        if self.control is not None and self.state != "idle":
            self.control.request_stop()

    def set_breakpoints(self, block_ids):
        """Breakpoints changed in the editor (also while running)."""
        if self.control is not None:
            self.control.set_breakpoints(block_ids)

    def set_delay(self, seconds: float):
        """The slow-motion slider moved."""
        if self.control is not None:
            self.control.set_delay(seconds)

    def shutdown(self, timeout_ms: int = 5000) -> bool:
        """Stop any run and wait for its thread (the app is closing); True when it ended."""
        if self.thread is None:
            return True
        self.stop()
        ended = self.thread.wait(timeout_ms)
        self._follow.stop()
        if ended:
            self._on_thread_finished()
        return ended

    # --- following the run --------------------------------------------------------------

    def _set_state(self, state: str):
        self.state = state
        self.window.run_toolbar.set_state(state)
        self.sig_state_changed.emit(state)

    def _highlight(self, block_id):
        if block_id != self._shown_block:
            self._shown_block = block_id
            self.window.editor.call("highlight", {"id": block_id})

    def _follow_run(self):
        if self.thread is None or self.state != "running":
            return
        runner = self.thread.runner
        self._highlight(runner.hooks.current_block)
        self.window.variables.show_values(runner.variables_snapshot())

    def _on_event(self, event):
        window = self.window
        if isinstance(event, RunPaused):
            self._set_state("paused")
            self._highlight(event.block_id)
            key = "paused_breakpoint" if event.reason == "breakpoint" else "paused"
            window.statusBar().showMessage(tr(key, window.language))
        elif isinstance(event, RunResumed):
            window.statusBar().clearMessage()
        elif isinstance(event, OutputPrinted):
            window.console.append(event.text)
        elif isinstance(event, VariablesChanged):
            window.variables.show_values(event.values)
        elif isinstance(event, RunFinished):
            self._on_finished(event)

    def _on_finished(self, result: RunFinished):
        window = self.window
        self._follow.stop()
        self.last_result = result
        self._highlight(None)
        if result.outcome == "error":
            window.console.append(result.message, "error")
            window.editor.call("markError", {"id": result.block_id, "message": result.message})
            box = plain_message_box(window, QMessageBox.Icon.Warning, tr("error_title", window.language), result.message)
            box.setObjectName("run_error_box")
            box.setDetailedText(result.details or "")
            box.open()
        else:
            window.console.append(tr("run_finished" if result.outcome == "finished" else "run_stopped",
                                     window.language), "info")
        window.statusBar().clearMessage()

    def _on_thread_finished(self):
        if self.thread is None:  # already handled by shutdown()
            return
        self.thread.deleteLater()
        self.thread = None
        self.control = None
        sys.setswitchinterval(self._switch_interval)
        self._set_state("idle")
        self.sig_finished.emit(self.last_result)
