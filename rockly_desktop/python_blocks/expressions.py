"""Expressions back to value blocks: the profile's templates first, then Blockly's standard blocks as its Python
generator writes them. ``None`` means no block says it (the statement holding it stays Python)."""
import ast
import math

from rockly_desktop.python_blocks.literals import NOT_CONVERTED, literal_value, plain_name

COMPARE = {ast.Eq: "EQ", ast.NotEq: "NEQ", ast.Lt: "LT", ast.LtE: "LTE", ast.Gt: "GT", ast.GtE: "GTE"}
ARITHMETIC = {ast.Add: "ADD", ast.Sub: "MINUS", ast.Mult: "MULTIPLY", ast.Div: "DIVIDE", ast.Pow: "POWER"}
BOOLEAN = {ast.And: "AND", ast.Or: "OR"}
# math.NAME(x) -> (block type, its OP): Blockly's math_single, math_round (all import math)
MATH_CALLS = {"sqrt": ("math_single", "ROOT"), "fabs": ("math_single", "ABS"), "log": ("math_single", "LN"),
              "log10": ("math_single", "LOG10"), "exp": ("math_single", "EXP"),
              "ceil": ("math_round", "ROUNDUP"), "floor": ("math_round", "ROUNDDOWN")}
TRIGONOMETRY = {"sin": "SIN", "cos": "COS", "tan": "TAN"}
MATH_CONSTANTS = {"pi": "PI", "e": "E"}
IMPORT_MATH, IMPORT_RANDOM = "import math", "import random"


