"""What a laser scan (sensor_msgs/LaserScan) sees in one direction: the one definition of "ahead"
that a profile's commands, its simulator view and the Robot state panel share.

"Ahead" is a sector, ``AHEAD_HALF_WIDTH`` to each side of the direction, not one beam: a thin
table leg between two beams is still seen. A reading of -inf is something closer than the laser
measures (REP 117); +inf, NaN or a value outside [range_min, range_max] is no reading.
"""
import math

from rockly_desktop.core.state_store import field_value

AHEAD_HALF_WIDTH = math.radians(15)


def nearest_reading(ranges, angle_min: float, angle_increment: float, range_min: float, range_max: float,
                    centre: float = 0.0, half_width: float = AHEAD_HALF_WIDTH) -> float:
    """Metres to the nearest reading within ``half_width`` radians of ``centre`` (0: ahead,
    counter-clockwise positive); ``math.inf`` when nothing is there."""
    nearest = math.inf
    for index, value in enumerate(ranges):
        if abs(math.remainder(angle_min + index * angle_increment - centre, math.tau)) > half_width + 1e-6:
            continue
        value = float(value)
        if value == -math.inf:
            value = range_min
        elif not range_min <= value <= range_max:
            continue
        nearest = min(nearest, value)
    return nearest


def nearest_in_scan(scan, centre: float = 0.0, half_width: float = AHEAD_HALF_WIDTH) -> float:
    """``nearest_reading`` of a LaserScan, as a dict or a ROS message; KeyError, TypeError or
    ValueError when it is not a laser scan."""
    return nearest_reading(field_value(scan, "ranges"), float(field_value(scan, "angle_min")),
                           float(field_value(scan, "angle_increment")), float(field_value(scan, "range_min")),
                           float(field_value(scan, "range_max")), centre, half_width)
