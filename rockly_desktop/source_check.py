"""``python -m rockly_desktop.source_check``: is a kept program's code what its blocks generate? Run by the robot's
agent (``runtime.agent.source_match``) in a process of its own, where the window's Rockly (Qt WebEngine, Blockly) is
installed beside the agent.

It reads one JSON object on standard input: ``{"source": .rockly text, "language", "run_code", "blocks",
"variables"}`` (the ``RUN_CODE``, and ``PROGRAM``'s ``blocks`` and ``variables``, of the standalone file the agent
keeps), generates the source's code with a windowless editor as ``rockly export --standalone`` does, and prints
one JSON object: ``{"code": "same"}``, ``{"code": "differs", "part": "code" | "blocks" | "variables"}`` or
``{"code": "unchecked", "reason": TEXT}`` (this Rockly cannot generate that source: a block it does not know, a
profile not installed here). Without Qt WebEngine it exits with ``CANNOT_GENERATE`` and prints nothing.
"""
import json
import sys
import tempfile
from pathlib import Path

CANNOT_GENERATE = 3


def compare(request: dict, run_code: dict, types: dict, source_ids) -> dict:
    """What ``request`` (the kept program) says against what its source generated: ``run_code`` (the page's
    ``getRunCode`` answer) and ``types`` (block id -> type). Blockly gives a block the source names no id a new
    random one each time it loads it: of those, only their number and types must agree (``source_ids``: the ids
    the source names)."""
    if run_code.get("code") != request.get("run_code"):
        return {"code": "differs", "part": "code"}
    kept = request.get("blocks") if isinstance(request.get("blocks"), dict) else {}
    if not _same_blocks(kept, dict(types), set(source_ids)):
        return {"code": "differs", "part": "blocks"}
    if dict(run_code.get("variables") or {}) != (request.get("variables") or {}):
        return {"code": "differs", "part": "variables"}
    return {"code": "same"}


def _same_blocks(kept: dict, generated: dict, source_ids: set) -> bool:
    def named(blocks):
        return {block: kind for block, kind in blocks.items() if block in source_ids}

    def unnamed(blocks):
        return sorted(str(kind) for block, kind in blocks.items() if block not in source_ids)
    return named(kept) == named(generated) and unnamed(kept) == unnamed(generated)


def check(request: dict) -> dict:
    """Generate ``request``'s source and compare (see the module's docstring)."""
    from rockly_desktop.app import generate_headless
    from rockly_desktop.core.errors import RocklyError
    from rockly_desktop.core.program import parse_program
    from rockly_desktop.core.workspace_blocks import block_types_by_id

    language = request.get("language") if request.get("language") in ("en", "de") else "en"
    with tempfile.TemporaryDirectory(prefix="rockly-source-check-") as folder:
        path = Path(folder) / "program.rockly"
        path.write_text(str(request.get("source", "")), encoding="utf-8")
        try:
            source_ids = block_types_by_id(parse_program(path.read_text(encoding="utf-8"), path.name).workspace)
            _program, _python, run_code, workspace = generate_headless(path, language)
        except RocklyError as error:
            return {"code": "unchecked", "reason": error.in_language(language)}
    return compare(request, run_code, block_types_by_id(workspace), source_ids)


def main() -> int:
    """Check the program on standard input; print the outcome."""
    try:
        import PySide6.QtWebEngineWidgets  # noqa: F401  (only to know this Rockly can generate)
    except ImportError:
        return CANNOT_GENERATE
    request = json.loads(sys.stdin.buffer.read().decode("utf-8"))
    print(json.dumps(check(request), ensure_ascii=False), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
