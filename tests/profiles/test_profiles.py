"""Block and toolbox files of a profile, the real HOBBIT profile, and texts per language."""
import copy
import re
import shutil

import pytest
from profile_copies import HOBBIT_DIR, SHARED_TOOLBOXES, EditableProfile, copy_profile

from rockly_desktop.core.errors import ManifestError
from rockly_desktop.profiles.i18n import is_localized, localize
from rockly_desktop.profiles.profile import load_profile


@pytest.fixture
def profile(tmp_path) -> EditableProfile:
    return copy_profile(tmp_path / "hobbit")


def load_error(profile, shared=SHARED_TOOLBOXES) -> ManifestError:
    with pytest.raises(ManifestError) as caught:
        load_profile(profile.root, shared)
    return caught.value


def assert_error(profile, file_name, field, problem_part):
    error = load_error(profile)
    assert error.path == str(profile.path(file_name))
    assert error.field == field
    assert problem_part in error.problem
    return error


# --- blocks.yaml ----------------------------------------------------------------------------


@pytest.mark.parametrize("value", [[], None, "hobbit_move", {"type": "hobbit_move"}],
                         ids=["empty list", "null", "a string", "a mapping"])
def test_blocks_must_be_a_non_empty_list(profile, value):
    profile.edit("blocks.yaml", lambda data: data.update(blocks=value))
    assert_error(profile, "blocks.yaml", "blocks", "must be a non-empty list of block definitions")


def test_blocks_key_missing_is_refused(profile):
    profile.write("blocks.yaml", {"block": []})
    assert_error(profile, "blocks.yaml", "blocks", "must be a non-empty list")


def test_block_that_is_not_a_mapping_is_named_by_position(profile):
    profile.edit("blocks.yaml", lambda data: data["blocks"].insert(2, "hobbit_fly"))
    assert_error(profile, "blocks.yaml", "blocks[2]", "must be a mapping with 'type', 'message0' and 'python'")


@pytest.mark.parametrize("change", [
    lambda raw: raw.pop("type"),
    lambda raw: raw.update(type="hobbit move"),
    lambda raw: raw.update(type="1move"),
    lambda raw: raw.update(type="hobbit-move"),
    lambda raw: raw.update(type="hobbit_move\n"),
    lambda raw: raw.update(type=7),
], ids=["missing", "space", "starts with digit", "dash", "trailing newline", "number"])
def test_missing_or_bad_block_type_is_refused(profile, change):
    profile.edit_block("hobbit_move", change)
    assert_error(profile, "blocks.yaml", "blocks[0].type", "must be a block type name (letters, digits, '_')")


def test_missing_message0_is_refused(profile):
    profile.edit_block("hobbit_turn", lambda raw: raw.pop("message0"))
    assert_error(profile, "blocks.yaml", "blocks[hobbit_turn].message0", "is missing: the text shown on the block")


@pytest.mark.parametrize("change", [
    lambda raw: raw.pop("python"),
    lambda raw: raw.update(python=""),
    lambda raw: raw.update(python={"code": "   "}),
    lambda raw: raw.update(python={"values": {"direction": {"+": "forward"}}}),
    lambda raw: raw.update(python=["robot.drive()"]),
], ids=["missing", "empty string", "blank code", "no code", "a list"])
def test_missing_python_is_refused(profile, change):
    profile.edit_block("hobbit_move", change)
    assert_error(profile, "blocks.yaml", "blocks[hobbit_move].python",
                 "is missing: the Python the block becomes ('code: ...')")


def test_unknown_python_keys_are_named(profile):
    profile.edit_block("hobbit_move", lambda raw: raw["python"].update(value={}, default={"speed": 1}))
    assert_error(profile, "blocks.yaml", "blocks[hobbit_move].python",
                 "unknown key(s) ['default', 'value'] (use code, values, defaults, handlers)")


def test_template_placeholder_naming_no_field_or_input_lists_what_there_is(profile):
    profile.edit_block("hobbit_move", lambda raw: raw["python"].update(code="robot.drive({sped}, {direction})"))
    error = assert_error(profile, "blocks.yaml", "blocks[hobbit_move].python.code",
                         "uses {sped}, but the block has no field or input named 'sped'")
    assert error.problem.endswith("(it has: ['direction', 'speed'])")


