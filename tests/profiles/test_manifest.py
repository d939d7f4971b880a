"""profile.yaml validation: each problem gives a ManifestError naming the file, the field and what is wrong."""
import os
import re

import pytest
from profile_copies import SHARED_TOOLBOXES, EditableProfile, copy_profile

from rockly_desktop.core.errors import ManifestError
from rockly_desktop.profiles.manifest import MANIFEST_FIELDS, read_manifest
from rockly_desktop.profiles.profile import load_profile


@pytest.fixture
def profile(tmp_path) -> EditableProfile:
    return copy_profile(tmp_path / "hobbit")


def set_field(profile, name, value):
    return profile.edit("profile.yaml", lambda data: data.update({name: value}))


def load_error(profile) -> ManifestError:
    """Load the profile, which must fail; return the error."""
    with pytest.raises(ManifestError) as caught:
        load_profile(profile.root, SHARED_TOOLBOXES)
    return caught.value


def assert_manifest_error(profile, field, problem_part):
    error = load_error(profile)
    assert error.path == str(profile.path("profile.yaml"))
    assert error.field == field
    assert problem_part in error.problem
    assert str(error) == f"{error.path}: {field}: {error.problem}"
    return error


def test_unchanged_copy_is_valid(profile):
    manifest = read_manifest(profile.root)
    assert manifest["id"] == "hobbit"
    assert load_profile(profile.root, SHARED_TOOLBOXES).id == "hobbit"


def test_unknown_field_is_named_with_the_known_ones(profile):
    set_field(profile, "translations", {"de": "x"})
    error = assert_manifest_error(profile, "translations", "unknown field (known fields: schema, id, name, version")
    assert "legacy_fields" in error.problem


@pytest.mark.parametrize("name", [spec.name for spec in MANIFEST_FIELDS if spec.required])
def test_each_missing_required_field_is_named_with_its_meaning(profile, name):
    profile.edit("profile.yaml", lambda data: data.pop(name))
    description = next(spec.description for spec in MANIFEST_FIELDS if spec.name == name)
    assert_manifest_error(profile, name, f"is missing: {description}")


def test_required_fields_are_the_documented_ones():
    required = [spec.name for spec in MANIFEST_FIELDS if spec.required]
    assert required == ["schema", "id", "name", "version", "blocks", "toolbox", "api"]


@pytest.mark.parametrize("value", [2, 0, "1", None, True, [1]])
def test_wrong_schema_is_refused(profile, value):
    set_field(profile, "schema", value)
    assert_manifest_error(profile, "schema", f"must be 1 (this Rockly does not read schema {value!r})")


@pytest.mark.parametrize("value", ["Hobbit", "1hobbit", "ho-bit", "ho bit", "_hobbit", "", "a" * 41, 7, None,
                                   "hobbit\n", "höbbit"])
def test_bad_id_is_refused(profile, value):
    set_field(profile, "id", value)
    assert_manifest_error(profile, "id",
                          "must be lower-case letters, digits and '_', starting with a letter (at most 40)")


@pytest.mark.parametrize("value", ["r2d2", "my_robot_2", "a" * 40])
def test_good_ids_are_accepted(profile, value):
    set_field(profile, "id", value)
    assert load_profile(profile.root, SHARED_TOOLBOXES).id == value


@pytest.mark.parametrize("value", [1.0, 1, "v1", "1.0 beta", "1.0-", "", "one", "1.0\n", None])
def test_bad_version_is_refused_with_a_quoting_hint(profile, value):
    set_field(profile, "version", value)
    assert_manifest_error(profile, "version", "must be a version text like '1.0.0' (quote it in YAML)")


@pytest.mark.parametrize("value", ["1", "1.2", "1.2.3", "1.2.3-beta.1", "2.0.0.dev1"])
def test_good_versions_are_accepted(profile, value):
    set_field(profile, "version", value)
    assert load_profile(profile.root, SHARED_TOOLBOXES).version == value


@pytest.mark.parametrize("field", ["name", "description"])
@pytest.mark.parametrize("value",
                         ["", "   ", 5, {"de": "Nur Deutsch"}, {"en": "", "de": "x"}, {"en": "x", "de": 3}, []],
                         ids=["empty", "blank", "number", "no english", "empty english", "non-text german", "list"])
