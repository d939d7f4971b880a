"""An in-process stand-in for a ROS graph, and the RobotBackend that drives it.

A profile's simulator lives in a ``SimWorld``: it subscribes to topics, publishes
others, and serves services and actions under their ROS names. A program talks to the
same world through a ``SimBackend``, so its commands run exactly as they would against
the robot. Messages are plain dicts shaped like the ROS messages; every subscriber,
caller and goal gets its own copy, as if the message had crossed the wire.
"""
import copy
import logging
import threading
import time
from collections import defaultdict

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import RobotCommandError, RobotTimeout, RocklyError
from rockly_desktop.robot.interface import GoalHandle, GoalOutcome, GoalStatus, RobotBackend
from rockly_desktop.robot.wrappers.ros_versions import ros_name, short_type

log = logging.getLogger(__name__)

POLL_SECONDS = 0.01
_SCALARS = frozenset((int, float, str, bool, type(None)))


def message_copy(value):
    """A deep copy of a message (dicts, lists, numbers, texts), as if it had crossed the wire: a
    quick walk for that plain data (a laser scan's 360 ranges: ~20x quicker than ``copy.deepcopy``),
    ``copy.deepcopy`` for anything else."""
    kind = type(value)
    if kind in _SCALARS:
        return value
    if kind is dict:
        return {key: message_copy(item) for key, item in value.items()}
    if kind is list:
        if _SCALARS.issuperset(map(type, value)):
            return value.copy()
        return [message_copy(item) for item in value]
    return copy.deepcopy(value)


# actionlib_msgs/GoalStatus codes, as the real robot's action servers report them.
_ACTIONLIB_CODES = {GoalStatus.PREEMPTED: 2, GoalStatus.SUCCEEDED: 3, GoalStatus.ABORTED: 4, GoalStatus.REJECTED: 5}


class SimGoal:
    """One goal on a simulated action server; ``outcome`` is set when it has ended."""

    def __init__(self, action: str):
        self.action = action
        self.cancelled = threading.Event()
        self.outcome = None