def test_template_placeholder_on_a_block_without_arguments_says_none(profile):
    profile.edit_block("hobbit_stop", lambda raw: raw.update(python="robot.stop({now})"))
    assert_error(profile, "blocks.yaml", "blocks[hobbit_stop].python.code", "(it has: none)")


@pytest.mark.parametrize("code, detail", [
    ("robot.drive({speed, {direction})", "unexpected '{' in field name"),
    ("robot.drive({speed)", "expected '}' before end of string"),
    ("robot.drive({speed}, {direction}})", "Single '}' encountered in format string"),
], ids=["unclosed before next", "unclosed at end", "stray closing"])
def test_broken_template_braces_are_explained(profile, code, detail):
    profile.edit_block("hobbit_move", lambda raw: raw["python"].update(code=code))
    error = assert_error(profile, "blocks.yaml", "blocks[hobbit_move].python.code", "the template is broken")
    assert error.problem == f"the template is broken ({detail}); write a literal brace as '{{{{' or '}}}}'"


def test_literal_braces_written_twice_are_fine(profile):
    profile.edit_block("hobbit_stop", lambda raw: raw.update(python="robot.publish('/x', 'String', {{'a': 1}})"))
    code = load_profile(profile.root, SHARED_TOOLBOXES).block("hobbit_stop").code
    assert code == "robot.publish('/x', 'String', {{'a': 1}})"


@pytest.mark.parametrize("values, name", [
    ({"speed": {"1": "one"}}, "speed"),
    ({"nothing": {"a": "b"}}, "nothing"),
    ({"direction": ["forward", "backward"]}, "direction"),
], ids=["on a value input", "on an unknown name", "not a mapping"])
def test_values_on_anything_but_a_field_are_refused(profile, values, name):
    profile.edit_block("hobbit_move", lambda raw: raw["python"].update(values=values))
    assert_error(profile, "blocks.yaml", f"blocks[hobbit_move].python.values.{name}",
                 "must map the values of a field of this block")


@pytest.mark.parametrize("values", [["direction"], None, "direction"], ids=["list", "null", "string"])
def test_values_that_are_not_a_mapping_are_refused(profile, values):
    profile.edit_block("hobbit_move", lambda raw: raw["python"].update(values=values))
    assert_error(profile, "blocks.yaml", "blocks[hobbit_move].python.values", "must map field names")


@pytest.mark.parametrize("defaults, name", [
    ({"direction": "+"}, "direction"),
    ({"distance": 1}, "distance"),
], ids=["on a field", "on an unknown name"])
def test_defaults_on_anything_but_a_value_input_are_refused(profile, defaults, name):
    profile.edit_block("hobbit_move", lambda raw: raw["python"].update(defaults=defaults))
    assert_error(profile, "blocks.yaml", f"blocks[hobbit_move].python.defaults.{name}",
                 "names no value input of this block")


@pytest.mark.parametrize("defaults", [["speed"], None, 0], ids=["list", "null", "number"])
def test_defaults_that_are_not_a_mapping_are_refused(profile, defaults):
    profile.edit_block("hobbit_move", lambda raw: raw["python"].update(defaults=defaults))
    assert_error(profile, "blocks.yaml", "blocks[hobbit_move].python.defaults", "must map value input names")


def test_defaults_on_a_statement_input_are_refused(profile):
    def add_statement(raw):
        raw["message0"] = "drive %1 %2 then %3"
        raw["args0"].append({"type": "input_statement", "name": "then"})
        raw["python"]["defaults"] = {"then": "pass"}
    profile.edit_block("hobbit_move", add_statement)
    assert_error(profile, "blocks.yaml", "blocks[hobbit_move].python.defaults.then", "names no value input")


def typed(raw, dropdown="message_type", mutator="rockly_typed_fields"):
    raw["message0"] = "publish %1 as %2"
    raw["args0"] = [{"type": "input_value", "name": "topic"},
                    {"type": "field_dropdown", "name": dropdown, "options": [["std_msgs/String", "std_msgs/String"]]}]
    raw["mutator"] = mutator
    raw["python"] = {"code": f"robot.publish_any({{topic}}, {{{dropdown}}}, {{fields}})"}


