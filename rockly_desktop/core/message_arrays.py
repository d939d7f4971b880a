"""Large arrays of a message dict kept compact (``array.array``, ``bytes``) and made lists where wanted.

A ROS 2 message comes from the helper with its numeric arrays as ``array.array`` (a 1 MB image
is 1 MB, not 8 MB of list), and the state store keeps it so. A program gets lists, as ever
(``as_lists``); the panels get lists of a few numbers and compact arrays of many (``as_shown``),
which the Topic monitor shows as a size and their first values.
"""
import array

SHOWN_ITEMS = 64
"""Arrays of at most this many items are shown as lists (they can be expanded, their items plotted)."""


def as_lists(message):
    """``message`` with every ``array.array`` a list (the same object when it has none)."""
    return _converted(message, 0)


def as_shown(message):
    """``message`` with arrays of at most SHOWN_ITEMS items as lists, larger ones kept compact."""
    return _converted(message, SHOWN_ITEMS)


def _converted(value, keep_over):
    if isinstance(value, array.array):
        return value.tolist() if not keep_over or len(value) <= keep_over else value
    if isinstance(value, dict):
        items = {key: _converted(item, keep_over) for key, item in value.items()}
        return value if all(items[key] is item for key, item in value.items()) else items
    if isinstance(value, list) and value and isinstance(value[0], (dict, list, array.array)):
        items = [_converted(item, keep_over) for item in value]
        return value if all(new is old for new, old in zip(items, value)) else items
    return value
