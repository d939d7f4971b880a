"""Arithmetic whose result would hold Python for minutes is refused before it starts."""
import pytest

from rockly_desktop.executor.large_results import MAX_REPEATED_ITEMS, power, times


def test_usual_powers_and_products_are_computed():
    assert power(2, 10) == 1024
    assert power(2.5, 2) == 6.25
    assert power(10, -2) == 0.01
    assert power(1, 10**12) == 1 and power(-1, 10**12 + 1) == -1
    assert times(6, 7) == 42
    assert times("ab", 3) == "ababab"
    assert times([0], 4) == [0, 0, 0, 0]


def test_a_power_with_millions_of_digits_is_refused():
    with pytest.raises(OverflowError, match="about 954,242,508 digits"):
        power(9, 999_999_999)


def test_a_product_of_huge_numbers_is_refused():
    huge = 1 << 600_000
    with pytest.raises(OverflowError):
        times(huge, huge)


@pytest.mark.parametrize("sequence", ["ab", [None]])
def test_repeating_past_the_limit_is_refused(sequence):
    with pytest.raises(MemoryError):
        times(sequence, MAX_REPEATED_ITEMS + 1)
