"""Whatever text a person or a file gives (a file name, a profile's id and version, a variable, a block id,
a made block's sentence, tooltip, interface and values) reaches generated Python only quoted: random
text pushed through the plain export, the standalone export (as the agent reads it back) and a made
block's template compiles to exactly the statements Rockly writes, never one more (issue 30)."""
import ast
from types import SimpleNamespace

from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from rockly_desktop.core.export import python_module_text
from rockly_desktop.core.python_syntax import parse_python
from rockly_desktop.profiles.packs.generate import block_definition, python_preview
from rockly_desktop.profiles.packs.spec import BlockInput, MadeBlock
from rockly_desktop.profiles.packs.template_check import check_template
from rockly_desktop.robot.wrappers.limits import Limits
from rockly_desktop.runtime.agent.library import standalone_program
from rockly_desktop.runtime.standalone_file import standalone_text

ANY_TEXT = st.text(st.characters(codec=None, exclude_categories=()), max_size=40)
ESCAPE = "x\nimport os; os.system('touch pwned')\n#"
RUN_CODE = "__rockly__.block('a')\nrobot.say('hi')\n"


def top_level(text: str) -> list:
    return [type(node).__name__ for node in parse_python(text).body]


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(source=ANY_TEXT, profile_id=ANY_TEXT)
@example(source=f"{ESCAPE}.rockly", profile_id=ESCAPE)
@example(source="a\rb\x00c\u2028d\ud800", profile_id="\x0c\x0b")
def test_the_plain_export_keeps_any_file_and_profile_name_in_its_comment(source, profile_id):
    text = python_module_text("pass\n", profile_id, source)
    compile(text, "export.py", "exec")
    assert top_level(text) == ["Pass"]


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(source=ANY_TEXT, profile_id=ANY_TEXT, version=ANY_TEXT, names=st.dictionaries(ANY_TEXT, ANY_TEXT, max_size=3),
       language=st.sampled_from(["en", "de"]))
@example(source=f"{ESCAPE}.rockly", profile_id="hobbit", version="1.0.0", names={ESCAPE: ESCAPE}, language="en")
def test_the_standalone_export_holds_any_name_as_data_and_the_agent_reads_it_back(source, profile_id, version,
                                                                                 names, language):
    profile = SimpleNamespace(id=profile_id, version=version)
    text = standalone_text(source, profile, {"code": RUN_CODE, "variables": names}, names, Limits(), language)
    compile(text, "OUT.py", "exec")
    assert top_level(text) == ["Import", "Assign", "Assign", "If"]
    program, run_code = standalone_program(text)
    assert (program["source"], program["profile"], program["variables"], program["blocks"], run_code) == (
        source, {"id": profile_id, "version": version}, names, names, RUN_CODE)


SAFE_TEXT = st.text(st.characters(codec="utf-8"), max_size=30)


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(sentence=SAFE_TEXT, tooltip=SAFE_TEXT, interface=SAFE_TEXT, fixed=SAFE_TEXT, default=SAFE_TEXT,
       result=st.text(st.characters(codec="utf-8"), min_size=1, max_size=30))
@example(sentence=ESCAPE, tooltip=ESCAPE, interface="')\nimport os\n('", fixed="{x}}{{", default='"""',
         result="'+__import__('os').getcwd()+'")
def test_a_made_blocks_texts_stay_quoted_in_its_template(sentence, tooltip, interface, fixed, default, result):
    block = MadeBlock("made_say", "call_service", interface, "hobbit_msgs/Request",
                      inputs=(BlockInput("words", "text", "requestText", default=default),),
                      fixed={"sessionID": fixed}, sentence={"en": sentence + " %1"}, category={"en": "Made"},
                      colour="#4c97ff", tooltip={"en": tooltip}, result=result)
    python = block_definition(block)["python"]
    check_template(python["code"], {"words": "value"})
    preview = python_preview(block)
    call = parse_python(preview, mode="eval").body
    assert ast.unparse(call.func) == "ros.field"
    assert [ast.literal_eval(argument) for argument in call.args[0].args[:2]] == [interface, "hobbit_msgs/Request"]
    assert ast.literal_eval(call.args[1]) == result
