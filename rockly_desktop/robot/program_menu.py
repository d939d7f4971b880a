"""How a robot offers the agent's programs on its own UI (``rockly agent --offer-on-robot-ui``).

A profile that can declares ``program_menu`` in its manifest: its hook (a ``ProgramMenu`` subclass, through the
SDK) and settings as data (whether it offers Stop while a program runs, how long one question waits). The agent
asks it again and again: which program to start, or, while one runs, whether to stop it.
"""
from dataclasses import dataclass
from typing import ClassVar, Optional


@dataclass(frozen=True)
class MenuChoice:
    """What a person chose on the robot's UI: ``start`` the program ``name``, or ``stop`` the running one."""

    action: str  # MenuChoice.START or MenuChoice.STOP
    name: Optional[str] = None

    START: ClassVar[str] = "start"
    STOP: ClassVar[str] = "stop"


class ProgramMenu:
    """The base of a profile's ``program_menu`` hook: offers programs in ``language``.

    ``offers_stop``: whether it offers Stop while a program runs (the manifest's ``stop``); ``answer_seconds``:
    how long one question waits for the person before the agent asks anew (``answer_seconds``)."""

    def __init__(self, language: str = "en", offers_stop: bool = False, answer_seconds: float = 60.0):
        self.language = language
        self.offers_stop = offers_stop
        self.answer_seconds = answer_seconds

    def choose(self, backend, programs: list, running: str = None):
        """Offer ``programs`` (their names, in order) and wait for the person's choice; while the program
        ``running`` runs (only when ``offers_stop``), offer to stop it instead. Returns a ``MenuChoice``, or None
        when nobody chose (the question timed out, an answer that names nothing): the agent asks again. Raises a
        RocklyError when the robot's UI cannot be reached (the agent says so and tries again later).

        ``backend``: this question's RobotBackend (topics, services and actions by ROS names, as ``RobotCommands``
        use it); its waits end (ProgramStopped) when what is offered changes: the agent then asks anew."""
        raise NotImplementedError
