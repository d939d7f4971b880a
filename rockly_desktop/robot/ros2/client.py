"""Rockly's side of the ROS 2 helper: starts the process, sends requests, routes its answers.

One helper per Rockly process (``Ros2Helper.get``), started on first use and ended with
Rockly (``atexit``, or ``close``). A reader thread takes every frame the helper writes:
answers wake their caller, events go to the handlers registered for them. When the helper's
pipe ends (it died), every caller waiting and every later request fail at once with
RobotConnectionLost; the helper itself sends the safe stop as its last act when it can.
"""
import atexit
import itertools
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
from rockly_desktop.robot.ros2.node import main
main()
"""
PACKAGE_DIR = Path(__file__).resolve().parents[2]
START_TIMEOUT = 30.0  # loading rclpy and the DDS library, on a busy 2-core machine
POLL_SECONDS = 0.01
STDERR_LINES = 20
MAX_NAMES = 4096  # names whose resolution is kept


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
    _current_lock = threading.Lock()

    @classmethod
    def get(cls, settings: Ros2Settings = None) -> "Ros2Helper":
        """The process's helper with ``settings``; a helper with other settings is ended first."""
        settings = settings or Ros2Settings()
        with cls._current_lock:
            helper = cls._current
            if helper is not None and (helper.lost or helper.settings != settings):
                helper.close()
                helper = None
            if helper is None:
                helper = cls._current = cls(settings)
            return helper

    @classmethod
    def close_current(cls):
        """End the process's helper, if one runs (at exit, and by tests)."""
        with cls._current_lock:
            helper, cls._current = cls._current, None
        if helper is not None:
            helper.close()

    @classmethod
    def end(cls, helper: "Ros2Helper"):
        """End ``helper``; the next ``get`` starts a new one if it was the process's."""
        with cls._current_lock:
            if cls._current is helper:
                cls._current = None
        helper.close()

    def __init__(self, settings: Ros2Settings):
        self.settings = settings
        python = ros2_python()
        env = settings.environment()
        env.pop("PYTHONPATH", None)
        env["ROS_PYTHON_CHECK_FIELDS"] = "1"  # a wrong field type is refused, not sent as garbage
        self.process = subprocess.Popen(
            [str(python), "-c", _BOOTSTRAP, str(PACKAGE_DIR)], stdin=subprocess.PIPE,
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env, cwd="/", start_new_session=True)
        self.lost = False
        self.exit_reason = ""
        self._write_lock = threading.Lock()
        self._ids = itertools.count(1)
        self._pending = {}
        self._handlers = {}
        self._failures = deque(maxlen=10)
        self._encoders = {}  # message type -> its MessageEncoder, or None: sent as fields
        self._names = {}  # (name, whether a service) -> the name the helper's node resolves it to, "" refused
        self._stderr = deque(maxlen=STDERR_LINES)
        self._hello = threading.Event()
        self.info = {}
        self._stderr_reader = threading.Thread(target=self._read_errors, name="ros2-helper-stderr", daemon=True)
        self._stderr_reader.start()
        threading.Thread(target=self._read, name="ros2-helper-reader", daemon=True).start()
        if not self._hello.wait(START_TIMEOUT) or self.lost:
            detail = self.exit_reason or app_local_text("ros2_no_hello", timeout=START_TIMEOUT)
            self.close()
            raise Ros2Unavailable(f"the ROS 2 helper did not start with {python}: {detail}",
                                  "helper_failed", python=str(python), detail=detail)
        atexit.register(self.close)

    # --- reading
    def _read_errors(self):
        for line in self.process.stderr:
            self._stderr.append(line.decode(errors="replace").rstrip())

    def _read(self):
        stream = self.process.stdout
        try:
            while True:
                frame = wire.read_frame(stream)
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
            self._hello.set()
        elif kind == "failed":
            self._failures.append(data)
        else:
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

    def cast(self, op: str, *args):
        """Send a request that gets no answer (its failure is raised by a later ``check``)."""
        self.check()
        self._write((wire.CAST, 0, op, args))

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
        """End the helper: its stdin closes, it does the safe stop and leaves (killed after 3 s)."""
        try:
            with self._write_lock:
                self.process.stdin.close()
        except OSError:
            pass  # it is gone already
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