@pytest.mark.parametrize("dropdown", ["message_type", "service_type", "action_type"])
def test_a_typed_fields_block_gets_the_fields_slot(profile, dropdown):
    profile.edit_block("hobbit_move", lambda raw: typed(raw, dropdown))
    spec = load_profile(profile.root, SHARED_TOOLBOXES).block("hobbit_move")
    assert spec.slots == {"topic": "value", dropdown: "field", "fields": "typed_fields"}


def test_an_unknown_mutator_is_refused_naming_the_one_there_is(profile):
    profile.edit_block("hobbit_move", lambda raw: typed(raw, mutator="my_mutator"))
    assert_error(profile, "blocks.yaml", "blocks[hobbit_move].mutator",
                 "'my_mutator' is not a mutator Rockly's editor has (it has: rockly_typed_fields)")


def test_a_typed_fields_block_needs_its_type_dropdown(profile):
    profile.edit_block("hobbit_move", lambda raw: typed(raw, dropdown="kind"))
    assert_error(profile, "blocks.yaml", "blocks[hobbit_move].mutator",
                 "needs exactly one field_dropdown named one of ['message_type', 'service_type', 'action_type']")


def test_a_typed_fields_block_may_not_have_its_own_fields_input(profile):
    def with_fields_input(raw):
        typed(raw)
        raw["message0"] += " %3"
        raw["args0"].append({"type": "input_value", "name": "fields"})
    profile.edit_block("hobbit_move", with_fields_input)
    assert_error(profile, "blocks.yaml", "blocks[hobbit_move].mutator", "adds the slot 'fields'")


def with_handler(raw, handlers, variable_type="field_variable"):
    raw["message0"] = "drive %1 %2 seeing %3 do %4"
    raw["args0"] += [{"type": variable_type, "name": "seen", "variable": "seen"},
                     {"type": "input_statement", "name": "meanwhile"}]
    raw["python"]["code"] = "robot.drive({speed}, {direction}, {meanwhile})"
    raw["python"]["handlers"] = handlers


def test_a_handler_names_a_statement_input_and_a_variable_field(profile):
    profile.edit_block("hobbit_move", lambda raw: with_handler(raw, {"meanwhile": "seen"}))
    assert load_profile(profile.root, SHARED_TOOLBOXES).block("hobbit_move").handlers == {"meanwhile": "seen"}


@pytest.mark.parametrize("handlers, variable_type, field, problem", [
    ({"speed": "seen"}, "field_variable", "python.handlers.speed", "names no statement input"),
    ({"meanwhile": "seen"}, "field_input", "python.handlers.meanwhile", "'seen' is no field_variable of this block"),
    ({"meanwhile": "nothing"}, "field_variable", "python.handlers.meanwhile", "'nothing' is no field_variable"),
    (["meanwhile"], "field_variable", "python.handlers", "must map statement inputs to a variable field"),
], ids=["value input", "text field", "missing field", "list"])
def test_broken_handlers_are_explained(profile, handlers, variable_type, field, problem):
    profile.edit_block("hobbit_move", lambda raw: with_handler(raw, handlers, variable_type))
    assert_error(profile, "blocks.yaml", f"blocks[hobbit_move].{field}", problem)


def test_duplicate_block_type_is_refused(profile):
    profile.edit("blocks.yaml", lambda data: data["blocks"].append(copy.deepcopy(data["blocks"][0])))
    assert_error(profile, "blocks.yaml", "blocks[hobbit_move]", "is defined twice")


# --- toolbox.yaml ---------------------------------------------------------------------------


def test_unknown_shared_category_lists_the_available_ones(profile):
    profile.edit("toolbox.yaml", lambda data: data["categories"].append({"shared": "robots"}))
    count = len(profile.read("toolbox.yaml")["categories"])
    assert_error(profile, "toolbox.yaml", f"categories[{count - 1}].shared",
                 "no shared category 'robots' (there are: functions, lists, logic, loops, math, ros, text, variables)")


@pytest.mark.parametrize("entry", ["hobbit_fly", {"type": "hobbit_fly", "inputs": {}}], ids=["by name", "as mapping"])
def test_profile_category_listing_an_undefined_block_is_refused(profile, entry):
    profile.edit("toolbox.yaml", lambda data: data["categories"][0]["blocks"].append(entry))
    drive_blocks = len(profile.read("toolbox.yaml")["categories"][0]["blocks"])
    assert_error(profile, "toolbox.yaml", f"categories[0].blocks[{drive_blocks - 1}]",
                 "block 'hobbit_fly' is not defined in the profile's block file")


