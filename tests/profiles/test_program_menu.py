"""A profile's ``program_menu`` (how ``rockly agent --offer-on-robot-ui`` offers the programs on the robot's own UI):
checked as data in the manifest, its hook reached through the SDK; HOBBIT's reads the person's tablet answer."""
import sys

import pytest
from profile_copies import SHARED_TOOLBOXES, copy_profile
from test_manifest import assert_manifest_error, set_field

from rockly_desktop.core.errors import ManifestError
from rockly_desktop.profiles.profile import load_profile
from rockly_desktop.profiles.registry import ProfileRegistry
from rockly_desktop.sdk import MenuChoice, ProgramMenu


@pytest.fixture
def profile(tmp_path):
    return copy_profile(tmp_path / "hobbit")


@pytest.mark.parametrize("value, problem", [
    ("rockly_hobbit.menu:TabletProgramMenu", "must say its hook"),
    ({"hook": "no colon"}, "must say its hook"),
    ({"hook": "rockly_hobbit.menu:TabletProgramMenu", "stop": "yes"}, "'stop' must be true or false"),
    ({"hook": "rockly_hobbit.menu:TabletProgramMenu", "answer_seconds": 0}, "'answer_seconds' must be a number"),
    ({"hook": "rockly_hobbit.menu:TabletProgramMenu", "pairing": "on"}, "'pairing' must be true or false"),
    ({"hook": "rockly_hobbit.menu:TabletProgramMenu", "buttons": 3}, "unknown key(s) ['buttons']"),
])
def test_a_wrong_program_menu_is_named_with_what_is_wrong(profile, value, problem):
    set_field(profile, "program_menu", value)
    assert_manifest_error(profile, "program_menu", problem)


def test_a_hook_that_cannot_be_imported_is_a_manifest_error_naming_the_field(profile, monkeypatch):
    monkeypatch.setattr(sys, "path", list(sys.path))  # the copy's folder is put on it: not for later tests
    set_field(profile, "program_menu", {"hook": "rockly_nowhere.menu:NoSuchMenu"})
    with pytest.raises(ManifestError) as caught:
        load_profile(profile.root, SHARED_TOOLBOXES).program_menu("en")
    assert caught.value.field == "program_menu"
    assert "cannot import rockly_nowhere.menu:NoSuchMenu" in caught.value.problem


def test_hobbit_offers_its_programs_with_stop_and_turtlebot_declares_no_way():
    registry = ProfileRegistry.discover()
    menu = registry.get("hobbit").program_menu("de")
    assert isinstance(menu, ProgramMenu) and menu.offers_stop and menu.answer_seconds == 60 and menu.offers_pairing
    assert registry.get("turtlebot").program_menu("en") is None


class Tablet:
    """A RobotBackend standing for HOBBIT's tablet: records the /MMUI requests, answers as a person typed."""

    def __init__(self, answer):
        self.answer, self.requests = answer, []

    def call_service(self, name, srv_type, request, timeout):
        self.requests.append((name, srv_type, request, timeout))
        return {"params": [{"name": "result", "value": self.answer}]}


@pytest.mark.parametrize("answer, chosen", [("2", "wave"), (" WAVE ", "wave"), ("Long", "long"), ("3", None),
                                            ("0", None), ("dance", None), ("", None)])
def test_hobbit_reads_a_number_or_a_name_typed_on_the_tablet(answer, chosen):
    tablet = Tablet(answer)
    menu = ProfileRegistry.discover().get("hobbit").program_menu("de")
    menu.offers_pairing = False  # rockly agent --no-pairing-on-robot-ui
    choice = menu.choose(tablet, ["long", "wave"])
    assert choice == (MenuChoice(MenuChoice.START, chosen) if chosen else None)
    ((name, srv_type, request, timeout),) = tablet.requests
    assert (name, srv_type, request["sessionID"], request["requestText"]) == ("/MMUI", "hobbit_msgs/Request", "0", "")
    assert request["params"] == [
        {"name": "type", "value": "D_NAME"},
        {"name": "text", "value": "Welches Programm soll ich ausführen?\n1. long\n2. wave\n"
                                  "Tippe seine Nummer oder seinen Namen."},
        {"name": "speak", "value": "Welches Programm soll ich ausführen?"},
        {"name": "Timeout", "value": "60"}]
    assert timeout > 60


@pytest.mark.parametrize("answer, stops", [("yes", True), ("no", False), ("", False)])
def test_while_a_program_runs_hobbit_asks_yes_or_no_whether_to_stop_it(answer, stops):
    tablet = Tablet(answer)
    choice = ProfileRegistry.discover().get("hobbit").program_menu("en").choose(tablet, ["long"], running="long")
    assert choice == (MenuChoice(MenuChoice.STOP) if stops else None)
    assert tablet.requests[0][2]["params"][:2] == [{"name": "type", "value": "D_YES_NO"},
                                                   {"name": "text", "value": "“long” is running. Shall I stop it?"}]


@pytest.mark.parametrize("programs, answer, chosen, text", [
    (["long", "wave"], "0", MenuChoice(MenuChoice.PAIR), "Which program shall I run?\n1. long\n2. wave\n"
                                                        "0. Pair a laptop with me (shows a code)\n"
                                                        "Type its number or its name."),
    (["long", "wave"], "2", MenuChoice(MenuChoice.START, "wave"), None),
    ([], " 0 ", MenuChoice(MenuChoice.PAIR), "No programs are kept for me yet.\nTo pair a laptop with me, type 0."),
    ([], "1", None, None),
])
def test_where_pairing_is_offered_hobbits_list_ends_with_0_to_pair_a_laptop(programs, answer, chosen, text):
    tablet = Tablet(answer)
    choice = ProfileRegistry.discover().get("hobbit").program_menu("en").choose(tablet, programs)
    assert choice == chosen
    if text is not None:
        assert tablet.requests[0][2]["params"][:2] == [{"name": "type", "value": "D_NAME"},
                                                       {"name": "text", "value": text}]


def test_hobbit_shows_the_pairing_code_on_the_tablet_for_its_two_minutes_and_does_not_speak_it():
    tablet = Tablet("")
    ProfileRegistry.discover().get("hobbit").program_menu("de").show_pairing_code(tablet, "K7Q-M2X", 120)
    ((name, _, request, timeout),) = tablet.requests
    assert name == "/MMUI" and timeout > 120
    assert request["params"] == [
        {"name": "type", "value": "D_OK"},
        {"name": "text", "value": "Um einen Laptop mit mir zu koppeln, tippe diesen Code in Rockly auf ihm ein "
                                  "(Roboter → Programme auf dem Roboter…):\nK7Q-M2X\nEr gilt einmal, 2 Minuten lang."},
        {"name": "speak", "value": "Hier ist ein Code, um einen Laptop mit mir zu koppeln."},
        {"name": "Timeout", "value": "120"}]
