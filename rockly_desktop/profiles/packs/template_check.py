"""What a block pack's Python may say: calls of Rockly's commands with values, and nothing else.

A pack is shared as a file, so it is data, never code: each block's template may only call the
profile's commands (``robot.NAME(...)``) and the generic ROS commands (``ros.NAME(...)``), with
arguments that are literals, the block's inputs, or such calls again; and wait in a ``while`` on
such calls (the made blocks' ``wait_until``). No import, no name of Python's (``open``,
``__import__``), no attribute walk (``robot.backend.publish``), no subscript, lambda, f-string,
``*``/``**`` or assignment. Every block the maker makes passes; a template written by hand that
does more is refused with its line, before the pack is installed or read.

The check reads the template as the page fills it in (``resources/blockly/templates.js``): a value
input becomes a name, a field a literal, a statement input ``pass`` at its indentation.
"""
import ast
import re
import string

from rockly_desktop.core.python_syntax import parse_python

COMMAND_OBJECTS = ("robot", "ros")
_PUBLIC = re.compile(r"^[a-z][a-z0-9_]*$")
_SLOT_PREFIX = "__slot_"
_INDENT = "  "  # Blockly's Python generator's indentation
_LITERAL_NODES = (ast.Constant,)
_CONTAINERS = (ast.List, ast.Tuple, ast.Set)
_UNARY = (ast.Not, ast.USub, ast.UAdd)


class TemplateRefused(ValueError):
    """A pack's template does more than call Rockly's commands: ``line`` (1-based) and what it does."""

    def __init__(self, line: int, problem: str):
        self.line = line
        self.problem = problem
        super().__init__(f"line {line}: {problem}")


def _filled(code: str, slots: dict, handlers: dict) -> str:
    """``code`` with each placeholder as the page fills it in, for reading with ``ast``."""
    pieces = []
    for literal, name, _spec, _conversion in string.Formatter().parse(code):
        pieces.append(literal)
        if name is None:
            continue
        slot = slots.get(name)
        if slot == "statement" and name not in handlers:
            pieces.append(_INDENT + "pass\n")
        elif slot == "field":
            pieces.append("0")
        elif slot == "typed_fields":
            pieces.append("{}")
        else:  # a value input, or a handler (the name of a function defined before the program)
            pieces.append(_SLOT_PREFIX + name)
    return "".join(pieces)


def check_template(code: str, slots: dict = None, handlers: dict = None) -> None:
    """Raise TemplateRefused when the template ``code`` (a block's ``python: code:``, with its
    ``slots`` and ``handlers`` as ``BlockSpec`` holds them) does more than call Rockly's commands."""
    filled = _filled(code, slots or {}, handlers or {})
    source = filled if "\n" in filled.strip() else filled.strip()
    try:
        tree = parse_python(source)
    except SyntaxError as error:
        raise TemplateRefused(error.lineno or 1, f"this is not Python ({error.msg})") from None
    checker = _Checker(source)
    for statement in tree.body:
        checker.statement(statement)


class _Checker:
    """Walks a filled template's tree; ``source`` names what it refuses."""

    def __init__(self, source: str):
        self.source = source

    def statement(self, node) -> None:
        if isinstance(node, ast.Pass):
            return
        if isinstance(node, ast.Expr):
            self.expression(node.value)
            return
        if isinstance(node, ast.While) and not node.orelse:
            self.expression(node.test)
            for statement in node.body:
                self.statement(statement)
            return
        raise TemplateRefused(node.lineno, f"a block pack may only call robot.… and ros.… commands, not "
                                           f"'{self.words(node)}'")

    def expression(self, node) -> None:
        if isinstance(node, _LITERAL_NODES):
            return
        if isinstance(node, ast.Name):
            if node.id.startswith(_SLOT_PREFIX):
                return
            raise TemplateRefused(node.lineno, f"'{node.id}' is no input of the block, no literal and no command")
        if isinstance(node, ast.Call):
            self.call(node)
            return
        if isinstance(node, _CONTAINERS):
            children = node.elts
        elif isinstance(node, ast.Dict):
            if any(key is None for key in node.keys):
                raise TemplateRefused(node.lineno, "'**' is not allowed in a block pack")
            children = [*node.keys, *node.values]
        elif isinstance(node, ast.UnaryOp) and isinstance(node.op, _UNARY):
            children = [node.operand]
        elif isinstance(node, ast.BoolOp):
            children = node.values
        elif isinstance(node, ast.Compare):
            children = [node.left, *node.comparators]
        else:
            raise TemplateRefused(node.lineno, f"a block pack may only pass values to robot.… and ros.… commands, "
                                               f"not '{self.words(node)}'")
        for child in children:
            self.expression(child)

    def call(self, node: ast.Call) -> None:
        function = node.func
        if not (isinstance(function, ast.Attribute) and isinstance(function.value, ast.Name)
                and function.value.id in COMMAND_OBJECTS and _PUBLIC.fullmatch(function.attr)):
            raise TemplateRefused(node.lineno, f"a block pack may only call robot.… and ros.… commands, not "
                                               f"'{self.words(function)}'")
        for argument in node.args:
            if isinstance(argument, ast.Starred):
                raise TemplateRefused(node.lineno, "'*' is not allowed in a block pack")
            self.expression(argument)
        for keyword in node.keywords:
            if keyword.arg is None:
                raise TemplateRefused(node.lineno, "'**' is not allowed in a block pack")
            self.expression(keyword.value)

    def words(self, node) -> str:
        """What ``node`` says in the template, on one line and cut short (the runtime runs on Python 3.8: no
        ``ast.unparse``)."""
        text = (ast.get_source_segment(self.source, node) or type(node).__name__).splitlines()[0]
        return text if len(text) <= 60 else text[:57] + "..."
