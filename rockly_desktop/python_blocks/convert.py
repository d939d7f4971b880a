"""A Python program turned into a Rockly program: every statement a block says becomes that block, every other
one a Python block holding its text; comments become block comments where they stand before a statement."""
import ast
from dataclasses import dataclass, field

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import ProgramFileError
from rockly_desktop.core.program import Program
from rockly_desktop.core.workspace_blocks import MAX_BLOCK_DEPTH, block_depth
from rockly_desktop.python_blocks.expressions import IMPORT_MATH, IMPORT_RANDOM, ExpressionConverter
from rockly_desktop.python_blocks.literals import NOT_CONVERTED, RESERVED, literal_value, plain_name
from rockly_desktop.python_blocks.statements import NUMBER_IMPORT, StatementConverter
from rockly_desktop.python_blocks.templates import TemplateIndex
from rockly_desktop.python_blocks.workspace import WorkspaceBuilder, comment_icon

BLOCKLY_IMPORTS = (NUMBER_IMPORT, IMPORT_MATH, IMPORT_RANDOM)
"""The imports Blockly's generator writes for the blocks that need them."""


@dataclass(frozen=True)
class KeptPython:
    """A part of the text that stayed Python (a Python block): its first and last line."""

    first_line: int
    last_line: int


@dataclass
class Conversion:
    """The program the text became, and the parts that stayed Python (none: the conversion lost nothing)."""

    program: Program
    kept_python: list = field(default_factory=list)

    @property
    def lossless(self) -> bool:
        """True when every line became blocks."""
        return not self.kept_python


@dataclass
class Names:
    """What the program names: its variables, functions (name -> returns a value), their parameters, and every
    name it reads."""

    variables: set
    procedures: dict
    parameters: dict
    loaded: set
    reserved: frozenset = RESERVED


def python_to_program(source, profile) -> Conversion:
    """Convert a parsed ``source.PythonSource`` to a Program for ``profile`` (a ``profiles.profile.Profile``);
    ProgramFileError when its blocks would nest deeper than a program may (a stack counts one per block)."""
    return _Converter(source, profile).run()


