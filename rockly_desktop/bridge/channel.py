"""The QWebChannel object the editor page talks to: one JSON message in, one out.

Calls from Python are queued until the page has said hello and run ``setup``; replies
are matched to their callbacks by id; replies for a page that has since been reloaded
are dropped.
"""
import itertools
import logging

from PySide6.QtCore import QObject, QTimer, Signal, Slot

from rockly_desktop.core import deep_json

log = logging.getLogger(__name__)


class PageChannel(QObject):
    """The Python end of the editor page's channel (registered as ``rocklyBridge``)."""

    toPage = Signal(str)  # noqa: N815 - name seen by the page's JavaScript
    sig_hello = Signal()
    sig_event = Signal(object)  # a dict; "object" so numbers beyond 64 bits pass unconverted

    def __init__(self, parent=None):
        super().__init__(parent)
        self._ids = itertools.count(1)
        self._callbacks = {}
        self._queued = []
        self._open = False

    def reset(self):
        """Forget the page: a new one is loading. Calls it was sent are never answered;
        queued calls wait for the next page."""
        self._open = False
        self._callbacks.clear()

    def open(self):
        """The page is set up: send everything queued, in order."""
        self._open = True
        queued, self._queued = self._queued, []
        for message, call_id, callback in queued:
            self._send(message, call_id, callback)

    def _send(self, message: str, call_id: int, callback):
        if callback is not None:
            self._callbacks[call_id] = callback
        self.toPage.emit(message)

    @property
    def is_open(self) -> bool:
        """True once the page has run setup and accepts calls."""
        return self._open

    def call(self, name: str, args=None, callback=None, *, immediately=False):
        """Ask the page to run ``name(args)``; ``callback(result, error)`` gets the answer.

        Calls wait in a queue until the page is open, unless ``immediately`` (used
        for ``setup`` itself).
        """
        call_id = next(self._ids)
        message = deep_json.dumps({"call": name, "id": call_id, "args": args or {}})
        if self._open or immediately:
            self._send(message, call_id, callback)
        else:
            self._queued.append((message, call_id, callback))

    @Slot(str)
    def fromPage(self, text: str):  # noqa: N802 - name seen by the page's JavaScript
        """Receive one JSON message from the page.

        Handling is deferred to the event loop: QWebChannel delivers no further
        messages while this slot runs, so a handler that waits for another answer
        (``call_blocking``) would otherwise never get it.
        """
        QTimer.singleShot(0, self, lambda: self._dispatch(text))

    def _dispatch(self, text: str):
        try:
            message = deep_json.loads(text)  # a stack of 500+ blocks is too deep for json.loads
        except ValueError:
            log.error("editor page sent a message that is not JSON: %.200s", text)
            return
        if "reply" in message:
            callback = self._callbacks.pop(message["reply"], None)
            if callback is not None:
                callback(message.get("result"), message.get("error"))
        elif message.get("event") == "hello":
            self.sig_hello.emit()
        else:
            self.sig_event.emit(message)
