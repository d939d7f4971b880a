"""Statements back to statement blocks: the profile's templates, then Blockly's loops, conditions, variables
and function calls as its Python generator writes them. ``None``: no block says it (it stays Python)."""
import ast

from rockly_desktop.core.python_syntax import parse_python
from rockly_desktop.python_blocks.literals import literal_value, plain_name
from rockly_desktop.python_blocks.workspace import chain

NUMBER_IMPORT = "from numbers import Number"


class StatementConverter:
    """Turns one statement node into a block; ``body`` (given by the converter) turns a list of statements."""

    def __init__(self, builder, templates, names, expressions, fill_template):
        self.builder = builder
        self.templates = templates
        self.names = names
        self.expressions = expressions
        self.fill_template = fill_template
        self.body = None  # set by the converter: list of statements -> list of blocks
        self.uses_number_import = False

    def block(self, node):
        """The statement block saying ``node``, or None."""
        for template in self.templates.statement_templates(node):
            bindings = template.match(node)
            if bindings is not None:
                block = self.fill_template(template.spec, bindings)
                if block is not None:
                    return block
        method = getattr(self, "_" + type(node).__name__.lower(), None)
        return method(node) if method is not None else None

    def _value(self, node):
        return self.expressions.block(node)

    def _expr(self, node):
        call = node.value
        if (isinstance(call, ast.Call) and isinstance(call.func, ast.Name) and call.func.id == "print"
                and len(call.args) == 1 and not call.keywords and not isinstance(call.args[0], ast.Starred)):
            text = self._value(call.args[0])
            return self.builder.block("text_print", inputs={"TEXT": text}) if text is not None else None
        if (isinstance(call, ast.Call) and isinstance(call.func, ast.Name) and not call.keywords
                and self.names.procedures.get(call.func.id) is False):
            return self.expressions.procedure_call("procedures_callnoreturn", call)
        return None

    def _assign(self, node):
        if len(node.targets) != 1 or not isinstance(node.targets[0], ast.Name):
            return None
        name = plain_name(node.targets[0].id, self.names.reserved)
        if name is None or name not in self.names.variables:
            return None
        delta = _change_delta(name, node.value)
        if delta is not None:
            value = self._value(delta)
            if value is None:
                return None
            self.uses_number_import = True
            return self.builder.block("math_change", {"VAR": self.builder.variable(name)}, {"DELTA": value})
        value = self._value(node.value)
        if value is None:
            return None
        return self.builder.block("variables_set", {"VAR": self.builder.variable(name)}, {"VALUE": value})

    def _if(self, node):
        inputs, branches, otherwise = {}, [], None
        while True:
            branches.append(node)
            rest = node.orelse
            if len(rest) == 1 and isinstance(rest[0], ast.If) and rest[0].col_offset == node.col_offset:
                node = rest[0]  # `elif`: written at the same indentation as its `if`
                continue
            otherwise = rest or None
            break
        for index, branch in enumerate(branches):
            condition = self._value(branch.test)
            if condition is None:
                return None
            inputs[f"IF{index}"] = condition
            inputs[f"DO{index}"] = self._stack(branch.body)
        extra = {}
        if len(branches) > 1:
            extra["elseIfCount"] = len(branches) - 1
        if otherwise is not None:
            extra["hasElse"] = True
            inputs["ELSE"] = self._stack(otherwise)
        return self.builder.block("controls_if", inputs=inputs, extra_state=extra or None)

    def _while(self, node):
        if node.orelse:
            return None
        test, mode = node.test, "WHILE"
        if isinstance(test, ast.UnaryOp) and isinstance(test.op, ast.Not):
            test, mode = test.operand, "UNTIL"
        condition = self._value(test)
        if condition is None:
            return None
        return self.builder.block("controls_whileUntil", {"MODE": mode},
                                  {"BOOL": condition, "DO": self._stack(node.body)})

    def _for(self, node):
        if node.orelse or not isinstance(node.target, ast.Name):
            return None
        target = node.target.id
        times = _range_count(node.iter)
        if times is not None and target not in self.names.variables and target not in self.names.loaded:
            count = self._value(times)
            if count is None:
                return None
            return self.builder.block("controls_repeat_ext", inputs={"TIMES": count, "DO": self._stack(node.body)})
        name = plain_name(target, self.names.reserved)
        if name is None or name not in self.names.variables:
            return None
        counted = _counted_range(node.iter)
        if counted is not None:
            inputs = {key: self.builder.block("math_number", {"NUM": value}) for key, value in counted.items()}
            return self.builder.block("controls_for", {"VAR": self.builder.variable(name)},
                                      {**inputs, "DO": self._stack(node.body)})
        items = self._value(node.iter)
        if items is None:
            return None
        return self.builder.block("controls_forEach", {"VAR": self.builder.variable(name)},
                                  {"LIST": items, "DO": self._stack(node.body)})

    def _break(self, node):
        return self.builder.block("controls_flow_statements", {"FLOW": "BREAK"})

    def _continue(self, node):
        return self.builder.block("controls_flow_statements", {"FLOW": "CONTINUE"})

    def _stack(self, statements):
        """The first block of the stack saying ``statements`` (``pass`` alone: empty), or None."""
        return chain(self.body(statements))


def _range_count(node):
    """The count of ``range(4)`` or ``range(int(x))`` as Blockly's repeat writes it, else None."""
    if not (isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "range"
            and len(node.args) == 1 and not node.keywords):
        return None
    count = node.args[0]
    if isinstance(count, ast.Constant) and type(count.value) is int:
        return count
    if (isinstance(count, ast.Call) and isinstance(count.func, ast.Name) and count.func.id == "int"
            and len(count.args) == 1 and not count.keywords and not isinstance(count.args[0], ast.Starred)):
        return count.args[0]
    return None


def _counted_range(node):
    """``{FROM, TO, BY}`` of Blockly's "count with" over whole numbers as it writes it (``range(5)``,
    ``range(1, 11)``, ``range(1, 11, 2)``, ``range(10, 0, -1)``), else None."""
    if not (isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "range"
            and not node.keywords and 1 <= len(node.args) <= 3):
        return None
    values = [literal_value(argument) for argument in node.args]
    if not all(type(value) is int for value in values):
        return None
    if len(values) == 1:
        start, stop, step = 0, values[0], 1
    else:
        start, stop, step = values[0], values[1], values[2] if len(values) == 3 else 1
    if step > 0 and start <= stop - 1:
        counted = {"FROM": start, "TO": stop - 1, "BY": step}
    elif step < 0 and start > stop + 1:
        counted = {"FROM": start, "TO": stop + 1, "BY": -step}
    else:
        return None
    written = _written_range(counted["FROM"], counted["TO"], counted["BY"])
    return counted if written == values else None


def _written_range(start: int, end: int, step: int) -> list:
    """The arguments of ``range(...)`` Blockly writes for counting from ``start`` to ``end`` by ``step``."""
    if start <= end:
        arguments = [end + 1] if start == 0 and step == 1 else [start, end + 1]
        return arguments + ([step] if step != 1 else [])
    return [start, end - 1, -step]


def _change_delta(name: str, value):
    """The delta of Blockly's ``x = (x if isinstance(x, Number) else 0) + delta``, else None."""
    if not (isinstance(value, ast.BinOp) and isinstance(value.op, ast.Add) and isinstance(value.left, ast.IfExp)):
        return None
    guard = value.left
    wanted = f"(({name} if isinstance({name}, Number) else 0))"
    if ast.dump(parse_python(wanted, mode="eval").body) != ast.dump(guard):
        return None
    return value.right
