"""Run errors in plain words, in English and German, naming the variable involved. No Qt."""
import pytest

from rockly_desktop.core.errors import ManifestError, RobotCommandError, RobotTimeout
from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.events import OutputPrinted, RunFinished
from rockly_desktop.executor.problems import explain
from rockly_desktop.executor.runner import ProgramRunner


def run(code, language, variables=None, namespace=None, on_end=None):
    events = []
    result = ProgramRunner(code, namespace or {}, RunControl(), events.append, variables, on_end, language).run()
    return result, events


# (program, its variables as Blockly name -> Python name, English, German)
CASES = [
    ("name = 'Anna'\nage = 7\n__rockly__.block('join')\nprint(name + age)\n", {"name": "name", "age": "age"},
     "A text and a number cannot be added (“name” is 'Anna', “age” is 7); use “create text with” to join them.",
     "Ein Text und eine Zahl können nicht addiert werden („name“ ist 'Anna', „age“ ist 7); "
     "verbinde sie mit „erstelle Text aus“."),
    ("Punkte = 3\nprint(Punkte + ' points')\n", {"Punkte": "Punkte"},
     "A number and a text cannot be added (“Punkte” is 3); use “create text with” to join them.",
     "Eine Zahl und ein Text können nicht addiert werden („Punkte“ ist 3); verbinde sie mit „erstelle Text aus“."),
    ("count = None\ncount = count + 1\n", {"my count": "count"},
     "The variable “my count” has no value yet: set it before you use it.",
     "Die Variable „my count“ hat noch keinen Wert: Setze sie, bevor du sie benutzt."),
    ("things = None\nthings.append(1)\n", {"things": "things"},
     "The variable “things” has no value yet: set it before you use it.",
     "Die Variable „things“ hat noch keinen Wert: Setze sie, bevor du sie benutzt."),
    ("def nothing():\n  pass\nx = nothing() * 2\n", {"x": "x"},
     "Something here has no value (it is empty).", "Hier hat etwas keinen Wert (es ist leer)."),
    ("a = 'apple'\nb = 3\nprint(a < b)\n", {"a": "a", "b": "b"},
     "A text and a number cannot be compared with “<” (“a” is 'apple', “b” is 3).",
     "Ein Text und eine Zahl können nicht mit „<“ verglichen werden („a“ ist 'apple', „b“ ist 3)."),
    ("items = [1, 2]\nprint(items - 1)\n", {"items": "items"},
     "A list and a number cannot be used with “−” (“items” is [1, 2]).",
     "Eine Liste und eine Zahl können nicht mit „−“ gerechnet werden („items“ ist [1, 2])."),
    ("import math\nx = 'nine'\nprint(math.sqrt(x))\n", {"x": "x"},
     "This needs a number, but this is a text (“x” is 'nine').",
     "Hier wird eine Zahl gebraucht, aber das ist ein Text („x“ ist 'nine')."),
    ("n = 5\nprint(len(n))\n", {"n": "n"},
     "This needs a text or a list, but this is a number (“n” is 5).",
     "Hier wird ein Text oder eine Liste gebraucht, aber das ist eine Zahl („n“ ist 5)."),
    ("n = 5\nn.append(1)\n", {"n": "n"},
     "This needs a list, but this is a number (“n” is 5).",
     "Hier wird eine Liste gebraucht, aber das ist eine Zahl („n“ ist 5)."),
    ("scores = [4, 9]\nprint(scores[5])\n", {"scores": "scores"},
     "There is no item at that position: “scores” has only 2 items.",
     "An dieser Stelle gibt es nichts: „scores“ hat nur 2 Elemente."),
    ("scores = [4]\nprint(scores[5])\n", {"scores": "scores"},
     "There is no item at that position: “scores” has only one item.",
     "An dieser Stelle gibt es nichts: „scores“ hat nur ein Element."),
    ("scores = []\nprint(scores.pop())\n", {"scores": "scores"},
     "The list “scores” is empty.", "Die Liste „scores“ ist leer."),
    ("print('abc'[7])\n", {}, "There is no letter at that position in the text.",
     "An dieser Stelle gibt es keinen Buchstaben im Text."),
    ("print(int('abc'))\n", {}, "'abc' is not a number.", "'abc' ist keine Zahl."),
    ("import math\nprint(math.sqrt(-1))\n", {},
     "This calculation has no result (like the square root of a negative number).",
     "Diese Rechnung hat kein Ergebnis (wie die Wurzel aus einer negativen Zahl)."),
    ("x = 1\nx = x / 0\n", {}, "Dividing by zero is not possible.", "Durch null teilen geht nicht."),
    ("def f():\n  return f()\nf()\n", {}, "A function calls itself too often (endless repetition).",
     "Eine Funktion ruft sich zu oft selbst auf (endlose Wiederholung)."),
    ("def greet():\n  print(wer)\ngreet()\n", {"who": "wer"},
     "“who” is used before it was given a value.", "„who“ wird benutzt, bevor es einen Wert bekommen hat."),
    ("raise RuntimeError('internal state 0x3f broken')\n", {},
     "Something unexpected went wrong in this block (the details tell more).",
     "In diesem Block ist etwas Unerwartetes schiefgegangen (die Details sagen mehr)."),
]