def test_block_removed_from_blocks_file_but_left_in_toolbox_is_caught(profile):
    profile.edit("blocks.yaml",
                 lambda data: data.update(blocks=[raw for raw in data["blocks"] if raw["type"] != "hobbit_emo"]))
    assert_error(profile, "toolbox.yaml", "categories[1].blocks[1]", "block 'hobbit_emo' is not defined")


def test_category_without_name_is_refused(profile):
    profile.edit("toolbox.yaml", lambda data: data["categories"][1].pop("name"))
    assert_error(profile, "toolbox.yaml", "categories[1]", "a category needs a 'name'")


def test_category_that_is_not_a_mapping_is_refused(profile):
    profile.edit("toolbox.yaml", lambda data: data["categories"].insert(0, "Drive"))
    assert_error(profile, "toolbox.yaml", "categories[0]", "a category needs a 'name'")


@pytest.mark.parametrize("blocks", [[], None], ids=["empty", "missing"])
def test_category_without_blocks_is_refused(profile, blocks):
    profile.edit("toolbox.yaml", lambda data: data["categories"][2].update(blocks=blocks))
    assert_error(profile, "toolbox.yaml", "categories[2].blocks", "must list the blocks of the category")


def test_block_entry_that_is_neither_name_nor_mapping_with_type_is_refused(profile):
    profile.edit("toolbox.yaml", lambda data: data["categories"][0]["blocks"].insert(1, {"kind": "block"}))
    assert_error(profile, "toolbox.yaml", "categories[0].blocks[1]", "must be a block type, or a mapping with 'type'")


@pytest.mark.parametrize("value", [[], None, {"name": "Drive"}], ids=["empty", "null", "mapping"])
def test_toolbox_needs_a_non_empty_category_list(profile, value):
    profile.write("toolbox.yaml", {"categories": value})
    assert_error(profile, "toolbox.yaml", "categories", "must be a non-empty list of categories")


def test_broken_shared_category_file_is_named(profile, tmp_path):
    shared = tmp_path / "toolboxes"
    shutil.copytree(SHARED_TOOLBOXES, shared)
    (shared / "logic.yaml").write_text("colour: '#5b80a5'\nblocks: [controls_if]\n", encoding="utf-8")
    error = load_error(profile, shared)
    assert error.path == str(shared / "logic.yaml")
    assert error.field == "category"
    assert error.problem == "a category needs a 'name'"


# --- YAML syntax in the block and toolbox files ------------------------------------------------


@pytest.mark.parametrize("file_name", ["blocks.yaml", "toolbox.yaml"])
def test_invalid_yaml_in_block_or_toolbox_file_names_the_line(profile, file_name):
    lines = profile.path(file_name).read_text(encoding="utf-8").splitlines()
    first_key = next(number for number, line in enumerate(lines, 1) if re.match(r"^\w+:", line))
    lines.insert(first_key, "  - [unclosed, list")
    lines.insert(first_key + 1, "  bad: here")
    profile.write_text(file_name, "\n".join(lines) + "\n")
    error = load_error(profile)
    assert error.path == str(profile.path(file_name))
    assert error.field is None
    assert re.fullmatch(r"this is not valid YAML at line \d+, column \d+: .+", error.problem)
    line = int(re.search(r"line (\d+)", error.problem).group(1))
    assert line in (first_key + 1, first_key + 2)


@pytest.mark.parametrize("file_name", ["blocks.yaml", "toolbox.yaml"])
@pytest.mark.parametrize("text", ["- hobbit_move\n", "", "just words\n"], ids=["list", "empty", "scalar"])
def test_block_or_toolbox_file_that_is_not_a_mapping_is_refused(profile, file_name, text):
    profile.write_text(file_name, text)
    error = load_error(profile)
    assert error.path == str(profile.path(file_name))
    assert error.field is None
    assert error.problem == "the file must contain a mapping (key: value lines) at the top level"


# --- the real HOBBIT profile -------------------------------------------------------------------

