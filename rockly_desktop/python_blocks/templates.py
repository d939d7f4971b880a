"""The profile's (and its block packs') block templates as syntax-tree patterns, matched against a program's
Python: ``robot.drive({speed}, {direction})`` becomes a pattern whose slots bind what stands in their place."""
import ast
import string
from dataclasses import dataclass

from rockly_desktop.core.python_syntax import parse_python

SLOT_PREFIX = "__rockly_slot_"


@dataclass(frozen=True)
class Template:
    """One block's template: its spec, the pattern (an expression, or one statement) and how specific it is."""

    spec: object  # profiles.blocks.BlockSpec
    pattern: ast.AST
    weight: int  # nodes that are not slots: the more, the more specific

    def match(self, node: ast.AST):
        """The slots' bindings (slot name -> node, or list of statements) when ``node`` fits, else None."""
        bindings = {}
        return bindings if _matches(self.pattern, node, bindings, self.spec.slots) else None


def _slot_name(node):
    if isinstance(node, ast.Name) and node.id.startswith(SLOT_PREFIX):
        return node.id[len(SLOT_PREFIX):]
    return None


def _matches(pattern, node, bindings: dict, slots: dict) -> bool:
    slot = _slot_name(pattern)
    if slot is not None:
        bindings[slot] = node
        return isinstance(node, ast.expr)
    if type(pattern) is not type(node):
        return False
    if isinstance(pattern, ast.AST):
        for name in pattern._fields:
            if name == "ctx":
                continue
            if not _matches(getattr(pattern, name), getattr(node, name, None), bindings, slots):
                return False
        return True
    if isinstance(pattern, list):
        statement_slot = _statement_slot(pattern, slots)
        if statement_slot is not None:
            bindings[statement_slot] = node
            return True
        return len(pattern) == len(node) and all(
            _matches(p, n, bindings, slots) for p, n in zip(pattern, node, strict=True))
    return pattern == node and type(pattern) is type(node)


def _statement_slot(pattern: list, slots: dict):
    """The slot of a body that is only a statement input's placeholder (``{body}`` on its own line)."""
    if len(pattern) == 1 and isinstance(pattern[0], ast.Expr):
        slot = _slot_name(pattern[0].value)
        if slot is not None and slots.get(slot) == "statement":
            return slot
    return None


def _pattern_text(code: str) -> str:
    """The template with each ``{name}`` a slot identifier and ``{{``/``}}`` single braces."""
    parts = []
    for literal, name, _, _ in string.Formatter().parse(code):
        parts.append(literal)
        if name is not None:
            parts.append(SLOT_PREFIX + name)
    return "".join(parts)


def template_of(spec):
    """The Template of a BlockSpec, or None when its template is no single expression or statement."""
    text = _pattern_text(spec.code)
    try:
        if spec.is_expression:
            pattern = parse_python(text.strip(), mode="eval").body
        else:
            body = parse_python(_dedented(text)).body
            if len(body) != 1:
                return None
            pattern = body[0]
    except (SyntaxError, ValueError, RecursionError):
        return None
    weight = sum(1 for node in ast.walk(pattern) if _slot_name(node) is None)
    return Template(spec, pattern, weight)


def _dedented(text: str) -> str:
    lines = text.splitlines()
    while lines and not lines[0].strip():
        lines.pop(0)
    indent = len(lines[0]) - len(lines[0].lstrip()) if lines else 0
    return "\n".join(line[indent:] if line[:indent].isspace() else line for line in lines)


def _key(node) -> str:
    """What a pattern and a node must share to be worth matching: the called name, else the node's kind."""
    if isinstance(node, ast.Expr):
        return _key(node.value)
    if isinstance(node, ast.Compare) and node.left is not None:
        return "compare:" + _key(node.left)
    if isinstance(node, ast.Call):
        return "call:" + ast.dump(node.func)
    return type(node).__name__


class TemplateIndex:
    """Every template of a profile, looked up by the node they could match, most specific first."""

    def __init__(self, specs):
        self._expressions, self._statements = {}, {}
        for spec in specs:
            template = template_of(spec)
            if template is None:
                continue
            table = self._expressions if spec.is_expression else self._statements
            table.setdefault(_key(template.pattern), []).append(template)
        for table in (self._expressions, self._statements):
            for templates in table.values():
                templates.sort(key=lambda template: -template.weight)

    def expression_templates(self, node) -> list:
        """The expression templates that may match ``node``."""
        return self._expressions.get(_key(node), [])

    def statement_templates(self, node) -> list:
        """The statement templates that may match ``node``."""
        return self._statements.get(_key(node), [])


def robot_commands(tree) -> set:
    """The names of the ``robot.NAME(...)`` calls in a syntax tree."""
    return {node.func.attr for node in ast.walk(tree)
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
            and isinstance(node.func.value, ast.Name) and node.func.value.id == "robot"}


def profile_commands(specs) -> set:
    """The ``robot`` commands a profile's block templates call."""
    commands = set()
    for spec in specs:
        template = template_of(spec)
        if template is not None:
            commands |= robot_commands(template.pattern)
    return commands


def written_for(tree, profile, profiles) -> str:
    """The id of another of ``profiles`` whose commands the program calls when ``profile`` lacks some, else None."""
    used = robot_commands(tree)
    if used <= profile_commands(profile.blocks):
        return None
    return next((other.id for other in profiles if other.id != profile.id
                 and used <= profile_commands(other.blocks)), None)