def test_bad_text_is_refused(profile, field, value):
    set_field(profile, field, value)
    assert_manifest_error(profile, field,
                          "must be a non-empty text, or one text per language with English ('en') present")


@pytest.mark.parametrize("value", [["de", "en"], [], "en", ["de"]],
                         ids=["german first", "empty", "not a list", "no english"])
def test_languages_must_start_with_english(profile, value):
    set_field(profile, "languages", value)
    assert_manifest_error(profile, "languages", "must be a list of language codes starting with 'en'")


def test_unsupported_language_is_named(profile):
    set_field(profile, "languages", ["en", "de", "fr"])
    assert_manifest_error(profile, "languages", "unsupported language(s) ['fr']; Rockly speaks ['en', 'de']")


@pytest.mark.parametrize("field", ["blocks", "toolbox"])
def test_file_field_naming_a_missing_file_is_refused(profile, field):
    set_field(profile, field, "nothing.yaml")
    assert_manifest_error(profile, field, "names 'nothing.yaml', which does not exist in the profile folder")


@pytest.mark.parametrize("field", ["blocks", "toolbox"])
def test_file_field_naming_a_folder_is_refused(profile, field):
    set_field(profile, field, "msg")
    assert_manifest_error(profile, field, "names 'msg', which does not exist in the profile folder")


def test_deleted_blocks_file_is_reported_against_the_manifest_field(profile):
    profile.path("blocks.yaml").unlink()
    assert_manifest_error(profile, "blocks", "names 'blocks.yaml', which does not exist")


@pytest.mark.parametrize("field", ["blocks", "toolbox"])
def test_file_field_escaping_the_profile_folder_is_refused(profile, tmp_path, field):
    (tmp_path / "outside.yaml").write_text("blocks: []\n", encoding="utf-8")
    set_field(profile, field, "../outside.yaml")
    assert_manifest_error(profile, field, "must stay inside the profile folder")


def test_absolute_path_outside_the_profile_folder_is_refused(profile, tmp_path):
    outside = tmp_path / "outside.yaml"
    outside.write_text("blocks: []\n", encoding="utf-8")
    set_field(profile, "blocks", str(outside))
    assert_manifest_error(profile, "blocks", "must stay inside the profile folder")


def test_symlink_leading_out_of_the_profile_folder_is_refused(profile, tmp_path):
    outside = tmp_path / "elsewhere"
    outside.mkdir()
    (outside / "blocks.yaml").write_text("blocks: []\n", encoding="utf-8")
    os.symlink(outside, profile.path("linked"))
    set_field(profile, "blocks", "linked/blocks.yaml")
    assert_manifest_error(profile, "blocks", "must stay inside the profile folder")


@pytest.mark.parametrize("value", ["", 5, None], ids=["empty", "number", "null"])
def test_file_field_that_is_no_path_is_refused(profile, value):
    set_field(profile, "toolbox", value)
    assert_manifest_error(profile, "toolbox", "must be a path relative to the profile folder")


@pytest.mark.parametrize("field", ["messages", "python_path"])
def test_folder_field_naming_a_missing_folder_is_refused(profile, field):
    set_field(profile, field, "nowhere")
    assert_manifest_error(profile, field, "names 'nowhere', which does not exist in the profile folder")


def test_folder_field_naming_a_file_is_refused(profile):
    set_field(profile, "messages", "blocks.yaml")
    assert_manifest_error(profile, "messages", "names 'blocks.yaml', which does not exist in the profile folder")


@pytest.mark.parametrize("field", ["messages", "python_path"])
def test_folder_field_escaping_the_profile_folder_is_refused(profile, field):
    set_field(profile, field, "..")
    assert_manifest_error(profile, field, "must stay inside the profile folder")


@pytest.mark.parametrize("field", ["api", "simulator"])
@pytest.mark.parametrize("value", ["rockly_hobbit.api.Hobbit", "rockly_hobbit/api:Hobbit", "rockly_hobbit.api:",
                                   ":Hobbit", "rockly_hobbit.api:Hobbit:more", "rockly_hobbit..api:Hobbit",
                                   "1hobbit:Hobbit", "rockly_hobbit.api:Hobbit()", "rockly_hobbit.api:Hobbit\n", 5])
