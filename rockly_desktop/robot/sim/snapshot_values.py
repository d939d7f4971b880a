"""Reading a simulator's snapshot in its view without trusting it.

A view draws whatever dict it is given: any value may be missing, of the wrong type, NaN
or endless. These readers turn each into something drawable (a default, a clamped float,
a list of points) and never raise. Pure Python, so a view's drawing logic can be tested
without Qt.
"""
import math


def with_defaults(snapshot, defaults: dict) -> dict:
    """A new dict: ``defaults`` overlaid with ``snapshot`` (anything but a dict counts as empty)."""
    result = dict(defaults)
    if isinstance(snapshot, dict):
        result.update(snapshot)
    return result


def as_number(value, default=0.0, lo=None, hi=None) -> float:
    """``value`` as a finite float (else ``default``), clamped to ``lo``..``hi``."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        return default
    if not math.isfinite(number):
        return default
    if lo is not None:
        number = max(lo, number)
    if hi is not None:
        number = min(hi, number)
    return number


def as_point(value):
    """An (x, y) pair of finite floats, or None."""
    try:
        x, y = float(value[0]), float(value[1])
    except (TypeError, ValueError, IndexError, KeyError):
        return None
    return (x, y) if math.isfinite(x) and math.isfinite(y) else None


def as_points(values, limit: int) -> list:
    """The last ``limit`` valid (x, y) points of ``values``, oldest first; the others are left out."""
    try:
        return [pt for pt in (as_point(value) for value in list(values or [])[-limit:]) if pt is not None]
    except TypeError:
        return []