class ExpressionConverter:
    """Turns expression nodes into value blocks; ``slots`` fills a template's slots (see ``blocks``)."""

    def __init__(self, builder, templates, names, fill_template):
        self.builder = builder
        self.templates = templates
        self.names = names  # the program's Names: .variables, .procedures (name -> has a return), .reserved
        self.fill_template = fill_template
        self.imports = set()  # the imports the blocks made need (Blockly writes them again)

    def block(self, node):
        """The value block saying ``node``, or None."""
        for template in self.templates.expression_templates(node):
            bindings = template.match(node)
            if bindings is not None:
                block = self.fill_template(template.spec, bindings)
                if block is not None:
                    return block
        return self._standard(node)

    def _standard(self, node):
        make = self.builder.block
        value = literal_value(node)
        if value is not NOT_CONVERTED:
            return self._literal(value)
        if isinstance(node, ast.Name):
            name = plain_name(node.id, self.names.reserved)
            if name is None or name not in self.names.variables:
                return None
            return make("variables_get", {"VAR": self.builder.variable(name)})
        if isinstance(node, ast.BinOp):
            return self._binary(node)
        if isinstance(node, ast.Call):
            return self._call(node)
        if isinstance(node, ast.Compare) and len(node.ops) == 1 and type(node.ops[0]) in COMPARE:
            return self._two("logic_compare", COMPARE[type(node.ops[0])], node.left, node.comparators[0])
        if isinstance(node, ast.BoolOp):
            result = self.block(node.values[0])
            for right in node.values[1:]:
                result = self._joined("logic_operation", BOOLEAN[type(node.op)], result, self.block(right))
            return result
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.Not):
            inner = self.block(node.operand)
            return make("logic_negate", inputs={"BOOL": inner}) if inner is not None else None
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
            inner = self.block(node.operand)
            return make("math_single", {"OP": "NEG"}, {"NUM": inner}) if inner is not None else None
        if isinstance(node, ast.IfExp):
            parts = [self.block(part) for part in (node.test, node.body, node.orelse)]
            if None in parts:
                return None
            return make("logic_ternary", inputs=dict(zip(("IF", "THEN", "ELSE"), parts, strict=False)))
        if isinstance(node, ast.Attribute) and _is_module(node.value, "math") and node.attr in MATH_CONSTANTS:
            self.imports.add(IMPORT_MATH)
            return make("math_constant", {"CONSTANT": MATH_CONSTANTS[node.attr]})
        if isinstance(node, ast.List):
            items = [self.block(item) for item in node.elts]
            if None in items:
                return None
            if not items:
                return make("lists_create_empty")
            return make("lists_create_with", inputs={f"ADD{index}": item for index, item in enumerate(items)},
                        extra_state={"itemCount": len(items)})
        return None

    def _literal(self, value):
        make = self.builder.block
        if value is None:
            return make("logic_null")
        if isinstance(value, bool):
            return make("logic_boolean", {"BOOL": "TRUE" if value else "FALSE"})
        if isinstance(value, str):
            return make("text", {"TEXT": value})
        if isinstance(value, float) and math.isnan(value):
            return None
        if isinstance(value, float) and value.is_integer() and not math.isinf(value):
            return None  # the generator writes 2.0 as 2: keep the text
        if isinstance(value, int) and abs(value) >= 2 ** 53:
            return None  # the editor's numbers are doubles: it could not keep this one
        return make("math_number", {"NUM": value})

    def _binary(self, node):
        if isinstance(node.op, ast.Add):
            joined = self._text_join([node.left, node.right])
            if joined is not None:
                return joined
        if (isinstance(node.op, ast.Mult) and isinstance(node.left, ast.List) and len(node.left.elts) == 1
                and not isinstance(node.left.elts[0], ast.Starred)):
            return self._two_inputs("lists_repeat", node.left.elts[0], node.right, ("ITEM", "NUM"))
        if isinstance(node.op, ast.Mod):
            return self._two_inputs("math_modulo", node.left, node.right, ("DIVIDEND", "DIVISOR"))
        if type(node.op) in ARITHMETIC:
            return self._two("math_arithmetic", ARITHMETIC[type(node.op)], node.left, node.right)
        return None

    def _text_join(self, parts):
        """``'a' + str(b)``: Blockly's text join of two items (each a text literal or ``str(...)``)."""
        items = []
        for part in parts:
            if isinstance(part, ast.Constant) and isinstance(part.value, str):
                items.append(self.block(part))
            elif _is_str_call(part) and not (isinstance(part.args[0], ast.Constant)
                                             and isinstance(part.args[0].value, str)):
                items.append(self.block(part.args[0]))
            else:
                return None
        if None in items:
            return None
        return self.builder.block("text_join", inputs={f"ADD{index}": item for index, item in enumerate(items)},
                                  extra_state={"itemCount": len(items)})

    def _call(self, node):
        items = _joined_items(node)
        if items is not None:
            blocks = [self.block(item) for item in items]
            if None in blocks or len(blocks) < 3:
                return None
            return self.builder.block("text_join", inputs={f"ADD{index}": item for index, item in enumerate(blocks)},
                                      extra_state={"itemCount": len(blocks)})
        if _is_str_call(node) and not (isinstance(node.args[0], ast.Constant) and isinstance(node.args[0].value, str)):
            return self._text_join_one(node.args[0])
        if node.keywords or any(isinstance(argument, ast.Starred) for argument in node.args):
            return None
        function, arguments = node.func, node.args
        if isinstance(function, ast.Name) and function.id == "round" and len(arguments) == 1:
            return self._math("math_round", "ROUND", arguments[0])
        if isinstance(function, ast.Attribute) and _is_module(function.value, "math"):
            return self._math_call(function.attr, arguments)
        if isinstance(function, ast.Attribute) and _is_module(function.value, "random"):
            if function.attr == "random" and not arguments:
                self.imports.add(IMPORT_RANDOM)
                return self.builder.block("math_random_float")
            if function.attr == "randint" and len(arguments) == 2:
                block = self._two_inputs("math_random_int", arguments[0], arguments[1], ("FROM", "TO"))
                if block is not None:
                    self.imports.add(IMPORT_RANDOM)
                return block
            return None
        if isinstance(node.func, ast.Name) and self.names.procedures.get(node.func.id) is True and not node.keywords:
            return self.procedure_call("procedures_callreturn", node)
        return None

    def _math_call(self, name: str, arguments):
        if name in MATH_CALLS and len(arguments) == 1:
            return self._math(*MATH_CALLS[name], arguments[0])
        if (name == "pow" and len(arguments) == 2 and isinstance(arguments[0], ast.Constant)
                and type(arguments[0].value) is int and arguments[0].value == 10):
            return self._math("math_single", "POW10", arguments[1])
        if name in TRIGONOMETRY and len(arguments) == 1:
            degrees = _degrees(arguments[0])
            return self._math("math_trig", TRIGONOMETRY[name], degrees) if degrees is not None else None
        return None

    def _math(self, block_type: str, operator: str, argument):
        inner = self.block(argument)
        if inner is None:
            return None
        self.imports.add(IMPORT_MATH)
        return self.builder.block(block_type, {"OP": operator}, {"NUM": inner})

    def _text_join_one(self, inner):
        block = self.block(inner)
        if block is None:
            return None
        return self.builder.block("text_join", inputs={"ADD0": block}, extra_state={"itemCount": 1})

    def procedure_call(self, block_type, node):
        """A call of a function the program defines (``procedures_callreturn``/``callnoreturn``), or None."""
        params = self.names.parameters.get(node.func.id)
        if params is None or len(params) != len(node.args) or any(isinstance(a, ast.Starred) for a in node.args):
            return None
        arguments = [self.block(argument) for argument in node.args]
        if None in arguments:
            return None
        return self.builder.block(block_type, inputs={f"ARG{index}": arg for index, arg in enumerate(arguments)},
                                  extra_state={"name": node.func.id, "params": list(params)})

    def _two(self, block_type, operator, left, right):
        return self._joined(block_type, operator, self.block(left), self.block(right))

    def _joined(self, block_type, operator, left, right):
        if left is None or right is None:
            return None
        return self.builder.block(block_type, {"OP": operator}, {"A": left, "B": right})

    def _two_inputs(self, block_type, left, right, names):
        blocks = [self.block(left), self.block(right)]
        if None in blocks:
            return None
        return self.builder.block(block_type, inputs=dict(zip(names, blocks, strict=False)))


