"""A plain test node in a process of its own, which prints {"ready": true} once it listens and then one
JSON line per thing it saw; the lines are read on a thread of their own. It leaves when its stdin ends."""
import json
import subprocess
import threading


class JsonLineNode:
    """``command`` run with ``env``; ``lines``: what it printed after its ready line (``what`` names it)."""

    def __init__(self, command, env, what: str):
        self.process = subprocess.Popen([str(part) for part in command], stdin=subprocess.PIPE,
                                        stdout=subprocess.PIPE, text=True, env=env)
        self.lines = []
        ready = json.loads(self.process.stdout.readline() or "{}")
        assert ready.get("ready"), f"{what} did not start"
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self):
        for line in self.process.stdout:
            self.lines.append(json.loads(line))

    def stop(self):
        """End the node (its stdin closed; killed if it does not leave within 10 s)."""
        self.process.stdin.close()
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