class _Converter:
    def __init__(self, source, profile):
        self.source = source
        self.lines = source.lines
        self.profile = profile
        self.specs = {spec.type: spec for spec in profile.blocks + profile.shared_blocks}
        self.builder = WorkspaceBuilder()
        self.kept = []
        self.claimed_comments = set(source.header_lines)
        self.handler_defs = {}
        self._used_handlers = set()

    def run(self) -> Conversion:
        body = list(self.source.tree.body)
        imports, declarations = _leading_imports(body), _leading_declarations(body)
        declared = [node.targets[0].id for node in declarations]
        self.handler_defs = {node.name: node for node in body if _is_handler_shape(node)
                             and node.name in _keyword_names(self.source.tree)}
        self.names = _names(self.source.tree, declared, set(self.handler_defs))
        for name in declared + sorted(self.names.variables - set(declared)):
            self.builder.declare(name)
        templates = TemplateIndex(self.specs.values())
        self.expressions = ExpressionConverter(self.builder, templates, self.names, self._fill_template)
        self.statements = StatementConverter(self.builder, templates, self.names, self.expressions,
                                             self._fill_template)
        self.statements.body = self._body
        stacks, main_blocks, previous_end = [], [], max(self.source.header_lines, default=0)
        handlers_waiting = []
        for node in body:
            if isinstance(node, ast.FunctionDef) and node.name in self.names.procedures:
                block = self._procedure(node)
                if block is not None:
                    stacks.append([block])
                    continue
            if node.name in self.handler_defs if isinstance(node, ast.FunctionDef) else False:
                handlers_waiting.append((len(main_blocks), node))
                continue
            main_blocks.extend(self._body([node], previous_end))
            previous_end = node.end_lineno
        for position, node in reversed(handlers_waiting):
            if node.name not in self._used_handlers:
                main_blocks[position:position] = self._body([node], _first_line(node) - 1)
        unreferenced = [node for node in declarations if node.targets[0].id not in self.builder.referenced]
        if unreferenced and self.kept:  # a Python block may read it: Blockly declares only what blocks use
            main_blocks[:0] = [self._kept_block(node) for node in unreferenced]
        needed = self.expressions.imports | ({NUMBER_IMPORT} if self.statements.uses_number_import else set())
        main_blocks[:0] = [self._kept_block(node) for node in imports if _source_of(node) not in needed]
        stacks = stacks + [main_blocks]
        left_over = self._unclaimed_comments()
        if left_over:
            main_blocks.append(self._comment_block(left_over))
        workspace = self.builder.workspace([stack for stack in stacks if stack])
        depth = block_depth(workspace)
        if depth > MAX_BLOCK_DEPTH:
            raise ProgramFileError(self.source.path, app_local_text("file_too_deep", depth=depth,
                                                                    limit=MAX_BLOCK_DEPTH))
        program = Program(self.profile.id, workspace, packs=self.profile.packs_used(workspace))
        return Conversion(program, sorted(self.kept, key=lambda part: part.first_line))

    # -- bodies, comments and Python blocks

    def _body(self, statements, previous_end=None) -> list:
        if len(statements) == 1 and isinstance(statements[0], ast.Pass) and not self._inline_comments(statements[0]):
            return []
        blocks = []
        if previous_end is None:
            previous_end = _first_line(statements[0]) - 1 if statements else 0
        for node in statements:
            comment = self._comments_between(previous_end, _first_line(node))
            block = None if self._inline_comments(node) else self.statements.block(node)
            if block is None:
                block = self._kept_block(node)
            if comment is not None:
                block["icons"] = comment_icon(comment)
            blocks.append(block)
            previous_end = node.end_lineno
        return blocks

    def _comments_between(self, after: int, before: int):
        texts = []
        for line in range(after + 1, before):
            comment = self.source.comments.get(line)
            if comment is None or line in self.claimed_comments or not self._standalone(line, comment):
                continue
            self.claimed_comments.add(line)
            text = comment[1]
            texts.append(text[1:] if text.startswith(" ") else text)
        return "\n".join(texts) if texts else None

    def _standalone(self, line: int, comment) -> bool:
        return not self.lines[line - 1][:comment[0]].strip()

    def _inline_comments(self, node) -> bool:
        """True when a comment shares a line with ``node``'s own code (not with a nested statement's)."""
        nested = [child for name in ("body", "orelse", "finalbody") for child in getattr(node, name, []) or []]
        for line in range(_first_line(node), node.end_lineno + 1):
            comment = self.source.comments.get(line)
            if comment is None or self._standalone(line, comment):
                continue
            if not any(_first_line(child) <= line <= child.end_lineno for child in nested):
                return True
        return False

    def _kept_block(self, node) -> dict:
        first, last = _first_line(node), node.end_lineno
        self.kept.append(KeptPython(first, last))
        for line in range(first, last + 1):
            self.claimed_comments.add(line)
        return self.builder.python_block(_dedent(self.lines[first - 1:last], node.col_offset))

    def _unclaimed_comments(self) -> list:
        return [line for line in sorted(self.source.comments) if line not in self.claimed_comments]

    def _comment_block(self, lines: list) -> dict:
        self.kept.append(KeptPython(lines[0], lines[-1]))
        return self.builder.python_block("\n".join("#" + self.source.comments[line][1] for line in lines))

    # -- functions

    def _procedure(self, node):
        params = self.names.parameters[node.name]
        body = list(node.body)
        expected_globals = [name for name in self.builder.variables if name not in params]
        if body and isinstance(body[0], ast.Global):
            if list(body[0].names) != expected_globals:
                return None
            body.pop(0)
        elif expected_globals:
            return None
        returns = self.names.procedures[node.name]
        value = None
        if returns:
            value = self.expressions.block(body.pop().value)
            if value is None:
                return None
        if any(isinstance(inner, ast.Return) for statement in body for inner in ast.walk(statement)):
            return None
        if self._inline_comments(node) or node.decorator_list:
            return None
        block_type = "procedures_defreturn" if returns else "procedures_defnoreturn"
        inputs = {"STACK": self.statements._stack(body) if body else None}
        if value is not None:
            inputs["RETURN"] = value
        extra = {"params": [{"name": name, "id": self.builder.variable(name)["id"]} for name in params]}
        block = self.builder.block(block_type, {"NAME": node.name}, inputs, extra if params else None)
        comment = self._comments_between(self._previous_end(node), node.lineno)
        if comment is not None:
            block["icons"] = comment_icon(comment)
        return block

    def _previous_end(self, node) -> int:
        before = [other.end_lineno for other in self.source.tree.body if other.end_lineno < _first_line(node)]
        return max(before + [max(self.source.header_lines, default=0)])

    def _handler(self, name_node, variable_field):
        """``(stack, variable)`` of a handler function named by ``name_node`` (``None``: no handler), or None."""
        if literal_value(name_node) is None:
            return None, None
        node = self.handler_defs.get(getattr(name_node, "id", None))
        if node is None:
            return None
        body = list(node.body)
        if body and isinstance(body[0], ast.Global):
            if list(body[0].names) != list(self.builder.variables):
                return None
            body.pop(0)
        argument = node.args.args[0].arg
        if not (body and isinstance(body[0], ast.Assign) and len(body[0].targets) == 1
                and isinstance(body[0].targets[0], ast.Name) and isinstance(body[0].value, ast.Name)
                and body[0].value.id == argument):
            return None
        target = body.pop(0).targets[0].id
        if plain_name(target, self.names.reserved) is None or not body:
            return None
        self._used_handlers.add(node.name)
        return self.statements._stack(body), target

    # -- templates

    def _fill_template(self, spec, bindings):
        """The block of ``spec`` whose slots hold ``bindings``, or None when a slot's content does not fit."""
        fields, inputs, extra = {}, {}, None
        kinds = _field_kinds(spec.definition)
        for slot, node in bindings.items():
            kind = spec.slots.get(slot)
            if kind == "field" and slot in _type_fields(kinds) and "fields" in spec.slots:
                value = literal_value(node)
                if not isinstance(value, str):
                    return None
                fields[slot] = value
            elif kind == "field":
                value = self._field_value(spec, slot, kinds.get(slot), node)
                if value is NOT_CONVERTED:
                    return None
                fields[slot] = value
            elif kind == "value":
                block = self.expressions.block(node)
                if block is None:
                    return None
                inputs[slot] = block
            elif kind == "statement" and slot in spec.handlers:
                handled = self._handler(node, spec.handlers[slot])
                if handled is None:
                    return None
                stack, variable = handled
                inputs[slot] = stack
                if variable is not None:
                    fields[spec.handlers[slot]] = self.builder.variable(variable)
            elif kind == "statement":
                inputs[slot] = self.statements._stack(node)
            elif kind == "typed_fields":
                typed = self._typed_fields(spec, node, bindings)
                if typed is None:
                    return None
                extra, field_inputs = typed
                inputs.update(field_inputs)
            else:
                return None
        for _name, variable_field in spec.handlers.items():
            if variable_field not in fields:
                default = _default_variable(spec.definition, variable_field)
                fields[variable_field] = self.builder.variable(default)
        return self.builder.block(spec.type, fields or None, inputs, extra)

    def _field_value(self, spec, slot, field_kind, node):
        if field_kind == "field_variable":
            name = plain_name(getattr(node, "id", ""), self.names.reserved)
            return self.builder.variable(name) if name is not None else NOT_CONVERTED
        value = literal_value(node)
        if value is NOT_CONVERTED:
            return NOT_CONVERTED
        mapping = spec.values.get(slot)
        if mapping:
            for key, mapped in mapping.items():
                if mapped == value and type(mapped) is type(value):
                    return key
        if field_kind == "field_number":
            return value if type(value) in (int, float) else NOT_CONVERTED
        if field_kind == "field_checkbox":
            return ("TRUE" if value else "FALSE") if isinstance(value, bool) else NOT_CONVERTED
        if not isinstance(value, str):
            return NOT_CONVERTED
        options = _dropdown_options(spec.definition, slot)
        if options is not None and value not in options:
            return NOT_CONVERTED
        return value

    def _typed_fields(self, spec, node, bindings):
        """``(extraState, inputs)`` of a typed-fields block from its dict of fields, or None."""
        kinds = _field_kinds(spec.definition)
        type_field = next(iter(_type_fields(kinds)), None)
        type_node = literal_value(bindings.get(type_field))
        if type_field is None or not isinstance(type_node, str):
            return None
        leaves = {}
        if not _flatten(node, "", leaves):
            return None
        known = self._type_catalog(type_field).get(type_node)
        fields = known if known is not None else [[path, _check(value), None] for path, value in leaves.items()]
        inputs = {}
        for path, value in leaves.items():
            block = self.expressions.block(value)
            if block is None:
                return None
            inputs["field:" + path] = block
        return {"type": type_node, "fields": fields}, inputs

    def _type_catalog(self, type_field) -> dict:
        catalog = self.profile.ros_types.editor_catalog
        return catalog.get({"message_type": "messages", "service_type": "services", "action_type": "actions"}
                           [type_field], {})


