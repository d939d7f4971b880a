"""The Blockly workspace in a QWebEngineView, driven through PageChannel.

``start()`` (re)loads the page with a profile's blocks and toolbox in one language;
``sig_ready`` fires when the workspace exists; ``sig_changed`` carries every edit
(workspace JSON + generated Python). Other calls are queued until the page is ready.
"""
import logging

from PySide6.QtCore import QUrl, Signal
from PySide6.QtWebChannel import QWebChannel
from PySide6.QtWebEngineCore import QWebEnginePage, QWebEngineProfile
from PySide6.QtWebEngineWidgets import QWebEngineView

from rockly_desktop.bridge.channel import PAGE_RELOADED, PageChannel
from rockly_desktop.bridge.offline import LocalOnlyInterceptor
from rockly_desktop.core import paths

log = logging.getLogger(__name__)

ANSWER_TIMEOUT_MS = 15000  # for calls the page answers at once (its state, the run code)

_interceptor = None


def offline_web_profile() -> QWebEngineProfile:
    """The web profile of every editor page: refuses all network requests, keeps nothing on disk.

    It is Qt's default profile, which Qt itself keeps alive until every page is gone
    (a profile of our own, deleted before a page, crashes the process at exit).
    Its interceptor is ``offline_web_profile().interceptor``.
    """
    global _interceptor
    profile = QWebEngineProfile.defaultProfile()
    if _interceptor is None:
        profile.setHttpCacheType(QWebEngineProfile.HttpCacheType.MemoryHttpCache)
        profile.setPersistentCookiesPolicy(QWebEngineProfile.PersistentCookiesPolicy.NoPersistentCookies)
        _interceptor = LocalOnlyInterceptor(profile)
        profile.setUrlRequestInterceptor(_interceptor)
    profile.interceptor = _interceptor
    return profile


def plain_look(look: dict) -> dict:
    """``look`` as the page takes it: {"highContrast": bool, "largeText": bool}."""
    return {"highContrast": bool(look.get("highContrast")), "largeText": bool(look.get("largeText"))}


class EditorPage(QWebEnginePage):
    """A page that reports JavaScript errors instead of hiding them in the console."""

    sig_js_error = Signal(str)

    def javaScriptConsoleMessage(self, level, message, line, source):
        """Qt override: log page messages; errors also go to ``sig_js_error``."""
        if level == QWebEnginePage.JavaScriptConsoleMessageLevel.ErrorMessageLevel:
            log.error("editor page: %s (%s:%s)", message, source, line)
            self.sig_js_error.emit(f"{message} ({source}:{line})")
        else:
            log.debug("editor page: %s", message)


