"""Rockly's ROS 2 helper process: one rclpy node that does what Rockly asks over stdin/stdout.

Started by ``robot.ros2.client.Ros2Helper`` with ``.venv-ros2``'s Python (which imports
``rockly_desktop`` from Rockly's folder and calls ``main``); it imports rclpy, this package's
modules, ``robot.ros2.wire`` and the frame of stamped commands (``robot.wrappers.ros_versions``)
only. Requests come as ``wire`` frames on stdin; the node spins in its own thread (subscription,
feedback and result callbacks), waits that may take a while (a service or action server to appear)
run in a small pool, everything else inline.

A thread of its own says it is alive every ``wire.HEARTBEAT_SECONDS`` (Rockly ends a helper
that falls silent). When stdin ends (Rockly quit or died) or SIGTERM comes, its last act is the
profile's safe stop (given by ``configure``), then it leaves.
"""
import os
import signal
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor

import rclpy
from rclpy.action import ActionClient
from rclpy.executors import SingleThreadedExecutor
from rclpy.signals import SignalHandlerOptions

from rockly_desktop.robot.ros2 import wire
from rockly_desktop.robot.ros2.helper import graph_offers, qos, type_descriptions
from rockly_desktop.robot.ros2.helper.layouts import layout
from rockly_desktop.robot.ros2.helper.ros_values import (
    BadValue,
    MissingInterface,
    from_message,
    interface_class,
    parameter_value,
    to_message,
    to_parameter_value,
)
from rockly_desktop.robot.ros2.helper.topic_reader import TopicReader
from rockly_desktop.robot.wrappers.ros_versions import FRAME_ID

FIRST_PUBLISH_WAIT = 2.0  # a new publisher waits this long for the graph's subscribers to match
ACTION_SERVER_WAIT = 5.0
PARAMETER_WAIT = 5.0  # a node's parameter service: a fresh helper's discovery and then some
SERVER_SETTLE = 0.25
PARAMETER_TRIES = 3  # reading or setting a parameter is safe to ask again when an answer was lost
TOPIC_WAIT = 1.0  # a subscription without a type waits this long (a fresh helper: its discovery) for the topic
REPLACE_WAIT = 1.0  # a publisher of a new type waits this long for the one it replaces to be gone
_GOAL_STATUS = {4: "succeeded", 5: "preempted", 6: "aborted"}


class Failure(wire.TextError):
    """A request that cannot be done; ``kind`` is 'timeout' or 'command' (Rockly's error class), its
    words Rockly's catalogue text ``key`` with ``values``."""

    def __init__(self, kind, key, **values):
        super().__init__(key, **values)
        self.kind = kind


class Reported(Failure):
    """A failure already told to Rockly another way (a goal's end): a cast does not report it again."""


class Later:
    """An answer that comes later (a service's response): settled once (the response and its deadline
    may race), and given to the request's ``answer_with`` whichever of the two comes first."""

    def __init__(self):
        self.settled = threading.Event()
        self._lock = threading.Lock()
        self._outcome = None
        self._answer = None

    def answer_with(self, answer):
        """Answer the request with ``answer(ok, value)`` once settled (at once if it is)."""
        with self._lock:
            self._answer, outcome = answer, self._outcome
        if outcome is not None:
            answer(*outcome)

    def settle(self, ok, value):
        """The outcome; a later one is ignored."""
        with self._lock:
            if self._outcome is not None:
                return
            self._outcome, answer = (ok, value), self._answer
        self.settled.set()
        if answer is not None:
            answer(ok, value)


