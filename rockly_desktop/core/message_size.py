"""About how many bytes a robot message holds in memory, cheaply enough to ask for every message.

The state store and the recorder bound what they keep by bytes, not by count: one camera
image weighs as much as a thousand odometry messages. A message is a dict of fields (ROS 2,
the simulator) or a rospy message object (ROS 1); large arrays are compact there (``bytes``,
``array.array``) or Python lists. A list of dicts or messages is judged by its first item
(its items share one type), so a message costs a walk of its fields, not of its arrays.
"""
import array

_ITEM = 8          # a list's pointer to each item
_NUMBER = 32       # a float or a large int in a list: the object and its pointer
_CONTAINER = 64    # a dict, list or message object's own overhead
_FIELD = 48        # a dict entry or an object's slot, with its small value


def message_bytes(message) -> int:
    """About how many bytes ``message`` (a dict, a list or a rospy message) takes in memory."""
    return _size(message, 0)


def _size(value, depth):
    if isinstance(value, (bytes, bytearray, str)):
        return _CONTAINER + len(value)
    if isinstance(value, array.array):
        return _CONTAINER + value.itemsize * len(value)
    if depth > 12:  # deeper than any message type: counted as one field
        return _FIELD
    if isinstance(value, dict):
        return _CONTAINER + sum(_FIELD + _size(item, depth + 1) for item in value.values())
    if isinstance(value, (list, tuple)):
        if not value:
            return _CONTAINER
        first = value[0]
        if isinstance(first, (int, float)):
            return _CONTAINER + len(value) * (_ITEM if isinstance(first, bool) else _NUMBER)
        return _CONTAINER + len(value) * (_ITEM + _size(first, depth + 1))
    slots = getattr(value, "__slots__", None)
    if slots and not isinstance(slots, str):  # a rospy message: its fields are its slots
        return _CONTAINER + sum(_FIELD + _size(getattr(value, name, None), depth + 1) for name in slots)
    if hasattr(value, "nbytes"):  # a numpy array
        return _CONTAINER + int(value.nbytes)
    return 0  # a number, None or a bool: inside its field's cost