class EditorView(QWebEngineView):
    """The block editor: a web view showing Blockly, with a small Python API."""

    sig_ready = Signal()
    # workspace JSON (a dict, any number size), generated Python, origin: "user" | "load"
    sig_changed = Signal(object, str, str)
    sig_page_error = Signal(str)
    sig_breakpoints = Signal(list)  # block ids, after the user toggled one
    sig_edit_made_block = Signal(str)  # a made block's type: its context menu's "Edit this block…"

    def __init__(self, parent=None):
        super().__init__(parent)
        web_profile = offline_web_profile()
        self.interceptor = web_profile.interceptor
        page = EditorPage(web_profile, self)
        page.sig_js_error.connect(self.sig_page_error)
        self.setPage(page)
        self.channel = PageChannel(self)
        web_channel = QWebChannel(page)
        web_channel.registerObject("rocklyBridge", self.channel)
        page.setWebChannel(web_channel)
        self.channel.sig_hello.connect(self._on_hello)
        self.channel.sig_event.connect(self._on_event)
        self._setup_args = None
        self._on_first_result = None
        self._page_state = "loading"  # -> "hello" (page waits for setup) -> "setup sent"
        self._prepared = False  # the setup sent is prepare()'s, not yet claimed by start()
        self._prepared_answer = None  # its answer, when it came before start()
        self.known_block_types = frozenset()
        self._look = plain_look({})
        self.workspace = {}
        self.python = ""
        # Chromium starts and loads Blockly while Python goes on building the window.
        self.load(QUrl.fromLocalFile(str(paths.editor_page())))

    @property
    def is_ready(self) -> bool:
        """True when the workspace exists and calls go straight to the page."""
        return self.channel.is_open

    def prepare(self, editor_config: dict, language: str, texts=None):
        """Set the page up for a profile ahead of ``start``, its workspace hidden.

        Called while the window is still being built, so that Blockly builds the workspace
        meanwhile. A ``start`` with the same profile, language and texts then only shows
        the program and the workspace; any other ``start`` loads a fresh page.
        """
        self._setup_args = self._setup(editor_config, language, None, texts, hidden=True, look=self._look)
        self._prepared = True
        if self._page_state == "hello":
            self._send_setup()

    def start(self, editor_config: dict, language: str, first_call=None, on_first_result=None, texts=None):
        """Set the page up for a profile's ``editor_config`` in ``language``.

        The first call configures the page that began loading when the view was made;
        later calls (another profile or language) load a fresh page. ``first_call``
        (name, args) runs inside the set-up, before the first paint (a program to open);
        ``on_first_result(result, error)`` gets its answer. ``texts`` are the page's own
        menu texts (``addBreakpoint``, ``removeBreakpoint``) in ``language``.
        """
        setup = self._setup(editor_config, language, first_call, texts, hidden=False, look=self._look)
        prepared, self._prepared = self._prepared, False
        self._on_first_result = on_first_result
        if prepared and self._page_state == "setup sent" and self._same_page(setup):
            self._show_prepared(first_call)
            answer, self._prepared_answer = self._prepared_answer, None
            if answer is not None:
                self._on_setup(*answer)
            return
        self._setup_args = setup
        if self._page_state == "hello":
            self._send_setup()
        elif self._page_state == "setup sent":
            self.channel.reset()
            self._page_state = "loading"
            self._prepared_answer = None
            self.load(QUrl.fromLocalFile(str(paths.editor_page())))

    @staticmethod
    def _setup(editor_config, language, first_call, texts, hidden, look) -> dict:
        return {
            "language": language,
            "profile": editor_config,
            "media": QUrl.fromLocalFile(str(paths.blockly_vendor_dir() / "media") + "/").toString(),
            "first": {"call": first_call[0], "args": first_call[1]} if first_call else None,
            "texts": texts,
            "hidden": hidden,
            "look": look,
        }

    def _same_page(self, setup: dict) -> bool:
        """True when ``setup`` asks for the page the prepared setup made."""
        ignored = ("first", "hidden", "look")  # a look set meanwhile follows the setup (set_look)
        return ({key: value for key, value in setup.items() if key not in ignored}
                == {key: value for key, value in self._setup_args.items() if key not in ignored})

    def call(self, name: str, args=None, callback=None, timeout_ms=None):
        """Run a page call when the page is ready; ``callback(result, error)`` gets the answer.

        The answer always comes later, from the event loop. A page reloaded before it
        answered, or (with ``timeout_ms``) one that took longer than that once the call
        was sent, answers with an error instead.
        """
        self.channel.call(name, args, callback, timeout_ms=timeout_ms)

    def load_workspace(self, workspace: dict, callback=None, breakpoints=()):
        """Show a workspace (Blockly JSON) with breakpoints on ``breakpoints`` (block ids).

        The page keeps the old workspace if this one fails. The answer is
        ``{"loaded": True}`` or ``{"unknownTypes": [...]}`` (nothing changed).
        """
        self.call("load", {"workspace": workspace, "breakpoints": list(breakpoints)}, callback)

    def import_xml(self, xml: str, callback=None):
        """Show a first-Rockly Blockly XML program; answered like ``load_workspace``."""
        self.call("importXml", {"xml": xml}, callback)

    def set_toolbox(self, toolbox: dict):
        """Show ``toolbox`` (Blockly toolbox JSON) instead of the profile's; the program stays as it is."""
        if self._setup_args is not None:  # a page that reloads gets it too
            self._setup_args["profile"] = {**self._setup_args["profile"], "toolbox": toolbox}
        self.call("setToolbox", {"toolbox": toolbox})

    def set_look(self, look: dict):
        """Show the blocks with ``look`` ({"highContrast": bool, "largeText": bool}), this page and every
        page loaded later.

        A page not yet set up gets it with its setup, which injects Blockly in that look: changing the
        look of a page with blocks measures every block again (some 200 ms for 300 blocks).
        """
        look = plain_look(look)
        if look == self._look:
            return
        self._look = look
        if self._setup_args is not None:
            self._setup_args["look"] = look  # a setup not sent yet, or a page loaded again
        if self._page_state == "setup sent":
            self.call("setLook", look)

    def clear(self):
        """Empty the workspace."""
        self.call("clear")

    def undo(self):
        """Undo the last edit."""
        self.call("undo")

    def redo(self):
        """Redo the last undone edit."""
        self.call("redo")

    def _on_hello(self):
        self.channel.reset()
        self._page_state = "hello"
        if self._setup_args is not None:
            self._send_setup()

    def _send_setup(self):
        self._page_state = "setup sent"
        self.channel.call("setup", self._setup_args, self._on_setup, immediately=True)

    def _on_setup(self, result, error):
        if error == PAGE_RELOADED:  # a new page is loading; its own setup follows
            return
        if self._prepared:  # kept until start() says what to show
            self._prepared_answer = (result, error)
            return
        if error:
            callback, self._on_first_result = self._on_first_result, None
            self.sig_page_error.emit(f"the editor could not start: {error}")
            if callback is not None:
                callback(None, error)
            return
        self.known_block_types = frozenset(result["blockTypes"])
        self.channel.open()
        if self._setup_args["hidden"]:  # start()'s first call and show went right behind it
            return
        callback, self._on_first_result = self._on_first_result, None
        self.sig_ready.emit()
        if callback is not None:
            first_answer = result.get("program") or {}
            callback(first_answer.get("result"), first_answer.get("error"))

    def _show_prepared(self, first_call):
        """Send start()'s first call and ``show`` right behind the prepared setup, ahead of every other
        call: the page runs its calls in order, so they need not wait for the setup's answer.
        Ready once the first is answered, after a setup that worked."""
        def on_first(result, error):
            if error == PAGE_RELOADED or not self.channel.is_open:  # a reload, or a setup that failed (and said so)
                return
            callback, self._on_first_result = self._on_first_result, None
            self.sig_ready.emit()
            if callback is not None:
                callback(result, error)

        if first_call:
            self.channel.call(*first_call, on_first, immediately=True)
            self.channel.call("show", immediately=True)
        else:
            self.channel.call("show", None, on_first, immediately=True)

    def _on_event(self, message: dict):
        event = message.get("event")
        if event == "changed":
            self.workspace = message["workspace"]
            self.python = message["python"]
            self.sig_changed.emit(self.workspace, self.python, message.get("origin", "user"))
        elif event == "breakpoints":
            self.sig_breakpoints.emit(message["ids"])
        elif event == "editMadeBlock":
            self.sig_edit_made_block.emit(str(message.get("type", "")))
        elif event == "error":
            self.sig_page_error.emit(f"{message.get('message')} ({message.get('source')}:{message.get('line')})")
