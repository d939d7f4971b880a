"""Learning the fields of a type the robot offers but Rockly has no definition for, off the window's thread.

``FieldLearning.ask(offer)`` runs the robot link's ``interface_definition(kind, name, type)`` (which waits
on the robot, bounded in time) on a thread of its own; on the window's thread, what came back is learnt
(``learn_definition``: every catalogue of the process knows the type then) and ``sig_learnt(offer)`` or
``sig_failed(offer, why)`` follow. Each offer is asked once at a time; an answer after ``forget()`` (the
maker closed) is dropped.
"""
import threading

import shiboken6
from PySide6.QtCore import QObject, Signal

from rockly_desktop.core.errors import RobotCommandError
from rockly_desktop.core.ros_definitions import learn_definition
from rockly_desktop.profiles.packs.interfaces import knows_type
from rockly_desktop.ui.blockmaker.offers import DEFINITION


class _Messenger(QObject):
    """Lives on the window's thread: its signal, emitted on the asking thread, is delivered there (queued)."""

    sig_done = Signal(object, object)  # the LearntDefinition, or the RobotCommandError that came instead


class FieldLearning(QObject):
    """Asks the robot for the definitions of live offers ``profile`` does not know: ``asker()`` gives, on the
    window's thread, the robot link's ``interface_definition`` (None: no robot to ask; None as ``asker``: never)."""

    sig_learnt = Signal(object)  # the Offer whose type's fields are now known
    sig_failed = Signal(object, object)  # the Offer, and why (a RobotCommandError, said in the window's language)

    def __init__(self, profile, asker, parent=None):
        super().__init__(parent)
        self._profile = profile
        self._asker = asker
        self._asking = set()  # offers whose definition is on its way
        self._messengers = set()  # kept alive until their answer is delivered on the window's thread
        self._threads = []
        self._generation = 0

    def needed(self, offer) -> bool:
        """True when ``offer``'s fields must be asked of the robot: it is live, typed, of a kind with fields,
        and the profile does not know its type."""
        kind = DEFINITION.get(offer.kind)
        return bool(kind and offer.live and offer.type and not knows_type(self._profile, offer.type, kind))

    def can_ask(self) -> bool:
        """True when there is a robot to ask."""
        return self._asker is not None and self._asker() is not None

    @property
    def busy(self) -> bool:
        """True while an answer is still to be delivered (or dropped) on the window's thread."""
        return bool(self._messengers)

    def asking(self, offer) -> bool:
        """True while ``offer``'s definition is on its way."""
        return offer in self._asking

    def ask(self, offer):
        """Ask the robot for ``offer``'s definition (nothing when it is already on its way)."""
        ask = self._asker() if self._asker is not None else None
        if offer in self._asking or ask is None:
            return
        messenger, generation = _Messenger(), self._generation
        self._asking.add(offer)
        self._messengers.add(messenger)
        messenger.sig_done.connect(lambda learnt, error: self._answered(messenger, offer, generation, learnt, error))

        def call():
            try:
                learnt, error = ask(offer.kind, offer.name, offer.type), None
            except RobotCommandError as refused:
                learnt, error = None, refused
            messenger.sig_done.emit(learnt, error)

        thread = threading.Thread(target=call, daemon=True, name="rockly-maker-learn")
        self._threads = [known for known in self._threads if known.is_alive()] + [thread]
        thread.start()

    def _answered(self, messenger, offer, generation, learnt, error):
        self._messengers.discard(messenger)
        if generation != self._generation or not shiboken6.isValid(self):
            return
        self._asking.discard(offer)
        if error is not None:
            self.sig_failed.emit(offer, error)
            return
        learn_definition(offer.type, DEFINITION[offer.kind], learnt.text, learnt.nested)
        self.sig_learnt.emit(offer)

    def forget(self):
        """Drop the answers on their way (their threads end on their own, each ask being bounded)."""
        self._generation += 1
        self._asking.clear()

    def wait(self, seconds: float):
        """Wait up to ``seconds`` for the asking threads to end (tests, closing)."""
        for thread in self._threads:
            thread.join(seconds)
