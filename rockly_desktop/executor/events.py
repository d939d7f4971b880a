"""What happens during a run, as small immutable events (sent from the worker thread)."""
from dataclasses import dataclass, field


@dataclass(frozen=True)
class BlockEntered:
    """The program is about to run the block ``block_id``."""

    block_id: str


@dataclass(frozen=True)
class RunPaused:
    """The program waits before ``block_id``; ``reason`` is 'breakpoint', 'step' or 'pause'."""

    block_id: str
    reason: str


@dataclass(frozen=True)
class RunResumed:
    """The program goes on after a pause."""


@dataclass(frozen=True)
class OutputPrinted:
    """The program printed ``text`` (one line, without the newline)."""

    text: str


@dataclass(frozen=True)
class VariablesChanged:
    """The program's variables (Blockly names) and their values, as people read them (``value_text``)."""

    values: dict = field(default_factory=dict)


@dataclass(frozen=True)
class RunFinished:
    """The run ended. ``outcome``: 'finished', 'stopped' or 'error'.

    For an error, ``block_id`` is the block it came from, ``message`` a plain-language
    explanation and ``details`` the traceback (None when the robot refused: ``by_robot``,
    a bump, a capability the teacher switched off, a goal it could not reach — what the
    robot says is all there is to tell, nothing in Rockly or the program broke).
    """

    outcome: str
    block_id: str = None
    message: str = None
    details: str = None
    by_robot: bool = False
