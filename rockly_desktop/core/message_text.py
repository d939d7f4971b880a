"""How the Topic monitor writes a message's values: numbers exactly, strings quoted, lists summed up."""
import array
import json
import numbers
from itertools import islice

TEXT_LIMIT = 200
"""Characters of a long string or value shown."""


def value_kind(value) -> str:
    """``"dict"``, ``"list"``, ``"number"`` (not a bool) or ``"leaf"``."""
    if isinstance(value, dict):
        return "dict"
    if isinstance(value, (list, tuple, array.array)):  # array: a long one kept compact (core/message_arrays)
        return "list"
    if isinstance(value, numbers.Real) and not isinstance(value, bool):
        return "number"
    return "leaf"


def _clip(text: str) -> str:
    return text if len(text) <= TEXT_LIMIT else text[:TEXT_LIMIT] + "…"


def value_text(value) -> str:
    """How one value is shown: numbers exactly, strings quoted, bytes by size."""
    if isinstance(value, str):
        return _clip(json.dumps(value, ensure_ascii=False))
    if isinstance(value, (bytes, bytearray)):
        return f"<{len(value)} bytes> {value[:16].hex(' ')}" + (" …" if len(value) > 16 else "")
    if isinstance(value, float):
        text = f"{value:.15g}"  # 15 digits: every digit meaningful, no 1.9449999999999998
        return text if any(mark in text for mark in ".en") else text + ".0"
    return _clip(str(value))


def summary(value, items_text) -> str:
    """The value column of a dict (empty) or list row: its first values, or ``items_text(count)``
    (the window's translated "N items") for a list of dicts or lists."""
    if value_kind(value) == "dict":
        return ""
    if not value:
        return "[]"
    if any(value_kind(item) in ("dict", "list") for item in islice(value, 8)):
        return items_text(len(value))
    parts, width = [], 0
    for item in islice(value, 12):
        part = value_text(item)
        if width + len(part) > 60 and parts:
            break
        parts.append(part)
        width += len(part) + 2
    text = "[" + ", ".join(parts) + (", …]" if len(parts) < len(value) else "]")
    return f"({len(value)}) {text}" if len(parts) < len(value) else text
