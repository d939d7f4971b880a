"""The robot's agent (``rockly agent``) as a process of its own, and ``rockly robot`` as a user runs it."""
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]


class AgentProcess:
    """``rockly agent --backend BACKEND`` on a free localhost port, its programs in ``library``."""

    def __init__(self, library: Path, *options, backend="sim", env=None):
        self.process = subprocess.Popen(
            [sys.executable, "-m", "rockly_desktop", "agent", "--backend", backend, "--host", "127.0.0.1",
             "--port", "0", "--library", str(library), "--language", "en", *map(str, options)],
            cwd=REPO, env=env, text=True, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        ready = self.process.stdout.readline()
        assert "listening on" in ready, ready + self.process.stderr.read()
        self.port = int(ready.split("listening on 127.0.0.1:")[1].split(",")[0])

    def robot(self, *args, language="en", timeout=120, env=None) -> subprocess.CompletedProcess:
        """``rockly robot --port PORT ARGS`` run to its end."""
        return subprocess.run(self.robot_command(*args, language=language), capture_output=True, text=True,
                              timeout=timeout, cwd=REPO, env=env)

    def robot_command(self, *args, language="en") -> list:
        return [sys.executable, "-m", "rockly_desktop", "robot", "--port", str(self.port), "--language", language,
                *map(str, args)]

    def stop(self):
        """End the agent as systemd does (SIGTERM); kill it only if it does not end."""
        if self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(60)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait(10)
        self.process.stdout.close()
        self.process.stderr.close()
