"""Whether the program on the robot is the one open in the window: the blocks, their fields and how they are
joined, leaving out where they lie on the canvas and the ids the page makes up for blocks that came without."""
from rockly_desktop.core.program import parse_program


def same_program(robot_source: str, window_workspace: dict) -> bool:
    """True when ``robot_source`` (the ``.rockly`` text the robot keeps) holds the window's blocks."""
    return _outline(parse_program(robot_source, "robot").workspace) == _outline(window_workspace)


def _outline(workspace: dict):
    blocks = (workspace.get("blocks") or {}).get("blocks") or []
    return sorted((_block(top) for top in blocks), key=repr)


def _block(block):
    if not isinstance(block, dict):
        return None
    inputs = block.get("inputs") or {}
    return (block.get("type"), repr(sorted((block.get("fields") or {}).items())),
            repr(block.get("extraState")),
            tuple((name, _block(value.get("block")), _block(value.get("shadow")))
                  for name, value in sorted(inputs.items()) if isinstance(value, dict)),
            _block((block.get("next") or {}).get("block")))