FIRST_ROCKLY_TYPES = {
    "hobbit_move", "hobbit_turn", "hobbit_head", "hobbit_emo", "hobbit_arm_move", "hobbit_arm_turntable",
    "hobbit_arm_gripper", "hobbit_navigation_test", "hobbit_show_info", "hobbit_show_info_confirm",
    "hobbit_yes_no", "hobbit_user_input", "hobbit_call_service", "ROS_publisher",
}


@pytest.fixture(scope="module")
def hobbit():
    return load_profile(HOBBIT_DIR, SHARED_TOOLBOXES, "built-in")


def args_of(definition) -> list:
    """Every field/input argument of a block definition, in order (args0, args1, ...)."""
    return [arg for key in sorted(k for k in definition if re.fullmatch(r"args\d+", k)) for arg in definition[key]]


def arg(profile, block_type, name) -> dict:
    matches = [item for item in args_of(profile.block(block_type).definition) if item.get("name") == name]
    assert len(matches) == 1, f"{block_type} has {len(matches)} arguments named {name}"
    return matches[0]


def dropdown_values(profile, block_type, name) -> list:
    field = arg(profile, block_type, name)
    assert field["type"] == "field_dropdown"
    return [option[1] for option in field["options"]]


def assert_value_input(profile, block_type, name):
    assert arg(profile, block_type, name)["type"] == "input_value"


def test_real_hobbit_profile_loads_without_errors(hobbit):
    assert hobbit.id == "hobbit"
    assert hobbit.version == "1.0.0"
    assert hobbit.display_name("en") == "HOBBIT"
    assert hobbit.display_name("de") == "HOBBIT"
    assert hobbit.manifest["languages"] == ["en", "de"]
    assert hobbit.source == "built-in"


def test_hobbit_keeps_every_first_rockly_block_type(hobbit):
    assert FIRST_ROCKLY_TYPES <= hobbit.block_types


def test_hobbit_move_and_turn_have_first_rockly_fields(hobbit):
    assert_value_input(hobbit, "hobbit_move", "speed")
    assert dropdown_values(hobbit, "hobbit_move", "direction") == ["+", "-"]
    assert_value_input(hobbit, "hobbit_turn", "angle")
    assert dropdown_values(hobbit, "hobbit_turn", "direction") == ["+", "-"]


def test_hobbit_head_has_exactly_the_thirteen_first_rockly_positions(hobbit):
    values = dropdown_values(hobbit, "hobbit_head", "head_position")
    expected = ["center_center", "up_center", "down_center", "center_right", "center_left", "up_right", "up_left",
                "down_right", "down_left", "littledown_center", "to_grasp", "to_turntable", "search_table"]
    assert len(values) == 13
    assert sorted(values) == sorted(expected)


def test_hobbit_emo_has_exactly_the_first_rockly_emotions(hobbit):
    values = dropdown_values(hobbit, "hobbit_emo", "emotion")
    expected = ["HAPPY", "VHAPPY", "LTIRED", "VTIRED", "CONCERNED", "SAD", "WONDERING", "NEUTRAL", "SLEEPING"]
    assert len(values) == len(expected)
    assert sorted(values) == sorted(expected)


@pytest.mark.parametrize("block_type, expected", [
    ("hobbit_arm_move", ["MoveToCandle", "MoveToHome", "MoveToPreGraspFloor", "MoveToPreGraspTable", "MoveToTray"]),
    ("hobbit_arm_turntable", ["MoveToLearning", "StoreTurntable", "TurnTurntableCW", "TurnTurntableCCW"]),
    ("hobbit_arm_gripper", ["OpenGripper", "CloseGripper"]),
])
def test_hobbit_arm_blocks_have_the_first_rockly_movements(hobbit, block_type, expected):
    values = dropdown_values(hobbit, block_type, "movement")
    assert len(values) == len(expected)
    assert sorted(values) == sorted(expected)


def test_hobbit_navigation_test_has_position_and_quaternion_inputs(hobbit):
    for name in ("pos_x", "pos_y", "pos_z", "quat_x", "quat_y", "quat_z", "quat_w"):
        assert_value_input(hobbit, "hobbit_navigation_test", name)


def test_hobbit_yes_no_is_a_boolean_question(hobbit):
    assert dropdown_values(hobbit, "hobbit_yes_no", "yes_no") == ["D_YES", "D_NO"]
    assert_value_input(hobbit, "hobbit_yes_no", "text")
    assert hobbit.block("hobbit_yes_no").definition["output"] == "Boolean"
    assert hobbit.block("hobbit_yes_no").is_expression


