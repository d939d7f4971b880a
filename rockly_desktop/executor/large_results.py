"""Arithmetic a running program does through ``__rockly__``: refused when the result is too large.

Python computes ``9 ** 999999999`` in one step that holds the interpreter for minutes:
no STOP, no window redraw. The page routes powers, products and repeated lists of the
code Rockly runs through these functions, which say no before starting such a step.
"""
import math

MAX_RESULT_BITS = 1_000_000  # about 300,000 digits: computed in milliseconds
MAX_REPEATED_ITEMS = 10_000_000  # items (or letters) a repeated list or text may have


def _too_big(bits: int):
    return OverflowError(f"the result would have about {int(bits * math.log10(2)):,} digits "
                         f"(Rockly computes up to {int(MAX_RESULT_BITS * math.log10(2)):,})")


def _is_whole(value) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


def power(base, exponent):
    """``base ** exponent``, refusing whole-number results of more than MAX_RESULT_BITS."""
    if _is_whole(base) and _is_whole(exponent) and exponent > 0 and abs(base) > 1:
        bits = exponent * math.log2(abs(base))
        if bits > MAX_RESULT_BITS:
            raise _too_big(bits)
    return base ** exponent


def times(a, b):
    """``a * b``, refusing huge whole numbers and texts or lists repeated past MAX_REPEATED_ITEMS."""
    if _is_whole(a) and _is_whole(b):
        bits = a.bit_length() + b.bit_length()
        if bits > MAX_RESULT_BITS:
            raise _too_big(bits)
    elif isinstance(a, (str, list, tuple)) and _is_whole(b) or isinstance(b, (str, list, tuple)) and _is_whole(a):
        sequence, count = (a, b) if _is_whole(b) else (b, a)
        if len(sequence) * count > MAX_REPEATED_ITEMS:
            raise MemoryError(f"{len(sequence) * count:,} items are too many")
    return a * b
