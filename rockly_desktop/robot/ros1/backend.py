"""The RobotBackend on ROS 1: rospy topics, services and actionlib, by ROS names and types.

Every wait polls in 10 ms steps so a stop request ends it at once, and fails with
RobotConnectionLost within ~2 s when the master stops answering, or when the robot node
it waits on is gone (see liveness). Publishers, subscribers, service proxies and action
clients are made once per name and shared by all runs.
"""
import threading
import time
import xmlrpc.client

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import DefinitionNotLearnt, RobotCommandError, RobotConnectionLost, RobotTimeout
from rockly_desktop.robot.interface import GoalHandle, GoalOutcome, GoalStatus, RobotBackend
from rockly_desktop.robot.next_message import next_message
from rockly_desktop.robot.ros1.connection import ask_master
from rockly_desktop.robot.ros1.live_definitions import topic_definition
from rockly_desktop.robot.ros1.liveness import LOOK_SECONDS, Dependencies, NodeLiveness
from rockly_desktop.robot.ros1.message_values import from_message, to_message
from rockly_desktop.robot.ros1.service_calls import ServiceCaller

POLL_SECONDS = 0.01
# A new publisher waits at most this long for the subscribers the master lists to connect: each connects
# through the master, its own node and this one (three processes), over 1 s on a busy robot or computer.
FIRST_PUBLISH_WAIT = 5.0

_ACTIONLIB_STATUS = {3: GoalStatus.SUCCEEDED, 4: GoalStatus.ABORTED, 2: GoalStatus.PREEMPTED,
                     8: GoalStatus.PREEMPTED, 5: GoalStatus.REJECTED, 9: GoalStatus.ABORTED}


class RosGraph:
    """Shared rospy endpoints of this process, made on first use (thread-safe)."""

    def __init__(self, connection, types):
        import rospy

        self._rospy = rospy
        self.connection = connection
        self.types = types
        self._lock = threading.Lock()
        self._publishers = {}
        self._published = set()
        self._topics = {}
        self._services = {}
        self._actions = {}
        self.goals_sent = set()  # actions whose goal publisher has waited for its subscribers
        self.unreached = {}  # topic -> how many subscribers answered when a whole wait for them ended unconnected
        self.available_services = set()
        self.sent = {}  # topic -> (when, message) this node last published (commands like /head/move)
        # Told of each service call this node makes, as (service, "service", {request, response}):
        # calls cannot be watched on the graph, so a panel showing one (a tablet's last question)
        # learns of it here, as the simulator's world tap reports it.
        self.service_watchers = []
        self.service_calls = ServiceCaller()
        self.liveness = NodeLiveness(connection.master_uri, rospy.get_name())

    def message_class(self, topic, msg_type):
        """The class of ``msg_type``; a type no package here defines is learnt from a publisher of
        ``topic`` (its connection header says the definition), else RobotCommandError as before."""
        try:
            return self.types.message_class(msg_type)
        except RobotCommandError as unknown:
            try:
                learnt = topic_definition(self.connection.master_uri, self._rospy.resolve_name(topic))
            except DefinitionNotLearnt:
                raise unknown from None
            if learnt.type_name != msg_type:
                raise unknown from None
            self.types.learn(msg_type, learnt.full_text)
            return self.types.message_class(msg_type)

    def publisher(self, topic, msg_type):
        """The shared publisher of ``topic``, and whether this is its first publish."""
        message_class = self.message_class(topic, msg_type) if topic not in self._publishers else None
        with self._lock:
            publisher = self._publishers.get(topic)
            if publisher is None:
                publisher = self._publishers[topic] = self._rospy.Publisher(
                    topic, message_class or self.types.message_class(msg_type), queue_size=10)
            first = topic not in self._published
            self._published.add(topic)
            return publisher, first

    def subscriber_count(self, topic) -> int:
        """How many other nodes subscribe to ``topic`` and answer (a killed node the master still
        lists does not count); 0 if the master does not answer."""
        state = self.liveness.subscribers(topic)
        return state[1] if state is not None else 0

    def topic(self, topic, msg_type):
        """The shared subscription to ``topic``: latest message and callbacks."""
        message_class = self.message_class(topic, msg_type) if topic not in self._topics else None
        with self._lock:
            entry = self._topics.get(topic)
            if entry is None:
                entry = self._topics[topic] = _Topic(self._rospy, topic, message_class or self.types.message_class(
                    msg_type))
            return entry

    def service(self, name, srv_type):
        with self._lock:
            proxy = self._services.get(name)
            if proxy is None:
                proxy = self._services[name] = self._rospy.ServiceProxy(
                    name, self.types.service_class(srv_type), persistent=True)
            return proxy

    def forget_service(self, name):
        """Drop a service's connection after a failure; the next call connects anew."""
        with self._lock:
            proxy = self._services.pop(name, None)
            self.available_services.discard(name)
        if proxy is not None:
            proxy.close()

    def action_client(self, action, action_type):
        import actionlib

        with self._lock:
            client = self._actions.get(action)
            if client is None:
                action_class = self.types.action_classes(action_type)[0]
                client = self._actions[action] = actionlib.SimpleActionClient(action, action_class)
            return client


