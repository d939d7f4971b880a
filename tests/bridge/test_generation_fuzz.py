"""Generated text through the real generator: any text a person types stays exactly that text,
any comment stays a comment, any number stays the number the editor holds (hypothesis)."""
import ast
import math

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from program_builder import block, text

from rockly_desktop.core.python_syntax import parse_python
from rockly_desktop.profiles.opening import ProgramToOpen

FUZZ = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
# Any text Blockly can hold: lone surrogates cannot reach the page (JSON from Python has none).
ANY_TEXT = st.text(st.characters(exclude_categories=("Cs",)), max_size=40)


def generate(editor, profile, *top_blocks) -> str:
    return editor.python_for(ProgramToOpen(path=None, profile=profile,
                                           workspace={"blocks": {"languageVersion": 0, "blocks": list(top_blocks)}}))


@FUZZ
@given(ANY_TEXT)
def test_any_text_becomes_exactly_that_string(headless_editor, hobbit, value):
    code = generate(headless_editor, hobbit, block("text_print", inputs={"TEXT": text(value)}))

    call = parse_python(code).body[0].value
    assert isinstance(call, ast.Call) and call.func.id == "print"
    assert ast.literal_eval(call.args[0]) == value


@FUZZ
@given(ANY_TEXT)
def test_any_comment_stays_a_comment(headless_editor, hobbit, comment):
    program = block("hobbit_stop", icons={"comment": {"text": comment, "pinned": False}})

    for code in (generate(headless_editor, hobbit, program), headless_editor.call_and_wait("getRunCode")["code"]):
        tree = parse_python(code)
        calls = [node.func.attr for node in ast.walk(tree)
                 if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)]
        assert calls.count("stop") == 1 and set(calls) <= {"stop", "block"}


@FUZZ
@given(st.integers(min_value=-(2 ** 53), max_value=2 ** 53)
       | st.floats(allow_nan=False, allow_infinity=False, width=64))
def test_any_number_becomes_the_same_number(headless_editor, hobbit, value):
    code = generate(headless_editor, hobbit, block("text_print", inputs={"TEXT": block("math_number", {"NUM": value})}))

    written = ast.literal_eval(parse_python(code).body[0].value.args[0])
    assert written == value or math.isclose(written, value, rel_tol=1e-15, abs_tol=0)
