"""Recovery files written by other, real processes: one killed with SIGKILL, one still running."""
import json
import os
import signal
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]

_WRITE = """
import json, os, signal, sys
from rockly_desktop.core.program import Program
from rockly_desktop.core.recovery import RecoverySession
program, program_path, end = json.loads(sys.argv[1])
session = RecoverySession()
session.write(Program(**program), program_path)
print(session.path, flush=True)
if end == "kill":
    os.kill(os.getpid(), signal.SIGKILL)
sys.stdin.read()
"""


def _start(program, program_path, end):
    env = {**os.environ, "PYTHONPATH": str(REPO)}
    document = {"profile_id": program.profile_id, "workspace": program.workspace, "breakpoints": program.breakpoints}
    return subprocess.Popen([sys.executable, "-c", _WRITE, json.dumps([document, program_path, end])],
                            stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True, env=env, cwd=REPO)


def left_by_killed_process(program, program_path=None) -> Path:
    """A recovery file (in this test's data folder) whose Rockly was killed with SIGKILL."""
    process = _start(program, program_path, "kill")
    path = Path(process.stdout.readline().strip())
    process.stdin.close()
    assert process.wait(timeout=30) == -signal.SIGKILL
    process.stdout.close()
    return path


class LiveProcess:
    """A process that wrote a recovery file and keeps running until ``end()``."""

    def __init__(self, program, program_path=None):
        self.process = _start(program, program_path, "live")
        self.path = Path(self.process.stdout.readline().strip())

    def end(self):
        """Let the process end (without removing its file, like a crash would)."""
        self.process.stdin.close()
        self.process.wait(timeout=30)
        self.process.stdout.close()
