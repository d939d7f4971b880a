"""Every text key Rockly's code names is in its catalogue (a key added to the code but not to
``resources/locale`` fails here, not in front of a child)."""
import ast
from pathlib import Path

from rockly_desktop.core.app_texts import app_catalogue
from rockly_desktop.core.python_syntax import parse_python

REPO = Path(__file__).resolve().parents[1]
# function -> the prefix its keys have in the catalogue
LOOKUPS = {"tr": "", "app_text": "", "app_local_text": "", "text": "problem_", "_text": "limit_"}
PREFIXED_IN = {"text": "executor/problems.py", "_text": "robot/wrappers/limits.py"}


def named_keys():
    """(file:line, catalogue key) of every lookup of a literal key in rockly_desktop."""
    found = []
    for path in sorted((REPO / "rockly_desktop").rglob("*.py")):
        relative = str(path.relative_to(REPO / "rockly_desktop"))
        for call in (node for node in ast.walk(parse_python(path.read_text(encoding="utf-8")))
                     if isinstance(node, ast.Call)):
            name = getattr(call.func, "id", None) or getattr(call.func, "attr", None)
            if name not in LOOKUPS or name in PREFIXED_IN and PREFIXED_IN[name] != relative:
                continue
            if call.args and isinstance(call.args[0], ast.Constant) and isinstance(call.args[0].value, str):
                found.append((f"{relative}:{call.lineno}", LOOKUPS[name] + call.args[0].value))
    return found


def test_every_key_the_code_names_is_in_the_catalogue():
    keys = named_keys()
    assert len(keys) > 200
    catalogue = app_catalogue()
    assert [(where, key) for where, key in keys if key not in catalogue] == []
