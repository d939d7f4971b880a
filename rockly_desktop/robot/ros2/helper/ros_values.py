"""rclpy interface classes by name, and plain dicts <-> rclpy messages (runs in the ROS 2 helper).

Names may be ``pkg/msg/Type`` or the short ``pkg/Type`` (ROS 1's spelling); a dict's missing
fields keep the type's defaults. Whole numbers are accepted for float fields, as on ROS 1.
Time stamps and durations also carry ROS 1's ``secs``/``nsecs`` (and accept them), and a
header's ROS 1 ``seq`` is dropped, so a profile (or simulator) written for ROS 1 runs unchanged.
"""
import array
import functools
import importlib
import importlib.util

from rosidl_parser.definition import AbstractNestedType, BasicType, NamespacedType

from rockly_desktop.robot.ros2.wire import TextError


class MissingInterface(TextError, LookupError):
    """A ROS 2 interface type this environment does not have (its words: a catalogue text)."""


class BadValue(TextError, ValueError):
    """A value a ROS 2 message or parameter cannot hold (its words: a catalogue text)."""


_FLOATS = {"float", "double", "long double"}


# every publish asks (a name found once stays found; a missing one is looked for again)
@functools.lru_cache(maxsize=None)
def interface_class(name: str, kind: str):
    """The class of ``name`` (``pkg/Type`` or ``pkg/KIND/Type``); kind is msg, srv or action.

    An action may be named as on ROS 1, ``pkg/NameAction``.

    Raises LookupError naming what is missing (a package not installed in ROS 2's environment).
    """
    parts = name.strip("/").split("/")
    if len(parts) == 3:
        package, kind, type_name = parts
        kinds = (kind,)
    elif len(parts) == 2:
        package, type_name = parts
        kinds = (kind, "action", "srv") if kind == "msg" else (kind,)  # an action's or service's own messages
    else:
        raise MissingInterface("ros2_not_a_type", name=name)
    if importlib.util.find_spec(package) is None:
        raise MissingInterface("ros2_no_package", package=package)
    if kind == "action" and type_name.endswith("Action") and len(parts) == 2:
        type_name = type_name[:-len("Action")]
    for each in kinds:
        try:
            return _member(importlib.import_module(f"{package}.{each}"), type_name)
        except (ImportError, AttributeError):
            continue
    raise MissingInterface("ros2_no_type", package=package, kind=kind, type=type_name)


def _member(module, type_name: str):
    """``Type`` of a module, or a part of one the graph names with an underscore
    (``Fibonacci_FeedbackMessage``, an action's feedback topic; ``SetBool_Request``)."""
    if hasattr(module, type_name):
        return getattr(module, type_name)
    base, _underscore, part = type_name.partition("_")
    owner = getattr(module, base)
    return getattr(owner, part) if hasattr(owner, part) else getattr(owner.Impl, part)


def class_of(namespaced: NamespacedType):
    """The rclpy class of a nested field's type."""
    return getattr(importlib.import_module(".".join(namespaced.namespaces)), namespaced.name)


def _value(slot, value, path):
    if isinstance(slot, AbstractNestedType):
        item = slot.value_type
        if isinstance(item, NamespacedType):
            return [to_message(class_of(item), entry, f"{path}[{index}]") for index, entry in enumerate(value)]
        if isinstance(item, BasicType) and item.typename in _FLOATS:
            return [float(entry) if _whole_number(entry) else entry for entry in value]
        return value
    if isinstance(slot, BasicType) and slot.typename in _FLOATS and _whole_number(value):
        return float(value)
    return value


def _whole_number(value) -> bool:
    """True for an int that goes into a float field as on ROS 1; a bool or a text does not (rclpy refuses it)."""
    return isinstance(value, int) and not isinstance(value, bool)


def to_message(message_class, data, path=""):
    """A ``message_class`` instance with the fields of the dict ``data`` (ValueError names a bad field)."""
    return _fill(message_class(), data, path)


