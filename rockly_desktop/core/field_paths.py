"""Fields of message dicts by path (``pose.pose.position.x``, ``ranges[3]``), as the panels offer them.

The Topic monitor lets a numeric field be dragged to the Plot panel as ``"topic|field.path"``;
the Plot panel completes the paths of a topic's numeric fields. Paths are the ones
:func:`rockly_desktop.core.state_store.field_value` reads.
"""
import array
import re
from itertools import islice

MAX_INDEXED_ITEMS = 32
"""List elements :func:`numeric_paths` offers."""

_NAME = re.compile(r"[A-Za-z_]\w*")


def field_mime_text(topic: str, path: str) -> str:
    """The drag text for one field: ``"topic|field.path"``."""
    return f"{topic}|{path}"


def parse_mime_text(text: str) -> list:
    """The (topic, path) pairs in a drag text: one ``topic|field.path`` a line; malformed lines are skipped."""
    fields = []
    for line in (text or "").splitlines():
        topic, bar, path = line.strip().partition("|")
        if bar and topic.strip() and path.strip():
            fields.append((topic.strip(), path.strip()))
    return fields


def numeric_paths(message, prefix: str = "") -> list:
    """The paths of the numeric fields in a message dict (the first few elements of lists), for completion."""
    paths = []
    if isinstance(message, dict):
        for key, value in message.items():
            paths += numeric_paths(value, f"{prefix}.{key}" if prefix else str(key))
    elif isinstance(message, (list, tuple, array.array)) and prefix:
        for index, value in enumerate(message[:MAX_INDEXED_ITEMS]):
            paths += numeric_paths(value, f"{prefix}[{index}]")
    elif isinstance(message, (int, float)) and not isinstance(message, bool) and prefix:
        paths.append(prefix)
    return paths


def child_fields(value, path, limit: int):
    """(label, child, child's field path or None) of a dict or list, lists cut after ``limit`` items.

    ``path`` is ``value``'s own path ("" for the message, None when it has none); a child has
    none when its key is not a name, or when it is an element of a list inside a list
    (``field_value`` knows ``name[i]``, not ``name[i][j]``).
    """
    if isinstance(value, dict):
        for key, child in value.items():
            name = str(key)
            valid = path is not None and _NAME.fullmatch(name)
            yield name, child, (f"{path}.{name}" if path else name) if valid else None
    else:
        indexable = bool(path) and not path.endswith("]")
        for position, child in enumerate(islice(value, limit)):
            yield f"[{position}]", child, f"{path}[{position}]" if indexable else None
