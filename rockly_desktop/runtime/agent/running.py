"""The one program the agent runs: its child process (``agent.child``), what the run has shown so far (for a
client attaching mid-run) and the watch on the editor (what a lost editor means for this program)."""
import json
import subprocess
import sys
import threading
import time

MAX_PRINTS = 200  # of the latest printed lines, given to a client that attaches


class ProgramRun:
    """Program ``about`` (its library entry) running from ``path`` with the child's command-line ``options``.

    ``publish``: called with every event record (from the child's stream, and the agent's ``run`` events);
    ``on_end``: called once when the child has ended; ``breakpoints``: the blocks to pause before (the controlling
    editor's)."""

    def __init__(self, about: dict, path, options: list, publish, on_end, breakpoints=()):
        self.about = about
        self.publish = publish
        self.state = "running"
        self.block = None
        self.paused = None
        self.variables = {}
        self.prints = []
        self.finished = None
        self.status = None
        self.breakpoints = []  # the controlling editor's; none while no editor controls the run
        self.started = time.time()
        self.last_heartbeat = None  # of the controlling client (the editor); the watch starts with the first
        self.stopped_for_lost_editor = False
        self._lock = threading.Lock()
        self._on_end = on_end
        self.process = subprocess.Popen(
            [sys.executable, "-m", "rockly_desktop.runtime.agent.child", str(path), *options],
            stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, bufsize=1)
        if breakpoints:  # read by the child before its program's first block (opening the robot link takes longer)
            self.set_breakpoints(breakpoints)
        self.errors = []
        threading.Thread(target=self._read_errors, daemon=True, name="agent-run-errors").start()
        self._reader = threading.Thread(target=self._read_events, daemon=True, name="agent-run-events")
        self._reader.start()
        self._watch = threading.Thread(target=self._watch_editor, daemon=True, name="agent-editor-watch")
        self._watch.start()

    def snapshot(self) -> dict:
        """What a client attaching now needs to show the run."""
        with self._lock:
            return {"program": self.about["name"], "profile": self.about.get("profile"), "state": self.state,
                    "block": self.block, "paused": self.paused, "variables": dict(self.variables),
                    "prints": list(self.prints), "finished": self.finished, "status": self.status,
                    "breakpoints": list(self.breakpoints), "on_lost_editor": self.about.get("on_lost_editor"),
                    "decide_seconds": self.about.get("decide_seconds")}

    def request(self, what: str):
        """Pass ``pause``, ``step``, ``continue`` or ``stop`` to the running program."""
        try:
            self.process.stdin.write(what + "\n")
            self.process.stdin.flush()
        except (OSError, ValueError):  # it has ended
            pass

    def set_breakpoints(self, block_ids: list):
        """Pause the program before these blocks from now on (the editor's breakpoints; none: run through)."""
        self.breakpoints = [str(block) for block in block_ids]
        self.request("breakpoints " + json.dumps(self.breakpoints))

    def heartbeat(self):
        """The editor (the controlling client) is there now."""
        self.last_heartbeat = time.monotonic()

    def end(self, timeout: float = 30.0):
        """Stop the program (the safe stop runs in the child) and wait for its process; kill it only if it hangs."""
        self.request("stop")
        try:
            self.process.wait(timeout)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait(10)
        self._reader.join(10)

    def _read_events(self):
        for line in self.process.stdout:
            try:
                record = json.loads(line)
            except ValueError:
                continue
            if not isinstance(record, dict):
                continue
            self._take(record)
            self.publish(record)
        status = self.process.wait()
        with self._lock:
            self.state = "ended"
            self.status = status
        self._on_end(self)  # first: a client told the run ended may start the next one at once
        self.publish({"event": "run", "state": "ended", "program": self.about["name"], "status": status,
                      "stopped_for_lost_editor": self.stopped_for_lost_editor,
                      "errors": self.errors[-5:]})

    def _read_errors(self):
        for line in self.process.stderr:
            self.errors.append(line.rstrip("\n"))
            del self.errors[:-50]

    def _take(self, record: dict):
        kind = record.get("event")
        with self._lock:
            if kind == "block":
                self.block = record.get("id")
            elif kind == "print":
                self.prints.append(record.get("text"))
                del self.prints[:-MAX_PRINTS]
            elif kind == "variables":
                self.variables = dict(record.get("values") or {})
            elif kind == "paused":
                self.state, self.paused = "paused", record
            elif kind == "resumed":
                self.state, self.paused = "running", None
            elif kind == "finished":
                self.state, self.finished = "finishing", record

    def _watch_editor(self):
        """With "stop the robot" for a lost editor: stop the run once the editor (the controlling client) has not
        been heard from for the program's time to decide (the watch starts with its first heartbeat; a window
        attaching again in time and taking control keeps the run going)."""
        if self.about.get("on_lost_editor") != "stop":
            return
        decide = float(self.about.get("decide_seconds", 2.0))
        while self.process.poll() is None:
            heard = self.last_heartbeat
            if heard is not None and time.monotonic() - heard > decide:
                self.stopped_for_lost_editor = True
                self.publish({"event": "run", "state": "editor_lost", "program": self.about["name"]})
                self.request("stop")
                return
            time.sleep(0.02)
