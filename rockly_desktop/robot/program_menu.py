"""How a robot offers the agent's programs on its own UI (``rockly agent --offer-on-robot-ui``).

A profile that can declares ``program_menu`` in its manifest: its hook (a ``ProgramMenu`` subclass, through the
SDK) and settings as data (whether it offers Stop while a program runs, how long one question waits, whether it
shows a pairing code). The agent asks it again and again: which program to start, or, while one runs, whether to
stop it; and, where it offers pairing, shows the one-time code a person there asked for.
"""
from dataclasses import dataclass
from typing import ClassVar, Optional


@dataclass(frozen=True)
class MenuChoice:
    """What a person chose on the robot's UI: ``start`` the program ``name``, ``stop`` the running one, or ``pair`` a
    laptop (show a one-time pairing code)."""

    action: str  # MenuChoice.START, MenuChoice.STOP or MenuChoice.PAIR
    name: Optional[str] = None

    START: ClassVar[str] = "start"
    STOP: ClassVar[str] = "stop"
    PAIR: ClassVar[str] = "pair"


class ProgramMenu:
    """The base of a profile's ``program_menu`` hook: offers programs in ``language``.

    ``offers_stop``: whether it offers Stop while a program runs (the manifest's ``stop``); ``answer_seconds``:
    how long one question waits for the person before the agent asks anew (``answer_seconds``); ``offers_pairing``:
    whether, while nothing runs, it also offers to pair a laptop (the manifest's ``pairing``; the agent turns it off
    with ``--no-pairing-on-robot-ui``), and then shows the code with ``show_pairing_code``."""

    def __init__(self, language: str = "en", offers_stop: bool = False, answer_seconds: float = 60.0,
                 offers_pairing: bool = False):
        self.language = language
        self.offers_stop = offers_stop
        self.answer_seconds = answer_seconds
        self.offers_pairing = offers_pairing

    def choose(self, backend, programs: list, running: str = None):
        """Offer ``programs`` (their names, in order) and wait for the person's choice; while the program
        ``running`` runs (only when ``offers_stop``), offer to stop it instead. Returns a ``MenuChoice``, or None
        when nobody chose (the question timed out, an answer that names nothing): the agent asks again. With
        ``offers_pairing`` (and nothing running) it also offers to pair a laptop (``MenuChoice(MenuChoice.PAIR)``),
        also when ``programs`` is empty. Raises a
        RocklyError when the robot's UI cannot be reached (the agent says so and tries again later).

        ``backend``: this question's RobotBackend (topics, services and actions by ROS names, as ``RobotCommands``
        use it); its waits end (ProgramStopped) when what is offered changes: the agent then asks anew."""
        raise NotImplementedError

    def show_pairing_code(self, backend, code: str, seconds: int):
        """Show the one-time pairing ``code`` (as ``K7Q-M2X``; it works once, for ``seconds``) on the robot's own
        UI, for the person who asked for it, until they confirm or ``seconds`` have passed; only where
        ``offers_pairing``. Shown there only: never spoken aloud, logged or sent anywhere else. ``backend`` as for
        ``choose``. Raises a RocklyError when the UI cannot be reached."""
        raise NotImplementedError
