"""What a laser scan sees in a direction (rockly_desktop/robot/laser.py): one sector, the same everywhere."""
import math

import pytest

from rockly_desktop.robot.laser import AHEAD_HALF_WIDTH, nearest_in_scan, nearest_reading

STEP = math.radians(1)


def _scan(ranges, **changes):
    return dict({"angle_min": 0.0, "angle_increment": STEP, "range_min": 0.12, "range_max": 3.5,
                 "ranges": ranges}, **changes)


def test_ahead_is_the_nearest_reading_in_the_sector_not_one_beam():
    ranges = [2.5] * 360
    ranges[10] = 1.21                       # inside the 15° each side
    ranges[20] = 0.4                        # outside it
    assert nearest_in_scan(_scan(ranges)) == 1.21
    assert math.degrees(AHEAD_HALF_WIDTH) == pytest.approx(15)


def test_other_directions_and_a_scan_that_starts_behind():
    ranges = [3.0] * 360
    ranges[90] = 0.5
    assert nearest_reading(ranges, 0.0, STEP, 0.12, 3.5, centre=math.pi / 2) == 0.5
    assert nearest_in_scan(_scan(ranges, angle_min=-math.pi / 2)) == 0.5    # beam 90 is now straight ahead


def test_too_close_counts_and_no_reading_is_nothing():
    assert nearest_in_scan(_scan([math.inf, math.nan, 0.0, 9.0])) == math.inf
    assert nearest_in_scan(_scan([math.inf, -math.inf])) == 0.12


def test_a_message_that_is_not_a_scan_raises():
    with pytest.raises(KeyError):
        nearest_in_scan({"data": 1})
    with pytest.raises(ValueError):
        nearest_in_scan(_scan(["far"]))
