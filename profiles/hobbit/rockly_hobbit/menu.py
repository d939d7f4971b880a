"""The agent's programs on HOBBIT's tablet (``rockly agent --offer-on-robot-ui hobbit``), through ``/MMUI``.

The tablet knows no list to pick from, so the programs are a ``D_NAME`` question listing them, numbered; the
person types a number or a name. While a program runs, a ``D_YES_NO`` question asks whether to stop it. Where the
agent offers pairing, the list ends with ``0.``, pairing a laptop: the code is then shown in a ``D_OK`` message (not
spoken), until the person confirms or it is no longer valid.
"""
from rockly_desktop.sdk import MenuChoice, ProgramMenu, RobotTimeout

from .api import MMUI_SERVICE, MMUI_TYPE
from .world import TEXTS

PAIR_NUMBER = "0"  # what a person types to pair a laptop (the programs are numbered from 1)


class TabletProgramMenu(ProgramMenu):
    """HOBBIT's ``program_menu`` hook: questions on its tablet."""

    def choose(self, backend, programs: list, running: str = None):
        """The person's choice on the tablet; None when the question timed out or the answer names no program."""
        if running is not None:
            question = TEXTS.text("menu_stop", self.language, name=running)
            answer = self._ask(backend, "D_YES_NO", question, question, self.answer_seconds)
            return MenuChoice(MenuChoice.STOP) if answer.strip().lower() == "yes" else None
        if programs:
            listed = "\n".join(f"{number}. {name}" for number, name in enumerate(programs, 1))
            if self.offers_pairing:
                listed += "\n" + TEXTS.text("menu_pair_item", self.language, number=PAIR_NUMBER)
            question = TEXTS.text("menu_question", self.language, programs=listed)
        else:
            question = TEXTS.text("menu_pair_only", self.language, number=PAIR_NUMBER)
        answer = self._ask(backend, "D_NAME", question, TEXTS.text("menu_speak", self.language), self.answer_seconds)
        if self.offers_pairing and answer.strip() == PAIR_NUMBER:
            return MenuChoice(MenuChoice.PAIR)
        name = chosen(answer, programs)
        return MenuChoice(MenuChoice.START, name) if name is not None else None

    def show_pairing_code(self, backend, code: str, seconds: int):
        """The code in a ``D_OK`` message for ``seconds`` (its ``Timeout``); what is spoken does not say it."""
        self._ask(backend, "D_OK", TEXTS.text("menu_pair_code", self.language, code=code, minutes=seconds // 60),
                  TEXTS.text("menu_pair_speak", self.language), seconds)

    def _ask(self, backend, dialog_type, text, speak, seconds) -> str:
        params = [{"name": "type", "value": dialog_type}, {"name": "text", "value": text},
                  {"name": "speak", "value": speak}, {"name": "Timeout", "value": f"{seconds:g}"}]
        try:
            response = backend.call_service(MMUI_SERVICE, MMUI_TYPE,
                                            {"sessionID": "0", "requestText": "", "params": params}, seconds + 5)
        except RobotTimeout:
            return ""
        answers = [param.get("value", "") for param in response.get("params", []) if param.get("name") != "type"]
        return answers[0] if answers else ""


def chosen(answer: str, programs: list):
    """The program ``answer`` names: its number in the list (from 1) or its name (any case); None for neither."""
    answer = answer.strip()
    if answer.isdigit() and 1 <= int(answer) <= len(programs):
        return programs[int(answer) - 1]
    return next((name for name in programs if name.casefold() == answer.casefold()), None)
