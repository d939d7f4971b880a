"""Generic ROS commands for any robot, bound as ``ros`` in programs (the shared ROS blocks).

They work by ROS names and types on whatever backend the program runs on (the simulator
or ROS 1). Dict arguments (a service request, an action goal) may also be given as JSON
text, since blocks have no dictionary block.
"""
import json
import logging

from rockly_desktop.core.errors import RobotCommandError
from rockly_desktop.core.state_store import field_value
from rockly_desktop.robot.commands import RobotCommands

log = logging.getLogger("rosout")  # on ROS 1, rospy sends this logger's records to /rosout

STD_TYPES = {"String": "std_msgs/String", "Bool": "std_msgs/Bool", "Float64": "std_msgs/Float64",
             "Int64": "std_msgs/Int64", "UInt64": "std_msgs/UInt64"}
LEVELS = {"info": logging.INFO, "warn": logging.WARNING, "error": logging.ERROR}
GOAL_TIMEOUT = 300.0


def _as_dict(value, what: str) -> dict:
    if value is None or value == "":
        return {}
    if isinstance(value, dict):
        return value
    try:
        parsed = json.loads(value) if isinstance(value, str) else None
    except json.JSONDecodeError as error:
        raise RobotCommandError(f"the {what} is not valid JSON ({error.msg})") from None
    if not isinstance(parsed, dict):
        raise RobotCommandError(f"the {what} must be a mapping like {{\"data\": 1}}, not {value!r}")
    return parsed


class RosCommands(RobotCommands):
    """Publish, listen, call services, send goals, parameters and logging on any robot."""

    def __init__(self, backend, say=print):
        """``say(text)`` shows log lines to the person (the run's console)."""
        super().__init__(backend)
        self.say = say

    def publish(self, topic, message_type, value):
        """Publish ``value`` on ``topic`` as a std_msgs type (String, Bool, Float64, Int64, UInt64)."""
        msg_type = self.choose(message_type, STD_TYPES, "message type")
        self.backend.publish(str(topic), msg_type, {"data": value})

    def publish_message(self, topic, message_type, fields):
        """Publish any message type, its fields given as a mapping (or JSON text)."""
        self.backend.publish(str(topic), str(message_type), _as_dict(fields, "message"))

    def wait_for_message(self, topic, timeout=10):
        """Wait for the next message on ``topic`` (any type) and return it."""
        return self.backend.wait_for_message(str(topic), None, self.number(timeout, "the timeout"))

    @staticmethod
    def field(message, path):
        """The field at ``path`` (``pose.pose.position.x``) of a message."""
        try:
            return field_value(message, str(path))
        except KeyError:
            raise RobotCommandError(f"the message has no field '{path}'") from None

    def latest(self, topic, path):
        """The newest value of the field ``path`` on ``topic`` (waiting briefly for a first message)."""
        message = self.backend.latest(str(topic), None) or self.wait_for_message(topic, 3)
        return self.field(message, path)

    def call_service(self, name, service_type, request=None, timeout=10):
        """Call a service; ``request`` is a mapping (or JSON text); returns the response."""
        return self.backend.call_service(str(name), str(service_type), _as_dict(request, "service request"),
                                         self.number(timeout, "the timeout"))

    def send_goal(self, action, action_type, goal=None, timeout=GOAL_TIMEOUT):
        """Send an action goal and wait: returns 'succeeded', 'aborted', 'preempted' or 'rejected'."""
        handle = self.backend.send_goal(str(action), str(action_type), _as_dict(goal, "goal"))
        return handle.wait(self.number(timeout, "the timeout")).status.value

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
