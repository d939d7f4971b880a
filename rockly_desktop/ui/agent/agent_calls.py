"""``AgentCalls``: a dialog's calls to a robot's agent, each on a thread of its own so that an agent host that
drops packets (the client waits up to 10 s) never freezes the window; the answer comes back on the window's
thread. An answer that comes after ``forget()`` (the dialog was closed) or after its owner is gone is dropped."""
import threading

import shiboken6
from PySide6.QtCore import QObject, Signal

from rockly_desktop.runtime.agent.client import AgentError


class _Messenger(QObject):
    """Lives on the window's thread: its signal, emitted on the call's thread, is delivered there (queued)."""

    sig_done = Signal(object, object)  # the answer, or the AgentError that came instead


class AgentCalls:
    """Runs ``work()`` off the window's thread and ``then(answer, error)`` on it, for the QObject ``owner``."""

    def __init__(self, owner: QObject):
        self._owner = owner
        self._generation = 0
        self._messengers = set()  # kept alive until their answer is delivered
        self._threads = []

    @property
    def busy(self) -> bool:
        """True while a call is on its way."""
        return bool(self._messengers)

    def run(self, work, then, unused=None):
        """Call ``work()`` (which may raise ``AgentError``) on a new thread; ``then(answer, error)`` follows on
        the window's thread unless the owner is gone or ``forget()`` came first: then ``unused(answer)`` (when
        given) lets go of what the answer holds."""
        messenger, generation = _Messenger(), self._generation
        self._messengers.add(messenger)

        def deliver(answer, error):
            self._messengers.discard(messenger)
            if shiboken6.isValid(self._owner) and generation == self._generation:
                then(answer, error)
            elif unused is not None and error is None:
                unused(answer)

        messenger.sig_done.connect(deliver)

        def call():
            try:
                answer, error = work(), None
            except AgentError as refused:
                answer, error = None, refused
            messenger.sig_done.emit(answer, error)

        thread = threading.Thread(target=call, daemon=True, name="agent-call")
        self._threads = [known for known in self._threads if known.is_alive()] + [thread]
        thread.start()

    def forget(self):
        """Drop the answers of the calls on their way (their threads end on their own)."""
        self._generation += 1

    def wait(self, seconds: float):
        """Wait up to ``seconds`` for the calls' threads to end (for tests and shutdown)."""
        for thread in self._threads:
            thread.join(seconds)
