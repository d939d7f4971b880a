"""Checks on a program's blocks before the editor page sees them.

Blockly trusts its input: a field holding a list makes it fail with "a is not
iterable", and a block asking for 100,000,000 inputs keeps the page busy for minutes,
after which nothing can be saved. These checks name the block (counted in the file's
order, as a person finds it), its type and what is wrong.
"""
import xml.etree.ElementTree as ElementTree

from rockly_desktop.core.workspace_blocks import blocks_in_file_order, local_name

MAX_EXTRA_ITEMS = 1000  # inputs a block may grow (text join items, else-ifs, parameters, typed fields)
EXACT_INTEGERS = 2 ** 53  # JavaScript's numbers hold whole numbers exactly up to here

_SCALAR = (str, int, float, bool)


def _where(number: int, block: dict) -> str:
    block_type = block.get("type")
    return f"block {number} ({block_type})" if isinstance(block_type, str) else f"block {number}"


def _field_problem(name, value):
    if isinstance(value, _SCALAR) or value is None:
        return None
    if isinstance(value, dict) and all(isinstance(part, (str, type(None))) for part in value.values()):
        return None  # a variable field: {"id": ..., "name": ..., "type": ...}
    return f"its field {name} holds {type(value).__name__ if not isinstance(value, dict) else 'an object'}, not a value"


def _size_problem(state, path="its saved state"):
    """The first number or list in a block's saved state that is larger than any real block needs."""
    pending = [(state, path)]
    while pending:
        value, where = pending.pop()
        if isinstance(value, bool):
            continue
        if isinstance(value, (int, float)) and value > MAX_EXTRA_ITEMS:
            return f"{where} asks for {value:,} (at most {MAX_EXTRA_ITEMS:,})"
        if isinstance(value, list):
            if len(value) > MAX_EXTRA_ITEMS:
                return f"{where} lists {len(value):,} items (at most {MAX_EXTRA_ITEMS:,})"
            pending.extend((item, where) for item in value)
        elif isinstance(value, dict):
            pending.extend((item, f"{where} {key}") for key, item in value.items())
    return None


def _block_problem(block: dict):
    block_id = block.get("id")
    if block_id is not None and not isinstance(block_id, str):
        return f"its id is {type(block_id).__name__}, not text"
    fields = block.get("fields", {})
    if not isinstance(fields, dict):
        return "its fields are not an object"
    for name, value in fields.items():
        problem = _field_problem(name, value)
        if problem:
            return problem
    for key in ("inputs", "next", "icons"):
        if not isinstance(block.get(key, {}), dict):
            return f"its {key} are not an object" if key != "next" else "its next is not an object"
    for name, connection in block.get("inputs", {}).items():
        if not isinstance(connection, dict) or not all(isinstance(part, dict) for part in connection.values()):
            return f"its input {name} does not hold a block"
    for key in ("x", "y"):
        if key in block and (isinstance(block[key], bool) or not isinstance(block[key], (int, float))):
            return f"its position {key} is not a number"
    return _size_problem(block["extraState"]) if "extraState" in block else None


def workspace_problem(workspace: dict):
    """What is wrong with the first bad block of a Blockly JSON workspace, or None."""
    top = workspace.get("blocks", {})
    if not isinstance(top, dict) or not isinstance(top.get("blocks", []), list):
        return "the workspace's blocks are not a list"
    for number, block in enumerate(top.get("blocks", []), start=1):
        if not isinstance(block, dict):
            return f"top-level block {number} is not a block (an object)"
    variables = workspace.get("variables", [])
    if not isinstance(variables, list) or not all(isinstance(item, dict) for item in variables):
        return "the workspace's variables are not a list of variables"
    for number, block in enumerate(blocks_in_file_order(workspace), start=1):
        problem = _block_problem(block)
        if problem:
            return f"{_where(number, block)}: {problem}"
    return None


def _as_javascript_writes(value: float) -> str:
    """A float as JavaScript's ``String(number)`` writes it (whole numbers below 1e21 in full)."""
    text = repr(value)
    if "e" not in text or abs(value) >= 1e21:
        return text.removesuffix(".0")
    mantissa, exponent = text.split("e")
    sign, mantissa = ("-", mantissa[1:]) if mantissa.startswith("-") else ("", mantissa)
    whole, _, fraction = mantissa.partition(".")
    return sign + (whole + fraction).ljust(len(whole) + int(exponent), "0")


def rounded_numbers(workspace: dict) -> list:
    """Whole numbers in fields too large for the editor to keep exactly (above 2**53), as
    ``{number, id, type, field, requested, now, rounded}`` like the page's replaced field values."""
    rounded = []
    for number, block in enumerate(blocks_in_file_order(workspace), start=1):
        fields = block.get("fields")
        for name, value in (fields.items() if isinstance(fields, dict) else ()):
            if isinstance(value, int) and not isinstance(value, bool) and abs(value) > EXACT_INTEGERS:
                now = _as_javascript_writes(float(value))
                if now != str(value):
                    rounded.append({"number": number, "id": block.get("id"), "type": block.get("type"),
                                    "field": name, "requested": value, "now": now, "rounded": True})
    return rounded


def xml_problem(root: ElementTree.Element):
    """What is wrong with the first block of parsed Blockly XML asking for too many inputs, or None."""
    elements = (element for element in root.iter() if local_name(element.tag) in ("block", "shadow"))
    for number, element in enumerate(elements, start=1):
        for child in element:
            if local_name(child.tag) != "mutation":
                continue
            for name, value in child.attrib.items():
                try:
                    size = float(value)
                except ValueError:
                    continue
                if size > MAX_EXTRA_ITEMS:
                    return (f"block {number} ({element.get('type')}): its mutation {name} asks for "
                            f"{value} (at most {MAX_EXTRA_ITEMS:,})")
    return None
