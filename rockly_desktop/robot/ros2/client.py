"""Rockly's side of the ROS 2 helper: starts the process, sends requests, routes its answers.

One helper per Rockly process (``Ros2Helper.get``), started on first use and ended with
Rockly (``atexit``, or ``close``); a link may keep a spare beside it (``get(spare=True)``),
started and discovered already, that takes over at once when the helper is lost. A reader
thread takes every frame the helper writes: answers wake their caller, events go to the
handlers registered for them. The helper says it is alive every ``wire.HEARTBEAT_SECONDS``;
a watch thread (which never writes, so a full pipe cannot hold it) ends a helper that keeps
Rockly waiting HUNG_AFTER for its next frame (stopped, frozen). When the helper's pipe ends
(it died or was ended), every caller waiting and every later request fail at once with
RobotConnectionLost, and the ``on_lost`` handlers are told (the link replaces it); the helper
itself sends the safe stop as its last act when it can.
"""
import atexit
import itertools
import logging
import re
import subprocess
import threading
import time
from collections import deque
from pathlib import Path

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import ProgramStopped, RobotCommandError, RobotConnectionLost, RobotTimeout
from rockly_desktop.robot.ros2 import wire
from rockly_desktop.robot.ros2.cdr_encoding import MessageEncoder, NotEncodable
from rockly_desktop.robot.ros2.environment import Ros2Settings, Ros2Unavailable, ros2_python

# The helper imports this package from where it is, and nothing else of Rockly's environment
# (a PYTHONPATH would also hand it every package installed beside Rockly).
_BOOTSTRAP = """import importlib.util, sys
spec = importlib.util.spec_from_file_location("rockly_desktop", sys.argv[1] + "/__init__.py",
                                              submodule_search_locations=[sys.argv[1]])
package = sys.modules["rockly_desktop"] = importlib.util.module_from_spec(spec)
spec.loader.exec_module(package)
from rockly_desktop.robot.ros2.helper.node import main
main()
"""
log = logging.getLogger(__name__)

PACKAGE_DIR = Path(__file__).resolve().parents[2]
START_TIMEOUT = 30.0  # loading rclpy and the DDS library, on a busy 2-core machine
POLL_SECONDS = 0.01
STDERR_LINES = 20
MAX_NAMES = 4096  # names whose resolution is kept
# Rockly waiting this long for the next frame (heartbeats come every wire.HEARTBEAT_SECONDS): the helper is hung.
# Within the 2 s promise of a safe stop, with room for the spare's stop; far above a loaded machine's hiccups.
HUNG_AFTER = 1.0
WATCH_SECONDS = 0.1
_COLOURS = re.compile(r"\x1b\[[0-9;]*m")
ROUND_TRIP_SECONDS = 0.5  # how often the round trip to the helper is measured (for the health light)


class _Pending:
    __slots__ = ("done", "ok", "value", "then")

    def __init__(self, then=None):
        self.done = threading.Event()
        self.ok = False
        self.value = None
        self.then = then  # called (ok, value) on the reader thread when the answer comes