def test_bad_import_path_is_refused(profile, field, value):
    set_field(profile, field, value)
    assert_manifest_error(profile, field, "must be 'package.module:Name'")


@pytest.mark.parametrize("value, problem", [
    ({"publish": {"topic": "/x", "type": "std_msgs/String"}}, "must be a list of actions"),
    (["stop"], "item 1 must be one action: {publish: ...} or {cancel_goals: ACTION}"),
    ([{"cancel_goals": "a", "publish": {"topic": "/x", "type": "t"}}], "item 1 must be one action"),
    ([{"cancel_goals": "hobbit_arm"}, {"publish": {"topic": "/cmd_vel"}}],
     "item 2: publish needs 'topic' and 'type' (and optional 'message')"),
    ([{"publish": "/cmd_vel"}], "item 1: publish needs 'topic' and 'type'"),
    ([{"cancel_goals": ""}], "item 1: cancel_goals needs an action name"),
    ([{"cancel_goals": ["move_base"]}], "item 1: cancel_goals needs an action name"),
    ([{"cancel_goals": "x"}, {"cancel_goals": "y"}, {"shutdown": True}],
     "item 3: unknown action 'shutdown' (use publish or cancel_goals)"),
], ids=["not a list", "item not a mapping", "two actions in one item", "publish without type", "publish a string",
        "cancel empty", "cancel a list", "unknown action"])
def test_bad_safe_stop_is_refused_naming_the_item(profile, value, problem):
    set_field(profile, "safe_stop", value)
    assert_manifest_error(profile, "safe_stop", problem)


def test_state_must_be_a_list(profile):
    set_field(profile, "state", {"topic": "/battery"})
    assert_manifest_error(profile, "state", "must be a list")


@pytest.mark.parametrize("value, problem", [
    ([], "must map block types to their old field names"),
    ({"hobbit_arm_gripper": "movement"},
     "'hobbit_arm_gripper' must map old field names to {field: NEW, values: {...}}"),
    ({"hobbit_arm_gripper": {"gripper_position": "movement"}},
     "'hobbit_arm_gripper.gripper_position' needs 'field: NEW_NAME'"),
    ({"hobbit_arm_gripper": {"gripper_position": {"values": {"open": "OpenGripper"}}}},
     "'hobbit_arm_gripper.gripper_position' needs 'field: NEW_NAME'"),
    ({"hobbit_arm_gripper": {"gripper_position": {"field": 3}}}, "needs 'field: NEW_NAME'"),
    ({"hobbit_arm_gripper": {"gripper_position": {"field": "movement", "values": ["open", "close"]}}},
     "'hobbit_arm_gripper.gripper_position.values' must map old values to new ones"),
], ids=["not a mapping", "block not a mapping", "alias a string", "alias without field", "field not text",
        "values a list"])
def test_bad_legacy_fields_are_refused(profile, value, problem):
    set_field(profile, "legacy_fields", value)
    assert_manifest_error(profile, "legacy_fields", problem)


# The problem wording differs between libyaml and PyYAML's pure-Python parser; both name the place.
@pytest.mark.parametrize("text, line, column, wording", [
    ('schema: 1\nid: hobbit\nname: HOBBIT\n  version: "1.0.0"\n', 4, 10, r"mapping values are not allowed"),
    ('schema: 1\nid: hobbit\nname: [HOBBIT\nversion: "1.0.0"\n', 4, 8, r"expected ',' or '\]'"),
    ("schema: 1\n\tid: hobbit\n", 2, 1, r"tab|'\\t'"),
], ids=["bad indentation", "unclosed list", "tab"])
def test_invalid_yaml_names_line_and_column(profile, text, line, column, wording):
    profile.write_text("profile.yaml", text)
    error = load_error(profile)
    assert error.path == str(profile.path("profile.yaml"))
    assert error.field is None
    prefix = f"this is not valid YAML at line {line}, column {column}: "
    assert error.problem.startswith(prefix)
    assert re.search(wording, error.problem[len(prefix):])


@pytest.mark.parametrize("text", ["- schema: 1\n- id: hobbit\n", "hobbit\n", "", "# only a comment\n"],
                         ids=["list", "scalar", "empty", "comment only"])
