"""The agent's menu on the robot's own UI (``agent.robot_menu.RobotMenu``) showing a pairing code a person there
asked for: made in the agent's real folder as ``rockly agent pair`` makes it, shown through the profile's menu only,
its role said in the agent's log without the code; a folder that cannot be written is said, and nothing shown."""
from pathlib import Path

from waiting import eventually

from rockly_desktop.profiles.registry import ProfileRegistry
from rockly_desktop.robot.program_menu import MenuChoice, ProgramMenu
from rockly_desktop.runtime.agent.library import Library
from rockly_desktop.runtime.agent.pairings import Pairings
from rockly_desktop.runtime.agent.robot_menu import RobotMenu
from rockly_desktop.runtime.agent.server import Agent


class PairingMenu(ProgramMenu):
    """A UI whose person asks for a code ``wanted`` times, then waits for ever; ``shown``: each code shown."""

    def __init__(self, wanted: int):
        super().__init__("en", offers_pairing=True)
        self.wanted = wanted
        self.shown = []

    def choose(self, backend, programs, running=None):
        if self.wanted:
            self.wanted -= 1
            return MenuChoice(MenuChoice.PAIR)
        backend.nap(600)  # ends (ProgramStopped) when the offer is closed

    def show_pairing_code(self, backend, code, seconds):
        self.shown.append((code, seconds))


def agent_with(pairings_folder: Path, library: Path) -> Agent:
    return Agent(Library(library, ProfileRegistry.discover().profiles), "sim", [], Pairings(pairings_folder))


def test_each_code_asked_for_is_new_shown_on_the_ui_only_and_pairs_in_its_role(tmp_path):
    agent, menu, said = agent_with(tmp_path / "agent", tmp_path / "library"), PairingMenu(2), []
    offer = RobotMenu(agent, menu, "hobbit", lambda interrupt: interrupt, say=said.append)
    try:
        eventually(lambda: len(menu.shown) == 2, 30)
    finally:
        offer.close()
    (first, seconds), (second, _) = menu.shown
    assert first != second and seconds == 120
    assert said == ["rockly agent: a pairing code was shown on the robot's own UI, as a person there asked (valid 2 "
                    "minutes, once; the laptop pairs as teacher)"] * 2  # no teacher paired yet: a fresh agent
    assert agent.pairings.pair(second, "laptop").role == "teacher"


def test_a_folder_that_cannot_be_written_is_said_and_no_code_is_shown(tmp_path):
    (tmp_path / "agent").write_text("a file where the agent's folder should be")
    agent, menu, said = agent_with(tmp_path / "agent", tmp_path / "library"), PairingMenu(1), []
    offer = RobotMenu(agent, menu, "hobbit", lambda interrupt: interrupt, say=said.append)
    try:
        eventually(lambda: said, 30)
    finally:
        offer.close()
    assert said[0].startswith("rockly agent: no pairing code can be made for the robot's own UI: ")
    assert menu.shown == []
