"""What a velocity command must be for a teacher's speed limit to hold on it.

A limit can only be kept on a message it understands: a ``geometry_msgs/Twist`` (or a
``TwistStamped``, whose ``twist`` is one) whose velocities are real numbers. Anything else on a
drive topic (another type with the same field names, a speed given as the text "1.0" or as
``true``, a vector that is no mapping) cannot be clamped, and a robot or a converter downstream
might still read it as a speed: under a limit it is refused, with ``velocity_problem`` saying why.
"""
import numbers
from collections.abc import Mapping

from rockly_desktop.robot.wrappers.ros_versions import short_type

TWIST, TWIST_STAMPED = "geometry_msgs/Twist", "geometry_msgs/TwistStamped"
_VECTORS = ("linear", "angular")
_AXES = ("x", "y", "z")


def is_velocity_number(value) -> bool:
    """True for a real number (an int or a float, not a bool): what a velocity field may hold."""
    return isinstance(value, numbers.Real) and not isinstance(value, bool)


def velocity_problem(msg_type, message):
    """None when ``message`` is a velocity a limit can keep; else ``(key, values)`` of the text saying
    why not (``limit_velocity_type`` or ``limit_velocity_value`` in Rockly's catalogue)."""
    kind = short_type(msg_type)
    if kind not in (TWIST, TWIST_STAMPED):
        return "limit_velocity_type", {"type": str(msg_type), "expected": f"{TWIST} / {TWIST_STAMPED}"}
    if message is None:
        return None
    if not isinstance(message, Mapping):
        return "limit_velocity_value", {"field": "(message)", "value": repr(message)}
    if kind == TWIST_STAMPED:
        unknown = set(message) - {"header", "twist"}
        if unknown:
            return "limit_velocity_value", {"field": sorted(unknown)[0], "value": repr(message[sorted(unknown)[0]])}
        return _twist_problem(message.get("twist"), "twist.")
    return _twist_problem(message, "")


def _twist_problem(twist, prefix):
    if twist is None:
        return None
    if not isinstance(twist, Mapping):
        return "limit_velocity_value", {"field": prefix.rstrip(".") or "(message)", "value": repr(twist)}
    for key, vector in twist.items():
        if key not in _VECTORS or not (vector is None or isinstance(vector, Mapping)):
            return "limit_velocity_value", {"field": prefix + str(key), "value": repr(vector)}
        for axis, value in (vector or {}).items():
            if axis not in _AXES or not is_velocity_number(value):
                return "limit_velocity_value", {"field": f"{prefix}{key}.{axis}", "value": repr(value)}
    return None