def test_top_level_that_is_not_a_mapping_is_refused(profile, text):
    profile.write_text("profile.yaml", text)
    error = load_error(profile)
    assert error.path == str(profile.path("profile.yaml"))
    assert error.field is None
    assert error.problem == "the file must contain a mapping (key: value lines) at the top level"


def test_manifest_that_is_not_utf8_cannot_be_read(profile):
    profile.path("profile.yaml").write_bytes("name: Gr\u00fc\u00dfe\n".encode("latin-1"))
    error = load_error(profile)
    assert error.path == str(profile.path("profile.yaml"))
    assert error.problem.startswith("the file cannot be read (")


def test_folder_without_a_manifest_is_not_a_profile(profile):
    profile.path("profile.yaml").unlink()
    error = load_error(profile)
    assert error.path == str(profile.path("profile.yaml"))
    assert error.field is None
    assert error.problem == "no profile manifest here (profile.yaml is missing)"


def test_first_problem_in_field_order_is_reported(profile):
    profile.edit("profile.yaml", lambda data: data.update(id="Bad Id", version=1.0))
    assert_manifest_error(profile, "id", "must be lower-case")


def test_reading_a_manifest_does_not_change_the_profile_files(profile):
    before = {path.name: (path.read_bytes(), path.stat().st_mtime_ns) for path in profile.root.glob("*.yaml")}
    load_profile(profile.root, SHARED_TOOLBOXES)
    after = {path.name: (path.read_bytes(), path.stat().st_mtime_ns) for path in profile.root.glob("*.yaml")}
    assert after == before


def _with_qos(profile, qos):
    return profile.edit("profile.yaml", lambda data: data["ros_interface"].update({"qos": qos}))


@pytest.mark.parametrize("qos", [{"/odom": "sensor_data"},
                                 {"/map": {"reliability": "reliable", "durability": "transient_local", "depth": 1}}])
def test_a_ros2_qos_for_a_topic_is_accepted(profile, qos):
    _with_qos(profile, qos)
    assert read_manifest(profile.root)["ros_interface"]["qos"] == qos


@pytest.mark.parametrize("qos", [{"/odom": "fast"}, {"/odom": {"reliability": "sometimes"}}, {"/odom": {"depth": 0}},
                                 ["/odom"]])
def test_an_unknown_qos_is_refused_with_the_known_ones(profile, qos):
    _with_qos(profile, qos)
    assert_manifest_error(profile, "ros_interface", "sensor_data")


def _with_versions(profile, versions):
    return set_field(profile, "ros_versions", versions)


@pytest.mark.parametrize("versions", [{"/cmd_vel": {"jazzy": "geometry_msgs/TwistStamped"}},
                                      {"cmd_vel": {"ros1": "geometry_msgs/Twist", "ros2": "geometry_msgs/msg/Twist",
                                                   "kilted": "geometry_msgs/TwistStamped"}}])
def test_types_per_ros_version_are_accepted_and_loaded(profile, versions):
    _with_versions(profile, versions)
    assert load_profile(profile.root, SHARED_TOOLBOXES).ros_versions == versions


@pytest.mark.parametrize(("versions", "problem"), [
    ({"/cmd_vel": {"jazz": "geometry_msgs/TwistStamped"}},
     "'/cmd_vel': unknown ROS version or distribution 'jazz' (use ros1, ros2, humble, iron, jazzy, kilted, rolling)"),
    ({"/no_such_topic": {"jazzy": "geometry_msgs/TwistStamped"}},
     "'/no_such_topic' is not in ros_interface: declare it there with its usual type first"),
    ({"/cmd_vel": {"jazzy": "TwistStamped"}}, "'/cmd_vel.jazzy' must be a type like geometry_msgs/TwistStamped"),
    ({"/cmd_vel": "geometry_msgs/TwistStamped"}, "'/cmd_vel' must map ROS versions or distributions (ros1, ros2"),
    ({"/cmd_vel": {}}, "'/cmd_vel' must map ROS versions or distributions"),
    ([], "must map ROS names to their types per version, e.g. {/cmd_vel: {jazzy: geometry_msgs/TwistStamped}}"),
])
def test_a_bad_type_per_ros_version_is_refused_saying_what_to_write(profile, versions, problem):
    _with_versions(profile, versions)
    assert_manifest_error(profile, "ros_versions", problem)
