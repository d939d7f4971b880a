"""JSON for program documents: any nesting depth, strict numbers.

Blockly's JSON nests one level per ``next`` block, so a stack of 500 blocks is over
1,000 levels deep, past what Python's recursive ``json`` module takes. ``loads`` and
``dumps`` use the fast C codec and fall back to an iterative one (no recursion, any
depth up to ``MAX_DEPTH``) when it gives up. Only real numbers pass: ``NaN``,
``Infinity`` and literals too large for a float (``1e400``) are refused, because the
editor page's ``JSON.parse`` refuses them and a program must read the same on both sides.
"""
import json
import math
import re
from json.decoder import scanstring
from json.encoder import encode_basestring, encode_basestring_ascii

MAX_DEPTH = 100_000  # levels of objects and lists: a stack of ~50,000 blocks

_WHITESPACE = re.compile(r"[ \t\n\r]*")
_NUMBER = re.compile(r"-?(?:0|[1-9]\d*)(\.\d+)?([eE][-+]?\d+)?")
_LITERALS = (("true", True), ("false", False), ("null", None))


class TooDeep(ValueError):
    """The document nests deeper than ``MAX_DEPTH``."""


def _refuse_constant(name: str):
    raise ValueError(f"{name} is not a number JSON allows")


def _finite_float(text: str) -> float:
    value = float(text)
    if not math.isfinite(value):
        raise ValueError(f"the number {text[:40]} is too large")
    return value


def loads(text: str):
    """Parse JSON ``text`` of any depth up to ``MAX_DEPTH``.

    Raises ``json.JSONDecodeError`` for broken text, ``ValueError`` for a number that
    is not finite, ``TooDeep`` past ``MAX_DEPTH``.
    """
    try:
        return json.loads(text, parse_constant=_refuse_constant, parse_float=_finite_float)
    except RecursionError:
        return _loads_iteratively(text)


def dumps(value, *, indent=None, ensure_ascii: bool = True) -> str:
    """Write ``value`` as JSON, any depth (``indent`` and ``ensure_ascii`` as ``json.dumps``).

    A document too deep for ``json`` is written compact, whatever ``indent`` says: its
    indentation would grow with the square of the depth (125 MB for 5,000 blocks).
    """
    try:
        return json.dumps(value, indent=indent, ensure_ascii=ensure_ascii, allow_nan=False)
    except RecursionError:
        return _dumps_iteratively(value, ensure_ascii)


def _skip(text: str, pos: int) -> int:
    return _WHITESPACE.match(text, pos).end()


def _key(text: str, pos: int):
    """An object's key and the position after its colon."""
    if not text.startswith('"', pos):
        raise json.JSONDecodeError("Expecting property name enclosed in double quotes", text, pos)
    key, pos = scanstring(text, pos + 1, True)
    pos = _skip(text, pos)
    if not text.startswith(":", pos):
        raise json.JSONDecodeError("Expecting ':' delimiter", text, pos)
    return key, _skip(text, pos + 1)


def _scalar(text: str, pos: int):
    """A string, number or literal at ``pos`` and the position after it."""
    if text.startswith('"', pos):
        return scanstring(text, pos + 1, True)
    for word, value in _LITERALS:
        if text.startswith(word, pos):
            return value, pos + len(word)
    match = _NUMBER.match(text, pos)
    if match is None or match.end() == pos:
        raise json.JSONDecodeError("Expecting value", text, pos)
    number = match.group()
    if match.group(1) or match.group(2):
        return _finite_float(number), match.end()
    return int(number), match.end()


def _loads_iteratively(text: str):
    stack = []  # [container, key of the value being read (objects only)]
    pos = _skip(text, 0)
    while True:
        opener = text[pos:pos + 1]
        if opener in ("{", "["):
            if len(stack) >= MAX_DEPTH:
                raise TooDeep(f"the JSON is nested too deeply (more than {MAX_DEPTH:,} levels)")
            pos = _skip(text, pos + 1)
            closer = "}" if opener == "{" else "]"
            if not text.startswith(closer, pos):
                if opener == "{":
                    key, pos = _key(text, pos)
                    stack.append([{}, key])
                else:
                    stack.append([[], None])
                continue
            value, pos = ({} if opener == "{" else []), pos + 1
        else:
            value, pos = _scalar(text, pos)
        while True:  # hand the finished value to its container, closing every container it completes
            if not stack:
                pos = _skip(text, pos)
                if pos != len(text):
                    raise json.JSONDecodeError("Extra data", text, pos)
                return value
            container, key = stack[-1]
            if isinstance(container, dict):
                container[key] = value
            else:
                container.append(value)
            pos = _skip(text, pos)
            if text.startswith(",", pos):
                pos = _skip(text, pos + 1)
                if isinstance(container, dict):
                    stack[-1][1], pos = _key(text, pos)
                break
            closer = "}" if isinstance(container, dict) else "]"
            if not text.startswith(closer, pos):
                raise json.JSONDecodeError(f"Expecting ',' delimiter or '{closer}'", text, pos)
            stack.pop()
            value, pos = container, pos + 1


def _scalar_text(value, ensure_ascii: bool) -> str:
    if isinstance(value, str):
        return (encode_basestring_ascii if ensure_ascii else encode_basestring)(value)
    if value is True or value is False or value is None:
        return {True: "true", False: "false", None: "null"}[value]
    if isinstance(value, int):
        return int.__repr__(value)
    if isinstance(value, float):
        if not math.isfinite(value):
            raise ValueError(f"{value!r} is not a number JSON allows")
        return float.__repr__(value)
    raise TypeError(f"Object of type {type(value).__name__} is not JSON serializable")


def _dumps_iteratively(value, ensure_ascii: bool) -> str:
    parts = []
    stack = []  # [iterator over a container's items, closing bracket, nothing written yet]

    def open_value(item):
        if isinstance(item, dict) and item:
            parts.append("{")
            stack.append([iter(item.items()), "}", True])
        elif isinstance(item, (list, tuple)) and item:
            parts.append("[")
            stack.append([iter(item), "]", True])
        elif isinstance(item, (dict, list, tuple)):
            parts.append("{}" if isinstance(item, dict) else "[]")
        else:
            parts.append(_scalar_text(item, ensure_ascii))

    open_value(value)
    while stack:
        frame = stack[-1]
        entry = next(frame[0], frame)
        if entry is frame:
            stack.pop()
            parts.append(frame[1])
            continue
        if not frame[2]:
            parts.append(", ")
        frame[2] = False
        if frame[1] == "}":
            key, entry = entry
            if not isinstance(key, str):
                raise TypeError(f"keys must be str, not {type(key).__name__}")
            parts.append(_scalar_text(key, ensure_ascii) + ": ")
        if len(stack) >= MAX_DEPTH:
            raise TooDeep(f"the JSON is nested too deeply (more than {MAX_DEPTH:,} levels)")
        open_value(entry)
    return "".join(parts)
