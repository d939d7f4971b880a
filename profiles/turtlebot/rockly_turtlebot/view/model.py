"""What a snapshot may say, its defaults, and reading it without trusting it.

Any value may be missing, of the wrong type, NaN or endless; the readers here turn each
into something drawable and never raise.
"""
import math

from rockly_desktop.sdk import as_number, as_points, with_defaults

num = as_number    # value as a finite float, clamped: num(value, default=0.0, lo=None, hi=None)

ROOM = (-0.5, -1.5, 3.5, 1.5)
RADIUS = 0.105
RANGE_MIN, RANGE_MAX = 0.12, 3.5

DEFAULT_SNAPSHOT = {
    "x": 0.0, "y": 0.0, "theta": 0.0, "trail": [], "linear": 0.0, "angular": 0.0, "scan": [],
    "range_min": RANGE_MIN, "range_max": RANGE_MAX, "room": ROOM, "boxes": [], "radius": RADIUS,
    "bumped": False, "bumps": 0, "battery": 100.0, "voltage": 12.4, "time": 0.0,
}


def merged(snapshot):
    """The defaults overlaid with ``snapshot`` (anything but a dict counts as empty)."""
    return with_defaults(snapshot, DEFAULT_SNAPSHOT)


def rectangle(value):
    """(x0, y0, x1, y1) of finite floats with x0 < x1 and y0 < y1, or None."""
    try:
        x0, y0, x1, y1 = (float(v) for v in value)
    except (TypeError, ValueError):
        return None
    if not all(map(math.isfinite, (x0, y0, x1, y1))) or x0 >= x1 or y0 >= y1:
        return None
    return x0, y0, x1, y1


def room(snapshot):
    return rectangle(snapshot.get("room")) or ROOM


def boxes(snapshot):
    try:
        found = [rectangle(box) for box in list(snapshot.get("boxes") or [])[:50]]
    except TypeError:
        return []
    return [box for box in found if box is not None]


def pose(snapshot):
    return num(snapshot.get("x")), num(snapshot.get("y")), num(snapshot.get("theta"))


def trail(snapshot, limit=600):
    """The last ``limit`` valid trail points, oldest first."""
    return as_points(snapshot.get("trail"), limit)


def scan(snapshot):
    """The laser's ranges as floats (a reading that is not a number becomes nan), at most 2000."""
    values = snapshot.get("scan") or []
    try:
        values = list(values)[:2000]
    except TypeError:
        return []
    result = []
    for value in values:
        try:
            result.append(float(value))
        except (TypeError, ValueError):
            result.append(math.nan)
    return result


def limits(snapshot):
    """(range_min, range_max) of the laser."""
    near = num(snapshot.get("range_min"), RANGE_MIN, 0.0, 100.0)
    far = num(snapshot.get("range_max"), RANGE_MAX, near + 0.01, 100.0)
    return near, far