def test_hobbit_user_input_gives_a_string(hobbit):
    assert_value_input(hobbit, "hobbit_user_input", "text")
    assert hobbit.block("hobbit_user_input").definition["output"] == "String"


def test_ros_publisher_has_the_first_rockly_fields(hobbit):
    assert_value_input(hobbit, "ROS_publisher", "message")
    assert dropdown_values(hobbit, "ROS_publisher", "message_type") == ["String", "Bool", "Float64", "Int64", "UInt64"]
    assert_value_input(hobbit, "ROS_publisher", "topic_name")


def test_hobbit_call_service_has_the_first_rockly_fields(hobbit):
    assert_value_input(hobbit, "hobbit_call_service", "service_name")
    assert_value_input(hobbit, "hobbit_call_service", "service_type")
    assert dropdown_values(hobbit, "hobbit_call_service", "has_parameters") == ["params", "no_params"]
    assert_value_input(hobbit, "hobbit_call_service", "service_parameters")


def test_statement_blocks_stack_and_expression_blocks_plug_in(hobbit):
    for spec in hobbit.blocks:
        if spec.is_expression:
            assert "previousStatement" not in spec.definition, spec.type
        else:
            assert "previousStatement" in spec.definition and "nextStatement" in spec.definition, spec.type


def test_slots_name_each_field_and_input_with_its_kind(hobbit):
    assert hobbit.block("hobbit_move").slots == {"direction": "field", "speed": "value"}
    assert hobbit.block("hobbit_stop").slots == {}


def test_message_placeholders_match_the_arguments_in_every_language(hobbit):
    for spec in hobbit.blocks:
        expected = {str(n) for n in range(1, len(spec.definition.get("args0", [])) + 1)}
        for language in ("en", "de"):
            text = localize(spec.definition["message0"], language)
            assert set(re.findall(r"%(\d+)", text)) == expected, (spec.type, language, text)


def test_every_block_has_german_texts(hobbit):
    for spec in hobbit.blocks:
        message = spec.definition["message0"]
        assert is_localized(message) and "de" in message, spec.type
        assert localize(message, "de") != localize(message, "en"), spec.type
        tooltip = spec.definition["tooltip"]
        assert is_localized(tooltip) and tooltip.get("de"), spec.type


# ROS type names are the same words in every language.
UNTRANSLATED_DROPDOWNS = {("ROS_publisher", "message_type"), ("ros_publish_value", "message_type")}  # ROS type names


def test_every_dropdown_label_has_german(hobbit):
    checked = 0
    for spec in hobbit.blocks:
        for item in args_of(spec.definition):
            if item.get("type") != "field_dropdown" or (spec.type, item["name"]) in UNTRANSLATED_DROPDOWNS:
                continue
            for label, value in item["options"]:
                assert is_localized(label) and isinstance(label.get("de"), str) and label["de"], (spec.type, value)
                checked += 1
    assert checked >= 40, "the loop must have looked at the dropdowns"


def test_untranslated_dropdown_labels_are_the_values_themselves(hobbit):
    for block_type, name in UNTRANSLATED_DROPDOWNS:
        assert all(label == value for label, value in arg(hobbit, block_type, name)["options"])


def test_every_field_value_has_a_python_mapping_where_the_block_maps_values(hobbit):
    for spec in hobbit.blocks:
        for name, mapping in spec.values.items():
            assert set(dropdown_values(hobbit, spec.type, name)) == set(mapping), spec.type


def test_every_hobbit_block_is_reachable_from_the_toolbox(hobbit):
    listed = {entry["type"] for category in hobbit.toolbox_categories for entry in category.get("contents", [])}
    assert hobbit.block_types <= listed


def test_toolbox_shadows_fill_real_value_inputs(hobbit):
    for category in hobbit.toolbox_categories:
        for entry in category.get("contents", []):
            if entry["type"] in hobbit.block_types:
                for name in entry.get("inputs", {}):
                    assert hobbit.block(entry["type"]).slots.get(name) == "value", (entry["type"], name)


