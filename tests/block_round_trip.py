"""One round trip through the real editor page: blocks → Python → blocks → Python."""
import json

from rockly_desktop.profiles.opening import read_program_to_open
from rockly_desktop.python_blocks.convert import python_to_program
from rockly_desktop.python_blocks.source import parse_source


def generated(editor, registry, path):
    """The profile, the Python the editor generates for the program at ``path`` and the workspace it then holds."""
    program = read_program_to_open(path, registry, registry.default())
    python = editor.python_for(program)
    return program.profile, python, editor.call_and_wait("getState")["workspace"]


def normalized(workspace: dict) -> str:
    """The block tree as JSON without ids and positions: variables by name, an input's block (else its shadow),
    a comment's text, typed fields' paths and checks. A variable no block uses is not in the Python: it
    does not count."""
    names = {variable["id"]: variable["name"] for variable in workspace.get("variables", [])}

    def clean(value):
        if isinstance(value, list):
            return [clean(item) for item in value]
        if not isinstance(value, dict):
            return value
        if set(value) == {"id"} and value["id"] in names:
            return names[value["id"]]
        if ("shadow" in value or "block" in value) and set(value) <= {"block", "shadow"}:
            return clean(value.get("block") or value.get("shadow"))
        out = {key: clean(item) for key, item in value.items() if key not in ("id", "x", "y")}
        if isinstance(out.get("comment"), dict):
            out["comment"] = out["comment"].get("text")
        if isinstance(out.get("fields"), list):  # typed fields
            out["fields"] = [entry[:2] for entry in out["fields"]]
        if isinstance(out.get("params"), list):  # a function's parameters
            out["params"] = [param["name"] if isinstance(param, dict) else param for param in out["params"]]
        return out

    return json.dumps(clean(workspace.get("blocks", {})), sort_keys=True)


def round_trip(editor, registry, path, folder) -> tuple:
    """``(conversion, python, python again, tree, tree again)`` of the program at ``path``."""
    profile, python, workspace = generated(editor, registry, path)
    conversion = python_to_program(parse_source(python), profile)
    converted = folder / "converted.rockly"
    converted.write_text(conversion.program.to_json())
    _, python_again, workspace_again = generated(editor, registry, converted)
    return conversion, python, python_again, normalized(workspace), normalized(workspace_again)
