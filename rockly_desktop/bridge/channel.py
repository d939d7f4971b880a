"""The QWebChannel object the editor page talks to: one JSON message in, one out.

Calls from Python are queued until the page has said hello and run ``setup``; replies
are matched to their callbacks by id. A call sent to a page that is then reloaded is
answered with an error (its late reply, if any, is dropped), as is one whose answer
does not come within its ``timeout_ms``: a callback is never left waiting.
"""
import itertools
import logging

from PySide6.QtCore import QObject, QTimer, Signal, Slot

from rockly_desktop.core import deep_json

log = logging.getLogger(__name__)

PAGE_RELOADED = "the editor page was reloaded before it answered"


class PageChannel(QObject):
    """The Python end of the editor page's channel (registered as ``rocklyBridge``)."""

    toPage = Signal(str)
    sig_hello = Signal()
    sig_event = Signal(object)  # a dict; "object" so numbers beyond 64 bits pass unconverted

    def __init__(self, parent=None):
        super().__init__(parent)
        self._ids = itertools.count(1)
        self._callbacks = {}
        self._queued = []
        self._open = False

    def reset(self):
        """Forget the page: a new one is loading. Calls it was sent are answered with an
        error (from the event loop); queued calls wait for the next page."""
        self._open = False
        waiting, self._callbacks = self._callbacks, {}
        for callback in waiting.values():
            QTimer.singleShot(0, self, lambda callback=callback: callback(None, PAGE_RELOADED))

    def open(self):
        """The page is set up: send everything queued, in order."""
        self._open = True
        queued, self._queued = self._queued, []
        for sending in queued:
            self._send(*sending)

    def _send(self, message: str, call_id: int, callback, timeout_ms):
        if callback is not None:
            self._callbacks[call_id] = callback
            if timeout_ms is not None:
                QTimer.singleShot(timeout_ms, self, lambda: self._expire(call_id, timeout_ms))
        self.toPage.emit(message)

    def _expire(self, call_id: int, timeout_ms: int):
        callback = self._callbacks.pop(call_id, None)
        if callback is not None:
            callback(None, f"the editor did not answer within {timeout_ms / 1000:.0f} s")

    @property
    def is_open(self) -> bool:
        """True once the page has run setup and accepts calls."""
        return self._open

    def call(self, name: str, args=None, callback=None, *, timeout_ms=None, immediately=False):
        """Ask the page to run ``name(args)``; ``callback(result, error)`` gets the answer.

        Calls wait in a queue until the page is open, unless ``immediately`` (used
        for ``setup`` itself). With ``timeout_ms``, a call the page has not answered
        that long after it was sent is answered with an error.
        """
        call_id = next(self._ids)
        message = deep_json.dumps({"call": name, "id": call_id, "args": args or {}})
        if self._open or immediately:
            self._send(message, call_id, callback, timeout_ms)
        else:
            self._queued.append((message, call_id, callback, timeout_ms))

    @Slot(str)
    def fromPage(self, text: str):
        """Receive one JSON message from the page.

        Handling is deferred to the event loop: QWebChannel delivers no further
        messages while this slot runs, so a handler that waits for another answer
        (the headless editor's blocking wait) would otherwise never get it.
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
