"""Running the program on screen: start/pause/step/continue/stop, highlighting, variables, errors.

The program's code runs in a process of its own (``runtime/program_process.py``), which has no robot link,
no limits and no network; a ProgramThread serves it here on the robot link, under the teacher's limits, with
the recording and the safe stop (``runtime/hosted_run.py``, decision 041). Its events arrive as queued signals;
the block it is at, its variables and what it printed are polled every 33 ms, so a tight loop at full
speed never floods the GUI, while a pause shows the exact block and values. A program's process is kept
started (``WarmProcess``) for the next run, so Run → first block does not wait for Python to start.
"""
import sys

import shiboken6
from PySide6.QtCore import QObject, QPoint, QRect, QSize, QTimer, Signal

from rockly_desktop.bridge.editor_view import ANSWER_TIMEOUT_MS
from rockly_desktop.core.errors import RocklyError
from rockly_desktop.executor.events import RunFinished, RunPaused, RunResumed, VariablesChanged
from rockly_desktop.executor.qt_adapter import ProgramThread
from rockly_desktop.ui.run.block_badges import badge_texts, badges_shown
from rockly_desktop.ui.run.run_messages import place_beside, run_problem_box
from rockly_desktop.ui.texts import robot_problem, tr

FOLLOW_MS = 33
RUN_SWITCH_INTERVAL = 0.001  # seconds


