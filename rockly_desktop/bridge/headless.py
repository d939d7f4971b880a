"""The block editor without a window: Blockly's own generator for command-line use.

Only here does Python wait for the page in a nested event loop: nothing else runs in
a headless process, so no person's click can arrive while the loop spins. The window
never waits; it goes on in a callback (see ``EditorView.call``).
"""
from PySide6.QtCore import QCoreApplication, QEvent, QEventLoop, QTimer

from rockly_desktop.bridge.editor_view import ANSWER_TIMEOUT_MS, EditorView
from rockly_desktop.core.errors import ProgramFileError


class UnknownBlocks(Exception):
    """The editor refused a program: it uses block types the page does not know."""

    def __init__(self, block_types):
        super().__init__(", ".join(block_types))
        self.block_types = block_types


# Blockly takes about 1 ms per block to load and render a program (10,000 blocks: ~10 s):
# waits for the page grow with the program so a large one is not cut off.
PER_BLOCK_MS = 4


class HeadlessEditor:
    """An EditorView that is never shown, driven synchronously."""

    def __init__(self, language: str = "en"):
        self.language = language
        self.view = EditorView()
        self.profile = None
        self.timeout_ms = ANSWER_TIMEOUT_MS  # how long a call may take, for the program shown
        self._errors = []
        self.view.sig_page_error.connect(self._errors.append)

    def use_profile(self, profile, timeout_ms: int = 30000):
        """Set the editor page up with ``profile``'s blocks and wait until it is ready."""
        if self.profile is not None and profile.id == self.profile.id:
            return
        loop = QEventLoop()
        self.view.sig_ready.connect(loop.quit)
        self.view.sig_page_error.connect(loop.quit)
        QTimer.singleShot(timeout_ms, loop.quit)
        self.view.start(profile.editor_config(self.language), self.language)
        loop.exec()
        self.view.sig_ready.disconnect(loop.quit)
        self.view.sig_page_error.disconnect(loop.quit)
        if not self.view.is_ready:
            detail = self._errors[-1] if self._errors else f"no answer within {timeout_ms / 1000:.0f} s"
            raise RuntimeError(f"the block editor did not start: {detail}")
        self.profile = profile

    def python_for(self, program) -> str:
        """The Python generated for a ProgramToOpen; raises UnknownBlocks if the page refuses it,
        ProgramFileError for a block without a type. Field values the page had to replace
        are kept in ``program.replaced_fields``."""
        self.use_profile(program.profile)
        self.timeout_ms = ANSWER_TIMEOUT_MS + PER_BLOCK_MS * program.block_count
        name, args = program.editor_call()
        result = self.call_and_wait(name, args)
        if result.get("untypedBlock"):
            broken = f"the file is broken: block {result['untypedBlock']} has no type"
            raise ProgramFileError(program.path or "the program", broken)
        if result.get("unknownTypes"):
            raise UnknownBlocks(result["unknownTypes"])
        program.take_load_result(result)
        return self.call_and_wait("getState")["python"]

    def call_and_wait(self, name: str, args=None, timeout_ms: int = None):
        """Run a page call and wait for its answer (at most ``timeout_ms``, by default what the
        program shown needs); raises RuntimeError on a page error or timeout."""
        if not self.view.is_ready:
            raise RuntimeError("the block editor is not set up (use_profile first)")
        loop = QEventLoop()
        answer = {}

        def on_answer(result, error):
            answer.update(result=result, error=error)
            loop.quit()

        self.view.call(name, args, on_answer, timeout_ms=timeout_ms or self.timeout_ms)
        loop.exec()  # the channel always answers: with the result, an error, or a timeout
        if answer["error"]:
            raise RuntimeError(answer["error"])
        return answer["result"]

    def close(self):
        """Delete the page now, before the application's web profile goes away."""
        self.view.deleteLater()
        QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)
