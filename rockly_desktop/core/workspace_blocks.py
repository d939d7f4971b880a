"""Which block types a program uses, from Blockly's JSON or the first Rockly's XML.

Everything here walks the blocks with an explicit stack, never by recursion: a program's
blocks nest one level per ``next``, far deeper than Python's recursion limit.
"""
import xml.etree.ElementTree as ElementTree
from collections import Counter

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import ProgramFileError
from rockly_desktop.core.xml_text import escape, quoteattr


def iter_blocks(workspace: dict):
    """Every block dict in a Blockly JSON workspace: top blocks, inputs, shadows, next blocks.

    Malformed parts (a list where a mapping belongs, and so on) are skipped.
    """
    top = workspace.get("blocks")
    top_blocks = top.get("blocks") if isinstance(top, dict) else None
    pending = list(top_blocks) if isinstance(top_blocks, list) else []
    while pending:
        block = pending.pop()
        if not isinstance(block, dict):
            continue
        yield block
        pending.extend(_child_blocks(block))


def blocks_in_file_order(workspace: dict):
    """Every block dict in a Blockly JSON workspace in the order the file's text has them
    (a block, then what its inputs and ``next`` hold, as written), so that "block 3" is the
    third ``"type"`` a person finds reading the file. Malformed parts are skipped."""
    top = workspace.get("blocks")
    top_blocks = top.get("blocks") if isinstance(top, dict) else None
    pending = list(reversed(top_blocks)) if isinstance(top_blocks, list) else []
    while pending:
        block = pending.pop()
        if not isinstance(block, dict):
            continue
        yield block
        children = []
        for key, value in block.items():
            if key == "inputs" and isinstance(value, dict):
                connections = list(value.values())
            else:
                connections = [value] if key == "next" else []
            for connection in connections:
                if isinstance(connection, dict):
                    children.extend(child for kind, child in connection.items()
                                    if kind in ("block", "shadow") and child)
        pending.extend(reversed(children))


# Blocks inside one another (a stack counts one level per block). The editor page's
# JavaScript runs out of stack loading a stack of 1,200-1,600 blocks.
MAX_BLOCK_DEPTH = 1000


def _child_blocks(block: dict):
    inputs = block.get("inputs")
    for connection in (list(inputs.values()) if isinstance(inputs, dict) else []) + [block.get("next")]:
        if isinstance(connection, dict):
            for kind in ("block", "shadow"):
                if isinstance(connection.get(kind), dict):
                    yield connection[kind]


def block_depth(workspace: dict) -> int:
    """How many blocks deep the workspace nests at its deepest (a lone block is 1)."""
    top = workspace.get("blocks")
    top_blocks = top.get("blocks") if isinstance(top, dict) else None
    pending = [(block, 1) for block in top_blocks if isinstance(block, dict)] if isinstance(top_blocks, list) else []
    deepest = 0
    while pending:
        block, depth = pending.pop()
        deepest = max(deepest, depth)
        pending.extend((child, depth + 1) for child in _child_blocks(block))
    return deepest


def xml_block_depth(root: ElementTree.Element) -> int:
    """How many ``<block>``/``<shadow>`` elements deep parsed Blockly XML nests at its deepest."""
    pending, deepest = [(root, 0)], 0
    while pending:
        element, depth = pending.pop()
        if local_name(element.tag) in ("block", "shadow"):
            depth += 1
            deepest = max(deepest, depth)
        pending.extend((child, depth) for child in element)
    return deepest


def untyped_block_number(workspace: dict):
    """The number (from 1, in file order) of the first block without a type, or None."""
    for number, block in enumerate(blocks_in_file_order(workspace), start=1):
        if not isinstance(block.get("type"), str) or not block.get("type"):
            return number
    return None


def block_types_in_workspace(workspace: dict) -> Counter:
    """Count the block types in a Blockly JSON workspace (blocks, shadows, nested)."""
    counts = Counter()
    for block in iter_blocks(workspace):
        block_type = block.get("type")
        counts[block_type if isinstance(block_type, str) and block_type else "(block without a type)"] += 1
    return counts


def local_name(tag: str) -> str:
    """An XML tag or attribute name without its namespace."""
    return tag.rsplit("}", 1)[-1]


def parse_blockly_xml(text: str, path="<text>") -> ElementTree.Element:
    """Parse Blockly XML as the first Rockly saved it; raise ProgramFileError if it is not."""
    if not text.strip():
        raise ProgramFileError(path, app_local_text("file_empty"))
    try:
        root = ElementTree.fromstring(text)
    except ElementTree.ParseError as error:
        raise ProgramFileError(path, app_local_text("file_not_xml", problem=error)) from None
    top = local_name(root.tag)
    if top != "xml":
        raise ProgramFileError(path, app_local_text("file_not_blockly", top=top))
    return root


def block_types_in_xml(root: ElementTree.Element) -> Counter:
    """Count the block types in parsed Blockly XML."""
    return Counter(
        element.get("type") or "(block without a type)"
        for element in root.iter() if local_name(element.tag) in ("block", "shadow")
    )


def untyped_xml_block_number(root: ElementTree.Element):
    """The number (from 1, in document order) of the first ``<block>``/``<shadow>`` without a type, or None."""
    elements = (element for element in root.iter() if local_name(element.tag) in ("block", "shadow"))
    for number, element in enumerate(elements, start=1):
        if not element.get("type"):
            return number
    return None


def rename_legacy_fields(root: ElementTree.Element, aliases: dict) -> int:
    """Rewrite old field names/values in place; return how many fields were changed.

    ``aliases`` maps block type -> old field name -> {"field": new name, "values": {old: new}}.
    """
    changed = 0
    for element in root.iter():
        if local_name(element.tag) not in ("block", "shadow"):
            continue
        for old_name, alias in aliases.get(element.get("type"), {}).items():
            for child in element:
                if local_name(child.tag) == "field" and child.get("name") == old_name:
                    child.set("name", alias["field"])
                    child.text = alias.get("values", {}).get(child.text, child.text)
                    changed += 1
    return changed


def xml_to_text(root: ElementTree.Element) -> str:
    """Serialise parsed XML back to text for the editor page.

    Element names are written without a namespace prefix (ElementTree would write
    ``<ns0:block>``, which Blockly does not recognise); a namespace the root had is kept
    as its plain ``xmlns`` attribute.
    """
    namespace = root.tag[1:].split("}", 1)[0] if root.tag.startswith("{") else None
    parts = []
    pending = [(root, False)]  # (element, its end tag is next)
    while pending:
        element, closing = pending.pop()
        tag = local_name(element.tag)
        if closing:
            parts.append(f"</{tag}>{escape(element.tail or '')}")
            continue
        attributes = {local_name(name): value for name, value in element.attrib.items()}
        if element is root and namespace:
            attributes["xmlns"] = namespace
        parts.append(f"<{tag}" + "".join(f" {name}={quoteattr(value)}" for name, value in attributes.items()))
        if len(element) == 0 and not element.text:
            parts.append(f" />{escape(element.tail or '')}")
            continue
        parts.append(">" + escape(element.text or ""))
        pending.append((element, True))
        pending.extend((child, False) for child in reversed(element))
    return "".join(parts)


def block_types_by_id(workspace: dict) -> dict:
    """Map each block id in a Blockly JSON workspace to its type."""
    return {block["id"]: block.get("type") for block in iter_blocks(workspace) if isinstance(block.get("id"), str)}
