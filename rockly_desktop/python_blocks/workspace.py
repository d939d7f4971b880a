"""The block JSON a conversion builds: blocks with ids of their own, the variables they name, Python blocks."""
PYTHON_BLOCK = "rockly_python"
"""The Python block: it holds text verbatim (``extraState.code``) and its generator writes it as it is."""


class WorkspaceBuilder:
    """Makes blocks with fresh ids and keeps the variables they use, in the order first seen."""

    def __init__(self):
        self._count = 0
        self.variables = {}  # name -> id
        self.referenced = set()  # the names a block's field names

    def block(self, block_type: str, fields=None, inputs=None, extra_state=None) -> dict:
        """A new block of ``block_type`` (``inputs``: name -> block, wrapped as Blockly's JSON wants)."""
        self._count += 1
        block = {"type": block_type, "id": f"py{self._count}"}
        if extra_state is not None:
            block["extraState"] = extra_state
        if fields:
            block["fields"] = fields
        filled = {name: {"block": child} for name, child in (inputs or {}).items() if child is not None}
        if filled:
            block["inputs"] = filled
        return block

    def variable(self, name: str) -> dict:
        """The value of a variable field naming ``name`` (the variable is added to the workspace)."""
        self.referenced.add(name)
        return {"id": self.declare(name)}

    def declare(self, name: str) -> str:
        """Add the variable ``name`` to the workspace (if new); its id."""
        return self.variables.setdefault(name, f"var_{name}")

    def python_block(self, code: str) -> dict:
        """A Python block holding ``code`` as it is."""
        return self.block(PYTHON_BLOCK, extra_state={"code": code})

    def workspace(self, stacks: list) -> dict:
        """Blockly's workspace JSON of the top-level ``stacks`` (each a list of statement blocks), one under another."""
        tops, y = [], 30
        for stack in stacks:
            if not stack:
                continue
            top = chain(stack)
            top.update(x=30, y=y)
            tops.append(top)
            y += 60 * (1 + sum(1 for _ in _stack_blocks(top)))
        workspace = {"blocks": {"languageVersion": 0, "blocks": tops}}
        used = {name: ident for name, ident in self.variables.items() if name in self.referenced}
        if used:
            workspace["variables"] = [{"name": name, "id": ident} for name, ident in used.items()]
        return workspace


def chain(blocks: list):
    """Link statement blocks into one stack (each the next of the one before); the first, or None."""
    for before, after in zip(blocks, blocks[1:], strict=False):
        before["next"] = {"block": after}
    return blocks[0] if blocks else None


def _stack_blocks(block):
    while block is not None:
        yield block
        block = block.get("next", {}).get("block")


def comment_icon(text: str) -> dict:
    """The ``icons`` entry of a block comment holding ``text``."""
    return {"comment": {"text": text, "pinned": False, "height": 80, "width": 160}}