def _flatten(node, prefix: str, leaves: dict) -> bool:
    if not isinstance(node, ast.Dict) or any(key is None for key in node.keys):
        return False
    for key, value in zip(node.keys, node.values, strict=False):
        if not (isinstance(key, ast.Constant) and isinstance(key.value, str)):
            return False
        path = prefix + key.value
        if isinstance(value, ast.Dict) and value.keys:
            if not _flatten(value, path + ".", leaves):
                return False
        else:
            leaves[path] = value
    return True


def _check(value) -> str:
    found = literal_value(value)
    if isinstance(found, bool):
        return "Boolean"
    if isinstance(found, (int, float)):
        return "Number"
    return "String" if isinstance(found, str) else None


def _field_kinds(definition: dict) -> dict:
    return {arg["name"]: arg.get("type") for key, args in definition.items()
            if key.startswith("args") and isinstance(args, list)
            for arg in args if isinstance(arg, dict) and "name" in arg}


def _type_fields(kinds: dict) -> list:
    return [name for name in ("message_type", "service_type", "action_type") if kinds.get(name) == "field_dropdown"]


def _dropdown_options(definition: dict, name: str):
    for key, args in definition.items():
        if key.startswith("args") and isinstance(args, list):
            for arg in args:
                if isinstance(arg, dict) and arg.get("name") == name and isinstance(arg.get("options"), list):
                    return {option[1] for option in arg["options"] if isinstance(option, list) and len(option) == 2}
    return None