class Ros2Helper:
    """The running helper process and its pipes (see ``wire`` for the frames)."""

    _current = None
    _spare = None
    _current_lock = threading.Lock()

    @classmethod
    def get(cls, settings: Ros2Settings = None, spare: bool = False) -> "Ros2Helper":
        """The process's helper with ``settings``; a helper with other settings (or a lost one) is
        ended first, and replaced by the spare when there is one. ``spare``: keep a spare started."""
        settings = settings or Ros2Settings()
        with cls._current_lock:
            helper = cls._current
            if helper is not None and (helper.lost or helper.settings != settings):
                helper.close()
                helper = None
            if helper is None:
                helper = cls._current = cls._take_spare(settings) or cls(settings)
            if spare and (cls._spare is None or cls._spare.lost):
                if cls._spare is not None:
                    cls._spare.close()
                cls._spare = cls(settings, wait=False)  # its process is there now, its start goes on beside
                threading.Thread(target=cls._spare.start_quietly, name="ros2-spare-start", daemon=True).start()
            return helper

    @classmethod
    def running(cls) -> "Ros2Helper | None":
        """The process's helper when it runs (not lost), else None; none is started."""
        helper = cls._current
        return helper if helper is not None and not helper.lost else None

    @classmethod
    def spare(cls) -> "Ros2Helper | None":
        """The spare kept beside the process's helper (it may still be starting), or None."""
        return cls._spare

    @classmethod
    def _take_spare(cls, settings) -> "Ros2Helper | None":
        """The spare, once started, when it has ``settings`` and lives; else None (and it is ended)."""
        spare, cls._spare = cls._spare, None
        if spare is None:
            return None
        try:
            spare.started()
        except Ros2Unavailable:
            return None
        if spare.lost or spare.settings != settings:
            spare.close()
            return None
        return spare

    @classmethod
    def close_current(cls):
        """End the process's helper and its spare, if they run (at exit, and by tests)."""
        with cls._current_lock:
            helpers, cls._current, cls._spare = (cls._current, cls._spare), None, None
        for helper in helpers:
            if helper is not None:
                helper.close()

    @classmethod
    def end(cls, helper: "Ros2Helper"):
        """End ``helper`` (and the spare, when it was the process's); the next ``get`` starts a new one."""
        with cls._current_lock:
            spare = None
            if cls._current is helper:
                cls._current, spare, cls._spare = None, cls._spare, None
        helper.close()
        if spare is not None:
            spare.close()

    def __init__(self, settings: Ros2Settings, wait: bool = True):
        """Start the helper with ``settings``; ``wait`` (the default) until it said hello (``started``)."""
        self.settings = settings
        self.began = time.monotonic()
        self.python = python = ros2_python()
        env = settings.environment()
        env.pop("PYTHONPATH", None)
        env["ROS_PYTHON_CHECK_FIELDS"] = "1"  # a wrong field type is refused, not sent as garbage
        self.process = subprocess.Popen(
            [str(python), "-c", _BOOTSTRAP, str(PACKAGE_DIR)], stdin=subprocess.PIPE,
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env, cwd="/", start_new_session=True)
        atexit.register(self.close)
        self.lost = False
        self.hung = False  # it was ended for keeping Rockly waiting (see HUNG_AFTER)
        self.exit_reason = ""
        self.round_trip = None  # seconds to the helper and back, as last measured
        self._write_lock = threading.Lock()
        self._ids = itertools.count(1)
        self._pending = {}
        self._handlers = {}
        self._lost_handlers = []
        self._failures = deque(maxlen=10)
        self._encoders = {}  # message type -> its MessageEncoder, or None: sent as fields
        self._names = {}  # (name, whether a service) -> the name the helper's node resolves it to, "" refused
        self._stderr = deque(maxlen=STDERR_LINES)
        self._hello = threading.Event()
        self._start_lock = threading.Lock()
        self._start_done = False
        self._start_failure = None
        self._closed = threading.Event()
        self._waiting_since = None  # when the reader began waiting for the next frame; None: it has one
        self.info = {}
        self.said_hello = None  # when (monotonic) the helper said hello: its DDS participant was made
        self._stderr_reader = threading.Thread(target=self._read_errors, name="ros2-helper-stderr", daemon=True)
        self._stderr_reader.start()
        threading.Thread(target=self._read, name="ros2-helper-reader", daemon=True).start()
        if wait:
            self.started()

    def started(self):
        """Wait until the helper said hello (then its watch begins); Ros2Unavailable saying why if it did not."""
        with self._start_lock:
            if not self._start_done:
                self._start_done = True
                if not self._hello.wait(START_TIMEOUT) or self.lost:
                    detail = self.exit_reason or app_local_text("ros2_no_hello", timeout=START_TIMEOUT)
                    self.close()
                    self._start_failure = Ros2Unavailable(
                        f"the ROS 2 helper did not start with {self.python}: {detail}", "helper_failed",
                        python=str(self.python), detail=detail)
                else:
                    threading.Thread(target=self._watch, name="ros2-helper-watch", daemon=True).start()
                    threading.Thread(target=self._measure, name="ros2-helper-round-trip", daemon=True).start()
        if self._start_failure is not None:
            raise self._start_failure

    def discovery_left(self) -> float:
        """Seconds until the helper's DDS participant had ``wire.DISCOVERY_SECONDS`` to discover the others (0 once
        it had): a wait for what the graph holds does not count them."""
        if self.said_hello is None:
            return wire.DISCOVERY_SECONDS
        return max(0.0, self.said_hello + wire.DISCOVERY_SECONDS - time.monotonic())

    def start_quietly(self):
        """``started``, for a spare: a failure is logged (the spare is then not taken)."""
        try:
            self.started()
        except Ros2Unavailable as problem:
            log.warning("the spare ROS 2 helper did not start: %s", problem)

    def on_lost(self, handler):
        """Call ``handler(helper)`` once the helper is lost (on the reader thread: it must not wait)."""
        self._lost_handlers.append(handler)
        if self.lost:
            handler(self)

    # --- liveness
    def _watch(self):
        """End the helper when the reader has waited HUNG_AFTER for its next frame. A watch that woke
        late (this process had no CPU) judges only at its next look, when the reader has caught up."""
        looked = time.monotonic()
        while not self._closed.wait(WATCH_SECONDS) and not self.lost:
            now, since = time.monotonic(), self._waiting_since
            on_time, looked = now - looked < WATCH_SECONDS + HUNG_AFTER / 2, now
            if on_time and since is not None and now - since > HUNG_AFTER:
                self._end_hung(now - since)
                return

    def _end_hung(self, silent: float):
        self.exit_reason = app_local_text("ros2_helper_hung", seconds=f"{silent:.1f}")
        self.hung = True
        log.warning("the ROS 2 helper (pid %s) said nothing for %.1f s: ended", self.process.pid, silent)
        self.process.kill()  # a stopped process too; its pipe's end then tells every waiting caller

    def _measure(self):
        """Time a round trip to the helper every ROUND_TRIP_SECONDS (``round_trip``), off the window's
        thread; a ping of its own, which leaves a failed cast to the command it belongs to (``check``)."""
        while not self._closed.wait(ROUND_TRIP_SECONDS) and not self.lost:
            call_id = next(self._ids)
            pending = self._pending[call_id] = _Pending()
            started = time.perf_counter()
            try:
                self._write((wire.CALL, call_id, "ping", ()))
            except RobotConnectionLost:
                return
            if pending.done.wait(2.0) and pending.ok:
                self.round_trip = time.perf_counter() - started
            else:
                self._pending.pop(call_id, None)

    # --- reading
    def _read_errors(self):
        for line in self.process.stderr:  # without the colours of Fast DDS's log: the lines may be shown
            self._stderr.append(_COLOURS.sub("", line.decode(errors="replace")).rstrip())

    def _read(self):
        stream = self.process.stdout
        try:
            while True:
                self._waiting_since = time.monotonic()
                frame = wire.read_frame(stream)
                self._waiting_since = None
                if frame is None:
                    break
                if frame[0] == wire.REPLY:
                    self._answered(frame)
                else:
                    self._event(frame)
        except Exception as error:  # a frame that cannot be read: the helper cannot be trusted any more
            self._stderr.append(f"unreadable answer: {error}")
        self._ended()

    def _answered(self, frame):
        _kind, call_id, ok, value = frame
        pending = self._pending.pop(call_id, None)
        if pending is not None:
            pending.ok, pending.value = ok, value
            pending.done.set()
            if pending.then is not None:
                pending.then(ok, value)

    def _event(self, frame):
        _kind, kind, key, data = frame
        if kind == "hello":
            if key != wire.PROTOCOL:
                self.exit_reason = app_local_text("ros2_other_protocol", helper=key, rockly=wire.PROTOCOL)
                self.process.kill()
                return
            self.info = data
            self.said_hello = time.monotonic()
            self._hello.set()
        elif kind == "failed":
            self._failures.append(data)
        elif kind != "alive":
            handler = self._handlers.get((kind, key))
            if handler is not None:
                handler(data)

    def _ended(self):
        try:
            code = self.process.wait(timeout=1.0)
        except subprocess.TimeoutExpired:
            code = None
        self._stderr_reader.join(timeout=1.0)  # its last words say why
        last = self._stderr[-1] if self._stderr else ""
        if not self.exit_reason:
            self.exit_reason = (app_local_text("ros2_exit_code_said", code=code, last=last) if last
                                else app_local_text("ros2_exit_code", code=code))
        self.lost = True
        self._hello.set()
        for pending in list(self._pending.values()):
            pending.done.set()
        self._pending.clear()
        for handler in list(self._lost_handlers) if not self._closed.is_set() else []:  # not when Rockly ended it
            try:
                handler(self)
            except Exception:  # one handler's failure must not keep the others from hearing it
                log.exception("a handler of the lost ROS 2 helper failed")

    # --- requests
    def _write(self, frame):
        data = wire.encode(frame)
        with self._write_lock:
            try:
                self.process.stdin.write(data)
                self.process.stdin.flush()
            except (BrokenPipeError, ValueError, OSError):
                raise self.lost_error() from None

    def lost_error(self) -> RobotConnectionLost:
        """The error a command gets once the helper is gone."""
        reason = self.exit_reason or app_local_text("ros2_pipe_closed")
        return RobotConnectionLost(app_local_text("ros2_helper_ended", reason=reason))

    def check(self):
        """Raise RobotConnectionLost when the helper is gone, or a failure of an earlier cast."""
        if self.lost:
            raise self.lost_error()
        if self._failures:
            raise _error(*self._failures.popleft())

    def drop_failures(self) -> list:
        """Let go of the earlier casts' failures nobody was told yet (logged): the safe stop's commands
        must not be refused for a program's last bad message. Returns them."""
        dropped = []
        while self._failures:
            dropped.append(self._failures.popleft())
            log.warning("a command before the safe stop failed: %s", _error(*dropped[-1]))
        return dropped

    def cast(self, op: str, *args):
        """Send a request that gets no answer (its failure is raised by a later ``check``)."""
        self.check()
        self._write((wire.CAST, 0, op, args))

    def send(self, op: str, *args, then=None):
        """Send request ``op`` without waiting and apart from the casts' failures (another user of the helper,
        e.g. the robot agent's topics beside a link, neither takes nor gets them): ``then(ok, value)`` is called
        with its answer on the reader thread. RobotConnectionLost when the helper is gone."""
        if self.lost:
            raise self.lost_error()
        call_id = next(self._ids)
        self._pending[call_id] = _Pending(then=then)
        self._write((wire.CALL, call_id, op, args))

    def publish(self, topic: str, msg_type: str, message):
        """Publish without waiting (a failure is raised by a later ``check``): as CDR bytes encoded
        here once the helper gave the type's layout, else as fields for the helper to check."""
        encoder = self._encoders.get(msg_type)
        if msg_type not in self._encoders:
            self.ask_layout(msg_type)
        elif encoder is not None:
            try:
                raw = encoder.encode(message)
            except NotEncodable:
                pass  # the helper checks it, and says what is wrong
            else:
                self.cast("publish_raw", topic, msg_type, raw)
                return
        self.cast("publish", topic, msg_type, message)

    def resolved(self, name: str, service: bool = False, interrupt=None) -> str:
        """``name`` as the helper's node resolves a topic or action (a service: ``service``) of that
        name (``op_resolve``), asked once per name; RobotCommandError for a name ROS 2 refuses."""
        key = (name, service)
        found = self._names.get(key)
        if found is None:
            if len(self._names) >= MAX_NAMES:  # a program making names without end keeps no more
                self._names.clear()
            found = self._names[key] = self.call("resolve", name, service, interrupt=interrupt) or ""
        if not found:
            raise RobotCommandError(app_local_text("ros_bad_name", name=name))
        return found

    def encoder(self, msg_type: str):
        """``msg_type``'s MessageEncoder once the helper gave its layout, else None (sent as fields)."""
        return self._encoders.get(msg_type)

    def ask_layout(self, msg_type: str):
        """Ask the helper for ``msg_type``'s layout (once) without waiting; its messages go as fields until it comes."""
        if msg_type in self._encoders:
            return
        self._encoders[msg_type] = None

        def answered(ok, layout):
            if ok and layout is not None:
                try:
                    self._encoders[msg_type] = MessageEncoder(layout)
                except ValueError:  # a layout this side cannot follow: the type goes as fields
                    pass
        call_id = next(self._ids)
        self._pending[call_id] = _Pending(then=answered)
        self._write((wire.CALL, call_id, "layout", (msg_type,)))

    def call(self, op: str, *args, interrupt=None, timeout: float = None):
        """Send a request and wait for its answer (interruptibly when ``interrupt`` is given).

        A stop raises ProgramStopped, the helper's death RobotConnectionLost (at once), a
        failed request RobotTimeout or RobotCommandError with the helper's text.
        """
        self.check()
        call_id = next(self._ids)
        pending = self._pending[call_id] = _Pending()
        self._write((wire.CALL, call_id, op, args))
        deadline = None if timeout is None else time.monotonic() + timeout
        while not pending.done.wait(POLL_SECONDS if interrupt is not None else 0.1):
            if interrupt is not None and interrupt.stop_requested:
                self._pending.pop(call_id, None)
                raise ProgramStopped("the program was stopped")
            if deadline is not None and time.monotonic() > deadline:
                self._pending.pop(call_id, None)
                raise RobotTimeout(app_local_text("ros2_helper_timeout", op=op, timeout=timeout))
        if not pending.ok:
            if self.lost and pending.value is None:
                raise self.lost_error()
            raise _error(*pending.value)
        return pending.value

    def on(self, kind: str, key, handler):
        """Call ``handler(data)`` (on the reader thread) for each ``kind`` event about ``key``."""
        self._handlers[(kind, key)] = handler

    def off(self, kind: str, key):
        """Stop calling the handler of ``kind`` events about ``key``."""
        self._handlers.pop((kind, key), None)

    def new_id(self) -> int:
        """A fresh id for a subscription or a goal."""
        return next(self._ids)

    def close(self):
        """End the helper: its stdin closes, it does the safe stop and leaves (killed after 3 s; at once
        when a write to it hangs: a helper that does not read cannot hear the close)."""
        self._closed.set()
        if self._write_lock.acquire(timeout=1.0):
            try:
                self.process.stdin.close()
            except OSError:
                pass  # it is gone already
            finally:
                self._write_lock.release()
        else:
            self.process.kill()
        try:
            self.process.wait(timeout=3.0)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        atexit.unregister(self.close)


def words(said):
    """The helper's words (``wire.said``) as Rockly's catalogue text, or the plain text it sent."""
    if isinstance(said, tuple):
        key, values = said
        return app_local_text(key, **values)
    return said


def _error(kind: str, said) -> RobotCommandError:
    text = words(said)
    return RobotTimeout(text) if kind == "timeout" else RobotCommandError(text)
