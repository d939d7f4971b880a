"""The link host: the process that owns the robot link serves a program that runs in a process of its own.

A limit in the program's process cannot hold against code that walks Python's object graph to the link
(decision 039). So the program runs in a child (``runtime/program_process.py``) that has no link, no limits
and, where Linux allows, no network; here, below it, are the link, the limits (the robot's and the
program's, stricter-of: the host takes none from the child), the recording and the safe stop. The child's
robot commands arrive as calls on the wire (``runtime/link_wire.py``) and are served on the wrapped
backend; its events are handed on as the run's.

STOP makes the robot safe here at once (the profile's safe stop on the link), refuses the child's further
commands, and tells the child to stop; a child that has not ended ``STOP_GRACE`` seconds later is killed.
The child ending for any reason (finished, crashed, killed) ends with the safe stop here too, unless the
robot was made safe after its last command.
"""
import fcntl
import os
import socket
import subprocess
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import rockly_desktop
from rockly_desktop.core.errors import ProgramStopped
from rockly_desktop.executor.events import BlockEntered, OutputPrinted, RunFinished
from rockly_desktop.executor.problems import text
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.runtime.event_stream import record_event
from rockly_desktop.runtime.link_wire import LineReader, encoded, error_record

STOP_GRACE = 2.0  # seconds a stopped program's process has to end before it is killed
WAITING_CALLS = 8  # calls that wait on the robot (services, goals, the next message) served at once
# what the child may still ask once the run is stopped (nothing that moves the robot)
AFTER_STOP = frozenset({"safe_stop", "unsubscribe", "goal_cancel", "goal_done", "latest", "resolve_name",
                        "get_param", "allowed_speed", "type_for"})
MOVES = frozenset({"publish", "send_goal", "call_service", "set_param"})  # after these the robot is not safe
WAITING = frozenset({"wait_for_message", "call_service", "send_goal", "goal_wait"})


def _python_path() -> str:
    """The child's PYTHONPATH: where this Rockly is, before the caller's (a checkout is not on the child's path
    by itself; an installed runtime is, and its site folder is not put before the standard library)."""
    root = Path(rockly_desktop.__file__).resolve().parent.parent
    given = [os.environ["PYTHONPATH"]] if os.environ.get("PYTHONPATH") else []
    installed = root.name in ("site-packages", "dist-packages")
    return os.pathsep.join(given if installed else [str(root)] + given)


class ProgramProcess:
    """A program's process, started (Rockly imported, and the profile's commands once ``prepare``d) before it
    is needed: a run hands it its program at once. Start one early (before the program is read, while the
    link opens), or keep one waiting."""

    def __init__(self, process: subprocess.Popen, sock: socket.socket):
        self.process = process
        self.sock = sock
        self.reader = LineReader(sock)
        self.profile = None
        self._send_lock = threading.Lock()

    @classmethod
    def start(cls, profile=None, hidden=()) -> "ProgramProcess":
        """Start a program's process (on this Python), for ``profile``'s robot when it is known already; it
        neither sees nor changes the ``hidden`` folders (``program_process.isolate``)."""
        mine, pair_end = socket.socketpair()
        mine.settimeout(None)  # blocking, whatever default another library set (rospy sets 60 s for every socket)
        # above the standard streams: where this process has one closed, the child's end could get its number, and
        # the child's own standard input (/dev/null) would take it
        theirs = fcntl.fcntl(pair_end.fileno(), fcntl.F_DUPFD_CLOEXEC, 3)
        pair_end.close()
        environment = dict(os.environ, PYTHONPATH=_python_path())
        try:
            output = sys.stderr.fileno()  # its stray prints never mix with an event stream on standard output
        except (AttributeError, OSError, ValueError):
            output = subprocess.DEVNULL
        try:
            process = subprocess.Popen([sys.executable, "-m", "rockly_desktop.runtime.program_process", str(theirs),
                                        *(str(Path(folder).resolve()) for folder in hidden)],
                                       pass_fds=(theirs,), stdin=subprocess.DEVNULL, stdout=output, env=environment,
                                       close_fds=True)
        finally:
            os.close(theirs)
        started = cls(process, mine)
        if profile is not None:
            started.prepare(profile)
        return started

    def prepare(self, profile):
        """Have the process make ``profile``'s commands ready (imported) now; once, before its run."""
        if self.profile is None:
            self.profile = profile
            self.send({"op": "profile", "profile": profile.command_side()})

    def send(self, record: dict) -> bool:
        """Send one record to the program's process; False when it is gone."""
        line = encoded(record)
        with self._send_lock:
            try:
                self.sock.sendall(line)
                return True
            except OSError:
                return False

    def kill(self):
        """End the process now (SIGKILL) and wait for it."""
        if self.process.poll() is None:
            self.process.kill()
        self.process.wait()

    def close(self):
        """Let go of the wire (the process, if alive, ends: its host is gone) and wait for the process."""
        try:
            self.sock.shutdown(socket.SHUT_RDWR)
        except OSError:
            pass
        self.sock.close()
        try:
            self.process.wait(STOP_GRACE)
        except subprocess.TimeoutExpired:
            self.kill()


