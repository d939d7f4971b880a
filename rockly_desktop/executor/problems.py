"""Why a program stopped, in words a child can act on, in English or German.

``explain(error, language, variables)`` turns an exception from the user's program into
one or two plain sentences (Rockly's catalogue, keys ``problem_*``). Python's own wording
("can only concatenate str (not "int") to str") never reaches the child; it stays in the
traceback behind "Show details". ``variables`` are the program's variables used on the line that failed, as
(Blockly name, value): they let the message name the value involved ("“count” has no
value yet"). Robot errors keep the profile's own text (its catalogue's, in the run's
language) inside a translated frame.
No Qt here: the runner calls this in the program's thread.
"""
import re
import reprlib

from rockly_desktop.core.app_texts import app_text
from rockly_desktop.core.errors import RobotCommandError, RobotTimeout, RocklyError

# What a child calls a value of a Python type: the catalogue's problem_kind_KIND (with its article,
# as the subject of a sentence).
_KIND_OF_TYPE = {
    "str": "text", "int": "number", "float": "number", "complex": "number", "bool": "truth",
    "list": "list", "tuple": "list", "range": "list", "dict": "message", "NoneType": "empty",
    "function": "function", "builtin_function_or_method": "function", "method": "function",
}
# Python's operators as the blocks show them.
_SYMBOLS = {"*": "×", "/": "÷", "//": "÷", "**": "^", "-": "−", "<=": "≤", ">=": "≥", "%": "%"}

_VALUE = reprlib.Repr()
_VALUE.maxstring = _VALUE.maxother = 40
_VALUE.maxlist = _VALUE.maxtuple = _VALUE.maxdict = 6
_MAX_NAMED = 3
_LIST_METHODS = ("append", "insert", "pop", "index", "remove", "extend", "sort", "reverse", "count")


def text(key: str, language: str, **values) -> str:
    """The run text ``key`` in ``language``: Rockly's catalogue entry ``problem_KEY``."""
    return app_text(f"problem_{key}", language, **values)


def _kind(type_name: str) -> str:
    return _KIND_OF_TYPE.get(type_name, "other")


def _kind_words(type_name: str, language: str) -> str:
    return app_text(f"problem_kind_{_kind(type_name)}", language, name=type_name)


def _after_colon(detail: str, language: str) -> str:
    """``detail`` as it follows a colon: German starts the sentence after it with a capital letter."""
    return _sentence(detail) if language == "de" else detail


def _sentence(message: str) -> str:
    return message[:1].upper() + message[1:]


def _named(variables, language, kinds=None) -> str:
    """' (“a” is 'x', “b” is 3)' for the variables of ``kinds`` (all if None), or ''."""
    shown = [text("value_is", language, name=name, value=_VALUE.repr(value)) for name, value in variables
             if kinds is None or _kind(type(value).__name__) in kinds][:_MAX_NAMED]
    return f" ({', '.join(shown)})" if shown else ""


def _with_values(message: str, variables, language, kinds=None) -> str:
    """``message`` with the named variables before its final full stop."""
    named = _named(variables, language, kinds)
    if not named:
        return message
    head, dot, tail = message.partition(";") if ";" in message else (message.rstrip("."), ".", "")
    return f"{head}{named}{dot}{tail}"


def explain(error: BaseException, language: str = "en", variables=(), names=None) -> str:
    """What went wrong, in words a child or a teacher can act on.

    ``variables``: (Blockly name, value) of the variables on the line that failed;
    ``names``: Python name -> Blockly name of the program's variables.
    """
    variables = list(variables)
    if isinstance(error, RobotTimeout):
        return text("timeout", language, detail=_after_colon(error.in_language(language), language))
    if isinstance(error, RobotCommandError):
        return text("robot", language, detail=_after_colon(error.in_language(language), language))
    if isinstance(error, RocklyError):  # written for people already
        return str(error)
    if isinstance(error, ZeroDivisionError):
        return text("zero_division", language)
    if isinstance(error, RecursionError):
        return text("recursion", language)
    if isinstance(error, NameError):
        return text("not_defined", language, name=_undefined_name(error, names or {}))
    if _about_nothing(error):
        empty = [name for name, value in variables if value is None]
        return text("empty_variable", language, name=empty[0]) if empty else text("empty_value", language)
    if isinstance(error, TypeError):
        return _type_problem(str(error), language, variables)
    if isinstance(error, AttributeError):
        type_name = type(getattr(error, "obj", None)).__name__
        if getattr(error, "name", None) in _LIST_METHODS and _kind(type_name) != "list":
            return _with_values(text("needs_list", language, a=_kind_words(type_name, language)),
                                variables, language, {_kind(type_name)})
        return _with_values(text("mismatch", language), variables, language)
    if isinstance(error, IndexError):
        return _index_problem(str(error), language, variables)
    if isinstance(error, KeyError):
        return text("no_entry", language, key=_VALUE.repr(error.args[0]) if error.args else "")
    if isinstance(error, ValueError):
        return _value_problem(str(error), language, variables)
    if isinstance(error, OverflowError):
        return text("too_big", language)
    if isinstance(error, MemoryError):
        return text("memory", language)
    return text("unexpected", language)