class RunSession(QObject):
    """One program run at a time; ``state`` is 'idle', 'starting' (waiting for the page's code),
    'running' or 'paused'.

    Collaborators: the ``document`` (profile), the ``editor`` (code, highlights, marks), the
    ``robots`` (``robot()``), the ``console`` and ``variables`` docks, the ``settings``
    (language) and ``parent``, the widget an error box belongs to.
    """

    sig_state_changed = Signal(str)
    sig_finished = Signal(object)  # RunFinished, once the run's thread has ended
    sig_status = Signal(str)  # a status-bar message; empty: clear it
    sig_recording_problem = Signal(str)  # the run is not recorded, or its recording stopped (from any thread)

    def __init__(self, document, editor, robots, console, variables, settings, parent):
        super().__init__(parent)
        self.document = document
        self.editor = editor
        self.robots = robots
        self.console = console
        self.variables = variables
        self.settings = settings
        self.state = "idle"
        self.control = None
        self.thread = None
        self.last_result = None
        self.last_recording = None  # the path of the last run's recording
        self._recording = None
        self._badges_shown = None  # the badge states last sent to the page
        self._values_on = False  # the run hands its expression blocks' values in (not at the Starter level)
        self._values_shown = None  # the values last sent to the page
        self._delay = 0.0
        self._start_request = None  # the run waiting for the page's code; None when cancelled
        self._switch_interval = sys.getswitchinterval()
        self._shown_block = None
        self._follow = QTimer(self)
        self._follow.setInterval(FOLLOW_MS)
        self._follow.timeout.connect(self._follow_run)
        self.sig_recording_problem.connect(lambda text: self.console.append(text, "error"))
        self._closing = False  # shut down: no process is kept for a next run
        self._warm = None  # the program's process waiting for the next run (a WarmProcess), from the first run on

    def warm_up(self):
        """Start the next run's program process now (for the document's profile), so Run → first block is quick."""
        if self._warm is None:
            from rockly_desktop.runtime.hosted_run import WarmProcess
            from rockly_desktop.runtime.robot_limits import default_path

            self._warm = WarmProcess(hidden=[self.settings.folder, default_path().parent])
        self._warm.warm(self.document.profile)

    # --- commands -----------------------------------------------------------------------

    def run(self, step_first: bool = False, page=None, notes=None) -> bool:
        """Start the program in the editor (pausing at its first block if ``step_first``), or on ``page``,
        another editor page (the block maker's preview: its one block tried once, under the same limits);
        ``notes(entry)`` is told what the run sends and what comes back (from the run's thread).

        The page is asked for the code; the run starts when it answers ('starting' until
        then). False when a run is already under way.
        """
        if self.state != "idle":
            return False
        request = object()
        self._start_request = request
        self._set_state("starting")
        self._values_on = badges_shown(self.settings, self.document.profile.id)
        self._values_shown = None
        (page or self.editor).call("getRunCode", {"values": self._values_on},
                         lambda run_code, error: self._start(request, run_code, error, step_first, notes),
                         timeout_ms=ANSWER_TIMEOUT_MS)
        return True

    def _start(self, request, run_code, error, step_first: bool, notes=None):
        if request is not self._start_request:  # stopped (or the window closed) while the page answered
            return
        self._start_request = None
        language = self.settings.language  # the run's messages are in the window's language
        if error:
            self.console.append(tr("run_not_started", language, error=error), "error")
            self._set_state("idle")
            return
        if not run_code["code"].strip():
            self.console.append(tr("run_empty", language), "info")
            self._set_state("idle")
            return
        from rockly_desktop.runtime.hosted_run import hosted_runner  # loaded at the first run, not at start-up
        from rockly_desktop.runtime.link_host import HostControl
        from rockly_desktop.ui.run.run_recordings import open_run_recording

        recording = None
        try:
            self.robots.reset_if_wanted()
            control = HostControl(run_code["breakpoints"], self._delay)
            robot = self.robots.robot()
            profile = self.document.profile
            limits = self.settings.teacher.limits(profile.id)  # kept by the backend, on any robot
            recording = open_run_recording(self.settings, self.document, self.editor.workspace, robot,
                                           self.sig_recording_problem.emit)
            self.last_recording = recording.path if recording is not None else None
            self._recording = recording if badges_shown(self.settings, profile.id) else None
            self._badges_shown = None
            self.warm_up()
            process = self._warm.take(profile)
            try:
                thread = ProgramThread(lambda emit: hosted_runner(process, profile, robot, run_code, control, emit,
                                                                  language, limits, recording, notes), self)
            except BaseException:
                process.kill()
                process.close()
                raise
        except (RocklyError, RuntimeError) as problem:
            if recording is not None:
                recording.close()
            self.console.append(" ".join(part for part in robot_problem(problem, language) if part), "error")
            self._set_state("idle")
            return
        if step_first:
            control.step()
        self.control, self.thread = control, thread
        thread.sig_event.connect(self._on_event)
        thread.finished.connect(self._on_thread_finished)
        self.editor.call("clearMarks")
        self.console.append(tr("run_started", language), "info")
        self._shown_block = None
        self._set_state("running")
        # The run's threads here (the program's lines read and served, a printing loop's many) take the GIL in
        # turns with the window; hand it over more often so the window keeps drawing (Python's default: 5 ms).
        self._switch_interval = sys.getswitchinterval()
        sys.setswitchinterval(RUN_SWITCH_INTERVAL)
        thread.start()
        self._follow.start()

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
        """Stop the program; the robot's safe stop follows. A run still waiting for its code never starts."""
        if self.state == "starting":
            self._cancel_start()
        elif self.control is not None and self.state != "idle":
            self.control.request_stop()

    def _cancel_start(self):
        self._start_request = None
        self._set_state("idle")

    def set_breakpoints(self, block_ids):
        """Breakpoints changed in the editor (also while running)."""
        if self.control is not None:
            self.control.set_breakpoints(block_ids)

    def set_delay(self, seconds: float):
        """The slow-motion slider moved (or was made): wait ``seconds`` at every block."""
        self._delay = seconds
        if self.control is not None:
            self.control.set_delay(seconds)

    def shutdown(self, timeout_ms: int = 5000) -> bool:
        """Stop any run and wait for its thread (the app is closing); True when it ended.

        A run still waiting for the page's code is cancelled: it never starts.
        """
        if self.state == "starting":
            self._cancel_start()
        self._closing = True
        if self._warm is not None:
            self._warm.close()
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
        self.sig_state_changed.emit(state)

    def _highlight(self, block_id):
        if block_id != self._shown_block:
            self._shown_block = block_id
            self.editor.call("highlight", {"id": block_id})

    def _follow_run(self):
        if self.thread is None or self.state != "running":
            return
        self._show_output()
        runner = self.thread.runner
        self._highlight(runner.hooks.current_block)
        self.variables.show_values(runner.variables_snapshot())
        self._show_badges()
        self._show_block_values()

    def _show_block_values(self):
        """Send the expression blocks' last values when they changed (shown on hover)."""
        if not self._values_on or self.thread is None:
            return
        values = self.thread.runner.values_snapshot()
        if values != self._values_shown:
            self._values_shown = values
            self.editor.call("setValues", {"values": values, "label": tr("block_value", self.settings.language)})

    def _show_badges(self):
        """Send the blocks' badges when their states changed (the run's recording keeps them)."""
        recording = self._recording
        if recording is None or recording.badges.states is self._badges_shown:
            return
        self._badges_shown = recording.badges.states
        self.editor.call("setBadges", {"badges": badge_texts(self._badges_shown, self.settings.language)})

    def _show_output(self, everything: bool = False):
        """Show what the program printed since the last look: a batch, or ``everything`` (at its end)."""
        if self.thread is None:
            return
        lines, skipped = self.thread.output.take(everything)
        if skipped:
            self.console.append(tr("output_skipped", self.settings.language, count=skipped), "info")
        self.console.append_lines(lines)

    def _on_event(self, event):
        # Everything printed before a pause, the end or any other event comes first.
        self._show_output(everything=True)
        if isinstance(event, RunPaused):
            self._set_state("paused")
            self._highlight(event.block_id)
            key = "paused_breakpoint" if event.reason == "breakpoint" else "paused"
            self.sig_status.emit(tr(key, self.settings.language))
        elif isinstance(event, RunResumed):
            self.sig_status.emit("")
        elif isinstance(event, VariablesChanged):
            self.variables.show_values(event.values)
        elif isinstance(event, RunFinished):
            self._on_finished(event)

    def _on_finished(self, result: RunFinished):
        language = self.settings.language
        self._follow.stop()
        self.last_result = result
        self._highlight(None)
        self._show_badges()
        self._show_block_values()
        if result.outcome == "error":
            self.console.append(result.message, "error")
            box = run_problem_box(self.parent(), result, self.document.profile.display_name(language), language,
                                  kiosk=self.settings.kiosk_mode)
            box.open()
            self.editor.call("markError", {"id": result.block_id, "message": result.message},
                             lambda marked, _error: self._put_beside_block(box, marked))
        else:
            self.console.append(tr("run_finished" if result.outcome == "finished" else "run_stopped", language), "info")
        self.sig_status.emit("")

    def _put_beside_block(self, box, marked):
        """Move the error's ``box`` beside its block (``marked``: the page's box of it, in page pixels)."""
        if not isinstance(marked, dict) or not shiboken6.isValid(box) or not box.isVisible():
            return  # no block to point to, or the box is gone
        zoom = self.editor.zoomFactor()
        corner = self.editor.mapToGlobal(QPoint(round(marked["left"] * zoom), round(marked["top"] * zoom)))
        block = QRect(corner, QSize(round(marked["width"] * zoom), round(marked["height"] * zoom)))
        place_beside(box, block, self.editor.window().frameGeometry())

    def _on_thread_finished(self):
        if self.thread is None:  # already handled by shutdown()
            return
        self.thread.deleteLater()
        self.thread = None
        self.control = None
        sys.setswitchinterval(self._switch_interval)
        self._set_state("idle")
        if self._warm is not None and not self._closing:
            self._warm.warm(self.document.profile)  # the next run's process, while the person looks
        self.sig_finished.emit(self.last_result)