class HostControl:
    """The run's controls on the host's side, as ``RunControl`` offers them: each request goes to the program's
    process; STOP also makes the robot safe here first (``on_stop``). ``interrupt`` is what the link's waits
    served here watch."""

    def __init__(self, breakpoints=(), delay: float = 0.0, trace: bool = False):
        self.interrupt = Interrupt()
        self.trace = trace
        self.breakpoints = frozenset(breakpoints)
        self.delay = max(0.0, delay)
        self.on_stop = None  # the host's safe stop, set while it serves a run
        self._send = None
        self._waiting = []  # requests made before the program's process was connected, in order
        self._lock = threading.Lock()

    def connect(self, send):
        """From now on, requests go to ``send(record)`` (those made before go first); None: nowhere."""
        with self._lock:
            self._send = send
            waiting, self._waiting = self._waiting, []
            if send is not None:
                for record in waiting:
                    send(record)

    def _request(self, record: dict):
        with self._lock:
            if self._send is None:
                self._waiting.append({"op": "control", **record})
            else:
                self._send({"op": "control", **record})

    def request_stop(self):
        """Tell the program to stop, make the robot safe at once and refuse the program's commands from now on (a
        wait served here that the stop or the safe stop ended answers ProgramStopped: a halted motion is not taken
        as done, nor as the robot's refusal)."""
        self.interrupt.request_stop()  # first: the waits served here end as stopped, before the safe stop ends them
        self._request({"do": "stop"})
        if self.on_stop is not None:
            self.on_stop()

    def request_pause(self):
        """Pause the program before its next block (or inside a motion that halts)."""
        self._request({"do": "pause"})

    def step(self):
        """Run one block, then pause again."""
        self._request({"do": "step"})

    def resume(self):
        """Continue a paused program."""
        self._request({"do": "continue"})

    def set_breakpoints(self, block_ids):
        """Pause before any of these blocks from now on."""
        self.breakpoints = frozenset(block_ids)
        self._request({"do": "breakpoints", "ids": sorted(self.breakpoints)})

    def set_delay(self, seconds: float):
        """Wait this long at each block (0 = full speed)."""
        self.delay = max(0.0, float(seconds))
        self._request({"do": "delay", "seconds": self.delay})


class _MirroredHooks:
    """Where the program is, as its process last said (what a recording asks of a runner's block hooks); the
    blocks it entered come in batches (``ProgramMirror.sampled``), so a recorder's budget is never spent here."""

    def __init__(self, entered=None):
        self.current_block = None
        self.block_budget = 0
        self.entered = entered


class ProgramMirror:
    """The program's runner as the host sees it: its current block, its variables and its blocks' values as
    the program's process last said them (what ``ProgramRunner`` offers a recording, an agent or a window).
    ``entered``: a deque the blocks entered go to, with their ``monotonic_ns`` (a recording's)."""

    def __init__(self, entered=None):
        self.hooks = _MirroredHooks(entered)
        self._variables = {}
        self._values = {}

    @property
    def wants_blocks(self) -> bool:
        """Whether the program's process is to say each block it enters (a recording takes them)."""
        return self.hooks.entered is not None

    def entering(self, block_id):
        """The program said it is at ``block_id`` (a BlockEntered event, when it says every block)."""
        self.hooks.current_block = block_id

    def sampled(self, record: dict):
        """The program's process said what changed of its block, variables, values and blocks entered."""
        if "block" in record:
            block = record["block"]
            self.hooks.current_block = block if isinstance(block, str) else None
        if isinstance(record.get("variables"), dict):
            self._variables = dict(record["variables"])
        if isinstance(record.get("values"), dict):
            self._values = dict(record["values"])
        entered = record.get("entered")
        if self.hooks.entered is not None and isinstance(entered, list):
            self.hooks.entered.extend((stamp, block) for stamp, block in
                                      (pair for pair in entered if isinstance(pair, list) and len(pair) == 2)
                                      if isinstance(stamp, int) and isinstance(block, str))

    def variables_snapshot(self) -> dict:
        """The program's variables (Blockly names, values as people read them)."""
        return dict(self._variables)

    def values_snapshot(self) -> dict:
        """The expression blocks' last values."""
        return dict(self._values)


