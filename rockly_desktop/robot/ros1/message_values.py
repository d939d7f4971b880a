"""Rockly's plain dicts converted to ROS 1 messages and back, with every value checked.

``to_message`` and ``from_message`` convert plain dicts shaped like the message (missing
fields keep their defaults, nested messages are dicts, lists of messages lists of dicts,
``time``/``duration`` are float seconds or ``{"secs": .., "nsecs": ..}``) to genpy
instances and back; errors name the field path.
"""
import importlib
import math
import numbers
import weakref
from collections.abc import Mapping

import genmsg.msgs
import genpy

from rockly_desktop.core.errors import RobotCommandError
from rockly_desktop.core.message_arrays import SHOWN_ITEMS

_INT_RANGES = {
    "int8": (-2 ** 7, 2 ** 7 - 1), "byte": (-2 ** 7, 2 ** 7 - 1),
    "uint8": (0, 2 ** 8 - 1), "char": (0, 2 ** 8 - 1),
    "int16": (-2 ** 15, 2 ** 15 - 1), "uint16": (0, 2 ** 16 - 1),
    "int32": (-2 ** 31, 2 ** 31 - 1), "uint32": (0, 2 ** 32 - 1),
    "int64": (-2 ** 63, 2 ** 63 - 1), "uint64": (0, 2 ** 64 - 1),
}
_FLOAT32_MAX = 3.4028234663852886e38
_FIELDS = weakref.WeakKeyDictionary()  # message class -> {field: type}


def _join(path, name):
    return f"{path}.{name}" if path else str(name)


def _bad(path, what, value):
    return RobotCommandError(f"{path}: expected {what}, got {value!r}")


def to_message(cls, data=None):
    """A ``cls`` instance from a dict shaped like the message (missing fields = defaults)."""
    if not (isinstance(cls, type) and issubclass(cls, genpy.Message)):
        raise RobotCommandError(f"to_message needs a ROS message class, got {cls!r}")
    return _to_message(cls, data, "")


def from_message(msg, compact: bool = False) -> dict:
    """A plain dict from a genpy message: nested messages as dicts, arrays as lists, ``uint8[]``
    as a list of numbers (with ``compact``: as the ``bytes`` rospy gave when it holds more than
    ``SHOWN_ITEMS``, what the panels show of a camera image), ``time``/``duration`` as
    ``{"secs": .., "nsecs": ..}``."""
    if not isinstance(msg, genpy.Message):
        raise RobotCommandError(f"from_message needs a ROS message, got {msg!r}")
    return {name: _from_value(getattr(msg, name), compact) for name in msg.__slots__}


def shown_message(message) -> dict:
    """What the state store's panels read of a recorded message: a rospy message as a compact dict
    (``from_message``), a dict (a service call this node made) as it is."""
    return message if isinstance(message, dict) else from_message(message, compact=True)


def _from_value(value, compact=False):
    if isinstance(value, genpy.Message):
        return from_message(value, compact)
    if isinstance(value, genpy.TVal):
        return {"secs": value.secs, "nsecs": value.nsecs}
    if isinstance(value, (bytes, bytearray)):
        return bytes(value) if compact and len(value) > SHOWN_ITEMS else list(value)
    if isinstance(value, (list, tuple)):
        return [_from_value(v, compact) for v in value]
    return value


def _to_message(cls, data, path):
    if isinstance(data, genpy.Message) and getattr(data, "_type", None) == cls._type:
        return data
    if data is None:
        data = {}
    if not isinstance(data, Mapping):
        raise _bad(path or cls._type, f"a dict for {cls._type}", data)
    fields = _fields(cls)
    for key in data:
        if key not in fields:
            raise RobotCommandError(f"{_join(path, key)}: {cls._type} has no field {key!r} "
                                    f"(its fields: {', '.join(cls.__slots__) or 'none'})")
    msg = cls()
    for name, field_type in fields.items():
        if name in data:
            setattr(msg, name, _to_field(cls, field_type, data[name], _join(path, name)))
    return msg


def _fields(cls) -> dict:
    """``{field: type}`` of a message class, worked out once per class."""
    fields = _FIELDS.get(cls)
    if fields is None:
        fields = _FIELDS[cls] = dict(zip(cls.__slots__, cls._slot_types))
    return fields


