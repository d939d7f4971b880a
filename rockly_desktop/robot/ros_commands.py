"""Generic ROS commands for any robot, bound as ``ros`` in programs (the shared ROS blocks).

They work by ROS names and types on whatever backend the program runs on (the simulator
or ROS 1). Dict arguments (a service request, an action goal) may also be given as JSON
text, since blocks have no dictionary block. With a DefinitionCatalog, messages, requests
and goals are checked against their type before they leave, so a wrong value is named
the same way on the simulator as on a real robot.
"""
import logging
import time
from collections import deque

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import RobotCommandError, RobotTimeout
from rockly_desktop.core.state_store import field_value
from rockly_desktop.robot.commands import RobotCommands

log = logging.getLogger("rosout")  # on ROS 1, rospy sends this logger's records to /rosout
_log = logging.getLogger(__name__)  # Rockly's own log, not the program's

STD_TYPES = {"String": "std_msgs/String", "Bool": "std_msgs/Bool", "Float64": "std_msgs/Float64",
             "Int64": "std_msgs/Int64", "UInt64": "std_msgs/UInt64"}
LEVELS = {"info": logging.INFO, "warn": logging.WARNING, "error": logging.ERROR}
GOAL_TIMEOUT = 300.0


class RosCommands(RobotCommands):
    """Publish, listen, call services, send goals, parameters and logging on any robot."""

    def __init__(self, backend, say=print, types=None):
        """``say(text)`` shows log lines to the person (the run's console); ``types`` checks what is sent."""
        super().__init__(backend)
        self.say = say
        self.types = types

    def _checked(self, data, type_name, kind, what):
        data = self.mapping(data, what)
        if self.types is not None:
            self.types.check(type_name, kind, data)
        return data

    def publish(self, topic, message_type, value):
        """Publish ``value`` on ``topic`` as a std_msgs type (String, Bool, Float64, Int64, UInt64)."""
        msg_type = self.choose(message_type, STD_TYPES, "message type")
        self.backend.publish(str(topic), msg_type, {"data": value})

    def publish_message(self, topic, message_type, fields):
        """Publish any message type, its fields given as a mapping (or JSON text)."""
        self.backend.publish(str(topic), str(message_type), self._checked(fields, message_type, "msg", "message"))

    def number_in(self, value, minimum, maximum, what):
        """``value`` as a number from ``minimum`` to ``maximum`` (None: unbounded on that side); a value
        outside stops the program on its block, naming ``what`` (a made block's input)."""
        number = self.number(value, what)
        if (minimum is not None and number < minimum) or (maximum is not None and number > maximum):
            raise RobotCommandError(app_local_text("pack_value_out_of_range", what=what, value=repr(value),
                                                   minimum="-" if minimum is None else minimum,
                                                   maximum="-" if maximum is None else maximum))
        return value

    def wait_for_message(self, topic, timeout=10):
        """Wait for the next message on ``topic`` (any type) and return it."""
        return self.backend.wait_for_message(str(topic), None, self.number(timeout, "the timeout"))

    @staticmethod
    def field(message, path):
        """The field at ``path`` (``pose.pose.position.x``) of a message."""
        try:
            return field_value(message, str(path))
        except KeyError:
            raise RobotCommandError(app_local_text("ros_no_field", path=path)) from None

    def latest(self, topic, path):
        """The newest value of the field ``path`` on ``topic`` (waiting briefly for a first message)."""
        message = self.backend.latest(str(topic), None) or self.wait_for_message(topic, 3)
        return self.field(message, path)

    def call_service(self, name, service_type, request=None, timeout=10):
        """Call a service; ``request`` is a mapping (or JSON text); returns the response."""
        request = self._checked(request, service_type, "srv", "service request")
        return self.backend.call_service(str(name), str(service_type), request, self.number(timeout, "the timeout"))

    def send_goal(self, action, action_type, goal=None, timeout=GOAL_TIMEOUT, while_waiting=None):
        """Send an action goal and wait: returns 'succeeded', 'aborted', 'preempted' or 'rejected'.

        ``while_waiting(feedback)``, if given, runs in this (the program's) thread with the
        newest feedback while the goal is under way; feedback that arrives while it runs
        is coalesced, so a slow handler sees the latest, not a backlog. If the wait ends
        any other way than with the goal's end (a stop, the timeout, an error in the
        handler), the goal is cancelled and the error passes on.
        """
        action, timeout = str(action), self.number(timeout, "the timeout")
        if while_waiting is not None and not callable(while_waiting):
            raise RobotCommandError(app_local_text("ros_not_a_function", value=repr(while_waiting)))
        goal = self._checked(goal, action_type, "action", "goal")
        pending = deque(maxlen=1)  # only the newest feedback waits for the handler
        handle = self.backend.send_goal(action, str(action_type), goal,
                                        feedback=pending.append if while_waiting is not None else None)
        try:
            if while_waiting is None:
                return handle.wait(timeout).status.value
            return self._wait_with_handler(handle, action, pending, while_waiting, timeout).status.value
        except BaseException:
            try:
                handle.cancel()
            except Exception:
                _log.exception("could not cancel the goal on the action '%s'", action)
            raise

    def _wait_with_handler(self, handle, action, pending, while_waiting, timeout):
        """Call ``while_waiting`` with each newest feedback until the goal ends; its outcome."""
        deadline = time.monotonic() + timeout
        while True:
            done = handle.done()  # before taking the feedback, so what came before the end is handed over
            if pending:
                while_waiting(pending.popleft())
            if done:
                return handle.wait(timeout)
            remaining = deadline - time.monotonic()
            if remaining <= 0 or not self.backend.wait_until(lambda: pending or handle.done(), remaining):
                raise RobotTimeout(app_local_text("sim_action_timeout", action=action, timeout=timeout))

    def cancel_goals(self, action):
        """Cancel every goal of the action server ``action``."""
        self.backend.cancel_all_goals(str(action))

    def get_param(self, name, default=None):
        """The value of a ROS parameter (``default`` if it is not set)."""
        return self.backend.get_param(str(name), default)

    def set_param(self, name, value):
        """Set a ROS parameter."""
        self.backend.set_param(str(name), value)

    def wait(self, seconds):
        """Do nothing for ``seconds`` seconds."""
        self.backend.sleep(max(0.0, self.number(seconds, "the waiting time")))

    def log(self, level, text):
        """Write ``text`` to the console (and to ROS's log on a real robot) as info, warn or error."""
        self.choose(level, LEVELS, "log level")
        self.say(f"[{level}] {text}")
        log.log(LEVELS[level], "%s", text)
