"""The robot as the program's process sees it: a RobotBackend that asks the link host for everything.

The program's process owns no robot link: every publish, look, call and goal goes to the host
(``runtime/link_host.py``) over the wire (``runtime/link_wire.py``), which keeps the limits and the
recording below it and does the safe stop. Subscriptions and action feedback come back as pushed
messages, called on a thread of their own (so a callback may command the robot). ``wait_until`` and
``sleep`` wait here, on the run's own Interrupt, so a stop or a pause holds them at once.
"""
import itertools
import os
import queue
import sys
import threading
import time

from rockly_desktop.robot.interface import GoalHandle, GoalOutcome, GoalStatus, RobotBackend
from rockly_desktop.runtime.link_wire import LineReader, encoded, raised_error

REPLY_POLL_SECONDS = 0.05  # how often a call waiting for the host looks whether the run was stopped
WATCH_SECONDS = 0.2  # how often a wait here asks the host whether the robot is still there


class HostConnection:
    """The program's end of the wire: calls answered by the host, pushed messages, and the host's other
    records (its control requests, the program to run) handed to ``on_record``. The host closing its end
    (it ended, or was killed) ends this process at once: nothing here may go on without it."""

    def __init__(self, sock, on_record):
        self._sock = sock
        self._on_record = on_record
        self._send_lock = threading.Lock()
        self._ids = itertools.count(1)
        self._pending = {}  # call id -> [threading.Event, reply record]
        self._handlers = {}  # ("message", subscription id) or ("feedback", goal id) -> callback
        self._pushed = queue.Queue()
        self._reader = LineReader(sock)

    def start(self):
        """Begin reading the host's records and calling the pushed messages' callbacks."""
        threading.Thread(target=self._read, name="rockly-host-reader", daemon=True).start()
        threading.Thread(target=self._dispatch, name="rockly-host-pushes", daemon=True).start()

    def send(self, record: dict):
        """Send one record to the host; a host that is gone ends this process at once (as its reader does)."""
        line = encoded(record)
        with self._send_lock:
            try:
                self._sock.sendall(line)
            except OSError:  # closed before it took this (it ended before the run began, or was killed)
                os._exit(1)

    def call(self, name: str, args=(), interrupt=None, block=None):
        """Ask the host's backend ``name(*args)`` and return its answer (its error raised here); while waiting,
        a stop of ``interrupt`` raises ProgramStopped (the host ends its side of the wait too). ``block``: the
        block the program is at (what a recording's badges put the command under)."""
        call_id = next(self._ids)
        waiting = [threading.Event(), None]
        self._pending[call_id] = waiting
        record = {"op": "call", "id": call_id, "name": name, "args": list(args)}
        if block is not None:
            record["block"] = block
        try:
            self.send(record)
            while not waiting[0].wait(REPLY_POLL_SECONDS):
                if interrupt is not None:
                    interrupt.check()
        finally:
            self._pending.pop(call_id, None)
        reply = waiting[1]
        if "error" in reply:
            raise raised_error(reply["error"])
        return reply.get("value")

    def on_push(self, kind: str, key, callback):
        """Call ``callback(message)`` for each ``kind`` ('message', 'feedback') pushed for ``key``."""
        self._handlers[(kind, key)] = callback

    def forget(self, kind: str, key):
        """No more calls for ``kind`` and ``key``."""
        self._handlers.pop((kind, key), None)

    def _read(self):
        try:
            while True:
                record = self._reader.read()
                if record is None:
                    break
                op = record.get("op")
                if op == "reply":
                    waiting = self._pending.get(record.get("id"))
                    if waiting is not None:
                        waiting[1] = record
                        waiting[0].set()
                elif op in ("message", "feedback"):
                    self._pushed.put(record)
                else:
                    self._on_record(record)
        except (OSError, ValueError) as broken:  # never from Rockly's own host: say it, for whoever looks
            print(f"rockly: the link host's wire broke: {broken}", file=sys.stderr, flush=True)
        os._exit(1)  # the host is gone: the robot is its to stop, and nothing here may drive on

    def _dispatch(self):
        while True:
            record = self._pushed.get()
            callback = self._handlers.get((record["op"], record.get("key")))
            if callback is not None:
                try:
                    callback(record.get("message"))
                except Exception:  # a callback's failure is its own (as in a ROS subscriber)
                    pass