def test_toolbox_names_are_translated_and_shared_categories_resolved(hobbit):
    names = [localize(category["name"], "de") for category in hobbit.toolbox_categories]
    assert names == ["Fahren", "Kopf", "Arm", "Tablet", "Sensoren", "Zeit", "Profis", "ROS",
                     "Logik", "Schleifen", "Mathematik", "Text", "Listen", "Variablen", "Funktionen"]
    by_name = {localize(category["name"], "en"): category for category in hobbit.toolbox_categories}
    assert {"kind": "block", "type": "controls_if"} in by_name["Logic"]["contents"]
    assert by_name["Variables"]["custom"] == "VARIABLE"
    assert by_name["Functions"]["custom"] == "PROCEDURE"


def test_editor_config_in_german_has_german_block_texts_and_python_templates(hobbit):
    config = hobbit.editor_config("de")
    assert config["profile"] == "hobbit"
    assert [block["definition"]["type"] for block in config["blocks"]] == [
        spec.type for spec in hobbit.blocks + hobbit.shared_blocks]
    head = next(block for block in config["blocks"] if block["definition"]["type"] == "hobbit_head")
    assert head["definition"]["message0"] == "schau %1"
    assert head["definition"]["args0"][0]["options"][0] == ["geradeaus", "center_center"]
    assert head["python"] == {"code": "robot.look({head_position})", "values": {}, "defaults": {},
                              "slots": {"head_position": "field"}, "handlers": {}, "expression": False}
    assert config["toolbox"]["kind"] == "categoryToolbox"
    assert config["types"]["actions"]["hobbit_msgs/ArmServerAction"] == [["command.data", "String", ""],
                                                                          ["velocity", "Number", 0]]
    assert config["toolbox"]["contents"][0]["name"] == "Fahren"


def toolbox_shadow_texts(config, category_name):
    """The TEXT of every text shadow in one category of an editor config's toolbox."""
    category = next(item for item in config["toolbox"]["contents"] if item["name"] == category_name)
    return [connection["shadow"]["fields"]["TEXT"] for entry in category.get("contents", [])
            for connection in entry.get("inputs", {}).values() if connection["shadow"]["type"] == "text"]


def test_toolbox_default_texts_are_in_the_editor_language(hobbit):
    assert toolbox_shadow_texts(hobbit.editor_config("en"), "Tablet") == [
        "Hello!", "Ready?", "Shall we play?", "What is your name?"]
    assert toolbox_shadow_texts(hobbit.editor_config("de"), "Tablet") == [
        "Hallo!", "Bereit?", "Wollen wir spielen?", "Wie heißt du?"]
    assert toolbox_shadow_texts(hobbit.editor_config("de"), "Text") == ["Hallo"]  # a shared category too
    assert toolbox_shadow_texts(hobbit.editor_config("fr"), "Tablet")[0] == "Hello!"


def test_every_default_text_in_hobbits_own_categories_has_german(hobbit):
    """Words a child reads are translated; ROS names (Expert, ROS) are the same in every language."""
    checked = 0
    for category in hobbit.toolbox_categories:
        if localize(category["name"], "en") in ("Expert", "ROS") or "contents" not in category:
            continue
        for entry in category["contents"]:
            for name, connection in entry.get("inputs", {}).items():
                if connection["shadow"]["type"] == "text":
                    value = connection["shadow"]["fields"]["TEXT"]
                    assert is_localized(value) and value.get("de"), (entry["type"], name)
                    checked += 1
    assert checked >= 4


def test_any_toolbox_field_value_may_be_written_per_language(profile):
    entry = {"type": "hobbit_show_info",
             "inputs": {"text": {"shadow": {"type": "text", "fields": {"TEXT": {"en": "Hi", "de": "Hallo"}}}}}}
    profile.edit("toolbox.yaml", lambda data: data["categories"][0]["blocks"].append(entry))
    loaded = load_profile(profile.root, SHARED_TOOLBOXES)
    drive = {language: loaded.editor_config(language)["toolbox"]["contents"][0]["contents"][-1]
             for language in ("en", "de")}
    assert drive["en"]["inputs"]["text"]["shadow"]["fields"] == {"TEXT": "Hi"}
    assert drive["de"]["inputs"]["text"]["shadow"]["fields"] == {"TEXT": "Hallo"}


