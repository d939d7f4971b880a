"""The base of every profile's robot commands (the object bound as ``robot`` in programs)."""
import json
import math

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import RobotCommandError


class RobotCommands:
    """Commands of one kind of robot, written against a RobotBackend.

    Subclasses add methods that read like what a person wants the robot to do
    (``robot.gripper('open')``) and translate them into topics, services and actions.
    The ``what`` of the checks below names the argument in an error: a text of the
    profile's catalogue (``Texts``), so that the error is shown in the run's language.
    """

    def __init__(self, backend):
        self._backend = backend

    @property
    def backend(self):
        """The RobotBackend these commands drive."""
        return self._backend

    def allowed_speed(self, own_speed: float, turning: bool = False) -> float:
        """How fast a motion the robot makes at its own ``own_speed`` (m/s; turning: rad/s) may go.

        ``own_speed`` itself unless a teacher's limit is lower: then the limit (and the console
        says so once). A command that drives a distance at the robot's own speed (a base
        driver's discrete motion) asks this first and, when the answer is lower, drives with
        velocity commands at that speed instead. The backend a run gives the commands answers it
        (a teacher's ``LimitedBackend``, or a wrapper around one); any other has no limits.
        """
        ask = getattr(self._backend, "allowed_speed", None)
        return own_speed if ask is None else ask(own_speed, turning)

    def ros_type(self, name: str, msg_type: str = None) -> str:
        """The type this robot wants on the ROS ``name`` (the profile's ``ros_versions`` resolved for it).

        Commands need not ask before publishing: a message written for the ``ros_interface`` type
        (a Twist dict on ``/cmd_vel``) is sent as the type the robot wants (a TwistStamped). This is
        for commands that read or show the type. ``msg_type`` where nothing differs per version.
        """
        ask = getattr(self._backend, "type_for", None)
        return msg_type if ask is None else ask(name, msg_type)

    @staticmethod
    def choose(value, choices, what: str):
        """Return ``choices[value]``; a value not in ``choices`` raises a RobotCommandError listing them."""
        try:
            known = value in choices
        except TypeError:  # an unhashable value, e.g. a list from a program
            known = False
        if not known:
            listed = ", ".join(repr(choice) for choice in choices)
            raise RobotCommandError(app_local_text("command_unknown_choice", what=what, value=repr(value),
                                                   choices=listed))
        return choices[value]

    @staticmethod
    def number(value, what: str) -> float:
        """``value`` as a float; anything else raises a RobotCommandError naming ``what``."""
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
            raise RobotCommandError(app_local_text("command_not_number", what=what, value=repr(value)))
        return float(value)

    @staticmethod
    def mapping(value, what: str) -> dict:
        """``value`` as a dict of message fields: a mapping, JSON text of one (blocks have no
        dictionary block), or empty for None or ''; anything else raises a RobotCommandError."""
        if value is None or value == "":
            return {}
        if isinstance(value, dict):
            return dict(value)
        try:
            parsed = json.loads(value) if isinstance(value, str) else None
        except json.JSONDecodeError as error:
            raise RobotCommandError(app_local_text("command_not_json", what=what, problem=error.msg)) from None
        if not isinstance(parsed, dict):
            raise RobotCommandError(app_local_text("command_not_mapping", what=what, example='{"data": 1}',
                                                   value=repr(value)))
        return parsed
