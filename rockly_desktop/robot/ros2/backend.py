"""The RobotBackend on ROS 2: topics, services, actions and parameters through the helper process.

Every wait polls in 10 ms steps, so a stop request ends it at once, and fails at once with
RobotConnectionLost when the helper process is gone. Publishing is one-way after a topic's
first message (which waits for the publisher to match its subscribers); a failure of a
one-way request is raised by the next command.
"""
import threading
import time

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import RobotCommandError, RobotTimeout
from rockly_desktop.core.message_arrays import as_lists
from rockly_desktop.robot.interface import GoalHandle, GoalOutcome, GoalStatus, RobotBackend
from rockly_desktop.robot.next_message import next_message
from rockly_desktop.robot.ros2.client import words

POLL_SECONDS = 0.01


class Ros2Graph:
    """What runs share over one helper: subscriptions by topic, the topics published, the
    last message this node sent per topic, and who watches service calls (thread-safe)."""

    def __init__(self, helper):
        self.helper = helper
        self._lock = threading.Lock()
        self._topics = {}
        self.published = set()
        self.actions_ready = set()  # actions a goal reached: later goals need no answer before they go
        self.sent = {}  # topic -> (when, message) this node last published
        self.service_watchers = []

    def topic(self, topic: str, msg_type: str) -> "Ros2Topic":
        """The shared subscription to ``topic`` (``msg_type`` None: the graph's type)."""
        with self._lock:
            entry = self._topics.get(topic)
            if entry is None:
                entry = Ros2Topic(self.helper, topic, msg_type)
                self._topics[topic] = entry
            return entry

    def publish(self, topic: str, msg_type: str, message: dict, interrupt=None):
        """Publish; a topic's first message waits for the helper (publisher made, subscribers matched)."""
        if topic in self.published:
            self.helper.publish(topic, msg_type, message)
        else:
            self.helper.call("publish_first", topic, msg_type, message, interrupt=interrupt)
            self.published.add(topic)
            self.helper.ask_layout(msg_type)  # the next messages go encoded
        self.sent[topic] = (time.monotonic(), message)

    def close(self):
        """Stop every subscription (the helper stays)."""
        with self._lock:
            topics, self._topics = list(self._topics.values()), {}
        for entry in topics:
            entry.close()


class Ros2Topic:
    """One subscription in the helper: the latest message and the callbacks fanned out to.

    The helper sends a message's arrays of numbers compact (``array.array``): ``callbacks`` and
    ``latest`` get them as lists (``as_lists``, what a program works with), ``raw_callbacks`` as they
    came (the state feed: a camera's 1 MB image stays 1 MB in the state store)."""

    def __init__(self, helper, topic, msg_type):
        self._helper = helper
        self.name = topic
        self.sid = helper.new_id()
        self._latest = None
        self._latest_lists = (None, None)  # (the latest message as it came, as lists) once asked
        self.received_at = None
        self.callbacks = []
        self.raw_callbacks = []
        helper.on("msg", self.sid, self._on_message)
        try:
            self.msg_type = helper.call("subscribe", self.sid, topic, msg_type)
        except Exception:
            helper.off("msg", self.sid)
            raise

    @property
    def latest(self):
        """The newest message as a dict of lists, or None."""
        message = self._latest
        came, lists = self._latest_lists
        if came is not message:
            lists = None if message is None else as_lists(message)
            self._latest_lists = (message, lists)
        return lists

    def _on_message(self, message):
        self._latest = message
        self.received_at = time.monotonic()
        for callback in list(self.raw_callbacks):
            callback(message)
        if self.callbacks:
            data = as_lists(message)
            for callback in list(self.callbacks):
                callback(data)

    def close(self):
        self._helper.off("msg", self.sid)
        if not self._helper.lost:
            self._helper.cast("unsubscribe", self.sid)


class Ros2GoalHandle(GoalHandle):
    """A goal the helper sent; its end comes as a 'goal_end' event."""

    def __init__(self, backend, gid, action):
        self._backend = backend
        self._gid = gid
        self._action = action
        self.finished = threading.Event()
        self.outcome = None

    def ended(self, data):
        """The helper's (status, result, text) for this goal."""
        status, result, said = data
        self.outcome = GoalOutcome(GoalStatus(status), result, words(said))
        self.finished.set()

    def done(self) -> bool:
        """True once the goal reached a terminal state."""
        return self.finished.is_set()

    def wait(self, timeout: float) -> GoalOutcome:
        """Wait (interruptibly, failing at once when the helper is gone) for the goal's end."""
        if not self._backend.wait_for_event(self.finished, timeout):
            raise RobotTimeout(app_local_text("sim_action_timeout", action=self._action, timeout=timeout))
        return self.outcome

    def cancel(self) -> None:
        """Ask the action server to stop this goal."""
        if not self.finished.is_set():
            self._backend.graph.helper.cast("cancel_goal", self._gid)