class _Topic:
    """One shared rospy subscriber: keeps the latest message and fans out to callbacks.

    Messages are decoded to dicts only when someone asks: ``callbacks`` get dicts,
    ``raw_callbacks`` the rospy message objects (a state feed at 1 kHz stays cheap).
    """

    def __init__(self, rospy, topic, message_class):
        self._latest = None
        self.received_at = None
        self.callbacks = []
        self.raw_callbacks = []
        self._subscriber = rospy.Subscriber(topic, message_class, self._on_message)
        self.name = self._subscriber.resolved_name

    @property
    def latest(self):
        """The newest message as a dict, or None."""
        message = self._latest
        return from_message(message) if message is not None else None

    def _on_message(self, message):
        self._latest = message
        self.received_at = time.monotonic()
        for callback in list(self.raw_callbacks):
            callback(message)
        if self.callbacks:
            data = from_message(message)
            for callback in list(self.callbacks):
                callback(data)


class Ros1GoalHandle(GoalHandle):
    """A goal sent through an actionlib SimpleActionClient."""

    def __init__(self, backend, client, action, finished: threading.Event):
        """``finished`` is set by the client's done callback (the goal reached a terminal state)."""
        self._backend = backend
        self._client = client
        self._action = action
        self._finished = finished

    def done(self) -> bool:
        """True once the goal reached a terminal state."""
        return self._finished.is_set()

    def wait(self, timeout: float) -> GoalOutcome:
        """Wait for the goal's end (interruptible, waking the moment it ends, failing when the
        action server's node is gone); its status and result."""
        status = self._client.action_client.status_sub.resolved_name
        if not self._backend.wait_for_event(self._finished, timeout, depends=(status,)):
            raise RobotTimeout(app_local_text("sim_action_timeout", action=self._action, timeout=timeout))
        result = self._client.get_result()
        return GoalOutcome(_ACTIONLIB_STATUS[self._client.get_state()],
                           from_message(result) if result is not None else {}, self._client.get_goal_status_text())

    def cancel(self) -> None:
        """Ask the action server to stop this goal."""
        self._client.cancel_goal()


