"""Literals and names as Rockly's generators write them."""
import ast
import builtins
import keyword
import math

NOT_CONVERTED = object()
"""What ``literal_value`` gives for a node that is no literal."""

# Names Blockly renames when a variable or function is called so (Python's keywords and builtins, and what a
# run binds): a Name of these is never a block's variable.
RESERVED = frozenset(keyword.kwlist) | frozenset(dir(builtins)) | {"robot", "ros", "__rockly__", "math", "random",
                                                                   "Number"}


def literal_value(node):
    """The value of a literal Rockly writes (a number, ``-2``, a string, True/False/None, ``float('inf')``), or
    NOT_CONVERTED."""
    if isinstance(node, ast.Constant) and not isinstance(node.value, (bytes, complex)) and node.value is not Ellipsis:
        return node.value
    if (isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub) and isinstance(node.operand, ast.Constant)
            and type(node.operand.value) in (int, float)):
        return -node.operand.value
    if (isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "float"
            and len(node.args) == 1 and not node.keywords and isinstance(node.args[0], ast.Constant)
            and node.args[0].value in ("inf", "-inf")):
        return math.inf if node.args[0].value == "inf" else -math.inf
    return NOT_CONVERTED


def plain_name(name: str, reserved=RESERVED):
    """``name`` when Blockly writes a variable of that name as it is (ASCII, not reserved), else None."""
    if not name.isascii() or not name.isidentifier() or name in reserved or name.startswith("__"):
        return None
    return name
