"""Parsing Python text into a syntax tree, safe against CPython 3.11's shared AST depth counter.

CPython 3.11 keeps the counter that checks the AST constructor's recursion in the interpreter's shared
state, not per thread (python/cpython#106905). When another thread builds a tree at the same time, for
instance a traceback being formatted (3.11's ``traceback`` parses the failing line), ``ast.parse`` may
raise ``SystemError: AST constructor recursion depth mismatch`` for perfectly good text. That error says
nothing about the text, so the parse is simply done again.
"""
import ast

_ATTEMPTS = 5


def parse_python(source: str, mode: str = "exec") -> ast.AST:
    """``ast.parse(source, mode=mode)``; SyntaxError and ValueError pass through as ``ast.parse`` raises them."""
    for attempt in range(_ATTEMPTS):
        try:
            return ast.parse(source, mode=mode)
        except SystemError as error:
            if "recursion depth mismatch" not in str(error) or attempt == _ATTEMPTS - 1:
                raise
    raise AssertionError("unreachable")