class Ros1Backend(RobotBackend):
    """A RobotBackend over a RosGraph; ``interrupt`` ends its waits."""

    def __init__(self, graph: RosGraph, interrupt):
        self.graph = graph
        self.interrupt = interrupt
        self._dependencies = Dependencies(graph.liveness)

    def _check(self):
        self.interrupt.check()
        if self.graph.connection.lost:
            raise RobotConnectionLost(app_local_text("ros_connection_lost", master=self.graph.connection.master_uri))

    def _check_waiting(self, started: float, depends=()):
        """``_check``, and once a wait has lasted LOOK_SECONDS, that the nodes it depends on live."""
        self._check()
        if time.monotonic() - started >= LOOK_SECONDS:
            topic = self._dependencies.gone(depends)
            if topic is not None:
                raise RobotConnectionLost(app_local_text("ros_node_gone", topic=topic))

    def watch(self, waited: float) -> None:
        """Raise when the master is lost or, for a wait of ``waited`` s, a node listened to is gone."""
        self._check_waiting(time.monotonic() - waited)

    def wait_until(self, predicate, timeout: float, depends=()) -> bool:
        """Poll ``predicate`` until true (True) or ``timeout`` (False); stop, a lost master or a
        lost node this wait depends on (``depends`` and the topics listened to) raises."""
        started = time.monotonic()
        deadline = started + timeout
        while True:
            self._check_waiting(started, depends)
            if predicate():
                return True
            if time.monotonic() >= deadline:
                return False
            self.interrupt.nap(POLL_SECONDS)

    def wait_for_event(self, event: threading.Event, timeout: float, depends=()) -> bool:
        """Like wait_until for an Event, but wakes the moment it is set (no polling delay)."""
        started = time.monotonic()
        deadline = started + timeout
        while True:
            self._check_waiting(started, depends)
            remaining = deadline - time.monotonic()
            if event.wait(max(0.0, min(POLL_SECONDS, remaining))):
                return True
            if remaining <= 0:
                return False

    def resolve_name(self, name: str, kind: str = "topics") -> str:
        """``name`` as rospy resolves it for a publisher, subscriber or service proxy (this node's
        namespace, ``~`` its own name, the command line's remappings); an action as actionlib does
        (remapped first, then resolved). RobotCommandError for a name rospy or the master refuses
        (empty; holding a space or a colon: the master registers it nowhere)."""
        import rospy

        name = str(name)
        resolved = rospy.resolve_name(rospy.remap_name(name) if kind == "actions" else name) if name else ""
        if not resolved or " " in resolved or ":" in resolved:
            raise RobotCommandError(app_local_text("ros_bad_name", name=name))
        return resolved

    def connect_publisher(self, topic: str, msg_type: str):
        """The publisher of ``topic``; on first use, or while nobody is connected yet, wait (≤ FIRST_PUBLISH_WAIT)
        until the subscribers the master lists have connected."""
        self._check()
        publisher, first = self.graph.publisher(topic, msg_type)
        if first or publisher.get_num_connections() == 0:
            self._wait_for_subscribers(publisher)
        return publisher

    def _wait_for_subscribers(self, publisher):
        """Wait (≤ FIRST_PUBLISH_WAIT) until ``publisher`` is connected to every subscriber the master lists that
        answers. Subscribers a whole wait ended without (one of another type, one that cannot reach this computer's
        address) are not waited for again, unless the master lists more of them."""
        topic = publisher.resolved_name
        expected = [self.graph.subscriber_count(topic)]
        if expected[0] and self.graph.unreached.get(topic) == expected[0]:
            return

        def all_connected() -> bool:
            if publisher.get_num_connections() < expected[0]:
                return False
            # enough connections: but one may be a subscriber that came meanwhile (this node's own state feed
            # following the new topic) while a listed one is still connecting; counted again, the master says
            expected[0] = self.graph.subscriber_count(topic)
            return publisher.get_num_connections() >= expected[0]

        if self.wait_until(all_connected, FIRST_PUBLISH_WAIT):
            self.graph.unreached.pop(topic, None)
        else:
            self.graph.unreached[topic] = expected[0]

    def publish(self, topic: str, msg_type: str, message: dict) -> None:
        """Publish on ``topic`` (a new publisher first waits for its subscribers to connect)."""
        publisher = self.connect_publisher(topic, msg_type)  # on first use, or its first message is lost
        publisher.publish(to_message(publisher.data_class, message))
        self.graph.sent[topic] = (time.monotonic(), message)

    def _type_of(self, topic: str, msg_type):
        """``msg_type``, or (when None) the type the master knows for ``topic``."""
        if msg_type:
            return msg_type
        try:
            types = dict(ask_master(self.graph.connection.master_uri, "getTopicTypes"))
        except (OSError, xmlrpc.client.Error):
            types = {}
        if topic not in types:
            raise RobotTimeout(app_local_text("ros_no_topic", topic=topic))
        return types[topic]

    def subscribe(self, topic: str, msg_type: str, callback):
        """Call ``callback(dict)`` per message; returns the unsubscribe function."""
        self._check()
        entry = self.graph.topic(topic, self._type_of(topic, msg_type))
        entry.callbacks.append(callback)
        no_longer_depend = self._dependencies.listen(entry.name)

        def unsubscribe():
            if callback in entry.callbacks:
                entry.callbacks.remove(callback)
                no_longer_depend()
        return unsubscribe

    def latest(self, topic: str, msg_type: str):
        """The last message seen on ``topic`` (subscribing on first use) or sent by this node, or None."""
        self._check()
        entry = self.graph.topic(topic, self._type_of(topic, msg_type))
        sent_at, sent = self.graph.sent.get(topic, (None, None))
        if sent is not None and (entry.received_at is None or sent_at >= entry.received_at):
            return sent  # our own command is newer than what came back (or nothing came yet)
        return entry.latest

    def wait_for_message(self, topic: str, msg_type: str, timeout: float) -> dict:
        """The next message on ``topic``; RobotTimeout naming it after ``timeout``."""
        return next_message(self, topic, msg_type, timeout)

    def call_service(self, name: str, srv_type: str, request: dict, timeout: float) -> dict:
        """Call a service; Stop, a lost master and ``timeout`` end the wait at once (see service_calls)."""
        self._check()
        proxy = self.graph.service(name, srv_type)
        if name not in self.graph.available_services:
            def probe():
                try:
                    proxy.wait_for_service(timeout=0.05)
                except Exception:
                    return False
                return True

            if not self.wait_until(probe, timeout):
                raise RobotTimeout(app_local_text("sim_service_missing", name=name, timeout=timeout))
            self.graph.available_services.add(name)
        deadline = time.monotonic() + timeout
        connection = self.graph.connection
        outcome = self.graph.service_calls.call(
            proxy, request,
            should_end=lambda: self.interrupt.stop_requested or connection.lost or time.monotonic() >= deadline,
            cut=lambda: self.graph.forget_service(name))
        if outcome.ended:
            self._check()
            raise RobotTimeout(app_local_text("ros_service_timeout", name=name, timeout=timeout))
        if outcome.error is not None:
            self.graph.forget_service(name)
            raise RobotCommandError(app_local_text("sim_service_failed", name=name, error=outcome.error))
        response = from_message(outcome.response)
        for watcher in list(self.graph.service_watchers):
            watcher(name, "service", {"request": request, "response": response})
        return response

    def send_goal(self, action: str, action_type: str, goal: dict, feedback=None) -> GoalHandle:
        """Send a goal (waiting up to 5 s for the action server); feedback as dicts."""
        self._check()
        client = self.graph.action_client(action, action_type)
        import rospy

        if not self.wait_until(lambda: client.wait_for_server(rospy.Duration(0.05)), 5.0):
            raise RobotCommandError(app_local_text("sim_no_action", action=action))
        if action not in self.graph.goals_sent:  # actionlib waits for the server only, not for others listening
            self._wait_for_subscribers(client.action_client.pub_goal)
            self.graph.goals_sent.add(action)
        goal_class = self.graph.types.action_classes(action_type)[1]
        callback = (lambda message: feedback(from_message(message))) if feedback else None
        finished = threading.Event()
        client.send_goal(to_message(goal_class, goal), done_cb=lambda _state, _result: finished.set(),
                         feedback_cb=callback)
        return Ros1GoalHandle(self, client, action, finished)

    def cancel_all_goals(self, action: str) -> None:
        """Cancel every goal on the action server: an empty GoalID on ``<action>/cancel``."""
        self.publish(f"{action}/cancel", "actionlib_msgs/GoalID", {})

    def get_param(self, name: str, default=None):
        """A parameter from the ROS parameter server, or ``default``."""
        self._check()
        import rospy

        return rospy.get_param(name, default)

    def set_param(self, name: str, value) -> None:
        """Set a parameter on the ROS parameter server."""
        self._check()
        import rospy

        rospy.set_param(name, value)

    def sleep(self, seconds: float) -> None:
        """Wait ``seconds`` (pausable, stoppable; a lost master ends it within ~2 s)."""
        self.interrupt.sleep(seconds, watch=self._check)