def _to_field(owner, field_type, value, path):
    base, is_array, length = genmsg.msgs.parse_type(field_type)
    if not is_array:
        return _to_scalar(owner, base, value, path)
    if base in ("uint8", "char") and isinstance(value, (bytes, bytearray)):
        items = bytes(value)
    elif isinstance(value, (list, tuple)):
        items = [_to_scalar(owner, base, v, f"{path}[{i}]") for i, v in enumerate(value)]
    else:
        raise _bad(path, "a list", value)
    if length is not None and len(items) != length:
        raise RobotCommandError(f"{path}: expected {length} values, got {len(items)}")
    return bytes(items) if base in ("uint8", "char") else items


def _to_scalar(owner, base, value, path):
    if base in _INT_RANGES:
        return _to_int(base, value, path)
    if base in ("float32", "float64"):
        if isinstance(value, bool) or not isinstance(value, numbers.Real):
            raise _bad(path, "a number", value)
        number = float(value)
        if base == "float32" and math.isfinite(number) and abs(number) > _FLOAT32_MAX:
            raise RobotCommandError(f"{path}: {value!r} is too large for a float32")
        return number
    if base == "bool":
        if isinstance(value, bool):
            return value
        if isinstance(value, numbers.Integral) and value in (0, 1):
            return bool(value)
        raise _bad(path, "true or false", value)
    if base == "string":
        if not isinstance(value, str):
            raise _bad(path, "a string", value)
        return value
    if base in ("time", "duration"):
        return _to_time(base, value, path)
    return _to_message(field_class(owner, base), value, path)


def _to_int(base, value, path):
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise _bad(path, "a whole number", value)
    if not isinstance(value, numbers.Integral):
        if not (math.isfinite(value) and float(value).is_integer()):
            raise _bad(path, "a whole number", value)
    number = int(value)
    low, high = _INT_RANGES[base]
    if not low <= number <= high:
        raise RobotCommandError(f"{path}: {value!r} is out of range for {base} ({low} to {high})")
    return number


def _to_time(base, value, path):
    cls = genpy.Time if base == "time" else genpy.Duration
    if isinstance(value, cls):
        return value
    try:
        if isinstance(value, Mapping):
            unknown = set(value) - {"secs", "nsecs"}
            if unknown:
                raise RobotCommandError(f"{path}: a {base} has only 'secs' and 'nsecs', not {sorted(unknown)[0]!r}")
            return cls(_to_int("int64", value.get("secs", 0), _join(path, "secs")),
                       _to_int("int64", value.get("nsecs", 0), _join(path, "nsecs")))
        if isinstance(value, numbers.Real) and not isinstance(value, bool) and math.isfinite(value):
            return cls.from_sec(float(value))
    except (TypeError, ValueError, OverflowError) as e:
        raise RobotCommandError(f"{path}: {value!r} is not a valid {base}: {e}") from e
    raise _bad(path, f"a {base} in seconds (a number) or {{'secs': .., 'nsecs': ..}}", value)



def slot_class(owner, slot):
    """The message class of field ``slot`` of message class ``owner``."""
    return field_class(owner, owner._slot_types[owner.__slots__.index(slot)])


def field_class(owner, type_name):
    """The class of a nested field's type, as the module that defines ``owner`` sees it."""
    if "/" not in type_name:
        type_name = "std_msgs/Header" if type_name == "Header" else f"{owner._type.split('/')[0]}/{type_name}"
    package, name = type_name.split("/")
    namespace = getattr(owner.__init__, "__globals__", {})
    msg_module = getattr(namespace.get(package), "msg", None)
    cls = getattr(msg_module, name, None) or namespace.get(f"_{package}__{name}")  # genpy.dynamic's name for it
    if not (isinstance(cls, type) and issubclass(cls, genpy.Message)):
        try:
            cls = getattr(importlib.import_module(f"{package}.msg"), name, None)
        except ImportError:
            cls = None
    if not (isinstance(cls, type) and issubclass(cls, genpy.Message)):
        raise RobotCommandError(f"The ROS message type {type_name} (used by {owner._type}) cannot be found.")
    return cls
