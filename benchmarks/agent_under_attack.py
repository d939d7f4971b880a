"""The agent's answers while a stranger attacks it (``rockly agent --backend sim`` on 127.0.0.1), in one run:

  - STOP: a ``stop`` request's answer on a connection of its own (aim <= 50 ms), and the gaps between the
    agent's alive beats that connection hears (every 0.5 s when nothing holds it up);
  - baseline: the same with no attack, measured first in the same run; each attack's ratio to it;
  - the attacks (each alone): a 4 MB program text that takes gigabytes to parse, sent again and again; as many
    idle connections as the agent holds, from other addresses; a slowloris line; a flood of ill-typed requests.

    python benchmarks/agent_under_attack.py
"""
import json
import os
import statistics
import sys
import tempfile
import threading
import time
from pathlib import Path

from _paths import REPO  # noqa: F401  (its set-up: Rockly and the tests' helpers importable)
from agent_tools import AgentProcess
from agent_wire import hello, tls_connection

from rockly_desktop.runtime.agent.tcp_transport import MAX_CONNECTIONS_PER_ADDRESS

STOPS = 40


class Line:
    """A raw TLS connection to the agent that reads answers and alive beats on a thread of its own; it says hello
    as the paired laptop (a paired client turned hostile: the bounds hold for it too)."""

    def __init__(self, agent, source="127.0.0.1"):
        self.socket, nonce = tls_connection(agent.port, source)
        self.answers, self.beats = {}, []
        self._arrived = threading.Condition()
        threading.Thread(target=self._read, daemon=True).start()
        self.ask(hello(nonce, agent.key))

    def _read(self):
        buffer = b""
        try:
            while data := self.socket.recv(1 << 16):
                buffer += data
                *lines, buffer = buffer.split(b"\n")
                for line in lines:
                    message = json.loads(line)
                    with self._arrived:
                        if "alive" in message:
                            self.beats.append(time.perf_counter())
                        else:
                            self.answers[message.get("reply")] = time.perf_counter()
                        self._arrived.notify_all()
        except (OSError, ValueError):
            pass

    def send(self, data: bytes):
        self.socket.sendall(data)

    def ask(self, request) -> float:
        """Seconds from sending ``request`` to its answer."""
        started = time.perf_counter()
        self.send((json.dumps(request) + "\n").encode())
        with self._arrived:
            self._arrived.wait_for(lambda: request["id"] in self.answers, 60)
        return self.answers[request["id"]] - started

    def close(self):
        self.socket.close()


def measure(agent):
    """``(STOP answer seconds, alive beat gaps)`` on a fresh connection."""
    line = Line(agent)
    first_id = 1000
    times = []
    for number in range(STOPS):
        times.append(line.ask({"op": "stop", "id": first_id + number}))
        time.sleep(0.05)
    beats = list(line.beats)
    line.close()
    return times, [later - earlier for earlier, later in zip(beats, beats[1:], strict=False)]


def huge_sends(agent, stop):
    line = Line(agent, "127.0.0.3")
    text = "a\n" * 2_000_000
    number = 0
    while not stop.is_set():
        number += 1
        line.ask({"op": "send", "id": number, "name": "lines", "standalone": text})
    line.close()


def idle_crowd(agent, stop):
    crowd = [Line(agent, f"127.0.0.{4 + index // MAX_CONNECTIONS_PER_ADDRESS}")
             for index in range(3 * MAX_CONNECTIONS_PER_ADDRESS)]
    stop.wait()
    for line in crowd:
        line.close()


def slowloris(agent, stop):
    line = Line(agent, "127.0.0.9")
    while not stop.wait(0.5):
        try:
            line.send(b"{")
        except OSError:
            line = Line(agent, "127.0.0.9")
    line.close()


def ill_typed_flood(agent, stop):
    line = Line(agent, "127.0.0.10")
    number = 0
    while not stop.is_set():
        number += 1
        line.ask({"op": "start", "id": number, "name": ["x"], "answers": 5})
    line.close()


def report(name, stops, gaps, baseline):
    ratio = statistics.median(stops) / statistics.median(baseline)
    print(f"{name}: STOP answered median {statistics.median(stops) * 1000:.1f} ms, max {max(stops) * 1000:.1f} ms "
          f"(aim <= 50 ms), ratio {ratio:.2f} to no attack; alive beats: largest gap "
          f"{max(gaps, default=float('nan')):.2f} s (every 0.5 s)", flush=True)


def main():
    with tempfile.TemporaryDirectory(prefix="rockly-bench-attack-") as folder:
        os.environ["XDG_CONFIG_HOME"] = str(Path(folder) / "config")  # the pairing's key: not the user's
        agent = AgentProcess(Path(folder) / "library")
        try:
            baseline, gaps = measure(agent)
            report("no attack", baseline, gaps, baseline)
            for name, attack in (("4 MB program texts", huge_sends), ("idle connections", idle_crowd),
                                 ("slowloris", slowloris), ("ill-typed flood", ill_typed_flood)):
                stop = threading.Event()
                attacker = threading.Thread(target=attack, args=(agent, stop), daemon=True)
                attacker.start()
                time.sleep(1.0)  # the attack under way
                stops, gaps = measure(agent)
                stop.set()
                attacker.join(60)
                report(name, stops, gaps, baseline)
        finally:
            agent.stop()
    return 0


if __name__ == "__main__":
    sys.exit(main())