class LinkHost:
    """Serves one run of a program's process on ``backend`` (the link's backend with the limits and the
    recording around it) and ``link`` (its safe stop). ``emit(event)``: each run event; ``on_safe_stop(failures)``:
    each safe stop done here (a recording notes it)."""

    def __init__(self, process: ProgramProcess, backend, link, control: HostControl, emit, language: str,
                 mirror: ProgramMirror, on_safe_stop=None):
        self.process = process
        self.backend = backend
        self.link = link
        self.control = control
        self.emit = emit
        self.language = language
        self.mirror = mirror
        self.on_safe_stop = on_safe_stop
        self.result = None
        self.refused = None  # the profile's commands could not be made: why, in the run's language
        self.isolated = None  # whether the program's process left the network
        self._gate = threading.Lock()
        self._stopped = False
        self._safe = False  # the robot was made safe after the program's last command
        self._safe_failures = []
        self._subscriptions = {}
        self._goals = {}
        self._goal_ids = iter(range(1, sys.maxsize))
        self._calls = ThreadPoolExecutor(WAITING_CALLS, thread_name_prefix="rockly-host-call")
        self._ended = threading.Event()

    def serve(self, run_code: dict) -> RunFinished:
        """Hand the program to its process, serve it until it ends, make the robot safe; how the run ended."""
        self.control.on_stop = self._stop_now
        self.control.connect(self.process.send)
        self.process.send({"op": "start", "run_code": run_code, "language": self.language,
                           "trace": self.control.trace, "breakpoints": sorted(self.control.breakpoints),
                           "delay": self.control.delay, "entered": self.mirror.wants_blocks})
        reader = threading.Thread(target=self._read, name="rockly-host-serve", daemon=True)
        reader.start()
        if self.control.interrupt.stop_requested:  # stopped while the link opened
            self._stop_now()
            self.process.send({"op": "control", "do": "stop"})
        while not self._ended.wait(0.05):
            if self._stopped and time.monotonic() - self._stopped_at > STOP_GRACE:
                self.process.kill()  # it did not end when told: the wire closes, the reader ends
        reader.join()
        self.control.connect(None)
        self.process.close()
        for unsubscribe in list(self._subscriptions.values()):
            _quietly(unsubscribe)
        self._calls.shutdown(wait=True)
        if self.refused is not None:
            self._safe_stop()
            return None
        if not self._safe:
            self._safe_stop()
        if self.result is None:  # the process ended without saying how (crashed, killed)
            if self._stopped:
                self.result = RunFinished("stopped", self.mirror.hooks.current_block)
            else:
                self.result = RunFinished("error", self.mirror.hooks.current_block,
                                          text("process_ended", self.language,
                                               status=self.process.process.returncode))
            if self._safe_failures:
                self.emit(OutputPrinted(text("unsafe_stop", self.language)))
            self.emit(self.result)
        return self.result

    def _stop_now(self):
        with self._gate:
            if not self._stopped:
                self._stopped, self._stopped_at = True, time.monotonic()
                self._safe_stop_locked()

    def _safe_stop(self) -> list:
        with self._gate:
            return self._safe_stop_locked()

    def _safe_stop_locked(self) -> list:
        if not self._safe:
            self._safe_failures = list(self.link.safe_stop())
            self._safe = True
            if self.on_safe_stop is not None:
                self.on_safe_stop(self._safe_failures)
        return self._safe_failures

    # --- the program's process, read on a thread of its own ---------------------------------------

    def _read(self):
        try:
            while True:
                record = self.process.reader.read()
                if record is None:
                    break
                self._take(record)
        except (OSError, ValueError):  # a broken or overlong line: the process is not to be trusted
            self.process.kill()
        finally:
            self._ended.set()

    def _take(self, record: dict):
        op = record.get("op")
        if op == "call":
            self._call(record)
        elif op == "event":
            event = record_event(record)
            if isinstance(event, BlockEntered):
                self.mirror.entering(event.block_id)
            if isinstance(event, RunFinished):
                self.result = event
            if event is not None:
                self.emit(event)
        elif op == "sample":
            self.mirror.sampled(record)
        elif op == "ready":
            self.isolated = bool(record.get("isolated"))
        elif op == "refused":
            self.refused = str(record.get("text"))

    def _call(self, record: dict):
        name, args, call_id = record.get("name"), record.get("args"), record.get("id")
        if isinstance(record.get("block"), str):  # where the program is: a recording puts the command there
            self.mirror.entering(record["block"])
        if not isinstance(args, list) or not hasattr(self, "_serve_" + str(name)):
            self._reply(call_id, error=error_record(ValueError(f"no robot call {name!r}"), self.language))
        elif name in WAITING:
            self._calls.submit(self._answer, call_id, name, args)
        else:
            self._answer(call_id, name, args)

    def _answer(self, call_id, name: str, args: list):
        try:
            if name in MOVES:
                with self._gate:
                    if self._stopped:
                        raise ProgramStopped("the program was stopped")
                    self._safe = False
                    value = getattr(self, "_serve_" + name)(*args)
            else:
                if self._stopped and name not in AFTER_STOP:
                    raise ProgramStopped("the program was stopped")
                value = getattr(self, "_serve_" + name)(*args)
            if self._stopped and name in WAITING:  # the stop ended the wait: a halted motion is not done
                raise ProgramStopped("the program was stopped")
        except Exception as error:
            self._reply(call_id, error=error_record(error, self.language))
            return
        self._reply(call_id, value=value)

    def _reply(self, call_id, value=None, error=None):
        record = {"op": "reply", "id": call_id}
        if error is not None:
            record["error"] = error
        else:
            record["value"] = value
        try:
            self.process.send(record)
        except (ValueError, TypeError) as unsendable:  # too big for the wire, or no JSON: said as the call's error
            self.process.send({"op": "reply", "id": call_id, "error": error_record(unsendable, self.language)})

    # --- the calls a program's process may make: nothing else reaches the link -------------------

    def _serve_resolve_name(self, name, kind="topics"):
        return self.backend.resolve_name(str(name), str(kind))

    def _serve_publish(self, topic, msg_type, message):
        self.backend.publish(str(topic), msg_type, message)

    def _push(self, record: dict):
        """A message or feedback for the program, from the link's thread: one the wire cannot carry is left out."""
        try:
            self.process.send(record)
        except (ValueError, TypeError):
            pass

    def _serve_subscribe(self, key, topic, msg_type):
        def forward(message):
            self._push({"op": "message", "key": key, "message": message})
        self._subscriptions[key] = self.backend.subscribe(str(topic), msg_type, forward)

    def _serve_unsubscribe(self, key):
        unsubscribe = self._subscriptions.pop(key, None)
        if unsubscribe is not None:
            unsubscribe()

    def _serve_latest(self, topic, msg_type):
        return self.backend.latest(str(topic), msg_type)

    def _serve_wait_for_message(self, topic, msg_type, timeout):
        return self.backend.wait_for_message(str(topic), msg_type, float(timeout))

    def _serve_call_service(self, name, srv_type, request, timeout):
        return self.backend.call_service(str(name), srv_type, request, float(timeout))

    def _serve_send_goal(self, action, action_type, goal, wants_feedback):
        goal_id = next(self._goal_ids)

        def feedback(message):
            self._push({"op": "feedback", "key": goal_id, "message": message})
        self._goals[goal_id] = self.backend.send_goal(str(action), action_type, goal,
                                                      feedback if wants_feedback else None)
        return goal_id

    def _serve_goal_done(self, goal_id):
        return self._goals[goal_id].done()

    def _serve_goal_wait(self, goal_id, timeout):
        outcome = self._goals[goal_id].wait(float(timeout))
        return {"status": outcome.status.value, "result": outcome.result, "text": outcome.text}

    def _serve_goal_cancel(self, goal_id):
        self._goals[goal_id].cancel()

    def _serve_cancel_all_goals(self, action):
        self.backend.cancel_all_goals(str(action))

    def _serve_get_param(self, name, default=None):
        return self.backend.get_param(str(name), default)

    def _serve_set_param(self, name, value):
        self.backend.set_param(str(name), value)

    def _serve_allowed_speed(self, own_speed, turning=False):
        ask = getattr(self.backend, "allowed_speed", None)
        return float(own_speed) if ask is None else ask(float(own_speed), bool(turning))

    def _serve_type_for(self, name, msg_type=None):
        ask = getattr(self.backend, "type_for", None)
        return msg_type if ask is None else ask(str(name), msg_type)

    def _serve_watch(self, waited):
        self.backend.watch(float(waited))

    def _serve_safe_stop(self):
        return self._safe_stop()


def _quietly(call):
    try:
        call()
    except Exception:  # the link may be gone already; the safe stop below does not need it
        pass

