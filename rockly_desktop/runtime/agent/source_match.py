"""Whether each kept program's code is what its blocks generate, as its ``about.json`` says in ``"code"``:

    "same"       the agent generated the ``.rockly`` source's code here and it is the code that runs
    "differs"    it is not (``"code_part"``: the code, the blocks' ids or the variables): the sender's Rockly
                 generated something else, or someone wrote the code by hand
    "unchecked"  this robot cannot generate it (``"code_reason"``: one of ``REASONS``, or the sentence the
                 window's Rockly said: a block or profile not known here)
    "no_source"  it came without its ``.rockly`` source (a ``.py`` sent as it is)
    "checking"   not yet known

A check starts the window's Rockly in a process of its own (``python -m rockly_desktop.source_check``: a
windowless Blockly), one at a time on a thread of its own: nothing of it runs in the agent's process or under its
lock, and a STOP never waits for it. The runtime alone (no Qt) cannot generate: its programs stay "unchecked".
"""
import json
import os
import queue
import subprocess
import sys
import threading

from rockly_desktop.runtime.agent.program_check import standalone_parts
from rockly_desktop.runtime.agent.protocol import AgentRefusal

CHECK_SECONDS = 120.0  # a windowless Blockly starts in some seconds; a 10,000-block program generates in ~10 s
CANNOT_GENERATE = 3  # source_check's exit status where Qt WebEngine is not installed
REASONS = ("runtime_only", "timeout", "failed", "off")  # each a catalogue text: robot_code_reason_...


def first_state(has_source: bool) -> dict:
    """The ``about.json`` fields of a program just kept."""
    return {"code": "checking" if has_source else "no_source"}


def generated_here(standalone_text: str, source_text: str) -> dict:
    """``{"code": ...}`` (see the module's docstring) for one program, checked in a child process."""
    try:
        program, run_code = standalone_parts(standalone_text)
    except AgentRefusal:
        return {"code": "differs", "code_part": "code"}
    request = {"source": source_text, "language": program.get("language", "en"), "run_code": run_code,
               "blocks": program.get("blocks"), "variables": program.get("variables") or {}}
    environment = dict(os.environ, QT_QPA_PLATFORM="offscreen")
    try:
        done = subprocess.run([sys.executable, "-m", "rockly_desktop.source_check"], capture_output=True,
                              input=json.dumps(request).encode("utf-8"), timeout=CHECK_SECONDS, env=environment,
                              check=False)
    except (OSError, subprocess.TimeoutExpired):
        return {"code": "unchecked", "code_reason": "timeout"}
    try:
        outcome = json.loads(done.stdout) if done.returncode == 0 else None
    except ValueError:
        outcome = None
    if not isinstance(outcome, dict) or outcome.get("code") not in ("same", "differs", "unchecked"):
        return {"code": "unchecked", "code_reason": "runtime_only" if done.returncode in (1, CANNOT_GENERATE)
                else "failed"}
    found = {"code": outcome["code"]}
    if "part" in outcome:
        found["code_part"] = str(outcome["part"])
    if "reason" in outcome:
        found["code_reason"] = str(outcome["reason"])[:300]
    return found


class SourceChecks:
    """Checks programs of ``library`` one after the other on a thread of its own; ``checked()`` is called after
    each outcome is written. ``enabled`` False: every program with a source stays "unchecked"."""

    def __init__(self, library, checked, enabled: bool = True):
        self.library = library
        self.checked = checked
        self.enabled = enabled
        self._waiting = queue.Queue()
        self._thread = threading.Thread(target=self._check_each, daemon=True, name="agent-source-checks")
        self._thread.start()

    def check_later(self, about: dict):
        """Check the program ``about`` names (as ``store`` kept it; a newer one of that name is left alone)."""
        if about.get("code") == "checking":
            self._waiting.put(about)

    def close(self):
        """Stop checking (a check under way ends with its child)."""
        self._waiting.put(None)
        self._thread.join(CHECK_SECONDS + 10)

    def _check_each(self):
        while True:
            about = self._waiting.get()
            if about is None:
                return
            texts = self.library.texts(about["name"], about["kept"])
            if texts is None:
                continue  # deleted or replaced meanwhile: its successor has its own check
            outcome = generated_here(*texts) if self.enabled else {"code": "unchecked", "code_reason": "off"}
            if self.library.note(about["name"], about["kept"], outcome):
                self.checked()