def _fill(message, data, path):
    """``message`` with the fields of ``data`` set; a nested message is filled where it is (cheaper
    than a new one, which its setter would check again)."""
    if not data:
        return message
    message_class = type(message)
    if not isinstance(data, dict):
        if path:
            raise BadValue("ros2_field_not_fields", field=path, value=repr(data))
        raise BadValue("ros2_message_not_fields", value=repr(data))
    if is_time(message_class):
        data = {_ROS1_TIME.get(name, name): value for name, value in data.items()}
    elif is_header(message_class) and "seq" in data:
        data = {name: value for name, value in data.items() if name != "seq"}  # ROS 1's, gone in ROS 2
    fields = slots(message_class)
    for name, value in data.items():
        where = f"{path}.{name}" if path else name
        if name not in fields:
            raise BadValue("ros2_no_field", type=message_class.__name__, field=where)
        slot = fields[name]
        if isinstance(slot, NamespacedType):
            _fill(getattr(message, name), value, where)
            continue
        try:
            setattr(message, name, _value(slot, value, where))
        except BadValue:
            raise
        except (AssertionError, TypeError, ValueError) as error:
            if str(error):
                raise BadValue("ros2_bad_field", field=where, value=repr(value), error=str(error)) from None
            raise BadValue("ros2_wrong_type_field", field=where, value=repr(value)) from None
    return message


@functools.lru_cache(maxsize=None)
def slots(message_class) -> dict:
    """Field name -> its rosidl type, per class (asked for every message, so kept)."""
    return dict(zip(message_class.get_fields_and_field_types(), message_class.SLOT_TYPES))


def from_message(message, compact: bool = False) -> dict:
    """The message as plain dicts, lists and numbers; with ``compact``, its sequences of numbers
    (``uint8[]``, ``float32[]``) stay ``array.array`` (a topic's messages cross the pipe so, and Rockly's
    side makes them lists for a program, ``core/message_arrays.py``)."""
    data = {name: _plain(getattr(message, name), compact) for name in slots(type(message))}
    if is_time(type(message)):
        data.update(secs=data["sec"], nsecs=data["nanosec"])
    return data


_ROS1_TIME = {"secs": "sec", "nsecs": "nanosec"}


@functools.lru_cache(maxsize=None)
def is_header(message_class) -> bool:
    """Whether ``message_class`` is std_msgs/Header (ROS 1's ``seq`` is dropped from it)."""
    return message_class.__module__.startswith("std_msgs.") and message_class.__name__ == "Header"


@functools.lru_cache(maxsize=None)
def is_time(message_class) -> bool:
    """Whether ``message_class`` is a stamp or a duration (ROS 1's ``secs``/``nsecs`` are taken too)."""
    return message_class.__module__.startswith("builtin_interfaces.") and message_class.__name__ in ("Time", "Duration")


_COMPACT_ITEMS = 64  # a fixed-size array (numpy) of more items stays compact too


def _plain(value, compact=False):
    if hasattr(value, "get_fields_and_field_types"):
        return from_message(value, compact)
    if isinstance(value, list):
        return [_plain(entry, compact) for entry in value]
    if isinstance(value, array.array):
        return value if compact else value.tolist()
    if hasattr(value, "tolist"):
        if compact and value.size > _COMPACT_ITEMS and value.dtype.char in array.typecodes:
            return array.array(value.dtype.char, value.tobytes())
        return value.tolist()
    return value


def parameter_value(value) -> object:
    """A rcl_interfaces ParameterValue as a Python value (None when the parameter is not set)."""
    kinds = {1: "bool_value", 2: "integer_value", 3: "double_value", 4: "string_value",
             5: "byte_array_value", 6: "bool_array_value", 7: "integer_array_value",
             8: "double_array_value", 9: "string_array_value"}
    field = kinds.get(value.type)
    return None if field is None else _plain(getattr(value, field))


def to_parameter_value(value):
    """A Python value as a rcl_interfaces ParameterValue."""
    from rcl_interfaces.msg import ParameterValue

    if isinstance(value, bool):
        return ParameterValue(type=1, bool_value=value)
    if isinstance(value, int):
        return ParameterValue(type=2, integer_value=value)
    if isinstance(value, float):
        return ParameterValue(type=3, double_value=value)
    if isinstance(value, str):
        return ParameterValue(type=4, string_value=value)
    if isinstance(value, (list, tuple)) and value:
        first = value[0]
        if isinstance(first, bool):
            return ParameterValue(type=6, bool_array_value=list(value))
        if isinstance(first, int):
            return ParameterValue(type=7, integer_array_value=list(value))
        if isinstance(first, float):
            return ParameterValue(type=8, double_array_value=[float(v) for v in value])
        if isinstance(first, str):
            return ParameterValue(type=9, string_array_value=list(value))
    raise BadValue("ros2_bad_parameter_value", value=repr(value))
