"""parse_python: good text parses even when CPython 3.11's shared AST depth counter trips (python/cpython#106905)."""
import ast
import threading

import pytest

from rockly_desktop.core import python_syntax
from rockly_desktop.core.python_syntax import parse_python


def test_a_depth_mismatch_from_another_thread_is_parsed_again(monkeypatch):
    real_parse, calls = ast.parse, []

    def tripping_parse(source, *args, **kwargs):
        if source == "x = 1":
            calls.append(source)
            if len(calls) == 1:
                raise SystemError("AST constructor recursion depth mismatch (before=120, after=30)")
        return real_parse(source, *args, **kwargs)

    monkeypatch.setattr(python_syntax.ast, "parse", tripping_parse)
    tree = parse_python("x = 1")
    assert isinstance(tree.body[0], ast.Assign) and len(calls) == 2


def test_other_system_errors_and_syntax_errors_pass_through(monkeypatch):
    with pytest.raises(SyntaxError):
        parse_python("x = (")

    real_parse = ast.parse

    def broken_parse(source, *args, **kwargs):
        if source == "x = 1":
            raise SystemError("something else")
        return real_parse(source, *args, **kwargs)

    monkeypatch.setattr(python_syntax.ast, "parse", broken_parse)
    with pytest.raises(SystemError, match="something else"):
        parse_python("x = 1")


class _Finalised:
    """Garbage in a cycle whose finaliser runs Python: the collector then hands the GIL to other threads
    in the middle of a tree being built, which is how a traceback or a rospy thread trips the counter."""

    def __init__(self):
        self.cycle = self

    def __del__(self):
        sum(range(100))


def test_many_threads_parsing_at_once_beside_garbage_collection_all_get_their_trees():
    source = "\n".join(f"def f{i}(a):\n    return [b for b in range(a) if b % {i + 1}]" for i in range(300))
    trees, errors, parsing = [], [], threading.Event()

    def parse_many():
        try:
            for _ in range(25):
                trees.append(parse_python(source))
        except Exception as error:  # gathered for the assertion below
            errors.append(error)

    def make_garbage():
        for _ in range(200_000):  # bounded: the collector may fall behind a thread that only makes garbage
            if parsing.is_set():
                return
            _Finalised()

    garbage = threading.Thread(target=make_garbage)
    threads = [threading.Thread(target=parse_many) for _ in range(4)]
    garbage.start()
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    parsing.set()
    garbage.join()
    assert not errors and len(trees) == 100 and all(len(tree.body) == 300 for tree in trees)