class Helper:
    """The node and its endpoints, one per name; answers requests (see ``wire``)."""

    def __init__(self, out):
        self._out = out
        self.started = time.monotonic()
        self._out_lock = threading.Lock()
        self._lock = threading.Lock()
        rclpy.init(signal_handler_options=SignalHandlerOptions.NO)  # our SIGTERM: the safe stop first
        # no parameter services of its own: fewer entities for the executor to wait on
        self.node = rclpy.create_node(f"rockly_{os.getpid()}", start_parameter_services=False)
        self._executor = SingleThreadedExecutor()
        self._executor.add_node(self.node)
        self._spin = threading.Thread(target=self._executor.spin, name="ros2-spin", daemon=True)
        self._spin.start()
        self._pool = ThreadPoolExecutor(8, thread_name_prefix="ros2-wait")
        self._publishers = {}
        # subscriptions: on a node of their own, read without the executor (topic_reader)
        self.topics = TopicReader(rclpy.create_node(f"rockly_{os.getpid()}_topics", start_parameter_services=False))
        self._services = {}
        self._actions = {}
        self._goals = {}
        self._settled = set()
        self.qos_overrides = {}
        self._kept_qos = {}  # QoS asked for by ``keep_qos``: a profile's ``configure`` does not replace it
        self.safe_stop = []
        self.sim = None

    # --- sending to Rockly
    def send(self, frame):
        data = wire.encode(frame)
        with self._out_lock:
            self._out.write(data)
            self._out.flush()

    def event(self, kind, key, data=None):
        self.send((wire.EVENT, kind, key, data))

    def beat(self):
        """Say 'alive' every HEARTBEAT_SECONDS until Rockly's pipe closes (its own thread: a request
        that waits long does not hold it up, a stopped or frozen process does)."""
        while True:
            time.sleep(wire.HEARTBEAT_SECONDS)
            try:
                self.event("alive", None)
            except (OSError, ValueError):
                return

    # --- requests
    # requests that may wait (for a server, a match, an answer) run on the pool, not the reading loop
    WAITING_OPS = {"publish_first", "subscribe", "service", "goal", "cancel_all", "get_param", "set_param",
                   "parameters", "type_description"}

    def handle(self, frame):
        """Do one request (``op_<name>``): inline, or on the pool when it may wait (a goal to a
        server already reached does not)."""
        mode, call_id, op, args = frame
        method = getattr(self, f"op_{op}", None)
        if method is None:
            return self._answer(mode, call_id, False, ("command", f"unknown request '{op}'"), op)
        if op in self.WAITING_OPS and not self._at_once(op, args):
            self._pool.submit(self._run, mode, call_id, op, method, args)
        else:
            self._run(mode, call_id, op, method, args)

    def _at_once(self, op, args) -> bool:
        """Whether a request that may wait will not, this time (its server is reached: it is only sent)."""
        if op == "goal":
            return self._server_ready(args[1])
        if op == "service":
            client = self._services.get(args[0])
            return client is not None and client in self._settled and client.service_is_ready()
        return False

    def _run(self, mode, call_id, op, method, args):
        try:
            value = method(*args)
            if isinstance(value, Later):
                value.answer_with(lambda ok, answer: self._answer(mode, call_id, ok, answer, op))
                return
        except Reported as error:
            if mode == wire.CALL:
                self._answer(mode, call_id, False, (error.kind, wire.said(error)), op)
        except Failure as error:
            self._answer(mode, call_id, False, (error.kind, wire.said(error)), op)
        except (LookupError, ValueError, TypeError, AssertionError) as error:
            self._answer(mode, call_id, False, ("command", wire.said(error)), op)
        except Exception as error:  # the helper must outlive a failed request
            self._answer(mode, call_id, False, ("command", f"{type(error).__name__}: {error}"), op)
        else:
            self._answer(mode, call_id, True, value, op)

    def _answer(self, mode, call_id, ok, value, op):
        if mode == wire.CALL:
            self.send((wire.REPLY, call_id, ok, value))
        elif not ok:
            self.event("failed", op, value)

    def op_ping(self, value=None):
        return value

    def op_resolve(self, name, service):
        """The topic or action (a service: ``service``) ``name`` reaches from this node: expanded
        (``{ns}``, ``{node}``, ``~``) and remapped as rclpy does when it makes one; None for a name
        rcl refuses. Publishers, service and action clients are all made on this node."""
        try:
            return (self.node.resolve_service_name if service else self.node.resolve_topic_name)(name)
        except (RuntimeError, ValueError, TypeError):  # rcl's RCLError; a name pybind cannot take (a NUL)
            return None

    def op_missing(self, types):
        """(name, package) of the ``types`` ({name: message type}) whose interface package is not installed here."""
        missing = []
        for name, type_name in types.items():
            try:
                interface_class(type_name, "msg")
            except MissingInterface as error:
                missing.append((name, error.values.get("package", type_name)))
        return missing

    def op_configure(self, qos_overrides, safe_stop, match=True):
        """The profile's QoS overrides and safe stop; the stop's publishers are made now, and matched
        unless ``match`` is False (a helper replacing a lost one: its stop must not wait behind a topic
        nobody subscribes to; a publish matches first anyway). Returns the topics that cannot be
        published here (a type ROS 2's environment lacks)."""
        self.qos_overrides = {**(qos_overrides or {}), **self._kept_qos}
        self.safe_stop = list(safe_stop or [])
        problems = []
        for action in self.safe_stop:
            if "publish" in action:
                try:
                    if match:
                        self.op_publish_first(action["publish"]["topic"], action["publish"]["type"], None)
                    else:
                        self._publisher(action["publish"]["topic"], action["publish"]["type"])
                except LookupError:
                    problems.append(action["publish"]["topic"])
        return problems

    def op_keep_qos(self, topic, setting):
        """Give ``topic``'s publisher and subscription made from now on the QoS ``setting`` (``qos.from_setting``),
        whatever a profile configures (the robot agent's topics: reliable and deep)."""
        qos.from_setting(setting)  # a bad setting is refused here, not when the publisher is made
        self._kept_qos[topic] = self.qos_overrides[topic] = setting

    def op_ends(self, topic):
        """``(publishers, subscribers)`` of ``topic`` on other nodes than this helper's own."""
        own = {self.node.get_name(), self.topics.node.get_name()}

        def others(endpoints):
            return sum(1 for info in endpoints if info.node_name not in own)
        return (others(self.node.get_publishers_info_by_topic(topic)),
                others(self.node.get_subscriptions_info_by_topic(topic)))

    def _publisher(self, topic, type_name):
        """The publisher on ``topic``: one per topic (Fast DDS refuses a second type on a topic in one
        participant), so another type replaces it (a Jazzy robot's TwistStamped the safe stop's Twist)."""
        message_class = interface_class(type_name, "msg")
        with self._lock:
            entry = self._publishers.get(topic)
            if entry is not None and entry[1] is not message_class:
                self.node.destroy_publisher(entry[0])
                entry = None
            if entry is None:
                entry = self._publishers[topic] = (self._new_publisher(topic, message_class), message_class)
            return entry

    def _new_publisher(self, topic, message_class):
        """A publisher of ``message_class`` on ``topic``. One of another type destroyed just before may live
        on while the spinning executor holds it (rclpy destroys a handle once it is not in use), and DDS
        then refuses the new type: the executor is woken to let go of it, and the publisher made again."""
        deadline = time.monotonic() + REPLACE_WAIT
        while True:
            try:
                return self.node.create_publisher(message_class, topic, qos.for_publisher(topic, self.qos_overrides))
            except RuntimeError:  # rclpy's RCLError: what rcl refuses
                if time.monotonic() >= deadline:
                    raise
                self._executor.wake()
                time.sleep(0.005)

    def op_publish_first(self, topic, type_name, message):
        """Make the publisher, wait until the subscribers the graph lists have matched it (``_match``), publish."""
        publisher, _class = self._publisher(topic, type_name)
        self._match(publisher, topic)
        if message is not None:
            self.op_publish(topic, type_name, message)

    def _match(self, publisher, topic):
        """Wait (≤ FIRST_PUBLISH_WAIT) until ``publisher`` has matched every subscriber the graph lists for ``topic``,
        and at least one: discovery is gradual in ROS 2, a robot's subscriber may not be known yet
        (in the helper's first seconds, it waits until discovery had DISCOVERY_SECONDS)."""
        deadline = max(time.monotonic() + FIRST_PUBLISH_WAIT, self.started + wire.DISCOVERY_SECONDS)
        while (publisher.get_subscription_count() < max(1, self.node.count_subscribers(topic))
               and time.monotonic() < deadline):
            time.sleep(0.005)

    def op_publish(self, topic, type_name, message):
        """Publish the fields ``message`` (checked: a wrong one is named)."""
        publisher, message_class = self._matched_publisher(topic, type_name)
        publisher.publish(to_message(message_class, message))

    def op_publish_raw(self, topic, type_name, raw):
        """Publish a message Rockly's side encoded from the type's layout (``op_layout``), as it is."""
        publisher, _message_class = self._matched_publisher(topic, type_name)
        publisher.publish(raw)

    def op_layout(self, type_name):
        """The layout of ``type_name`` for Rockly's side to encode its messages (``layouts``), or None."""
        return layout(interface_class(type_name, "msg"))

    def _matched_publisher(self, topic, type_name):
        """The publisher on ``topic``; while it has matched nobody but the graph lists subscribers (or
        the helper is too young to know them all: a spare taking over sends the safe stop), matched first."""
        publisher, message_class = self._publisher(topic, type_name)
        if publisher.get_subscription_count() == 0 and (
                self.node.count_subscribers(topic) > 0 or time.monotonic() < self.started + wire.DISCOVERY_SECONDS):
            self._match(publisher, topic)
        return publisher, message_class

    def op_subscribe(self, sid, topic, type_name):
        """Subscribe (QoS matched to the publishers); messages come as ('msg', sid, dict) events, their
        arrays of numbers compact (``from_message``'s ``compact``).

        Without a type, the graph's type of ``topic`` is used. Returns the type. Nothing queues here:
        the reading thread writes each message to the pipe, and while Rockly's side reads slower than a
        robot publishes (a camera), the write waits and the subscription's own history (its QoS depth)
        keeps the latest messages, dropping the oldest.
        """
        deadline = max(time.monotonic() + TOPIC_WAIT, self.started + wire.DISCOVERY_SECONDS)
        while not type_name:
            type_name = (dict(self.node.get_topic_names_and_types()).get(topic) or [None])[0]
            if type_name:
                break
            if time.monotonic() >= deadline:
                raise Failure("timeout", "ros_no_topic", topic=topic)
            time.sleep(0.01)
        message_class = interface_class(type_name, "msg")
        profile = qos.for_subscription(topic, type_name, self.node.get_publishers_info_by_topic(topic),
                                       self.qos_overrides)
        send = self.send
        self.topics.subscribe(sid, message_class, topic,
                              lambda message: send((wire.EVENT, "msg", sid, from_message(message, compact=True))),
                              profile)
        return type_name

    def op_unsubscribe(self, sid):
        self.topics.unsubscribe(sid)

    def op_graph(self):
        """Topics (name, types, publisher count), this node's own publishers by topic ("own", shown
        beside the others'), services and action names of the ROS 2 graph.

        A topic's publishers are the others' (not this node's own), and their types come first:
        a state feed following the graph then never subscribes to what only Rockly publishes, in the
        type Rockly happened to publish first (Fast DDS allows one type per topic in a participant,
        so that subscription would refuse the publisher of the type a robot wants, a TwistStamped).
        """
        me = (self.node.get_name(), self.node.get_namespace())
        topics, own = [], {}
        for name, types in self.node.get_topic_names_and_types():
            publishers = self.node.get_publishers_info_by_topic(name)
            others = [info for info in publishers if (info.node_name, info.node_namespace) != me]
            if len(others) < len(publishers):
                own[name] = len(publishers) - len(others)
            published = list(dict.fromkeys(info.topic_type for info in others))
            topics.append((name, published + [type_name for type_name in types if type_name not in published],
                           len(others)))
        typed = self.node.get_service_names_and_types()
        services = [name for name, _types in typed]
        actions = sorted({name[:-len("/_action/send_goal")] for name in services
                          if name.endswith("/_action/send_goal")})
        return {"topics": topics, "own": own, "services": services, "actions": actions,
                "typed_services": graph_offers.typed_services(typed),
                "typed_actions": graph_offers.typed_actions(typed)}

    def op_parameters(self, seconds):
        """``node:param`` of the graph's nodes that list their parameters within ``seconds``."""
        services = [name for name, _types in self.node.get_service_names_and_types()]
        return graph_offers.parameter_names(
            services, lambda name: self._service_client(name, "rcl_interfaces/srv/ListParameters"), seconds)

    def op_type_description(self, topic, seconds):
        """``topic``'s type as its publisher's node describes it within ``seconds`` (``type_descriptions``), or None."""
        return type_descriptions.described_type(self.node, topic, lambda name: self._service_client(
            name, "type_description_interfaces/srv/GetTypeDescription"), seconds)

    # --- services
    def _ready(self, client, wait, key, **values):
        """Wait for ``client``'s server; the first time, also give the server SERVER_SETTLE to discover
        us: a server that has not matched the client's reader drops its answer (Fast DDS waits 100 ms).
        A server that does not come fails with the text ``key`` and ``values``."""
        if not client.wait_for_service(timeout_sec=wait):
            raise Failure("timeout", key, **values)
        if client not in self._settled:
            time.sleep(SERVER_SETTLE)
            self._settled.add(client)

    def _service_client(self, name, type_name):
        with self._lock:
            client = self._services.get(name)
            if client is None:
                client = self._services[name] = (self.node.create_client(interface_class(type_name, "srv"), name))
            return client

    def op_service(self, name, type_name, request, timeout):
        """Call a service (waiting up to ``timeout`` for it to appear and answer): the response dict, Later.

        A server already reached is only sent the request (inline, see ``_at_once``): the response is
        answered from the spinning thread as it comes, and a pool thread keeps the deadline."""
        client = self._service_client(name, type_name)
        deadline = time.monotonic() + timeout
        if not self._at_once("service", (name,)):
            self._ready(client, timeout, "sim_service_missing", name=name, timeout=timeout)
        future = client.call_async(to_message(client.srv_type.Request, request))
        response = Later()

        def responded(_future):
            if future.exception() is not None:
                failure = Failure("command", "sim_service_failed", name=name, error=str(future.exception()))
                response.settle(False, (failure.kind, wire.said(failure)))
            else:
                response.settle(True, from_message(future.result()))
        future.add_done_callback(responded)
        self._pool.submit(self._expire, response, max(0.0, deadline - time.monotonic()), client, future, name, timeout)
        return response

    @staticmethod
    def _expire(response, seconds, client, future, name, timeout):
        """The service call's deadline: unanswered by then, it fails as timed out."""
        if not response.settled.wait(seconds):
            client.remove_pending_request(future)
            failure = Failure("timeout", "ros_service_timeout", name=name, timeout=timeout)
            response.settle(False, (failure.kind, wire.said(failure)))

    # --- actions
    def _server_ready(self, action) -> bool:
        """True when a goal to ``action`` need not wait for its server (it can be sent inline)."""
        client = self._actions.get(action)
        return client is not None and client.server_is_ready()

    def _action_client(self, action, type_name):
        with self._lock:
            client = self._actions.get(action)
            if client is None:
                client = self._actions[action] = ActionClient(self.node, interface_class(type_name, "action"), action)
            return client

    def op_goal(self, gid, action, type_name, goal):
        """Send a goal; its feedback, acceptance and end come as events keyed by ``gid``."""
        client = self._action_client(action, type_name)
        if not client.wait_for_server(timeout_sec=ACTION_SERVER_WAIT):
            self.event("goal_end", gid, ("aborted", {}, ("sim_no_action", {"action": action})))
            raise Reported("command", "sim_no_action", action=action)
        if client not in self._settled:  # as for a service's first call (see _ready)
            time.sleep(SERVER_SETTLE)
            self._settled.add(client)
        try:
            goal_message = to_message(client._action_type.Goal, goal)
        except BadValue as error:
            self.event("goal_end", gid, ("aborted", {}, wire.said(error)))
            raise Reported("command", error.key, **error.values) from None
        send = self.send
        self._goals[gid] = [None, False]  # the server's handle once it accepts; cancelled before that
        future = client.send_goal_async(
            goal_message, feedback_callback=lambda message: send(
                (wire.EVENT, "feedback", gid, from_message(message.feedback))))
        future.add_done_callback(lambda done: self._goal_answered(gid, done))

    def _goal_answered(self, gid, future):
        entry = self._goals[gid]
        handle = future.result()
        if handle is None or not handle.accepted:
            self._goals.pop(gid, None)
            self.event("goal_end", gid, ("rejected", {}, ("ros2_goal_rejected", {})))
            return
        entry[0] = handle
        if entry[1]:
            handle.cancel_goal_async()
        handle.get_result_async().add_done_callback(lambda done: self._goal_ended(gid, done))

    def _goal_ended(self, gid, future):
        self._goals.pop(gid, None)
        response = future.result()
        status = _GOAL_STATUS.get(response.status, "aborted")
        self.event("goal_end", gid, (status, from_message(response.result), ""))

    def op_cancel_goal(self, gid):
        entry = self._goals.get(gid)
        if entry is None:
            return
        if entry[0] is None:
            entry[1] = True
        else:
            entry[0].cancel_goal_async()

    def op_cancel_all(self, action):
        """Cancel every goal of ``action``, whoever sent it (a zero goal id and stamp means all)."""
        from action_msgs.srv import CancelGoal

        client = self._service_client(f"{action.rstrip('/')}/_action/cancel_goal", "action_msgs/srv/CancelGoal")
        if client.wait_for_service(timeout_sec=FIRST_PUBLISH_WAIT):
            client.call_async(CancelGoal.Request())

    # --- parameters
    def _parameter_service(self, node, kind):
        type_name = {"get": "rcl_interfaces/srv/GetParameters", "set": "rcl_interfaces/srv/SetParameters"}[kind]
        client = self._service_client(f"/{node.strip('/')}/{kind}_parameters", type_name)
        self._ready(client, PARAMETER_WAIT, "ros2_no_parameter_node", node=node)
        return client

    def _call(self, client, request):
        for _try in range(PARAMETER_TRIES):
            future = client.call_async(request)
            done = threading.Event()
            future.add_done_callback(lambda _future, done=done: done.set())
            if done.wait(PARAMETER_WAIT / PARAMETER_TRIES):
                return future.result()
            client.remove_pending_request(future)
        raise Failure("timeout", "ros2_parameters_silent")

    def op_get_param(self, node, name):
        """``(True, value)`` of a node's parameter, or ``(False, None)`` when it is not set."""
        client = self._parameter_service(node, "get")
        response = self._call(client, client.srv_type.Request(names=[name]))
        value = parameter_value(response.values[0]) if response.values else None
        return (value is not None, value)

    def op_set_param(self, node, name, value):
        from rcl_interfaces.msg import Parameter

        client = self._parameter_service(node, "set")
        request = client.srv_type.Request(parameters=[Parameter(name=name, value=to_parameter_value(value))])
        result = self._call(client, request).results[0]
        if not result.successful:
            raise Failure("command", "ros2_parameter_refused", node=node, name=name, reason=result.reason)

    # --- serving a simulator (see sim_serving)
    def op_sim_serve(self, services, actions):
        """Serve the world's services and actions (names -> types) from the ``rockly_sim`` node."""
        from rockly_desktop.robot.ros2.helper.sim_serving import SimServing

        if self.sim is None:
            self.sim = SimServing(rclpy, self.event)
        left_out = []
        for endpoints, serve in ((services, self.sim.serve), (actions, self.sim.offer)):
            for name, type_name in endpoints.items():
                try:
                    serve(name, type_name)
                except LookupError as error:
                    left_out.append((name, type_name, wire.said(error)))
        return left_out

    def op_sim_answer(self, rid, ok, data):
        self.sim.answer(rid, ok, data)

    def op_sim_feedback(self, gid, data):
        self.sim.feedback(gid, data)

    def op_sim_goal_end(self, gid, status, result, text):
        self.sim.goal_end(gid, status, result, text)

    # --- the end
    def _zero(self, message_class):
        """An all-zero ``message_class``; a stamped one (a TwistStamped) stamped now, in the frame Rockly's stamped
        commands are given in, as every command before it was (a robot may drop a command stamped at 0)."""
        message = message_class()
        if message_class.get_fields_and_field_types().get("header") == "std_msgs/Header":
            message.header.stamp = self.node.get_clock().now().to_msg()
            message.header.frame_id = FRAME_ID
        return message

    def do_safe_stop(self):
        """The profile's safe stop, sent and (briefly) waited for delivery: the helper's last act."""
        for action in self.safe_stop:
            try:
                if "publish" in action:
                    body = action["publish"]
                    current = self._publishers.get(body["topic"])
                    if current and current[1] is not interface_class(body["type"], "msg") and not body.get("message"):
                        current[0].publish(self._zero(current[1]))  # a stop in the type the robot was sent
                    else:
                        self.op_publish(body["topic"], body["type"], dict(body.get("message") or {}))
                    self._publishers[body["topic"]][0].wait_for_all_acked(rclpy.duration.Duration(seconds=0.5))
                else:
                    self.op_cancel_all(action["cancel_goals"])
            except Exception as error:  # every part of the stop is tried
                print(f"rockly ros2 helper: safe stop {action} failed: {error}", file=sys.stderr)

    def close(self):
        if self.sim is not None:
            self.sim.close()
        self._pool.shutdown(wait=False, cancel_futures=True)
        self._executor.shutdown(timeout_sec=1.0)
        self._spin.join(timeout=1.0)
        self.topics.close()
        self.topics.node.destroy_node()
        self.node.destroy_node()
        rclpy.try_shutdown()