class SimWorld:
    """Topics, services and action servers of a simulated robot; safe to use from any thread.

    Subscriber callbacks, service handlers and goal feedback run in the thread that
    caused them (the publisher's, the caller's, the goal's) and must not block for long.
    """

    def __init__(self):
        self._changed = threading.Condition(threading.RLock())
        self._latest = {}
        self._subscribers = defaultdict(list)
        self._services = {}
        self._actions = {}
        self._goals = set()
        self._taps = []
        self.params = {}  # the parameter server of the simulated robot

    def tap(self, callback, skip=()):
        """Also show ``callback(topic, msg_type, message)`` everything that happens in the world, but for
        the topics in ``skip``.

        Topics as they are published; a service call as ``<service>`` with its request and
        response; an action goal as ``<action>/goal`` and its end as ``<action>/result``
        (the topics actionlib uses on ROS), so state panels read both the same way.
        """
        self._taps.append((callback, frozenset(skip)))

    def untap(self, callback):
        """Show ``callback`` nothing more."""
        self._taps = [(tapped, skip) for tapped, skip in self._taps if tapped != callback]

    def _show_taps(self, topic, msg_type, message):
        for callback, skip in list(self._taps):
            if topic not in skip:
                callback(topic, msg_type, message_copy(message))

    # --- topics -----------------------------------------------------------------------

    def publish(self, topic: str, msg_type: str, message: dict) -> None:
        """Make ``message`` the topic's latest, hand it to every subscriber, wake waiters."""
        with self._changed:
            self._latest[topic] = (msg_type, message_copy(message))
            callbacks = list(self._subscribers[topic])
        for callback in callbacks:
            callback(message_copy(message))
        self._show_taps(topic, msg_type, message)
        with self._changed:
            self._changed.notify_all()

    def subscribe(self, topic: str, callback):
        """Call ``callback(message)`` for every later message on ``topic``; returns an unsubscribe function."""
        with self._changed:
            self._subscribers[topic].append(callback)

        def unsubscribe():
            with self._changed:
                self._subscribers[topic].remove(callback)

        return unsubscribe

    def latest(self, topic: str):
        """A copy of the last message published on ``topic``, or None."""
        with self._changed:
            entry = self._latest.get(topic)
            return message_copy(entry[1]) if entry else None

    def topics(self) -> list:
        """Every topic that has had a message, as sorted ``(topic, msg_type)`` pairs."""
        with self._changed:
            return sorted((topic, msg_type) for topic, (msg_type, _message) in self._latest.items())

    # --- services -----------------------------------------------------------------------

    def advertise_service(self, name: str, handler) -> None:
        """Serve ``name`` with ``handler(request, interrupt) -> response`` (replacing an older one)."""
        with self._changed:
            self._services[name] = handler
            self._changed.notify_all()

    def has_service(self, name: str) -> bool:
        """True when a service ``name`` is advertised."""
        with self._changed:
            return name in self._services

    def services(self) -> list:
        """The names of the advertised services, sorted."""
        with self._changed:
            return sorted(self._services)

    def call_service(self, name: str, request: dict, interrupt) -> dict:
        """Run the service's handler in this thread and return its response.

        An error inside the handler reaches the caller as a RobotCommandError naming the
        service, as a ROS service error would; Rockly's own errors (a stop) pass unchanged.
        """
        with self._changed:
            handler = self._services.get(name)
        if handler is None:
            raise RobotCommandError(app_local_text("sim_no_service", name=name))
        try:
            response = handler(message_copy(request), interrupt)
        except RocklyError:
            raise
        except Exception as error:
            raise RobotCommandError(app_local_text("sim_service_failed", name=name, error=error)) from error
        self._show_taps(name, "service", {"request": request, "response": response})
        return message_copy(response)

    # --- actions ------------------------------------------------------------------------

    def has_action(self, name: str) -> bool:
        """True when an action server ``name`` is up."""
        with self._changed:
            return name in self._actions

    def actions(self) -> list:
        """The names of the action servers that are up, sorted."""
        with self._changed:
            return sorted(self._actions)

    def advertise_action(self, name: str, handler) -> None:
        """Serve the action ``name``: ``handler(goal, feedback, cancelled) -> (GoalStatus, result[, text])``.

        ``text`` is the reason a goal ended as it did (actionlib's status text), e.g. why it was aborted.

        Each goal runs the handler in its own thread; ``feedback(dict)`` sends feedback and
        ``cancelled`` (a threading.Event) is set when the goal is cancelled.
        """
        with self._changed:
            self._actions[name] = handler

    def send_goal(self, action: str, goal: dict, feedback=None) -> SimGoal:
        """Start ``goal`` on the action server; ``feedback(dict)`` is called from the goal's thread."""
        with self._changed:
            handler = self._actions.get(action)
            if handler is None:
                raise RobotCommandError(app_local_text("sim_no_action", action=action))
            sim_goal = SimGoal(action)
            self._goals.add(sim_goal)
        self._show_taps(f"/{action.strip('/')}/goal", "action goal", {"goal": goal})
        thread = threading.Thread(target=self._run_goal, args=(handler, sim_goal, message_copy(goal), feedback),
                                  name=f"sim goal {action}", daemon=True)
        thread.start()
        return sim_goal

    def running_goals(self) -> int:
        """How many goals are running now (sent and not yet ended)."""
        with self._changed:
            return len(self._goals)

    def cancel_goals(self, action: str) -> None:
        """Cancel every active goal on the action server ``action``."""
        with self._changed:
            for sim_goal in self._goals:
                if sim_goal.action == action:
                    sim_goal.cancelled.set()

    def _run_goal(self, handler, sim_goal: SimGoal, goal: dict, feedback):
        def send_feedback(message):
            if feedback is not None:
                feedback(message_copy(message))

        try:
            status, result, *reason = handler(goal, send_feedback, sim_goal.cancelled)
        except Exception:
            log.exception("the action server '%s' failed", sim_goal.action)
            status, result, reason = GoalStatus.ABORTED, {}, []
        with self._changed:
            sim_goal.outcome = GoalOutcome(status, message_copy(result), str(reason[0]) if reason else "")
            self._goals.discard(sim_goal)
            self._changed.notify_all()
        status_message = {"status": _ACTIONLIB_CODES[status], "text": sim_goal.outcome.text}
        self._show_taps(f"/{sim_goal.action.strip('/')}/result", "action result",
                        {"status": status_message, "result": result})

    # --- waiting ------------------------------------------------------------------------

    def wait_for(self, predicate, timeout: float) -> bool:
        """Wait until ``predicate()`` is true, re-checking whenever the world changes; False on timeout."""
        with self._changed:
            return self._changed.wait_for(predicate, timeout)