class Ros2Backend(RobotBackend):
    """A RobotBackend over a Ros2Graph; ``interrupt`` ends its waits. ``graph`` may be a function
    ``graph(interrupt)`` giving it at the first command (a link whose helper is being replaced)."""

    def __init__(self, graph, interrupt):
        self._graph = graph
        self.interrupt = interrupt

    @property
    def graph(self) -> Ros2Graph:
        """The graph this backend works through (the same for all its commands)."""
        if callable(self._graph):
            self._graph = self._graph(self.interrupt)
        return self._graph

    @property
    def _helper(self):
        return self.graph.helper

    def _check(self):
        self.interrupt.check()
        self._helper.check()

    def watch(self, waited: float) -> None:
        """Raise when the helper is lost (or the run stopped)."""
        self._check()

    def wait_until(self, predicate, timeout: float) -> bool:
        """Poll ``predicate`` until true (True) or ``timeout`` (False); a stop or a lost helper raises."""
        deadline = time.monotonic() + timeout
        while True:
            self._check()
            if predicate():
                return True
            if time.monotonic() >= deadline:
                return False
            self.interrupt.nap(POLL_SECONDS)

    def wait_for_event(self, event: threading.Event, timeout: float) -> bool:
        """Like wait_until for an Event, but wakes the moment it is set."""
        deadline = time.monotonic() + timeout
        while True:
            self._check()
            remaining = deadline - time.monotonic()
            if event.wait(max(0.0, min(POLL_SECONDS, remaining))):
                return True
            if remaining <= 0:
                return False

    def resolve_name(self, name: str, kind: str = "topics") -> str:
        """``name`` as the helper's node resolves it (rclpy's expansion and remapping; an action's name
        resolves as a topic's); RobotCommandError for a name ROS 2 refuses. Asked once per name."""
        self._check()
        return self._helper.resolved(str(name), kind == "services", self.interrupt)

    def publish(self, topic: str, msg_type: str, message: dict) -> None:
        """Publish ``message`` on ``topic`` (reliable unless the profile's ``ros_interface.qos`` says otherwise)."""
        self._check()
        self.graph.publish(topic, msg_type, message, self.interrupt)

    def topic_types(self, topic: str) -> list:
        """The types the ROS 2 graph lists for ``topic`` (its publishers' and subscribers'), as pkg/msg/Type."""
        self._check()
        return [type_name for name, types, _count in self._helper.call("graph", interrupt=self.interrupt)["topics"]
                if name == topic for type_name in types]

    def subscribe(self, topic: str, msg_type: str, callback):
        """Call ``callback(dict)`` per message; returns the unsubscribe function."""
        self._check()
        entry = self.graph.topic(topic, msg_type)
        entry.callbacks.append(callback)

        def unsubscribe():
            if callback in entry.callbacks:
                entry.callbacks.remove(callback)
        return unsubscribe

    def latest(self, topic: str, msg_type: str):
        """The last message seen on ``topic`` (subscribing on first use) or sent by this node, or None."""
        self._check()
        entry = self.graph.topic(topic, msg_type)
        sent_at, sent = self.graph.sent.get(topic, (None, None))
        if sent is not None and (entry.received_at is None or sent_at >= entry.received_at):
            return sent
        return entry.latest

    def wait_for_message(self, topic: str, msg_type: str, timeout: float) -> dict:
        """The next message on ``topic``; RobotTimeout naming it after ``timeout`` (counted once a fresh helper had
        its discovery: a robot's publisher may not be known in its first seconds)."""
        return next_message(self, topic, msg_type, timeout, grace=self._helper.discovery_left())

    def call_service(self, name: str, srv_type: str, request: dict, timeout: float) -> dict:
        """Call a service; Stop, a lost helper and ``timeout`` end the wait at once."""
        self._check()
        response = self._helper.call("service", name, srv_type, request, timeout, interrupt=self.interrupt)
        for watcher in list(self.graph.service_watchers):
            watcher(name, "service", {"request": request, "response": response})
        return response

    def send_goal(self, action: str, action_type: str, goal: dict, feedback=None) -> GoalHandle:
        """Send a goal (the helper waits up to 5 s for the action server); feedback as dicts."""
        self._check()
        helper = self._helper
        gid = helper.new_id()
        handle = Ros2GoalHandle(self, gid, action)
        if feedback is not None:
            helper.on("feedback", gid, feedback)
        helper.on("goal_end", gid, lambda data: (helper.off("feedback", gid), helper.off("goal_end", gid),
                                                  handle.ended(data)))
        if action in self.graph.actions_ready:
            helper.cast("goal", gid, action, action_type, goal)  # a failure ends the goal (aborted, with why)
            return handle
        try:
            helper.call("goal", gid, action, action_type, goal, interrupt=self.interrupt)
        except Exception:
            helper.off("feedback", gid)
            helper.off("goal_end", gid)
            raise
        self.graph.actions_ready.add(action)
        return handle

    def cancel_all_goals(self, action: str) -> None:
        """Cancel every goal on the action server (a cancel request with a zero goal id)."""
        self._check()
        self._helper.cast("cancel_all", action)

    def get_param(self, name: str, default=None):
        """A node's parameter (``node:param``; ``/node/param`` means the same), or ``default``."""
        self._check()
        found, value = self._helper.call("get_param", *_node_and_param(name), interrupt=self.interrupt)
        return value if found else default

    def set_param(self, name: str, value) -> None:
        """Set a node's parameter (``node:param``)."""
        self._check()
        self._helper.call("set_param", *_node_and_param(name), value, interrupt=self.interrupt)

    def sleep(self, seconds: float) -> None:
        """Wait ``seconds`` (pausable, stoppable; a lost helper ends it at once)."""
        self.interrupt.sleep(seconds, watch=self._helper.check)


def _node_and_param(name: str) -> tuple:
    """ROS 2 parameters live on nodes: ``node:param``, or ROS 1's ``/node/param`` read the same way."""
    if ":" in name:
        node, param = name.split(":", 1)
    else:
        node, _slash, param = name.strip("/").rpartition("/")
    if not node or not param:
        raise RobotCommandError(app_local_text("ros2_bad_parameter_name", name=name))
    return node, param