def _undefined_name(error: NameError, names: dict) -> str:
    name = getattr(error, "name", None)
    if not name:  # UnboundLocalError names it only in its text
        found = re.search(r"'([^']+)'", str(error))
        name = found.group(1) if found else "?"
    return names.get(name, name)


def _about_nothing(error) -> bool:
    """The error is about a value that is None: a variable that was never set, a function without a result."""
    if isinstance(error, AttributeError):
        return getattr(error, "obj", 0) is None
    return isinstance(error, TypeError) and "NoneType" in str(error)


_CONCATENATE = re.compile(r'can only concatenate (\w+) \(not "(\w+)"\) to \w+')
_OPERANDS = re.compile(r"unsupported operand type\(s\) for ([^:]+): '(\w+)' and '(\w+)'")
_COMPARE = re.compile(r"'([<>=!]+)' not supported between instances of '(\w+)' and '(\w+)'")
_NEEDS_NUMBER = (re.compile(r"bad operand type for (?:unary .|abs\(\)): '(\w+)'"),
                 re.compile(r"must be real number, not (\w+)"),
                 re.compile(r"type (\w+) doesn't define __\w+__ method"),
                 re.compile(r"(?:int|float)\(\) argument must be .*, not '(\w+)'"))
_NEEDS_SEQUENCE = (re.compile(r"object of type '(\w+)' has no len\(\)"),
                   re.compile(r"'(\w+)' object is not (?:iterable|subscriptable)"))


def _type_problem(message: str, language: str, variables) -> str:
    found = _CONCATENATE.search(message)
    if found:
        op, first, second = "+", found.group(1), found.group(2)
    else:
        found = _OPERANDS.search(message)
        op, first, second = (found.group(1).strip(), found.group(2), found.group(3)) if found else (None, None, None)
    if op is not None:
        kinds = {_kind(first), _kind(second)}
        words = {"a": _kind_words(first, language), "b": _kind_words(second, language)}
        key = "join_text" if op == "+" and "text" in kinds else "calculate"
        phrase = text(key, language, op=_SYMBOLS.get(op, op), **words)
        return _sentence(_with_values(phrase, variables, language, kinds))
    found = _COMPARE.search(message)
    if found:
        op, first, second = found.groups()
        words = {"a": _kind_words(first, language), "b": _kind_words(second, language)}
        return _sentence(_with_values(text("compare", language, op=_SYMBOLS.get(op, op), **words),
                                      variables, language, {_kind(first), _kind(second)}))
    for key, patterns in (("needs_number", _NEEDS_NUMBER), ("needs_text_or_list", _NEEDS_SEQUENCE)):
        for pattern in patterns:
            found = pattern.search(message)
            if found:
                type_name = found.group(1)
                return _with_values(text(key, language, a=_kind_words(type_name, language)),
                                    variables, language, {_kind(type_name)})
    return _with_values(text("mismatch", language), variables, language)


def _index_problem(message: str, language: str, variables) -> str:
    if message.startswith("string index"):
        return text("no_letter", language)
    lists = [(name, value) for name, value in variables if isinstance(value, (list, tuple))]
    if "empty" in message:
        return text("empty_list_of", language, name=lists[0][0]) if lists else text("empty_list", language)
    if len(lists) == 1:
        name, value = lists[0]
        if not value:
            return text("empty_list_of", language, name=name)
        if len(value) == 1:
            return text("no_item_of_one", language, name=name)
        return text("no_item_of", language, name=name, count=len(value))
    return text("no_item", language)


_NOT_A_NUMBER = re.compile(r"(?:invalid literal for \w+\(\) with base \d+|could not convert string to \w+): (.*)$")


def _value_problem(message: str, language: str, variables) -> str:
    found = _NOT_A_NUMBER.search(message)
    if found:
        return _sentence(text("not_a_number", language, value=found.group(1)))
    if "math domain error" in message:
        return text("no_result", language)
    if "not in list" in message:
        return text("not_in_list", language)
    if "substring not found" in message:
        return text("not_in_text", language)
    return _with_values(text("bad_value", language), variables, language)