def _is_module(node, name: str) -> bool:
    return isinstance(node, ast.Name) and node.id == name


def _degrees(node):
    """``x`` of Blockly's ``x / 180.0 * math.pi`` (degrees to radians), else None."""
    if not (isinstance(node, ast.BinOp) and isinstance(node.op, ast.Mult) and isinstance(node.right, ast.Attribute)
            and _is_module(node.right.value, "math") and node.right.attr == "pi"):
        return None
    division = node.left
    if not (isinstance(division, ast.BinOp) and isinstance(division.op, ast.Div)
            and isinstance(division.right, ast.Constant) and type(division.right.value) is float
            and division.right.value == 180.0):
        return None
    return division.left


def _joined_items(node):
    """The items of Blockly's text join of three or more: ``''.join([str(x) for x in [a, b, c]])``, else None."""
    function = node.func
    if not (isinstance(function, ast.Attribute) and function.attr == "join" and isinstance(function.value, ast.Constant)
            and function.value.value == "" and len(node.args) == 1 and not node.keywords):
        return None
    comprehension = node.args[0]
    if not (isinstance(comprehension, ast.ListComp) and len(comprehension.generators) == 1):
        return None
    loop = comprehension.generators[0]
    element = comprehension.elt
    if (loop.ifs or loop.is_async or not isinstance(loop.target, ast.Name) or not isinstance(loop.iter, ast.List)
            or not _is_str_call(element) or not isinstance(element.args[0], ast.Name)
            or element.args[0].id != loop.target.id):
        return None
    return loop.iter.elts


def _is_str_call(node) -> bool:
    return (isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "str"
            and len(node.args) == 1 and not node.keywords and not isinstance(node.args[0], ast.Starred))
