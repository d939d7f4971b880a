"""Building Blockly JSON workspaces and .rockly documents in tests, readably."""
from itertools import pairwise

from rockly_desktop.core import deep_json


def block(block_type, fields=None, inputs=None, next_block=None, **extra):
    """One block as Blockly JSON; ``inputs`` values are blocks (wrapped as real blocks)."""
    data = {"type": block_type, **extra}
    if fields:
        data["fields"] = fields
    if inputs:
        data["inputs"] = {name: {"block": value} for name, value in inputs.items()}
    if next_block:
        data["next"] = {"block": next_block}
    return data


def number(value):
    """A math_number block."""
    return block("math_number", {"NUM": value})


def text(value):
    """A text block."""
    return block("text", {"TEXT": value})


def stack(*blocks):
    """Chain statement blocks one under the other; return the first."""
    for upper, lower in pairwise(blocks):
        upper["next"] = {"block": lower}
    return blocks[0]


def workspace(*top_blocks):
    """A workspace with the given top-level blocks."""
    return {"blocks": {"languageVersion": 0, "blocks": list(top_blocks)}}


def rockly_document(top_blocks, profile="hobbit") -> str:
    """The text of a .rockly file holding ``top_blocks``."""
    return deep_json.dumps({"format": "rockly-program", "version": 1, "profile": profile,
                       "workspace": workspace(*top_blocks)})