class RemoteGoal(GoalHandle):
    """A goal the host sent for the program; the host keeps the real handle under ``goal_id``."""

    def __init__(self, backend: "RemoteBackend", goal_id: int):
        self._backend = backend
        self._id = goal_id

    def done(self) -> bool:
        """True once the goal has ended."""
        return bool(self._backend.ask("goal_done", self._id))

    def wait(self, timeout: float) -> GoalOutcome:
        """Wait for the goal's end (the host waits; a stop ends it); RobotTimeout after ``timeout``."""
        outcome = self._backend.ask("goal_wait", self._id, timeout)
        return GoalOutcome(GoalStatus(outcome["status"]), outcome.get("result") or {}, outcome.get("text") or "")

    def cancel(self) -> None:
        """Ask the action server to stop working on this goal."""
        self._backend.ask("goal_cancel", self._id)


class RemoteBackend(RobotBackend):
    """A RobotBackend whose robot is the host's: each call is one round trip on ``host`` (a HostConnection);
    ``interrupt`` is the run's own (its stop and pause hold the waits here)."""

    def __init__(self, host: HostConnection, interrupt):
        self._host = host
        self.interrupt = interrupt
        self.hooks = None  # the runner's block hooks, once it runs: each call names the block the program is at
        self._subscriptions = itertools.count(1)

    def _block(self):
        return None if self.hooks is None else self.hooks.current_block

    def ask(self, name: str, *args):
        """One call of the host's backend."""
        return self._host.call(name, args, self.interrupt, self._block())

    def resolve_name(self, name: str, kind: str = "topics") -> str:
        """``name`` as the robot's middleware resolves it (the host asks it)."""
        return self.ask("resolve_name", name, kind)

    def publish(self, topic: str, msg_type: str, message: dict) -> None:
        """Publish on ``topic`` (within the host's limits)."""
        self.ask("publish", topic, msg_type, message)

    def subscribe(self, topic: str, msg_type: str, callback):
        """Call ``callback(message)`` for each message on ``topic``; returns the unsubscribe function."""
        key = next(self._subscriptions)
        self._host.on_push("message", key, callback)
        self.ask("subscribe", key, topic, msg_type)

        def unsubscribe():
            self._host.forget("message", key)
            self.ask("unsubscribe", key)
        return unsubscribe

    def _watcher(self):
        """What a wait here calls at each step: every ``WATCH_SECONDS`` it asks the host whether the robot is still
        there (the host's link raises RobotConnectionLost for a lost master or node, as its own waits do)."""
        started = time.monotonic()
        asked = [started]

        def watch():
            now = time.monotonic()
            if now - asked[0] >= WATCH_SECONDS:
                asked[0] = now
                self.ask("watch", now - started)
        return watch

    def wait_until(self, predicate, timeout: float) -> bool:
        """Wait here until ``predicate()`` is true (True) or ``timeout`` passes (False); a stop or a lost robot
        raises."""
        watch = self._watcher()

        def watched():
            watch()
            return predicate()
        return self.interrupt.wait_until(watched, timeout)

    def latest(self, topic: str, msg_type: str):
        """The last message the robot sent on ``topic``, or None."""
        return self.ask("latest", topic, msg_type)

    def wait_for_message(self, topic: str, msg_type: str, timeout: float) -> dict:
        """The next message on ``topic`` (the host waits); RobotTimeout after ``timeout``."""
        return self.ask("wait_for_message", topic, msg_type, timeout)

    def call_service(self, name: str, srv_type: str, request: dict, timeout: float) -> dict:
        """Call a service through the host."""
        return self.ask("call_service", name, srv_type, request, timeout)

    def send_goal(self, action: str, action_type: str, goal: dict, feedback=None) -> GoalHandle:
        """Send a goal through the host; ``feedback(message)`` is called here for each feedback."""
        goal_id = self.ask("send_goal", action, action_type, goal, feedback is not None)
        if feedback is not None:
            self._host.on_push("feedback", goal_id, feedback)
        return RemoteGoal(self, goal_id)

    def cancel_all_goals(self, action: str) -> None:
        """Cancel every goal of ``action``."""
        self.ask("cancel_all_goals", action)

    def get_param(self, name: str, default=None):
        """A parameter, or ``default``."""
        return self.ask("get_param", name, default)

    def set_param(self, name: str, value) -> None:
        """Set a parameter."""
        self.ask("set_param", name, value)

    def sleep(self, seconds: float) -> None:
        """Wait ``seconds`` here (a pause holds the clock, a stop or a lost robot raises)."""
        self.interrupt.sleep(seconds, watch=self._watcher())

    def allowed_speed(self, own_speed: float, turning: bool = False) -> float:
        """How fast a motion at the robot's own speed may go under the host's limits."""
        return self.ask("allowed_speed", own_speed, turning)

    def type_for(self, name: str, msg_type: str = None) -> str:
        """The type the robot wants on ``name``."""
        return self.ask("type_for", name, msg_type)
