"""The separate echo node of the agent's benchmarks (ROS 1 in agent.py, ROS 2 in _agent_ros2.py): a process running
``node_source`` that prints "ready", then ``KIND TIME`` (move or zero, the receive time) for each Twist on /cmd_vel."""
import subprocess
import threading
import time


class TwistEcho:
    """The echo node as a process; ``seen`` gets ``(kind, receive time)`` of every Twist it prints."""

    def __init__(self, python, node_source, env):
        self.seen = []
        self.process = subprocess.Popen([str(python), "-c", node_source], env=env, stdout=subprocess.PIPE, text=True)
        assert self.process.stdout.readline().startswith("ready")
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self):
        for line in self.process.stdout:
            kind, when = line.split()
            self.seen.append((kind, float(when)))

    def wait_for(self, kind, after, timeout=10.0):
        """The receive time of the first Twist of ``kind`` received after ``after``."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            for seen_kind, when in list(self.seen):
                if seen_kind == kind and when > after:
                    return when
            time.sleep(0.0005)
        raise RuntimeError(f"no {kind} Twist on the wire")
