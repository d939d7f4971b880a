"""Messages encoded in Rockly's process as ROS 2 sends them (CDR), so the helper publishes them as they are.

The helper gives a type's layout (``helper.layouts``); ``MessageEncoder`` turns a message dict into the
bytes rclpy would serialise from it: little-endian CDR after a 4-byte encapsulation header, each
number aligned to its size from the header's end, strings and sequences led by a 32-bit length.

The encoder takes only what the helper's own way (``helper.ros_values.to_message`` with rclpy's field
checks) would take and encode the same: a value it is not sure of (a string where a number
belongs, an unknown field, a number out of its type's range, a list too long) raises
NotEncodable, and that message goes to the helper as fields, which then says what is wrong in its
words. Standard library only.
"""
import math
import struct

ENCAPSULATION = b"\x00\x01\x00\x00"  # plain CDR, little-endian
_LENGTH = struct.Struct("<I")
_ROS1_TIME = {"secs": "sec", "nsecs": "nanosec"}
_FLOAT32_MAX = 3.402823466e+38
_INTEGER_RANGES = {code: (-(1 << (8 * size - 1)), (1 << (8 * size - 1)) - 1) if code.islower()
                   else (0, (1 << (8 * size)) - 1)
                   for code, size in (("b", 1), ("B", 1), ("h", 2), ("H", 2), ("i", 4), ("I", 4),
                                      ("q", 8), ("Q", 8))}


class NotEncodable(Exception):
    """A message Rockly's side leaves to the helper, which checks it field by field."""


class MessageEncoder:
    """Encodes message dicts of one type (its ``helper.layouts`` layout) as CDR bytes."""

    def __init__(self, layout):
        self._write = _message_writer(layout, "")

    def encode(self, message) -> bytes:
        """``message`` (a dict; missing fields take the type's defaults) as CDR; NotEncodable when
        the helper should check it."""
        out = bytearray(ENCAPSULATION)
        self._write(out, message)
        return bytes(out)


def _pad(out, size):
    """Zeros up to the next multiple of ``size`` from the encapsulation header's end."""
    gap = (4 - len(out)) % size
    if gap:
        out += bytes(gap)


# --- checks: the value as rclpy would store it, or NotEncodable
def _boolean(value):
    if type(value) is not bool:
        raise NotEncodable
    return value


def _integer(code):
    low, high = _INTEGER_RANGES[code]

    def check(value):
        if type(value) is not int or not low <= value <= high:
            raise NotEncodable
        return value
    return check


def _double(value):
    if type(value) is float:
        return value
    if type(value) is not int:
        raise NotEncodable
    try:
        return float(value)  # a whole number in a float field, as on ROS 1
    except OverflowError:
        raise NotEncodable from None


def _single(value):
    value = _double(value)
    if (value < -_FLOAT32_MAX or value > _FLOAT32_MAX) and not math.isinf(value):
        raise NotEncodable
    return value


def _number_check(code):
    if code == "?":
        return _boolean
    if code == "d":
        return _double
    if code == "f":
        return _single
    return _integer(code)


# --- writers: write(out, value) appends the value's bytes to ``out``
def _writer(spec):
    kind = spec[0]
    if kind == "num":
        return _number_writer(spec[1])
    if kind == "octet":
        return _octet_writer
    if kind == "str":
        return _string_writer(spec[1])
    if kind == "msg":
        return _message_writer(spec[1], spec[2])
    if kind == "array":
        return _array_writer(spec[1], spec[2], fixed=True)
    if kind == "seq":
        return _array_writer(spec[1], spec[2], fixed=False)
    raise ValueError(f"no writer for a layout of kind {kind!r}")


def _number_writer(code):
    packer = struct.Struct("<" + code)
    check = _number_check(code)

    def write(out, value):
        _pad(out, packer.size)
        out += packer.pack(check(value))
    return write


def _octet_writer(out, value):
    if type(value) is not bytes or len(value) != 1:
        raise NotEncodable
    out += value


def _string_bytes(value, bound):
    if type(value) is not str or (bound and len(value) > bound) or "\0" in value:
        raise NotEncodable
    try:
        return value.encode("utf-8")
    except UnicodeEncodeError:  # a lone surrogate: rclpy refuses it too
        raise NotEncodable from None


def _string_writer(bound):
    def write(out, value):
        encoded = _string_bytes(value, bound)
        _pad(out, 4)
        out += _LENGTH.pack(len(encoded) + 1)
        out += encoded
        out += b"\0"
    return write


def _array_writer(item, size, fixed):
    """A fixed-size array (``size`` items) or a sequence (at most ``size``, 0: any number)."""
    if item[0] == "num":
        write_items = _numbers_writer(item[1])
    else:
        write_one = _writer(item)

        def write_items(out, values):
            for value in values:
                write_one(out, value)

    def write(out, values):
        if type(values) not in (list, tuple):
            raise NotEncodable
        if fixed:
            if len(values) != size:
                raise NotEncodable
        else:
            if size and len(values) > size:
                raise NotEncodable
            _pad(out, 4)
            out += _LENGTH.pack(len(values))
        write_items(out, values)
    return write


def _numbers_writer(code):
    """Numbers of one type, packed together (aligned once: each after the first is aligned too)."""
    check = _number_check(code)
    size = struct.calcsize(code)

    def write(out, values):
        if not values:
            return
        _pad(out, size)
        out += struct.pack(f"<{len(values)}{code}", *[check(value) for value in values])
    return write


def _message_writer(layout, special):
    names = frozenset(name for name, _spec, _default in layout)
    fields_of = _fields_reader(names, special)
    if all(spec[0] == "num" for _name, spec, _default in layout):
        return _numbers_message_writer(layout, fields_of)
    fields = [(name, _writer(spec), default) for name, spec, default in layout]

    def write(out, data):
        data = fields_of(data)
        for name, write_field, default in fields:
            write_field(out, data.get(name, default))
    return write


def _numbers_message_writer(layout, fields_of):
    """A message of numbers only (a vector, a point, a stamp): packed at once, by a struct made for
    where it starts (its alignment gaps depend on that, modulo 8)."""
    fields = [(name, _number_check(spec[1]), default) for name, spec, default in layout]
    codes = [spec[1] for _name, spec, _default in layout]
    packers = [struct.Struct("<" + _aligned_format(codes, start)) for start in range(8)]

    def write(out, data):
        data = fields_of(data)
        out += packers[(len(out) - 4) % 8].pack(*[check(data.get(name, default)) for name, check, default in fields])
    return write


def _aligned_format(codes, start):
    """The struct format of ``codes`` packed from offset ``start``, each aligned to its size."""
    parts, offset = [], start
    for code in codes:
        size = struct.calcsize(code)
        gap = (-offset) % size
        parts.append(f"{gap}x{code}" if gap else code)
        offset += gap + size
    return "".join(parts)


def _fields_reader(names, special):
    """A function giving a message's value as a dict of the type's fields (ROS 1's names of a stamp's
    fields taken, a header's ``seq`` left out, as the helper's way does); NotEncodable otherwise."""
    empty = {}

    def fields_of(data):
        if not data:  # as the helper's way: no fields (or None) is the type's defaults
            return empty
        if type(data) is not dict:
            raise NotEncodable
        if special == "time":
            data = {_ROS1_TIME.get(name, name): value for name, value in data.items()}
        elif special == "header" and "seq" in data:
            data = {name: value for name, value in data.items() if name != "seq"}
        if not names.issuperset(data):
            raise NotEncodable
        return data
    return fields_of
