"""Toolbox levels, capabilities and the drive interface in profile.yaml: filtering and validation errors."""
import pytest
from profile_copies import SHARED_TOOLBOXES, copy_profile

from rockly_desktop.core.errors import ManifestError
from rockly_desktop.profiles.profile import load_profile

NAME = {"en": "Starter", "de": "Einsteiger"}


@pytest.fixture
def profile(tmp_path):
    return copy_profile(tmp_path / "hobbit")


def set_field(profile, name, value):
    profile.edit("profile.yaml", lambda data: data.update({name: value}))


def error_for(profile) -> ManifestError:
    with pytest.raises(ManifestError) as caught:
        load_profile(profile.root, SHARED_TOOLBOXES)
    assert caught.value.path == str(profile.path("profile.yaml"))
    return caught.value


def types(toolbox) -> list:
    return [entry["type"] for category in toolbox["contents"] for entry in category.get("contents", [])]


def test_a_level_keeps_whole_categories_and_single_blocks_in_the_toolbox_order(hobbit):
    config = hobbit.editor_config("de", "explorer")
    names = [category["name"] for category in config["toolbox"]["contents"]]
    assert names == ["Fahren", "Kopf", "Arm", "Tablet", "Sensoren", "Zeit", "Logik", "Schleifen", "Mathematik",
                     "Text", "Variablen"]
    assert len(config["blocks"]) == len(hobbit.editor_config("de")["blocks"])  # every block stays defined
    assert types(hobbit.toolbox("en", "starter")) == ["hobbit_move", "hobbit_turn", "hobbit_stop", "hobbit_head",
                                                       "hobbit_emo", "hobbit_show_info", "hobbit_wait",
                                                       "controls_repeat_ext"]
    assert hobbit.toolbox("en", "full") == hobbit.toolbox("en") == hobbit.toolbox("en", "no_such_level")


def test_switched_off_capabilities_hide_their_blocks(hobbit):
    shown = types(hobbit.toolbox("en", "explorer", ["arm", "navigation"]))
    assert not {"hobbit_arm_gripper", "hobbit_arm_joints", "hobbit_navigate"} & set(shown)
    assert "hobbit_arm_moving" in shown  # reading the arm's state is no arm command


@pytest.mark.parametrize(("field", "value", "where", "problem"), [
    ("levels", [], "levels", "must be a non-empty list of levels"),
    ("levels", [{"name": NAME, "blocks": ["hobbit_move"]}], "levels", "item 1 needs an 'id'"),
    ("levels", [{"id": "starter", "blocks": ["hobbit_move"]}], "levels", "item 1 ('starter') needs a 'name'"),
    ("levels", [{"id": "starter", "name": NAME}], "levels", "must list 'categories' or 'blocks'"),
    ("levels", [{"id": "starter", "name": NAME, "blocks": "hobbit_move"}], "levels", "'blocks' must be a list"),
    ("levels", [{"id": "a", "name": "A", "categories": "all"}, {"id": "a", "name": "B", "categories": "all"}],
     "levels", "the id 'a' is used twice"),
    ("levels", [{"id": "a", "name": NAME, "categories": "all", "colour": "red"}], "levels",
     "unknown key(s) ['colour']"),
    ("levels", [{"id": "a", "name": NAME, "categories": ["Driving"]}], "levels[0].categories",
     "'a' names the category 'Driving', which the toolbox does not have"),
    ("levels", [{"id": "a", "name": NAME, "blocks": ["hobbit_fly"]}], "levels[0].blocks",
     "'a' names the block 'hobbit_fly', which is not in the toolbox"),
    ("capabilities", [{"id": "arm", "name": NAME, "blocks": ["hobbit_arm_move"]}], "capabilities",
     "must name the topics, services or actions it covers"),
    ("capabilities", [{"id": "arm", "name": NAME, "actions": "hobbit_arm"}], "capabilities",
     "'actions' must be a list of names"),
    ("capabilities", [{"id": "arm", "name": NAME, "actions": ["hobbit_arm"], "blocks": ["hobbit_claw"]}],
     "capabilities[0].blocks", "'arm' names the block 'hobbit_claw'"),
    ("velocity_topics", "/cmd_vel", "velocity_topics", "must be a list of topic names like /cmd_vel"),
])
def test_bad_levels_and_capabilities_name_the_file_and_field(profile, field, value, where, problem):
    set_field(profile, field, value)
    error = error_for(profile)
    assert error.field == where
    assert problem in error.problem, error.problem