class SimGoalHandle(GoalHandle):
    """A program's handle on a goal running in a SimWorld."""

    def __init__(self, sim_goal: SimGoal, backend: "SimBackend"):
        self._goal = sim_goal
        self._backend = backend

    def done(self) -> bool:
        """True once the action server has ended the goal."""
        return self._goal.outcome is not None

    def wait(self, timeout: float) -> GoalOutcome:
        """Wait for the goal's outcome; a stop request raises ProgramStopped, a timeout RobotTimeout."""
        if not self._backend.wait_until(self.done, timeout):
            raise RobotTimeout(app_local_text("sim_action_timeout", action=self._goal.action, timeout=timeout))
        return self._goal.outcome

    def cancel(self) -> None:
        """Ask the action server to stop working on this goal."""
        self._goal.cancelled.set()


class SimBackend(RobotBackend):
    """A RobotBackend on a SimWorld; every wait ends within ~10 ms of a stop request.

    ``listens`` ({topic: {types}}) are the types the simulated robot subscribes with, and ``types``
    (a DefinitionCatalog) the definitions Rockly knows: a message of another type on such a topic,
    or one whose values do not fit its type (a speed as the text "1.0" or as true), is refused with
    a RobotCommandError, as a real ROS would not deliver it. ``published`` (a set) gets each topic published on.
    """

    def __init__(self, world: SimWorld, interrupt, listens=None, types=None, published=None):
        self._world = world
        self._published = published if published is not None else set()
        self.interrupt = interrupt
        self._listens = listens or {}
        self._types = types

    def subscribe(self, topic: str, msg_type: str, callback):
        """Call ``callback`` for each message on ``topic``; returns the unsubscribe function."""
        return self._world.subscribe(topic, callback)

    def publish(self, topic: str, msg_type: str, message: dict) -> None:
        """Publish ``message`` on ``topic``, refused as a real ROS would not deliver it (see the class)."""
        expected = self._listens.get(ros_name(topic))
        if msg_type and expected and short_type(msg_type) not in expected:
            raise RobotCommandError(app_local_text("sim_type_not_heard", topic=topic, type=msg_type,
                                                   expected=" / ".join(sorted(expected))))
        if msg_type and self._types is not None:
            try:
                self._types.check(short_type(msg_type), "msg", message)
            except RobotCommandError as error:
                raise RobotCommandError(app_local_text("sim_message_refused", type=msg_type, topic=topic,
                                                       problem=str(error))) from None
        self._published.add(topic)
        self._world.publish(topic, msg_type, message)

    def latest(self, topic: str, msg_type: str):
        """The last message on ``topic``, or None."""
        return self._world.latest(topic)

    def wait_for_message(self, topic: str, msg_type: str, timeout: float) -> dict:
        """The first message published on ``topic`` after this call; RobotTimeout after ``timeout`` s."""
        received = []
        unsubscribe = self._world.subscribe(topic, received.append)
        try:
            if not self.wait_until(lambda: received, timeout):
                raise RobotTimeout(app_local_text("sim_no_message", topic=topic, timeout=timeout))
        finally:
            unsubscribe()
        return received[0]

    def call_service(self, name: str, srv_type: str, request: dict, timeout: float) -> dict:
        """Call ``name``, waiting up to ``timeout`` s for it to be advertised; RobotTimeout if it never is."""
        if not self.wait_until(lambda: self._world.has_service(name), timeout):
            raise RobotTimeout(app_local_text("sim_service_missing", name=name, timeout=timeout))
        return self._world.call_service(name, request, self.interrupt)

    def send_goal(self, action: str, action_type: str, goal: dict, feedback=None) -> GoalHandle:
        """Start ``goal`` on the action server ``action``; RobotCommandError if there is none."""
        return SimGoalHandle(self._world.send_goal(action, goal, feedback), self)

    def cancel_all_goals(self, action: str) -> None:
        """Cancel every active goal on ``action``, whoever sent it (as actionlib's cancel_all_goals)."""
        self._world.cancel_goals(action)

    def get_param(self, name: str, default=None):
        """A parameter of the simulated world, or ``default``."""
        return self._world.params.get(name, default)

    def set_param(self, name: str, value) -> None:
        """Set a parameter of the simulated world."""
        self._world.params[name] = value

    def sleep(self, seconds: float) -> None:
        """Wait ``seconds``; a stop request raises ProgramStopped."""
        self.interrupt.sleep(seconds)

    def wait_until(self, predicate, timeout: float) -> bool:
        """Wait until ``predicate()`` holds (True) or ``timeout`` passes (False); a stop request raises."""
        deadline = time.monotonic() + timeout
        while True:
            self.interrupt.check()
            remaining = deadline - time.monotonic()
            if self._world.wait_for(predicate, min(POLL_SECONDS, max(0.0, remaining))):
                self.interrupt.check()  # a stop meanwhile wins: the safe stop that followed it ended the wait
                return True
            if remaining <= 0:
                return False