def _leave_on_term(_signum, _frame):
    raise SystemExit(0)


def main():
    stdin, stdout = sys.stdin.buffer, sys.stdout.buffer
    sys.stdout = sys.stderr  # nothing but frames may reach Rockly's pipe
    signal.signal(signal.SIGTERM, _leave_on_term)
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl+C is Rockly's to handle (a safe stop, then EOF)
    helper = Helper(stdout)
    import rclpy.utilities

    distro = os.environ.get("ROS_DISTRO") or "kilted"
    helper.event("hello", wire.PROTOCOL, {"pid": os.getpid(), "distro": distro,
                                          "domain": rclpy.utilities.get_default_context().get_domain_id(),
                                          "share": sorted(_share_dirs())})
    threading.Thread(target=helper.beat, name="ros2-heartbeat", daemon=True).start()
    try:
        while True:
            frame = wire.read_frame(stdin)
            if frame is None:
                break
            helper.handle(frame)
    finally:
        helper.do_safe_stop()
        helper.close()
        sys.stderr.flush()
        # Leave now: a pool worker still waiting on a slow node must not keep the helper (and its place in the
        # graph) alive after its last act; Rockly hears the end as its pipe closing.
        os._exit(0)


def _share_dirs():
    """Folders holding the installed interface packages' definitions (``<dir>/<pkg>/msg/*.msg``):
    this Python's prefix (the wheels put them there) and any sourced ROS 2 workspaces."""
    prefixes = [sys.prefix] + [entry for entry in os.environ.get("AMENT_PREFIX_PATH", "").split(os.pathsep) if entry]
    return {os.path.join(prefix, "share") for prefix in prefixes if os.path.isdir(os.path.join(prefix, "share"))}


if __name__ == "__main__":
    main()