def test_editor_config_in_an_unknown_language_falls_back_to_english(hobbit):
    config = hobbit.editor_config("fr")
    move = next(block for block in config["blocks"] if block["definition"]["type"] == "hobbit_move")
    assert move["definition"]["message0"] == "drive %1 %2 metres"
    assert config["toolbox"]["contents"][0]["name"] == "Drive"


def test_legacy_fields_of_hobbit_map_the_old_gripper_field(hobbit):
    assert hobbit.legacy_fields == {"hobbit_arm_gripper": {"gripper_position": {
        "field": "movement", "values": {"open": "OpenGripper", "close": "CloseGripper"}}}}
    new_values = set(dropdown_values(hobbit, "hobbit_arm_gripper", "movement"))
    assert set(hobbit.legacy_fields["hobbit_arm_gripper"]["gripper_position"]["values"].values()) == new_values


# --- texts per language ----------------------------------------------------------------------


@pytest.mark.parametrize("value, expected", [
    ({"en": "drive", "de": "fahre"}, True),
    ({"en": "drive"}, True),
    ({"en": "drive", "fr": "conduis"}, True),
    ({"de": "fahre"}, False),
    ({"en": "drive", "DE": "fahre"}, False),
    ({"en": "drive", "deu": "fahre"}, False),
    ({"en": "drive", 1: "x"}, False),
    ({"type": "field_dropdown", "name": "x"}, False),
    ({}, False),
    ("drive", False),
    (["en", "de"], False),
    (None, False),
])
def test_is_localized_recognises_one_text_per_language(value, expected):
    assert is_localized(value) is expected


def test_localize_picks_the_language_and_falls_back_to_english():
    text = {"en": "drive", "de": "fahre"}
    assert localize(text, "de") == "fahre"
    assert localize(text, "en") == "drive"
    assert localize(text, "fr") == "drive"
    assert localize({"en": "drive", "de": None}, "de") == "drive"


def test_localize_resolves_texts_anywhere_inside_a_definition_without_changing_it():
    definition = {"type": "hobbit_emo", "message0": {"en": "feel %1", "de": "fühle %1"}, "colour": "#9a5cc6",
                  "args0": [{"type": "field_dropdown", "name": "emotion",
                             "options": [[{"en": "happy", "de": "fröhlich"}, "HAPPY"], ["SAD", "SAD"]]}],
                  "previousStatement": None, "extra": 3}
    original = copy.deepcopy(definition)

    german = localize(definition, "de")

    assert german == {"type": "hobbit_emo", "message0": "fühle %1", "colour": "#9a5cc6",
                      "args0": [{"type": "field_dropdown", "name": "emotion",
                                 "options": [["fröhlich", "HAPPY"], ["SAD", "SAD"]]}],
                      "previousStatement": None, "extra": 3}
    assert definition == original


@pytest.mark.parametrize("template", ["robot.drive({speed!r})", "robot.drive({speed:>5})", "robot.drive({speed.real})"])
def test_templates_accept_only_plain_placeholders(profile, template):
    profile.edit_block("hobbit_move", lambda raw: raw["python"].update(code=template))
    assert_error(profile, "blocks.yaml", "blocks[hobbit_move].python.code", "placeholders are plain names")


FRENCH_PO = '''msgid "drive %1 %2 metres"
msgstr "avance %1 %2 mètres"

msgid "Drive"
msgstr "Rouler"

#, fuzzy
msgid "HOBBIT drives straight ahead or back by this many metres."
msgstr "une ancienne traduction"
'''


def test_a_third_language_for_a_profile_is_one_file_in_its_catalogue(profile):
    (profile.root / "locale").mkdir(exist_ok=True)
    profile.write_text("locale/fr.po", FRENCH_PO)
    loaded = load_profile(profile.root, SHARED_TOOLBOXES)
    config = loaded.editor_config("fr")
    drive = next(block["definition"] for block in config["blocks"] if block["definition"]["type"] == "hobbit_move")
    assert drive["message0"] == "avance %1 %2 mètres"
    assert drive["tooltip"] == "HOBBIT drives straight ahead or back by this many metres."   # fuzzy: English
    assert config["toolbox"]["contents"][0]["name"] == "Rouler"
    assert loaded.editor_config("de")["toolbox"]["contents"][0]["name"] == "Fahren"     # the YAML's own German
