"""A message type's layout as plain data, for Rockly's side to encode its messages (runs in the ROS 2 helper).

Rockly's process has no rclpy, but encoding a message there (``cdr_encoding``) and publishing the
bytes as they are spares the helper building an rclpy message and converting it to C, which is
most of a publish's cost. The layout comes from the rclpy class itself (its rosidl slot types and
a fresh instance's defaults), so it is the type the helper would publish.

A layout is a tuple of ``(name, spec, default)`` per field, in order. A spec is one of:
``("num", code)`` a number or bool as a ``struct`` code (``?`` bool, ``b``…``Q`` integers, ``f``/``d``
floats), ``("octet",)``, ``("str", bound)`` (bound 0: unbounded), ``("msg", layout, special)`` a nested
message (special: "time" for a stamp or duration, "header" for std_msgs/Header, else ""),
``("array", item, size)`` and ``("seq", item, bound)``. A type with a field none of these can hold
(a wide string, a character) has no layout: its messages go the way of every other, as fields.
"""
import array

from rosidl_parser.definition import (
    AbstractSequence,
    Array,
    BasicType,
    BoundedSequence,
    BoundedString,
    NamespacedType,
    UnboundedString,
)

from rockly_desktop.robot.ros2.helper.ros_values import class_of, is_header, is_time, slots

_CODES = {"boolean": "?", "int8": "b", "uint8": "B", "int16": "h", "uint16": "H", "int32": "i", "uint32": "I",
          "int64": "q", "uint64": "Q", "float": "f", "double": "d"}


class NoLayout(Exception):
    """A field Rockly's side cannot encode."""


def layout(message_class):
    """``message_class``'s layout (see above), or None when Rockly's side cannot encode it."""
    try:
        return _layout(message_class)
    except NoLayout:
        return None


def _layout(message_class):
    fields = slots(message_class)
    if not fields:
        raise NoLayout("no fields")  # ROS 2 gives an empty type a hidden member of its own
    fresh = message_class()
    return tuple((name, _spec(slot), _plain(getattr(fresh, name)))
                 for name, slot in fields.items())


def _spec(slot):
    if isinstance(slot, BasicType):
        if slot.typename == "octet":
            return ("octet",)
        if slot.typename not in _CODES:
            raise NoLayout(slot.typename)
        return ("num", _CODES[slot.typename])
    if isinstance(slot, (BoundedString, UnboundedString)):
        return ("str", slot.maximum_size if isinstance(slot, BoundedString) else 0)
    if isinstance(slot, NamespacedType):
        nested = class_of(slot)
        special = "time" if is_time(nested) else "header" if is_header(nested) else ""
        return ("msg", _layout(nested), special)
    if isinstance(slot, Array):
        return ("array", _item(slot.value_type), slot.size)
    if isinstance(slot, AbstractSequence):
        bound = slot.maximum_size if isinstance(slot, BoundedSequence) else 0
        return ("seq", _item(slot.value_type), bound)
    raise NoLayout(repr(slot))


def _item(value_type):
    item = _spec(value_type)
    if item[0] == "octet":
        raise NoLayout("an array of octets")  # rclpy holds them as bytes objects or a bytes string, by version
    return item


def _plain(value):
    """A default as plain data: a nested message's default is its own layout's (``None``)."""
    if hasattr(value, "get_fields_and_field_types"):
        return None
    if isinstance(value, list):
        return [_plain(entry) for entry in value]
    if isinstance(value, array.array) or hasattr(value, "tolist"):
        return value.tolist()
    return value