@pytest.mark.parametrize(("code", "variables", "english", "german"), CASES)
def test_an_error_is_said_plainly_in_both_languages(code, variables, english, german):
    for language, expected in (("en", english), ("de", german)):
        result, _events = run(code, language, variables)
        assert result.outcome == "error"
        assert result.message == expected, language
        assert "Traceback" in result.details  # the Python stays one click away


@pytest.mark.parametrize("code", [case[0] for case in CASES])
def test_no_python_wording_reaches_the_child(code):
    for language in ("en", "de"):
        message = run(code, language, {})[0].message
        for python in ("NoneType", "concatenate", "operand", "str", "int", "instances", "Error", "not defined"):
            assert python not in message, (language, message)


def test_the_variable_is_found_inside_a_function():
    code = "def add_one(n):\n  return n + 1\nresult = add_one('x')\n"
    result, _events = run(code, "en", {"n": "n", "result": "result"})
    assert result.message == ("A text and a number cannot be added (“n” is 'x'); "
                              "use “create text with” to join them.")


def test_a_long_value_is_shortened():
    code = f"t = {'a' * 500!r}\nprint(t + 1)\n"
    message = run(code, "en", {"t": "t"})[0].message
    assert len(message) < 160 and "..." in message


def test_robot_errors_keep_the_profiles_text_inside_a_translated_frame():
    def refuse():
        raise RobotCommandError("the field linear.x needs a number, not 'fast'")

    def silent():
        raise RobotTimeout("the arm did not answer within 30 s")

    # a plain text is shown as it is (German starts the sentence after the colon with a capital)
    for language, frame, timeout, first in (
            ("en", "The robot could not do this: ", "The robot did not answer in time: ", "t"),
            ("de", "Das konnte der Roboter nicht tun: ", "Der Roboter hat nicht rechtzeitig geantwortet: ", "T")):
        result, _events = run("__rockly__.block('drive')\nrobot_drive()\n", language, namespace={"robot_drive": refuse})
        detail = first + "he field linear.x needs a number, not 'fast'"
        assert (result.block_id, result.message) == ("drive", frame + detail)
        result, _events = run("robot_arm()\n", language, namespace={"robot_arm": silent})
        assert result.message == timeout + first + "he arm did not answer within 30 s"


def test_rocklys_own_errors_are_shown_as_written():
    error = ManifestError("profile.yaml", "state", "must be a list")
    assert explain(error, "de") == str(error)


def test_a_failing_safe_stop_is_reported_in_the_runs_language():
    def broken_stop():
        raise RuntimeError("no connection")

    result, events = run("x = 1\n", "de", on_end=broken_stop)
    assert result == RunFinished("finished")
    assert OutputPrinted("Achtung: Der Roboter konnte nicht sicher angehalten werden.") in events


def test_an_unreadable_program_is_said_in_the_runs_language():
    result, _events = run("if (:\n", "de")
    assert result.outcome == "error" and result.message.startswith("Das Programm kann nicht gelesen werden: ")


def test_english_is_the_default():
    events = []
    result = ProgramRunner("x = 1 / 0\n", {}, RunControl(), events.append).run()
    assert result.message == "Dividing by zero is not possible."