def _default_variable(definition: dict, name: str) -> str:
    for key, args in definition.items():
        if key.startswith("args") and isinstance(args, list):
            for arg in args:
                if isinstance(arg, dict) and arg.get("name") == name:
                    return str(arg.get("variable") or name)
    return name


def _source_of(node) -> str:
    return ast.unparse(node)


def _leading_imports(body: list) -> list:
    """The imports Blockly writes, taken off the start of ``body``."""
    imports = []
    while body and isinstance(body[0], (ast.Import, ast.ImportFrom)) and _source_of(body[0]) in BLOCKLY_IMPORTS:
        imports.append(body.pop(0))
    return imports


def _leading_declarations(body: list) -> list:
    """Blockly's variable declarations (``x = None``, each name once), taken off the start of ``body``."""
    declarations, declared = [], []
    while body and _is_declaration(body[0], declared):
        declarations.append(body.pop(0))
        declared.append(declarations[-1].targets[0].id)
    return declarations


def _is_declaration(node, declared: list) -> bool:
    return (isinstance(node, ast.Assign) and len(node.targets) == 1 and isinstance(node.targets[0], ast.Name)
            and isinstance(node.value, ast.Constant) and node.value.value is None
            and node.targets[0].id not in declared and plain_name(node.targets[0].id) is not None)


def _is_handler_shape(node) -> bool:
    return (isinstance(node, ast.FunctionDef) and len(node.args.args) == 1 and not node.decorator_list
            and not node.args.vararg and not node.args.kwarg and not node.args.kwonlyargs and not node.args.defaults)


def _first_line(node) -> int:
    return min([node.lineno] + [decorator.lineno for decorator in getattr(node, "decorator_list", [])])


def _dedent(lines: list, column: int) -> str:
    return "\n".join(line[column:] if line[:column].isspace() or not line[:column] else line for line in lines)


def _keyword_names(tree) -> set:
    """The names passed as keyword arguments (``while_waiting=while_waiting``): a handler's function."""
    return {keyword.value.id for node in ast.walk(tree) if isinstance(node, ast.Call)
            for keyword in node.keywords if isinstance(keyword.value, ast.Name)}


def _names(tree, declared: list, handlers: set) -> Names:
    """The variables (declared, assigned, looped over by for-each, parameters), functions and read names."""
    variables, procedures, parameters, loaded = set(declared), {}, {}, set()
    range_targets = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Load):
            loaded.add(node.id)
        elif isinstance(node, ast.Assign):
            variables.update(target.id for target in node.targets if isinstance(target, ast.Name))
        elif isinstance(node, ast.For) and isinstance(node.target, ast.Name):
            if isinstance(node.iter, ast.Call) and getattr(node.iter.func, "id", None) == "range":
                range_targets.add(node.target.id)
            else:
                variables.add(node.target.id)
    for node in tree.body:
        if isinstance(node, ast.FunctionDef) and (not _is_simple_signature(node) or node.name in handlers):
            continue
        if isinstance(node, ast.FunctionDef):
            params = tuple(arg.arg for arg in node.args.args)
            last = node.body[-1]
            procedures[node.name] = isinstance(last, ast.Return) and last.value is not None
            parameters[node.name] = params
            variables.update(params)
    variables |= range_targets & loaded  # a count's variable read in its body: Blockly's "count with"
    variables = {name for name in variables if plain_name(name) is not None and name not in procedures}
    return Names(variables, procedures, parameters, loaded)


def _is_simple_signature(node) -> bool:
    arguments = node.args
    return not (arguments.vararg or arguments.kwarg or arguments.kwonlyargs or arguments.defaults
                or arguments.posonlyargs or node.decorator_list)
